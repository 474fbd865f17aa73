# an unknown joint letter
mech < links 3; joints R X; spatial >
