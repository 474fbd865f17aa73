//! The book's transform written as a block over symbols, `[R, p; 0, 1]`
//! with R in SO(3) (3.62), and its inverse in closed form (3.64):
//! T⁻¹ = `[Rᵀ, -Rᵀ p; 0, 1]`.

use crate::values::value::Sym;

/// Whether `s` is the constant number `x` (the literal `0` or `1` of a
/// transform's last row).
fn is_const(s: &Sym, x: f64) -> bool {
    matches!(s, Sym::Const(v, _) if v.as_scalar() == Some(x))
}

/// The inverse (3.64) of `[R, p; 0, 1]` (or `[R, p; 0, 0, 0, 1]`), given
/// that the checker typed it a transform in SE(3), so that R is a rotation
/// and Rᵀ = R⁻¹ (3.57): `[Rᵀ, -Rᵀ p; 0, 1]`. None for any other shape.
pub(super) fn inverse(s: &Sym) -> Option<Sym> {
    let Sym::Block(rows) = s else { return None };
    let [top, bottom] = rows.as_slice() else {
        return None;
    };
    let [r, p] = top.as_slice() else { return None };
    let last = match bottom.as_slice() {
        [z, o] if is_const(z, 0.0) && is_const(o, 1.0) => bottom.clone(),
        [a, b, c, o]
            if is_const(a, 0.0) && is_const(b, 0.0) && is_const(c, 0.0) && is_const(o, 1.0) =>
        {
            bottom.clone()
        }
        _ => return None,
    };
    let rt = r.clone().transpose();
    let moved = Sym::times(Sym::Neg(Box::new(rt.clone())), p.clone());
    Some(Sym::Block(vec![vec![rt, moved], last]))
}
