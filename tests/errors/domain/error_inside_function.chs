# An error inside a user function shows where it was called, too.
f(x) = sqrt(x - 3) + 1

y = 4
f(y)
f(2)
