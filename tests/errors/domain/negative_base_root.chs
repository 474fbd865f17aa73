# A negative base to a fractional power is not real; the message names the
# base it means, (-8), and the real cube root.
(-8)^(1/3)
-8^(1/3)
