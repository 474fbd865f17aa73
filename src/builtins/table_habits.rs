//! Builtins a student reaches for out of habit (issue 22): `diag` (the
//! diagonal matrix of the book's inertia matrices and MATLAB's `diag`),
//! `linspace(a, b, n)` (a list of n evenly spaced numbers, as MATLAB and
//! numpy give it; a range `a:step:b` is the chasles way with a step), and
//! `Trans(x, y, z)` with the three numbers of a translation.

use std::rc::Rc;

use nalgebra::DMatrix;

use super::{Area, ArgError, Args, Builtin, Typing};
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::SE3;
use crate::values::num::Num;
use crate::values::value::Value;

/// The longest `linspace` (as the longest range).
const MAX_POINTS: f64 = 1_000_000.0;

/// `diag(a, b, c)` or `diag(v)`: the diagonal matrix; `diag(M)` of a
/// square matrix: its diagonal as a vector.
fn diag_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    if let [one] = args {
        return Ok(match one.kind.shape() {
            _ if one.kind == Kind::Unknown => Ty::plain(Kind::Unknown),
            Some((Some(1), Some(1))) => Ty::plain(Kind::Matrix(Some(1), Some(1))),
            Some((n, Some(1))) => Ty::plain(Kind::Matrix(n, n)),
            Some((Some(r), Some(c))) if r == c => Ty::plain(Kind::Vector(Some(r))),
            _ => {
                return Err(ArgError::type_of(
                    0,
                    format!(
                        "diag takes numbers, a vector or a square matrix, not {}",
                        one.kind.a()
                    ),
                ));
            }
        });
    }
    for (i, t) in args.iter().enumerate() {
        if !t.kind.maybe_scalar() {
            return Err(ArgError::type_of(
                i,
                format!("diag(a, b, …) takes numbers, not {}", t.kind.a()),
            ));
        }
    }
    Ok(Ty::plain(Kind::Matrix(Some(args.len()), Some(args.len()))))
}

fn eval_diag(a: &mut Args) -> Result<Value, Diagnostic> {
    let entries: Vec<f64> = if a.len() == 1 {
        let m = a.mat(0)?;
        if m.ncols() != 1 && m.nrows() == m.ncols() {
            let d: Vec<f64> = (0..m.nrows()).map(|i| m[(i, i)]).collect();
            return Ok(Value::vector(Kind::Vector(Some(d.len())), &d));
        }
        m.iter().copied().collect()
    } else {
        (0..a.len())
            .map(|i| a.scalar(i))
            .collect::<Result<_, _>>()?
    };
    let n = entries.len();
    let m = DMatrix::from_fn(n, n, |i, j| if i == j { entries[i] } else { 0.0 });
    Ok(Value::Num {
        kind: Kind::Matrix(Some(n), Some(n)),
        m: Num::from_dmatrix(m),
        exact: Default::default(),
    })
}

fn linspace_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    for (i, t) in args.iter().enumerate() {
        if !t.kind.maybe_scalar() {
            return Err(ArgError::type_of(
                i,
                format!("linspace takes numbers, not {}", t.kind.a()),
            ));
        }
    }
    Ok(Ty::plain(Kind::list(Kind::Scalar)))
}

fn eval_linspace(a: &mut Args) -> Result<Value, Diagnostic> {
    let (lo, hi) = (a.scalar(0)?, a.scalar(1)?);
    let n = if a.len() == 3 { a.scalar(2)? } else { 100.0 };
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(a.domain("linspace needs finite ends (no inf or NaN)"));
    }
    if n.fract() != 0.0 || !(1.0..=MAX_POINTS).contains(&n) {
        return Err(a.error(
            2,
            ErrorKind::Domain,
            format!("linspace takes a whole number of points from 1 to 1000000, not {n}"),
        ));
    }
    let n = n as usize;
    let items: Vec<Value> = (0..n)
        .map(|k| {
            // The last is b exactly (and the only one, for n = 1).
            let x = if k + 1 == n {
                hi
            } else {
                lo + (hi - lo) * k as f64 / (n - 1) as f64
            };
            Value::scalar(x)
        })
        .collect();
    Ok(Value::List(Rc::new(items)))
}

/// `Trans(p)` or `Trans(x, y, z)`.
fn trans_rule(args: &[Ty]) -> Result<Ty, ArgError> {
    let ok = match args {
        [p] => p.kind == Kind::Unknown || p.kind.shape() == Some((Some(3), Some(1))),
        _ => args.iter().all(|t| t.kind.maybe_scalar()),
    };
    if !ok {
        return Err(ArgError {
            arg: None,
            kind: ErrorKind::Type,
            message: "Trans takes a 3-vector p, or its three numbers x, y, z".into(),
        });
    }
    if args.len() == 2 {
        return Err(ArgError {
            arg: None,
            kind: ErrorKind::Arity,
            message: "Trans takes a 3-vector p, or three numbers x, y, z, not two".into(),
        });
    }
    Ok(Ty::plain(Kind::SE3))
}

fn eval_trans(a: &mut Args) -> Result<Value, Diagnostic> {
    let p = if a.len() == 3 {
        crate::lie::Vec3::new(a.scalar(0)?, a.scalar(1)?, a.scalar(2)?)
    } else {
        a.vec3(0)?
    };
    Ok(SE3::translate(&p).into())
}

/// `Trans` (§3.3.1) as a row: `table_screw` had it with one argument.
pub(super) fn trans() -> Builtin {
    Builtin {
        name: "Trans",
        aliases: &["trans"],
        signature: "Trans(p: 3-vector) or Trans(x, y, z) -> SE3",
        section: "§3.3.1",
        doc: "pure translation by p: [I, p; 0, 1]",
        example: "Trans(1, 2, 3)",
        area: Area::Transforms,
        typing: Typing::Custom {
            arity: (1, 3),
            rule: trans_rule,
        },
        eval: eval_trans,
    }
}

/// The builtins of this table, in help order.
pub(super) fn builtins() -> Vec<Builtin> {
    vec![
        Builtin {
            name: "diag",
            aliases: &[],
            signature: "diag(a, b, … | v: vector | M: square matrix) -> matrix | vector",
            section: "—",
            doc: "the diagonal matrix of the numbers or vector; of a square matrix, its diagonal",
            example: "diag(1, 2, 3)",
            area: Area::LinearAlgebra,
            typing: Typing::Custom {
                arity: (1, 64),
                rule: diag_rule,
            },
            eval: eval_diag,
        },
        Builtin {
            name: "linspace",
            aliases: &[],
            signature: "linspace(a: scalar, b: scalar, n: scalar) -> list",
            section: "—",
            doc: "n evenly spaced numbers from a to b, ends included (a range a:step:b gives a step)",
            example: "linspace(0, pi, 5)",
            area: Area::Pictures,
            typing: Typing::Custom {
                arity: (2, 3),
                rule: linspace_rule,
            },
            eval: eval_linspace,
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules() {
        let s = Ty::scalar();
        assert_eq!(
            diag_rule(&[s, s, s]).unwrap().kind,
            Kind::Matrix(Some(3), Some(3))
        );
        let v = Ty::plain(Kind::Vector(Some(3)));
        assert_eq!(
            diag_rule(&[v]).unwrap().kind,
            Kind::Matrix(Some(3), Some(3))
        );
        assert!(diag_rule(&[v, s]).is_err());
        assert_eq!(trans_rule(&[s, s, s]).unwrap().kind, Kind::SE3);
        assert!(trans_rule(&[s, s]).is_err());
        assert_eq!(trans_rule(&[v]).unwrap().kind, Kind::SE3);
    }
}
