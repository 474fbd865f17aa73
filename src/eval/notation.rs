//! The book's notation in evaluation (LANGUAGE.md §4):
//!
//! - `I` is the identity of the size its context needs: `I + sin(θ) W` is
//!   3×3 when W is, `T - I` 4×4, `I * X` as tall as X;
//! - `e^(A t)`, `e^([w] θ)`: `e` raised to a matrix is `exp`;
//! - `(1 - cos θ)[w]`: a bracket holding a 3- or 6-vector right after a
//!   name or `)` is the book's bracket, multiplied, not an index;
//! - `[R, p; 0, 1]`: a lone `0` in a block matrix is the zero block that
//!   fits;
//! - a function given one tuple whose length is its arity takes the tuple's
//!   parts as its arguments: `rot_zyx(euler_zyx(R))`.

use super::convert;
use super::interp::{Interp, Typed};
use super::value::Value;
use crate::builtins::Builtin;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{BinOp, Expr, ExprKind, Span};

/// Whether `e` has an `I` whose size comes from around it (`I`, `2 I`,
/// `-I`, `I + W`).
#[inline]
fn mentions_identity(e: &Expr) -> bool {
    match &e.kind {
        // Most operands: a name that is not `I`, a number, a call.
        ExprKind::Var(name) => name == "I",
        ExprKind::Unary { .. } | ExprKind::Binary { .. } => mentions_identity_in(e),
        _ => false,
    }
}

/// [`mentions_identity`] of a unary or binary operation.
fn mentions_identity_in(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Var(name) => name == "I",
        ExprKind::Unary { operand, .. } => mentions_identity(operand),
        ExprKind::Binary {
            op: BinOp::Pow,
            lhs,
            ..
        } => mentions_identity(lhs),
        ExprKind::Binary { lhs, rhs, .. } => mentions_identity(lhs) || mentions_identity(rhs),
        _ => false,
    }
}

/// The name `e` as written, the base of `e^x` (Euler's number when no
/// variable `e` is bound).
pub(super) fn is_euler(e: &Expr) -> bool {
    matches!(&e.kind, ExprKind::Var(n) if n == "e")
}

/// Rows and columns of a checked operand.
fn dims(t: &Typed) -> Option<(usize, usize)> {
    if let Some(Value::Num { m, .. }) = t.val.as_deref() {
        return Some(m.shape());
    }
    match t.ty.kind.shape()? {
        (Some(r), Some(c)) => Some((r, c)),
        _ => None,
    }
}

