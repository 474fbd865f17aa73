//! Ranges and `end` as indices (LANGUAGE.md §4), as MATLAB writes them:
//! `S[1:3]` (the ω part of a screw), `T[1:3, 4]` (the position of a
//! transform), `T[1:3, 1:3]`, `v[end]`, `v[end - 1]`, `xs[2:end]` on a list.
//! 1-based and inclusive; `end` is the length of its dimension (of a vector
//! its length, of a matrix its rows or columns).

use std::rc::Rc;

use nalgebra::DMatrix;

use super::interp::refine;
use super::interp::{Interp, Typed};
use super::value::Value;
use crate::check::ty::{Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Expr, ExprKind, IndexArg, Span};
use crate::values::num::Num;

/// Whether `e` mentions the name `end`.
fn mentions_end(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Var(n) => n == "end",
        ExprKind::Binary { lhs, rhs, .. } => mentions_end(lhs) || mentions_end(rhs),
        ExprKind::Unary { operand, .. } => mentions_end(operand),
        ExprKind::Range { start, step, end } => {
            mentions_end(start) || step.as_deref().is_some_and(mentions_end) || mentions_end(end)
        }
        ExprKind::Call { args, .. } | ExprKind::Paren(args) => args.iter().any(mentions_end),
        _ => false,
    }
}

/// `e` with `end` replaced by the number `n`.
fn with_end(e: &Expr, n: f64) -> Expr {
    let kind = match &e.kind {
        ExprKind::Var(name) if name == "end" => ExprKind::Number(n),
        ExprKind::Binary {
            op,
            lhs,
            rhs,
            op_span,
            implicit,
        } => ExprKind::Binary {
            op: *op,
            lhs: Box::new(with_end(lhs, n)),
            rhs: Box::new(with_end(rhs, n)),
            op_span: *op_span,
            implicit: *implicit,
        },
        ExprKind::Unary { op, operand } => ExprKind::Unary {
            op: *op,
            operand: Box::new(with_end(operand, n)),
        },
        ExprKind::Range { start, step, end } => ExprKind::Range {
            start: Box::new(with_end(start, n)),
            step: step.as_ref().map(|s| Box::new(with_end(s, n))),
            end: Box::new(with_end(end, n)),
        },
        ExprKind::Call { func, args } => ExprKind::Call {
            func: func.clone(),
            args: args.iter().map(|a| with_end(a, n)).collect(),
        },
        ExprKind::Paren(args) => ExprKind::Paren(args.iter().map(|a| with_end(a, n)).collect()),
        other => other.clone(),
    };
    Expr { kind, span: e.span }
}

/// One index: positions (1-based) and whether it was a single number.
struct Picked {
    at: Vec<f64>,
    single: bool,
    /// Checking: whether `at` is every position picked (literals, `end`
    /// of a known size), so that the slice's length is `at.len()`.
    known: bool,
}

impl Picked {
    /// How many positions are picked, when checking knows.
    fn len(&self) -> Option<usize> {
        (self.known && self.at.iter().all(|x| x.is_finite())).then_some(self.at.len())
    }
}

