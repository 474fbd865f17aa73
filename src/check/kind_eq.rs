//! How kinds compare and hash (LANGUAGE.md §5). Kinds are compared at
//! every node of every statement (a result's kind against its checked one,
//! a binding's against its name's), so `==` is written out to be inlined:
//! only tuple and list kinds, whose parts are interned, compare their parts
//! out of line. It is the relation a derived `==` would give, but for a
//! list's known length, which is not compared ([`Kind::List`]); the
//! matches are over every variant, so that a new one must say how it
//! compares and hashes.

use super::ty::Kind;

/// Kinds are compared at every node (a result's kind against its checked
/// one, a binding's against its name's): the comparison is inlined, and
/// only tuple and list kinds, whose parts are interned, compare their
/// parts out of line. The same relation as a derived `==` but for a
/// list's known length; the match is over every variant, so that a new
/// one must say how it compares.
impl PartialEq for Kind {
    #[inline(always)]
    fn eq(&self, other: &Kind) -> bool {
        use Kind::*;
        // (the variants first: most kinds compared are unit variants, or
        // differ there; the data only of the same variant)
        if std::mem::discriminant(self) != std::mem::discriminant(other) {
            return false;
        }
        match (self, other) {
            (Vector(a), Vector(b)) => a == b,
            (Matrix(a, b), Matrix(c, d)) => a == c && b == d,
            (Adjoint { transposed: a }, Adjoint { transposed: b }) => a == b,
            (Tuple(a), Tuple(b)) => same_parts(a, b),
            // (a list's known length is not part of its kind: [`Kind::List`])
            (List(a, _), List(b, _)) => {
                same_parts(std::slice::from_ref(*a), std::slice::from_ref(*b))
            }
            (
                Scalar | Bool | SO3 | SE3 | So3 | Se3 | SO2 | SE2 | So2 | Se2 | Twist | Screw
                | Wrench | Mechanism | Function | Picture | Text | Unknown,
                _,
            ) => true,
            // (the discriminants are equal: never reached)
            (Vector(_) | Matrix(..) | Adjoint { .. } | Tuple(_) | List(..), _) => false,
        }
    }
}

/// Hashes what [`Kind`]'s `==` compares: the variant and its data.
impl std::hash::Hash for Kind {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        use Kind::*;
        std::mem::discriminant(self).hash(state);
        match self {
            Vector(n) => n.hash(state),
            Matrix(r, c) => (r, c).hash(state),
            Adjoint { transposed } => transposed.hash(state),
            Tuple(ks) => ks.hash(state),
            List(k, _) => k.hash(state),
            Scalar | Bool | SO3 | SE3 | So3 | Se3 | SO2 | SE2 | So2 | Se2 | Twist | Screw
            | Wrench | Mechanism | Function | Picture | Text | Unknown => {}
        }
    }
}

/// The parts of two tuple (or list) kinds are equal: the same interned
/// slice, or equal part by part.
#[inline(never)]
fn same_parts(a: &[Kind], b: &[Kind]) -> bool {
    std::ptr::eq(a, b) || a == b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `==` and hashing of kinds agree with their structure (their debug
    /// text) over every variant, nested tuples and lists, and sizes known
    /// and unknown.
    #[test]
    fn kinds_compare_and_hash_by_their_structure() {
        use std::hash::{BuildHasher, RandomState};
        let mut kinds = vec![
            Kind::Scalar,
            Kind::Bool,
            Kind::SO3,
            Kind::SE3,
            Kind::So3,
            Kind::Se3,
            Kind::SO2,
            Kind::SE2,
            Kind::So2,
            Kind::Se2,
            Kind::Twist,
            Kind::Screw,
            Kind::Wrench,
            Kind::Mechanism,
            Kind::Function,
            Kind::Picture,
            Kind::Text,
            Kind::Unknown,
            Kind::Adjoint { transposed: false },
            Kind::Adjoint { transposed: true },
        ];
        for n in [None, Some(1), Some(3), Some(6)] {
            kinds.push(Kind::Vector(n));
            for m in [None, Some(3), Some(4)] {
                kinds.push(Kind::Matrix(n, m));
            }
        }
        let simple = kinds.clone();
        for (i, k) in simple.iter().enumerate() {
            kinds.push(Kind::list(*k));
            kinds.push(Kind::tuple(vec![*k, simple[(i + 1) % simple.len()]]));
        }
        kinds.push(Kind::tuple(vec![Kind::list(Kind::SO3), Kind::Scalar]));
        kinds.push(Kind::list(Kind::tuple(vec![
            Kind::SE3,
            Kind::Vector(Some(6)),
        ])));
        let hasher = RandomState::new();
        for a in &kinds {
            for b in &kinds {
                let same = format!("{a:?}") == format!("{b:?}");
                assert_eq!(a == b, same, "{a:?} == {b:?}");
                if same {
                    assert_eq!(hasher.hash_one(a), hasher.hash_one(b), "{a:?}");
                }
            }
        }
    }
}
