//! Symbolic axes in closed form (LANGUAGE.md §7, issue 21). A `given`
//! vector, screw axis, twist or wrench is a name in the tree of symbols
//! (`[w] t`, `exp([S] θ) T_sb`), so that frame algebra prints as the book
//! writes it. Where a result is built from such names, numbers and
//! symbolic values only, and asks for a closed form (an `exp`, `Rot`,
//! `det`, a product with a symbolic matrix), it is shown computed: each
//! name becomes the column of its components `w[1]`, `w[2]`, `w[3]` and
//! the tree is evaluated by the same operations on canonical forms. An
//! exponential of such an axis assumes the book's ω̂ is a unit vector
//! ([`crate::sym::axis`]); the assumption spreads to every operand that
//! meets it, and a note says it was made. The binding keeps the tree, so
//! numbers bound later are put into the operations as typed (a
//! non-unit w then gives the numeric exp of \[w\] t, not the formula).

use super::interp::Interp;
use super::ops::Sel;
use super::value::{Sym, Value};
use crate::builtins;
use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::apply::{self, Op};
use crate::sym::axis;
use crate::sym::matrix::Mat;
use crate::syntax::ast::{BinOp, CmpOp, Span};
use crate::values::formula;
use std::cell::RefCell;
use std::sync::Arc;

/// The components of a `given` vector of this kind: 3 for a 3-vector, 6
/// for a 6-vector, twist, screw axis or wrench; None for matrices.
fn entries(kind: &Kind) -> Option<u8> {
    match kind {
        Kind::Vector(Some(3)) => Some(3),
        Kind::Vector(Some(6)) | Kind::Twist | Kind::Screw | Kind::Wrench => Some(6),
        _ => None,
    }
}

/// What a name in the tree is now: a `given` vector's kind (and whether
/// a note has said it is assumed a unit axis: the assumption then holds
/// for every later use, §7), or a number.
enum Leaf {
    Vector(Kind, bool),
    Number(Value),
}

/// Every leaf can be computed with: names of `given` vectors (or of
/// numbers), numbers and formulas; and some node asks for a closed form
/// (a call, or a symbolic matrix such as `Rotz(t)` among the operands —
/// not a symbolic scalar: `[w] t` stays as typed).
fn worth_lowering(s: &Sym, leaf: &dyn Fn(&str) -> Option<Leaf>, asks: &mut bool) -> bool {
    match s {
        Sym::Name(n) => n == "deg" || leaf(n).is_some(),
        Sym::Const(v, _) => match &**v {
            Value::Num { .. } => true,
            Value::Formula { m, .. } => {
                *asks |= m.data.len() > 1;
                true
            }
            _ => false,
        },
        Sym::Identity(_) => false,
        // (a comparison decided in closed form: `dot(u, u) == 1`)
        Sym::Compare(_, a, b) => {
            *asks = true;
            worth_lowering(a, leaf, asks) && worth_lowering(b, leaf, asks)
        }
        Sym::Call(_, xs) => {
            *asks = true;
            xs.iter().all(|x| worth_lowering(x, leaf, asks))
        }
        Sym::Product(xs) | Sym::Vector(xs) => xs.iter().all(|x| worth_lowering(x, leaf, asks)),
        Sym::Block(rows) => rows.iter().flatten().all(|x| worth_lowering(x, leaf, asks)),
        Sym::Inv(x)
        | Sym::Neg(x)
        | Sym::Bracket(x)
        | Sym::Transpose(x)
        | Sym::Member(x, _)
        | Sym::Index(x, _) => worth_lowering(x, leaf, asks),
        Sym::Add(a, b) | Sym::Sub(a, b) | Sym::Div(a, b) | Sym::Pow(a, b) => {
            worth_lowering(a, leaf, asks) && worth_lowering(b, leaf, asks)
        }
    }
}

