//! Mechanisms (chapter 2): joints, Grübler's formula, C-space topology.
//!
//! Plain Rust, no knowledge of the chasles language. The language layer
//! turns `mech < links 4; joints R R R R; planar >` (LANGUAGE.md §9) into
//! [`Mechanism::from_spec`]`(Some("planar"), Some(4), &[(1,"R"), …], None)`
//! and prints the result's [`Display`](std::fmt::Display) form; `dof(m)` is
//! [`Mechanism::dof`].
//!
//! - [`JointType`], [`Joint`]: the joints of §2.2.1 with their freedoms `f`
//!   and constraints `c` (Table 2.1); a compound joint such as RP is one
//!   joint whose `f` is the sum (Examples 2.1, 2.3).
//! - [`Space`]: planar, spatial or spherical, fixing `m` (Proposition 2.1).
//! - [`Mechanism`]: `N` links and `J` joints, Grübler's formula (2.4)
//!   `dof = m(N − 1 − J) + Σ f_i`, the formula with its numbers substituted,
//!   the C-space topology of an open chain (§2.3.1) and notes (a closed
//!   chain gives only a lower bound).
//! - [`MechError`], [`MechPart`]: what is wrong with a spec, and which
//!   written item it is about.

#![warn(missing_docs)]

mod joint;
mod mechanism;
mod report;

#[cfg(test)]
mod tests;

pub use joint::{Joint, JointType, Space};
pub use mechanism::{Legs, MAX_COUNT, MAX_LETTERS, MechError, MechPart, Mechanism};
