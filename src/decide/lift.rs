//! Proofs of identities between numbers made from exact ones (LANGUAGE.md
//! §7, issue 21): `sin(1)^2 + cos(1)^2 == 1`, `cos(2) == cos(1)^2 -
//! sin(1)^2`, `Rotz(1) Rotz(2) == Rotz(3)`. Neither side has an exact form
//! (sin 1 is a float), but each was made by operations over exact numbers
//! (its recipe, [`crate::values::exact::Exact::with_recipe`]). The recipe
//! is made again by the symbolic engine with every angle `x` of a sine,
//! cosine or rotation read as `x·ν`, where ν is a symbol that stands for
//! 1: each side becomes a function of ν that is the side's value at
//! ν = 1. When the two functions have the same canonical form, with no
//! float anywhere in it, they are equal for every ν, so at ν = 1: the
//! sides are equal, proven. Anything else proves nothing
//! ([`super::certify`] then bounds the difference).

use crate::values::exact::deref;
use std::collections::HashMap;

use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat, Surd};
use crate::sym::expr::{Expr, Symbol, Var};
use crate::values::exact::Operation;
use crate::values::recipe::{Recipe, Step};
use crate::values::value::Value;
use std::rc::Rc;

mod cleared;
mod field;
mod kept;
mod motion;
mod symbols;
use cleared::cleared_equal;
use field::{reduced, widened, z_of};

/// What the canonical forms of both sides' recipes, with their angles
/// scaled by ν (the module's doc), prove of `a == b`: `Ok(())` equal;
/// `Err(d)` different, `d` an entry of `a − b` that is a nonzero exact
/// number (no ν left: the same at ν = 1); None nothing.
pub fn verdict(a: &Value, b: &Value) -> Option<Result<(), Expr>> {
    verdict_of(a, b, false)
}

/// True when the squares of the numbers `a` and `b` are proven equal as
/// [`verdict`] proves sides equal: then a = ±b, and the signs decide
/// (`super::certify`: sin(π/5) == √((5 − √5)/8), tan(π/8) == √2 − 1).
pub fn squares_equal(a: &Value, b: &Value) -> bool {
    matches!(verdict_of(a, b, true), Some(Ok(())))
}

/// [`verdict`], of the squares of the sides when `squared`.
fn verdict_of(a: &Value, b: &Value, squared: bool) -> Option<Result<(), Expr>> {
    let mut lift = Lift {
        squared,
        ..Lift::default()
    };
    let first = proof(a, b, &mut lift);
    if matches!(first, Some(Ok(()))) {
        return first;
    }
    // (again with every angle a + bπ read as a whole multiple of μ = 1/M
    // plus one of ρ = π/L: angles then add as the powers of e^{iμ} and
    // e^{iρ} multiply, Rotx(-π) Rotx(1 deg) == Rotx(-π + 1 deg))
    let split = lift.split()?;
    let roots = lift.roots.clone();
    let mut lift = Lift {
        split: Some(split),
        squared,
        roots: roots.clone(),
        ..Lift::default()
    };
    let mut tried = proof(a, b, &mut lift);
    if !matches!(tried, Some(Ok(())))
        && let Some(l) = lift.wider
    {
        // (again in the field that holds the square roots met too)
        let mut wider = Lift {
            split: Some((split.0, l)),
            squared,
            roots,
            ..Lift::default()
        };
        tried = proof(a, b, &mut wider).or(tried);
    }
    tried.or(first)
}

/// How angles are read, and what was met of them.
#[derive(Default)]
struct Lift {
    /// Each side's lifted form, by the side's shared form.
    memo: HashMap<*const (), Option<Mat>>,
    /// The lifted forms of formulas' recipes, by recipe.
    recipes: HashMap<*const Recipe, Option<Mat>>,
    /// None: an angle x is x·ν. Some((M, L)): an angle a + bπ is
    /// (a M) μ + (b L) ρ, μ = 1/M, ρ = π/L.
    split: Option<(i64, i64)>,
    /// The angles met, as (a, b) of a + bπ (the others are atoms).
    angles: Option<Vec<(Rat, Rat)>>,
    /// The numbers read as independent symbols (an angle that is not
    /// a + bπ, such as the cos 2 of tan(cos 2)), by their fingerprints
    /// ([`fingerprint`]): the same recipe on both sides is one symbol.
    atoms: Vec<String>,
    /// A larger L whose field ℚ(e^{iπ/L}) holds the square roots met in
    /// the coefficients (their conductors divide 2L), when the split's L
    /// does not and the larger one is at most 360.
    wider: Option<i64>,
    /// The sides' squares are compared ([`squares_equal`]).
    squared: bool,
    /// Each square root √k met in an angle, with the least common
    /// denominator of its coefficients there: in a split, its symbol
    /// σₖ stands for √k/D, so that its multiples are whole (as μ's are).
    roots: Vec<(u128, i64)>,
}

