# inf and NaN: a domain error naming the cause, or the IEEE value with a warning
big = 2^1e308
undefined = inf - inf
Rotz(inf)
Normalize((inf, 0, 0))
inv([inf, 0; 0, 1])
exp([inf, 0; 0, 0])
MatrixLog3([inf - inf, 0, 0; 0, 1, 0; 0, 0, 1])
log(-1)
