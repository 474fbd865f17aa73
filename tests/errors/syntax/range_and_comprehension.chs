# A range has at most two colons; a comprehension one expression before `for`.
0:1:2:3
[1, 2 for k in 0:4]
[k for k in]
