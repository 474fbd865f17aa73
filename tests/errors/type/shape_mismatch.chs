# multiplying incompatible shapes
[1, 2; 3, 4] * (1, 2, 3)
