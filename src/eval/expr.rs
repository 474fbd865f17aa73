//! Expressions: each node's kind and frames by the rules of
//! [`crate::check::rules`], and its value through [`super::ops`] and the
//! builtin table. Symbolic operands give symbolic results.

use super::env::Mode;
use super::interp::{Interp, Typed, refine};
use super::value::Value;
use crate::builtins;
use crate::check::error::Operand;
use crate::check::rules::{self, Operands};
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind, suggest};
use crate::seam::apply::{Hints, Op};
use crate::syntax::ast::{BinOp, Expr, ExprKind, Name, Span, UnOp};
use crate::values::exact::Exact;

/// A type with its kind only: the frames dropped, as evaluation goes on
/// past a frame error where the frame mode lets it (§6).
pub(super) fn strip(t: &Ty) -> Ty {
    Ty::plain(t.kind)
}

impl Interp<'_> {
    pub(super) fn running(&self) -> bool {
        self.mode == Mode::Run
    }

    pub(super) fn domain(&self, span: Span, msg: impl Into<String>) -> Diagnostic {
        Diagnostic::error(ErrorKind::Domain, span, msg)
    }

    /// Checks (and evaluates) an expression.
    ///
    /// The recursion is as deep as the tree ([`crate::syntax::MAX_DEPTH`])
    /// times the user-function calls ([`super::interp::MAX_CALL_DEPTH`]):
    /// more than a thread's stack may hold, so the stack grows on the heap
    /// when it runs low. A symbolic result beyond the size limits of
    /// [`super::value::Sym::too_large`] is a domain error.
    pub fn expr(&mut self, e: &Expr) -> Result<Typed, Diagnostic> {
        // The stack is checked for room every fourth level of nesting (the
        // check costs more than a small node): the red zone covers the four
        // frames between checks, in debug builds too. A number is a leaf:
        // no room needed, nothing symbolic.
        if let ExprKind::Number(x) = e.kind {
            return Ok(Typed::new(
                Ty::scalar(),
                self.running().then(|| self.literal(x, e.span)),
            ));
        }
        let nest = self.nest;
        self.nest = nest.wrapping_add(1);
        let t = if nest.is_multiple_of(4) {
            stacker::maybe_grow(512 * 1024, 4 * 1024 * 1024, || self.expr_node(e))
        } else {
            self.expr_node(e)
        };
        self.nest = nest;
        if let Ok(t) = &t
            && matches!(
                t.val.as_deref(),
                Some(Value::Sym(_) | Value::Formula { .. })
            )
        {
            self.within_limits(t, e.span)?;
        }
        t
    }

    fn expr_node(&mut self, e: &Expr) -> Result<Typed, Diagnostic> {
        match &e.kind {
            ExprKind::Number(x) => Ok(Typed::new(
                Ty::scalar(),
                self.running().then(|| self.literal(*x, e.span)),
            )),
            ExprKind::Bool(b) => Ok(Typed::new(
                Ty::plain(Kind::Bool),
                self.running().then_some(Value::Bool(*b)),
            )),
            ExprKind::Var(name) => self.var(*name, e.span),
            ExprKind::Unary { op, operand } => {
                let t = self.expr(operand)?;
                if *op == UnOp::Pos {
                    return Ok(t);
                }
                let ty = match Op::Neg.rule(&[&t.ty], Hints::default()) {
                    Ok(ty) => ty,
                    Err(err) => {
                        self.rule_failure(err, e.span, None, Some(operand.span), None)?;
                        strip(&t.ty)
                    }
                };
                let val = match t.val.as_deref() {
                    Some(v) => Some(
                        Op::Neg
                            .apply(&[v], &ty.kind)
                            .map_err(|m| Op::Neg.failure(m, e.span))?,
                    ),
                    None => None,
                };
                Ok(Typed::new(ty, val))
            }
            ExprKind::Degrees(inner) => {
                let t = self.expr(inner)?;
                if !t.ty.kind.maybe_scalar() {
                    return Err(Diagnostic::error(
                        ErrorKind::Type,
                        inner.span,
                        format!("degrees apply to a number, not {}", t.ty.kind.a()),
                    ));
                }
                let val = match t.val.as_deref() {
                    Some(v) => Some(
                        Op::Degrees
                            .apply(&[v], &Kind::Scalar)
                            .map_err(|m| Op::Degrees.failure(m, inner.span))?,
                    ),
                    None => None,
                };
                Ok(Typed::new(Ty::scalar(), val))
            }
            ExprKind::Binary {
                op,
                lhs,
                rhs,
                op_span,
                ..
            } => self.binary(*op, lhs, rhs, *op_span, e.span),
            ExprKind::Call { func, args } => self.call(func.name, func.span, args, e.span),
            ExprKind::Member { base, member } => {
                let t = self.expr(base)?;
                let Some(op) = Op::member(&member.name) else {
                    // No such member: the rule says why.
                    let err = rules::member(&t.ty, &member.name).err().unwrap_or_default();
                    self.rule_failure(err, member.span, None, None, None)?;
                    return Ok(Typed::new(unreachable_type(), None));
                };
                let ty = match op.rule(&[&t.ty], Hints::default()) {
                    Ok(ty) => ty,
                    Err(err) => {
                        self.rule_failure(err, member.span, None, None, None)?;
                        unreachable_type()
                    }
                };
                let val = match t.val.as_deref() {
                    Some(v) => Some(
                        op.apply(&[v], &ty.kind)
                            .map_err(|m| op.failure(m, member.span))?,
                    ),
                    None => None,
                };
                let ty = refine(ty, &val);
                Ok(Typed::new(ty, val))
            }
            ExprKind::Index { base, args } => self.index(base, args, e.span),
            ExprKind::Paren(items) => self.paren(items, e.span),
            ExprKind::Brackets(rows) => self.brackets(rows, e.span),
            ExprKind::Mech(spec) => self.mech(spec, e.span),
            ExprKind::Compare {
                op,
                lhs,
                rhs,
                op_span,
            } => self.compare(*op, lhs, rhs, *op_span),
            _ => self.list_expr(e), // ranges, comprehensions, strings (§12)
        }
    }

    /// A number as typed, exact (LANGUAGE.md §3, §7): its decimals
    /// (`0.866` is 866/1000), or π where `pi` or `π` was written.
    #[inline]
    pub(super) fn literal(&self, x: f64, span: Span) -> Value {
        Value::Num {
            kind: Kind::Scalar,
            m: crate::values::num::Num::Scalar(x),
            exact: self.literal_exact(x, span),
        }
    }

    /// The exact form of the literal `x` typed at `span` ([`Interp::literal`]):
    /// [`Exact::Typed`] but for π and the literals a float does not hold.
    #[inline]
    pub(super) fn literal_exact(&self, x: f64, span: Span) -> Exact {
        if x == std::f64::consts::PI {
            self.pi_literal(span)
        } else if span.end - span.start > 15
            || (span.end - span.start > 3 && !(x.abs() >= f64::MIN_POSITIVE && x.is_finite()))
        {
            // (more digits than a float holds, or beyond its range:
            // `1e-400` is not 0)
            self.long_literal(x, span)
        } else {
            Exact::Typed
        }
    }

    /// The exact form of a literal of more than 15 characters, or one
    /// whose float is 0, subnormal or infinite: the decimal written, when
    /// its float does not read back as it (more than 15 significant
    /// digits: `1.00000000000000001` is not 1, nor `10000000000000000001`
    /// 10¹⁹; `1e-400` is not 0).
    #[cold]
    fn long_literal(&self, x: f64, span: Span) -> Exact {
        match crate::values::exact::written(crate::values::exact::literal_token(self.text(span))) {
            Some(r) if Some(&r) != crate::values::exact::decimal(x).as_ref() => Exact::known(
                crate::sym::Mat::scalar(crate::sym::Expr::constant(crate::sym::coef::Coef::rat(r))),
            ),
            _ => Exact::Typed,
        }
    }

    /// The exact form of a literal whose float is π's: π where `pi` or
    /// `π` was written, else the decimals typed.
    #[cold]
    fn pi_literal(&self, span: Span) -> Exact {
        if matches!(
            crate::values::exact::literal_token(self.text(span)),
            "pi" | "π"
        ) {
            Exact::known(crate::sym::Mat::scalar(crate::sym::Expr::pi()))
        } else {
            // (`3.1415926535897932` is that decimal, not π's float)
            self.long_literal(std::f64::consts::PI, span)
        }
    }

    #[inline]
    fn var(&mut self, name: Name, span: Span) -> Result<Typed, Diagnostic> {
        // Numbers (most names read) are what they were bound to: a copy
        // (the numbers shared), boxed as the result holds it, when no axis
        // was assumed a unit vector and no symbol is `given` (the paths of
        // `var_read` then change nothing).
        if let Some((ty, v)) = self.bound_number(name) {
            return Ok(Typed {
                ty,
                val: Some(Box::new(v.clone())),
            });
        }
        self.var_read(name, span)
    }

    /// The type and numbers bound to `name` when reading it is just that
    /// (see [`Interp::var`]); None for every other name.
    #[inline]
    pub(super) fn bound_number(&self, name: Name) -> Option<(Ty, &Value)> {
        let b = self.env.get(name)?;
        match &b.val {
            Some(v @ Value::Num { .. })
                if self.running() && self.env.relied.is_empty() && !self.env.has_givens() =>
            {
                Some((b.ty, v))
            }
            _ => None,
        }
    }

    /// [`Interp::var`] of anything but bound numbers read plainly: a value
    /// replayed with the numbers bound since, a constant (`pi`, `e`, `I`),
    /// or the error of an unknown name.
    #[inline(never)]
    fn var_read(&mut self, name: Name, span: Span) -> Result<Typed, Diagnostic> {
        if let Some(b) = self.env.get(name) {
            let mut warnings = Vec::new();
            let v = if self.running() {
                super::substitute::current(b.bound(), self.env, &mut warnings).map_err(|e| {
                    Diagnostic::error(
                        ErrorKind::Domain,
                        span,
                        format!("{name} with the numbers bound since: {}", e.0),
                    )
                })?
            } else {
                None
            };
            // (what relied on an axis assumed unit, super::relied)
            let v = self.relied_read(name.as_str(), v, span, &mut warnings);
            // (a value made from symbols that has become numbers is typed
            // by what it is now, as typed first: `rpy` gives a vector)
            let ty = match (&b.val, v.as_deref()) {
                (Some(old), Some(now)) if crate::values::recipe::holds_symbols(old) => {
                    super::interp::refine_by(b.ty, Some(now))
                }
                _ => b.ty,
            };
            // (the warnings of the steps replayed, at the name read: once
            // per binding of the numbers it reads, as typed first)
            if !warnings.is_empty() {
                for mut w in self.env.fresh_warnings(name.as_str(), warnings) {
                    w.span = span;
                    if !self.warnings.iter().any(|x| x.message == w.message) {
                        self.warnings.push(w);
                    }
                }
            }
            if self.env.has_givens() {
                // (the numbers of given symbols it holds, super::hold)
                super::hold::note_read(self.env, name);
            }
            return Ok(Typed { ty, val: v });
        }
        let name = name.as_str();
        if let Some(d) = self.derivative_symbol(name) {
            return Ok(d);
        }
        match name {
            "inf" | "Inf" | "∞" => {
                return Ok(Typed::new(
                    Ty::scalar(),
                    self.running().then(|| Value::scalar(f64::INFINITY)),
                ));
            }
            "e" => {
                return Ok(Typed::new(
                    Ty::scalar(),
                    self.running().then(|| Value::scalar(std::f64::consts::E)),
                ));
            }
            // The unit of `pi/6 rad`: angles are in radians already.
            "rad" => {
                return Ok(Typed::new(
                    Ty::scalar(),
                    self.running().then(|| Value::scalar(1.0)),
                ));
            }
            // The identity of the size its context needs (LANGUAGE.md §4).
            "I" => return self.identity(span),
            _ => {}
        }
        if builtins::lookup(name).is_some() || self.env.func(name).is_some() {
            return Err(Diagnostic::error(
                ErrorKind::Name,
                span,
                format!("'{name}' is a function"),
            )
            .with_help(super::slips::function_as_value(name)));
        }
        let mut d = Diagnostic::error(ErrorKind::Name, span, format!("unknown name '{name}'"));
        if let Some(h) = crate::diagnostics::habits::name(name) {
            return Err(d.with_help(h));
        }
        // T_{0,1} unknown but T_01 known: the same frames spelled otherwise.
        let frames = crate::syntax::ident::name_frames(name);
        if frames != crate::syntax::ident::NameFrames::None {
            let base = crate::syntax::ident::base_name(name);
            let same = |k: &&str| {
                crate::syntax::ident::base_name(k) == base
                    && crate::syntax::ident::name_frames(k) == frames
            };
            if let Some(other) = self.env.var_texts().filter(same).min() {
                return Err(d.with_help(format!("{other} names the same frames: use {other}")));
            }
        }
        // T_cb unknown but T_bc known: the inverse is one step away.
        if let crate::syntax::ident::NameFrames::Pair(a, b) =
            crate::syntax::ident::name_frames(name)
        {
            let base = crate::syntax::ident::base_name(name);
            let reversed = if name.contains('{') {
                format!("{base}_{{{b},{a}}}")
            } else {
                format!("{base}_{b}{a}")
            };
            if self.env.get(&reversed).is_some() {
                return Err(d.with_help(format!("{reversed} is known: {name} = inv({reversed})")));
            }
        }
        let mut candidates: Vec<&str> = self.env.var_texts().collect();
        candidates.extend(builtins::all_names());
        if let Some(s) = suggest::did_you_mean(name, &candidates) {
            d = d.with_help(format!("did you mean '{s}'?"));
        } else {
            d = d.with_help(super::slips::declare_it(name));
        }
        Err(d)
    }

    fn binary(
        &mut self,
        op: BinOp,
        lhs: &Expr,
        rhs: &Expr,
        op_span: Span,
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        if op == BinOp::Pow
            && let Some(t) = self.power_notation(lhs, rhs, span)?
        {
            return Ok(t);
        }
        let (l, r) = self.operands(op, lhs, rhs)?;
        self.no_arithmetic(&[(&l, lhs.span), (&r, rhs.span)], op_span)?;
        let hints = Hints {
            operands: Operands {
                lhs: Operand::new(lhs, self.src),
                rhs: Operand::new(rhs, self.src),
            },
            exponent: literal_number(rhs).or_else(|| r.val.as_deref().and_then(Value::as_scalar)),
        };
        let identity_factor = |op, a, b| crate::seam::transform::identity_factor(op, a, b);
        let bin = op;
        let op = Op::Arith(op);
        let rule = |a: &Ty, b: &Ty| op.rule(&[a, b], hints);
        let ty = match rule(&l.ty, &r.ty) {
            Ok(ty) => ty,
            Err(err) => {
                self.rule_failure(err, span, Some(lhs.span), Some(rhs.span), Some(op_span))?;
                rule(&strip(&l.ty), &strip(&r.ty))
                    .map_err(|e| Diagnostic::error(ErrorKind::Type, op_span, e.into_message()))?
            }
        };
        let val = match (l.val, r.val) {
            // (only a product with a given name's symbol can have one:
            // numbers, the hot path, skip it)
            (Some(a), Some(b))
                if (matches!(*a, Value::Sym(_)) || matches!(*b, Value::Sym(_)))
                    && let Some(v) = identity_factor(bin, (&a, &l.ty.kind), (&b, &r.ty.kind)) =>
            {
                Some(v)
            }
            (Some(a), Some(b)) => Some(
                op.apply_pair(a, b, &ty.kind)
                    .map_err(|m| op.failure(m, op_span))?,
            ),
            _ => None,
        };
        // Checking: nothing to refine or box.
        if val.is_none() {
            return Ok(Typed { ty, val: None });
        }
        Ok(Typed::new(refine(ty, &val), val))
    }
}

