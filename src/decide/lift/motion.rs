//! The exponential of a rotation or a motion lifted as a rotation's angle
//! is: `exp([ω̂] θ)` and `exp([S] θ)` are Rodrigues' formula (3.51) and
//! Proposition 3.25 in cos θ and sin θ, so `exp([ẑ] 0.1) exp([ẑ] 0.2) ==
//! exp([ẑ] 0.3)` is proven as `Rotz(0.1) Rotz(0.2) == Rotz(0.3)` is, and
//! so are angles in degrees. The argument M (an exact so(3) or se(3)
//! matrix, or the 3- or 6-vector of one, its entries a + bπ with a and b
//! rational or surds) is θ·M̂ with its ω̂ a unit vector (rational, or with
//! surd entries: `(1, 1, 1)/√3`) and θ = α + βπ, α and β rational; read as the lift
//! reads angles (θ·ν, or whole multiples of μ = 1/M and ρ = π/L), θ
//! becomes Θ, and M becomes M̂·Θ. The exponential of that, made by the
//! symbolic engine, is a function of the lift's symbols whose value at
//! their numbers (ν = 1, μ = 1/M, ρ = π/L) is e^M: the same argument as
//! for a sine's angle, so an identity between the lifted forms holds at
//! those numbers. Unlike a sine's, θ is not taken modulo 2π: a screw of
//! pitch h ≠ 0 translates by 2πh in a whole turn.

use super::Lift;
use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::{Expr, Var};
use crate::sym::surd::Surd;
use crate::values::exact::Operation;

/// `m`, the lifted operand `i` of operation `op`, with its angle read by
/// `lift` when `op` is an exponential and `m` its argument, of the form
/// [`angle_read`] reads; else left as it is.
pub(super) fn read_angle(op: &Operation, i: usize, m: &mut Mat, lift: &mut Lift) {
    if i == 0
        && exponential(op)
        && let Some(read) = angle_read(m, lift)
    {
        *m = read;
    }
}

/// True for the builtins that take the exponential of an so(3) or se(3)
/// argument (`exp` of a matrix of those kinds, MatrixExp3, MatrixExp6).
fn exponential(op: &Operation) -> bool {
    let Operation::Call(name) = op else {
        return false;
    };
    crate::builtins::lookup(name)
        .is_some_and(|b| matches!(b.name, "exp" | "MatrixExp3" | "MatrixExp6"))
}

/// `m`, the lifted argument of an exponential ([`exponential`]), with its
/// angle read by `lift` (the module's doc): M = θ·M̂ with ω̂ a unit vector
/// and θ = α + βπ (α, β rational, θ ≠ 0), lifted as M̂·Θ for Θ the angle θ
/// as the lift reads it. M̂'s entries may be surds (an axis typed unit,
/// `(1, 1, 1)/sqrt(3)` or `w/norm(w)`), so long as θ is rational and
/// M̂'s surds come to no float: Rodrigues' formula then has those surds as
/// coefficients, exactly. None when M is not an exact so(3) or se(3)
/// matrix or vector of that form (an angle that is not a + bπ, an axis
/// whose norm is not rational, `(1, 1, 0)`, a translation not along θ):
/// it is then lifted as it is.
fn angle_read(m: &Mat, lift: &mut Lift) -> Option<Mat> {
    let parts: Vec<(Surd, Surd)> = m
        .data
        .iter()
        .map(super::surd_and_pi)
        .collect::<Option<_>>()?;
    let a: Vec<Surd> = parts.iter().map(|(x, _)| x.clone()).collect();
    let b: Vec<Surd> = parts.iter().map(|(_, y)| y.clone()).collect();
    let (wa, wb) = (
        rotation_part(m.rows, m.cols, &a)?,
        rotation_part(m.rows, m.cols, &b)?,
    );
    // (θ = α + βπ and M̂ from the rational part when it has a rotation,
    // else from the part in π; the other part must be the same M̂ scaled)
    let (alpha, beta, hat) = match rational_norm(&wa)? {
        n if !n.is_zero() => {
            let inv = n.inv()?;
            let beta = dot(&wb, &wa)?.as_rat()?.mul(&inv);
            (n, beta, scaled(&a, &inv))
        }
        _ => {
            let n = rational_norm(&wb)?;
            let hat = scaled(&b, &n.inv()?);
            (Rat::ZERO, n, hat)
        }
    };
    if scaled(&hat, &alpha) != a || scaled(&hat, &beta) != b {
        return None;
    }
    let theta =
        Expr::constant(Coef::rat(alpha)).add(&Expr::constant(Coef::rat(beta)).mul(&Expr::pi()));
    // (as it is: e^{[S](θ + 2π)} is e^{[S]θ} only for a screw of pitch 0)
    let read = lift.angle_of(&theta, false)?;
    let data = hat
        .into_iter()
        .map(|r| Expr::constant(Coef::real(r)).mul(&read))
        .collect();
    Some(Mat { data, ..*m })
}

