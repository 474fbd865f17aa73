//! Whether numbers for some symbols of a closed form (put in by `subs`, or
//! bound while other symbols stay free; LANGUAGE.md §7) land inside the
//! branch the closed form holds on. `MatrixLog6` of `RpToTrans(Rotz(c),
//! (a, 1, 2))` is its closed form for 1 − cos c > 0: at c = 0 that form,
//! with a still free, gives (0, 0, 0, 0, 0, 2), where the log of the pure
//! translation is (0, 0, 0, a, 1, 2).

use crate::sym::Symbol;
use crate::values::recipe::{Recipe, Step};
use std::collections::HashSet;
use std::rc::Rc;

/// The branch (as its note says it) of a closed form made in `r` whose
/// conditions on the symbols `at` has numbers for are not surely met: a
/// condition that reads only those symbols is at or past its bound there
/// (1 − cos c = 0 at c = 0), or an angle past ±π (at π the closed form is
/// one of the two logs the book allows). None when every such condition
/// holds, or reads free symbols too (still a branch on those, as its note
/// says).
pub(crate) fn left_at(r: &Rc<Recipe>, at: &dyn Fn(&Symbol) -> Option<f64>) -> Option<String> {
    const TOL: f64 = 1e-12;
    let pi = std::f64::consts::PI;
    let only = |e: &crate::sym::Expr| {
        let mut syms = Vec::new();
        e.symbols(&mut syms);
        !syms.is_empty() && syms.iter().all(|s| at(s).is_some())
    };
    let mut seen = HashSet::new();
    let mut todo = vec![r];
    while let Some(r) = todo.pop() {
        if !seen.insert(Rc::as_ptr(r)) {
            continue;
        }
        if let Step::Closed(on) | Step::Guard(on) = &r.step {
            let positive = on
                .positive
                .iter()
                .filter(|e| only(e))
                .any(|e| e.eval(at).is_none_or(|v| v <= TOL));
            let angle = on
                .angles
                .iter()
                .filter(|e| only(e))
                .any(|e| e.eval(at).is_none_or(|v| v.abs() > pi + TOL));
            if positive || angle {
                return Some(on.text.clone());
            }
        }
        todo.extend(r.args.iter());
    }
    None
}

/// The refusal of a closed form read with numbers for some of its symbols
/// that leave its branch ([`left_at`]) while others are free: its form
/// there is not the call's, which waits for them.
pub(crate) fn refusal(r: &Rc<Recipe>, at: &dyn Fn(&Symbol) -> Option<f64>) -> Option<String> {
    left_at(r, at).map(|branch| {
        format!(
            "cannot decide: the numbers bound leave the branch of the closed form ({branch}), \
             where it is not the call's value; bind the symbols still free too"
        )
    })
}
