//! `==` of trees over `given` matrices by the algebra of their blocks
//! (LANGUAGE.md §7; issue 35): `inv(T U) == inv(U) inv(T)` for the
//! book's transforms `[R, p; 0, 1]` (3.62), whose products and inverses
//! the seam forms in closed form (3.63, 3.64), and `Ad(T U) == Ad(T) Ad(U)`
//! with Ad_T = `[R, 0; [p] R, R]` (Definition 3.20). Each side is written
//! as a sum of words over its atoms with integer coefficients, by
//! identities only: products distribute over sums, (A B)ᵀ = Bᵀ Aᵀ, and for
//! a rotation R (a `given` name typed SO(3) or SO(2)) Rᵀ R = R Rᵀ = I and
//! R⁻¹ = Rᵀ (Prop. 3.3); a bracket [R v] = R [v] Rᵀ (3.30, the bracket of
//! a rotated vector) is linear in v. Any other node is an atom, equal only
//! to a node equal to it. The sides are equal when their sums are the
//! same; otherwise nothing is said (false is not proven this way).

use crate::values::symbolic::Role;
use crate::values::value::{Sym, Value};
use std::collections::BTreeMap;

/// An atom of a word: the index of its node, transposed or not.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Atom {
    id: usize,
    t: bool,
}

/// A sum of words (products of atoms, the empty one I) with integer
/// coefficients, none zero.
#[derive(Debug, Clone, PartialEq, Default)]
struct Poly(BTreeMap<Vec<Atom>, i64>);

/// A block matrix of sums (rows of entries).
type Blocks = Vec<Vec<Poly>>;

/// The largest coefficient kept (beyond it nothing is said).
const MAX_COEF: i64 = 1 << 40;

/// The deepest node walked (a deeper tree is not decided this way: the
/// walk recurses).
const MAX_DEPTH: u32 = 200;

/// The most terms of a sum.
const MAX_TERMS: usize = 256;

/// The atoms met so far, and which are rotations (the size of each: 3
/// for SO(3), 2 for SO(2), 0 for an atom that is no rotation).
struct Atoms<'a> {
    nodes: Vec<Sym>,
    rotation: Vec<usize>,
    is_rotation: &'a dyn Fn(&str) -> Option<usize>,
    /// How deep in the tree the walk is ([`MAX_DEPTH`]).
    depth: u32,
}

/// Whether trees `a` and `b` are equal by the algebra of their blocks
/// (module doc): true when proven, false when not (never a verdict that
/// they differ). `is_rotation` gives the size of the names that are
/// rotations (3 for SO(3), 2 for SO(2)), None for the others.
pub fn equal(a: &Sym, b: &Sym, is_rotation: &dyn Fn(&str) -> Option<usize>) -> bool {
    let mut atoms = Atoms {
        nodes: Vec::new(),
        rotation: Vec::new(),
        is_rotation,
        depth: 0,
    };
    if let (Some((c, x)), Some((d, y))) = (atoms.blocks(a), atoms.blocks(b)) {
        return meet(c, d).is_some() && x == y;
    }
    match (atoms.poly(a), atoms.poly(b)) {
        (Some(x), Some(y)) => x == y,
        _ => false,
    }
}

/// How a block matrix is cut into its 2×2 blocks, which says what each
/// entry's sum stands for: a transform `[X, y; 0, 1]` (n − 1 | 1: its last
/// row and column are one entry wide), an adjoint (3 | 3), or either (the
/// identity and zero, the same under any cut into square diagonal
/// blocks). Blocks are compared and multiplied only under the same cut
/// (`[2 A, 0; 0, 1]` and `[2, 0; 0, A]` have the same sums and are not
/// equal).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Cut {
    Transform,
    Adjoint,
    Any,
}

/// The cut two block matrices share, if any.
fn meet(a: Cut, b: Cut) -> Option<Cut> {
    match (a, b) {
        (Cut::Any, c) | (c, Cut::Any) => Some(c),
        (a, b) => (a == b).then_some(a),
    }
}

/// Whether `s` is the scalar constant `x`.
fn is_const(s: &Sym, x: f64) -> bool {
    matches!(s, Sym::Const(v, _) if v.as_scalar() == Some(x))
}

