//! The errors of operations on values ([`super::ops`]): one enum whose
//! text is the message a user sees; the interpreter adds the span and the
//! kind of error (`Op::failure` in `seam::apply`). The bounds whose
//! breach is such an error are here too (re-exported by `ops`).

use crate::check::ty::Kind;

/// Largest matrix side accepted anywhere.
pub const MAX_DIM: usize = 10_000;
/// Largest number of entries of one matrix.
pub const MAX_ELEMENTS: usize = 4_000_000;
/// The most multiply-adds one operation may cost: about a second of work
/// (a 1000×1000 product). A larger product or matrix power would run for
/// minutes or hours.
pub const MAX_WORK: u128 = 1_000_000_000;

/// Why an operation on values failed; its text is the message a user
/// sees (the interpreter adds the span and the kind of error).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OpError {
    /// An operand that is not numbers (a tuple, a mechanism, a picture).
    #[error("expected numbers, found a {0}")]
    NotNumbers(Kind),
    /// `T x` with a 4×4 matrix that is neither a transform nor in se(3) (3.65).
    #[error(
        "a 4×4 matrix moves a point, T x = R x + p (3.65), only when its last row is (0, 0, 0, 1); \
         this one is not a transform (the transpose of a transform is not its inverse: use inv)"
    )]
    NotATransform,
    /// A product of matrices whose inner sizes differ (rows × columns of each).
    #[error("cannot multiply a {}×{} by a {}×{}", .0.0, .0.1, .1.0, .1.1)]
    Multiply((usize, usize), (usize, usize)),
    /// A sum of matrices of different shapes.
    #[error("cannot add a {}×{} and a {}×{}", .0.0, .0.1, .1.0, .1.1)]
    Add((usize, usize), (usize, usize)),
    /// An operation that costs more than [`MAX_WORK`] multiply-adds (the
    /// count, at most `u64::MAX`: a `u128` would make every result of an
    /// operation larger to move); `what` names it.
    #[error(
        "too much work: {work:.1e} multiply-adds ({what}; at most {:.0e})",
        MAX_WORK
    )]
    TooMuchWork {
        /// The multiply-adds it would cost.
        work: u64,
        /// The operation, as the message names it (`the inverse of a
        /// 5000×5000 matrix`).
        what: String,
    },
    /// A result of more than [`MAX_ELEMENTS`] entries (rows, columns).
    #[error(
        "a {rows}×{cols} result is too large (at most {} entries)",
        MAX_ELEMENTS
    )]
    TooLarge {
        /// Rows of the result.
        rows: usize,
        /// Columns of the result.
        cols: usize,
    },
    /// `x / d` with a `d` that is not a number.
    #[error("the divisor must be a number")]
    DivisorNotANumber,
    /// `x / 0`.
    #[error("division by zero")]
    DivisionByZero,
    /// `b ^ e` with no real value: the base and exponent as written, and
    /// the real root `-(|b|^e)` when the exponent is p/q with q and p odd.
    #[error(
        "{base} is not a real number (a negative base to a fractional power){}",
        real_root.as_ref().map(|r| format!("; its real root is -({r})")).unwrap_or_default()
    )]
    NotReal {
        /// The whole power as text, `(-8)^0.333…` (not only its base,
        /// despite the name).
        base: String,
        /// `|b|^e` as text, whose negation is the real root, when the
        /// exponent is p/q with p and q odd (q up to 9).
        real_root: Option<String>,
    },
    /// `X ^ e` with a matrix that is not square.
    #[error("powers need a square matrix")]
    PowerOfNonSquare,
    /// `X ^ e` with a whole exponent beyond 1e15.
    #[error("a matrix power's exponent must be at most 1e15 in size, got {0:e}")]
    ExponentTooLarge(f64),
    /// `X ^ e` with an exponent that is not whole.
    #[error("a matrix power needs a whole exponent, got {0}")]
    ExponentNotWhole(f64),
    /// `b ^ e` with an `e` that is not a number.
    #[error("the exponent must be a number")]
    ExponentNotANumber,
    /// `inv(0)`, `0^-1`.
    #[error("inverse of zero")]
    InverseOfZero,
    /// The inverse of a matrix with inf or NaN entries.
    #[error("the matrix has entries that are not finite (inf or NaN); it has no inverse")]
    InverseNotFinite,
    /// The inverse of a singular matrix, with its determinant when known.
    #[error(
        "the matrix is singular{}; it has no inverse",
        .0.map(|d| format!(" (determinant {})", super::number::fmt_num(d, 6))).unwrap_or_default()
    )]
    Singular(Option<f64>),
    /// A matrix whose reciprocal condition number is below the machine
    /// epsilon: singular to working precision.
    #[error(
        "the matrix is singular to working precision (reciprocal condition number {0:.1e}); it has no inverse"
    )]
    SingularToPrecision(f64),
    /// An inverse whose entries exceed the largest number.
    #[error("the inverse overflows: its entries would exceed 1.8e308")]
    InverseOverflow,
    /// The inverse of a matrix that is not square (rows, columns).
    #[error("only square matrices have inverses, not {0}×{1}")]
    InverseOfNonSquare(usize, usize),
    /// `x.name` where the value has no such part (§3.3.1: `T.R`, `T.p`).
    #[error("a {kind} has no member .{name}")]
    NoMember {
        /// The kind of the value the member was asked of.
        kind: Kind,
        /// The member's name after the dot.
        name: &'static str,
    },
    /// A 1-based index outside `1..n`.
    #[error("index {index} is out of range 1..{n} (indices start at 1, as in the book)")]
    IndexOutOfRange {
        /// The index as given (1-based).
        index: f64,
        /// How many entries the index counts among: the largest valid index.
        n: usize,
    },
    /// A 1-based index that is not a whole number (`x[1.5]`).
    #[error("index {0} is not a whole number (indices count entries from 1, as in the book)")]
    IndexNotWhole(f64),
    /// `t[i, j]` of a tuple.
    #[error("a tuple takes one index")]
    TupleIndex,
    /// `M[i]` of a matrix that is not a vector.
    #[error("a matrix takes two indices: M[i, j], M[i, :] or M[:, j]")]
    MatrixIndex,
    /// `M[i, j, k]`.
    #[error("at most two indices")]
    TooManyIndices,
    /// A row of `[ ... ]` whose blocks have different heights (the row,
    /// the first block's height, the other's).
    #[error("row {0} of the bracket joins blocks of {1} and {2} rows")]
    RowHeights(usize, usize, usize),
    /// Rows of `[ ... ]` of different widths (the first row's width, the
    /// other's, the other row).
    #[error("rows of the bracket have different widths: {0} and {1} (row {2})")]
    RowWidths(usize, usize, usize),
    /// An operation given the wrong number of operands.
    #[error("wrong number of operands")]
    Operands,
    /// An error of another path of the same operation (the exact one over
    /// symbolic scalars, or a builtin's), as its message.
    #[error("{0}")]
    Message(String),
}

