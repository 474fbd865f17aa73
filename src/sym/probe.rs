//! A quick numeric look before an exact test: the value of an expression
//! at one generic point, with a bound on its rounding. An identity of
//! canonical forms holds at every point, so a point where it fails by far
//! more than the rounding proves it false without forming it; only a
//! point where it holds leaves the exact test to decide. Used to see that
//! a symbolic 3×3 is no rotation (the derivative of one, say) without the
//! symbolic product R Rᵀ, which for entries of hundreds of terms costs
//! seconds (`values::formula::classify`).

use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use super::coef::Coef;
use super::expr::{Call, Expr, Func, Symbol, Var};
use super::matrix::Mat;
use super::phase::{PI_DEN, Unit};

const EPS: f64 = f64::EPSILON;

/// The generic point: a number in [0.31, 1.31) from the symbol's name,
/// the same every time. A component of a unit axis has none (its
/// components are not independent: ω̂₁² + ω̂₂² + ω̂₃² = 1).
fn generic(s: &Symbol) -> Option<f64> {
    if s.unit {
        return None;
    }
    let mut h = std::collections::hash_map::DefaultHasher::new();
    s.hash(&mut h);
    Some(0.31 + (h.finish() >> 11) as f64 / (1u64 << 53) as f64)
}

/// A coefficient's value and the size its parts add up to (what its
/// rounding is relative to).
fn coef(c: &Coef) -> ((f64, f64), f64) {
    let v = c.to_c64();
    let size = match c {
        Coef::Exact { re, im } => [re, im]
            .iter()
            .flat_map(|s| s.terms())
            .map(|(k, r)| r.to_f64().abs() * (k as f64).sqrt())
            .sum(),
        Coef::Approx { re, im } => re.abs() + im.abs(),
    };
    (v, size)
}

/// The value at the generic point and a bound on its absolute error;
/// None where there is no finite real value there (or no generic point).
pub fn value(e: &Expr) -> Option<(f64, f64)> {
    Memo::default().value(e)
}

/// What one look has worked out: each shared call's value (a call may sit
/// in thousands of terms) and each symbol's number.
#[derive(Default)]
struct Memo {
    calls: HashMap<*const Call, Option<(f64, f64)>>,
    symbols: HashMap<Symbol, Option<f64>>,
}

impl Memo {
    fn generic(&mut self, s: &Symbol) -> Option<f64> {
        if let Some(x) = self.symbols.get(s) {
            return *x;
        }
        let x = generic(s);
        self.symbols.insert(s.clone(), x);
        x
    }

    fn call(&mut self, c: &Arc<Call>) -> Option<(f64, f64)> {
        let key = Arc::as_ptr(c);
        if let Some(x) = self.calls.get(&key) {
            return *x;
        }
        let x = self.call_at(c);
        self.calls.insert(key, x);
        x
    }

    fn value(&mut self, e: &Expr) -> Option<(f64, f64)> {
        let (mut re, mut im, mut err) = (0.0, 0.0, 0.0);
        for (m, c) in &e.terms {
            // the term, a complex number, and a bound on its error's modulus
            let ((mut a, mut b), size) = coef(c);
            let mut et = 4.0 * EPS * size;
            for (v, p) in m {
                let k = f64::from(*p);
                let (x, y, ex) = match v {
                    Var::Pi => {
                        let x = std::f64::consts::PI.powi(*p);
                        (x, 0.0, EPS * (k.abs() + 1.0) * x)
                    }
                    Var::Sym(s) => {
                        let x = self.generic(s)?.powi(*p);
                        (x, 0.0, EPS * (k.abs() + 1.0) * x)
                    }
                    Var::Z(s) => {
                        let angle = match s.phase() {
                            // (u^PI_DEN = −1: the angle reduced exactly)
                            Some(Unit::Pi) => {
                                f64::from(p.rem_euclid(2 * PI_DEN as i32)) * Unit::Pi.radians()
                            }
                            Some(unit) => k * unit.radians(),
                            None => k * self.generic(s)?,
                        };
                        (angle.cos(), angle.sin(), EPS * (angle.abs() + 2.0))
                    }
                    Var::Call(c) => {
                        let (u, eu) = self.call(c)?;
                        // |u^p| over the interval u ± eu, and its slope
                        let (lo, hi) = (u.abs() - eu, u.abs() + eu);
                        if *p < 0 && lo <= 0.0 {
                            return None;
                        }
                        let slope = k.abs()
                            * if *p < 0 {
                                lo.powi(p - 1)
                            } else {
                                hi.powi(p - 1)
                            };
                        let x = u.powi(*p);
                        (x, 0.0, slope * eu + EPS * (k.abs() + 1.0) * x.abs())
                    }
                };
                let (t, f) = ((a * a + b * b).sqrt(), (x * x + y * y).sqrt());
                (a, b) = (a * x - b * y, a * y + b * x);
                et = t * ex + et * f + et * ex + 2.0 * EPS * t * f;
            }
            re += a;
            im += b;
            err += et + 2.0 * EPS * (re.abs() + im.abs());
        }
        // (a real expression: the imaginary parts cancel, within the bound)
        (re.is_finite() && err.is_finite() && im.abs() <= 1e3 * err + 1e-12).then_some((re, err))
    }

