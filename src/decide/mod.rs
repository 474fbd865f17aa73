//! Deciding `a == b`, `a ≈ b` and `a < b` (LANGUAGE.md §3, §7; issue 21:
//! never a wrong answer), below the interpreter: exact forms where both
//! sides have them (`equality`); for numbers made from exact ones,
//! certified ball arithmetic at 128 to 512 bits (`certify` over
//! `ball` and `balls`) and proofs by lifting the recipe to the
//! symbolic engine (`lift`, in cyclotomic fields `cyclotomic`; by exp
//! and log, `transcendental`); over symbols, the sides compared at
//! points (`witness`), which replays how each side was made with
//! numbers (`replay`: the same replay makes a value bound later a
//! number, and a comparison replayed is decided here again, so the two
//! live in one room); inverse trigonometric sides by their principal
//! ranges (`inverse`), and the exact form of a logarithm of an exponential
//! by the principal branch (`log_exp`: log e^X = X for ‖ω‖ < π); trees of the book's transforms by the algebra of
//! their blocks (`blocks`: (T U)⁻¹ = U⁻¹ T⁻¹); the half-turn branch of a rotation's log
//! (`turn`, §3.2.3.3) and the order of scalars (`order`); `sum`, `min`
//! and `max` of items that may be exact, as the items written out
//! (`folds`), for numbers typed first and bound later alike; where a
//! value is defined as typed in one unknown (`domain`: `x/x` not at 0); the
//! rate of a builtin at numbers, for the derivative of a kept call (`rate`). Imports
//! the operation seam ([`crate::seam`]), nothing from the interpreter.

pub(crate) mod ball;
pub(crate) mod balls;
pub(crate) mod blocks;
pub(crate) mod branch_at;
pub(crate) mod certify;
pub(crate) mod constant;
pub(crate) mod cyclotomic;
pub(crate) mod domain;
pub(crate) mod equality;
pub(crate) mod folds;
pub(crate) mod inverse;
pub(crate) mod lift;
pub(crate) mod log_exp;
pub(crate) mod order;
pub(crate) mod partly;
pub(crate) mod powers;
pub(crate) mod rate;
pub(crate) mod replay;
pub(crate) mod transcendental;
pub(crate) mod turn;
pub(crate) mod witness;
