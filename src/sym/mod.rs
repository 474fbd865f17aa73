//! Symbolic scalars and matrices (LANGUAGE.md §7): mathematics, not
//! evaluation — this module imports nothing from the language layers.
//! [`expr`] holds the canonical form (trigonometric polynomials as Laurent
//! polynomials in z = e^{iθ}, exact coefficients from [`coef`]), [`matrix`]
//! the book's closed forms over it (Rodrigues, Proposition 3.16, the
//! adjoint), and `print` the book's notation, its shorthand and LaTeX.

pub mod arc;
pub mod axis;
pub mod bilinear;
pub mod branch;
pub mod coef;
pub mod collect;
pub mod dense;
pub mod diff;
pub mod eval;
pub mod expr;
pub mod exps;
pub mod factor;
pub mod fraction;
pub mod generalize;
pub mod half;
pub mod intern;
pub mod inverse;
pub mod layout;
pub mod matexp;
pub mod matrix;
pub mod modular;
pub mod perfect;
pub mod phase;
pub mod print;
pub mod probe;
pub mod rat;
pub mod rational;
mod root_quotient;
pub mod shape;
pub mod shortest;
pub mod sign;
pub mod size;
pub mod solve;
pub mod solve_angle;
pub mod squarefree;
pub mod surd;
mod tangents;
pub mod together;
pub mod trig;

pub use expr::{Expr, Symbol, Wrt};
pub use matrix::Mat;
