//! The size of a product before it is formed (issue 21: refuse in time,
//! never after seconds of work). A monomial of a·b is a monomial of a
//! times one of b, so the terms of a·b are (before any cancel) the
//! Minkowski sum of the two sets of exponent vectors. Exponents are
//! packed into one integer index over the box they can span, and the sum
//! of sets is a union of shifted bit sets: a few thousand word operations
//! where forming the product takes millions of coefficient products.

use super::expr::{Expr, Var};
use super::matrix::Mat;

/// The most bits of a box the estimate spans (2 MB); beyond it, or when
/// the shifts would cost more than [`MAX_OPS`], there is no estimate.
const MAX_BITS: usize = 1 << 24;
/// The most word operations an estimate may take.
const MAX_OPS: usize = 10_000_000;

/// The number of terms of Σ_k a_k·b_k before cancellation (the Minkowski
/// sums of their monomials, united): the size of one entry of a matrix
/// product, or of one product when there is one pair. None when it cannot
/// be told cheaply.
pub fn sum_of_products(pairs: &[(&Expr, &Expr)]) -> Option<usize> {
    let pairs: Vec<(&Expr, &Expr)> = pairs
        .iter()
        .copied()
        .filter(|(a, b)| !a.terms.is_empty() && !b.terms.is_empty())
        .collect();
    if pairs.is_empty() {
        return Some(0);
    }
    // the variables, and the exponents' range of each side
    let mut vars: Vec<&Var> = Vec::new();
    let mut lo_a: Vec<i64> = Vec::new();
    let mut hi_a: Vec<i64> = Vec::new();
    let mut lo_b: Vec<i64> = Vec::new();
    let mut hi_b: Vec<i64> = Vec::new();
    for (side, e) in pairs.iter().flat_map(|(a, b)| [(0, *a), (1, *b)]) {
        for m in e.terms.keys() {
            for (v, _) in m {
                if !vars.contains(&v) {
                    vars.push(v);
                    for r in [&mut lo_a, &mut hi_a, &mut lo_b, &mut hi_b] {
                        r.push(0);
                    }
                }
            }
            for (i, v) in vars.iter().enumerate() {
                let x = m
                    .iter()
                    .find(|(w, _)| w == *v)
                    .map_or(0, |(_, x)| i64::from(*x));
                let (lo, hi) = if side == 0 {
                    (&mut lo_a, &mut hi_a)
                } else {
                    (&mut lo_b, &mut hi_b)
                };
                lo[i] = lo[i].min(x);
                hi[i] = hi[i].max(x);
            }
        }
    }
    // strides of the box of a·b
    let mut strides = Vec::with_capacity(vars.len());
    let mut bits: usize = 1;
    for i in 0..vars.len() {
        strides.push(bits);
        let span = usize::try_from(hi_a[i] + hi_b[i] - lo_a[i] - lo_b[i] + 1).ok()?;
        bits = bits.checked_mul(span).filter(|b| *b <= MAX_BITS)?;
    }
    let words = bits.div_ceil(64);
    let index = |e: &Expr, lo: &[i64]| -> Vec<usize> {
        e.terms
            .keys()
            .map(|m| {
                vars.iter()
                    .enumerate()
                    .map(|(i, v)| {
                        let x = m
                            .iter()
                            .find(|(w, _)| w == *v)
                            .map_or(0, |(_, x)| i64::from(*x));
                        (x - lo[i]) as usize * strides[i]
                    })
                    .sum()
            })
            .collect()
    };
    let ops: usize = pairs
        .iter()
        .map(|(a, b)| a.terms.len().min(b.terms.len()) * words)
        .sum();
    if ops > MAX_OPS {
        return None;
    }
    let mut out = vec![0u64; words];
    for (a, b) in &pairs {
        let (ia, ib) = (index(a, &lo_a), index(b, &lo_b));
        let (shifts, set) = if ia.len() <= ib.len() {
            (ia, ib)
        } else {
            (ib, ia)
        };
        let mut base = vec![0u64; words];
        for k in set {
            base[k / 64] |= 1 << (k % 64);
        }
        for s in shifts {
            or_shifted(&mut out, &base, s);
        }
    }
    Some(out.iter().map(|w| w.count_ones() as usize).sum())
}

/// The number of terms of the product `a b` before cancellation: a scalar
/// times a matrix entrywise, else the matrix product (None for sizes that
/// do not multiply, or when it cannot be told cheaply).
pub fn product(a: &Mat, b: &Mat) -> Option<usize> {
    let scaled = |k: &Expr, m: &Mat| -> Option<usize> {
        m.data.iter().map(|e| sum_of_products(&[(k, e)])).sum()
    };
    match (a.data.as_slice(), b.data.as_slice()) {
        ([k], _) => scaled(k, b),
        (_, [k]) => scaled(k, a),
        _ if a.cols == b.rows => {
            let mut n = 0;
            for i in 0..a.rows {
                for j in 0..b.cols {
                    let pairs: Vec<(&Expr, &Expr)> =
                        (0..a.cols).map(|k| (a.get(i, k), b.get(k, j))).collect();
                    n += sum_of_products(&pairs)?;
                }
            }
            Some(n)
        }
        _ => None,
    }
}

