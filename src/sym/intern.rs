//! Shared calls: a call kept in an expression (`sin` of a non-linear
//! argument, `sqrt`, `1/(a + b)`, …) is made once per thread and shared,
//! so that the monomials holding it — compared in every sum and product
//! of canonical forms ([`super::expr`]) — compare it by pointer instead of
//! walking its arguments, which may be sums of hundreds of terms (the
//! argument of `sin((sin a + cos b)^14)`). Sharing changes no value and no
//! order: two calls still compare by their arguments when they are not
//! the same allocation, and equal calls are one allocation (made on one
//! thread) or compare equal by their arguments.

use std::cell::RefCell;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Weak};

use super::expr::{Call, Var};

/// The calls alive on this thread, by the hash of their function and
/// arguments.
#[derive(Default)]
struct Table {
    calls: HashMap<u64, Vec<Weak<Call>>>,
    /// How many entries to allow before the dead ones are swept.
    sweep_at: usize,
    entries: usize,
}

thread_local! {
    static TABLE: RefCell<Table> = RefCell::new(Table::default());
}

fn hash_of(c: &Call) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    c.hash(&mut h);
    h.finish()
}

/// The shared call equal to `c`: one made before on this thread and still
/// alive, or `c` itself, shared from now on.
pub fn call(c: Call) -> Arc<Call> {
    let key = hash_of(&c);
    TABLE.with(|t| {
        let Ok(mut t) = t.try_borrow_mut() else {
            // (a call made while the table is in use: unshared is right too)
            return Arc::new(c);
        };
        if let Some(found) = t.calls.get(&key).and_then(|bucket| {
            bucket
                .iter()
                .filter_map(Weak::upgrade)
                .find(|old| old.cmp_args(&c) == Ordering::Equal)
        }) {
            return found;
        }
        let new = Arc::new(c);
        t.calls.entry(key).or_default().push(Arc::downgrade(&new));
        t.entries += 1;
        if t.entries > t.sweep_at {
            // drop the calls no expression holds any more; sweep again
            // when the live ones have doubled
            t.calls.retain(|_, bucket| {
                bucket.retain(|w| w.strong_count() > 0);
                !bucket.is_empty()
            });
            t.entries = t.calls.values().map(Vec::len).sum();
            t.sweep_at = (2 * t.entries).max(1024);
        }
        new
    })
}

impl Call {
    /// The order of calls: by function, then arguments (derived).
    fn cmp_args(&self, o: &Call) -> Ordering {
        (self.f, &self.args).cmp(&(o.f, &o.args))
    }
}

impl Var {
    /// The variant's place in the order: π, symbols, e^{iθ}'s, calls.
    fn rank(&self) -> u8 {
        match self {
            Var::Pi => 0,
            Var::Sym(_) => 1,
            Var::Z(_) => 2,
            Var::Call(_) => 3,
        }
    }
}

/// The order of variables: by variant, then by content — a call shared
/// with itself at once, without walking its arguments.
impl Ord for Var {
    fn cmp(&self, o: &Var) -> Ordering {
        match (self, o) {
            (Var::Sym(a), Var::Sym(b)) | (Var::Z(a), Var::Z(b)) => a.cmp(b),
            (Var::Call(a), Var::Call(b)) => {
                if Arc::ptr_eq(a, b) {
                    Ordering::Equal
                } else {
                    a.cmp_args(b)
                }
            }
            _ => self.rank().cmp(&o.rank()),
        }
    }
}

impl PartialOrd for Var {
    fn partial_cmp(&self, o: &Var) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

#[cfg(test)]
mod tests {
    use super::super::expr::{Expr, Symbol};
    use super::*;

    #[test]
    fn equal_calls_are_one_allocation_and_order_as_before() {
        let t = Expr::symbol(Symbol::new("t"));
        let u = t.mul(&t).add(&Expr::int(1));
        let (a, b) = (Expr::sqrt(&u), Expr::sqrt(&u));
        let call = |e: &Expr| match e.terms.keys().next().map(|m| &m[0].0) {
            Some(Var::Call(c)) => c.clone(),
            _ => panic!("not a call: {e:?}"),
        };
        assert!(Arc::ptr_eq(&call(&a), &call(&b)));
        // two different calls order by their arguments, as derived
        let v = Expr::sqrt(&u.add(&Expr::int(1)));
        let (x, y) = (Var::Call(call(&a)), Var::Call(call(&v)));
        assert_eq!(x.cmp(&y), call(&a).cmp_args(&call(&v)));
        assert_eq!(y.cmp(&x), x.cmp(&y).reverse());
        assert!(Var::Pi < Var::Sym(Symbol::new("t")) && Var::Z(Symbol::new("t")) < x);
    }
}
