# destructuring the wrong number of parts
(a, b, c) = AxisAng3((1, 2, 3))