impl Interp<'_> {
    /// Both operands of `op`, the one holding a free `I` evaluated second
    /// with the size the other gives it.
    #[inline(always)]
    pub(super) fn operands(
        &mut self,
        op: BinOp,
        lhs: &Expr,
        rhs: &Expr,
    ) -> Result<(Typed, Typed), Diagnostic> {
        let (in_lhs, in_rhs) = (mentions_identity(lhs), mentions_identity(rhs));
        // Sums, products and any comparison (`R Rᵀ == I`); not `^` or `/`.
        // (The environment is asked about `I` only when an operand has one.)
        let sized = in_lhs != in_rhs
            && !matches!(op, BinOp::Pow | BinOp::Div)
            && self.env.get(*super::env::IDENTITY).is_none();
        if sized && in_lhs {
            let r = self.expr(rhs)?;
            let n = match (op, dims(&r)) {
                (BinOp::Mul, Some((rows, _))) => Some(rows),
                (_, Some((rows, cols))) if rows == cols => Some(rows),
                _ => None,
            };
            let l = self.sized_identity(n, lhs)?;
            return Ok((l, r));
        }
        let l = self.expr(lhs)?;
        if sized && in_rhs {
            let n = match (op, dims(&l)) {
                (BinOp::Mul, Some((_, cols))) => Some(cols),
                (_, Some((rows, cols))) if rows == cols => Some(rows),
                _ => None,
            };
            let r = self.sized_identity(n, rhs)?;
            return Ok((l, r));
        }
        let r = self.expr(rhs)?;
        Ok((l, r))
    }

    /// Evaluates `e` with `I` of size `n` (a scalar or unknown context,
    /// `n` = None or 1, keeps the size from further out).
    pub(super) fn sized_identity(
        &mut self,
        n: Option<usize>,
        e: &Expr,
    ) -> Result<Typed, Diagnostic> {
        let outer = self.eye;
        if let Some(n) = n.filter(|&n| n > 1) {
            self.eye = Some(n);
        }
        let out = self.expr(e);
        self.eye = outer;
        out
    }

    /// The entries of a bracket row; an `I` among them (`[I, p; 0, 1]`)
    /// is as tall as the others.
    pub(super) fn bracket_row(&mut self, row: &[Expr]) -> Result<Vec<Typed>, Diagnostic> {
        let free = |e: &Expr| mentions_identity(e);
        let sized = self.env.get(*super::env::IDENTITY).is_none();
        let mut out: Vec<Option<Typed>> = vec![None; row.len()];
        for (slot, e) in out.iter_mut().zip(row) {
            if !(sized && free(e)) {
                *slot = Some(self.expr(e)?);
            }
        }
        let height = out
            .iter()
            .flatten()
            .filter_map(|t| dims(t).map(|d| d.0))
            .max();
        let mut done = Vec::with_capacity(row.len());
        for (slot, e) in out.into_iter().zip(row) {
            done.push(match slot {
                Some(t) => t,
                None => self.sized_identity(height, e)?,
            });
        }
        Ok(done)
    }

    /// Evaluates `e` to see what it is, before it is evaluated again in
    /// its place: its warnings are left to the second evaluation.
    pub(super) fn probe(&mut self, e: &Expr) -> Result<Typed, Diagnostic> {
        let warned = self.warnings.len();
        let t = self.expr(e);
        self.warnings.truncate(warned);
        t
    }

    /// `I` with no binding: the identity of the size its context needs.
    pub(super) fn identity(&mut self, span: Span) -> Result<Typed, Diagnostic> {
        let Some(n) = self.eye else {
            return Err(Diagnostic::error(
                ErrorKind::Name,
                span,
                "`I` has no size here",
            )
            .with_help(
                "I takes the size of what it is added to or multiplied with (I + W, T - I); alone, write eye(3) or eye(4)",
            ));
        };
        let m = crate::values::num::Num::identity(n);
        let val = self.running().then(|| Value::Num {
            kind: convert::classify(&m),
            m,
            exact: crate::values::exact::Exact::Typed,
        });
        let kind = match &val {
            Some(v) => v.kind(),
            None => Kind::Matrix(Some(n), Some(n)),
        };
        Ok(Typed::new(Ty::plain(kind), val))
    }

    /// `e^x` with `e` unbound is `exp(x)` (LANGUAGE.md §4), whatever x
    /// is: a number (exact or float), a symbol (so `diff(e^(t), t)` and
    /// `e^(t) == exp(t)` are exp's), a matrix (`e^(A t)`, e^{[ω]θ}).
    /// None when `e` is bound: `e = 3; e^(2)` is 9.
    pub(super) fn e_power(
        &mut self,
        lhs: &Expr,
        rhs: &Expr,
        span: Span,
    ) -> Option<Result<Typed, Diagnostic>> {
        if !is_euler(lhs) || self.env.get(*super::env::EULER).is_some() {
            return None;
        }
        Some(self.call(*super::env::EXP, lhs.span, std::slice::from_ref(rhs), span))
    }

    /// `e^x` with `e` unbound, written as the call `exp(x)` it is (for
    /// `explain`, whose steps are exp's); None for any other expression.
    pub(super) fn euler_call(&self, e: &Expr) -> Option<Expr> {
        let ExprKind::Binary {
            op: BinOp::Pow,
            lhs,
            rhs,
            ..
        } = &e.kind
        else {
            return None;
        };
        if !is_euler(lhs) || self.env.get(*super::env::EULER).is_some() {
            return None;
        }
        Some(Expr {
            kind: ExprKind::Call {
                func: crate::syntax::ast::Ident {
                    name: *super::env::EXP,
                    span: lhs.span,
                },
                args: vec![(**rhs).clone()],
            },
            span: e.span,
        })
    }

    /// A power in the book's notation: `e^(A t)` ([`Interp::e_power`]),
    /// `exp(X)^n` ([`Interp::exp_power`]), `X[v]^2`
    /// ([`Interp::bracket_power`]); None for any other power.
    pub(super) fn power_notation(
        &mut self,
        lhs: &Expr,
        rhs: &Expr,
        span: Span,
    ) -> Result<Option<Typed>, Diagnostic> {
        if let Some(t) = self.e_power(lhs, rhs, span) {
            return t.map(Some);
        }
        if let Some(t) = self.exp_power(lhs, rhs, span) {
            return t.map(Some);
        }
        self.bracket_power(lhs, rhs, span)
    }

    /// `exp(X)^n` for an integer n is `exp(n X)` (LANGUAGE.md §7: e^{X}
    /// commutes with itself, so (e^{X})ⁿ = e^{nX}, n < 0 included): one
    /// closed form of the multiple, not the n-th power of the entries
    /// (`exp([(1,2,3)] x)^50` is Rodrigues' form at the angle 50√14 x).
    /// None when `lhs` is not a call of the builtin `exp` with one
    /// argument over symbols, or the exponent is not an integer number.
    pub(super) fn exp_power(
        &mut self,
        lhs: &Expr,
        rhs: &Expr,
        span: Span,
    ) -> Option<Result<Typed, Diagnostic>> {
        let ExprKind::Call { func, args } = &lhs.kind else {
            return None;
        };
        let [arg] = args.as_slice() else {
            return None;
        };
        // (a user function or a value named exp is not the builtin)
        if func.name != *super::env::EXP
            || self.env.func(func.name).is_some()
            || self.env.get(func.name).is_some()
        {
            return None;
        }
        let n = match self.probe(rhs) {
            Ok(t) => t.val.as_deref().and_then(Value::as_scalar)?,
            Err(_) => return None,
        };
        if n.fract() != 0.0 || n.abs() > f64::from(i32::MAX) {
            return None;
        }
        // (numbers keep their power: the closed form is for symbols)
        match self.probe(arg) {
            Ok(t)
                if t.val
                    .as_deref()
                    .is_some_and(|v| matches!(v, Value::Sym(_) | Value::Formula { .. })) => {}
            _ => return None,
        }
        let multiple = Expr {
            kind: ExprKind::Binary {
                op: BinOp::Mul,
                lhs: Box::new(rhs.clone()),
                rhs: Box::new(arg.clone()),
                op_span: Span::new(rhs.span.start, rhs.span.start),
                implicit: true,
            },
            span: arg.span,
        };
        let call = Expr {
            kind: ExprKind::Call {
                func: func.clone(),
                args: vec![multiple],
            },
            span,
        };
        Some(self.expr(&call))
    }

    /// `X[v]` with `v` a 3- or 6-vector: the book's `X [v]`, a product.
    pub(super) fn bracket_index(
        &mut self,
        base: &Expr,
        arg: &Expr,
        span: Span,
    ) -> Result<Option<Typed>, Diagnostic> {
        let t = self.probe(arg)?;
        if !matches!(t.ty.kind.vec_len(), Some(3 | 6)) {
            return Ok(None);
        }
        let bracket = Expr {
            kind: ExprKind::Brackets(vec![vec![arg.clone()]]),
            span: Span::new(base.span.end, span.end),
        };
        let product = Expr {
            kind: ExprKind::Binary {
                op: BinOp::Mul,
                lhs: Box::new(base.clone()),
                rhs: Box::new(bracket),
                op_span: Span::new(base.span.end, base.span.end),
                implicit: true,
            },
            span,
        };
        self.expr(&product).map(Some)
    }

    /// `(1 - cos θ)[w]^2`: the power is the bracket's, `X ([w]^2)`.
    pub(super) fn bracket_power(
        &mut self,
        lhs: &Expr,
        rhs: &Expr,
        span: Span,
    ) -> Result<Option<Typed>, Diagnostic> {
        let ExprKind::Index { base, args } = &lhs.kind else {
            return Ok(None);
        };
        let [crate::syntax::ast::IndexArg::Expr(arg)] = args.as_slice() else {
            return Ok(None);
        };
        if !matches!(self.probe(arg)?.ty.kind.vec_len(), Some(3 | 6)) {
            return Ok(None);
        }
        let bracket = Expr {
            kind: ExprKind::Brackets(vec![vec![arg.clone()]]),
            span: Span::new(base.span.end, lhs.span.end),
        };
        let power = Expr {
            kind: ExprKind::Binary {
                op: BinOp::Pow,
                lhs: Box::new(bracket),
                rhs: Box::new(rhs.clone()),
                op_span: Span::new(lhs.span.end, rhs.span.start),
                implicit: false,
            },
            span: Span::new(base.span.end, span.end),
        };
        let product = Expr {
            kind: ExprKind::Binary {
                op: BinOp::Mul,
                lhs: base.clone(),
                rhs: Box::new(power),
                op_span: Span::new(base.span.end, base.span.end),
                implicit: true,
            },
            span,
        };
        self.expr(&product).map(Some)
    }

    /// A builtin given one tuple (or vector: `(a, b, c)` of scalars)
    /// whose parts fit its arguments: the parts.
    /// `Err(one)` when they do not.
    #[inline]
    pub(super) fn spread(&self, b: &Builtin, one: Typed) -> Result<Vec<Typed>, Typed> {
        // Only a tuple or a vector has parts (most arguments are neither).
        if !matches!(one.ty.kind, Kind::Tuple(_) | Kind::Vector(Some(_))) {
            return Err(one);
        }
        let parts = parts(&one);
        if parts.len() < 2 || b.check(std::slice::from_ref(&one.ty)).is_ok() {
            return Err(one);
        }
        let tys: Vec<Ty> = parts.iter().map(|t| t.ty).collect();
        if b.check(&tys).is_err() {
            return Err(one);
        }
        Ok(parts)
    }
}

