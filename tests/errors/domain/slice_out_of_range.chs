# Ranges index 1-based and inclusive; past the end is an error.
v = (1, 2, 3)
v[2:end]
v[2:5]
T = Trans(1, 2, 3)
T[1:3, 5]