impl From<String> for OpError {
    fn from(message: String) -> OpError {
        OpError::Message(message)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_are_the_ones_users_see() {
        let work = OpError::TooMuchWork {
            work: 8_000_000_000_000,
            what: "a 20000×20000 by 20000×20000 product".into(),
        };
        assert_eq!(
            work.to_string(),
            "too much work: 8.0e12 multiply-adds (a 20000×20000 by 20000×20000 product; at most 1e9)"
        );
        assert_eq!(
            OpError::TooLarge {
                rows: 3,
                cols: 5_000_000
            }
            .to_string(),
            "a 3×5000000 result is too large (at most 4000000 entries)"
        );
        assert_eq!(
            OpError::Multiply((4, 4), (3, 3)).to_string(),
            "cannot multiply a 4×4 by a 3×3"
        );
        let root = OpError::NotReal {
            base: "(-8)^(1/3)".into(),
            real_root: Some("8^(1/3)".into()),
        };
        assert_eq!(
            root.to_string(),
            "(-8)^(1/3) is not a real number (a negative base to a fractional power); its real root is -(8^(1/3))"
        );
        assert_eq!(
            OpError::Singular(Some(0.0)).to_string(),
            "the matrix is singular (determinant 0); it has no inverse"
        );
        assert_eq!(
            OpError::Singular(None).to_string(),
            "the matrix is singular; it has no inverse"
        );
        assert_eq!(
            OpError::ExponentTooLarge(1e20).to_string(),
            "a matrix power's exponent must be at most 1e15 in size, got 1e20"
        );
        assert_eq!(
            OpError::IndexOutOfRange { index: 7.0, n: 6 }.to_string(),
            "index 7 is out of range 1..6 (indices start at 1, as in the book)"
        );
        assert_eq!(
            OpError::IndexNotWhole(1.5).to_string(),
            "index 1.5 is not a whole number (indices count entries from 1, as in the book)"
        );
        assert_eq!(
            OpError::NoMember {
                kind: Kind::Vector(Some(3)),
                name: "R"
            }
            .to_string(),
            format!("a {} has no member .R", Kind::Vector(Some(3)))
        );
    }
}
