//! A stated assumption holds for every later use of its symbol, and the
//! value that relied on it says so when numbers break it (LANGUAGE.md §7).
//! After `R = exp([u] θ)` notes that u is assumed a unit vector, `d =
//! dot(u, u) == 1` is true; the comparison is kept as a tree (shown
//! decided in closed form), and the binding remembers which axes its
//! closed form took as unit vectors. Once numbers are bound to such an
//! axis, reading the value computes it again with them (a bool is a value
//! like any other: `false` at u = (1, 1, 0)), and when they are not a unit
//! vector a warning names the assumption and the numbers that break it —
//! never a stale `true` printed silently.

use super::env::Relied;
use super::interp::Interp;
use super::value::{Sym, Value};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{CmpOp, Span};
use crate::syntax::name::Name;

/// How far ‖u‖ may be from 1 before numbers bound to u break the
/// assumption (the numbers as typed: `(0.6, 0, 0.8)` is exactly a unit
/// vector).
const UNIT_TOL: f64 = 1e-9;

impl Interp<'_> {
    /// `a op b` decided `true` or `false` over trees whose closed form took
    /// a `given` axis as a unit vector: the comparison itself, kept as a
    /// tree (decided again when it is read with numbers). None when no
    /// side is a tree or no axis was assumed.
    pub(super) fn relied_comparison(&self, op: CmpOp, a: &Value, b: &Value) -> Option<Value> {
        if !matches!(a, Value::Sym(_)) && !matches!(b, Value::Sym(_)) {
            return None;
        }
        let to = crate::seam::apply::to_sym;
        let tree = Sym::Compare(op, Box::new(to(a)), Box::new(to(b)));
        (!self.unit_axes_of(&tree).is_empty()).then_some(Value::Sym(tree))
    }

    /// After `name` is bound: remembers the axes its closed form took as
    /// unit vectors (or forgets what an earlier binding of it relied on).
    #[inline]
    pub(super) fn note_reliance(&mut self, name: Name) {
        // (most sessions assume no axis a unit vector: nothing to do)
        if !(self.env.relied.is_empty() && self.env.units_noted.is_empty()) {
            self.note_reliance_of(name);
        }
    }

    /// [`Interp::note_reliance`] where an axis has been assumed a unit.
    #[inline(never)]
    fn note_reliance_of(&mut self, name: Name) {
        self.env.relied.retain(|r| r.name != name.as_str());
        let Some(b) = self.env.get(name) else {
            return;
        };
        let stamp = b.stamp;
        let axes = match b.val.as_ref() {
            Some(Value::Sym(s)) if !b.symbolic => self.unit_axes_of(s),
            _ => return,
        };
        if !axes.is_empty() {
            self.env.relied.push(Relied {
                name: name.to_string(),
                stamp,
                axes,
            });
        }
    }

    /// `name` read as `v`: a comparison kept over an axis assumed unit
    /// reads as its bool while the axis is free ([`Interp::decided_now`]),
    /// and the warnings of the assumptions numbers broke since go to
    /// `warnings` ([`Interp::broken_assumptions`]).
    pub(super) fn relied_read(
        &self,
        name: &str,
        v: Option<Value>,
        span: Span,
        warnings: &mut Vec<Diagnostic>,
    ) -> Option<Box<Value>> {
        if !self.env.relied.is_empty() {
            warnings.extend(self.broken_assumptions(name, span));
        }
        // (boxed here, as the result holds it: not moved on by value)
        match v.as_ref().and_then(|x| self.decided_now(x)) {
            Some(b) => Some(Box::new(b)),
            None => v.map(Box::new),
        }
    }

    /// The warnings of reading `name` now: one for each axis its value
    /// took as a unit vector that is now bound to numbers that are not one.
    fn broken_assumptions(&self, name: &str, span: Span) -> Vec<Diagnostic> {
        if self.env.relied.is_empty() {
            return Vec::new();
        }
        let Some(b) = self.env.get(name) else {
            return Vec::new();
        };
        let Some(r) = self
            .env
            .relied
            .iter()
            .find(|r| r.name == name && r.stamp == b.stamp)
        else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for axis in &r.axes {
            let Some(v @ Value::Num { m, .. }) = self.env.get(&**axis).and_then(|x| x.val.as_ref())
            else {
                continue;
            };
            // (a screw axis S = (ω, v) assumed ‖ω‖ = 1, Proposition 3.16)
            let norm = m.iter().take(3).map(|x| x * x).sum::<f64>().sqrt();
            // (a screw axis with ω = 0 is the case the note also gave:
            // exp([S] θ) = [I, v θ; 0, 1])
            if (norm - 1.0).abs() <= UNIT_TOL || (m.len() == 6 && norm == 0.0) {
                continue;
            }
            let (what, n) = if m.len() == 6 {
                (
                    format!("{axis} = (ω, v) has ‖ω‖ = 1"),
                    format!("‖ω‖ = {}", short(norm)),
                )
            } else {
                (
                    format!("{axis} is a unit vector, ‖{axis}‖ = 1"),
                    format!("‖{axis}‖ = {}", short(norm)),
                )
            };
            out.push(
                Diagnostic::warning(
                    ErrorKind::Domain,
                    span,
                    format!(
                        "{name} was computed assuming {what}; {axis} = {} breaks it ({n}): {name} is computed again with these numbers",
                        crate::values::format::inline(v, 4)
                    ),
                )
                .with_help(format!(
                    "the assumption was noted where exp([{axis}] θ) was first put in closed form; bind a unit {axis} (divide by its norm) to keep it"
                )),
            );
        }
        out
    }
}

/// A norm on one line, 4 decimals at most.
fn short(x: f64) -> String {
    crate::values::number::fmt_num(x, 4)
}
