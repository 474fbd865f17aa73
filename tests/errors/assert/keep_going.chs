# With --keep-going every failed assertion is reported; the passing ones
# print nothing. A vector compared with a twist of another length is a
# type error, not a false assertion.
V_s = (0, 0, 1, 2, 0, 0)
assert V_s.w == (0, 0, 1)
assert V_s.v == (2, 0, 1)
assert norm(V_s.w) ~= 1
assert V_s == (0, 0, 1)
