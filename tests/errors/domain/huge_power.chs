# integer powers are computed by squaring; exponents beyond 1e15 are refused
R = Rotz(1)^1000000000
[1, 2; 3, 4]^1e300
Rotz(1)^0.5
# products are bounded by their work (at most 1e9 multiply-adds)
eye(1500) * eye(1500)
eye(2000)^1000000000
