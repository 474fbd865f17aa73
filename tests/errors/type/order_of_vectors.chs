# `<`, `<=`, `>`, `>=` order numbers; a vector has no order.
1 < 2
(1, 2, 3) < (2, 3, 4)
norm((1, 2, 3)) < norm((2, 3, 4))
