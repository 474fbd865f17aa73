# `*` of two column vectors: the student meant dot, .T or cross.
u = (1, 2, 3)
u * (1, 2, 3)
