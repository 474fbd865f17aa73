//! The symbols of the canonical form (LANGUAGE.md §7): a `given` name, a
//! function of time θ(t) and its rates θ̇, θ̈, or a component of either.

use std::sync::Arc;

/// A real symbol: a `given` name, a function of time or a rate of one, or
/// a component of either. The time variable t itself is a plain symbol.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Symbol {
    /// The name as declared, `theta`.
    pub name: Arc<str>,
    /// For a function of time (`given theta(t) : scalar`), its variable t.
    pub time: Option<Arc<str>>,
    /// How many times it is differentiated by time (θ̇ has one).
    pub dots: u8,
    /// The 1-based index of a component of a `given` vector, `w[2]`; 0
    /// otherwise.
    pub index: u8,
    /// One of ω̂₁, ω̂₂, ω̂₃ of an axis assumed to be a unit vector, where
    /// ω̂₁² + ω̂₂² + ω̂₃² = 1 holds ([`crate::sym::axis`]).
    pub unit: bool,
}

impl Symbol {
    /// A real symbol, `given t1 : scalar`.
    pub fn new(name: &str) -> Symbol {
        Symbol {
            name: name.into(),
            time: None,
            dots: 0,
            index: 0,
            unit: false,
        }
    }
    /// A function of time, θ(t), of the variable `t`.
    pub fn timed(name: &str) -> Symbol {
        Symbol::of_time(name, "t")
    }
    /// A function of the time variable `time`, θ(time).
    pub fn of_time(name: &str, time: &str) -> Symbol {
        Symbol {
            time: Some(time.into()),
            ..Symbol::new(name)
        }
    }
    /// True for a function of time (or one of its derivatives).
    pub fn is_timed(&self) -> bool {
        self.time.is_some()
    }
    /// The time derivative, θ̇.
    pub fn dot(&self) -> Symbol {
        Symbol {
            dots: self.dots.saturating_add(1),
            ..self.clone()
        }
    }
}