/// The blocks X and y of `[X, y; 0, 1]` (or `[X, y; 0, 0, 0, 1]`) as
/// written: a last row of scalar zeros and a scalar 1.
fn transform_rows(rows: &[Vec<Sym>]) -> Option<(&Sym, &Sym)> {
    let [top, bottom] = rows else { return None };
    let [x, y] = top.as_slice() else { return None };
    let (one, zeros) = bottom.split_last()?;
    let last = matches!(zeros.len(), 1 | 3)
        && zeros.iter().all(|z| is_const(z, 0.0))
        && is_const(one, 1.0);
    last.then_some((x, y))
}

impl Poly {
    fn one() -> Poly {
        Poly::constant(1)
    }

    fn constant(c: i64) -> Poly {
        let mut m = BTreeMap::new();
        if c != 0 {
            m.insert(Vec::new(), c);
        }
        Poly(m)
    }

    fn atom(a: Atom) -> Poly {
        let mut m = BTreeMap::new();
        m.insert(vec![a], 1);
        Poly(m)
    }

    /// Adds `c` times `w`; None when a coefficient grows past
    /// [`MAX_COEF`] or the sum past [`MAX_TERMS`].
    fn add_term(&mut self, w: Vec<Atom>, c: i64) -> Option<()> {
        let e = self.0.entry(w).or_insert(0);
        *e = e.checked_add(c).filter(|x| x.abs() <= MAX_COEF)?;
        if *e == 0 {
            self.0.retain(|_, c| *c != 0);
        }
        (self.0.len() <= MAX_TERMS).then_some(())
    }

    fn plus(mut self, o: &Poly, sign: i64) -> Option<Poly> {
        for (w, c) in &o.0 {
            self.add_term(w.clone(), c * sign)?;
        }
        Some(self)
    }
}

