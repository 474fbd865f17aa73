# exp of a vector: the book writes exp([w] theta)
exp((0, 0, 1))
