//! The parts of a tuple, each with its own type (LANGUAGE.md §3, §6): a
//! tuple literal `(T_ab, T_cb)` holds a {a}←{b} and a {c}←{b}, which one
//! tag for the whole tuple cannot say. [`Ty::parts`] keeps them, so that
//! indexing `t[1]` and destructuring `(A, B) = t` give each part its
//! frames back; a tuple a builtin made (`TransToRp(T_ab)`) has one tag,
//! from which [`super::ty::Frames::part`] gives its parts'.

use super::ty::{Kind, Ty};

pub use super::part_list::Parts;

/// Every list of part types made so far, by its contents and by number.
#[derive(Default)]
struct Table {
    ids: std::collections::HashMap<&'static [Ty], Parts, foldhash::fast::FixedState>,
    all: Vec<&'static [Ty]>,
}

static PARTS: std::sync::LazyLock<std::sync::Mutex<Table>> =
    std::sync::LazyLock::new(Default::default);

fn table() -> std::sync::MutexGuard<'static, Table> {
    // The table is only added to, so it is whole even after a panic.
    PARTS.lock().unwrap_or_else(|e| e.into_inner())
}

fn intern(parts: &[Ty]) -> Parts {
    let mut t = table();
    if let Some(&p) = t.ids.get(parts) {
        return p;
    }
    let list: &'static [Ty] = Box::leak(parts.to_vec().into_boxed_slice());
    t.all.push(list);
    let n = u32::try_from(t.all.len()).expect("fewer than 2^32 tuple types");
    let p = Parts(std::num::NonZeroU32::new(n).expect("counted from 1"));
    t.ids.insert(list, p);
    p
}

impl Parts {
    /// The part types this number stands for.
    pub fn get(self) -> &'static [Ty] {
        table().all[self.0.get() as usize - 1]
    }
}

impl Ty {
    /// The type of the tuple `(x, y, …)` of parts of these types: untagged,
    /// each part's own type kept when any says more than its kind.
    pub fn tuple_of(parts: &[Ty]) -> Ty {
        let mut t = Ty::plain(Kind::tuple(parts.iter().map(|p| p.kind).collect()));
        if parts.iter().any(|p| *p != Ty::plain(p.kind)) {
            t.parts = Some(intern(parts));
        }
        t
    }

    /// Part `i` (from 0) of a tuple: its own type when the tuple keeps one,
    /// else its kind with the part of the tuple's tag. None when `self` is
    /// no tuple or has no part `i`.
    pub fn part(&self, i: usize) -> Option<Ty> {
        let Kind::Tuple(kinds) = self.kind else {
            return None;
        };
        let kind = *kinds.get(i)?;
        match self.parts {
            Some(parts) => parts.get().get(i).copied(),
            None => Some(Ty::new(kind, self.frames.part(&kind))),
        }
    }

    /// The type of a part of a tuple when which part is not known (an
    /// index the checker has no number for): the parts' one type when they
    /// all have it, else None.
    pub fn any_part(&self) -> Option<Ty> {
        let Kind::Tuple(kinds) = self.kind else {
            return None;
        };
        let first = self.part(0)?;
        (1..kinds.len())
            .all(|i| self.part(i) == Some(first))
            .then_some(first)
    }

    /// True when the parts of a tuple differ in their frames or kinds (so
    /// that not knowing which part an index picks loses what they say).
    pub fn parts_differ(&self) -> bool {
        matches!(self.kind, Kind::Tuple(ks) if ks.len() > 1) && self.any_part().is_none()
    }
}

impl Kind {
    /// The kind of a list of `len` elements of kind `elem`, `len` known
    /// without numbers (None: not known; [`Kind::List`]).
    pub fn list_of_len(elem: Kind, len: Option<usize>) -> Kind {
        match Kind::list(elem) {
            Kind::List(k, _) => Kind::List(k, len.and_then(|n| u32::try_from(n).ok())),
            k => k,
        }
    }
    /// Whether the kind is, or has a part that is, [`Kind::Unknown`] (the
    /// kind of a given name's symbol, or a tuple of them).
    pub fn has_unknown(&self) -> bool {
        match self {
            Kind::Unknown => true,
            Kind::Tuple(parts) => parts.iter().any(Kind::has_unknown),
            _ => false,
        }
    }
    /// The number of items of a list kind, when checking knows it.
    pub fn list_len(&self) -> Option<usize> {
        match self {
            Kind::List(_, n) => n.map(|n| n as usize),
            _ => None,
        }
    }
}

impl Ty {
    /// The type of a list whose items all have type `item` (a
    /// comprehension's body): the item's kind and frames, and the item's
    /// own type kept when it is a tuple with parts of their own
    /// (`[(T_ab, T_cb) for k in 1:2]`).
    pub fn list_of(item: Ty, kind: Kind) -> Ty {
        let mut t = Ty::new(Kind::list(kind), item.frames);
        if item.parts.is_some() && item.kind == kind {
            t.parts = Some(intern(&[item]));
        }
        t
    }

    /// The type of an item of kind `kind` of a list typed `self`: the item
    /// type the list keeps ([`Ty::list_of`]), else `kind` with the list's
    /// frames.
    pub fn item(&self, kind: Kind) -> Ty {
        match (self.kind, self.parts.map(Parts::get)) {
            (Kind::List(..), Some([item])) if item.kind == kind => *item,
            _ => Ty::new(kind, self.frames),
        }
    }
}

/// A tuple's parts' types with the kinds the values say (evaluation may
/// know a part's kind better than the checker: `Unknown` becomes SE(3)).
pub fn with_kinds(t: &Ty, kind: Kind) -> Ty {
    let mut out = Ty::new(kind, t.frames);
    if let (Some(parts), Kind::Tuple(kinds)) = (t.parts.map(Parts::get), kind)
        && parts.len() == kinds.len()
    {
        let refined: Vec<Ty> = parts
            .iter()
            .zip(kinds)
            .map(|(p, k)| match p.kind == *k {
                true => *p,
                false => super::algebra::with_kind(p, *k),
            })
            .collect();
        out.parts = Some(intern(&refined));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::ty::Frames;

    #[test]
    fn a_tuple_keeps_each_parts_frames() {
        let t = Ty::tuple_of(&[
            Ty::new(Kind::SE3, Frames::pair("a", "b")),
            Ty::new(Kind::SE3, Frames::pair("c", "b")),
        ]);
        assert_eq!(t.frames, Frames::None);
        assert_eq!(t.part(0).map(|p| p.frames), Some(Frames::pair("a", "b")));
        assert_eq!(t.part(1).map(|p| p.frames), Some(Frames::pair("c", "b")));
        assert_eq!(t.part(2), None);
        assert!(t.parts_differ());
        assert_eq!(t.any_part(), None);
        // untagged parts: nothing to keep
        let plain = Ty::tuple_of(&[Ty::scalar(), Ty::plain(Kind::SO3)]);
        assert_eq!(plain.parts, None);
        // a builtin's tuple tagged {a}←{b}: R is {a}←{b}, p is in {a}
        let rp = Ty::new(
            Kind::tuple(vec![Kind::SO3, Kind::Vector(Some(3))]),
            Frames::pair("a", "b"),
        );
        assert_eq!(rp.part(1).map(|p| p.frames), Some(Frames::one("a")));
        assert!(rp.parts_differ());
        let same = Ty::tuple_of(&[Ty::new(Kind::SO3, Frames::pair("a", "b")); 2]);
        assert_eq!(same.any_part(), same.part(0));
    }
}
