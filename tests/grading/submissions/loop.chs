# A loop that does not end in any sensible time: stopped by --timeout.
x = 1
assert x == 1  # (a) before the loop
y = len([det(k * eye(200)) for k in 1:1000000])
assert y == 1000000  # (b) after the loop
