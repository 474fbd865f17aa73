//! The recipe of `subs(x, name, by)` (LANGUAGE.md §7): how the value was
//! made with `by` put for `name`, replayed once the numbers are bound.

use std::collections::HashMap;
use std::rc::Rc;

use crate::values::recipe::Recipe;
use crate::values::value::Value;

/// How `subs(x, name, by)` is made: the recipe of `x` with `by` put for
/// `name` in its leaves (each leaf substituted by the canonical engine), so
/// that the numbers bound later replay the steps of `x` (§7), as
/// `replay::subs_numbers` does when `by` leaves no symbol. None when `x` keeps
/// no recipe or a leaf cannot be substituted (the result is then a leaf).
pub(in crate::seam) fn substituted(x: &Value, name: &Value, by: &Value) -> Option<Rc<Recipe>> {
    let Value::Formula { how: Some(r), .. } = x else {
        return None;
    };
    let sym = match name {
        Value::Formula { m, .. } => match m.data.as_slice() {
            [e] => crate::sym::expr::as_symbol(e)?,
            _ => return None,
        },
        _ => return None,
    };
    let failed = std::cell::Cell::new(false);
    let leaf = |v: &Value| -> Option<Value> {
        let Value::Formula { kind, m, .. } = v else {
            return None;
        };
        let mut syms = Vec::new();
        m.data.iter().for_each(|e| e.symbols(&mut syms));
        if !syms.contains(&sym) {
            return None;
        }
        let args = [v.clone(), name.clone(), by.clone()];
        match crate::builtins::eval_symbolic("subs", &args, kind) {
            Some(Ok(v)) => Some(v),
            _ => {
                failed.set(true);
                None
            }
        }
    };
    let out = crate::values::recipe::rebase(r, &leaf, &mut HashMap::new());
    (!failed.get()).then_some(out)
}
