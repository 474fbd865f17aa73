//! The θ = π branch of the logarithm of a rotation with no exact form
//! but made from exact numbers (§3.2.3.3; issue 21: never a wrong answer):
//! `Rotz(−π + 1e-20)` has a skew part sinθ ω̂ of −1.2e-16 in floats, below
//! rounding, so its floats read it as a half turn and its log as +ẑπ with
//! the note that −ω̂ is as valid; its skew part is −1e-20 in fact, and the
//! log −ẑ(π − 1e-20). The rotation's recipe is evaluated again in
//! certified ball arithmetic ([`super::certify`]): a skew part whose ball
//! excludes 0 is no half turn, and gives ω̂'s sign.

use super::ball;
use super::certify::{Memo, PRECISIONS, balls};
use crate::lie::{Vec3, so3::HalfTurn};
use crate::values::exact_mat::Entries;
use crate::values::value::Value;

/// The branch of the logarithm of the rotation block of `v` (3×3 or 4×4)
/// decided by certified arithmetic on its recipe, where its floats put θ
/// within rounding of π (cosθ < 0, ‖sinθ ω̂‖ ≤ 1e-12) and it has no exact
/// form (an exact one is decided by `values::exact_mat::half_turn`): not
/// a half turn when a skew entry's ball excludes 0, with sinθ ω̂ and cosθ
/// to the balls' midpoints. None where the floats decide (a float, θ
/// away from π, a recipe not bounded, or a skew part within its balls of
/// 0 at 512 bits).
pub fn half_turn(v: &Value) -> Option<HalfTurn> {
    if !crate::values::exact_mat::near_half_turn(v) || v.exact_form().is_some() {
        return None;
    }
    for prec in PRECISIONS {
        let b = balls(v, prec, &mut Memo::default())?;
        let at = |i: usize, j: usize| &b.data[i * b.cols + j];
        let d = [
            ball::sub(at(2, 1), at(1, 2), prec)?,
            ball::sub(at(0, 2), at(2, 0), prec)?,
            ball::sub(at(1, 0), at(0, 1), prec)?,
        ];
        if d.iter().any(ball::nonzero) {
            let mid = |x: &ball::Ball| 0.5 * ball::floats(x).0;
            let tr = ball::add(&ball::add(at(0, 0), at(1, 1), prec)?, at(2, 2), prec)?;
            let c = ball::sub(&tr, &ball::int(&1.into()), prec)?;
            return Some(HalfTurn {
                skew: Vec3::new(mid(&d[0]), mid(&d[1]), mid(&d[2])),
                cos: mid(&c),
                half_turn: false,
            });
        }
    }
    None
}

/// The entries of a matrix with no exact form but made from exact numbers,
/// by certified arithmetic on its recipe: the midpoints of their balls,
/// and which are certainly not 0 (at the first precision that shows every
/// entry nonzero, else at 512 bits); None for a float, a value with an
/// exact form (`values::exact_mat::exact_entries`), or a recipe not
/// bounded. What Euler angles near gimbal lock read (cos b = 1e-20 is 0 in
/// the floats of `Roty(π/2 − 1e-20)`, whose ZYX angles are then not
/// (0.1, π/2, 0) with a gimbal-lock warning but (0.3, π/2, 0.2)).
pub fn entries(v: &Value) -> Option<Entries> {
    let Value::Num { exact, .. } = v else {
        return None;
    };
    if exact.is_float() || v.exact_form().is_some() {
        return None;
    }
    let mut out = None;
    for prec in PRECISIONS {
        let b = balls(v, prec, &mut Memo::default())?;
        let zero: Vec<Option<bool>> = b
            .data
            .iter()
            .map(|x| ball::nonzero(x).then_some(false))
            .collect();
        let done = zero.iter().all(Option::is_some);
        out = Some(Entries {
            floats: b.data.iter().map(|x| ball::floats(x).0).collect(),
            zero,
        });
        if done {
            break;
        }
    }
    out
}