/// The number of terms of xⁿ before cancellation (n·supp x, formed on bit
/// sets by squaring as the power itself is), or at least that many once
/// it passes `limit`: x^m has no more terms than xⁿ for m ≤ n (n·S holds a
/// translate of m·S), so the count stops at the first power past the
/// limit. None when it cannot be told cheaply.
pub fn power(x: &Expr, n: u64, limit: usize) -> Option<usize> {
    if n == 0 || x.terms.len() <= 1 {
        return Some(x.terms.len().min(1).max(usize::from(n == 0)));
    }
    let n = i64::try_from(n).ok()?;
    let mut vars: Vec<&Var> = Vec::new();
    for m in x.terms.keys() {
        for (v, _) in m {
            if !vars.contains(&v) {
                vars.push(v);
            }
        }
    }
    let exps = |m: &super::expr::Mono| -> Vec<i64> {
        vars.iter()
            .map(|v| {
                m.iter()
                    .find(|(w, _)| w == *v)
                    .map_or(0, |(_, e)| i64::from(*e))
            })
            .collect()
    };
    let all: Vec<Vec<i64>> = x.terms.keys().map(exps).collect();
    let (mut lo, mut hi) = (vec![0i64; vars.len()], vec![0i64; vars.len()]);
    for e in &all {
        for i in 0..vars.len() {
            lo[i] = lo[i].min(e[i]);
            hi[i] = hi[i].max(e[i]);
        }
    }
    // the box of xⁿ, offsets counted from n·lo
    let mut strides = Vec::with_capacity(vars.len());
    let mut bits: usize = 1;
    for i in 0..vars.len() {
        strides.push(bits);
        let span = usize::try_from((hi[i] - lo[i]).checked_mul(n)? + 1).ok()?;
        bits = bits.checked_mul(span)?;
    }
    let points: Vec<usize> = all
        .iter()
        .map(|e| {
            (0..vars.len())
                .map(|i| (e[i] - lo[i]) as usize * strides[i])
                .sum()
        })
        .collect();
    if bits <= MAX_BITS {
        let words = bits.div_ceil(64);
        let mut base = vec![0u64; words];
        for k in &points {
            base[k / 64] |= 1 << (k % 64);
        }
        let mut ops = 0usize;
        let mut sum = |a: &Vec<u64>, b: &Vec<u64>| -> Option<Vec<u64>> {
            let (shifts, set) = if count(a) <= count(b) { (a, b) } else { (b, a) };
            ops = ops.checked_add(count(shifts).checked_mul(words)?)?;
            if ops > MAX_OPS {
                return None;
            }
            let mut out = vec![0u64; words];
            for (w, word) in shifts.iter().enumerate() {
                let mut bits = *word;
                while bits != 0 {
                    let b = bits.trailing_zeros() as usize;
                    bits &= bits - 1;
                    or_shifted(&mut out, set, w * 64 + b);
                }
            }
            Some(out)
        };
        if let Some(k) = by_squaring(base, n, limit, &mut sum, |s| count(s)) {
            return Some(k);
        }
    }
    // a box too large for bits (many angles): sets of indices, each sum
    // stopped past the limit
    let mut pairs = 0usize;
    let mut sum = |a: &Vec<usize>, b: &Vec<usize>| -> Option<Vec<usize>> {
        let mut out = std::collections::HashSet::new();
        'all: for x in a {
            for y in b {
                pairs += 1;
                if pairs > MAX_PAIRS {
                    return None;
                }
                out.insert(x + y);
                if out.len() > limit {
                    break 'all;
                }
            }
        }
        Some(out.into_iter().collect())
    };
    by_squaring(points, n, limit, &mut sum, Vec::len)
}

/// The most index pairs the set form of [`power`] may add.
const MAX_PAIRS: usize = 4_000_000;

/// The members of a bit set.
fn count(s: &[u64]) -> usize {
    s.iter().map(|w| w.count_ones() as usize).sum()
}

/// n·S by squaring with the Minkowski sum `sum`, stopped as soon as a
/// partial sum has more than `limit` members (returning that count).
fn by_squaring<S: Clone>(
    mut base: S,
    mut n: i64,
    limit: usize,
    sum: &mut impl FnMut(&S, &S) -> Option<S>,
    len: impl Fn(&S) -> usize,
) -> Option<usize> {
    let mut acc: Option<S> = None;
    while n > 0 {
        if n & 1 == 1 {
            let a = match &acc {
                None => base.clone(),
                Some(a) => sum(a, &base)?,
            };
            if len(&a) > limit {
                return Some(len(&a));
            }
            acc = Some(a);
        }
        n >>= 1;
        if n > 0 {
            base = sum(&base, &base)?;
            if len(&base) > limit {
                return Some(len(&base));
            }
        }
    }
    acc.map(|a| len(&a))
}

