//! The Lie-group core: SO(3), SE(3), SO(2), SE(2), their algebras, adjoints,
//! exponentials and logarithms, and other representations of orientation.
//! Plain Rust on nalgebra; knows nothing of the chasles language.

/// A 3-vector (angular velocity, position, exponential coordinates).
pub type Vec3 = nalgebra::Vector3<f64>;
/// A 4-vector (unit quaternion `(w, x, y, z)`, homogeneous point).
pub type Vec4 = nalgebra::Vector4<f64>;
/// A 6-vector: twist `(ω, v)`, screw axis, or wrench `(m, f)`.
pub type Vec6 = nalgebra::Vector6<f64>;
/// A 2-vector.
pub type Vec2 = nalgebra::Vector2<f64>;
/// 2×2 (SO(2), so(2)).
pub type Mat2 = nalgebra::Matrix2<f64>;
/// 3×3 (SO(3), so(3), SE(2), se(2)).
pub type Mat3 = nalgebra::Matrix3<f64>;
/// 4×4 (SE(3), se(3)).
pub type Mat4 = nalgebra::Matrix4<f64>;
/// 6×6 (the adjoint representation `[Ad_T]`).
pub type Mat6 = nalgebra::Matrix6<f64>;