fn unreachable_type() -> Ty {
    Ty::plain(Kind::Unknown)
}

/// `2`, `-1`: the exponent of `X^-1` without evaluating.
fn literal_number(e: &Expr) -> Option<f64> {
    match &e.kind {
        ExprKind::Number(x) => Some(*x),
        ExprKind::Unary {
            op: UnOp::Neg,
            operand,
        } => literal_number(operand).map(|x| -x),
        // (whole numbers of whole literals, exactly as run computes them:
        // `T_cd^-1^2` is T_cd^-(1²) = inv(T_cd), `T^(1 - 2)` too, known
        // to `check`, which has no values)
        ExprKind::Binary { op, lhs, rhs, .. } => {
            let (a, b) = (literal_number(lhs)?, literal_number(rhs)?);
            let whole = |x: f64| x.fract() == 0.0 && x.abs() < 1e15;
            if !whole(a) || !whole(b) {
                return None;
            }
            // (a quotient or power of whole numbers that is not whole is
            // no −1, 0 or 1 in floats either: `T^(2^-1)` is T^(1/2))
            let x = match op {
                BinOp::Add => a + b,
                BinOp::Sub => a - b,
                BinOp::Mul => a * b,
                BinOp::Div if b != 0.0 => return Some(a / b),
                BinOp::Pow if (-64.0..=64.0).contains(&b) => return Some(a.powi(b as i32)),
                _ => return None,
            };
            whole(x).then_some(x)
        }
        _ => None,
    }
}
