//! Angles that hold the user's symbols (`cos(t + 0.3)`): the part in the
//! symbols stays as it is, the constant part is read as a number's angle
//! is ([`Lift::angle`]).

use super::{Lift, rational_and_pi};
use crate::sym::expr::{Expr, Symbol, Var};

/// True for a variable of the lift's own (ν, μ, ρ, an atom).
fn own(v: &Var) -> bool {
    let named = |s: &Symbol| s.name.starts_with('⟨');
    match v {
        Var::Sym(s) | Var::Z(s) => named(s),
        Var::Pi => false,
        Var::Call(c) => {
            let mut names = Vec::new();
            c.args.iter().for_each(|e| e.symbols(&mut names));
            names.iter().all(named)
        }
    }
}

impl Lift {
    /// An angle that may hold symbols, S + C: the part S in the symbols
    /// stays as it is, the constant part C is read as [`Lift::angle`]
    /// reads a number's (a symbol of its own when it is not a + bπ).
    pub(super) fn angle_with_symbols(&mut self, x: &Expr) -> Option<Expr> {
        let mut symbols = Expr::default();
        let mut constant = Expr::default();
        for (mono, c) in &x.terms {
            let term = Expr {
                terms: std::iter::once((mono.clone(), c.clone())).collect(),
            };
            let user = mono.iter().any(|(v, _)| !matches!(v, Var::Pi) && !own(v));
            if user {
                symbols = symbols.add(&term);
            } else {
                constant = constant.add(&term);
            }
        }
        if symbols.terms.is_empty() {
            return match rational_and_pi(&constant) {
                Some(_) => self.angle(&constant),
                None => Some(self.named(format!("{constant:?}"))),
            };
        }
        let c = match rational_and_pi(&constant) {
            _ if constant.terms.is_empty() => constant,
            Some(_) => self.angle(&constant)?,
            None => self.named(format!("{constant:?}")),
        };
        Some(symbols.add(&c))
    }
}
