# a reflection has determinant -1
log([1, 0, 0; 0, 1, 0; 0, 0, -1])