impl Interp<'_> {
    /// Whether the index `args` need this module: a range, or `end` while
    /// no value is named `end`.
    pub(super) fn is_slice(&self, args: &[IndexArg]) -> bool {
        args.iter().any(|a| match a {
            IndexArg::Expr(e) => {
                matches!(e.kind, ExprKind::Range { .. })
                    || (self.env.get("end").is_none() && mentions_end(e))
            }
            IndexArg::All(_) => false,
        })
    }

    /// `x[ranges or end]`.
    pub(super) fn slice(
        &mut self,
        base: &Expr,
        args: &[IndexArg],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        let t = self.expr(base)?;
        // (a range waiting for numbers has no items yet: its formula's
        // entries are its bounds, not its items)
        if let Some(d) = unindexable_range(t.value(), span) {
            return Err(d);
        }
        let (rows, cols) = match (t.value(), t.ty.kind) {
            (Some(Value::List(xs)), _) => (Some(xs.len()), Some(1)),
            (Some(v @ Value::Formula { .. }), _) => match crate::values::formula::mat_of(v) {
                Some(m) if v.kind() != Kind::Bool => (Some(m.rows), Some(m.cols)),
                _ => (None, None),
            },
            // (a given name: its kind's size, its entries `T_ab[i, j]`)
            (Some(Value::Sym(_)), k) => k.shape().unwrap_or((None, None)),
            (Some(v), _) => match v.as_matrix() {
                Some(m) => (Some(m.nrows()), Some(m.ncols())),
                None => (None, None),
            },
            (None, k @ Kind::List(..)) => (k.list_len(), Some(1)),
            (None, k) => k.shape().unwrap_or((None, None)),
        };
        // (checking: a tuple, a bool… has no entries to range over either)
        let entries = t.value().is_some() || t.ty.kind.shape().is_some();
        let entries = entries || matches!(t.ty.kind, Kind::List(..));
        if args.len() > 2 || (t.value().is_some() && rows.is_none()) || !entries {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                span,
                format!("cannot index {} with a range", t.ty.kind.a()),
            ));
        }
        let one = args.len() == 1;
        let mut picks = Vec::with_capacity(args.len());
        let mut sizes = Vec::with_capacity(args.len());
        for (i, a) in args.iter().enumerate() {
            let n = match (one, i) {
                (true, _) if cols == Some(1) => rows,
                (true, _) => rows.zip(cols).map(|(r, c)| r * c),
                (false, 0) => rows,
                _ => cols,
            };
            picks.push(self.pick(a, n)?);
            sizes.push(n);
        }
        let Some(value) = t.value() else {
            // Checking: positions written as literals (`v[1:4]`, `T[1:3,
            // 5]`) against the sizes the kind knows, as running will check
            // them (a list's length when its bounds are literal:
            // [`Kind::list_len`]).
            let whats = match one {
                true => ["the entries", ""],
                false => ["the rows", "the columns"],
            };
            if !matches!(t.ty.kind, Kind::List(..)) {
                for ((p, n), what) in picks.iter().zip(&sizes).zip(whats) {
                    if let Some(m) = p.at.iter().find_map(|&x| outside(x, *n, what)) {
                        return Err(Diagnostic::error(ErrorKind::Domain, span, m));
                    }
                }
            } else if let Some(m) = picks[0]
                .at
                .iter()
                .find_map(|&x| outside(x, sizes[0], "the list's items"))
            {
                return Err(Diagnostic::error(ErrorKind::Domain, span, m));
            }
            // Checking: the kind without the sizes, with the frames
            // running gives it (an item of a list, entries of a vector,
            // part of a column in the matrix's outer frame).
            let outer = match t.ty.frames.outer() {
                Some(a) => Frames::One(*a),
                None => Frames::None,
            };
            // (the length when the positions are known: `T_bc[1:3]` is a
            // 3-vector, as running makes it)
            let ty = match (t.ty.kind, picks.as_slice()) {
                (Kind::List(k, _), [p]) if p.single => t.ty.item(*k),
                (Kind::List(k, _), [p]) => Ty {
                    kind: Kind::list_of_len(*k, p.len()),
                    ..t.ty
                },
                (Kind::List(..), _) => t.ty,
                (_, [p]) | (_, [p, Picked { single: true, .. }]) if p.single => Ty::scalar(),
                (k, [p]) if k.is_vector() => Ty::new(Kind::Vector(p.len()), t.ty.frames),
                (_, [p]) => Ty::plain(Kind::Vector(p.len())),
                (_, [p, Picked { single: true, .. }]) => Ty::new(Kind::Vector(p.len()), outer),
                (_, [p, q]) => match (known_positions(p), known_positions(q)) {
                    (Some(rs), Some(cs)) => rotation_block(&t.ty, &rs, &cs),
                    _ => None,
                }
                .unwrap_or(Ty::plain(Kind::Matrix(p.len(), q.len()))),
                _ => Ty::plain(Kind::Matrix(None, None)),
            };
            return Ok(Typed::new(ty, None));
        };
        let check = |p: &Picked, n: usize, what: &str| -> Result<Vec<usize>, Diagnostic> {
            p.at.iter()
                .map(|&x| match outside(x, Some(n), what) {
                    Some(m) => Err(Diagnostic::error(ErrorKind::Domain, span, m)),
                    None => Ok(x as usize - 1),
                })
                .collect()
        };
        if let Value::List(xs) = value {
            let at = check(&picks[0], xs.len(), "the list's items")?;
            if picks[0].single {
                return Ok(Typed::new(
                    t.ty.item(list_elem(t.ty.kind)),
                    Some(xs[at[0]].clone()),
                ));
            }
            let items: Vec<Value> = at.iter().map(|&k| xs[k].clone()).collect();
            return Ok(Typed::new(t.ty, Some(Value::List(Rc::new(items)))));
        }
        if let Value::Formula { .. } | Value::Sym(_) = value
            && let (Some(r), Some(c)) = (rows, cols)
        {
            let (rs, cs) = if one {
                let at = check(&picks[0], r * c, "the entries")?;
                (
                    at.iter().map(|k| k % r).collect(),
                    at.iter().map(|k| k / r).collect(),
                )
            } else {
                (
                    check(&picks[0], r, "the rows")?,
                    check(&picks[1], c, "the columns")?,
                )
            };
            let block = (!one).then(|| rotation_block(&t.ty, &rs, &cs)).flatten();
            // (the frames the numbers' slice has, below)
            let mut sliced = symbolic(
                value,
                (&rs, &cs),
                (one, c),
                &picks,
                block.map(|b| b.kind),
                span,
            )?;
            sliced.ty.frames = match (sliced.ty.kind, one) {
                (Kind::Vector(_), true) if c == 1 => t.ty.frames,
                (Kind::Vector(_), false) => match t.ty.frames.outer() {
                    Some(a) => Frames::One(*a),
                    None => Frames::None,
                },
                _ => block.map_or(Frames::None, |b| b.frames),
            };
            return Ok(sliced);
        }
        let Some(m) = value.as_matrix() else {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                span,
                "cannot index this value",
            ));
        };
        let outer = match t.ty.frames.outer() {
            Some(a) => Frames::One(*a),
            None => Frames::None,
        };
        let (r, c) = (m.nrows(), m.ncols());
        let (rs, cs) = if one {
            // A vector's entries, or a matrix's column by column (MATLAB).
            let at = check(&picks[0], r * c, "the entries")?;
            let xs: Vec<f64> = at.iter().map(|&k| m[(k % r, k / r)]).collect();
            if picks[0].single {
                return Ok(Typed::new(Ty::scalar(), Some(Value::scalar(xs[0]))));
            }
            let frames = if c == 1 { t.ty.frames } else { Frames::None };
            let kind = Kind::Vector(Some(xs.len()));
            let val = Some(Value::vector(kind, &xs));
            return Ok(Typed::new(refine(Ty::new(kind, frames), &val), val));
        } else {
            (
                check(&picks[0], r, "the rows")?,
                check(&picks[1], c, "the columns")?,
            )
        };
        let sub = DMatrix::from_fn(rs.len(), cs.len(), |i, j| m[(rs[i], cs[j])]);
        let (kind, frames) = match (picks[0].single, picks[1].single) {
            (true, true) => return Ok(Typed::new(Ty::scalar(), Some(Value::scalar(sub[(0, 0)])))),
            (false, true) => (Kind::Vector(Some(rs.len())), outer),
            _ => match rotation_block(&t.ty, &rs, &cs) {
                Some(b) => (b.kind, b.frames),
                None => (Kind::Matrix(Some(rs.len()), Some(cs.len())), Frames::None),
            },
        };
        let val = Some(Value::Num {
            kind,
            m: Num::from_dmatrix(sub),
            exact: Default::default(),
        });
        Ok(Typed::new(refine(Ty::new(kind, frames), &val), val))
    }

    /// The positions one index argument picks, `end` being `n`.
    fn pick(&mut self, a: &IndexArg, n: Option<usize>) -> Result<Picked, Diagnostic> {
        let e = match a {
            IndexArg::All(_) => {
                let at = (1..=n.unwrap_or(0)).map(|k| k as f64).collect();
                let known = n.is_some();
                return Ok(Picked {
                    at,
                    single: false,
                    known,
                });
            }
            IndexArg::Expr(e) => e,
        };
        let e = with_end(e, n.map_or(f64::NAN, |n| n as f64));
        let t = self.expr(&e)?;
        if t.value().is_none()
            && let Some(at) = literal_positions(&e)
        {
            // checking: a literal's positions are known without numbers
            let single = !matches!(e.kind, ExprKind::Range { .. });
            return Ok(Picked {
                at,
                single,
                known: true,
            });
        }
        match t.value() {
            Some(Value::List(xs)) => Ok(Picked {
                at: xs
                    .iter()
                    .map(|x| x.as_scalar().unwrap_or(f64::NAN))
                    .collect(),
                single: false,
                known: true,
            }),
            Some(v) if v.as_scalar().is_some() => Ok(Picked {
                at: vec![v.as_scalar().unwrap_or(f64::NAN)],
                single: true,
                known: true,
            }),
            Some(_) => Err(Diagnostic::error(
                ErrorKind::Type,
                e.span,
                "an index must be a number or a range",
            )),
            None => Ok(Picked {
                at: Vec::new(),
                single: !matches!(t.ty.kind, Kind::List(..)),
                known: false,
            }),
        }
    }
}

