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
use crate::seam::apply::{self, Hints, Op};
use crate::syntax::ast::{BinOp, Expr, ExprKind, Name, Span, UnOp};
use crate::values::exact::Exact;

fn strip(t: &Ty) -> Ty {
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
        let exact = if x == std::f64::consts::PI {
            self.pi_literal(span)
        } else if span.end - span.start > 15
            || (span.end - span.start > 3 && !(x.abs() >= f64::MIN_POSITIVE && x.is_finite()))
        {
            // (more digits than a float holds, or beyond its range:
            // `1e-400` is not 0)
            self.long_literal(x, span)
        } else {
            Exact::Typed
        };
        Value::Num {
            kind: Kind::Scalar,
            m: crate::values::num::Num::Scalar(x),
            exact,
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

    fn var(&mut self, name: Name, span: Span) -> Result<Typed, Diagnostic> {
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
            d = d.with_help(super::slips::declare_it(name, self.mode == Mode::Check));
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
        let op = Op::Arith(op);
        let rule = |a: &Ty, b: &Ty| op.rule(&[a, b], hints);
        let ty = match rule(&l.ty, &r.ty) {
            Ok(ty) => ty,
            Err(err) => {
                self.rule_failure(err, span, Some(lhs.span), Some(rhs.span), Some(op_span))?;
                rule(&strip(&l.ty), &strip(&r.ty))
                    .map_err(|e| Diagnostic::error(ErrorKind::Type, op_span, e.message))?
            }
        };
        let val = match (l.val, r.val) {
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

    pub(super) fn call(
        &mut self,
        name: Name,
        name_span: Span,
        args: &[Expr],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        if let Some(f) = self.env.func(name).cloned() {
            return self.user_call(&f, args, span);
        }
        let found = self.env.builtin(name);
        if found.is_none() && self.env.get(name).is_some() {
            return self.value_times_paren(name, name_span, args, span);
        }
        let name = name.as_str();
        let Some(b) = found else {
            let mut d = Diagnostic::error(
                ErrorKind::Name,
                name_span,
                format!("unknown function '{name}'"),
            );
            let args_text = match (args.first(), args.last()) {
                (Some(a), Some(b)) => self.text(Span::new(a.span.start, b.span.end)),
                _ => "",
            };
            if let Some(h) = crate::diagnostics::habits::function(name, args_text) {
                return Err(d.with_help(h));
            }
            let mut names = builtins::all_names();
            names.extend(self.env.fn_texts());
            if let Some(s) = suggest::did_you_mean(name, &names) {
                d = d.with_help(format!("did you mean {s}?"));
            }
            return Err(d);
        };
        if b.name == "solve" && self.running() {
            return self.solve(args, span);
        }
        // The arguments' types go on the interpreter's stack of them (no
        // vector per call); whatever happens, the stack is as it was after.
        let base = self.env.arg_tys.len();
        let out = if super::hold::reads_symbols(b.name, args) && self.running() {
            self.symbol_call(b, name, args, span, base)
        } else {
            self.builtin_call(b, name, args, span, base)
        };
        self.env.arg_tys.truncate(base);
        out
    }

    /// A call of builtin `b`, its arguments' types pushed on
    /// [`Interp::arg_tys`] above `base`.
    #[inline(always)]
    pub(super) fn builtin_call(
        &mut self,
        b: &'static builtins::Builtin,
        name: &str,
        args: &[Expr],
        span: Span,
        base: usize,
    ) -> Result<Typed, Diagnostic> {
        let running = self.running();
        // The types go on the stack; the values, when running, into the
        // vector the builtin takes (checking has none to keep).
        let mut vals = Vec::with_capacity(if running { args.len() } else { 0 });
        let mut keep = |tys: &mut Vec<Ty>, t: Typed| {
            tys.push(t.ty);
            if let Some(v) = t.val {
                vals.push(*v);
            } else if running {
                vals.push(Value::scalar(f64::NAN));
            }
        };
        for (i, a) in args.iter().enumerate() {
            let t = match (i, b.name, &a.kind) {
                // Rot(x, θ): the axis may be written as a bare x, y or z.
                (0, "Rot", ExprKind::Var(axis))
                    if self.env.get(axis).is_none()
                        && let Some(v) = unit_axis(axis) =>
                {
                    // (the axis as typed, `(1, 0, 0)`: exact, so that
                    // `Rot(x, pi)` is as exact as `Rotx(pi)`, issue 35)
                    let val = running.then(|| Value::Num {
                        kind: Kind::Vector(Some(3)),
                        m: crate::values::num::Num::vector(&v),
                        exact: crate::values::exact::Exact::Typed,
                    });
                    Typed::new(Ty::plain(Kind::Vector(Some(3))), val)
                }
                // diff(x, t): the variable may be a name with no value (time).
                _ => match self.time_variable(b.name, i, a) {
                    Some(t) => t,
                    // (`frame(I, p)`: the call fixes the size of `I`)
                    None if matches!(&a.kind, ExprKind::Var(n) if *n == *super::env::IDENTITY) => {
                        self.sized_identity(super::slips::identity_size(b, i), a)?
                    }
                    None => self.expr(a)?,
                },
            };
            // `rot_zyx(euler_zyx(R))`: one tuple as the arguments.
            match args.len() {
                1 => match self.spread(b, t) {
                    Ok(parts) => parts
                        .into_iter()
                        .for_each(|p| keep(&mut self.env.arg_tys, p)),
                    Err(t) => keep(&mut self.env.arg_tys, t),
                },
                _ => keep(&mut self.env.arg_tys, t),
            }
        }
        // The call's rule (its table row's check, then one frame for a
        // vector or Lie-algebra result, §6); refused, with the operands'
        // frames dropped when the frame mode lets evaluation go on.
        let op = Op::Call(b, name);
        let ty = match op.rule(&self.env.arg_tys[base..], Hints::default()) {
            Ok(ty) => ty,
            Err(err) => {
                let at = err
                    .arg
                    .and_then(|i| args.get(usize::from(i)))
                    .map_or(span, |a| a.span);
                let plain: Vec<Ty> = self.env.arg_tys[base..].iter().map(strip).collect();
                self.rule_failure(err, at, args.first().map(|a| a.span), None, None)?;
                op.rule(&plain, Hints::default()).map_err(|e| {
                    Diagnostic::error(e.kind.unwrap_or(ErrorKind::Type), at, e.message)
                })?
            }
        };
        if !self.running() {
            return Ok(Typed::new(ty, None));
        }
        self.warnings
            .extend(super::slips::radians_slip(b.name, args));
        // (len, sum, min, max of a range that waits for numbers wait too)
        if let [range] = vals.as_slice()
            && matches!(b.name, "len" | "sum" | "min" | "max")
            && let Some(v) = crate::values::waiting::of_range(b.name, range, ty.kind)
        {
            return Ok(Typed::new(ty, Some(v)));
        }
        if let Some(v) = super::list::symbolic_len(b, &self.env.arg_tys[base..], &vals) {
            return Ok(Typed::new(ty, Some(v)));
        }
        if let Some(v) = super::tuple_call::each_part(op, b.name, &vals, &mut self.warnings) {
            let val = Some(v.map_err(|m| op.failure(m, span))?);
            return Ok(Typed::new(ty, val));
        }
        super::list::numbers_only(b, &vals, span)?;
        crate::seam::transform::known(b, name, &vals, &self.env.arg_tys[base..], args, span)?;
        if vals
            .iter()
            .any(|v| matches!(v, Value::Sym(_) | Value::Formula { .. }))
        {
            let refs: Vec<&Value> = vals.iter().collect();
            // (subs with a number replays how its operand was made, §7)
            let subs = (b.name == "subs")
                .then(|| crate::decide::replay::subs_numbers(&refs, &mut self.warnings))
                .flatten()
                .map(|v| {
                    v.map(|v| super::substitute::retag(v, &ty.kind))
                        .map_err(crate::values::error::OpError::Message)
                });
            if let Some(v) = subs.or_else(|| op.exact_or_symbolic(&refs, &ty.kind)) {
                let val = Some(v.map_err(|m| op.failure(m, span))?);
                self.warnings
                    .extend(builtins::branch_note(b.name, &vals, span));
                return Ok(Typed::new(refine(ty, &val), val));
            }
        }
        let spans = match args {
            [one] => apply::Spans::repeat(one.span, vals.len()),
            _ => args.iter().map(|a| a.span).collect(),
        };
        // Only pictures read the arguments' types and source text.
        let typed = if b.area == builtins::Area::Pictures {
            self.typed_args(self.env.arg_tys[base..].to_vec(), args)
        } else {
            Vec::new()
        };
        let site = apply::Site {
            spans,
            call_span: span,
            typed,
            warnings: &mut self.warnings,
            certified_turn: Some(crate::decide::turn::half_turn),
            certified_entries: Some(crate::decide::turn::entries),
        };
        // (the exact form's recipe keeps the arguments given back: no copy)
        let (mut v, vals) = apply::call_keeping(b, vals, site)?;
        v.set_call_exact(op.exact_of_owned(vals, &ty.kind));
        crate::decide::replay::not_finite_group(&v, b.name, span)?;
        let val = Some(v);
        Ok(Typed::new(refine(ty, &val), val))
    }
}

/// The unit vector of an axis named `x`, `y` or `z`.
fn unit_axis(name: &str) -> Option<[f64; 3]> {
    match name {
        "x" => Some([1.0, 0.0, 0.0]),
        "y" => Some([0.0, 1.0, 0.0]),
        "z" => Some([0.0, 0.0, 1.0]),
        _ => None,
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
        _ => None,
    }
}