/// The work of one term product by the general path, in packed term
/// products ([`super::dense`]; measured in release builds, about 30 times
/// slower).
pub const GENERAL_COST: usize = 32;

/// The work of forming Σ_k a_k·b_k, in packed term products: each pair's
/// terms multiplied, weighted by the path the product takes (and, on the
/// general path, by the words of big coefficients, [`Expr::size`]). Known
/// before any of it is done, so that an operation can be refused in time.
pub fn work(pairs: &[(&Expr, &Expr)]) -> usize {
    pairs
        .iter()
        .map(|(a, b)| {
            let n = a.terms.len().saturating_mul(b.terms.len());
            let packed = n >= super::dense::MIN_WORK
                && super::dense::packable(a)
                && super::dense::packable(b);
            if packed {
                n
            } else {
                a.size()
                    .saturating_mul(b.size())
                    .saturating_mul(GENERAL_COST)
            }
        })
        .fold(0, usize::saturating_add)
}

/// [`work`] with kept calls' arguments not counted: a term product
/// compares shared calls by pointer, so their arguments cost it nothing
/// (a derivative's parts hold its entries' calls in most terms, and
/// [`work`] charged their arguments' size to every product: 4.3e9 for
/// 13,392 term products).
pub fn flat_work(pairs: &[(&Expr, &Expr)]) -> usize {
    let flat = |e: &Expr| -> usize { e.terms.values().map(|c| 1 + c.words()).sum() };
    pairs
        .iter()
        .map(|(a, b)| {
            let n = a.terms.len().saturating_mul(b.terms.len());
            let packed = n >= super::dense::MIN_WORK
                && super::dense::packable(a)
                && super::dense::packable(b);
            if packed {
                n
            } else {
                flat(a).saturating_mul(flat(b)).saturating_mul(GENERAL_COST)
            }
        })
        .fold(0, usize::saturating_add)
}

/// The work of the product `a b` (as [`product`] forms it), in packed term
/// products; None for sizes that do not multiply.
pub fn product_work(a: &Mat, b: &Mat) -> Option<usize> {
    let scaled = |k: &Expr, m: &Mat| m.data.iter().map(|e| work(&[(k, e)])).sum();
    match (a.data.as_slice(), b.data.as_slice()) {
        ([k], _) => Some(scaled(k, b)),
        (_, [k]) => Some(scaled(k, a)),
        _ if a.cols == b.rows => {
            let mut n = 0usize;
            for i in 0..a.rows {
                for j in 0..b.cols {
                    let pairs: Vec<(&Expr, &Expr)> =
                        (0..a.cols).map(|k| (a.get(i, k), b.get(k, j))).collect();
                    n = n.saturating_add(work(&pairs));
                }
            }
            Some(n)
        }
        _ => None,
    }
}

/// `out |= base << s` (bit sets of the same length; bits shifted past the
/// end cannot be set, the box holds every sum).
fn or_shifted(out: &mut [u64], base: &[u64], s: usize) {
    let (w, b) = (s / 64, s % 64);
    for i in (w..out.len()).rev() {
        let j = i - w;
        let mut x = base[j] << b;
        if b > 0 && j > 0 {
            x |= base[j - 1] >> (64 - b);
        }
        out[i] |= x;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sym::Symbol;

    #[test]
    fn the_estimate_counts_the_terms_of_a_product() {
        let v = |n: &str| Expr::symbol(Symbol::new(n));
        let x = Expr::cos(&v("a"))
            .add(&Expr::cos(&v("b")))
            .add(&Expr::cos(&v("c")))
            .add(&Expr::int(1));
        let x4 = x.powi(4).unwrap();
        let x8 = x4.mul(&x4);
        assert_eq!(sum_of_products(&[(&x4, &x4)]), Some(x8.terms.len()));
        let y = v("L").add(&Expr::sin(&v("a")));
        // sin a cos a = sin(2a)/2: a term cancels, the count is an upper bound
        assert_eq!(
            sum_of_products(&[(&y, &x)]),
            Some(y.mul(&x).terms.len() + 1)
        );
        assert_eq!(power(&x, 8, usize::MAX), Some(x8.terms.len()));
        assert!(power(&y, 5, usize::MAX) >= Some(y.powi(5).unwrap().terms.len()));
        // a sum of products: the union
        let both = x.mul(&x).add(&y.mul(&y));
        assert!(sum_of_products(&[(&x, &x), (&y, &y)]) >= Some(both.terms.len()));
    }
}
