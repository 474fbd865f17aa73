//! Group elements as types, in the manner of Sophus: [`SO3`], [`SE3`],
//! [`SO2`], [`SE2`], each a matrix known to be in its group, with the
//! operations of the [`LieGroup`] trait — membership with a tolerance,
//! projection, composition, inverse, exponential, logarithm and adjoint.
//! They are thin wrappers over the free functions of [`so3`], [`se3`],
//! [`so2`], [`se2`] and [`project`] (same numbers, same accuracy), so that
//! callers dispatch once on the group instead of re-deriving blocks.

use super::{Mat2, Mat3, Mat4, Mat6, Vec3, Vec6, project, se2, se3, so2, so3};

/// A matrix Lie group of the book (§3.2–3.3): its elements as matrices,
/// its tangent space (exponential coordinates), and its adjoint.
pub trait LieGroup: Sized + Copy {
    /// The matrix of an element: 3×3 for SO(3) and SE(2), 4×4 for SE(3),
    /// 2×2 for SO(2).
    type Matrix: Copy + std::ops::Mul<Output = Self::Matrix>;
    /// Exponential coordinates: ω̂θ ∈ ℝ³ for SO(3) (§3.2.3), Sθ ∈ ℝ⁶ for
    /// SE(3) (§3.3.3), θ for SO(2), (ω, v_x, v_y)θ for SE(2).
    type Tangent;
    /// The matrix of the adjoint representation Ad_g (Definition 3.6).
    type Adjoint;

    /// The group's name as the book writes it, `SO(3)`.
    const NAME: &'static str;

    /// The identity element.
    fn identity() -> Self;
    /// The distance of a matrix from the group (DistanceToSO3/SE3, §3.6);
    /// infinite when an entry is not finite.
    fn distance(m: &Self::Matrix) -> f64;
    /// The nearest element (ProjectToSO3/SE3, §3.6).
    fn project(m: &Self::Matrix) -> Self;
    /// The element `m` is, when it is within `tol` of the group
    /// ([`Self::distance`]); taken as it is, not projected.
    fn from_matrix(m: &Self::Matrix, tol: f64) -> Option<Self> {
        (Self::distance(m) <= tol).then(|| Self::assume(*m))
    }
    /// An element known to be in the group (a value whose kind says so,
    /// already read within tolerance); not checked again.
    fn assume(m: Self::Matrix) -> Self;
    /// The element's matrix.
    fn matrix(&self) -> &Self::Matrix;
    /// The product g₁g₂ (T_ac = T_ab T_bc, (3.63); R_ac = R_ab R_bc).
    fn compose(&self, other: &Self) -> Self {
        Self::assume(*self.matrix() * *other.matrix())
    }
    /// The inverse in closed form: Rᵀ (Prop. 3.3), (3.64) for transforms.
    fn inverse(&self) -> Self;
    /// The exponential of exponential coordinates: Rodrigues (3.51),
    /// Proposition 3.16 / (3.88) for SE(3).
    fn exp(v: &Self::Tangent) -> Self;
    /// The logarithm: §3.2.3.3 for SO(3), §3.3.3.2 for SE(3).
    fn log(&self) -> Self::Tangent;
    /// The adjoint Ad_g: R itself for SO(3), \[Ad_T\] (3.83) for SE(3).
    fn adjoint(&self) -> Self::Adjoint;
}

/// Finite entries only: NaN or inf is infinitely far from every group.
fn finite<'a>(xs: impl IntoIterator<Item = &'a f64>) -> bool {
    xs.into_iter().all(|x| x.is_finite())
}

/// A rotation matrix R ∈ SO(3): RᵀR = I, det R = 1 (§3.2.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SO3(Mat3);

/// A homogeneous transformation T = (R, p) ∈ SE(3) (3.62).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SE3(Mat4);

/// A planar rotation ∈ SO(2) (Definition 3.2 with n = 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SO2(Mat2);

/// A planar transformation ∈ SE(2) (Definition 3.5 with n = 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SE2(Mat3);

