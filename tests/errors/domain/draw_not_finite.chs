# A value with inf or NaN entries cannot be drawn; no file is written.
p = (inf, 0, 0)
draw(p)
draw([(k, 0, 0) for k in (0, inf)])
draw(view(0, 1))
