//! Compound expressions: indexing `M[i, j]`, parenthesized vectors and
//! tuples `(1, 2, 3)`, brackets `[w]` and block matrices `[R, p; 0, 0, 0, 1]`
//! (LANGUAGE.md §4), and `mech < ... >` literals (chapter 2).

use super::interp::refine;
use super::interp::{Interp, Typed};
use super::ops::Sel;
use super::value::Value;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::apply::{self, Hints, Op};
use crate::syntax::ast::{Expr, ExprKind, IndexArg, Span};

impl Interp<'_> {
    pub(super) fn index(
        &mut self,
        base: &Expr,
        args: &[IndexArg],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        // `S[1:3]`, `T[1:3, 4]`, `v[end]`.
        if self.is_slice(args) {
            return self.slice(base, args, span);
        }
        if let [IndexArg::Expr(arg)] = args
            && let Some(product) = self.bracket_index(base, arg, span)?
        {
            return Ok(product);
        }
        let t = self.expr(base)?;
        let mut sels = Vec::new();
        for a in args {
            match a {
                IndexArg::All(_) => sels.push(Sel::All),
                IndexArg::Expr(e) => {
                    let it = self.expr(e)?;
                    if !it.ty.kind.maybe_scalar() {
                        return Err(Diagnostic::error(
                            ErrorKind::Type,
                            e.span,
                            "an index must be a number",
                        ));
                    }
                    // (an index over symbols would pick an entry that is
                    // not known yet: refused, never read as NaN)
                    let waits = || {
                        Diagnostic::error(
                            ErrorKind::Domain,
                            e.span,
                            format!(
                                "an index must be a number: `{}` has no number yet",
                                self.text(e.span).trim()
                            ),
                        )
                        .with_help("bind numbers to the given names before indexing with them")
                    };
                    let at = match it.value() {
                        Some(v) => v.as_scalar().ok_or_else(waits)?,
                        // (checking: a given name with no number is refused
                        // as running refuses it; a literal index is known,
                        // any other is not)
                        None if self.unbound_symbol(e) => return Err(waits()),
                        None => super::literals::literal_index(e).unwrap_or(f64::NAN),
                    };
                    sels.push(Sel::At(at));
                }
            }
        }
        if let Kind::List(..) = &t.ty.kind {
            return self.list_item(t, &sels, span);
        }
        let op = Op::Index(&sels);
        let ty = op
            .rule(&[&t.ty], Hints::default())
            .map_err(|e| Diagnostic::error(ErrorKind::Type, span, e.into_message()))?;
        let val = match t.val.as_deref() {
            Some(v) => {
                // (a given name's symbol has no entries to refuse with:
                // `T_ab[2]` of a given SE(3) is refused by its kind, as
                // numbers are)
                if let Value::Sym(_) = v
                    && let Some(m) = crate::seam::shapes::index_refusal(&t.ty.kind, &sels)
                {
                    return Err(op.failure(m, span));
                }
                Some(op.apply(&[v], &ty.kind).map_err(|m| op.failure(m, span))?)
            }
            None => {
                // checking refuses what running will: `L[1]` of a 4×8
                // matrix, `t[3]` of a pair, `x[1.5]`
                if let Some(m) = crate::seam::shapes::index_refusal(&t.ty.kind, &sels) {
                    return Err(op.failure(m, span));
                }
                if matches!(sels.as_slice(), [Sel::At(x)] if x.is_nan()) && t.ty.parts_differ() {
                    self.unknown_part(base, span);
                }
                None
            }
        };
        Ok(Typed::new(refine(ty, &val), val))
    }

    /// Checking: whether the index `e` is a `given` scalar that has no
    /// number yet, alone or plus or minus a literal (`n`, `n + 1`, `2 - n`):
    /// running refuses it. (Other expressions over symbols are left to
    /// running: `n - n` is a number.)
    fn unbound_symbol(&self, e: &Expr) -> bool {
        use crate::syntax::ast::BinOp;
        match &e.kind {
            ExprKind::Var(n) => self
                .env
                .get(*n)
                .is_some_and(|b| b.symbolic && b.ty.kind == Kind::Scalar),
            ExprKind::Binary {
                op: BinOp::Add | BinOp::Sub,
                lhs,
                rhs,
                ..
            } => {
                (self.unbound_symbol(lhs) && super::literals::literal_index(rhs).is_some())
                    || (super::literals::literal_index(lhs).is_some() && self.unbound_symbol(rhs))
            }
            ExprKind::Paren(items) if items.len() == 1 => self.unbound_symbol(&items[0]),
            _ => false,
        }
    }

    /// Checking `t[k]` of a tuple whose parts differ, `k` no literal: which
    /// part it is is known only when running, so its frames are not
    /// checked here; a warning says so (running checks them: LANGUAGE.md §6).
    fn unknown_part(&mut self, base: &Expr, span: Span) {
        let shown = self.text(span).trim().to_string();
        let tuple = self.text(base.span).trim().to_string();
        let d = Diagnostic::warning(
            ErrorKind::Frame,
            span,
            format!(
                "cannot tell which part of `{tuple}` `{shown}` is without numbers: its kind and frames are not checked"
            ),
        )
        .with_help(format!(
            "index with a number (`{tuple}[1]`) or destructure `(a, b) = {tuple}` to have each part checked; `chasles run` checks the part it picks"
        ));
        self.frames.warning(d, &mut self.warnings);
    }

    pub(super) fn paren(&mut self, items: &[Expr], span: Span) -> Result<Typed, Diagnostic> {
        if let Some(t) = self.typed_vector(items) {
            return Ok(t);
        }
        let mut ts = Vec::with_capacity(items.len());
        for i in items {
            ts.push(self.expr(i)?);
        }
        self.paren_of(ts, span)
    }

    /// `(1, 2, 3, 4, 5, 6)` run: a vector of numbers as typed, made at
    /// once (what [`Interp::paren_of`] makes of the literals, without a
    /// box for each); None for anything else (a literal that is π or has
    /// more digits than a float holds, a name, checking).
    fn typed_vector(&self, items: &[Expr]) -> Option<Typed> {
        const MOST: usize = 36;
        let n = items.len();
        if !self.running() || !(2..=MOST).contains(&n) {
            return None;
        }
        let mut xs = [0.0; MOST];
        for (x, e) in xs.iter_mut().zip(items) {
            let ExprKind::Number(typed) = e.kind else {
                return None;
            };
            match self.literal_exact(typed, e.span) {
                crate::values::exact::Exact::Typed => *x = typed,
                _ => return None,
            }
        }
        let kind = Kind::Vector(Some(n));
        let val = Value::Num {
            kind,
            m: crate::values::num::Num::vector(&xs[..n]),
            exact: crate::values::exact::Exact::Typed,
        };
        Some(Typed::new(Ty::plain(kind), Some(val)))
    }

    /// `(a, b, c)` of checked parts: a vector of scalars, else a tuple.
    pub(super) fn paren_of(&mut self, ts: Vec<Typed>, span: Span) -> Result<Typed, Diagnostic> {
        // (A pattern, not `==`: kinds compare by a call.)
        let all_scalar = ts.iter().all(|t| matches!(t.ty.kind, Kind::Scalar));
        if all_scalar {
            let ty = Ty::plain(Kind::Vector(Some(ts.len())));
            let val = match ts
                .iter()
                .map(|t| t.val.as_deref())
                .collect::<Option<Vec<_>>>()
            {
                Some(refs) if self.running() => Some(
                    Op::Vector
                        .apply(&refs, &ty.kind)
                        .map_err(|m| Op::Vector.failure(m, span))?,
                ),
                _ => None,
            };
            return Ok(Typed::new(ty, val));
        }
        // each part keeps its own type: `(T_ab, T_cb)[2]` is {c}←{b}
        let ty = Ty::tuple_of(&ts.iter().map(|t| t.ty).collect::<Vec<_>>());
        let val = ts
            .iter()
            .map(|t| t.value().cloned())
            .collect::<Option<Vec<_>>>()
            .map(Value::Tuple);
        Ok(Typed::new(ty, val))
    }

    pub(super) fn brackets(&mut self, rows: &[Vec<Expr>], span: Span) -> Result<Typed, Diagnostic> {
        if rows.iter().all(Vec::is_empty) {
            return Err(Diagnostic::error(
                ErrorKind::Syntax,
                span,
                "empty brackets: a vector or matrix needs at least one entry",
            )
            .with_help("write the entries, e.g. [1, 2, 3] or [1, 0; 0, 1]"));
        }
        if let [row] = rows
            && let [e] = row.as_slice()
        {
            return self.bracket(e, span);
        }
        let rows: Vec<&Vec<Expr>> = rows.iter().filter(|r| !r.is_empty()).collect();
        let mut trows = Vec::with_capacity(rows.len());
        for row in &rows {
            let tr = self.bracket_row(row)?;
            // `[point(p), point(q)]`: a list of pictures (§12).
            if rows.len() == 1 && tr.iter().all(|t| t.ty.kind == Kind::Picture) {
                let items: Option<Vec<Value>> = tr.iter().map(|t| t.value().cloned()).collect();
                let ty = Ty::plain(Kind::list(Kind::Picture));
                return Ok(Typed::new(
                    ty,
                    items.map(|v| Value::List(std::rc::Rc::new(v))),
                ));
            }
            for (t, e) in tr.iter().zip(row.iter()) {
                if t.ty.kind.shape().is_none() {
                    return Err(not_inside(&t.ty.kind, e.span));
                }
            }
            trows.push(tr);
        }
        let widths: Vec<usize> = trows.iter().map(Vec::len).collect();
        let op = Op::Block(&widths);
        let tys: Vec<&Ty> = trows.iter().flatten().map(|t| &t.ty).collect();
        let ty = op
            .rule(&tys, Hints::default())
            .map_err(|e| Diagnostic::error(ErrorKind::Type, span, e.into_message()))?;
        let ty = transform_block(&rows, &trows).unwrap_or(ty);
        // checking refuses a row of blocks of heights the kinds know to
        // differ (`[T_ab, v]`), or rows of widths, as running will; and so
        // does running over given names, whose symbols have no numbers to
        // compare (`[T, p]` with T : SE3 was a "4×5 matrix")
        let names = || {
            trows
                .iter()
                .flatten()
                .any(|t| matches!(t.value(), Some(Value::Sym(_))))
        };
        if !self.running() || names() {
            let lone = |e: &Expr| matches!(e.kind, ExprKind::Number(x) if x == 0.0);
            let kinds: Vec<Vec<(Kind, bool)>> = trows
                .iter()
                .zip(&rows)
                .map(|(r, es)| {
                    r.iter()
                        .zip(es.iter())
                        .map(|(t, e)| (t.ty.kind, lone(e)))
                        .collect()
                })
                .collect();
            if let Some(m) = crate::seam::shapes::block_refusal(&kinds) {
                return Err(op.failure(m, span));
            }
        }
        if !self.running() {
            return Ok(Typed::new(ty, None));
        }
        let mut vrows: Vec<Vec<Value>> = trows
            .into_iter()
            .map(|r| {
                r.into_iter()
                    .map(|t| t.val.map_or_else(|| Value::scalar(f64::NAN), |v| *v))
                    .collect()
            })
            .collect();
        // `[Rotz(t), p; 0, 1]` among formulas: its lone 0 is a zero block
        if vrows
            .iter()
            .flatten()
            .any(|v| matches!(v, Value::Formula { .. }))
            && !vrows.iter().flatten().any(Value::is_symbolic)
        {
            super::notation::zero_blocks(&rows, &mut vrows);
        }
        let v = match apply::block(&vrows) {
            Some(v) => v,
            None => {
                super::notation::zero_blocks(&rows, &mut vrows);
                apply::block_numeric(&vrows)
            }
        };
        let mut val = Some(v.map_err(|m| op.failure(m, span))?);
        // (a formula's kind is what the rule says: the transform (3.62))
        if let (Kind::SE3, Some(Value::Formula { kind, .. })) = (ty.kind, val.as_mut()) {
            *kind = Kind::SE3;
        }
        Ok(Typed::new(refine(ty, &val), val))
    }

    /// `[x]`, one entry: the general path of [`Interp::brackets`] without
    /// its rows (the book's bracket `[S]` is common).
    fn bracket(&mut self, e: &Expr, span: Span) -> Result<Typed, Diagnostic> {
        // `[S]` of a name bound to numbers: the bracket of the numbers read
        // where they are bound (what the path below makes of the name's
        // copy, without the copy).
        if let ExprKind::Var(name) = &e.kind
            && let Some((ty, x)) = self.bound_number(*name)
        {
            let ty = bracket_rule(&ty, e.span, span)?;
            let val = Some(apply::bracket_numeric(x).map_err(|m| BRACKET.failure(m, span))?);
            return Ok(Typed::new(refine(ty, &val), val));
        }
        let t = self.expr(e)?;
        let ty = bracket_rule(&t.ty, e.span, span)?;
        if !self.running() {
            return Ok(Typed::new(ty, None));
        }
        // (numbers, `[S]` of a screw axis: no formula or symbol to look
        // for, and no rows to make)
        let v = match t.val.as_deref() {
            Some(x @ Value::Num { .. }) => apply::bracket_numeric(x),
            _ => {
                let rows = [vec![t.val.map_or_else(|| Value::scalar(f64::NAN), |v| *v)]];
                apply::block(&rows).unwrap_or_else(|| apply::block_numeric(&rows))
            }
        };
        let val = Some(v.map_err(|m| BRACKET.failure(m, span))?);
        Ok(Typed::new(refine(ty, &val), val))
    }

    pub(super) fn mech(
        &mut self,
        spec: &crate::syntax::ast::MechSpec,
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        use crate::mech::{MechPart, Mechanism};
        if let Some((word, s)) = spec.unknown.first() {
            return Err(Diagnostic::error(
                ErrorKind::Syntax,
                *s,
                format!("unknown mechanism item '{word}'"),
            )
            .with_help("items: links N; joints …; legs K CHAIN; planar | spatial | spherical"));
        }
        if let Some(d) = self.name_before_joint(spec) {
            return Err(d);
        }
        // Counts written as expressions (`links N`, `legs n UPS`, `(n)R`).
        let links = match (&spec.links, &spec.links_expr) {
            (Some(_), Some(e)) => Some(self.mech_count(e)?),
            (l, _) => l.map(|(n, _)| n),
        };
        let legs_k = match (&spec.legs, &spec.legs_expr) {
            (Some(_), Some(e)) => Some(self.mech_count(e)?),
            (l, _) => l.as_ref().map(|(k, _, _)| *k),
        };
        let mut joints: Vec<(i64, &str)> = Vec::with_capacity(spec.joints.len());
        for j in &spec.joints {
            let count = match &j.count_expr {
                Some(e) => self.mech_count(e)?,
                None => j.count,
            };
            joints.push((count, j.letters.as_str()));
        }
        if !self.running()
            && (spec.links_expr.is_some()
                || spec.legs_expr.is_some()
                || spec.joints.iter().any(|j| j.count_expr.is_some()))
        {
            // Checking: the counts have no numbers yet.
            return Ok(Typed::new(Ty::plain(Kind::Mechanism), None));
        }
        let m = Mechanism::from_spec(
            spec.space.as_ref().map(|(s, _)| s.as_str()),
            links,
            &joints,
            spec.legs
                .as_ref()
                .zip(legs_k)
                .map(|((_, c, _), k)| (k, c.as_str())),
        )
        .map_err(|e| {
            let at = match e.part {
                MechPart::Links => spec.links.map(|(_, s)| s),
                MechPart::Joint(i) => spec.joints.get(i).map(|j| j.span),
                MechPart::Legs => spec.legs.as_ref().map(|(_, _, s)| *s),
                MechPart::Space => spec.space.as_ref().map(|(_, s)| *s),
                MechPart::Whole => None,
            };
            let mut d = Diagnostic::error(ErrorKind::Domain, at.unwrap_or(span), e.message.clone());
            if let Some(h) = &e.help {
                d = d.with_help(h.clone());
            }
            d
        })?;
        let val = self.running().then(|| Value::Mech(std::rc::Rc::new(m)));
        Ok(Typed::new(Ty::plain(Kind::Mechanism), val))
    }

    /// `joints n R` with `n` a bound name: joints are words (lower case
    /// letters too, `r` is R), so a name before a joint reads two ways, as
    /// a joint of its own or as the count of the next; the error shows the
    /// one spelling of a count given by a name, `(n)R` (LANGUAGE.md §9, as
    /// `8R` is eight R joints). None when no group reads so.
    fn name_before_joint(&self, spec: &crate::syntax::ast::MechSpec) -> Option<Diagnostic> {
        use crate::mech::JointType;
        let joint = |w: &str| {
            JointType::contact(w).is_some()
                || w.chars().all(|c| JointType::from_letter(c).is_some())
        };
        spec.joints.windows(2).find_map(|pair| {
            let [word, next] = pair else { return None };
            let letters = word.letters.as_str();
            let counted = self.text(next.span).starts_with(|c: char| !c.is_ascii_alphabetic());
            if joint(letters) || !joint(&next.letters) || counted || self.env.get(letters).is_none() {
                return None;
            }
            // (`2 n R`: the count written before the name goes inside too)
            let count = self.text(word.span);
            let gap = if JointType::contact(&next.letters).is_some() { " " } else { "" };
            let fix = format!("({count}){gap}{}", next.letters);
            Some(
                Diagnostic::error(
                    ErrorKind::Syntax,
                    word.span.join(next.span),
                    format!(
                        "`{count} {}`: a joint count given by a name is written in parentheses, `{fix}`",
                        next.letters
                    ),
                )
                .with_help(format!(
                    "`{fix}` is {count} {} joints, as `8R` is eight R joints; joints are words (`r` is R too), so a bare name before a joint would be a joint of its own",
                    next.letters
                )),
            )
        })
    }

    /// A count of a mechanism written as an expression (`links N`): a
    /// whole number (0 while checking, where it has no value). A count
    /// made from free symbols is refused, not kept to wait for numbers as
    /// a comparison or a range waits (`crate::values::waiting`): a
    /// mechanism is no number, vector or list that a recipe can replay,
    /// but a whole report (Grübler's formula with its numbers, a lower
    /// bound, a C-space topology) made once its joints are counted; so
    /// the user is told to bind the count first.
    fn mech_count(&mut self, e: &Expr) -> Result<i64, Diagnostic> {
        let t = self.expr(e)?;
        if !t.ty.kind.maybe_scalar() {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                e.span,
                format!("a count must be a whole number, not {}", t.ty.kind.a()),
            ));
        }
        if let Some(v) = t.value()
            && crate::values::recipe::holds_symbols(v)
        {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                e.span,
                format!(
                    "a count takes a number, not the symbolic {}",
                    crate::values::format::inline(v, 4)
                ),
            )
            .with_help("bind a number to its given names first (§7)"));
        }
        let Some(x) = t.value().and_then(Value::as_scalar) else {
            return Ok(0);
        };
        if x.fract() != 0.0 || !x.is_finite() || x.abs() > 1e15 {
            // (all the digits where six would show a whole number: 4.0000000001)
            let mut shown = crate::values::number::fmt_num(x, 6);
            if x.is_finite() && x.abs() <= 1e15 && !shown.contains(['.', 'e']) {
                shown = format!("{x}");
            }
            return Err(Diagnostic::error(
                ErrorKind::Domain,
                e.span,
                format!("a count must be a whole number, not {shown}"),
            ));
        }
        Ok(x as i64)
    }
}