impl LieGroup for SO3 {
    type Matrix = Mat3;
    type Tangent = Vec3;
    type Adjoint = Mat3;
    const NAME: &'static str = "SO(3)";

    fn identity() -> SO3 {
        SO3(Mat3::identity())
    }
    fn distance(m: &Mat3) -> f64 {
        if finite(m.iter()) {
            project::distance_to_so3(m)
        } else {
            f64::INFINITY
        }
    }
    fn project(m: &Mat3) -> SO3 {
        SO3(project::project_to_so3(m))
    }
    fn assume(m: Mat3) -> SO3 {
        SO3(m)
    }
    fn matrix(&self) -> &Mat3 {
        &self.0
    }
    fn inverse(&self) -> SO3 {
        SO3(so3::inv(&self.0))
    }
    fn exp(v: &Vec3) -> SO3 {
        SO3(so3::exp(v))
    }
    fn log(&self) -> Vec3 {
        so3::log(&self.0)
    }
    fn adjoint(&self) -> Mat3 {
        self.0
    }
}

impl LieGroup for SE3 {
    type Matrix = Mat4;
    type Tangent = Vec6;
    type Adjoint = Mat6;
    const NAME: &'static str = "SE(3)";

    fn identity() -> SE3 {
        SE3(Mat4::identity())
    }
    fn distance(m: &Mat4) -> f64 {
        if finite(m.iter()) {
            project::distance_to_se3(m)
        } else {
            f64::INFINITY
        }
    }
    fn project(m: &Mat4) -> SE3 {
        SE3(project::project_to_se3(m))
    }
    fn assume(m: Mat4) -> SE3 {
        SE3(m)
    }
    fn matrix(&self) -> &Mat4 {
        &self.0
    }
    fn inverse(&self) -> SE3 {
        SE3(se3::inv(&self.0))
    }
    fn exp(v: &Vec6) -> SE3 {
        SE3(se3::exp(v))
    }
    fn log(&self) -> Vec6 {
        se3::log(&self.0)
    }
    fn adjoint(&self) -> Mat6 {
        se3::adjoint(&self.0)
    }
}

impl SO3 {
    /// `Rot(ω̂, θ)`: the rotation by θ about the axis ω̂ (normalised), by
    /// Rodrigues' formula (3.51).
    pub fn about(axis: &Vec3, theta: f64) -> SO3 {
        SO3(so3::rot(axis, theta))
    }
    /// `Rotx(θ)`: the rotation by θ about x̂ (§3.2.1).
    pub fn rot_x(theta: f64) -> SO3 {
        SO3(so3::rotx(theta))
    }
    /// `Roty(θ)`: the rotation by θ about ŷ (§3.2.1).
    pub fn rot_y(theta: f64) -> SO3 {
        SO3(so3::roty(theta))
    }
    /// `Rotz(θ)`: the rotation by θ about ẑ (§3.2.1).
    pub fn rot_z(theta: f64) -> SO3 {
        SO3(so3::rotz(theta))
    }
    /// Whether the rotation angle is π, where the logarithm's axis is one
    /// of two (§3.2.3.3, case (ii)).
    pub fn is_half_turn(&self) -> bool {
        so3::is_half_turn(&self.0)
    }
    /// The spatial and body angular velocities (ω_s, ω_b) of R moving
    /// at Ṙ: \[ω_s\] = Ṙ Rᵀ (3.37), \[ω_b\] = Rᵀ Ṙ (3.38).
    pub fn angular_velocities(&self, rdot: &Mat3) -> (Vec3, Vec3) {
        so3::angular_velocities(&self.0, rdot)
    }
}

