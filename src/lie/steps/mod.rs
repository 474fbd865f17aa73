//! The book's algorithms of chapter 3 step by step (`explain`, LANGUAGE.md
//! §14): each function here runs the same computation as its plain
//! counterpart in [`super::so3`] or [`super::se3`] (it calls the same
//! pieces: the SO(3) logarithm's `log_parts_with`, the same coefficients) and
//! records, in the book's order, every intermediate quantity with the
//! equation, proposition or section it comes from. The last step's value is
//! the plain function's value, bit for bit (a property test checks it).
//!
//! Where chasles computes a quantity by another formula than the book's to
//! stay accurate (θ near 0 or π), the step carries a note saying which and
//! why.
//!
//! Submodules: [`log`] (§3.2.3.3, §3.3.3.2), [`exp`] (3.51, Prop. 3.16),
//! [`motion`] (inverses (3.64), Ad (Definition 3.6), screw axes §3.3.2.2,
//! wrenches (3.99)), [`orient`] (Euler angles, roll-pitch-yaw, quaternions,
//! Cayley parameters with their branches).

pub mod exp;
pub mod log;
pub mod motion;
pub mod orient;

use super::{Mat3, Mat4, Mat6, Vec3, Vec4, Vec6};

/// A quantity of one step, typed as the book reads it.
#[derive(Clone, Debug, PartialEq)]
pub enum Quantity {
    /// A number (tr R, θ, h, …).
    Scalar(f64),
    /// A 3-vector (ω̂, p, v, q, ŝ, exponential coordinates ω̂θ).
    Vector3(Vec3),
    /// A 4-vector (a unit quaternion).
    Vector4(Vec4),
    /// A 6-vector (exponential coordinates Sθ, a screw axis, a twist).
    Vector6(Vec6),
    /// A wrench (m, f) (3.97).
    Wrench(Vec6),
    /// A screw axis S (§3.3.2.2).
    Screw(Vec6),
    /// A rotation R ∈ SO(3).
    Rotation(Mat3),
    /// An element of so(3): \[ω̂\], \[ω̂\]θ.
    So3(Mat3),
    /// A 3×3 matrix that is neither (G(θ), G⁻¹(θ), \[p\]R, \[ω̂\]²).
    Matrix3(Mat3),
    /// A transform T ∈ SE(3).
    Transform(Mat4),
    /// An element of se(3): \[S\]θ.
    Se3(Mat4),
    /// The 6×6 adjoint \[Ad_T\] (Definition 3.6).
    Adjoint(Mat6),
    /// A 6×6 matrix that is not an adjoint (\[Ad_T\]ᵀ).
    Matrix6(Mat6),
    /// Which case of an algorithm applies (`"general"`, `"identity"`,
    /// `"half_turn"`, `"pure_translation"`, `"gimbal_lock"`, …).
    Case(&'static str),
}

/// One step of a book algorithm: the quantity `name` (a stable name of
/// LANGUAGE.md §14: `trace`, `theta`, `omega_hat`, `so3`, `v`, `G_inv`, `q`,
/// `s_hat`, `h`, `dof`, …) computed by the formula `text` (`latex`) of the
/// book's `reference`, with this case's `value`.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The book's equation (`"3.54"`), proposition (`"Prop. 3.16"`),
    /// definition (`"Def. 3.6"`) or section (`"3.2.3.3"`).
    pub reference: &'static str,
    /// The stable name of the quantity.
    pub name: &'static str,
    /// The formula as the book writes it, in Unicode.
    pub text: String,
    /// The same formula in LaTeX.
    pub latex: String,
    /// Which formula chasles used instead of the book's and why, when it did.
    pub note: Option<String>,
    /// This case's value.
    pub value: Quantity,
}

impl Step {
    /// A step with no note.
    pub fn new(
        reference: &'static str,
        name: &'static str,
        text: impl Into<String>,
        latex: impl Into<String>,
        value: Quantity,
    ) -> Step {
        Step {
            reference,
            name,
            text: text.into(),
            latex: latex.into(),
            note: None,
            value,
        }
    }

    /// The step with a note on how chasles computed it.
    pub fn note(mut self, note: impl Into<String>) -> Step {
        self.note = Some(note.into());
        self
    }
}

/// A number for a note, to 6 significant digits.
pub(crate) fn num(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-4..1e6).contains(&a) {
        let s = format!("{x:.6}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_string()
    } else {
        format!("{x:.3e}")
    }
}
