# a stray operator
x = 2 * * 3
