//! Symbolic axes (LANGUAGE.md §7; Rodrigues' formula (3.51), Proposition
//! 3.16): the components of a `given` vector are symbols `w[1]`, `w[2]`,
//! `w[3]`. Where an exponential takes such a vector as its axis, the book's
//! ω̂ is a unit vector: its components become *unit* components, and the
//! canonical form holds ω̂₁² + ω̂₂² + ω̂₃² = 1 by writing ω̂₃² as
//! 1 − ω̂₁² − ω̂₂². The relation is monic in ω̂₃, so the remainder (at most
//! linear in ω̂₃) is unique: two expressions equal on the unit sphere have
//! equal forms, and `==` stays decided exactly. A negative power of ω̂₃ is
//! not reduced; [`Expr::unit_reduced`] tells the comparison so.

use std::sync::Arc;

use super::coef::Coef;
use super::expr::{Expr, Mono, Symbol, Var};
use num_traits::{One, Zero};

impl Symbol {
    /// Component `index` (1-based) of the `given` vector `name`, `w[2]`.
    pub fn component(name: &str, index: u8) -> Symbol {
        Symbol {
            index,
            ..Symbol::new(name)
        }
    }
    /// Component `index` of the same vector, with the same unit mark.
    fn sibling(&self, index: u8) -> Symbol {
        Symbol {
            index,
            ..self.clone()
        }
    }
    /// ω̂₃ of a unit axis: the component the relation eliminates.
    fn is_last_unit(&self) -> bool {
        self.unit && self.index == 3
    }
    /// One of ω̂₁, ω̂₂, ω̂₃ of a vector, not yet marked unit.
    fn plain_axis_part(&self) -> bool {
        (1..=3).contains(&self.index) && !self.unit && self.dots == 0 && self.time.is_none()
    }
}

/// The components of a `given` vector of `n` entries, as symbols.
pub fn components(name: &str, n: u8) -> Vec<Expr> {
    (1..=n)
        .map(|i| Expr::symbol(Symbol::component(name, i)))
        .collect()
}

fn square(s: &Symbol) -> Expr {
    let x = Expr::symbol(s.clone());
    x.mul(&x)
}

impl Expr {
    /// ω̂₃² = 1 − ω̂₁² − ω̂₂² for every unit axis (a power ω̂₃ᵉ, e ≥ 2,
    /// becomes (1 − ω̂₁² − ω̂₂²)^⌊e/2⌋ ω̂₃^(e mod 2)): the canonical form on
    /// the unit sphere.
    pub(super) fn fold_units(self) -> Expr {
        let hit = |v: &Var, e: i32| matches!(v, Var::Sym(s) if s.is_last_unit()) && e >= 2;
        if !self.terms.keys().flatten().any(|(v, e)| hit(v, *e)) {
            return self;
        }
        let mut out = Expr::zero();
        for (m, c) in self.terms {
            let mut rest: Mono = Vec::with_capacity(m.len());
            let mut t = Expr::constant(c);
            for (v, e) in m {
                match &v {
                    Var::Sym(s) if hit(&v, e) => {
                        let left = Expr::one()
                            .sub(&square(&s.sibling(1)))
                            .sub(&square(&s.sibling(2)));
                        t = t.mul(&left.powi(i64::from(e / 2)).unwrap_or_default());
                        if e % 2 != 0 {
                            rest.push((v.clone(), 1));
                        }
                    }
                    _ => rest.push((v, e)),
                }
            }
            let mut r = Expr::zero();
            r.push(rest, Coef::one());
            out = out.add(&t.mul(&r));
        }
        out
    }

    /// True when the form is the unique one on the unit sphere: no
    /// negative power of a unit ω̂₃ (1/ω̂₃ is kept as it is).
    pub fn unit_reduced(&self) -> bool {
        !self
            .terms
            .keys()
            .flatten()
            .any(|(v, e)| matches!(v, Var::Sym(s) if s.is_last_unit()) && *e < 0)
    }

    /// The `given` vectors whose components appear here as unit components
    /// (the axes assumed to be unit vectors).
    pub fn unit_axes(&self, out: &mut Vec<Arc<str>>) {
        let mut syms = Vec::new();
        self.symbols(&mut syms);
        for s in syms {
            if s.unit && !out.contains(&s.name) {
                out.push(s.name.clone());
            }
        }
    }

    /// The components 1–3 of the vectors `names` taken as the unit axis
    /// they were assumed to be elsewhere in the same expression (so that
    /// R w = w for R = exp(\[w\] t)), reduced on the sphere.
    pub fn assume_unit(&self, names: &[Arc<str>]) -> Expr {
        let mut syms = Vec::new();
        self.symbols(&mut syms);
        if !syms
            .iter()
            .any(|s| s.plain_axis_part() && names.contains(&s.name))
        {
            return self.clone();
        }
        self.subst(&|s| {
            (s.plain_axis_part() && names.contains(&s.name)).then(|| {
                Expr::symbol(Symbol {
                    unit: true,
                    ..s.clone()
                })
            })
        })
    }
}

