# two names side by side
T_ab T_bc
