//! Reading a plain matrix as a group element (LANGUAGE.md §5): accepted
//! silently within 1e-9 of the group, projected (SVD, ProjectToSO3) with a
//! warning within 1e-2 (the book prints 3 digits), refused beyond, with the
//! book's DistanceToSO3/DistanceToSE3 measure in the message.

use nalgebra::DMatrix;

use super::num::Num;
use crate::check::ty::Kind;
use crate::lie::{LieGroup, Mat2, Mat3, SE2, SE3, SO2, SO3};

/// Within this distance a matrix is taken as a group element as it is.
pub const ACCEPT_TOL: f64 = 1e-9;
/// Within this distance a matrix is projected onto the group, with a warning.
pub const PROJECT_TOL: f64 = 1e-2;

/// A group a plain matrix can be read as.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// SO(3), the 3×3 rotation matrices (Definition 3.1).
    SO3,
    /// SE(3), the 4×4 homogeneous transformations (Definition 3.4, (3.62)).
    SE3,
    /// SO(2), the 2×2 rotation matrices (Definition 3.2).
    SO2,
    /// SE(2), the 3×3 planar transformations (Definition 3.5).
    SE2,
}

impl Group {
    /// The kind a matrix read as this group takes.
    pub fn kind(self) -> Kind {
        match self {
            Group::SO3 => Kind::SO3,
            Group::SE3 => Kind::SE3,
            Group::SO2 => Kind::SO2,
            Group::SE2 => Kind::SE2,
        }
    }
    /// The side of its square matrices: 3 for SO(3) and SE(2), 4 for
    /// SE(3), 2 for SO(2).
    pub fn size(self) -> usize {
        match self {
            Group::SO3 | Group::SE2 => 3,
            Group::SE3 => 4,
            Group::SO2 => 2,
        }
    }
    /// The group as the book writes it, `SO(3)`, for messages.
    pub fn name(self) -> &'static str {
        match self {
            Group::SO3 => "SO(3)",
            Group::SE3 => "SE(3)",
            Group::SO2 => "SO(2)",
            Group::SE2 => "SE(2)",
        }
    }
    /// What a member is called in an error message.
    pub fn noun(self) -> &'static str {
        match self {
            Group::SO3 | Group::SO2 => "a rotation matrix",
            Group::SE3 | Group::SE2 => "a homogeneous transformation",
        }
    }
}

/// How a matrix relates to a group.
#[derive(Debug, Clone, PartialEq)]
pub enum Membership {
    /// Within [`ACCEPT_TOL`].
    Exact(Num),
    /// Within [`PROJECT_TOL`]: the projection and the distance.
    Projected(Num, f64),
    /// Too far: the distance (and the determinant of the rotation block).
    Outside {
        /// DistanceToSO3/SE3 of the matrix (§3.6), beyond [`PROJECT_TOL`].
        distance: f64,
        /// det of the rotation block (negative for a reflection).
        det: f64,
    },
}

fn mat2(m: &Num) -> Mat2 {
    Mat2::from_column_slice(m.as_slice())
}

/// The distance of `m` from `group` (DistanceToSO3/SE3, §3.6), or None if
/// the shape is wrong or an entry is not finite.
pub fn distance(m: &Num, group: Group) -> Option<f64> {
    let n = group.size();
    if m.nrows() != n || m.ncols() != n || m.iter().any(|x| !x.is_finite()) {
        return None;
    }
    Some(match (group, m) {
        (Group::SO3, Num::M3(r)) => SO3::distance(r),
        (Group::SE3, Num::M4(t)) => SE3::distance(t),
        (Group::SO2, _) => SO2::distance(&mat2(m)),
        (Group::SE2, Num::M3(t)) => SE2::distance(t),
        _ => return None,
    })
}

