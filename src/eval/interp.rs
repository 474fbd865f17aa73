//! The interpreter: one pass over each statement that infers every
//! expression's kind and frames (the check of LANGUAGE.md §6) and, in
//! [`Mode::Run`], computes its value through the Lie-group core. `chasles
//! check` runs the same pass in [`Mode::Check`], with no numbers.

use super::env::{Binding, Env, FrameMode, Mode, Stored};
use super::value::{UserFn, Value};
use crate::check::rules::RuleError;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Span, Stmt, StmtKind};

pub use super::outcome::{Names, Outcome};

/// A checked (and, when running, evaluated) expression.
///
/// The value is boxed: the interpreter returns a `Typed` from every node,
/// and a 4×4 held inline would make each of those moves a 240-byte copy
/// (in `chasles check` of nothing at all).
#[derive(Debug, Clone)]
pub struct Typed {
    /// Its kind and frames, as the checker inferred them.
    pub ty: Ty,
    /// Its value; None when only checking.
    pub val: Option<Box<Value>>,
}

impl Typed {
    /// A checked expression and, when running, its value.
    #[inline]
    pub fn new(ty: Ty, val: Option<Value>) -> Typed {
        Typed {
            ty,
            val: val.map(Box::new),
        }
    }
    /// The value (none when checking).
    pub fn value(&self) -> Option<&Value> {
        self.val.as_deref()
    }
}

/// Runs statements against an environment.
pub struct Interp<'a> {
    /// The session's bindings, read and added to.
    pub env: &'a mut Env,
    /// The source text the statements' spans point into.
    pub src: &'a str,
    /// Check only, or check and evaluate.
    pub mode: Mode,
    /// What a frame mismatch is: an error, a warning or nothing (`--frames`).
    pub frames: FrameMode,
    /// Warnings of the current statement.
    pub warnings: Vec<Diagnostic>,
    pub(super) depth: usize,
    /// How deep [`Interp::expr`] is nested in the tree now (the stack is
    /// checked for room every few levels, not at every node).
    pub(super) nest: u32,
    /// The size an unbound `I` takes here (from the operand beside it).
    pub(super) eye: Option<usize>,
}

/// The runtime kind refines the static one (a literal that is a rotation
/// is SO(3)); frames stay as the checker found them.
#[inline]
pub(super) fn refine(ty: Ty, val: &Option<Value>) -> Ty {
    refine_by(ty, val.as_ref())
}

/// [`refine`] by a value held elsewhere (a boxed result).
#[inline(always)]
pub(super) fn refine_by(ty: Ty, val: Option<&Value>) -> Ty {
    match val {
        Some(v @ (Value::Num { .. } | Value::Tuple(_) | Value::Formula { .. })) => {
            let kind = v.kind();
            // Nothing to refine (and no frames to copy) when the numbers
            // say what the checker said and it knew nothing more.
            if kind == ty.kind && ty.algebra.is_none() && ty.moves.is_none() {
                ty
            } else if ty.parts.is_some() {
                // (a tuple's parts keep their own frames)
                crate::check::parts::with_kinds(&ty, kind)
            } else {
                crate::check::algebra::with_kind(&ty, kind)
            }
        }
        _ => ty,
    }
}

/// The error of a statement stopped by the evaluation budget
/// ([`crate::budget`]): a domain error naming the limit (LANGUAGE.md §1:
/// a budget exceeded is exit 1), at `span`.
pub fn budget_error(stop: crate::budget::Stop, span: Span) -> Diagnostic {
    Diagnostic::error(ErrorKind::Domain, span, stop.to_string()).with_help(stop.help())
}

/// How deep user functions may call each other.
pub const MAX_CALL_DEPTH: usize = 64;

