//! `==` over `given` names where the trees alone cannot decide
//! (LANGUAGE.md §7, "what a `given` kind says is used"): the kinds written
//! out (Rᵀ = R⁻¹ for R in SO(3), Prop. 3.3; Wᵀ = −W in so(3)), then the
//! algebra of the book's block transforms ((T U)⁻¹ = U⁻¹ T⁻¹, 3.63–3.64;
//! Ad_{TU} = Ad_T Ad_U). Both only ever add a `true`: what they cannot
//! prove stays "cannot decide".

use super::compare::equal;
use super::interp::Interp;
use super::value::Value;
use crate::check::ty::Kind;
use crate::syntax::ast::CmpOp;

impl Interp<'_> {
    /// [`equal`], and where it cannot decide two trees over `given`
    /// matrices, the same with what their names' kinds say written out
    /// ([`crate::decide::equality::with_kinds`]: `inv(R) == R^T` for a
    /// rotation R, `W^T == -W` for W in so(3)).
    fn equal_by_kinds(&self, a: &Value, b: &Value, op: CmpOp) -> Result<Option<bool>, String> {
        let first = equal(a, b, op);
        if !matches!(first, Ok(None))
            || op.is_order()
            || !(matches!(a, Value::Sym(_)) || matches!(b, Value::Sym(_)))
        {
            return first;
        }
        let kind_of = |n: &str| self.env.get(n).filter(|b| b.symbolic).map(|b| b.ty.kind);
        let canon = |v: &Value| {
            Value::Sym(crate::decide::equality::with_kinds(
                &crate::seam::apply::to_sym(v),
                &kind_of,
            ))
        };
        match equal(&canon(a), &canon(b), op) {
            Ok(Some(true)) => Ok(Some(true)),
            _ => first,
        }
    }

    /// [`equal`], and for trees over `given` matrices that it cannot
    /// tell, the algebra of their blocks ([`crate::decide::blocks`]: the
    /// book's transforms, (T U)⁻¹ = U⁻¹ T⁻¹) with the names typed SO(3)
    /// or SO(2) as rotations.
    pub(super) fn equal_trees(
        &self,
        a: &Value,
        b: &Value,
        op: CmpOp,
    ) -> Result<Option<bool>, String> {
        let v = self.equal_by_kinds(a, b, op);
        if op == CmpOp::Eq
            && matches!(v, Ok(None))
            && (matches!(a, Value::Sym(_)) || matches!(b, Value::Sym(_)))
        {
            let to = crate::seam::apply::to_sym;
            let rotation = |n: &str| match self.env.get(n) {
                Some(b) if b.symbolic && b.ty.kind == Kind::SO3 => Some(3),
                Some(b) if b.symbolic && b.ty.kind == Kind::SO2 => Some(2),
                _ => None,
            };
            if crate::decide::blocks::equal(&to(a), &to(b), &rotation) {
                return Ok(Some(true));
            }
        }
        v
    }
}
