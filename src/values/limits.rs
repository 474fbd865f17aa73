//! The work and size limits of symbolic operations (issue 21: answer in
//! time or refuse in time, naming the limit, never after seconds of work):
//! what a product, a sum of products or an inverse would cost is counted
//! before it is formed, against [`MAX_WORK`], [`CHEAP_WORK`] and the
//! expression limit [`super::symbolic::MAX_SYM_NODES`].

use crate::check::ty::Kind;
use crate::sym::Expr;
use crate::sym::matrix::Mat;

/// The most work one operation may do, in packed term products
/// ([`crate::sym::size::work`]; a general term product counts 32): about
/// 0.2 s in a release build. The expression limit of
/// [`super::symbolic::MAX_SYM_NODES`] bounds what is kept; this bounds the
/// work before it is known.
pub const MAX_WORK: usize = 64_000_000;

/// The work an operation may do before the size of its result is known
/// (about 0.05 s in a release build): a product that costs more, and whose
/// terms counted before cancellation pass the expression limit, is
/// refused before any of it is formed (issue 21: refuse in time, never
/// after seconds of work). Cheaper products are formed, and their size
/// checked after (the adjoint of a tilted 6-joint chain cancels from up to
/// 72,105 terms to 6,561).
pub const CHEAP_WORK: usize = 16_000_000;

/// Refuses the product `a b` (`what` names it) before it is formed when
/// its work passes [`MAX_WORK`], or when its work passes [`CHEAP_WORK`]
/// and its terms, counted before cancellation
/// ([`crate::sym::size::product`]), pass the expression limit.
pub fn fits(a: &Mat, b: &Mat, what: &str) -> Result<(), String> {
    let limit = super::symbolic::MAX_SYM_NODES;
    let work = crate::sym::size::product_work(a, b).unwrap_or(0);
    if work > MAX_WORK {
        return Err(format!(
            "symbolic expression too large: the {what} would take {work} term products (more than {MAX_WORK})"
        ));
    }
    if work <= CHEAP_WORK {
        return Ok(());
    }
    match crate::sym::size::product(a, b) {
        Some(n) if n > limit => Err(format!(
            "symbolic expression too large: the {what} would have up to {n} terms (more than {limit})"
        )),
        _ => Ok(()),
    }
}

/// Refuses, as [`fits`] does, what is formed as one sum of products
/// Σ_k a_k·b_k in each entry (`sums`, one per entry; `what` names it):
/// before any of it is formed when its work passes [`MAX_WORK`], or passes
/// [`CHEAP_WORK`] while its terms counted before cancellation pass the
/// expression limit (a derivative as [`Expr::diff_parts`] gives it).
pub fn fits_sums(sums: &[Vec<(&Expr, &Expr)>], what: &str) -> Result<(), String> {
    let limit = super::symbolic::MAX_SYM_NODES;
    let work = sums
        .iter()
        .map(|p| crate::sym::size::flat_work(p))
        .fold(0, usize::saturating_add);
    if work > MAX_WORK {
        return Err(format!(
            "symbolic expression too large: the {what} would take {work} term products (more than {MAX_WORK})"
        ));
    }
    if work <= CHEAP_WORK {
        return Ok(());
    }
    let n: Option<usize> = sums
        .iter()
        .map(|p| crate::sym::size::sum_of_products(p))
        .sum();
    match n {
        Some(n) if n > limit => Err(format!(
            "symbolic expression too large: the {what} would have up to {n} terms (more than {limit})"
        )),
        _ => Ok(()),
    }
}

/// How many times the expression limit the determinant of an inverse may
/// have terms before cancellation ([`fits_inverse`]).
pub const DET_SLACK: usize = 8;

/// Refuses, as [`fits`] does for a product, the inverse adj(A)/det(A) of a
/// general square matrix whose determinant is too large to form: its
/// cofactor expansion has as many terms before cancellation as the
/// permanent of the entries' term counts, and every entry of the inverse
/// holds det(A) (as a reciprocal, unless it cancels). Refused before any
/// of it is formed when that passes [`DET_SLACK`] times the expression
/// limit: the inverse of a 3×3 of 11th to 15th powers of sums of sines
/// and cosines (a determinant of up to 168,881 terms) took 5 s to be
/// refused by the size of its result, and minutes to be classified.
pub fn fits_inverse(kind: &Kind, x: &Mat) -> Result<(), String> {
    if matches!(kind, Kind::SO3 | Kind::SO2 | Kind::SE3) || x.rows != x.cols || x.rows > 4 {
        return Ok(());
    }
    let n = x.rows;
    let sizes: Vec<usize> = x.data.iter().map(|e| e.terms.len().max(1)).collect();
    // the permanent, row by row over the columns not yet taken
    fn permanent(sizes: &[usize], n: usize, row: usize, taken: u32) -> usize {
        if row == n {
            return 1;
        }
        (0..n)
            .filter(|c| taken & (1 << c) == 0)
            .map(|c| {
                sizes[row * n + c].saturating_mul(permanent(sizes, n, row + 1, taken | 1 << c))
            })
            .fold(0, usize::saturating_add)
    }
    let terms = permanent(&sizes, n, 0, 0);
    let limit = super::symbolic::MAX_SYM_NODES;
    if terms > DET_SLACK * limit {
        return Err(format!(
            "symbolic expression too large: the inverse's determinant would have up to {terms} \
             terms before cancellation (more than {})",
            DET_SLACK * limit
        ));
    }
    Ok(())
}