/// The message for position `x` of an index when it is not a whole number
/// or is outside `1..n` (`what` names the dimension); None when it is
/// fine or not known (`n` unknown, or `x` NaN: `end` of a size checking
/// does not know).
fn outside(x: f64, n: Option<usize>, what: &str) -> Option<String> {
    if x.is_nan() {
        return None;
    }
    if x.fract() != 0.0 || !x.is_finite() {
        return Some(crate::values::error::OpError::IndexNotWhole(x).to_string());
    }
    let n = n?;
    (x < 1.0 || x > n as f64).then(|| format!("index {x} is outside 1..{n} ({what})"))
}

/// The positions an index written with literals picks (`2`, `1:4`,
/// `1:2:5`), known without evaluating it; None for anything else.
fn literal_positions(e: &Expr) -> Option<Vec<f64>> {
    let ExprKind::Range { start, step, end } = &e.kind else {
        return super::literals::literal_index(e).map(|x| vec![x]);
    };
    let a = super::literals::literal_index(start)?;
    let h = match step {
        Some(h) => super::literals::literal_index(h)?,
        None => 1.0,
    };
    let b = super::literals::literal_index(end)?;
    let n = crate::seam::range::range_count(a, h, b).ok()?;
    Some((0..n).map(|i| a + i as f64 * h).collect())
}