/// `e` with the split's μ and ρ (1/M and π/L, [`Lift::split`]) at their
/// numbers where they stand alone, outside a sine's e^{iρ} and outside a
/// kept call: the linear part of a screw's exponential in its angle
/// (Prop. 3.25's Iθ and (θ − sin θ)), which an exact form beside it
/// holds as a multiple of π.
pub(super) fn bare_angles_at(e: &Expr, m: i64, l: i64) -> Expr {
    let (Some(mu), Some(rho)) = (Rat::int(m).inv(), Rat::int(l).inv()) else {
        return e.clone();
    };
    let mut out = Expr::default();
    for (mono, c) in &e.terms {
        let mut t = Expr::constant(c.clone());
        for (v, k) in mono {
            let f = match v {
                Var::Sym(s) if *s.name == *super::MU => Expr::constant(Coef::rat(mu.clone())),
                Var::Sym(s) if *s.name == *super::RHO => Expr::pi().scale(&Coef::rat(rho.clone())),
                _ => Expr::var(v.clone()),
            };
            t = t.mul(&f.powi(i64::from(*k)).unwrap_or_default());
        }
        out = out.add(&t);
    }
    out
}

/// Each of `x` times `k`.
fn scaled(x: &[Surd], k: &Rat) -> Vec<Surd> {
    x.iter().map(|r| r.scale(k)).collect()
}

/// u·w (None when a product of roots is too large to hold).
fn dot(u: &[Surd; 3], w: &[Surd; 3]) -> Option<Surd> {
    u.iter()
        .zip(w)
        .try_fold(Surd::ZERO, |s, (x, y)| Some(s.add(&x.mul(y)?)))
}

/// ω of an so(3) matrix, an se(3) matrix, a 3-vector ω or a 6-vector
/// (ω, v), from its entries `x` row by row; None for any other shape, or
/// a matrix that is not of that form exactly (not skew, a bottom row that
/// is not 0).
fn rotation_part(rows: usize, cols: usize, x: &[Surd]) -> Option<[Surd; 3]> {
    let at = |i: usize, j: usize| &x[i * cols + j];
    match (rows, cols) {
        (3 | 6, 1) => Some([x[0].clone(), x[1].clone(), x[2].clone()]),
        (3, 3) | (4, 4) => {
            for i in 0..3 {
                for j in 0..3 {
                    if *at(i, j) != at(j, i).neg() {
                        return None;
                    }
                }
            }
            if rows == 4 && !(0..4).all(|j| at(3, j).is_zero()) {
                return None;
            }
            Some([at(2, 1).clone(), at(0, 2).clone(), at(1, 0).clone()])
        }
        _ => None,
    }
}

/// ‖w‖ when it is rational (w·w the square of a rational: so for a
/// unit axis with surd entries, `(1, 1, 1)/√3`, but not `(1, 1, 0)`).
fn rational_norm(w: &[Surd; 3]) -> Option<Rat> {
    Surd::sqrt_of(&dot(w, w)?.as_rat()?)?.as_rat()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i128, d: i128) -> Rat {
        Rat::new(n, d).expect("a fraction")
    }

    fn rat(n: i128, d: i128) -> Surd {
        Surd::rat(q(n, d))
    }

    #[test]
    fn the_rotation_part_and_its_norm() {
        let z = [Surd::ZERO, Surd::ZERO, rat(1, 10)];
        // [ẑ] 0.1, row by row
        let m = [
            Surd::ZERO,
            rat(-1, 10),
            Surd::ZERO,
            rat(1, 10),
            Surd::ZERO,
            Surd::ZERO,
            Surd::ZERO,
            Surd::ZERO,
            Surd::ZERO,
        ];
        assert_eq!(rotation_part(3, 3, &m), Some(z.clone()));
        assert_eq!(rational_norm(&z), Some(q(1, 10)));
        // (3/50, 4/50, 0): a norm of 1/10; (1/10, 1/10, 0) has none rational
        assert_eq!(
            rational_norm(&[rat(3, 50), rat(4, 50), Surd::ZERO]),
            Some(q(1, 10))
        );
        assert_eq!(rational_norm(&[rat(1, 10), rat(1, 10), Surd::ZERO]), None);
        // (1, 1, 1)/√3 and (1, 2, 3)/√14 are unit axes with surd entries
        let third = Surd::sqrt_of(&q(1, 3)).expect("√(1/3)");
        assert_eq!(
            rational_norm(&[third.clone(), third.clone(), third]),
            Some(q(1, 1))
        );
        let w: Vec<Surd> = (1..=3)
            .map(|k| Surd::sqrt_of(&q(k * k, 14)).expect("a root"))
            .collect();
        assert_eq!(
            rational_norm(&[w[0].clone(), w[1].clone(), w[2].clone()]),
            Some(q(1, 1))
        );
        // not skew: no rotation part
        let mut bent = m.clone();
        bent[0] = rat(1, 10);
        assert_eq!(rotation_part(3, 3, &bent), None);
        // a 6-vector's first three entries
        let v: Vec<Surd> = (1..=6).map(|k| rat(k, 1)).collect();
        assert_eq!(
            rotation_part(6, 1, &v),
            Some([rat(1, 1), rat(2, 1), rat(3, 1)])
        );
        assert_eq!(rotation_part(2, 2, &v[..4]), None);
    }
}