impl Lift {
    /// (M, L): the least common denominators of the angles' rational
    /// parts and of their multiples of π, when both are small enough for
    /// whole powers.
    fn split(&self) -> Option<(i64, i64)> {
        let mut m = num_bigint::BigInt::from(1);
        let mut l = num_bigint::BigInt::from(1);
        for (a, b) in self.angles.as_ref()? {
            m = num_integer::Integer::lcm(&m, &a.parts().1);
            l = num_integer::Integer::lcm(&l, &b.parts().1);
        }
        // (μ's powers are only multiplied: large ones cost nothing, to
        // the exponents' range; ρ's are reduced by Φ_2L, of degree < 2L)
        let small = |n: &num_bigint::BigInt, most: i64| {
            i64::try_from(n.clone()).ok().filter(|n| *n <= most)
        };
        Some((small(&m, 1_000_000_000)?, small(&l, 100_000)?))
    }

    /// An angle `x` as this lift reads it.
    fn angle(&mut self, x: &Expr) -> Option<Expr> {
        self.angle_of(x, true)
    }

    /// [`Lift::angle`], a + bπ read as a + (b mod 2)π when `periodic`
    /// (the angle of a sine: cos(10²⁰π + 1) lifts as cos 1 does), as it
    /// is otherwise (the angle of a screw motion, which also translates).
    fn angle_of(&mut self, x: &Expr, periodic: bool) -> Option<Expr> {
        let turns = |b: Rat| if periodic { b.rem_euclid(2) } else { b };
        let parts = rational_and_pi(x).map(|(a, b)| (a, turns(b)));
        let reduced;
        let x = match &parts {
            Some((a, b)) if rational_and_pi(x).is_some_and(|(_, b0)| b0 != *b) => {
                reduced = Expr::constant(Coef::rat(a.clone()))
                    .add(&Expr::constant(Coef::rat(b.clone())).mul(&Expr::pi()));
                &reduced
            }
            _ => x,
        };
        match (parts, self.split) {
            (Some((a, b)), Some((m, l))) => {
                let scaled = |r: &Rat, k: i64| Coef::rat(r.mul(&Rat::int(k)));
                Some(
                    symbol(MU)
                        .scale(&scaled(&a, m))
                        .add(&symbol(RHO).scale(&scaled(&b, l))),
                )
            }
            // (an exact angle a + bπ with square roots in a and b
            // rational, √2 or 1 + √2 + π/3: its rational part read as a
            // rational angle's, each c√k of a as c σₖ, σₖ a symbol that
            // stands for √k, so that cos(2√2) and cos²√2 − sin²√2 meet)
            (None, split)
                if let Some((r, b)) = surd_and_pi(x).and_then(|(a, b)| Some((a, b.as_rat()?))) =>
            {
                let b = turns(b);
                let rational = r
                    .terms()
                    .find(|(k, _)| *k == 1)
                    .map_or(Rat::ZERO, |(_, c)| c.clone());
                let whole = match split {
                    Some((m, l)) => symbol(MU)
                        .scale(&Coef::rat(rational.mul(&Rat::int(m))))
                        .add(&symbol(RHO).scale(&Coef::rat(b.mul(&Rat::int(l))))),
                    None => {
                        let at = Expr::constant(Coef::rat(rational.clone()))
                            .add(&Expr::constant(Coef::rat(b.clone())).mul(&Expr::pi()));
                        self.angles.get_or_insert_with(Vec::new).push((rational, b));
                        at.mul(&symbol(NU))
                    }
                };
                let mut roots = Expr::default();
                for (k, c) in r.terms().filter(|(k, _)| *k > 1) {
                    let d = self.root_denominator(k, c, split.is_some())?;
                    let symbol = symbol(&format!("{ROOT}{k}/{d}⟩"));
                    roots = roots.add(&symbol.scale(&Coef::rat(c.mul(&Rat::int(d)))));
                }
                Some(whole.add(&roots))
            }
            // (any other exact angle, π², is a symbol of its own)
            (None, _) => Some(self.named(format!("{x:?}"))),
            (Some(ab), None) => {
                self.angles.get_or_insert_with(Vec::new).push(ab);
                Some(x.mul(&symbol(NU)))
            }
        }
    }

