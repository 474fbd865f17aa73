//! Calls (LANGUAGE.md §4): a user function's, a name's value times a
//! parenthesis (`T (1, 0, 0)`), and a builtin's — its arguments checked
//! and evaluated, its table row's rule giving the result's kind and
//! frames (§6), the value computed by the builtin through the seam
//! ([`crate::seam::call`]) with its exact form's recipe (§3).

use super::expr::strip;
use super::interp::{Interp, Typed, refine};
use super::value::Value;
use crate::builtins;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind, suggest};
use crate::seam::apply::{self, Hints, Op};
use crate::syntax::ast::{Expr, ExprKind, Name, Span};

impl Interp<'_> {
    /// `name(args)` (LANGUAGE.md §4): a user function's call, a bound
    /// name's value times a parenthesis, or a builtin's call; an unknown
    /// name is an error that suggests the nearest one.
    #[inline(always)]
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
        // (the name as the table spells it: the same text)
        let Some((b, name)) = found else {
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
        let keep = |tys: &mut Vec<Ty>, vals: &mut Vec<Value>, t: Typed| {
            tys.push(t.ty);
            if let Some(v) = t.val {
                vals.push(*v);
            } else if running {
                vals.push(Value::scalar(f64::NAN));
            }
        };
        for (i, a) in args.iter().enumerate() {
            // A name bound to numbers that are not a tuple or vector (which
            // may be spread over the arguments), `Ad(T_ab)`, `log(T_ac)`:
            // its copy goes straight into the arguments, without the box a
            // node's result is held in (`Interp::var`).
            if let ExprKind::Var(n) = &a.kind
                && let Some((ty, v)) = self.bound_number(*n)
                && !matches!(ty.kind, Kind::Tuple(_) | Kind::Vector(Some(_)))
                && *n != *super::env::IDENTITY
            {
                let v = v.clone();
                self.env.arg_tys.push(ty);
                vals.push(v);
                continue;
            }
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
                        .for_each(|p| keep(&mut self.env.arg_tys, &mut vals, p)),
                    Err(t) => keep(&mut self.env.arg_tys, &mut vals, t),
                },
                _ => keep(&mut self.env.arg_tys, &mut vals, t),
            }
        }
        // The call's rule (its table row's check, then one frame for a
        // vector or Lie-algebra result, §6); refused, with the operands'
        // frames dropped when the frame mode lets evaluation go on.
        let op = Op::Call(b, name);
        let ty = match op.rule(&self.env.arg_tys[base..], Hints::default()) {
            Ok(ty) => ty,
            Err(err) => {
                // (a rotation written as a 3×3 that reads as SE(2), §5)
                let retried = match running {
                    true => self.rotation_read_as_se2(op, err, &vals, base),
                    false => Err(err),
                };
                match retried {
                    Ok(ty) => ty,
                    Err(err) => {
                        let at = err
                            .arg
                            .and_then(|i| args.get(usize::from(i)))
                            .map_or(span, |a| a.span);
                        let plain: Vec<Ty> = self.env.arg_tys[base..].iter().map(strip).collect();
                        self.rule_failure(err, at, args.first().map(|a| a.span), None, None)?;
                        op.rule(&plain, Hints::default()).map_err(|e| {
                            Diagnostic::error(
                                e.kind.unwrap_or(ErrorKind::Type),
                                at,
                                e.into_message(),
                            )
                        })?
                    }
                }
            }
        };
        if !self.running() {
            // (`eye(3)`, `zeros(2, 3)` of literal sizes: the kind their
            // numbers will have, so checking knows their shape)
            let ty = literal_matrix(b.name, args, |e| self.known_number(e)).map_or(ty, Ty::plain);
            return Ok(Typed::new(ty, None));
        }
        self.warnings
            .extend(super::slips::radians_slip(b.name, args));
        // Numbers only (the common case) go straight to the builtin: the
        // paths below are for lists, tuples and symbols, and for
        // `simplify` of a number.
        let numbers = vals.iter().all(|v| matches!(v, Value::Num { .. }));
        // (a vector that may be exact is summed as its entries written
        // out would be: `crate::decide::folds`)
        let folded =
            || matches!(b.name, "sum" | "min" | "max") && vals.iter().any(Value::may_be_exact);
        if !numbers || super::tuple_call::takes_numbers(b.name) || folded() {
            if let Some(v) = self.call_on_parts(b, op, &vals, &ty, span, base)? {
                return Ok(Typed::new(ty, Some(v)));
            }
            super::list::numbers_only(b, &vals, span)?;
            crate::seam::transform::known(b, name, &vals, &self.env.arg_tys[base..], args, span)?;
        }
        if !numbers
            && vals
                .iter()
                .any(|v| matches!(v, Value::Sym(_) | Value::Formula { .. }))
        {
            let refs: Vec<&Value> = vals.iter().collect();
            // (subs with a number replays how its operand was made, §7)
            let subs = (b.name == "subs")
                .then(|| crate::decide::replay::subs_numbers(&refs, &mut self.warnings))
                .flatten()
                // (of a call kept over given names: its formulas substituted)
                .or_else(|| match refs.as_slice() {
                    [Value::Sym(x), name, by] if b.name == "subs" => {
                        crate::calculus::put::subs_tree(x, name, by, self.env, &mut self.warnings)
                            .map(Ok)
                    }
                    _ => None,
                })
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
        // (log e^X on the principal branch is X exactly, `decide::log_exp`:
        // asked of the kinds a logarithm gives only)
        let log = match ty.kind {
            Kind::So3 | Kind::Se3 | Kind::Vector(Some(3 | 6)) | Kind::Twist => {
                crate::decide::log_exp::exact_of(b.name, &vals, &v)
            }
            _ => None,
        };
        v.set_call_exact(log.unwrap_or_else(|| op.exact_of_owned(vals, &ty.kind)));
        crate::decide::domain::not_finite_group(&v, b.name, span)?;
        let val = Some(v);
        Ok(Typed::new(refine(ty, &val), val))
    }

    /// A call's rule refused, retried for a rotation written as a 3×3
    /// whose numbers read as SE(2) (LANGUAGE.md §5): near SO(3) it is a
    /// rotation (read, or projected with a warning, by the builtin), and
    /// the rule is asked again with it as a plain 3×3; farther, the error's
    /// help names `SO3(M)`. Any other refusal is `err` as it was.
    #[cold]
    #[inline(never)]
    fn rotation_read_as_se2(
        &mut self,
        op: Op<'_>,
        mut err: crate::check::rules::RuleError,
        vals: &[Value],
        base: usize,
    ) -> Result<Ty, crate::check::rules::RuleError> {
        let tys = &self.env.arg_tys[base..];
        let retype = |t: &[Ty]| op.rule(t, Hints::default()).is_ok();
        match super::slips::se2_for_rotation(tys, vals, retype) {
            Some(super::slips::Se2Read::Near(i)) => {
                self.env.arg_tys[base + i].kind = Kind::Matrix(Some(3), Some(3));
                op.rule(&self.env.arg_tys[base..], Hints::default())
            }
            Some(super::slips::Se2Read::Far(_)) => {
                let signature = match op {
                    Op::Call(b, _) => b.signature,
                    _ => "",
                };
                err.help = Some(format!(
                    "this 3×3 reads as SE(2) (last row (0, 0, 1)); SO3(M) reads a matrix as a rotation (projected within 1e-2, else an error giving its distance); signature: {signature}"
                ));
                Err(err)
            }
            None => Err(err),
        }
    }

    /// A call whose value comes from its arguments' parts or kinds, not
    /// from the builtin: `len`, `sum`, `min`, `max` of a range that waits
    /// for numbers, `sum`, `min`, `max` of items that may be exact
    /// ([`crate::decide::folds`]), `len` and `det` known from a symbolic argument's kind,
    /// `subs`, `simplify`, `expand` of each part of a tuple (None: the
    /// builtin itself runs).
    fn call_on_parts(
        &mut self,
        b: &'static builtins::Builtin,
        op: Op<'_>,
        vals: &[Value],
        ty: &Ty,
        span: Span,
        base: usize,
    ) -> Result<Option<Value>, Diagnostic> {
        if let [range] = vals
            && matches!(b.name, "len" | "sum" | "min" | "max")
            && let Some(v) = crate::values::waiting::of_range(b.name, range, ty.kind)
        {
            return Ok(Some(v));
        }
        // (the sum of no items is the zero of their kind: of no twists in
        // {s}, the zero twist in {s}, not the number 0)
        if b.name == "sum"
            && let [Value::List(items)] = vals
            && items.is_empty()
            && let Some((Some(r), Some(c))) = ty.kind.shape()
        {
            let kind = match ty.kind {
                Kind::SO3 | Kind::SE3 | Kind::SO2 | Kind::SE2 => Kind::Matrix(Some(r), Some(c)),
                k => k,
            };
            return Ok(Some(Value::Num {
                kind,
                m: crate::values::num::Num::zeros(r, c),
                exact: crate::values::exact::Exact::Typed,
            }));
        }
        if let [xs] = vals
            && let Some(v) = crate::decide::folds::of_call(b.name, xs)
        {
            let kind = if b.name == "sum" {
                ErrorKind::Type
            } else {
                ErrorKind::Domain
            };
            return v.map(Some).map_err(|m| Diagnostic::error(kind, span, m));
        }
        if let Some(v) = super::list::symbolic_len(b, &self.env.arg_tys[base..], vals) {
            return Ok(Some(v));
        }
        match super::tuple_call::each_part(op, b.name, vals, self.env, &mut self.warnings) {
            Some(v) => v.map(Some).map_err(|m| op.failure(m, span)),
            None => Ok(None),
        }
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

/// The kind of `eye(n)` or `zeros(r, c)` (`zeros(n)` is n×n) whose sizes
/// are whole numbers written with literals (`known`: `eye(3)`, or `eye(k)`
/// after `k = 3`), small enough to make: as its numbers classify (`eye(3)`
/// is SO(3), `zeros(3, 1)` a 3-vector). None for any other call, or sizes
/// not known so.
fn literal_matrix(
    name: &str,
    args: &[crate::syntax::ast::Expr],
    known: impl Fn(&crate::syntax::ast::Expr) -> Option<f64>,
) -> Option<Kind> {
    const MOST: f64 = 64.0;
    let size = |e: &crate::syntax::ast::Expr| {
        known(e)
            .filter(|x| x.fract() == 0.0 && (1.0..=MOST).contains(x))
            .map(|x| x as usize)
    };
    let m = match (name, args) {
        ("eye", [n]) => crate::values::num::Num::identity(size(n)?),
        ("zeros", [n]) => crate::values::num::Num::zeros(size(n)?, size(n)?),
        ("zeros", [r, c]) => crate::values::num::Num::zeros(size(r)?, size(c)?),
        _ => return None,
    };
    Some(crate::values::convert::classify(&m))
}
