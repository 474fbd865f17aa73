# wrong number of arguments: the signature is printed
MatrixExp3((1, 2, 3), 2)