impl<'a> Interp<'a> {
    /// An interpreter over `env` for statements parsed from `src`.
    pub fn new(env: &'a mut Env, src: &'a str, mode: Mode, frames: FrameMode) -> Interp<'a> {
        Interp {
            env,
            src,
            mode,
            frames,
            warnings: Vec::new(),
            depth: 0,
            nest: 0,
            eye: None,
        }
    }

    /// The source text of a span.
    pub(super) fn text(&self, span: Span) -> &'a str {
        self.src.get(span.start..span.end).unwrap_or("")
    }

    /// Turns a rule failure into a diagnostic, or — for a frame mismatch
    /// under `--frames warn|off` — into a warning (returns Ok(())).
    pub(super) fn rule_failure(
        &mut self,
        e: RuleError,
        span: Span,
        lhs: Option<Span>,
        rhs: Option<Span>,
        op: Option<Span>,
    ) -> Result<(), Diagnostic> {
        let e = e.into_refusal();
        let kind = e.kind.unwrap_or(ErrorKind::Type);
        let mut d = Diagnostic::error(kind, op.unwrap_or(span), e.message);
        if let (Some(l), false) = (lhs, e.lhs.is_empty()) {
            d = d.with_label(l, e.lhs);
        }
        if let (Some(r), false) = (rhs, e.rhs.is_empty()) {
            d = d.with_label(r, e.rhs);
        }
        if !e.op.is_empty() {
            d = d.with_primary_label(e.op);
        }
        if let Some(h) = e.help {
            d = d.with_help(h);
        }
        let frame = kind == ErrorKind::Frame;
        self.frames.refusal(frame, d, &mut self.warnings)
    }

    /// Whether a statement that has computed `val` may take effect: the
    /// budget is not spent (a loop it stopped may have left a partial
    /// result) and the session has room to hold the value.
    #[inline(always)]
    fn commit(&self, val: Option<&Value>, span: Span) -> Result<(), Diagnostic> {
        crate::budget::check()
            .and_then(|()| crate::budget::room(val.map_or(0, super::env::numbers)))
            .map_err(|stop| budget_error(stop, span))
    }

    /// Runs one statement. On error nothing is bound.
    pub fn stmt(&mut self, s: &Stmt) -> Result<Outcome, Diagnostic> {
        self.warnings.clear();
        self.env.numbers_read.clear();
        let out = |names: Names, t: Typed| Outcome {
            span: s.span,
            names,
            ty: t.ty,
            val: t.val,
            note: None,
            // (a statement ended by `;` is silent, LANGUAGE.md §3)
            prints: !s.silent,
            parts: Vec::new(),
            labels: &[],
            steps: None,
        };
        match &s.kind {
            StmtKind::Expr(e) => {
                let mut t = self.expr(e)?;
                self.commit(t.value(), s.span)?;
                crate::check::rules::settle_in_place(&mut t.ty);
                if t.ty.kind != Kind::Function {
                    self.bind_value(*super::env::ANS, &t);
                }
                let mut o = out(Names::Many(Vec::new()), t);
                o.labels = self.part_labels(e);
                self.shown(&mut o.val, s.span);
                Ok(o)
            }
            StmtKind::Assign { target, value } => {
                let mut t = self.assigned(target.name, value)?;
                self.commit(t.value(), s.span)?;
                crate::check::rules::settle_in_place(&mut t.ty);
                self.bind_checked(target.name, &mut t, target.span, value.span)?;
                // (Fig. 3.13: `v_b = (0, 0, 1.5)` is a point, as the book uses it)
                // (only a free vector can be made a point, and not one
                // declared so: `given v_s : free`)
                if t.ty.free {
                    let role = || {
                        let claim = self.env.claim(target.name);
                        claim.role.filter(|_| !claim.declared)
                    };
                    t.ty.free = !super::slips::literal_point(&target.name, role, value);
                }
                // A number silenced by `;` moves into its binding: nothing
                // shows it (§3), so no copy is kept for printing; its
                // not-finite warning is given here, before it moves.
                if s.silent
                    && let Some(v @ Value::Num { .. }) = t.val.as_deref()
                {
                    let warning = super::outcome::not_finite(v, s.span);
                    self.bind_from(target.name, &t.ty, t.val.take().map(Stored::Moved));
                    self.note_literal(target.name, value);
                    self.note_reliance(target.name);
                    self.warnings.extend(warning);
                    return Ok(out(Names::One([target.name]), t));
                }
                self.bind_value(target.name, &t);
                self.note_literal(target.name, value);
                let mut o = out(Names::One([target.name]), t);
                self.shown(&mut o.val, s.span);
                // (after it is shown: showing a closed form notes the axes
                // it takes as unit vectors, super::relied)
                self.note_reliance(target.name);
                Ok(o)
            }
            StmtKind::Destructure { targets, value } => {
                let parts = match &value.kind {
                    // `(A, B) = (T_ab, T_cb)`: each part as its own value,
                    // keeping its own frames (a tuple's type has one tag
                    // for all its parts, and a literal's has none)
                    crate::syntax::ast::ExprKind::Paren(items)
                        if items.len() == targets.len() && items.len() > 1 =>
                    {
                        let mut parts = Vec::with_capacity(items.len());
                        for item in items {
                            let t = self.expr(item)?;
                            self.commit(t.value(), s.span)?;
                            parts.push(t);
                        }
                        parts
                    }
                    _ => {
                        let t = self.expr(value)?;
                        self.commit(t.value(), s.span)?;
                        self.split_tuple(&t, targets.len(), value.span)?
                    }
                };
                let mut bound = Vec::new();
                for (target, mut part) in targets.iter().zip(parts) {
                    self.bind_checked(target.name, &mut part, target.span, value.span)?;
                    bound.push(part);
                }
                for (target, b) in targets.iter().zip(&bound) {
                    self.bind_value(target.name, b);
                }
                let names = Names::Many(targets.iter().map(|t| t.name).collect());
                let ty = Ty::plain(Kind::tuple(bound.iter().map(|b| b.ty.kind).collect()));
                let val = bound
                    .iter()
                    .map(|b| b.value().cloned())
                    .collect::<Option<Vec<_>>>()
                    .map(Value::Tuple);
                let val = val.map(|v| super::formula::constant_shown(&v).unwrap_or(v));
                let mut o = out(names, Typed::new(ty, val));
                o.parts = bound.into_iter().map(|b| b.ty).collect();
                Ok(o)
            }
            StmtKind::Given { names, ty, times } => {
                if let Some((role, len)) = crate::check::role::given_role(&ty.name) {
                    for t in times.iter().flatten() {
                        self.bind_time(t, &Kind::Vector(Some(len)))?;
                    }
                    self.given_role(names, role, len);
                    let mut o = out(
                        Names::Many(Vec::new()),
                        Typed::new(Ty::plain(Kind::Vector(Some(len))), None),
                    );
                    o.prints = false;
                    return Ok(o);
                }
                let kind = given_kind(&ty.name).ok_or_else(|| {
                    Diagnostic::error(
                        ErrorKind::Type,
                        ty.span,
                        // (as written: `SE3(3)` is no `SE33`)
                        format!("unknown type '{}'", self.text(ty.span).trim()),
                    )
                    .with_help(
                        "given types: scalar vec3 vec6 SO3 SE3 SO2 SE2 so3 se3 twist screw wrench; free, point (a free vector, a point)",
                    )
                })?;
                for (n, time) in names.iter().zip(times) {
                    if let Some(t) = time {
                        self.bind_time(t, &kind)?;
                    }
                    // (its frames and, for a vector, free or point by its
                    // letters: the claim numbers bound to it would make)
                    let ty = self.env.claim(n.name).given_ty(kind);
                    // A scalar is computed with (§7); other kinds stay names.
                    let val = if kind == Kind::Scalar {
                        let s = match time {
                            Some(t) => crate::sym::Symbol::of_time(&n.name, &t.name),
                            None => crate::sym::Symbol::new(&n.name),
                        };
                        super::formula::scalar(crate::sym::Expr::symbol(s))
                    } else {
                        Value::Sym(super::value::Sym::Name(String::from(n.name)))
                    };
                    self.env.set(n.name, Binding::given(ty, val));
                }
                let mut o = out(Names::Many(Vec::new()), Typed::new(Ty::plain(kind), None));
                o.prints = false;
                Ok(o)
            }
            StmtKind::FnDef { name, params, body } => {
                // A user function may shadow a builtin, as in Python and
                // MATLAB (`trans(n) = n`), with a note (issue 36).
                if let Some(b) = crate::builtins::lookup(&name.name) {
                    self.warnings
                        .push(super::slips::shadowed(&name.name, b.signature, name.span));
                }
                let f = UserFn {
                    name: String::from(name.name),
                    params: params.iter().map(|p| String::from(p.name)).collect(),
                    body: body.clone(),
                    source: self.env.source,
                };
                self.env
                    .fns
                    .insert(super::env::Key(name.name), std::rc::Rc::new(f));
                let mut o = out(
                    Names::Many(Vec::new()),
                    Typed::new(Ty::plain(Kind::Function), None),
                );
                o.prints = false;
                Ok(o)
            }
            StmtKind::Assert(cond) => {
                let noted = self.env.units_noted.len();
                self.assert(cond)?;
                self.commit(None, s.span)?;
                // A passing check needs no remarks on its values (θ = π
                // notes); an axis assumed unit is still to be said.
                self.warnings
                    .retain(|w| w.severity != crate::diagnostics::Severity::Note);
                self.env.units_noted.truncate(noted);
                let mut o = out(
                    Names::Many(Vec::new()),
                    Typed::new(Ty::plain(Kind::Bool), None),
                );
                o.prints = false;
                Ok(o)
            }
            StmtKind::Explain(e) => {
                let mut t = match self.expr(e) {
                    Ok(t) => t,
                    Err(d) if d.kind == ErrorKind::Frame => {
                        return Err(self.explain_frame_error(e, d));
                    }
                    Err(d) => return Err(d),
                };
                self.commit(t.value(), s.span)?;
                crate::check::rules::settle_in_place(&mut t.ty);
                let steps = self.explain(e, &t)?;
                if t.ty.kind != Kind::Function {
                    self.bind_value(*super::env::ANS, &t);
                }
                let mut o = out(Names::Many(Vec::new()), t);
                o.labels = self.part_labels(e);
                self.shown(&mut o.val, s.span);
                o.steps = (!steps.is_empty()).then(|| Box::new(steps));
                Ok(o)
            }
            StmtKind::Derive { target } => {
                let (chain, t) = self.derive(target)?;
                self.commit(t.value(), s.span)?;
                self.bind_value(target.name, &t);
                self.note_reliance(target.name);
                let mut o = out(Names::One([target.name]), t);
                o.note = Some(format!("{} = {chain}", target.name));
                Ok(o)
            }
        }
    }

    /// The names of the parts of a bare builtin call's tuple (`q`, `s`, `h`
    /// of `screw_params`); empty for anything else or a user function.
    fn part_labels(&self, e: &crate::syntax::ast::Expr) -> &'static [&'static str] {
        match &e.kind {
            crate::syntax::ast::ExprKind::Call { func, .. }
                if self.env.func(func.name).is_none() =>
            {
                crate::builtins::lookup(&func.name)
                    .and_then(|b| crate::builtins::parts::part_names(b.name))
                    .unwrap_or(&[])
            }
            _ => &[],
        }
    }

    /// The parts of a tuple (or the entries of a vector) for destructuring.
    fn split_tuple(&self, t: &Typed, n: usize, span: Span) -> Result<Vec<Typed>, Diagnostic> {
        let kinds: Vec<Kind> = match &t.ty.kind {
            Kind::Tuple(ks) => ks.to_vec(),
            // A list's length is known only from its value.
            Kind::List(k, _) => match t.val.as_deref() {
                Some(Value::List(vs)) => vs.iter().map(Value::kind).collect(),
                _ => vec![**k; n],
            },
            Kind::Vector(Some(len)) => vec![Kind::Scalar; *len],
            Kind::Unknown | Kind::Vector(None) => vec![Kind::Unknown; n],
            k => {
                return Err(Diagnostic::error(
                    ErrorKind::Type,
                    span,
                    format!("cannot destructure a {k} into {n} names"),
                )
                .with_help("destructuring takes a tuple, e.g. (w, theta) = AxisAng3(expc)"));
            }
        };
        if kinds.len() != n {
            return Err(Diagnostic::error(
                ErrorKind::Arity,
                span,
                format!(
                    "the value has {} parts but {n} names are given",
                    kinds.len()
                ),
            ));
        }
        let vals: Vec<Option<Value>> = match t.val.as_deref() {
            Some(Value::Tuple(vs)) => vs.iter().cloned().map(Some).collect(),
            Some(Value::List(vs)) => vs.iter().cloned().map(Some).collect(),
            Some(v @ Value::Num { .. }) => crate::seam::shapes::entries(v)
                .into_iter()
                .map(Some)
                .collect(),
            // a symbolic vector's entries, each `v[i]` (so each remembers
            // how it was made, §7)
            Some(v @ Value::Formula { .. }) if t.ty.kind.is_vector() => (1..=n)
                .map(|i| {
                    let sel = [super::ops::Sel::At(i as f64)];
                    crate::seam::apply::Op::Index(&sel)
                        .apply(&[v], &Kind::Scalar)
                        .ok()
                })
                .collect(),
            // a symbolic call's tuple (`axis_ang3((0, 0, a))`): each part
            // its index, computed once the symbols have numbers (§7)
            Some(Value::Sym(s)) if matches!(t.ty.kind, Kind::Tuple(_)) => (1..=n)
                .map(|i| {
                    Some(Value::Sym(super::value::Sym::Index(
                        Box::new(s.clone()),
                        vec![Some(i as f64)],
                    )))
                })
                .collect(),
            _ => vec![None; n],
        };
        Ok(kinds
            .into_iter()
            .zip(vals)
            .enumerate()
            .map(|(i, (k, v))| {
                // a tuple's part i, with its own frames (§6)
                let part = t.ty.part(i).unwrap_or(Ty::new(k, t.ty.frames.part(&k)));
                let ty = match &v {
                    Some(Value::Sym(_)) | None => part,
                    Some(v) => refine_by(part, Some(v)),
                };
                Typed::new(ty, v)
            })
            .collect())
    }
}