/// The unit axes in a value's entries.
fn unit_axes(v: &Value) -> Vec<Arc<str>> {
    let mut out = Vec::new();
    if let Value::Formula { m, .. } = v {
        m.data.iter().for_each(|e| e.unit_axes(&mut out));
    }
    out
}

/// `v` with the axes `names` taken as unit vectors.
fn assume(v: Value, names: &[Arc<str>]) -> Value {
    match v {
        Value::Formula { kind, m, .. } if !names.is_empty() => {
            formula::make(&kind, m.map(|e| e.assume_unit(names)))
        }
        v => v,
    }
}

/// Operands that share the unit-axis assumption of any one of them.
fn share_units(args: Vec<Value>) -> Vec<Value> {
    let mut names: Vec<Arc<str>> = Vec::new();
    for a in &args {
        for n in unit_axes(a) {
            if !names.contains(&n) {
                names.push(n);
            }
        }
    }
    if names.is_empty() {
        return args;
    }
    args.into_iter().map(|a| assume(a, &names)).collect()
}

/// What [`lower`] assumed on the way: the axes taken as unit vectors, and
/// the notes of closed forms on a branch (at `span`, the statement's).
#[derive(Default)]
struct Assumed {
    axes: RefCell<Vec<Arc<str>>>,
    notes: RefCell<Vec<Diagnostic>>,
    span: Span,
}

/// `op` on computed operands: by numbers when all are numbers, else by
/// the canonical forms ([`Op::formula`]); None when it has no exact form.
/// The unit axes of the result join `assumed`.
fn apply_op(op: Op, args: Vec<Value>, assumed: &Assumed) -> Option<Value> {
    let args = share_units(args);
    let refs: Vec<&Value> = args.iter().collect();
    if refs.iter().all(|v| matches!(v, Value::Num { .. })) {
        return op.numeric(&refs, None).ok();
    }
    if !formula::applies(&refs) {
        return None;
    }
    let v = op.formula(&refs, &Kind::Unknown)?.ok()?;
    let mut seen = assumed.axes.borrow_mut();
    for n in unit_axes(&v) {
        if !seen.contains(&n) {
            seen.push(n);
        }
    }
    Some(v)
}

