# Modern Robotics, Exercise 19(c) (§2.7, Figure 2.29(b)): a four-fingered hand with a
# fixed palm grasping an ellipsoidal object without slip. Reading: each no-slip
# fingertip point contact acts as a spherical joint, so each finger is a URRS leg
# from the palm (ground) to the object.
# N = 2 + 4·3 = 14, J = 16: dof = 6(14 − 1 − 16) + 8·1 + 4·2 + 4·3 = 10.
hand = mech < legs 4 URRS; spatial >
dof(hand)

# --- The expected values, checked ---------------------------------------------
assert dof(hand) == 10
