# not a rotation matrix: the distance from SO(3) is given
MatrixLog3([1, 2, 3; 4, 5, 6; 7, 8, 10])
