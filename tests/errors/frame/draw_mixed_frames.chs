# One picture shows one reference frame: {a} in {s} and {c} in {b} do not
# share one. T_sa * T_ab would put {b} in {s}.
T_sa = Trans((1, 0, 0))
T_bc = Trans((0, 1, 0))
draw(T_sa, T_bc)