    /// D of the symbol σₖ = √k/D that a coefficient `c` of √k in an angle
    /// is a multiple of: 1 unless `split`, then the least common
    /// denominator of the coefficients of √k met before the split (the
    /// same for every angle of the split; None for one larger than i64).
    /// Each coefficient met is noted.
    fn root_denominator(&mut self, k: u128, c: &Rat, split: bool) -> Option<i64> {
        let den = c.parts().1;
        match self.roots.iter_mut().find(|(j, _)| *j == k) {
            Some((_, d)) => {
                let l = num_integer::Integer::lcm(&num_bigint::BigInt::from(*d), &den);
                if !split {
                    *d = i64::try_from(l).ok()?;
                }
            }
            None => self.roots.push((k, i64::try_from(den).ok()?)),
        }
        Some(match split {
            true => self
                .roots
                .iter()
                .find(|(j, _)| *j == k)
                .map_or(1, |(_, d)| *d),
            false => 1,
        })
    }

    /// The symbol that stands for the number printed `print` (an atom).
    fn named(&mut self, print: String) -> Expr {
        let n = match self.atoms.iter().position(|p| *p == print) {
            Some(n) => n,
            None => {
                self.atoms.push(print);
                self.atoms.len() - 1
            }
        };
        symbol(&format!("{ATOM}{n}⟩"))
    }
}

/// (a, b) of an exact angle a + bπ with a, b rational.
fn rational_and_pi(x: &Expr) -> Option<(Rat, Rat)> {
    let (a, b) = surd_and_pi(x)?;
    Some((a.as_rat()?, b.as_rat()?))
}

/// x as a + bπ with a and b real surds (no other symbol, no float).
fn surd_and_pi(x: &Expr) -> Option<(Surd, Surd)> {
    let (mut a, mut b) = (Surd::ZERO, Surd::ZERO);
    for (mono, c) in &x.terms {
        let r = c.as_real()?;
        match mono.as_slice() {
            [] => a = r,
            [(Var::Pi, 1)] => b = r,
            _ => return None,
        }
    }
    Some((a, b))
}

/// The proof `verdict` asks for, with angles read by `lift`.
fn proof(a: &Value, b: &Value, lift: &mut Lift) -> Option<Result<(), Expr>> {
    let (mut x, mut y) = (side(a, lift)?, side(b, lift)?);
    if lift.squared {
        if x.data.len() != 1 || y.data.len() != 1 {
            return None;
        }
        x.data[0] = x.data[0].mul(&x.data[0]);
        y.data[0] = y.data[0].mul(&y.data[0]);
    }
    if let Some((m, l)) = lift.split {
        // (μ and ρ outside a sine, the angle of a screw's translation: at
        // their numbers, as the exact forms beside them hold π)
        for e in x.data.iter_mut().chain(y.data.iter_mut()) {
            *e = motion::bare_angles_at(e, m, l);
        }
        lift.wider = widened(x.data.iter().chain(&y.data), l);
        let z = z_of(x.data.iter().chain(&y.data));
        for e in x.data.iter_mut().chain(y.data.iter_mut()) {
            *e = reduced(e, l, &z);
        }
    }
    if (x.rows, x.cols) != (y.rows, y.cols)
        || !x.data.iter().all(exact)
        || !y.data.iter().all(exact)
    {
        return None;
    }
    if x.data == y.data {
        return Some(Ok(()));
    }
    if x.data
        .iter()
        .zip(&y.data)
        .all(|(p, q)| p == q || cleared_equal(p, q, lift.split))
    {
        return Some(Ok(()));
    }
    x.data
        .iter()
        .zip(&y.data)
        .map(|(p, q)| p.sub(q))
        .find(|d| {
            !d.terms.is_empty()
                && d.terms
                    .keys()
                    .all(|mono| mono.iter().all(|(v, _)| matches!(v, Var::Pi)))
        })
        .map(Err)
}

