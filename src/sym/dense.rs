//! The product of two large expressions over packed exponents (issue 21:
//! the product of exponentials of a tilted 6-joint chain, and its adjoint,
//! in milliseconds). Where every coefficient is a complex rational that
//! fits a machine word, both factors are brought to a common denominator,
//! each monomial becomes one integer index into the box of exponents the
//! product can reach, and the product is a convolution of integer
//! coefficients: no fraction is reduced and no monomial compared until the
//! end. The result is the same canonical form as the term-by-term product
//! ([`Expr::mul`]); anything outside these bounds (surds, floats, big
//! fractions, an overflow, a box too large) is left to it.

use std::collections::HashMap;

use super::coef::{Coef, Rat, Surd};
use super::expr::{Expr, Mono, Var};

/// The fewest term products for which the packed product is worth it.
pub const MIN_WORK: usize = 256;
/// The largest box held as a dense array (entries of 32 bytes: 8 MB).
const DENSE_BOX: u64 = 1 << 18;
/// The largest common denominator and scaled numerator (so that a product
/// of two fits an `i128` with room for sums; a sum that overflows falls
/// back).
const WORD: u128 = 1 << 62;

/// One factor: each term's index in the box and its real and imaginary
/// numerators over the common denominator.
struct Packed {
    terms: Vec<(u64, i128, i128)>,
}

/// True when every coefficient of `e` is a complex rational that fits a
/// machine word: the packed product applies (short of an overflow).
pub fn packable(e: &Expr) -> bool {
    e.terms.values().all(|c| match c {
        Coef::Exact { re, im } => small(re).is_some() && small(im).is_some(),
        Coef::Approx { .. } => false,
    })
}