/// u = ω̂θ with ω̂ the components of one `given` vector, taken as a unit
/// axis, and θ an expression: (ω̂ as unit components, θ). None when u is
/// no such product (a numeric axis is [`super::matrix::exp3`]'s case).
pub fn symbolic_axis(u: &[Expr]) -> Option<(Vec<Expr>, Expr)> {
    if u.len() != 3 {
        return None;
    }
    let mut syms = Vec::new();
    u.iter().for_each(|e| e.symbols(&mut syms));
    let mut tried: Vec<Arc<str>> = Vec::new();
    for s in &syms {
        if s.index != 1 || s.dots > 0 || s.time.is_some() || tried.contains(&s.name) {
            continue;
        }
        tried.push(s.name.clone());
        let unit: Vec<Expr> = (1..=3)
            .map(|i| {
                Expr::symbol(Symbol {
                    unit: true,
                    ..s.sibling(i)
                })
            })
            .collect();
        let u: Vec<Expr> = u
            .iter()
            .map(|e| e.assume_unit(&tried[tried.len() - 1..]))
            .collect();
        let Some(theta) = u[0].div_exact(&unit[0]) else {
            continue;
        };
        if theta.is_zero() || !theta.unit_reduced() {
            continue;
        }
        if unit.iter().zip(&u).all(|(w, x)| w.mul(&theta) == *x) {
            return Some((unit, theta));
        }
    }
    None
}

/// The unit axis of `Rot(v, θ)` for v a positive multiple of a `given`
/// vector's components (Rot normalizes its axis): ω̂ as unit components.
pub fn unit_direction(v: &[Expr]) -> Option<Vec<Expr>> {
    let (axis, k) = symbolic_axis(v)?;
    let k = k.as_const()?;
    (k.to_c64().0 > 0.0 && k.to_c64().1 == 0.0).then_some(axis)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::matrix::{Mat, rodrigues, skew};

    fn s(n: &str) -> Expr {
        Expr::symbol(Symbol::new(n))
    }

    fn unit_w() -> Vec<Expr> {
        symbolic_axis(&components("w", 3)).unwrap().0
    }

    #[test]
    fn the_unit_relation_is_applied_canonically() {
        let w = unit_w();
        let n2 = w.iter().fold(Expr::zero(), |acc, x| acc.add(&x.mul(x)));
        assert_eq!(n2, Expr::one());
        // ω̂₃⁴ = (1 − ω̂₁² − ω̂₂²)²
        let w34 = w[2].powi(4).unwrap();
        let left = Expr::one().sub(&w[0].mul(&w[0])).sub(&w[1].mul(&w[1]));
        assert_eq!(w34, left.mul(&left));
        // plain components have no relation
        let p = components("w", 3);
        let p2 = p.iter().fold(Expr::zero(), |acc, x| acc.add(&x.mul(x)));
        assert_ne!(p2, Expr::one());
        assert_eq!(p2.assume_unit(&["w".into()]), Expr::one());
    }

    #[test]
    fn an_axis_times_an_angle_splits() {
        let (t1, t2) = (s("t1"), s("t2"));
        let theta = t1.add(&t2);
        let u: Vec<Expr> = components("w", 3).iter().map(|x| x.mul(&theta)).collect();
        let (axis, th) = symbolic_axis(&u).unwrap();
        assert_eq!(th, theta);
        assert_eq!(axis, unit_w());
        // (w1 t, w2 t, 2 w3 t) is no axis times an angle
        let mut bad = u.clone();
        bad[2] = bad[2].scale(&Coef::int(2));
        assert!(symbolic_axis(&bad).is_none());
        let twice: Vec<Expr> = components("w", 3)
            .iter()
            .map(|x| x.scale(&Coef::int(2)))
            .collect();
        assert_eq!(unit_direction(&twice), Some(unit_w()));
        let neg: Vec<Expr> = components("w", 3).iter().map(Expr::neg).collect();
        assert_eq!(unit_direction(&neg), None);
    }

    #[test]
    fn rodrigues_with_a_symbolic_axis_is_a_rotation_about_it() {
        let (a, b) = (s("a"), s("b"));
        let w = unit_w();
        let r = rodrigues(&w, &a);
        assert_eq!(r.mul(&r.transpose()).unwrap(), Mat::identity(3));
        assert_eq!(r.det().unwrap(), Expr::one());
        assert_eq!(
            r.mul(&Mat::column(w.clone())).unwrap(),
            Mat::column(w.clone())
        );
        let ab = r.mul(&rodrigues(&w, &b)).unwrap();
        assert_eq!(ab, rodrigues(&w, &a.add(&b)));
        // the diagonal is cos θ + (1 − cos θ) ω̂₁² (3.52)
        let c = Expr::cos(&a);
        assert_eq!(
            *r.get(0, 0),
            c.add(&Expr::one().sub(&c).mul(&w[0].mul(&w[0])))
        );
        assert_eq!(
            skew(&w).mul(&Mat::column(w.clone())).unwrap(),
            Mat::zeros(3, 1)
        );
    }
}
