# a vector where a rotation is needed
MatrixLog3((1, 2, 3))
