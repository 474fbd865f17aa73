# Lists are limited to a million items; the message gives the count.
xs = 0:1e7
[a + b for a in 0:1e4, b in 0:1e3]
0:0:1
