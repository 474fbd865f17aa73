# a rotation or transform name asserts its group at the binding (§5):
# within 1e-2 of it the matrix is projected with a warning, farther is an error
R_sb = [0, -1, 0; 1, 0, 0; 0, 0, 1.001]
R_sc = [1, 0, 0; 0, 1, 0; 0, 0, 2]
T_ab = [1, 0, 0, 1; 0, 1, 0, 2; 0, 0, 1, 3; 1, 0, 0, 1]
M_sc = [1, 0, 0; 0, 1, 0; 0, 0, 2]
