# LANGUAGE.md §5: a 4×4 with last row (0, 0, 0, 1) whose rotation block is
# no rotation is bound with a warning giving the distance. The book's
# Exercise 3.25(a) prints A with r₃₃ = 1 (a misprint: A is not in SE(3)).
X = [1, 0, 0, 1; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1]
A = [0, 0, 1, 0; 0, 1, 0, 1; -1, 0, 1, 0; 0, 0, 0, 1]    # warning: 1.7321 from SE(3)
B = inv(X) A X                                         # a plain 4×4 product
log(A)                                                 # error: not a transform
A = [0, 0, 1, 0; 0, 1, 0, 1; -1, 0, 0, 0; 0, 0, 0, 1]    # r₃₃ = 0: a transform
B = inv(X) A X