/// The names of the lift's own symbols, which no typed name can be
/// (identifiers hold no ⟨): ν scales every angle, μ = 1/M and ρ = π/L
/// split them, ⟨αn⟩ is a number read as a symbol of its own and ⟨√k⟩
/// stands for √k in an angle.
const NU: &str = "⟨ν⟩";
const MU: &str = "⟨μ⟩";
const RHO: &str = "⟨ρ⟩";
const ATOM: &str = "⟨α";
const ROOT: &str = "⟨√";

/// The symbol `name` (ν, μ, ρ: they stand for numbers in the angles).
fn symbol(name: &str) -> Expr {
    Expr::symbol(Symbol::new(name))
}

/// True when no coefficient anywhere in `e` is a float (calls' arguments
/// included): its canonical form is then a proof, not a rounding.
fn exact(e: &Expr) -> bool {
    e.terms.iter().all(|(mono, c)| {
        matches!(c, Coef::Exact { .. })
            && mono.iter().all(|(v, _)| match v {
                Var::Call(call) => call.args.iter().all(exact),
                _ => true,
            })
    })
}

/// The builtins whose scalar arguments are angles: (name, which argument).
fn angle_of(op: &Operation) -> Option<usize> {
    let Operation::Call(name) = op else {
        return None;
    };
    match crate::builtins::lookup(name)?.name {
        "sin" | "cos" | "tan" | "cot" | "sec" | "csc" | "Rotx" | "Roty" | "Rotz" => Some(0),
        "Rot" => Some(1),
        _ => None,
    }
}

/// The canonical form of `v` with its angles scaled by ν: its exact form
/// when it has one, else its recipe made again symbolically.
fn lifted(v: &Value, lift: &mut Lift, depth: u32) -> Option<Mat> {
    let Value::Num { exact, .. } = v else {
        return None;
    };
    if let Some(form) = v.exact_form() {
        return Some(form);
    }
    if depth > 64 {
        return None;
    }
    let key = exact.identity()?;
    if let Some(found) = lift.memo.get(&key) {
        return found.clone();
    }
    let out = exact
        .with_recipe(|p| {
            let angle = angle_of(&p.op);
            let mut forms = Vec::new();
            for (i, a) in deref(&p.args.refs()).into_iter().enumerate() {
                let mut m = lifted(a, lift, depth + 1)?;
                // (an exponential's angle, read as a sine's is: motion.rs)
                motion::read_angle(&p.op, i, &mut m, lift);
                if Some(i) == angle {
                    if m.data.len() != 1 {
                        return None;
                    }
                    // (an angle made by a recipe that is not a + bπ, the
                    // cos 2 of tan(cos 2), is read as a symbol of its own:
                    // an identity in it holds whatever its value)
                    m.data[0] = if a.exact_form().is_none() && rational_and_pi(&m.data[0]).is_none()
                    {
                        atom(a, lift)?
                    } else {
                        lift.angle(&m.data[0])?
                    };
                }
                forms.push(Value::Formula {
                    kind: a.kind(),
                    m,
                    how: None,
                });
            }
            if let Some(m) = kept::kept(&p.op, &forms) {
                return Some(m);
            }
            crate::seam::exactness::formula_of(&p.op, forms, &p.kind)
        })
        .flatten();
    // (a form past MAX_LIFTED_TERMS proves nothing: a product of many
    // exponentials about other axes grows by a factor at each one)
    let out =
        out.filter(|m| m.data.iter().map(|e| e.terms.len()).sum::<usize>() <= MAX_LIFTED_TERMS);
    // (a number the symbolic engine cannot make exactly, atan 2 or
    // tan(cos 2), is read as a symbol of its own, as its angle would be)
    let out = match out {
        Some(m) if m.data.iter().all(self::exact) => Some(m),
        _ if v.as_scalar().is_some() => atom(v, lift).map(Mat::scalar),
        out => out,
    };
    lift.memo.insert(key, out.clone());
    out
}

