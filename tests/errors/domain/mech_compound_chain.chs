# The book names a serial chain by its letters ("an RRRP open chain",
# example 2.7) and a compound joint too (the RP pair of example 2.1):
# letters written together are one compound joint, and where that leaves
# too few joints to connect the links, both readings are shown, not one
# answered (read as one joint, the SCARA would have 22 dof).
mech < links 5; joints RRRP; spatial >
mech < links 5; joints R R R P; spatial >
mech < links 9; joints 2RP; planar >
# The caterpillar of exercise 2.18(a): seven RP pairs join eight links.
mech < links 8; joints 7RP; planar >
# A count a hair from a whole number shows all its digits.
n = 4.0000000001
mech < links n; joints 4R; planar >