/// The tree computed with its vectors as columns of components.
fn lower(s: &Sym, leaf: &dyn Fn(&str) -> Option<Leaf>, assumed: &Assumed) -> Option<Value> {
    let go = |x: &Sym| lower(x, leaf, assumed);
    let one = |op: Op, x: &Sym| apply_op(op, vec![go(x)?], assumed);
    let two = |op: BinOp, a: &Sym, b: &Sym| apply_op(Op::Arith(op), vec![go(a)?, go(b)?], assumed);
    match s {
        Sym::Name(n) if n == "deg" => Some(Value::scalar(std::f64::consts::PI / 180.0)),
        Sym::Name(n) => match leaf(n)? {
            Leaf::Number(v) => Some(v),
            Leaf::Vector(kind, unit) => {
                let parts = axis::components(n, entries(&kind)?);
                let parts = match unit {
                    // (ω̂₁, ω̂₂, ω̂₃ of the axis noted unit: ‖u‖ = 1 holds)
                    true => {
                        let name: Arc<str> = Arc::from(n.as_str());
                        // (read as a unit vector: what is made of it relies
                        // on ‖u‖ = 1 even where no ω̂ is left, dot(u, u) = 1)
                        let mut seen = assumed.axes.borrow_mut();
                        if !seen.contains(&name) {
                            seen.push(name.clone());
                        }
                        drop(seen);
                        parts
                            .iter()
                            .map(|e| e.assume_unit(std::slice::from_ref(&name)))
                            .collect()
                    }
                    false => parts,
                };
                Some(formula::make(&kind, Mat::column(parts)))
            }
        },
        Sym::Const(v, _) => Some((**v).clone()),
        Sym::Identity(_) => None,
        Sym::Compare(op, a, b) => {
            let mut both = share_units(vec![go(a)?, go(b)?]).into_iter();
            let (x, y) = (both.next()?, both.next()?);
            for v in [&x, &y] {
                if let Value::Formula { m, .. } = v
                    && !m.data.iter().all(crate::sym::Expr::unit_reduced)
                {
                    return None;
                }
            }
            let mut seen = assumed.axes.borrow_mut();
            for n in unit_axes(&x).into_iter().chain(unit_axes(&y)) {
                if !seen.contains(&n) {
                    seen.push(n);
                }
            }
            super::compare::equal(&x, &y, *op).ok()?.map(Value::Bool)
        }
        Sym::Product(fs) => {
            let mut acc = go(fs.first()?)?;
            for f in &fs[1..] {
                acc = apply_op(Op::Arith(BinOp::Mul), vec![acc, go(f)?], assumed)?;
            }
            Some(acc)
        }
        Sym::Inv(x) => {
            let b = builtins::lookup("inv")?;
            one(Op::Call(b, "inv"), x)
        }
        Sym::Neg(x) => one(Op::Neg, x),
        Sym::Transpose(x) => one(Op::Transpose, x),
        Sym::Member(x, part) => one(Op::Member(*part), x),
        Sym::Index(x, sels) => {
            let sel: Vec<Sel> = sels.iter().map(|s| s.map_or(Sel::All, Sel::At)).collect();
            one(Op::Index(&sel), x)
        }
        Sym::Add(a, b) => two(BinOp::Add, a, b),
        Sym::Sub(a, b) => two(BinOp::Sub, a, b),
        Sym::Div(a, b) => two(BinOp::Div, a, b),
        Sym::Pow(a, b) => two(BinOp::Pow, a, b),
        Sym::Bracket(x) => {
            let rows = vec![vec![go(x)?]];
            match apply::block(&rows) {
                Some(v) => v.ok(),
                None => apply::block_numeric(&rows).ok(),
            }
        }
        Sym::Block(rows) => {
            let rows: Vec<Vec<Value>> = rows
                .iter()
                .map(|r| r.iter().map(go).collect::<Option<_>>())
                .collect::<Option<_>>()?;
            let rows: Vec<Vec<Value>> = {
                let flat = share_units(rows.iter().flatten().cloned().collect());
                let mut it = flat.into_iter();
                rows.iter()
                    .map(|r| it.by_ref().take(r.len()).collect())
                    .collect()
            };
            match apply::block(&rows) {
                Some(v) => v.ok(),
                None => apply::block_numeric(&rows).ok(),
            }
        }
        Sym::Vector(parts) => {
            let parts: Vec<Value> = parts.iter().map(go).collect::<Option<_>>()?;
            apply_op(Op::Vector, parts, assumed)
        }
        Sym::Call(fun, args) => {
            let b = builtins::lookup(fun.name)?;
            let args: Vec<Value> = args.iter().map(go).collect::<Option<_>>()?;
            let v = apply_op(Op::Call(b, fun.name), args.clone(), assumed)?;
            let note = builtins::branch_note(fun.name, &share_units(args), assumed.span);
            assumed.notes.borrow_mut().extend(note);
            Some(v)
        }
    }
}