/// The number of items of the range `start:step:end` written with whole
/// numbers `known` without evaluating them (`0:4` has 5, `10:-2:1` 5;
/// `0:k` after `k = 4` 5: [`Interp::known_number`]), as running counts
/// them ([`crate::seam::range::count`]: whole bounds and step count
/// exactly in floats); None for any other range (a bound named, a
/// fraction, a step of zero, too long a list). A literal whose float is
/// whole but whose typed decimal is not (`2.9999999999999999`) counts
/// here at most one more than running's exact count: checking then
/// passes an index running refuses, never the other way.
pub(super) fn literal_len(
    (start, step, end): (&Expr, Option<&Expr>, &Expr),
    known: impl Fn(&Expr) -> Option<f64>,
) -> Option<usize> {
    let whole = |e: &Expr| known(e).filter(|x| x.fract() == 0.0);
    let h = match step {
        Some(h) => whole(h)?,
        None => 1.0,
    };
    crate::seam::range::range_count(whole(start)?, h, whole(end)?).ok()
}

/// `x[ranges]` of a vector or matrix over symbols (LANGUAGE.md §7): each
/// entry picked by an index operation, put together as a vector or matrix
/// (so that, bound later, it is replayed as typed first). With one index
/// `rs` and `cs` are the entries' rows and columns in order; with two,
/// the rows and the columns picked.
fn symbolic(
    value: &Value,
    (rs, cs): (&[usize], &[usize]),
    (one, cols): (bool, usize),
    picks: &[Picked],
    block: Option<Kind>,
    span: Span,
) -> Result<Typed, Diagnostic> {
    use super::ops::Sel;
    use crate::seam::apply::Op;
    let vector = cols == 1;
    let entry = |i: usize, j: usize| -> Result<Value, Diagnostic> {
        let sel = if vector {
            vec![Sel::At((i + 1) as f64)]
        } else {
            vec![Sel::At((i + 1) as f64), Sel::At((j + 1) as f64)]
        };
        let op = Op::Index(&sel);
        op.apply(&[value], &Kind::Scalar)
            .map_err(|e| op.failure(e, span))
    };
    let column = |xs: Vec<Value>| -> Result<Typed, Diagnostic> {
        let kind = Kind::Vector(Some(xs.len()));
        let refs: Vec<&Value> = xs.iter().collect();
        let v = Op::Vector
            .apply(&refs, &kind)
            .map_err(|e| Op::Vector.failure(e, span))?;
        Ok(Typed::new(Ty::plain(kind), Some(v)))
    };
    if one || picks[1].single {
        let xs: Vec<Value> = if one {
            rs.iter()
                .zip(cs)
                .map(|(&i, &j)| entry(i, j))
                .collect::<Result<_, _>>()?
        } else {
            rs.iter()
                .map(|&i| entry(i, cs[0]))
                .collect::<Result<_, _>>()?
        };
        if picks[0].single {
            let x = xs
                .into_iter()
                .next()
                .unwrap_or_else(|| Value::scalar(f64::NAN));
            return Ok(Typed::new(Ty::scalar(), Some(x)));
        }
        return column(xs);
    }
    let rows: Vec<Vec<Value>> = rs
        .iter()
        .map(|&i| cs.iter().map(|&j| entry(i, j)).collect::<Result<_, _>>())
        .collect::<Result<_, _>>()?;
    let v = match crate::seam::apply::block(&rows) {
        Some(v) => v,
        None => crate::seam::apply::block_numeric(&rows),
    }
    .map_err(|e| Diagnostic::error(ErrorKind::Domain, span, e.to_string()))?;
    // (a matrix, as the numbers typed first give it: a 2×2 block of a
    // rotation is no SO(2) for being one at these numbers; the rotation
    // block of a transform is its R, `rotation_block`)
    let kind = block.unwrap_or(Kind::Matrix(Some(rs.len()), Some(cs.len())));
    let v = match v {
        Value::Formula {
            m, how: Some(r), ..
        } => Value::Formula {
            kind,
            m,
            how: Some(
                crate::values::recipe::Recipe::node(
                    crate::values::recipe::Step::Retag,
                    vec![r.clone()],
                    kind,
                )
                .unwrap_or(r),
            ),
        },
        v => v,
    };
    Ok(Typed::new(Ty::plain(kind), Some(v)))
}

