# `explain` of a chain whose frames do not cancel: the error shows the
# chain step by step, the products that cancel and the one that does not.
T_ab = [Rotz(1), (1, 0, 0); 0, 1]
T_bc = [Rotx(1), (0, 1, 0); 0, 1]
T_dc = [Roty(1), (0, 0, 1); 0, 1]
explain T_ab T_bc T_dc
