# A two-frame name with numbered frames must split into exactly two
# frames (LANGUAGE.md §2): T_01 is {0}←{1}, T_123 needs braces.
T_01 = Trans((1, 0, 0))
T_123 = Trans((1, 0, 0))
T_{1,23} = Trans((1, 0, 0))
T_a12 = T_01
