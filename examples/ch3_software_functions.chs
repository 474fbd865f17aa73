# Modern Robotics, chapter 3, §3.6 "Software": every function of the book's
# software used on a small input, under the book's name and its snake_case
# alias (LANGUAGE.md §8).
#
# The inputs and answers are those of the docstring examples of the book's
# own software (the Modern Robotics library, github.com/NxRLab/ModernRobotics);
# the seed text lists the functions without examples. The test functions
# (NearZero … TestIfSE3) come from the book's exercises and library.
#
# Notes on conventions, as in §3.6 of the book:
#   MatrixExp3/MatrixExp6 take exponential coordinates (a 3-/6-vector), not
#   an so(3)/se(3) matrix; chasles also accepts the matrix.
#   MatrixLog3/MatrixLog6 return exponential coordinates, not a matrix.
#   The book's "AxisAng" and "MatrixLog" for 6-vectors are AxisAng6 and
#   MatrixLog6 (the seed text drops the 6).
#
# Expected values:
#   RotInv([0 0 1; 1 0 0; 0 1 0]) = [0 1 0; 0 0 1; 1 0 0]
#   VecToso3((1, 2, 3)) = [0 -3 2; 3 0 -1; -2 1 0];  so3ToVec of it = (1, 2, 3)
#   AxisAng3((1, 2, 3)) = ((0.2673, 0.5345, 0.8018), 3.7417)
#   MatrixExp3((1, 2, 3)) = [-0.6949 0.7135 0.0893; -0.192 -0.3038 0.9332; 0.693 0.6313 0.3481]
#   MatrixLog3([0 0 1; 1 0 0; 0 1 0]) = (1.2092, 1.2092, 1.2092)
#   RpToTrans([1 0 0; 0 0 -1; 0 1 0], (1, 2, 5)) = [1 0 0 1; 0 0 -1 2; 0 1 0 5; 0 0 0 1]
#   T = [1 0 0 0; 0 0 -1 0; 0 1 0 3; 0 0 0 1]:
#     TransToRp(T) = ([1 0 0; 0 0 -1; 0 1 0], (0, 0, 3))
#     TransInv(T)  = [1 0 0 0; 0 0 1 -3; 0 -1 0 0; 0 0 0 1]
#     Adjoint(T)   = [1 0 0 0 0 0; 0 0 -1 0 0 0; 0 1 0 0 0 0;
#                     0 0 3 1 0 0; 3 0 0 0 0 -1; 0 0 0 0 1 0]
#     MatrixLog6(T) = (1.5708, 0, 0, 0, 2.3562, 2.3562)
#   VecTose3((1, 2, 3, 4, 5, 6)) = [0 -3 2 4; 3 0 -1 5; -2 1 0 6; 0 0 0 0]
#   ScrewToAxis((3, 0, 0), (0, 0, 1), 2) = (0, 0, 1, 0, -3, 2)
#   AxisAng6((1, 0, 0, 1, 2, 3)) = ((1, 0, 0, 1, 2, 3), 1)
#   MatrixExp6((π/2, 0, 0, 0, 3π/4, 3π/4)) = T
#   NearZero(-1e-7) = true;  Normalize((1, 2, 3)) = (0.2673, 0.5345, 0.8018)
#   ProjectToSO3([0.675 0.150 0.720; 0.370 0.771 -0.511; -0.630 0.619 0.472])
#     = [0.679 0.1489 0.7189; 0.3732 0.7732 -0.5127; -0.6322 0.6164 0.4694]
#   ProjectToSE3 of that R with p = (1.2, 5.4, 3.6) and a bad last row
#     = [that rotation, (1.2, 5.4, 3.6); 0 0 0 1]
#   DistanceToSO3([1 0 0; 0 0.1 -0.95; 0 1 0.1]) = 0.0884;  TestIfSO3 = false
#   DistanceToSE3([1 0 0 1.2; 0 0.1 -0.95 1.5; 0 1 0.1 -0.9; 0 0 0.1 0.98]) = 0.1349;
#   TestIfSE3 = false;  test_if_so3(I) = true;  distance_to_se3(T) = 0

# --- Rotations ---------------------------------------------------------------
RotInv([0, 0, 1; 1, 0, 0; 0, 1, 0])
VecToso3((1, 2, 3))
vec_to_so3((1, 2, 3))            # snake_case
skew((1, 2, 3))                  # alias
so3ToVec([0, -3, 2; 3, 0, -1; -2, 1, 0])
vee([0, -3, 2; 3, 0, -1; -2, 1, 0])
(omghat, theta) = AxisAng3((1, 2, 3))
axis_ang3((1, 2, 3))
MatrixExp3((1, 2, 3))
MatrixExp3(VecToso3((1, 2, 3)))  # the so(3) matrix is accepted too
MatrixLog3([0, 0, 1; 1, 0, 0; 0, 1, 0])
matrix_log3([0, 0, 1; 1, 0, 0; 0, 1, 0])

