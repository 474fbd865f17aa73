# a typo in a builtin
MatrixLog(Rotz(1))
