//! Where chasles differs from the book's Python library (`modern_robotics`,
//! the software of §3.6 in Python): names, return shapes and tolerances.
//! chasles follows the book's text of §3.6 where the two disagree (the
//! logarithms return exponential coordinates, as §3.6 says, where the
//! Python package returns the so(3)/se(3) matrix). `:help NAME` shows the
//! difference under the function, `docs/builtins.md` lists it, and the
//! README's table is checked against this one (`tests/docs.rs`).

/// One difference: the builtin's book name and what differs, in words.
#[derive(Debug, Clone, Copy)]
pub struct Difference {
    /// The book's name of the function (as in the builtin table).
    pub name: &'static str,
    /// What the Python package does and what chasles does.
    pub text: &'static str,
}

/// Every difference from the `modern_robotics` Python package, in the
/// order of §3.6.
pub const DIFFERENCES: &[Difference] = &[
    Difference {
        name: "AxisAng3",
        text: "of the zero vector gives (0, 0) and a note: the axis is undefined at θ = 0 (§3.2.3.3 (i)); Python divides by zero (nan axis)",
    },
    Difference {
        name: "MatrixExp3",
        text: "takes the 3-vector ω̂θ, as §3.6 says, or the so(3) matrix [ω̂]θ, as Python does; Python returns exactly I when ‖ω̂θ‖ < 1e-6 (NearZero), chasles the rotation to full precision",
    },
    Difference {
        name: "MatrixLog3",
        text: "returns the 3-vector ω̂θ, as §3.6 says; Python returns the so(3) matrix [ω̂]θ (write log(R) or VecToso3(MatrixLog3(R)) for it). At θ = π both take the axis from (3.58), else (3.59), else (3.60); chasles decides θ = π by the exact form, Python by (tr R − 1)/2 ≤ −1 in floats",
    },
    Difference {
        name: "ScrewToAxis",
        text: "normalizes a direction s that is not a unit vector, with a warning; Python uses s as given",
    },
    Difference {
        name: "AxisAng6",
        text: "of the zero vector gives (0, 0) and a note (S is undefined at θ = 0); with ω ≈ 0 (NearZero) and v = 0 it takes θ = ‖ω‖; Python divides by zero (nan)",
    },
    Difference {
        name: "MatrixExp6",
        text: "takes the 6-vector Sθ, as §3.6 says, or the se(3) matrix [S]θ, as Python does; Python returns [I, v; 0, 1] when ‖ω‖ < 1e-6 (NearZero), chasles the transform to full precision",
    },
    Difference {
        name: "MatrixLog6",
        text: "returns the 6-vector Sθ, as §3.6 says; Python returns the se(3) matrix [S]θ (write log(T) or VecTose3(MatrixLog6(T)) for it)",
    },
    Difference {
        name: "Normalize",
        text: "of the zero vector is a domain error; Python returns nan entries",
    },
    Difference {
        name: "RotInv",
        text: "refuses a matrix that is not a rotation (beyond 1e-2 of SO(3); within, projected with a warning); Python transposes any matrix",
    },
    Difference {
        name: "TransInv",
        text: "refuses a matrix that is not a transform (beyond 1e-2 of SE(3)); Python inverts any 4×4 by the formula",
    },
];

/// The difference of the builtin `name` (its table name or an alias: the
/// book's `Normalize` is the table's `normalize`) from the Python
/// library, if any.
pub fn difference(name: &str) -> Option<&'static str> {
    let row = super::lookup(name).map_or(name, |b| b.name);
    DIFFERENCES
        .iter()
        .find(|d| d.name == name || super::lookup(d.name).is_some_and(|b| b.name == row))
        .map(|d| d.text)
}