# --- Rigid-body motions ------------------------------------------------------
RpToTrans([1, 0, 0; 0, 0, -1; 0, 1, 0], (1, 2, 5))
T = [1, 0, 0, 0; 0, 0, -1, 0; 0, 1, 0, 3; 0, 0, 0, 1]
(R, p) = TransToRp(T)
TransInv(T)
trans_inv(T)
VecTose3((1, 2, 3, 4, 5, 6))
se3ToVec([0, -3, 2, 4; 3, 0, -1, 5; -2, 1, 0, 6; 0, 0, 0, 0])
Adjoint(T)
adjoint(T)
Ad(T)
ScrewToAxis((3, 0, 0), (0, 0, 1), 2)
screw_to_axis((3, 0, 0), (0, 0, 1), 2)
(S, th) = AxisAng6((1, 0, 0, 1, 2, 3))
MatrixExp6((pi/2, 0, 0, 0, 3 pi/4, 3 pi/4))
MatrixExp6(VecTose3((pi/2, 0, 0, 0, 3 pi/4, 3 pi/4)))   # the se(3) matrix is accepted too
MatrixLog6(T)
matrix_log6(T)

# --- Tests, projection and distance -----------------------------------------
NearZero(-1e-7)
near_zero(-1e-7)
Normalize((1, 2, 3))
ProjectToSO3([0.675, 0.150, 0.720; 0.370, 0.771, -0.511; -0.630, 0.619, 0.472])
ProjectToSE3([0.675, 0.150, 0.720, 1.2; 0.370, 0.771, -0.511, 5.4; -0.630, 0.619, 0.472, 3.6; 0.003, 0.002, 0.010, 0.9])
DistanceToSO3([1, 0, 0; 0, 0.1, -0.95; 0, 1, 0.1])
TestIfSO3([1, 0, 0; 0, 0.1, -0.95; 0, 1, 0.1])
test_if_so3(eye(3))
DistanceToSE3([1, 0, 0, 1.2; 0, 0.1, -0.95, 1.5; 0, 1, 0.1, -0.9; 0, 0, 0.1, 0.98])
TestIfSE3([1, 0, 0, 1.2; 0, 0.1, -0.95, 1.5; 0, 1, 0.1, -0.9; 0, 0, 0.1, 0.98])
distance_to_se3(T)

# --- The expected values, checked ---------------------------------------------
assert RotInv([0, 0, 1; 1, 0, 0; 0, 1, 0]) == [0, 1, 0; 0, 0, 1; 1, 0, 0]
assert VecToso3((1, 2, 3)) == [0, -3, 2; 3, 0, -1; -2, 1, 0]
assert so3ToVec(VecToso3((1, 2, 3))) == (1, 2, 3)
assert omghat ≈ (1, 2, 3) / sqrt(14)
assert theta ≈ sqrt(14)
assert round(MatrixExp3((1, 2, 3)), 4) == [-0.6949, 0.7135, 0.0893; -0.192, -0.3038, 0.9332; 0.693, 0.6313, 0.3481]
assert MatrixLog3([0, 0, 1; 1, 0, 0; 0, 1, 0]) ≈ (2 pi / 3) * (1, 1, 1) / sqrt(3)
assert RpToTrans([1, 0, 0; 0, 0, -1; 0, 1, 0], (1, 2, 5)) == [1, 0, 0, 1; 0, 0, -1, 2; 0, 1, 0, 5; 0, 0, 0, 1]
assert (R, p) == ([1, 0, 0; 0, 0, -1; 0, 1, 0], (0, 0, 3))
assert TransInv(T) == [1, 0, 0, 0; 0, 0, 1, -3; 0, -1, 0, 0; 0, 0, 0, 1]
assert VecTose3((1, 2, 3, 4, 5, 6)) == [0, -3, 2, 4; 3, 0, -1, 5; -2, 1, 0, 6; 0, 0, 0, 0]
assert Adjoint(T) == [1, 0, 0, 0, 0, 0; 0, 0, -1, 0, 0, 0; 0, 1, 0, 0, 0, 0; 0, 0, 3, 1, 0, 0; 3, 0, 0, 0, 0, -1; 0, 0, 0, 0, 1, 0]
assert ScrewToAxis((3, 0, 0), (0, 0, 1), 2) == (0, 0, 1, 0, -3, 2)
assert (S, th) == ((1, 0, 0, 1, 2, 3), 1)
assert MatrixExp6((pi/2, 0, 0, 0, 3 pi/4, 3 pi/4)) ≈ T
assert MatrixLog6(T) ≈ (pi/2, 0, 0, 0, 3 pi/4, 3 pi/4)
assert NearZero(-1e-7)
assert Normalize((1, 2, 3)) ≈ (1, 2, 3) / sqrt(14)
assert round(ProjectToSO3([0.675, 0.150, 0.720; 0.370, 0.771, -0.511; -0.630, 0.619, 0.472]), 4) == [0.679, 0.1489, 0.7189; 0.3732, 0.7732, -0.5127; -0.6322, 0.6164, 0.4694]
assert round(DistanceToSO3([1, 0, 0; 0, 0.1, -0.95; 0, 1, 0.1]), 4) == 0.0884
assert TestIfSO3([1, 0, 0; 0, 0.1, -0.95; 0, 1, 0.1]) == false
assert round(DistanceToSE3([1, 0, 0, 1.2; 0, 0.1, -0.95, 1.5; 0, 1, 0.1, -0.9; 0, 0, 0.1, 0.98]), 4) == 0.1349
assert distance_to_se3(T) == 0
