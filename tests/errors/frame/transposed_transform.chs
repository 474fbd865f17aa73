# the transpose is the inverse only for rotations (Prop. 3.1): for a
# transform T⁻¹ = [Rᵀ, −Rᵀp; 0, 1] (Prop. 3.10), so T_ab.T is no transform
T_ab = RpToTrans(Rotz(pi/2), (1, 2, 0))
p_a = (1, 0, 0)
R_ab = T_ab.R
R_ab.T * (0, 1, 0)
T_ab.T * p_a
inv(T_ab) * p_a
T_ab^T * p_a
