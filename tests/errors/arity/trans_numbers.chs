# Trans takes a 3-vector or its three numbers.
Trans(2, 2, 0)
Trans((2, 2, 0))
Trans(2, 2)
