# A value with inf or NaN entries, or a symbol, cannot be drawn; no file is written.
p = (inf, 0, 0)
draw(p)
draw([(k, 0, 0) for k in (0, inf)])
draw(view(0, 1))
given T_ab : SE3
draw(T_ab)