/// The most terms, all entries together, of a lifted form (the products
/// of its operations grow as the square of their operands').
const MAX_LIFTED_TERMS: usize = 512;

/// The symbol that stands for number `v` in the lifted forms (the
/// [`Lift::atoms`]): one per fingerprint, so the same recipe typed on
/// both sides is the same symbol.
fn atom(v: &Value, lift: &mut Lift) -> Option<Expr> {
    Some(lift.named(fingerprint(v, 0)?))
}

/// The longest fingerprint made (a recipe that shares operands may
/// otherwise print exponentially long).
const MAX_PRINT: usize = 4096;

/// How `v` was made, as text: its exact form, else its operation over
/// its operands' fingerprints; equal texts are equal numbers.
fn fingerprint(v: &Value, depth: u32) -> Option<String> {
    let Value::Num { exact, kind, .. } = v else {
        return None;
    };
    if let Some(form) = v.exact_form() {
        return Some(format!("{form:?}"));
    }
    if depth > 64 {
        return None;
    }
    let out = exact
        .with_recipe(|p| {
            let mut s = format!("{:?}:{kind:?}(", p.op);
            for a in deref(&p.args.refs()) {
                s += &fingerprint(a, depth + 1)?;
                s.push(',');
                if s.len() > MAX_PRINT {
                    return None;
                }
            }
            s.push(')');
            Some(s)
        })
        .flatten()?;
    (out.len() <= MAX_PRINT).then_some(out)
}

/// The lifted form of a side: a number's ([`lifted`]), or a formula's,
/// made again from its recipe with its numbers lifted and its symbols as
/// themselves ([`lifted_recipe`]): an identity in ν, μ, ρ, the atoms and
/// the symbols holds at the numbers, for every value of the symbols
/// (`(cos(pi/7) + cos(3pi/7) + cos(5pi/7)) t == t/2`).
fn side(v: &Value, lift: &mut Lift) -> Option<Mat> {
    match v {
        Value::Num { .. } => lifted(v, lift, 0),
        Value::Formula { how: Some(r), .. } => lifted_recipe(r, lift),
        Value::Formula { how: None, m, .. } => m.data.iter().all(exact).then(|| m.clone()),
        _ => None,
    }
}

/// The deepest recipe of a formula lifted.
const MAX_RECIPE_DEPTH: u32 = 400;

/// The lifted form of a formula's recipe: its leaves' (numbers lifted, a
/// `given` symbol's canonical form as is), then each operation through
/// the exact path, the angles of sines, cosines and rotations read as
/// [`Lift::angle_with_symbols`] does.
fn lifted_recipe(r: &Rc<Recipe>, lift: &mut Lift) -> Option<Mat> {
    if r.depth > MAX_RECIPE_DEPTH {
        return None;
    }
    let key = Rc::as_ptr(r);
    if let Some(found) = lift.recipes.get(&key) {
        return found.clone();
    }
    let out = stacker::maybe_grow(64 * 1024, 1024 * 1024, || match &r.step {
        Step::Leaf(v @ Value::Num { .. }) => lifted(v, lift, 0),
        Step::Leaf(Value::Formula { m, .. }) => m.data.iter().all(exact).then(|| m.clone()),
        Step::Retag => lifted_recipe(r.args.first()?, lift),
        // (a closed form marked with its branch is the call, §7)
        Step::Closed(on) if !on.guards => lifted_recipe(r.args.first()?, lift),
        Step::Op(op) => {
            let angle = angle_of(op);
            let mut forms = Vec::with_capacity(r.args.len());
            for (i, a) in r.args.iter().enumerate() {
                let mut m = lifted_recipe(a, lift)?;
                if Some(i) == angle {
                    if m.data.len() != 1 {
                        return None;
                    }
                    m.data[0] = lift.angle_with_symbols(&m.data[0])?;
                }
                forms.push(Value::Formula {
                    kind: a.kind,
                    m,
                    how: None,
                });
            }
            crate::seam::exactness::formula_of(op, forms, &r.kind)
        }
        _ => None,
    });
    lift.recipes.insert(key, out.clone());
    out
}