impl Interp<'_> {
    /// What a name in a tree is now (a `given` vector, or bound to a number).
    fn leaf(&self, name: &str) -> Option<Leaf> {
        let b = self.env.get(name)?;
        match &b.val {
            Some(v @ Value::Num { .. }) => Some(Leaf::Number(v.clone())),
            Some(Value::Sym(Sym::Name(n))) if b.symbolic && n == name => {
                let unit = self.env.units_noted.iter().any(|m| m == name);
                entries(&b.ty.kind).map(|_| Leaf::Vector(b.ty.kind, unit))
            }
            _ => None,
        }
    }

    /// The tree computed in closed form when it is built from `given`
    /// vectors, numbers and symbolic scalars and asks for one (module doc),
    /// with the axes assumed to be unit vectors on the way; None
    /// otherwise, or when the closed form has no exact form or is beyond
    /// the size limits. With `asked` false also a tree that asks for no
    /// closed form (`w` beside `R * w` in a comparison).
    fn lower(&self, s: &Sym, asked: bool, span: Span) -> Option<(Value, Assumed)> {
        let leaf = |n: &str| self.leaf(n);
        let mut asks = false;
        if !worth_lowering(s, &leaf, &mut asks) || (asked && !asks) {
            return None;
        }
        let assumed = Assumed {
            span,
            ..Assumed::default()
        };
        let v = lower(s, &leaf, &assumed)?;
        // a twist's ω has no unit norm to assume (Proposition 3.16 is for
        // a screw axis): its exponential stays a call
        let twist = |n: &Arc<str>| {
            self.env
                .get(&**n)
                .is_some_and(|b| matches!(b.ty.kind, Kind::Twist | Kind::Wrench))
        };
        if assumed.axes.borrow().iter().any(twist) {
            return None;
        }
        match &v {
            Value::Formula { m, .. }
                if m.size() > super::symbolic::MAX_SYM_NODES
                    || m.depth() > crate::sym::expr::MAX_DEPTH =>
            {
                None
            }
            Value::Formula { .. } | Value::Num { .. } | Value::Bool(_) => Some((v, assumed)),
            _ => None,
        }
    }

    /// A comparison kept as a tree (`d = dot(u, u) == 1` over an axis
    /// assumed unit, `super::relied`) decided in closed form while its
    /// symbols are free: the bool a name of it reads as, so that `d ==
    /// true` and `(d, 1)` hold the bool. None for any other value.
    pub(super) fn decided_now(&self, v: &Value) -> Option<Value> {
        let Value::Sym(s @ Sym::Compare(..)) = v else {
            return None;
        };
        match self.lower(s, true, Span::default()) {
            Some((b @ Value::Bool(_), _)) => Some(b),
            _ => None,
        }
    }

    /// The `given` axes that the closed form of tree `s` takes as unit
    /// vectors (none when it has no closed form, [`Interp::lower`]).
    pub(super) fn unit_axes_of(&self, s: &Sym) -> Vec<Arc<str>> {
        self.lower(s, true, Span::default())
            .map(|(_, a)| a.axes.into_inner())
            .unwrap_or_default()
    }

    /// `a op b` where a side is a tree: both sides computed in closed form
    /// ([`Interp::lower`]), sharing their unit-axis assumptions, then
    /// compared by their canonical forms (with the note of what was
    /// assumed, at `span`); undecided where a form is not the unique one
    /// on the unit sphere. None when a side stays a tree.
    pub(super) fn lowered_equal(
        &mut self,
        a: &Value,
        b: &Value,
        op: CmpOp,
        span: Span,
    ) -> Option<Result<Option<bool>, String>> {
        if !matches!(a, Value::Sym(_)) && !matches!(b, Value::Sym(_)) {
            return None;
        }
        let side = |v: &Value| match v {
            Value::Sym(s) => self.lower(s, false, span),
            v @ (Value::Num { .. } | Value::Formula { .. }) => {
                Some((v.clone(), Assumed::default()))
            }
            _ => None,
        };
        let ((x, one), (y, two)) = (side(a)?, side(b)?);
        let mut both = share_units(vec![x, y]).into_iter();
        let (x, y) = (both.next()?, both.next()?);
        self.assumed(one);
        self.assumed(two);
        let reduced = |v: &Value| match v {
            Value::Formula { m, .. } => m.data.iter().all(crate::sym::Expr::unit_reduced),
            _ => true,
        };
        if !reduced(&x) || !reduced(&y) {
            return Some(Ok(None));
        }
        Some(super::compare::equal(&x, &y, op))
    }

    /// The sides of a comparison decided over trees of `given` vectors,
    /// computed in closed form (their components u[1], u[2], …) for the
    /// bool to be decided again when the vectors get numbers, as over
    /// scalars (§7, issue 35: `d = u[1] == 0.6; u = (0.6, 0, 0.8); d` was
    /// false). None where no side is a tree, or where a side's closed form
    /// assumed a unit axis (its canonical form holds the assumption, not
    /// the numbers bound later).
    pub(super) fn lowered_sides(&self, a: &Value, b: &Value, span: Span) -> Option<(Value, Value)> {
        if !matches!(a, Value::Sym(_)) && !matches!(b, Value::Sym(_)) {
            return None;
        }
        let side = |v: &Value| match v {
            Value::Sym(s) => {
                let (x, assumed) = self.lower(s, false, span)?;
                assumed.axes.borrow().is_empty().then_some(x)
            }
            v @ (Value::Num { .. } | Value::Formula { .. }) => Some(v.clone()),
            _ => None,
        };
        Some((side(a)?, side(b)?))
    }

    /// A statement's value as shown: a tree computed in closed form where
    /// [`Interp::lower`] gives one, with the note of the axes assumed to
    /// be unit vectors. The binding keeps the tree.
    pub(super) fn shown(&mut self, val: &mut Option<Box<Value>>, span: Span) {
        // (a formula whose canonical form is a number, `a/a` with `a`
        // free, shows that number; the binding keeps how it was made)
        if let Some(v) = val.as_deref()
            && let Some(n) = super::formula::constant_shown(v)
        {
            *val = Some(Box::new(n));
        }
        // (a comparison or range waiting for numbers says so where it is shown)
        if let Some(w) = val.as_deref().and_then(crate::values::waiting::first) {
            let note = Diagnostic::note(
                crate::diagnostics::ErrorKind::Domain,
                span,
                crate::values::waiting::note(w),
            );
            if !self.warnings.iter().any(|w| w.message == note.message) {
                self.warnings.push(note);
            }
        }
        if let Some(v) = val.as_deref()
            && let Value::Sym(s) = v
            && let Some((l, assumed)) = self.lower(s, true, span)
        {
            self.assumed(assumed);
            *val = Some(Box::new(l));
        }
    }

    /// The notes of what a closed form assumed: its branches, its axes.
    fn assumed(&mut self, a: Assumed) {
        for n in a.notes.into_inner() {
            if !self.warnings.iter().any(|w| w.message == n.message) {
                self.warnings.push(n);
            }
        }
        self.unit_note(&a.axes.into_inner(), a.span);
    }

    /// The note, once a session for each axis, that it was assumed to be a
    /// unit vector: Rodrigues' formula (3.51) for a 3-vector ω̂,
    /// Proposition 3.16 with ‖ω‖ = 1 for a screw axis S = (ω, v).
    fn unit_note(&mut self, assumed: &[Arc<str>], span: Span) {
        let mut fresh: Vec<&Arc<str>> = Vec::new();
        for n in assumed {
            if !fresh.contains(&n) && !self.env.units_noted.iter().any(|m| **m == **n) {
                fresh.push(n);
            }
        }
        let said: Vec<String> = fresh
            .iter()
            .map(|n| {
                let six = self
                    .env
                    .get(&***n)
                    .and_then(|b| entries(&b.ty.kind))
                    .is_some_and(|k| k == 6);
                if six {
                    format!(
                        "{n} = (ω, v) is assumed to have ‖ω‖ = 1 (Proposition 3.16; for ω = 0, exp([{n}] θ) = [I, v θ; 0, 1])"
                    )
                } else {
                    format!(
                        "{n} is assumed to be a unit vector, ‖{n}‖ = 1 (Rodrigues' formula 3.51)"
                    )
                }
            })
            .collect();
        if said.is_empty() {
            return;
        }
        self.env
            .units_noted
            .extend(fresh.iter().map(|n| n.to_string()));
        self.warnings.push(Diagnostic::note(
            ErrorKind::Domain,
            span,
            format!("a symbolic axis in closed form: {}", said.join("; ")),
        ));
    }
}
