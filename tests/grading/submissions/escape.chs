# Tries to write outside its folder; nothing is written under --no-write.
save(draw(Rotz(1)), "../../escaped.svg")
save(draw(Rotz(1)), "/tmp/chasles-escaped.svg")
assert 1 + 1 == 2  # (a) still graded