/// The book's transform (3.62) written as a block, `[R, p; 0, 1]` or
/// `[x]`, the book's bracket (3.30, 3.70): a block of one entry.
const BRACKET: Op<'static> = Op::Block(&[1]);

/// The type of `[x]` for an entry `x` of type `ty` written at `at` (the
/// bracket at `span`): a vector or matrix inside, else an error.
fn bracket_rule(ty: &Ty, at: Span, span: Span) -> Result<Ty, Diagnostic> {
    if ty.kind.shape().is_none() {
        return Err(not_inside(&ty.kind, at));
    }
    BRACKET
        .rule(&[ty], Hints::default())
        .map_err(|e| Diagnostic::error(ErrorKind::Type, span, e.into_message()))
}

/// `[R, p; 0, 0, 0, 1]`, with R in SO(3) and p a 3-vector: it is in
/// SE(3), between the frames of R (`[R_sb, p_sb; 0, 1]` is {s}←{b}), so
/// `inv`, `Ad`, `log` and `T.R`, `T.p` treat it as one (also over
/// symbols, where the numbers cannot tell). None for any other block.
fn transform_block(rows: &[&Vec<Expr>], trows: &[Vec<Typed>]) -> Option<Ty> {
    let [top, bottom] = trows else { return None };
    let [r, p] = top.as_slice() else { return None };
    let is = |e: &Expr, x: f64| matches!(e.kind, ExprKind::Number(y) if y == x);
    let last = rows.get(1)?;
    let zeros = match last.as_slice() {
        [z, o] => is(z, 0.0) && is(o, 1.0),
        [a, b, c, o] => is(a, 0.0) && is(b, 0.0) && is(c, 0.0) && is(o, 1.0),
        _ => false,
    };
    let rotation = r.ty.kind == Kind::SO3;
    let vector = matches!(p.ty.kind, Kind::Vector(Some(3)));
    (zeros && rotation && vector && bottom.len() == last.len())
        .then(|| Ty::new(Kind::SE3, r.ty.frames))
}

/// "a … cannot go inside [ ]", and for a tuple of numbers and vectors of
/// three or six entries in all (`(0, 0, 1, -cross(w, q))`, a screw axis
/// typed as it reads in the book) the help naming the 6-vector's
/// spelling: a pair of 3-vectors, `((0, 0, 1), v)` (§4).
fn not_inside(kind: &Kind, span: Span) -> Diagnostic {
    let d = Diagnostic::error(
        ErrorKind::Type,
        span,
        format!("a {kind} cannot go inside [ ]"),
    );
    let Kind::Tuple(parts) = kind else {
        return d;
    };
    let entries: Option<usize> = parts
        .iter()
        .map(|k| match k.shape() {
            Some((Some(n), Some(1))) => Some(n),
            _ if *k == Kind::Scalar => Some(1),
            _ => None,
        })
        .sum();
    match entries {
        Some(6) => d.with_help(
            "a tuple is not a vector: write the 6-vector (ω, v) as a pair of 3-vectors, `((0, 0, 1), v)`, or as six numbers",
        ),
        Some(3) => d.with_help(
            "a tuple is not a vector: write the 3-vector as three numbers, `(x, y, z)`, or a vector by name",
        ),
        _ => d,
    }
}