/// The parts of a tuple, or the entries of a vector, as operands; empty
/// for anything else.
pub(super) fn parts(t: &Typed) -> Vec<Typed> {
    let kinds = match &t.ty.kind {
        Kind::Tuple(kinds) => kinds.to_vec(),
        Kind::Vector(Some(n)) => vec![Kind::Scalar; *n],
        _ => return Vec::new(),
    };
    let vals: Vec<Option<Value>> = match t.val.as_deref() {
        Some(Value::Tuple(vs)) => vs.iter().cloned().map(Some).collect(),
        Some(Value::Num { m, .. }) if m.len() == kinds.len() => {
            m.iter().map(|&x| Some(Value::scalar(x))).collect()
        }
        _ => vec![None; kinds.len()],
    };
    // a tuple's parts with their frames (`(T_ab, T_cb)`'s own, or the
    // parts of a builtin's tag: R of `TransToRp(T_ab)` is {a}←{b})
    kinds
        .into_iter()
        .zip(vals)
        .enumerate()
        .map(|(i, (k, val))| {
            let ty = t.ty.part(i).unwrap_or(Ty::plain(k));
            Typed::new(super::interp::refine(ty, &val), val)
        })
        .collect()
}

/// `[R, p; 0, 1]`: each lone `0` literal of a block matrix becomes the
/// zero block as wide as its column (from rows with as many entries) and
/// as tall as its row.
pub(super) fn zero_blocks(rows: &[&Vec<Expr>], vals: &mut [Vec<Value>]) {
    let lone = |i: usize, j: usize| matches!(rows[i][j].kind, ExprKind::Number(x) if x == 0.0);
    crate::seam::shapes::zero_blocks_where(lone, vals);
}