    /// A call's value at the generic point and its error bound, carried from
    /// its argument's by the derivative.
    fn call_at(&mut self, c: &Call) -> Option<(f64, f64)> {
        let (x, ex) = self.value(&c.args[0])?;
        let (v, d) = match c.f {
            Func::Sin => (x.sin(), 1.0),
            Func::Cos => (x.cos(), 1.0),
            Func::Tan => (x.tan(), 1.0 + x.tan().powi(2)),
            Func::Asin | Func::Acos if x.abs() + ex < 1.0 => (
                if c.f == Func::Asin {
                    x.asin()
                } else {
                    x.acos()
                },
                1.0 / (1.0 - (x.abs() + ex).powi(2)).sqrt(),
            ),
            Func::Atan => (x.atan(), 1.0),
            Func::Sqrt if x > ex => (x.sqrt(), 0.5 / (x - ex).sqrt()),
            Func::Abs => (x.abs(), 1.0),
            Func::Exp => (x.exp(), (x + ex).exp()),
            Func::Recip if x.abs() > ex => (1.0 / x, 1.0 / (x.abs() - ex).powi(2)),
            Func::Atan2 => {
                let (a, ea) = self.value(c.args.get(1)?)?;
                let r = (x * x + a * a).sqrt();
                if r <= ex + ea {
                    return None;
                }
                (x.atan2(a), 1.0 / (r - ex - ea))
            }
            _ => return None,
        };
        let e = d * ex + 4.0 * EPS * v.abs();
        (v.is_finite() && e.is_finite()).then_some((v, e))
    }
}

impl Mat {
    /// True when M Mᵀ ≠ I at the generic point by far more than rounding:
    /// then M is surely no rotation (its exact test would say so after
    /// forming the product). False when it may be one, or the point does
    /// not tell.
    pub fn surely_not_orthogonal(&self) -> bool {
        let n = self.rows;
        if self.cols != n {
            return true;
        }
        let mut memo = Memo::default();
        let Some(xs) = self
            .data
            .iter()
            .map(|e| memo.value(e))
            .collect::<Option<Vec<_>>>()
        else {
            return false;
        };
        let at = |i: usize, j: usize| xs[i * n + j];
        (0..n).any(|i| {
            (0..n).any(|j| {
                let (mut s, mut e) = (if i == j { -1.0 } else { 0.0 }, 0.0);
                for k in 0..n {
                    let ((a, ea), (b, eb)) = (at(i, k), at(j, k));
                    s += a * b;
                    e += a.abs() * eb + ea * b.abs() + ea * eb + 4.0 * EPS * (a * b).abs();
                }
                s.abs() > 1e3 * e + 1e-9
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::matrix::{rodrigues, rot_axis};
    use super::*;

    fn sym(name: &str) -> Expr {
        Expr::symbol(Symbol::new(name))
    }

    #[test]
    fn rotations_pass_and_their_derivatives_do_not() {
        let (t, u) = (sym("t"), sym("u"));
        let angle = t
            .mul(&t)
            .add(&Expr::sin(&u.mul(&t)))
            .powi(5)
            .unwrap_or_default();
        let r = rot_axis(2, &angle);
        assert!(!r.surely_not_orthogonal());
        let w = [Expr::int(0), Expr::int(0), Expr::int(1)];
        assert!(!rodrigues(&w, &t).surely_not_orthogonal());
        let wrt = super::super::expr::Wrt::Sym(Symbol::new("t"));
        assert!(r.map(|e| e.diff(&wrt)).surely_not_orthogonal());
        assert!(r.scale(&Expr::int(2)).surely_not_orthogonal());
        // a unit axis has no generic point: the exact test decides
        let mut w = Symbol::new("w");
        w.unit = true;
        let r = rot_axis(0, &Expr::symbol(w));
        assert!(!r.scale(&Expr::int(2)).surely_not_orthogonal());
    }

    #[test]
    fn the_bound_covers_cancellation() {
        // (a + b)^12 expanded, minus the same: 0 within its bound
        let (a, b) = (sym("a"), sym("b"));
        let p = a.add(&b).powi(12).unwrap_or_default();
        let (v, e) = value(&p).unwrap_or_default();
        assert!(e > 0.0 && e < 1e-10 * v.abs().max(1.0), "{v} {e}");
        let (z, ez) = value(&p.sub(&p)).unwrap_or((1.0, 0.0));
        assert!(z.abs() <= ez);
    }
}