impl Atoms<'_> {
    /// The atom of node `s` (found again by structural equality).
    fn atom(&mut self, s: &Sym) -> Atom {
        let id = match self.nodes.iter().position(|n| n == s) {
            Some(i) => i,
            None => {
                let rot = match s {
                    Sym::Name(n) => (self.is_rotation)(n).unwrap_or(0),
                    _ => 0,
                };
                self.nodes.push(s.clone());
                self.rotation.push(rot);
                self.nodes.len() - 1
            }
        };
        Atom { id, t: false }
    }

    /// `w v` with a rotation's `Rᵀ R` and `R Rᵀ` cancelled where they meet.
    fn join(&self, w: &[Atom], v: &[Atom]) -> Vec<Atom> {
        let mut out = w.to_vec();
        for a in v {
            match out.last() {
                Some(b) if b.id == a.id && b.t != a.t && self.rotation[a.id] > 0 => {
                    out.pop();
                }
                _ => out.push(*a),
            }
        }
        out
    }

    fn times(&self, x: &Poly, y: &Poly) -> Option<Poly> {
        let mut out = Poly::default();
        for (w, c) in &x.0 {
            for (v, d) in &y.0 {
                let c = c.checked_mul(*d)?;
                out.add_term(self.join(w, v), c)?;
            }
        }
        Some(out)
    }

    /// The transpose of a sum: each word reversed, each atom transposed.
    fn transpose(&self, x: &Poly) -> Poly {
        let mut out = BTreeMap::new();
        for (w, c) in &x.0 {
            let v: Vec<Atom> = w.iter().rev().map(|a| Atom { id: a.id, t: !a.t }).collect();
            out.insert(v, *c);
        }
        Poly(out)
    }

    /// Whether every atom of word `w` is a rotation (so is the word).
    fn rotations(&self, w: &[Atom]) -> bool {
        w.iter().all(|a| self.rotation[a.id] > 0)
    }

    /// Whether word `w` is a rotation of SO(3) followed by an atom that is
    /// none (a vector, for the bracket: [R v] = R [v] Rᵀ).
    fn rotated(&self, w: &[Atom]) -> Option<(Atom, Vec<Atom>)> {
        let (v, rot) = w.split_last()?;
        let fits = !v.t && self.rotation[v.id] == 0 && rot.iter().all(|a| self.rotation[a.id] == 3);
        fits.then(|| (*v, rot.to_vec()))
    }

    /// R [v] Rᵀ for word R and vector atom v.
    fn bracket_term(&mut self, v: Atom, rot: Vec<Atom>) -> Vec<Atom> {
        let inner = Sym::Bracket(Box::new(self.nodes[v.id].clone()));
        let b = self.atom(&inner);
        let mut word = rot.clone();
        word.push(b);
        word.extend(rot.iter().rev().map(|a| Atom { id: a.id, t: !a.t }));
        word
    }

    /// `s` as a sum of words; None for a node past the limits.
    fn poly(&mut self, s: &Sym) -> Option<Poly> {
        if self.depth >= MAX_DEPTH {
            return None;
        }
        self.depth += 1;
        let p = self.poly_of(s);
        self.depth -= 1;
        p
    }

    /// [`Atoms::poly`] one level down.
    fn poly_of(&mut self, s: &Sym) -> Option<Poly> {
        Some(match s {
            Sym::Identity(_) => Poly::one(),
            Sym::Const(v, _) => match constant(v) {
                Some(c) => Poly::constant(c),
                None => Poly::atom(self.atom(s)),
            },
            Sym::Product(fs) => {
                let mut acc = Poly::one();
                for f in fs {
                    let p = self.poly(f)?;
                    acc = self.times(&acc, &p)?;
                }
                acc
            }
            Sym::Add(a, b) => self.poly(a)?.plus(&self.poly(b)?, 1)?,
            Sym::Sub(a, b) => self.poly(a)?.plus(&self.poly(b)?, -1)?,
            Sym::Neg(x) => Poly::default().plus(&self.poly(x)?, -1)?,
            Sym::Transpose(x) => {
                let p = self.poly(x)?;
                self.transpose(&p)
            }
            // (R⁻¹ = Rᵀ for a product of rotations, a sign kept)
            Sym::Inv(x) => {
                let p = self.poly(x)?;
                match p.0.iter().next() {
                    Some((w, c)) if p.0.len() == 1 && c.abs() == 1 && self.rotations(w) => {
                        self.transpose(&p)
                    }
                    _ => Poly::atom(self.atom(s)),
                }
            }
            Sym::Bracket(x) => self.bracket(x, s)?,
            _ => Poly::atom(self.atom(s)),
        })
    }

    /// `[x]` of a 3-vector: [R v] = R [v] Rᵀ for a word R of rotations
    /// and v an atom, each term so (the bracket is linear); else the
    /// bracket is an atom.
    fn bracket(&mut self, x: &Sym, whole: &Sym) -> Option<Poly> {
        let p = self.poly(x)?;
        let mut out = Poly::default();
        for (w, c) in &p.0 {
            let Some((v, rot)) = self.rotated(w) else {
                return Some(Poly::atom(self.atom(whole)));
            };
            let word = self.bracket_term(v, rot);
            out.add_term(word, *c)?;
        }
        Some(out)
    }

    /// `s` as a block matrix with its cut: a transform `[X, y; 0, 1]`
    /// (entries as sums), the adjoint `Ad` of one as `[R, 0; [p] R, R]`
    /// (Definition 3.20), the identity and zero, and products of such
    /// under the same cut; None for anything else.
    fn blocks(&mut self, s: &Sym) -> Option<(Cut, Blocks)> {
        match s {
            Sym::Block(rows) => {
                let (x, y) = transform_rows(rows)?;
                let (x, y) = (self.poly(x)?, self.poly(y)?);
                Some((
                    Cut::Transform,
                    vec![vec![x, y], vec![Poly::default(), Poly::one()]],
                ))
            }
            Sym::Call(f, args) if f.role == Role::Adjoint && args.len() == 1 => {
                let (Cut::Transform, t) = self.blocks(&args[0])? else {
                    return None;
                };
                let (r, p) = (t[0][0].clone(), t[0][1].clone());
                let b = self.bracket_of(&p)?;
                let pr = self.times(&b, &r)?;
                Some((
                    Cut::Adjoint,
                    vec![vec![r.clone(), Poly::default()], vec![pr, r]],
                ))
            }
            Sym::Identity(_) => Some((Cut::Any, diagonal(Poly::one()))),
            Sym::Const(v, _) if v.as_scalar().is_none() => match constant(v)? {
                c @ (0 | 1) => Some((Cut::Any, diagonal(Poly::constant(c)))),
                _ => None,
            },
            Sym::Product(fs) if fs.len() > 1 => {
                let (mut cut, mut acc) = self.blocks(&fs[0])?;
                for f in &fs[1..] {
                    let (c, b) = self.blocks(f)?;
                    cut = meet(cut, c)?;
                    acc = self.block_times(&acc, &b)?;
                }
                Some((cut, acc))
            }
            _ => None,
        }
    }

    /// `[p]` of a sum p already formed (each term a word of rotations
    /// ending in a vector atom).
    fn bracket_of(&mut self, p: &Poly) -> Option<Poly> {
        let mut out = Poly::default();
        for (w, c) in &p.0 {
            let (v, rot) = self.rotated(w)?;
            let word = self.bracket_term(v, rot);
            out.add_term(word, *c)?;
        }
        Some(out)
    }

    /// The product of two block matrices of the same partition (2×2).
    fn block_times(&self, a: &Blocks, b: &Blocks) -> Option<Blocks> {
        let square = |m: &Blocks| m.len() == 2 && m.iter().all(|r| r.len() == 2);
        if !square(a) || !square(b) {
            return None;
        }
        let mut out = vec![vec![Poly::default(), Poly::default()]; 2];
        for (i, row) in out.iter_mut().enumerate() {
            for (j, e) in row.iter_mut().enumerate() {
                for k in 0..2 {
                    let t = self.times(&a[i][k], &b[k][j])?;
                    *e = std::mem::take(e).plus(&t, 1)?;
                }
            }
        }
        Some(out)
    }
}

