//! The numbers inside a value: a scalar, the book's small vectors and
//! matrices held inline in fixed-size nalgebra types (a twist or screw
//! axis is a 6-vector (§3.3.2), a rotation 3×3 (§3.2.1), a transform 4×4
//! (§3.3.1), an adjoint 6×6 (Definition 3.6)), and a general `DMatrix`
//! only for other shapes. Every shape that has a fixed-size variant is
//! stored in it ([`Num::from_slice`] picks it), so the arithmetic of
//! [`super::ops`] and the builtins read a transform as a `Mat4` without
//! copying, and most values never touch the heap.
//!
//! `Num` answers the few matrix questions the rest of the code asks
//! (`nrows`, `ncols`, `shape`, `len`, entries by index, iteration in
//! column-major order) and converts to a `DMatrix` for the general path.

use std::borrow::Cow;
use std::rc::Rc;

use nalgebra::DMatrix;

use crate::lie::{Mat3, Mat4, Mat6, Vec3, Vec4, Vec6};

/// The numbers of a value: a scalar, a 3-, 4- or 6-vector, a 3×3, 4×4 or
/// 6×6 matrix, or a general matrix of any other shape (column-major, as
/// nalgebra stores every variant).
#[derive(Debug, Clone)]
pub enum Num {
    /// A number (a 1×1 matrix).
    Scalar(f64),
    /// A 3-vector: ω, v, p, exponential coordinates ω̂θ (§3.2.3).
    V3(Vec3),
    /// A 4-vector (a unit quaternion, a homogeneous point).
    V4(Vec4),
    /// A 6-vector: a twist V = (ω, v), screw axis S or wrench F (§3.3–3.4).
    V6(Vec6),
    /// A 3×3 matrix: R ∈ SO(3), \[ω\] ∈ so(3), SE(2). Shared, as the 4×4.
    M3(Rc<Mat3>),
    /// A 4×4 matrix: T ∈ SE(3) (3.62), \[V\] ∈ se(3) (3.71). Behind a
    /// reference count so that a value is 104 bytes to move, not 184 (a
    /// value moves ~20 times a statement), and a copy — a name read, a
    /// binding, an operand kept by an exact form's recipe — shares the
    /// numbers instead of allocating and copying them (changed in place
    /// only through [`Num::as_mut_slice`], which copies a shared matrix
    /// first).
    M4(Rc<Mat4>),
    /// A 6×6 matrix: \[Ad_T\] (Definition 3.6), \[ad_V\] (3.82). Shared, as
    /// the 4×4.
    M6(Rc<Mat6>),
    /// Any other shape (including 2×2, 2-vectors, rows and empty matrices).
    Dyn(DMatrix<f64>),
}

/// True when every entry of `xs` is finite (no NaN, no ±inf): 0·x is ±0
/// for a finite x and NaN otherwise, and the sum is kept in four lanes so
/// that the loop vectorizes (a single running sum cannot: floating-point
/// addition is not reassociated). Read by every statement (a result's
/// non-finite warning, a group operation's refusal), so it is worth the
/// lanes.
#[inline]
pub fn all_finite(xs: &[f64]) -> bool {
    let mut lanes = [0.0f64; 4];
    let mut chunks = xs.chunks_exact(4);
    for c in &mut chunks {
        for (l, x) in lanes.iter_mut().zip(c) {
            *l += x * 0.0;
        }
    }
    let tail: f64 = chunks.remainder().iter().map(|x| x * 0.0).sum();
    (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]) + tail == 0.0
}

/// [`all_finite`] of `xs` read as `N` entries, so that the loop is
/// unrolled for the size the variant fixes (a 4×4's 16 entries in four
/// steps, no remainder).
#[inline(always)]
fn all_finite_of<const N: usize>(xs: &[f64]) -> bool {
    match <&[f64; N]>::try_from(xs) {
        Ok(a) => all_finite(a),
        Err(_) => all_finite(xs),
    }
}

