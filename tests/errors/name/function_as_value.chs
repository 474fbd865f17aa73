# a function used as a value
x = RotInv