/// The 2×2 block matrix with `d` on its diagonal and 0 off it.
fn diagonal(d: Poly) -> Blocks {
    vec![vec![d.clone(), Poly::default()], vec![Poly::default(), d]]
}

/// An integer scalar constant (a coefficient), or 0 for a zero matrix and
/// 1 for an identity.
fn constant(v: &Value) -> Option<i64> {
    if let Some(x) = v.as_scalar() {
        return (x.fract() == 0.0 && x.abs() < 1e9).then_some(x as i64);
    }
    let m = v.as_matrix()?;
    if m.iter().all(|x| *x == 0.0) {
        return Some(0);
    }
    (m.is_square() && m.is_identity(0.0)).then_some(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name(n: &str) -> Sym {
        Sym::Name(n.into())
    }

    fn num(x: f64) -> Sym {
        Sym::Const(Box::new(Value::scalar(x)), format!("{x}"))
    }

    fn rotation(n: &str) -> Option<usize> {
        (n == "R").then_some(3)
    }

    #[test]
    fn a_rotation_cancels_its_transpose_and_nothing_else_does() {
        let rt_r = Sym::Product(vec![name("R").transpose(), name("R")]);
        let xt_x = Sym::Product(vec![name("X").transpose(), name("X")]);
        assert!(equal(&rt_r, &Sym::identity(), &rotation));
        assert!(!equal(&xt_x, &Sym::identity(), &rotation));
        // (R^T (R + X) - R^T X is I: products distribute)
        let sum = Sym::Sub(
            Box::new(Sym::Product(vec![
                name("R").transpose(),
                Sym::Add(Box::new(name("R")), Box::new(name("X"))),
            ])),
            Box::new(Sym::Product(vec![name("R").transpose(), name("X")])),
        );
        assert!(equal(&sum, &Sym::identity(), &rotation));
    }

    #[test]
    fn blocks_cut_differently_are_not_compared_by_their_sums() {
        let rt_r = Sym::Product(vec![name("R").transpose(), name("R")]);
        // [2 RᵀR, 0; 0, 1] is diag(2, 2, 2, 1); [2, 0; 0, RᵀR] is diag(2, 1, 1, 1)
        let a = Sym::Block(vec![
            vec![Sym::Product(vec![num(2.0), rt_r.clone()]), num(0.0)],
            vec![num(0.0), num(1.0)],
        ]);
        let b = Sym::Block(vec![vec![num(2.0), num(0.0)], vec![num(0.0), rt_r]]);
        assert!(!equal(&a, &b, &rotation));
        assert!(equal(&a, &a.clone(), &rotation));
    }

    #[test]
    fn a_deep_tree_is_left_undecided_not_walked() {
        let mut deep = name("X");
        for _ in 0..1000 {
            deep = Sym::Add(Box::new(deep), Box::new(name("X")));
        }
        // (equal as trees, but past the depth walked: no verdict here)
        assert!(!equal(&deep, &deep.clone(), &rotation));
    }
}