impl SE3 {
    /// `RpToTrans(R, p)`: T = [R, p; 0, 1] (3.62).
    pub fn from_parts(r: &SO3, p: &Vec3) -> SE3 {
        SE3(se3::from_rp(&r.0, p))
    }
    /// `Trans(p)`: the pure translation [I, p; 0, 1] (§3.3.1).
    pub fn translate(p: &Vec3) -> SE3 {
        SE3(se3::trans(p))
    }
    /// `TransToRp(T)`: the rotation R and position p of T = (R, p).
    pub fn parts(&self) -> (SO3, Vec3) {
        let (r, p) = se3::to_rp(&self.0);
        (SO3(r), p)
    }
    /// The spatial and body twists (V_s, V_b) of T moving at Ṫ:
    /// \[V_s\] = Ṫ T⁻¹, \[V_b\] = T⁻¹ Ṫ (Proposition 3.15, §3.3.2).
    pub fn twists(&self, tdot: &Mat4) -> (Vec6, Vec6) {
        se3::twists_from_derivative(&self.0, tdot)
    }
    /// The rotation R of T = (R, p).
    pub fn rotation(&self) -> SO3 {
        SO3(self.0.fixed_view::<3, 3>(0, 0).into_owned())
    }
    /// The translation p of T = (R, p).
    pub fn translation(&self) -> Vec3 {
        self.0.fixed_view::<3, 1>(0, 3).into_owned()
    }
    /// The point `x` moved by T: R x + p (3.65).
    pub fn act(&self, x: &Vec3) -> Vec3 {
        self.0.fixed_view::<3, 3>(0, 0) * x + self.0.fixed_view::<3, 1>(0, 3)
    }
}

impl LieGroup for SO2 {
    type Matrix = Mat2;
    type Tangent = f64;
    type Adjoint = f64;
    const NAME: &'static str = "SO(2)";

    fn identity() -> SO2 {
        SO2(Mat2::identity())
    }
    fn distance(m: &Mat2) -> f64 {
        if finite(m.iter()) {
            project::distance_to_so2(m)
        } else {
            f64::INFINITY
        }
    }
    fn project(m: &Mat2) -> SO2 {
        SO2(project::project_to_so2(m))
    }
    fn assume(m: Mat2) -> SO2 {
        SO2(m)
    }
    fn matrix(&self) -> &Mat2 {
        &self.0
    }
    fn inverse(&self) -> SO2 {
        SO2(self.0.transpose())
    }
    fn exp(theta: &f64) -> SO2 {
        SO2(so2::exp(*theta))
    }
    fn log(&self) -> f64 {
        so2::log(&self.0)
    }
    /// SO(2) is commutative: its adjoint is 1.
    fn adjoint(&self) -> f64 {
        1.0
    }
}

impl SE2 {
    /// The planar transform of angle θ and position (x, y) (3.16).
    pub fn from_angle(theta: f64, x: f64, y: f64) -> SE2 {
        SE2(se2::from_theta_xy(theta, x, y))
    }
}

impl LieGroup for SE2 {
    type Matrix = Mat3;
    type Tangent = Vec3;
    type Adjoint = Mat3;
    const NAME: &'static str = "SE(2)";