impl Interp<'_> {
    /// `given theta(t) : scalar` also declares the time variable `t` (unless
    /// it already has a value); only a scalar is a function of time.
    fn bind_time(&mut self, t: &crate::syntax::ast::Ident, kind: &Kind) -> Result<(), Diagnostic> {
        if *kind != Kind::Scalar {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                t.span,
                format!("only a scalar can be a function of time, not {}", kind.a()),
            )
            .with_help("given theta(t) : scalar"));
        }
        // The time variable is a plain symbol: declaring it again later
        // (`given t : scalar`) changes nothing (§7).
        if self.env.get(t.name).is_none() {
            let time = crate::sym::Expr::symbol(crate::sym::Symbol::new(&t.name));
            let time = super::formula::scalar(time);
            self.env.set(t.name, Binding::given(Ty::scalar(), time));
        }
        Ok(())
    }
}

/// The kinds `given` accepts (LANGUAGE.md §7), as the declaration spells
/// them (`given u : vec3`).
const GIVEN_KINDS: [(&str, Kind); 14] = [
    ("scalar", Kind::Scalar),
    ("vec3", Kind::Vector(Some(3))),
    ("vec6", Kind::Vector(Some(6))),
    ("SO3", Kind::SO3),
    ("SE3", Kind::SE3),
    ("SO2", Kind::SO2),
    ("SE2", Kind::SE2),
    ("so3", Kind::So3),
    ("se3", Kind::Se3),
    ("so2", Kind::So2),
    ("se2", Kind::Se2),
    ("twist", Kind::Twist),
    ("screw", Kind::Screw),
    ("wrench", Kind::Wrench),
];

