# The identities of the exponential decided by `==` with numbers (§3.2.3,
# §3.3.3; session 25).
#
# Covers:
#   - one rotation written two ways: e^{[ẑ]θ} (3.51) and Rot(ẑ, θ) (3.18),
#     at a decimal angle and in degrees;
#   - a one-parameter subgroup adds its angles, e^{[ω̂]a} e^{[ω̂]b} =
#     e^{[ω̂](a+b)}, for a rotation and for a screw of pitch 0.5 (Prop. 3.25),
#     and about a unit axis with surd entries, ω̂ = (1, 1, 1)/√3;
#   - R Rᵀ = I and det R = 1 (Prop. 3.1) of an exponential;
#   - a whole turn more is the same rotation, but a pitched screw moves
#     2πh along its axis: `false`;
#   - Ad_{T1 T2} = Ad_{T1} Ad_{T2} (Prop. 3.20) of exponentials;
#   - the logarithm of an exponential is its argument while θ < π (the
#     principal branch of §3.2.3.3 and §3.3.3.2), and past it X turned
#     back by whole turns, ω̂(θ − 2π) for θ = 4;
#   - the logarithm of a whole turn is 0 (case (a) of §3.2.3.3), and a
#     pure translation's for a screw of pitch 0.5 (session 28).
# Each `==` is proven from how its sides were made (Rodrigues' formula with
# the angles read exactly), never from rounded floats: a side that differs
# by a hundredth is `false`.

exp([(0, 0, 1)] 0.1) == Rotz(0.1)
exp([(0, 0, 1)] 10 deg) == Rotz(10 deg)
exp([(0, 0, 1)] 0.1) * exp([(0, 0, 1)] 0.2) == exp([(0, 0, 1)] 0.3)
exp([(0, 0, 1)] 0.1) * exp([(0, 0, 1)] 0.2) == exp([(0, 0, 1)] 0.31)

w = (1, 1, 1)/sqrt(3);
exp([w] 0.1) * exp([w] 0.2) == exp([w] 0.3)
exp([w] 1) == Rot((1, 1, 1), 1)

S = (0.6, 0.8, 0, 0.3, 0.4, 0);
h = dot(S[1:3], S[4:6])
exp([S] 10 deg) * exp([S] 20 deg) == exp([S] 30 deg)

R = exp([(1, 2, 2)/3] 0.5);
R * R.T == eye(3)
det(R) == 1
R == exp([(1, 2, 2)/3] (0.5 + 2 pi))
exp([S] 0.5) == exp([S] (0.5 + 2 pi))

T1 = exp([(0, 0, 1, 0, 2, 0)] 0.3);
T2 = exp([S] 0.7);
Ad(T1 * T2) == Ad(T1) * Ad(T2)

log(exp([w] 0.5)) == [w] 0.5
MatrixLog6(MatrixExp6((0, 0, 1, 0, 2, 0) * 3)) == (0, 0, 1, 0, 2, 0) * 3
log(exp([(0, 0, 1)] 4)) == [(0, 0, 1)] 4
log(exp([(0, 0, 1)] 4)) == [(0, 0, 1)] (4 - 2 pi)
log(Rotz(2 pi)) == zeros(3, 3)
MatrixLog6(exp([S] 2 pi)) == (0, 0, 0, 0.6, 0.8, 0) * pi

assert exp([(0, 0, 1)] 0.1) * exp([(0, 0, 1)] 0.2) == exp([(0, 0, 1)] 0.3)
assert h == 0.5