    fn identity() -> SE2 {
        SE2(Mat3::identity())
    }
    fn distance(m: &Mat3) -> f64 {
        if finite(m.iter()) {
            project::distance_to_se2(m)
        } else {
            f64::INFINITY
        }
    }
    fn project(m: &Mat3) -> SE2 {
        SE2(project::project_to_se2(m))
    }
    fn assume(m: Mat3) -> SE2 {
        SE2(m)
    }
    fn matrix(&self) -> &Mat3 {
        &self.0
    }
    fn inverse(&self) -> SE2 {
        SE2(se2::inv(&self.0))
    }
    fn exp(v: &Vec3) -> SE2 {
        SE2(se2::exp(v))
    }
    fn log(&self) -> Vec3 {
        se2::log(&self.0)
    }
    fn adjoint(&self) -> Mat3 {
        se2::adjoint(&self.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close<const R: usize, const C: usize>(
        a: &nalgebra::SMatrix<f64, R, C>,
        b: &nalgebra::SMatrix<f64, R, C>,
    ) -> bool {
        (a - b).amax() < 1e-12
    }

    #[test]
    fn se3_group_laws() {
        let t = SE3::exp(&Vec6::new(0.0, 0.0, 1.0, 0.0, 2.0, 0.0).scale(0.3));
        let u = SE3::exp(&Vec6::new(0.6, 0.0, 0.8, 1.0, -2.0, 0.5));
        assert!(close(
            t.compose(&t.inverse()).matrix(),
            SE3::identity().matrix()
        ));
        // Ad_{TU} = Ad_T Ad_U (the adjoint is a representation).
        assert!(close(
            &t.compose(&u).adjoint(),
            &(t.adjoint() * u.adjoint())
        ));
        assert!(close(&SE3::exp(&t.log()).0, &t.0));
        // Example 3.2's p moved by a translation-only transform.
        let shift = SE3(se3::trans(&Vec3::new(1.0, 2.0, 3.0)));
        assert_eq!(
            shift.act(&Vec3::new(1.0, 0.0, 0.0)),
            Vec3::new(2.0, 2.0, 3.0)
        );
        assert_eq!(t.rotation().compose(&t.rotation().inverse()).0, {
            let r = t.rotation().0;
            r * r.transpose()
        });
        assert_eq!(t.translation(), t.0.fixed_view::<3, 1>(0, 3).into_owned());
    }

    #[test]
    fn so3_membership_and_projection() {
        let r = SO3::exp(&Vec3::new(0.1, -0.2, 0.3));
        assert!(SO3::from_matrix(r.matrix(), 1e-9).is_some());
        let off = r.matrix() * 1.001;
        assert!(SO3::from_matrix(&off, 1e-9).is_none());
        let p = SO3::project(&off);
        assert!(SO3::distance(p.matrix()) < 1e-12);
        assert!(close(p.matrix(), r.matrix()));
        assert_eq!(SO3::distance(&(Mat3::identity() * f64::NAN)), f64::INFINITY);
        assert_eq!(r.adjoint(), *r.matrix());
        assert!(close(&SO3::exp(&r.log()).0, &r.0));
    }

    #[test]
    fn constructors_of_the_builtins() {
        // RpToTrans(Rotz(π/2), (1, 2, 3)) and back (§3.3.1).
        let r = SO3::rot_z(std::f64::consts::FRAC_PI_2);
        let t = SE3::from_parts(&r, &Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(t.parts(), (r, Vec3::new(1.0, 2.0, 3.0)));
        assert_eq!(t.act(&Vec3::new(1.0, 0.0, 0.0)), Vec3::new(1.0, 3.0, 3.0));
        assert!(close(
            SO3::about(&Vec3::new(0.0, 0.0, 2.0), 0.7).matrix(),
            SO3::rot_z(0.7).matrix()
        ));
        assert_eq!(
            SE3::translate(&Vec3::new(1.0, 2.0, 3.0)).translation(),
            Vec3::new(1.0, 2.0, 3.0)
        );
        assert!(SO3::rot_x(std::f64::consts::PI).is_half_turn());
        assert!(!SO3::rot_y(1.0).is_half_turn());
        // A frame turning about ẑ at 1 rad/s: ω_s = ω_b = ẑ (3.37, 3.38).
        let rdot = so3::hat(&Vec3::z()) * r.matrix();
        let (ws, wb) = r.angular_velocities(&rdot);
        assert!(close(&ws, &Vec3::z()) && close(&wb, &Vec3::z()));
        let g = SE2::from_angle(std::f64::consts::FRAC_PI_2, 2.0, 1.0);
        assert!(close(
            g.matrix(),
            &Mat3::new(0.0, -1.0, 2.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0)
        ));
    }

    #[test]
    fn planar_groups() {
        let r = SO2::exp(&0.4);
        assert!((r.compose(&r).log() - 0.8).abs() < 1e-15);
        assert!(close(
            r.compose(&r.inverse()).matrix(),
            SO2::identity().matrix()
        ));
        let t = SE2::exp(&Vec3::new(0.5, 1.0, -2.0));
        assert!(close(
            t.compose(&t.inverse()).matrix(),
            SE2::identity().matrix()
        ));
        assert!(close(&SE2::exp(&t.log()).0, &t.0));
        assert!(SE2::from_matrix(t.matrix(), 1e-9).is_some());
        assert_eq!(SO2::NAME, "SO(2)");
    }
}
