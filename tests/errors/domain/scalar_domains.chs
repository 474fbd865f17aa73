# numbers outside a function's domain
sqrt(-1)
acos(2)
x = 1 / 0
Normalize((0, 0, 0))