impl Num {
    /// True when every entry is finite ([`all_finite`]), the sizes of the
    /// fixed variants known: a statement's result, a group operation's
    /// operands and `exp`'s input are scanned by it.
    #[inline]
    pub fn all_finite(&self) -> bool {
        match self {
            Num::Scalar(x) => x.is_finite(),
            Num::V3(v) => all_finite_of::<3>(v.as_slice()),
            Num::V4(v) => all_finite_of::<4>(v.as_slice()),
            Num::V6(v) => all_finite_of::<6>(v.as_slice()),
            Num::M3(m) => all_finite_of::<9>(m.as_slice()),
            Num::M4(m) => all_finite_of::<16>(m.as_slice()),
            Num::M6(m) => all_finite_of::<36>(m.as_slice()),
            Num::Dyn(m) => all_finite(m.as_slice()),
        }
    }

    /// The numbers of an r×c matrix with entries `xs` in column-major
    /// order, in the fixed-size variant where the shape has one.
    pub fn from_slice(r: usize, c: usize, xs: &[f64]) -> Num {
        debug_assert_eq!(xs.len(), r * c);
        match (r, c) {
            (1, 1) => Num::Scalar(xs[0]),
            (3, 1) => Num::V3(Vec3::from_column_slice(xs)),
            (4, 1) => Num::V4(Vec4::from_column_slice(xs)),
            (6, 1) => Num::V6(Vec6::from_column_slice(xs)),
            (3, 3) => Num::M3(Rc::new(Mat3::from_column_slice(xs))),
            (4, 4) => Num::M4(Rc::new(Mat4::from_column_slice(xs))),
            (6, 6) => Num::M6(Rc::new(Mat6::from_column_slice(xs))),
            _ => Num::Dyn(DMatrix::from_column_slice(r, c, xs)),
        }
    }

    /// A general matrix, moved into the fixed-size variant where its shape
    /// has one (no copy otherwise).
    pub fn from_dmatrix(m: DMatrix<f64>) -> Num {
        match m.shape() {
            (1, 1) | (3, 1) | (4, 1) | (6, 1) | (3, 3) | (4, 4) | (6, 6) => {
                Num::from_slice(m.nrows(), m.ncols(), m.as_slice())
            }
            _ => Num::Dyn(m),
        }
    }

    /// A column vector.
    pub fn vector(xs: &[f64]) -> Num {
        Num::from_slice(xs.len(), 1, xs)
    }

    /// The r×c zero matrix.
    pub fn zeros(r: usize, c: usize) -> Num {
        Num::from_dmatrix(DMatrix::zeros(r, c))
    }

    /// The n×n identity.
    pub fn identity(n: usize) -> Num {
        Num::from_dmatrix(DMatrix::identity(n, n))
    }

    /// Rows and columns.
    #[inline]
    pub fn shape(&self) -> (usize, usize) {
        match self {
            Num::Scalar(_) => (1, 1),
            Num::V3(_) => (3, 1),
            Num::V4(_) => (4, 1),
            Num::V6(_) => (6, 1),
            Num::M3(_) => (3, 3),
            Num::M4(_) => (4, 4),
            Num::M6(_) => (6, 6),
            Num::Dyn(m) => m.shape(),
        }
    }
    /// Number of rows.
    #[inline]
    pub fn nrows(&self) -> usize {
        self.shape().0
    }
    /// Number of columns.
    #[inline]
    pub fn ncols(&self) -> usize {
        self.shape().1
    }
    /// Number of entries.
    #[inline]
    pub fn len(&self) -> usize {
        self.as_slice().len()
    }
    /// True for a matrix with no entries (`zeros(0, 3)`).
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// True when rows and columns are as many.
    #[inline]
    pub fn is_square(&self) -> bool {
        let (r, c) = self.shape();
        r == c
    }

    /// The entries in column-major order.
    #[inline]
    pub fn as_slice(&self) -> &[f64] {
        match self {
            Num::Scalar(x) => std::slice::from_ref(x),
            Num::V3(v) => v.as_slice(),
            Num::V4(v) => v.as_slice(),
            Num::V6(v) => v.as_slice(),
            Num::M3(m) => m.as_slice(),
            Num::M4(m) => m.as_slice(),
            Num::M6(m) => m.as_slice(),
            Num::Dyn(m) => m.as_slice(),
        }
    }
    /// The entries in column-major order, to change in place.
    #[inline]
    pub fn as_mut_slice(&mut self) -> &mut [f64] {
        match self {
            Num::Scalar(x) => std::slice::from_mut(x),
            Num::V3(v) => v.as_mut_slice(),
            Num::V4(v) => v.as_mut_slice(),
            Num::V6(v) => v.as_mut_slice(),
            // (a matrix shared with a copy is copied first: copy on write)
            Num::M3(m) => Rc::make_mut(m).as_mut_slice(),
            Num::M4(m) => Rc::make_mut(m).as_mut_slice(),
            Num::M6(m) => Rc::make_mut(m).as_mut_slice(),
            Num::Dyn(m) => m.as_mut_slice(),
        }
    }

