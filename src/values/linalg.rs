//! The inverse and determinant of a plain square matrix, judged by
//! conditioning, not by the size of the determinant: LU with partial
//! pivoting (nalgebra's) is exact about scale — `1e200·I`, `1e-200·I` and
//! `36·I₂₀₀` invert to full precision although their determinants
//! overflow or underflow — and the reciprocal condition number
//! rcond = 1/(‖A‖₁‖A⁻¹‖₁) says how many digits the inverse lost.
//! A matrix is singular when a pivot is exactly zero or rcond is below
//! the machine epsilon (singular to working precision, as MATLAB calls
//! it); it is ill-conditioned, with a warning, below [`ILL_CONDITIONED`].

use nalgebra::DMatrix;

use super::error::OpError;

/// Below this reciprocal condition number an inverse has lost more than
/// ten of its sixteen digits: a warning says so.
pub const ILL_CONDITIONED: f64 = 1e-10;

/// An inverse and how well it is determined.
#[derive(Debug, Clone)]
pub struct Inverse {
    /// The inverse matrix A⁻¹.
    pub m: DMatrix<f64>,
    /// The reciprocal condition number in the 1-norm, in (0, 1].
    pub rcond: f64,
}

/// The largest column sum of absolute values, ‖A‖₁.
fn norm1(m: &DMatrix<f64>) -> f64 {
    m.column_iter()
        .map(|c| c.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

/// rcond = 1/(‖A‖₁‖A⁻¹‖₁), each norm split into mantissa and power of
/// two, so that the product of a huge and a tiny norm neither overflows
/// nor underflows.
fn rcond(a: &DMatrix<f64>, inv: &DMatrix<f64>) -> f64 {
    let (na, ni) = (norm1(a), norm1(inv));
    if na == 0.0 || ni == 0.0 || !na.is_finite() || !ni.is_finite() {
        return 0.0;
    }
    let (ea, ei) = (na.log2().floor(), ni.log2().floor());
    let (ma, mi) = (na / ea.exp2(), ni / ei.exp2());
    (1.0 / (ma * mi)) * (-(ea + ei)).exp2()
}

/// The inverse of a square matrix with finite entries, by LU with partial
/// pivoting; Err for a singular matrix (an exactly zero pivot, or rcond
/// below the machine epsilon) or an inverse whose entries overflow.
pub fn inverse(a: &DMatrix<f64>) -> Result<Inverse, OpError> {
    let n = a.nrows();
    if n == 0 {
        return Ok(Inverse {
            m: a.clone(),
            rcond: 1.0,
        });
    }
    let lu = a.clone().lu();
    let Some(m) = lu.try_inverse() else {
        return Err(OpError::Singular(Some(0.0)));
    };
    if m.iter().any(|x| !x.is_finite()) {
        return Err(OpError::InverseOverflow);
    }
    let rcond = rcond(a, &m);
    if rcond < f64::EPSILON {
        return Err(OpError::SingularToPrecision(rcond));
    }
    Ok(Inverse { m, rcond })
}

/// The warning for an ill-conditioned inverse, if it is one.
pub fn conditioning_note(rcond: f64) -> Option<String> {
    (rcond < ILL_CONDITIONED).then(|| {
        let digits = (-rcond.log10()).round();
        format!(
            "the matrix is ill-conditioned (reciprocal condition number {rcond:.1e}): its inverse may have lost about {digits} of its 16 digits"
        )
    })
}

/// The determinant by LU, and whether it underflowed or overflowed: the
/// product of the pivots leaves the range of f64 although no pivot is
/// zero (`det(1e-200·I₃)` is 1e-600, printed as 0).
pub fn determinant(a: &DMatrix<f64>) -> (f64, Option<Range>) {
    let lu = a.clone().lu();
    let det = lu.determinant();
    let u = lu.u();
    let pivots = u.diagonal();
    if pivots.iter().any(|p| *p == 0.0 || !p.is_finite()) {
        return (det, None);
    }
    let log2: f64 = pivots.iter().map(|p| p.abs().log2()).sum();
    let range = if det == 0.0 || (det.is_subnormal() && log2 < -1022.0) {
        Some(Range::Under(log2 * std::f64::consts::LOG10_2))
    } else if det.is_infinite() {
        Some(Range::Over(log2 * std::f64::consts::LOG10_2))
    } else {
        None
    };
    (det, range)
}

/// A determinant outside the range of f64, with its decimal exponent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Range {
    /// Smaller than 2.2e-308 in size (printed as 0, or a subnormal number
    /// with fewer digits).
    Under(f64),
    /// Larger than 1.8e308 (printed as inf).
    Over(f64),
}

impl Range {
    /// The warning's text.
    pub fn note(self) -> String {
        match self {
            Range::Under(e) => format!(
                "the determinant underflows: it is about 1e{}, below the smallest normal number (2.2e-308), so it prints as 0 or with few digits; the matrix need not be singular (inv and rank judge that)",
                e.round()
            ),
            Range::Over(e) => format!(
                "the determinant overflows: it is about 1e{}, above the largest number (1.8e308)",
                e.round()
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: &DMatrix<f64>, b: &DMatrix<f64>) -> f64 {
        (a - b).abs().max() / b.abs().max()
    }

    #[test]
    fn scaled_matrices_invert_to_full_precision() {
        let cases: Vec<(DMatrix<f64>, DMatrix<f64>)> = vec![
            (
                DMatrix::identity(2, 2) * 1e200,
                DMatrix::identity(2, 2) * 1e-200,
            ),
            (
                DMatrix::identity(2, 2) * 1e-200,
                DMatrix::identity(2, 2) * 1e200,
            ),
            (
                DMatrix::identity(200, 200) * 36.0,
                DMatrix::identity(200, 200) / 36.0,
            ),
            (
                DMatrix::from_row_slice(2, 2, &[2.0, 1.0, 1.0, 1.0]) * 1e-170,
                DMatrix::from_row_slice(2, 2, &[1.0, -1.0, -1.0, 2.0]) * 1e170,
            ),
            (
                DMatrix::identity(2, 2) * 1e-160,
                DMatrix::identity(2, 2) * 1e160,
            ),
        ];
        for (a, want) in cases {
            let inv = inverse(&a).unwrap();
            assert!(rel(&inv.m, &want) < 1e-12, "{a}: {}", inv.m);
            assert!(inv.rcond > 0.1, "{}", inv.rcond);
        }
    }

    #[test]
    fn singular_only_when_it_is() {
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]);
        assert_eq!(inverse(&a).unwrap_err(), OpError::Singular(Some(0.0)));
        let b = DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        assert!(matches!(
            inverse(&b).unwrap_err(),
            OpError::SingularToPrecision(_)
        ));
        // Hilbert(8): cond ≈ 1.5e10, invertible with a warning.
        let h = DMatrix::from_fn(8, 8, |i, j| 1.0 / (i + j + 1) as f64);
        let inv = inverse(&h).unwrap();
        assert!(inv.rcond < ILL_CONDITIONED);
        assert!(
            conditioning_note(inv.rcond)
                .unwrap()
                .contains("ill-conditioned")
        );
        assert!(conditioning_note(0.5).is_none());
    }

    #[test]
    fn determinants_say_when_they_leave_the_range() {
        let (d, r) = determinant(&(DMatrix::identity(3, 3) * 1e-200));
        assert_eq!(d, 0.0);
        assert!(matches!(r, Some(Range::Under(e)) if (e + 600.0).abs() < 1e-9));
        assert!(r.unwrap().note().contains("about 1e-600"));
        let (d, r) = determinant(&(DMatrix::identity(3, 3) * 1e200));
        assert!(d.is_infinite());
        assert!(matches!(r, Some(Range::Over(_))));
        let (d, r) = determinant(&DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]));
        assert_eq!((d, r), (0.0, None));
        assert_eq!(determinant(&(DMatrix::identity(2, 2) * 3.0)), (9.0, None));
    }
}
