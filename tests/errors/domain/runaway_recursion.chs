# a user function that never stops calling itself is an error, not a stack overflow
f(x) = f(x) + 1
f(1)
g(x) = h(x)
h(x) = g(x)
g(2)
