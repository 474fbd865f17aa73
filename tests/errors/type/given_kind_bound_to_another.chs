# A name declared by `given` holds its kind when its numbers come
# (LANGUAGE.md §7): as if they had been typed first.
given x : scalar
y = 2 x
x = (1, 2, 3)
given R : SO3
z = R * R.T
R = [1, 2, 3; 4, 5, 6; 7, 8, 9]