/// The numerator and denominator of a coefficient's real or imaginary part
/// when it is a small rational.
fn small(s: &Surd) -> Option<(i128, i128)> {
    let (n, d) = s.rational()?.small()?;
    Some((i128::from(n), i128::from(d)))
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The least common denominator of every coefficient's parts in `side`
/// (at most [`WORD`]).
fn common_den(side: &[&Expr]) -> Option<u128> {
    let mut den: u128 = 1;
    for c in side.iter().flat_map(|e| e.terms.values()) {
        let Coef::Exact { re, im } = c else {
            return None;
        };
        for part in [re, im] {
            let d = small(part)?.1.unsigned_abs();
            den = den.checked_mul(d / gcd(den, d))?;
            if den > WORD {
                return None;
            }
        }
    }
    Some(den)
}

/// The terms of `e` packed over the denominator `den` (a multiple of each
/// coefficient's): each exponent counted from `lo` with `strides`.
fn pack(e: &Expr, vars: &[&Var], lo: &[i64], strides: &[u64], den: u128) -> Option<Packed> {
    // an absent variable has exponent 0, at offset −lo
    let base: u64 = lo.iter().zip(strides).map(|(l, s)| (-l) as u64 * s).sum();
    let den = den as i128;
    let mut terms = Vec::with_capacity(e.terms.len());
    for (m, c) in &e.terms {
        let Coef::Exact { re, im } = c else {
            return None;
        };
        let ((rn, rd), (inum, id)) = (small(re)?, small(im)?);
        let mut k = base;
        let mut at = 0;
        for (v, x) in m {
            while vars[at] != v {
                at += 1;
            }
            k = k.wrapping_add((i64::from(*x) as u64).wrapping_mul(strides[at]));
        }
        let scale = |n: i128, d: i128| -> Option<i128> {
            let x = n.checked_mul(den / d)?;
            (x.unsigned_abs() <= WORD).then_some(x)
        };
        terms.push((k, scale(rn, rd)?, scale(inum, id)?));
    }
    Some(Packed { terms })
}

/// a·b through packed exponents and integer coefficients; None when the
/// factors are outside the bounds of this path (the caller multiplies
/// term by term). The result is not yet folded ([`Expr::mul`] does that).
pub fn product(a: &Expr, b: &Expr) -> Option<Expr> {
    dot(&[(a, b)])
}

/// Σ_k a_k·b_k (an entry of a matrix product), canonical: packed in one
/// accumulation when it is worth it and within bounds (the products'
/// terms that cancel between them are never formed as maps), else
/// product by product.
pub fn sum_of_products(pairs: &[(&Expr, &Expr)]) -> Expr {
    let pairs: Vec<(&Expr, &Expr)> = pairs
        .iter()
        .copied()
        .filter(|(a, b)| !a.terms.is_empty() && !b.terms.is_empty())
        .collect();
    let work: usize = pairs
        .iter()
        .map(|(a, b)| a.terms.len().saturating_mul(b.terms.len()))
        .fold(0, usize::saturating_add);
    if pairs.len() > 1 && work >= MIN_WORK {
        let phases = pairs.iter().any(|(a, b)| a.has_phase() || b.has_phase());
        if let Some(e) = dot(&pairs) {
            return e.folded(phases);
        }
    }
    pairs
        .iter()
        .fold(Expr::default(), |acc, (a, b)| acc.add(&a.mul(b)))
}

/// Σ_k a_k·b_k, not yet folded, through packed exponents over one box and
/// one common denominator for every a_k and every b_k; None outside the
/// bounds of this path.
fn dot(pairs: &[(&Expr, &Expr)]) -> Option<Expr> {
    let (lefts, rights): (Vec<&Expr>, Vec<&Expr>) = pairs.iter().copied().unzip();
    // the variables of all, in monomial order, and the exponent ranges
    // of each side
    let mut vars: Vec<&Var> = pairs
        .iter()
        .flat_map(|(a, b)| a.terms.keys().chain(b.terms.keys()))
        .flatten()
        .map(|(v, _)| v)
        .collect();
    vars.sort();
    vars.dedup();
    let range = |side: &[&Expr], i: usize| -> (i64, i64) {
        side.iter()
            .flat_map(|e| e.terms.keys())
            .fold((0, 0), |(lo, hi), m| {
                let x = m
                    .iter()
                    .find(|(v, _)| v == vars[i])
                    .map_or(0, |(_, x)| i64::from(*x));
                (lo.min(x), hi.max(x))
            })
    };
    let (mut lo_a, mut lo_b, mut strides) = (Vec::new(), Vec::new(), Vec::new());
    let mut size: u64 = 1;
    for i in 0..vars.len() {
        let ((la, ha), (lb, hb)) = (range(&lefts, i), range(&rights, i));
        lo_a.push(la);
        lo_b.push(lb);
        strides.push(size);
        let span = u64::try_from(ha + hb - la - lb + 1).ok()?;
        size = size.checked_mul(span).filter(|s| *s < 1 << 62)?;
    }
    let (da, db) = (common_den(&lefts)?, common_den(&rights)?);
    let mut packed = Vec::with_capacity(pairs.len());
    for (a, b) in pairs {
        packed.push((
            pack(a, &vars, &lo_a, &strides, da)?,
            pack(b, &vars, &lo_b, &strides, db)?,
        ));
    }
    let sums = convolve(&packed, size)?;
    let den = i128::try_from(da.checked_mul(db)?).ok()?;
    let lo: Vec<i64> = lo_a.iter().zip(&lo_b).map(|(x, y)| x + y).collect();
    let mut terms: Vec<(Mono, Coef)> = Vec::with_capacity(sums.len());
    for (k, re, im) in sums {
        let mut m: Mono = Vec::new();
        let mut rest = k;
        for i in (0..vars.len()).rev() {
            let x = (rest / strides[i]) as i64 + lo[i];
            rest %= strides[i];
            if x != 0 {
                m.push((vars[i].clone(), i32::try_from(x).ok()?));
            }
        }
        m.reverse();
        let c = Coef::Exact {
            re: Surd::rat(Rat::new(re, den)?),
            im: Surd::rat(Rat::new(im, den)?),
        };
        terms.push((m, c));
    }
    // the box is walked in the order of the last variable first; the
    // monomial order is that of the first
    terms.sort_unstable_by(|x, y| x.0.cmp(&y.0));
    Some(Expr {
        terms: terms.into_iter().collect(),
    })
}

/// a·b, monomial by monomial (not yet folded): the general product.
pub fn term_by_term(a: &Expr, b: &Expr) -> Expr {
    let mut out = Expr::default();
    for (m, c) in &a.terms {
        // Past the evaluation budget, a cut-short product (discarded by
        // the session: `crate::budget`).
        if crate::budget::stopped() {
            break;
        }
        for (n, d) in &b.terms {
            out.push(super::expr::mono_mul(m, n), c.mul(d));
        }
    }
    out
}

/// The nonzero sums Σ a_i b_j over i + j = k of every pair, as (k, re, im); None on an
/// overflow or when the evaluation budget stops the work.
fn convolve(pairs: &[(Packed, Packed)], size: u64) -> Option<Vec<(u64, i128, i128)>> {
    let mut dense: Vec<(i128, i128)> = Vec::new();
    let mut sparse: HashMap<u64, (i128, i128)> = HashMap::new();
    let use_dense = size <= DENSE_BOX;
    if use_dense {
        dense = vec![(0, 0); size as usize];
    }
    for (ka, ar, ai, b) in pairs
        .iter()
        .flat_map(|(a, b)| a.terms.iter().map(move |&(k, r, i)| (k, r, i, b)))
    {
        if crate::budget::stopped() {
            return None;
        }
        for &(kb, br, bi) in &b.terms {
            let re = ar * br - ai * bi;
            let im = ar * bi + ai * br;
            let cell = if use_dense {
                &mut dense[(ka + kb) as usize]
            } else {
                sparse.entry(ka + kb).or_insert((0, 0))
            };
            cell.0 = cell.0.checked_add(re)?;
            cell.1 = cell.1.checked_add(im)?;
        }
    }
    let nonzero = |&(_, re, im): &(u64, i128, i128)| re != 0 || im != 0;
    Some(if use_dense {
        dense
            .into_iter()
            .enumerate()
            .map(|(k, (re, im))| (k as u64, re, im))
            .filter(nonzero)
            .collect()
    } else {
        sparse
            .into_iter()
            .map(|(k, (re, im))| (k, re, im))
            .filter(nonzero)
            .collect()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::expr::Symbol;

    #[test]
    fn the_packed_product_is_the_term_by_term_product() {
        let v = |n: &str| Expr::symbol(Symbol::new(n));
        let k = |n, d| Expr::constant(Coef::rat(Rat::new(n, d).unwrap()));
        let x = Expr::cos(&v("a"))
            .mul(&k(3, 5))
            .add(&Expr::sin(&v("b")).mul(&k(-4, 7)))
            .add(&v("L").mul(&Expr::cos(&v("a").add(&v("c")))))
            .add(&k(1, 3));
        let y = x.mul(&x).add(&Expr::sin(&v("c")).mul(&v("L")));
        let slow = term_by_term;
        assert_eq!(product(&x, &y), Some(slow(&x, &y)));
        assert_eq!(product(&y, &y), Some(slow(&y, &y)));
        // a sum of products in one accumulation, with terms that cancel
        let z = y.neg().add(&Expr::cos(&v("b")));
        let pairs = [(&x, &y), (&y, &x), (&x, &z), (&z, &z)];
        let by_products = pairs
            .iter()
            .fold(Expr::default(), |acc, (a, b)| acc.add(&a.mul(b)));
        assert_eq!(sum_of_products(&pairs), by_products);
        // a surd is outside this path
        let r = Expr::constant(Coef::real(
            crate::sym::coef::Surd::sqrt_of(&Rat::int(2)).unwrap(),
        ));
        assert_eq!(product(&x.mul(&r), &y), None);
    }
}
