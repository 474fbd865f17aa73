# A value before a parenthesis multiplies (`R (1, 0, 0)`), but `R(1, 2)`
# written as MATLAB indexes reads two ways: the error names `R[1, 2]`.
R = Rotz(pi/2)
R (1, 0, 0)
R(1, 2)
v = (1, 2, 3)
v(2)
