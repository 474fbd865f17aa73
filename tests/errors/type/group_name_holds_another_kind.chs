# A rotation or transform name requires its group (LANGUAGE.md §5): the
# wrong shape or group is a type error, before any distance is measured.
T_ab = [1, 2; 3, 4]
R_ab = Trans((1, 2, 3))
R_sb = (1, 2, 3)
