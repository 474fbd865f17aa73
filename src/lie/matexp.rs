//! The exponential of a general square matrix, `e^{A} = I + A + A²/2! + …`
//! (3.42)/(3.48), the solution operator of the linear ODE `ẋ = Ax`
//! (Proposition 3.7), for exercises 3.33–3.35.

use nalgebra::DMatrix;

/// `e^{A}` of a square matrix (3.48): scaling and squaring with a Padé
/// approximant (Higham 2005, as implemented by nalgebra's `Matrix::exp`),
/// accurate to a few ulps relative to ‖e^{A}‖ for well-conditioned A.
///
/// Panics if `a` is not square; the fallible form is [`try_expm`].
pub fn expm(a: &DMatrix<f64>) -> DMatrix<f64> {
    assert!(a.is_square(), "expm: the matrix must be square");
    if a.nrows() == 0 {
        return a.clone();
    }
    a.clone().exp()
}

/// [`expm`] that returns `None` for a non-square matrix or one with a
/// non-finite entry instead of panicking or producing NaN.
pub fn try_expm(a: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    if !a.is_square() || a.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let e = expm(a);
    e.iter().all(|x| x.is_finite()).then_some(e)
}

/// About how many n×n products (and solves) [`expm`] spends on `a`: the
/// degree-13 Padé approximant (6 products and one LU solve, counted as 8)
/// plus one squaring for each halving that brings ‖A‖₁ below θ₁₃ ≈ 5.37
/// (Higham 2005, Table 2.3). An upper estimate for small norms, where a
/// lower degree is used.
pub fn cost_in_products(a: &DMatrix<f64>) -> u64 {
    const THETA_13: f64 = 5.371_920_351_148_152;
    let norm1 = a
        .column_iter()
        .map(|c| c.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let squarings = if norm1 > THETA_13 {
        // Finite input has ‖A‖₁ < 1.8e308: at most ~1025 halvings.
        (norm1 / THETA_13).log2().ceil().min(2048.0) as u64
    } else {
        0
    };
    8 + squarings
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lie::{Vec3, so3};

    #[test]
    fn matches_rodrigues() {
        let w = Vec3::new(1.0, 2.0, 3.0);
        let a = DMatrix::from_iterator(3, 3, so3::hat(&w).iter().copied());
        let e = expm(&a);
        let r = so3::exp(&w);
        for i in 0..3 {
            for j in 0..3 {
                assert!((e[(i, j)] - r[(i, j)]).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn diagonal_and_nilpotent() {
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, -2.0]);
        let e = expm(&a);
        assert!((e[(0, 0)] - 1f64.exp()).abs() < 1e-15 * 3.0);
        assert!((e[(1, 1)] - (-2f64).exp()).abs() < 1e-16);
        let n = DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
        let e = expm(&n);
        let want = DMatrix::from_row_slice(3, 3, &[1.0, 1.0, 0.5, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0]);
        assert!((e - want).amax() < 1e-15);
        assert!(try_expm(&DMatrix::zeros(2, 3)).is_none());
        // Large norm: e^{diag(30, -30)}.
        let a = DMatrix::from_row_slice(2, 2, &[30.0, 0.0, 0.0, -30.0]);
        let e = expm(&a);
        assert!((e[(0, 0)] / 30f64.exp() - 1.0).abs() < 1e-13);
    }

    #[test]
    fn cost_counts_squarings() {
        assert_eq!(cost_in_products(&DMatrix::identity(4, 4)), 8);
        // ‖A‖₁ = 60: 60/5.37 ≈ 11.2 → 4 halvings.
        let a = DMatrix::from_row_slice(2, 2, &[30.0, 0.0, 30.0, -30.0]);
        assert_eq!(cost_in_products(&a), 12);
        let huge = DMatrix::from_row_slice(1, 1, &[1e300]);
        assert_eq!(cost_in_products(&huge), 8 + 995);
    }
}