/// The kind `given x : name` declares (LANGUAGE.md §7).
pub fn given_kind(name: &str) -> Option<Kind> {
    GIVEN_KINDS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, k)| *k)
}

/// How `given` spells `kind` (`vec3` for a 3-vector), if it declares it.
pub fn given_spelling(kind: &Kind) -> Option<&'static str> {
    GIVEN_KINDS.iter().find(|(_, k)| k == kind).map(|(n, _)| *n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::rules::RuleError;
    use std::mem::size_of;

    /// Every node of the interpreter returns a `Result<Typed, Diagnostic>`
    /// and every rule a `Result<Ty, RuleError>`: an error, rare, is one
    /// pointer, so that neither result is larger than its value (issue 40:
    /// with the texts held inline each result was 120 or 128 bytes, and
    /// moving them cost 4% of a statement).
    #[test]
    fn an_error_is_no_larger_than_a_pointer() {
        assert_eq!(size_of::<Diagnostic>(), size_of::<usize>());
        assert_eq!(size_of::<RuleError>(), size_of::<usize>());
        assert_eq!(size_of::<Result<Typed, Diagnostic>>(), size_of::<Typed>());
        assert_eq!(size_of::<Result<Ty, RuleError>>(), size_of::<Ty>());
        assert_eq!(size_of::<Result<(), Diagnostic>>(), size_of::<usize>());
    }

    /// A type moves through every node of every statement: a tuple's part
    /// types are a number in it, not a slice ([`crate::check::parts`]).
    #[test]
    fn a_type_stays_small() {
        assert!(size_of::<Ty>() <= 72, "{}", size_of::<Ty>());
    }
}
