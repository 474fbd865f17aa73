//! What a binding's name says beyond its frames (LANGUAGE.md §3–4): `given
//! u_b : free` declares that a name holds a free vector (or `: point` a
//! point), for names whose letters do not say it ([`crate::check::role`]);
//! and the book's twist, screw and wrench names bind a pair of 3-vectors as
//! the 6-vector it stands for: `V_s = (w_s, v_s)` is the twist (ω, v)
//! (§3.3.2), `S = (ω, v)` a screw axis, `F = (m, f)` a wrench (§3.4).
//! And a 4×4 bound to a plain name that looks like a transform — last row
//! (0, 0, 0, 1) — but whose rotation block is no rotation is named at
//! binding (§5): the book's Exercise 3.25(a) prints such an A (r₃₃ = 1).

use super::env::Binding;
use super::interp::{Interp, Typed};
use super::value::{Sym, Value};
use crate::check::role::Role;
use crate::check::rules::same_frames;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::apply;
use crate::syntax::ast::{Expr, ExprKind, Ident, Name, Span};

impl Interp<'_> {
    /// The value of `name = value`: a pair of 3-vectors under a twist,
    /// screw or wrench name is stacked into the 6-vector; `I` under a
    /// rotation or transform name is its identity; anything else is the
    /// value as written.
    pub(super) fn assigned(&mut self, name: Name, value: &Expr) -> Result<Typed, Diagnostic> {
        if let ExprKind::Paren(items) = &value.kind
            && let [a, b] = items.as_slice()
            && matches!(self.env.claim(name).letter, Some('V' | 'S' | 'B' | 'F'))
        {
            let (ta, tb) = (self.expr(a)?, self.expr(b)?);
            let three = |t: &Typed| matches!(t.ty.kind, Kind::Vector(Some(3)));
            if three(&ta) && three(&tb) {
                return self.stacked(name, ta, tb, (a.span, b.span), value.span);
            }
            return self.paren_of(vec![ta, tb], value.span);
        }
        // `R_01 = I`, `T_sb = I`: the name says a rotation or a transform
        // (§5), so `I` alone is the identity of the book's spatial group,
        // 3×3 or 4×4 (§4: the size its context needs; planar, `eye(2)`)
        if let ExprKind::Var(v) = &value.kind
            && *v == **super::env::IDENTITY
            && self.env.get(*super::env::IDENTITY).is_none()
        {
            let claim = self.env.claim(name);
            let n = match (claim.letter, claim.frames) {
                (Some('R'), crate::check::ty::Frames::Pair(..)) => Some(3),
                (Some('T'), crate::check::ty::Frames::Pair(..)) => Some(4),
                _ => None,
            };
            return self.sized_identity(n, value);
        }
        self.expr(value)
    }

    /// (ω, v) or (m, f) as one 6-vector, both parts in one frame.
    fn stacked(
        &mut self,
        name: Name,
        a: Typed,
        b: Typed,
        spans: (Span, Span),
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        let frames = match same_frames("stack", &a.ty, &b.ty) {
            Ok(f) => f,
            Err(mut e) => {
                let what = match self.env.claim(name).letter {
                    Some('F') => "a wrench (m, f)",
                    Some('V') => "a twist (ω, v)",
                    _ => "a screw axis (ω, v)",
                };
                e.message = format!("the two parts of {what} are in different frames");
                e.help = Some(
                    "express both in one frame first: rotate a vector with R_ab (ω_a = R_ab ω_b)"
                        .into(),
                );
                self.rule_failure(e, span, Some(spans.0), Some(spans.1), None)?;
                crate::check::ty::Frames::None
            }
        };
        let ty = Ty::new(Kind::Vector(Some(6)), frames);
        let val = match (a.val, b.val) {
            (Some(x), Some(y)) => {
                let rows = [vec![*x], vec![*y]];
                let v = apply::block(&rows).unwrap_or_else(|| apply::block_numeric(&rows));
                Some(v.map_err(|m| apply::Op::Block(&[1, 1]).failure(m, span))?)
            }
            _ => None,
        };
        Ok(Typed::new(ty, val))
    }

    /// `given u_b, n : free` (`: point`, `free2`, `point2`): each name
    /// holds a free vector (a point) from now on, whatever its letters say;
    /// a name bound to a vector keeps its value, another is declared as a
    /// symbolic `len`-vector.
    pub(super) fn given_role(&mut self, names: &[Ident], role: Role, len: usize) {
        for n in names {
            let claim = self.env.declare_role(n.name, role);
            let free = role.is_free();
            if let Some(b) = self.env.vars.get_mut(&super::env::Key(n.name))
                && b.ty.kind.is_vector()
            {
                b.ty.free = free;
                continue;
            }
            let ty = claim.given_ty(Kind::Vector(Some(len)));
            let val = Value::Sym(Sym::Name(String::from(n.name)));
            self.env.set(
                n.name,
                Binding {
                    ty,
                    val: Some(val),
                    symbolic: true,
                    derived: false,
                    stamp: 0,
                    absorbed: Vec::new(),
                },
            );
        }
    }
}

impl Interp<'_> {
    /// `A = [0, 0, 1, 0; 0, 1, 0, 1; -1, 0, 1, 0; 0, 0, 0, 1]`: a warning
    /// giving the distance to SE(3) (DistanceToSE3) when a plain 4×4 with
    /// last row (0, 0, 0, 1) is farther from SE(3) than book rounding.
    pub(super) fn transform_lookalike(&mut self, name: &str, t: &Typed, span: Span) {
        use super::convert::{Group, Membership, membership};
        let Some(Value::Num {
            m,
            kind: Kind::Matrix(Some(4), Some(4)),
            ..
        }) = t.value()
        else {
            return;
        };
        if m.shape() != (4, 4) || !m.row(3).eq([0.0, 0.0, 0.0, 1.0]) {
            return;
        }
        let Membership::Outside { distance, det } = membership(m, Group::SE3) else {
            return;
        };
        let fmt = |x: f64| crate::values::number::fmt_num(x, 4);
        self.warnings.push(
            Diagnostic::warning(
                ErrorKind::Domain,
                span,
                if det > 0.0 && distance < 1e8 {
                    format!(
                        "{name} looks like a transform (last row 0, 0, 0, 1) but is not one: it is {} from SE(3) (DistanceToSE3)",
                        fmt(distance)
                    )
                } else {
                    format!(
                        "{name} looks like a transform (last row 0, 0, 0, 1) but is not one: its rotation block has det {} (a rotation's is 1)",
                        fmt(det)
                    )
                },
            )
            .with_help(format!(
                "products with {name} are plain 4×4 products; check the entries (a misprint?): a rotation block has orthonormal columns and det R = 1 (Prop. 3.1)"
            )),
        );
    }
}