/// The projection of `m` onto `group` (ProjectToSO3/SE3, §3.6); `m` has
/// the group's shape.
pub fn project(m: &Num, group: Group) -> Num {
    match (group, m) {
        (Group::SO3, Num::M3(r)) => Num::M3(std::rc::Rc::new(*SO3::project(r).matrix())),
        (Group::SE3, Num::M4(t)) => Num::M4(std::rc::Rc::new(*SE3::project(t).matrix())),
        (Group::SE2, Num::M3(t)) => Num::M3(std::rc::Rc::new(*SE2::project(t).matrix())),
        (Group::SO2, _) => Num::from_slice(2, 2, SO2::project(&mat2(m)).matrix().as_slice()),
        _ => m.clone(),
    }
}

/// Any fixed-size matrix as a dynamic one.
pub fn dm<R: nalgebra::Dim, C: nalgebra::Dim, S: nalgebra::RawStorage<f64, R, C>>(
    m: &nalgebra::Matrix<f64, R, C, S>,
) -> DMatrix<f64> {
    let (r, c) = m.shape();
    DMatrix::from_iterator(r, c, m.iter().copied())
}

/// Classifies `m` against `group` (shape must already match).
pub fn membership(m: &Num, group: Group) -> Membership {
    let dist = distance(m, group).unwrap_or(f64::INFINITY);
    if dist <= ACCEPT_TOL {
        Membership::Exact(m.clone())
    } else if dist <= PROJECT_TOL {
        Membership::Projected(project(m, group), dist)
    } else {
        let k = if matches!(group, Group::SO2 | Group::SE2) {
            2
        } else {
            3
        };
        let det = if m.nrows() >= k && m.ncols() >= k {
            m.to_dmatrix().view((0, 0), (k, k)).determinant()
        } else {
            f64::NAN
        };
        Membership::Outside {
            distance: dist,
            det,
        }
    }
}

/// How an untyped 3×3 is read where a group element is wanted (`log`,
/// `explain`, LANGUAGE.md §5): SO(3) if it is one, else SE(2) if it is one;
/// within 1e-2 of both and in neither, the nearer, with `Some((d_so3,
/// d_se2))` so that the caller says which reading was taken (the two give
/// different kinds, so(3) or se(2)); near one only, that one (projected);
/// else SO(3), whose error gives the distance.
pub fn read_3x3(m: &Num) -> (Group, Option<(f64, f64)>) {
    let d3 = distance(m, Group::SO3).unwrap_or(f64::INFINITY);
    let d2 = distance(m, Group::SE2).unwrap_or(f64::INFINITY);
    if d3 <= ACCEPT_TOL {
        return (Group::SO3, None);
    }
    if d2 <= ACCEPT_TOL {
        return (Group::SE2, None);
    }
    let both = (d3 <= PROJECT_TOL && d2 <= PROJECT_TOL).then_some((d3, d2));
    match d2 < d3 && d2 <= PROJECT_TOL {
        true => (Group::SE2, both),
        false => (Group::SO3, both),
    }
}

/// The kind a freshly written matrix gets: SO(3) if it is a rotation, else
/// SE(2) if it is a planar transform (3×3); SE(3) (4×4), SO(2) (2×2); else a
/// plain matrix (LANGUAGE.md §5).
pub fn classify(m: &Num) -> Kind {
    let is = |g: Group| distance(m, g).is_some_and(|d| d <= ACCEPT_TOL);
    match m {
        Num::M3(_) if is(Group::SO3) => Kind::SO3,
        Num::M3(_) if is(Group::SE2) => Kind::SE2,
        Num::M4(_) if is(Group::SE3) => Kind::SE3,
        Num::M3(r) if is_skew(r) => Kind::So3,
        Num::M4(t)
            if is_skew(&t.fixed_view::<3, 3>(0, 0).into_owned())
                && t.row(3).iter().all(|x| *x == 0.0)
                && t.iter().any(|x| *x != 0.0) =>
        {
            Kind::Se3
        }
        _ => match m.shape() {
            (2, 2) if is(Group::SO2) => Kind::SO2,
            (r, 1) => Kind::Vector(Some(r)),
            (r, c) => Kind::Matrix(Some(r), Some(c)),
        },
    }
}

/// A nonzero matrix equal to minus its transpose (an element of so(3)).
fn is_skew(m: &Mat3) -> bool {
    let scale = m.abs().max();
    scale > 0.0 && (m + m.transpose()).abs().max() <= 1e-12 * scale
}
