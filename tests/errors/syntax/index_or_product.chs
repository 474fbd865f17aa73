# A bracket after a name, with a space: `R[1, 2]` indexes and
# `R * [1, 2]` multiplies; `R [1, 2]` could be either.
R = Rotz(30 deg)
R [1, 2]
R [1]
# The book's bracket of a vector is a product, space or not, and so is a
# vector of three entries (an index has one or two).
w = (0, 0, 1)
sin(30 deg) [w]
R [1, 0, 0]