    /// The entries in column-major order.
    #[inline]
    pub fn iter(&self) -> std::slice::Iter<'_, f64> {
        self.as_slice().iter()
    }

    /// The entries of row `r`, left to right.
    pub fn row(&self, r: usize) -> impl Iterator<Item = f64> + '_ {
        let (n, c) = self.shape();
        let xs = self.as_slice();
        (0..c).map(move |j| xs[j * n + r])
    }

    /// The same numbers as a general matrix (borrowed when they are one).
    pub fn to_dmatrix(&self) -> Cow<'_, DMatrix<f64>> {
        match self {
            Num::Dyn(m) => Cow::Borrowed(m),
            _ => {
                let (r, c) = self.shape();
                Cow::Owned(DMatrix::from_column_slice(r, c, self.as_slice()))
            }
        }
    }
    /// [`Num::to_dmatrix`], owned.
    pub fn into_dmatrix(self) -> DMatrix<f64> {
        match self {
            Num::Dyn(m) => m,
            other => other.to_dmatrix().into_owned(),
        }
    }

    /// Each entry mapped by `f` (same shape).
    pub fn map(&self, f: impl Fn(f64) -> f64) -> Num {
        let mut out = self.clone();
        for x in out.as_mut_slice() {
            *x = f(*x);
        }
        out
    }

    /// The transpose.
    pub fn transpose(&self) -> Num {
        match self {
            Num::Scalar(x) => Num::Scalar(*x),
            Num::M3(m) => Num::M3(Rc::new(m.transpose())),
            Num::M4(m) => Num::M4(Rc::new(m.transpose())),
            Num::M6(m) => Num::M6(Rc::new(m.transpose())),
            other => Num::from_dmatrix(other.to_dmatrix().transpose()),
        }
    }

    /// True for a square matrix within `eps` of the identity, entrywise.
    pub fn is_identity(&self, eps: f64) -> bool {
        let (r, c) = self.shape();
        r == c
            && self.iter().enumerate().all(|(k, x)| {
                let want = if k % r == k / r { 1.0 } else { 0.0 };
                (x - want).abs() <= eps
            })
    }

    /// The 3-vector, if it is one.
    pub fn as_v3(&self) -> Option<&Vec3> {
        match self {
            Num::V3(v) => Some(v),
            _ => None,
        }
    }
    /// The 6-vector, if it is one.
    pub fn as_v6(&self) -> Option<&Vec6> {
        match self {
            Num::V6(v) => Some(v),
            _ => None,
        }
    }
    /// The 3×3 matrix, if it is one.
    pub fn as_m3(&self) -> Option<&Mat3> {
        match self {
            Num::M3(m) => Some(m),
            _ => None,
        }
    }
    /// The 4×4 matrix, if it is one.
    pub fn as_m4(&self) -> Option<&Mat4> {
        match self {
            Num::M4(m) => Some(m),
            _ => None,
        }
    }
    /// The 6×6 matrix, if it is one.
    pub fn as_m6(&self) -> Option<&Mat6> {
        match self {
            Num::M6(m) => Some(m),
            _ => None,
        }
    }
}

impl PartialEq for Num {
    /// Same shape and the same entries (exactly).
    fn eq(&self, other: &Num) -> bool {
        self.shape() == other.shape() && self.as_slice() == other.as_slice()
    }
}

impl std::ops::Index<usize> for Num {
    type Output = f64;
    /// The `i`-th entry in column-major order (0-based).
    #[inline]
    fn index(&self, i: usize) -> &f64 {
        &self.as_slice()[i]
    }
}

impl std::ops::Index<(usize, usize)> for Num {
    type Output = f64;
    /// The entry in row `r`, column `c` (0-based).
    #[inline]
    fn index(&self, (r, c): (usize, usize)) -> &f64 {
        let (n, m) = self.shape();
        assert!(r < n && c < m, "index ({r}, {c}) out of a {n}×{m} matrix");
        &self.as_slice()[c * n + r]
    }
}