/// The type of the block of rows `rs` and columns `cs` (0-based, in the
/// order picked) of a value typed `t`, when it is the rotation block of a
/// transform: `T[1:3, 1:3]` of an SE(3) is `T.R`, an SO(3) between T's
/// frames, and `[1:2, 1:2]` of an SE(2) its SO(2) — with symbols and with
/// numbers alike (`MatrixExp6(…)[1:3, 1:3]` was a 3×3 matrix typed first
/// and SO(3) with the numbers bound later). None for any other block.
fn rotation_block(t: &Ty, rs: &[usize], cs: &[usize]) -> Option<Ty> {
    let n = match t.kind {
        Kind::SE3 => 3,
        Kind::SE2 => 2,
        _ => return None,
    };
    let leading = |xs: &[usize]| xs.len() == n && xs.iter().enumerate().all(|(i, &x)| i == x);
    if !(leading(rs) && leading(cs)) {
        return None;
    }
    crate::check::rules::member(t, "R").ok()
}

/// The 0-based positions checking knows an index picks (literals), None
/// when they are not all known whole numbers.
fn known_positions(p: &Picked) -> Option<Vec<usize>> {
    if !p.known {
        return None;
    }
    p.at.iter()
        .map(|&x| (x.fract() == 0.0 && x >= 1.0).then(|| x as usize - 1))
        .collect()
}

/// The kind of a list's elements.
fn list_elem(k: Kind) -> Kind {
    match k {
        Kind::List(e, _) => *e,
        other => other,
    }
}

/// The refusal of indexing `v` when it is a range waiting for numbers
/// (`(1:n)[2]` with `n` given, §7, §12): it has no items yet, its
/// formula's entries are its bounds. None for any other value.
pub(super) fn unindexable_range(v: Option<&Value>, span: Span) -> Option<Diagnostic> {
    let v = v.filter(|v| crate::values::waiting::is_range(v))?;
    Some(
        Diagnostic::error(
            ErrorKind::Domain,
            span,
            format!(
                "the range {} has no items until {}",
                crate::values::format::inline(v, 4),
                crate::values::waiting::once(v)
            ),
        )
        .with_help("bind numbers to the given names first, then index it (§7)"),
    )
}
