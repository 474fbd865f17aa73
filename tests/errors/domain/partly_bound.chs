# Numbers bound while other symbols are free (LANGUAGE.md §7): refused where
# the same numbers typed first are, though the canonical form cancelled the
# division ((a b)/(a b) is 1 over free a and b).
given a, b, c : scalar
y = (a*b)/(a*b) + c
z = a/b + c
b = 0
y
z