impl From<f64> for Num {
    fn from(x: f64) -> Num {
        Num::Scalar(x)
    }
}
impl From<Vec3> for Num {
    fn from(v: Vec3) -> Num {
        Num::V3(v)
    }
}
impl From<Vec4> for Num {
    fn from(v: Vec4) -> Num {
        Num::V4(v)
    }
}
impl From<Vec6> for Num {
    fn from(v: Vec6) -> Num {
        Num::V6(v)
    }
}
impl From<Mat3> for Num {
    fn from(m: Mat3) -> Num {
        Num::M3(Rc::new(m))
    }
}
impl From<Mat4> for Num {
    fn from(m: Mat4) -> Num {
        Num::M4(Rc::new(m))
    }
}
impl From<Mat6> for Num {
    fn from(m: Mat6) -> Num {
        Num::M6(Rc::new(m))
    }
}
impl From<DMatrix<f64>> for Num {
    fn from(m: DMatrix<f64>) -> Num {
        Num::from_dmatrix(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_pick_the_inline_variant() {
        assert!(matches!(Num::vector(&[1.0, 2.0, 3.0]), Num::V3(_)));
        assert!(matches!(Num::identity(4), Num::M4(_)));
        assert!(matches!(Num::identity(6), Num::M6(_)));
        assert!(matches!(Num::identity(2), Num::Dyn(_)));
        assert!(matches!(Num::zeros(1, 1), Num::Scalar(_)));
        assert!(matches!(Num::zeros(1, 3), Num::Dyn(_)));
    }

    #[test]
    fn all_finite_sees_every_entry() {
        for n in 0..20 {
            let xs: Vec<f64> = (0..n).map(|i| i as f64 - 3.5).collect();
            assert!(all_finite(&xs));
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                for at in 0..n {
                    let mut ys = xs.clone();
                    ys[at] = bad;
                    assert!(!all_finite(&ys), "{bad} at {at} of {n}");
                }
            }
        }
        // (huge finite entries stay finite: 0·x is 0, not an overflow)
        assert!(all_finite(&[f64::MAX, -f64::MAX, f64::MIN_POSITIVE, -0.0]));
        // (and each fixed size of `Num` reads every entry)
        for (r, c) in [
            (1, 1),
            (3, 1),
            (4, 1),
            (6, 1),
            (3, 3),
            (4, 4),
            (6, 6),
            (2, 5),
        ] {
            let n = r * c;
            let xs: Vec<f64> = (0..n).map(|i| i as f64 * 1e300).collect();
            assert!(Num::from_slice(r, c, &xs).all_finite(), "{r}×{c}");
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                for at in 0..n {
                    let mut ys = xs.clone();
                    ys[at] = bad;
                    assert!(
                        !Num::from_slice(r, c, &ys).all_finite(),
                        "{bad} at {at} of {r}×{c}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_value_is_small_to_move() {
        // The matrices are shared: the largest inline numbers are a 6-vector.
        assert_eq!(std::mem::size_of::<Num>(), 56);
        assert_eq!(std::mem::size_of::<crate::values::value::Value>(), 104);
    }

    #[test]
    fn a_copy_shares_a_matrix_until_it_is_changed() {
        let a = Num::identity(4);
        let mut b = a.clone();
        assert_eq!(a.as_slice().as_ptr(), b.as_slice().as_ptr());
        b.as_mut_slice()[1] = 2.0;
        // (copy on write: the original keeps its numbers)
        assert_eq!(a[(1, 0)], 0.0);
        assert_eq!(b[(1, 0)], 2.0);
        assert_ne!(a.as_slice().as_ptr(), b.as_slice().as_ptr());
    }

    #[test]
    fn indexing_is_column_major_like_nalgebra() {
        let d = DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        let n = Num::from_dmatrix(d.clone());
        assert_eq!(n[(0, 2)], 3.0);
        assert_eq!(n[(2, 0)], 7.0);
        assert_eq!(n[1], 4.0);
        assert_eq!(n.row(1).collect::<Vec<_>>(), vec![4.0, 5.0, 6.0]);
        assert_eq!(*n.to_dmatrix(), d);
        assert_eq!(n.transpose()[(0, 2)], 7.0);
        assert_eq!(Num::from_dmatrix(d.clone()), Num::Dyn(d));
    }
}
