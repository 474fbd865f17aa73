//! Exact numbers (LANGUAGE.md §3, §7, §10): a numeric value carries its
//! exact form while it has one — integers and decimals as typed (`0.866`
//! is 866/1000, not √3/2), π, square roots of exact numbers and what
//! arithmetic makes of them (`1/sqrt(2)` stays 1/√2) — as an [`Exact`]
//! beside its floats. The floats are what every numeric operation reads;
//! the exact form is asked for only by `==`, by a number entering a
//! symbolic expression, and by `--exact` printing.
//!
//! Exactness costs nothing where no one asks for it (issue 21): a literal
//! is only marked as typed ([`Exact::Typed`]: its digits are read back
//! from the float when asked), and an operation on exact operands records
//! how to compute its exact form ([`Exact::pending`]: the operation and
//! its operands in one allocation, no closure), which runs the first time
//! the form is asked for and is kept. A value with no exact form (sin 1,
//! a numeric matrix exponential) is a float ([`Exact::Float`]): it
//! compares as a float, and nothing guesses a closed form for it.

use std::cell::{Cell, OnceCell};
use std::rc::Rc;

use super::num::Num;
pub use super::operation::Operation;
pub use fraction::{Fraction, Fractions3};

mod fraction;
mod operands;
use super::value::Value;
use crate::check::ty::Kind;
use crate::sym::Mat;
use crate::sym::coef::{Coef, Rat};
use crate::sym::expr::{Expr, Var};
pub use operands::{Operand, Operands, deref};

/// What is known of a numeric value's exact form.
#[derive(Clone, Default)]
pub enum Exact {
    /// No exact form: the numbers are floats.
    #[default]
    Float,
    /// The numbers as typed: each entry is the shortest decimal that reads
    /// back as its float (`0.866`, `1e-13`, `2`).
    Typed,
    /// An exact form computed the first time it is asked for.
    Later(Rc<Later>),
    /// A fraction known at once, held inline ([`Fraction`]): a sum,
    /// difference, product or quotient of such numbers and of numbers as
    /// typed (`k/100` of a `k` of `1:100000`), and a range's items a + k·h
    /// of fractions. No allocation, where a recipe kept both operands.
    Ratio(Fraction),
    /// Fractions known at once, the entries of a 3-vector (ω, v or a
    /// position p of (3.62)) written of fractions held inline and numbers
    /// as typed (`(k/1000, 0, 0)`), packed inline ([`Fractions3`]): no
    /// allocation, where a recipe kept a copy of each entry's value. Its
    /// form is the recipe's, typed marks and all.
    Ratios(Fractions3),
}

impl std::fmt::Debug for Exact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Exact::Float => f.write_str("Float"),
            Exact::Typed => f.write_str("Typed"),
            Exact::Later(l) => match l.form.get() {
                Some(Some(m)) => write!(f, "Exact({m:?})"),
                Some(None) => f.write_str("Float"),
                None => f.write_str("Later"),
            },
            Exact::Ratio(r) => write!(f, "Ratio({:?})", r.rat()),
            Exact::Ratios(rs) => {
                let rats = rs.get().map(Fraction::rat);
                write!(f, "Ratios({rats:?})")
            }
        }
    }
}

/// An exact form made when first asked for, from its [`Pending`] recipe;
/// the result is kept.
pub struct Later {
    /// The form once asked for (boxed: most recipes are never asked, and
    /// the node stays 112 bytes, 128 with its counts).
    form: OnceCell<Option<Box<Mat>>>,
    make: Cell<Option<Make>>,
    /// The longest chain of recipes still waiting under this one (0 once
    /// the form is known); bounded by [`MAX_PENDING_DEPTH`].
    depth: u32,
    /// About how many bytes this holds, as the memory budget counts them
    /// ([`Exact::weight`]): fixed when it is made.
    bytes: u32,
}

/// The bytes of a [`Later`] node with its reference counts, as the
/// memory budget counts them ([`Exact::weight`]).
const NODE_BYTES: u64 = std::mem::size_of::<Later>() as u64 + 16;

/// The bytes of the box of a form known ([`Later::form`]).
const BOX_BYTES: u64 = std::mem::size_of::<Mat>() as u64;

/// The bytes of a closure's box and what it captures, estimated (a
/// range's item: its k and a shared pair of forms).
const CLOSURE_BYTES: u64 = 32;

/// The bytes of one term of an exact form (its place in the map, its
/// monomial and coefficient), estimated.
const TERM_BYTES: u64 = 96;

/// About the bytes an exact form `m` holds ([`Exact::weight`]).
fn form_bytes(m: &Mat) -> u64 {
    let entry = std::mem::size_of::<Expr>() as u64;
    m.data
        .iter()
        .map(|e| entry + TERM_BYTES * e.terms.len() as u64)
        .sum()
}

/// [`Exact::weight`] as a node's field holds it.
fn clamp(bytes: u64) -> u32 {
    u32::try_from(bytes).unwrap_or(u32::MAX)
}

/// The longest chain of waiting recipes kept (`x = x + 0.1` typed
/// 200,000 times): past it, the form is worked out at once, so working
/// it out later, and dropping the chain, never recurses deeper than
/// this on the stack.
pub const MAX_PENDING_DEPTH: u32 = 64;

/// How a [`Later`] form is made: an operation's [`Pending`] recipe (the
/// common case), or a closure (numbers bound later into a formula,
/// `decide::replay`).
enum Make {
    Op(Pending),
    Fn(Box<dyn FnOnce() -> Option<Mat>>),
}

/// How an exact form is made: one operation of the evaluator's seam over
/// its operands as they were (their numbers and their exact forms), run
/// by `run`, the evaluator's exact path (`seam::exactness`, which `values`
/// cannot name). Data, not a closure: recording it is one allocation with
/// the operands inline.
pub struct Pending {
    /// The operation.
    pub op: Operation,
    /// Its operands as they were.
    pub args: Operands,
    /// The result's kind as checked.
    pub kind: Kind,
    /// The exact path: the operation on the operands' exact forms (None:
    /// no exact form).
    pub run: fn(&Operation, &[&Value], &Kind) -> Option<Mat>,
}

impl Exact {
    /// A form known now (a formula whose entries are all exact numbers).
    pub fn known(m: Mat) -> Exact {
        let form = OnceCell::new();
        let bytes = clamp(NODE_BYTES + BOX_BYTES + form_bytes(&m));
        let _ = form.set(is_exact(&m).then(|| Box::new(m)));
        Exact::Later(Rc::new(Later {
            form,
            make: Cell::new(None),
            depth: 0,
            bytes,
        }))
    }
    /// A form computed by `p` when first asked for; at once when the
    /// chain of waiting recipes under it is longer than
    /// [`MAX_PENDING_DEPTH`].
    #[inline(always)]
    pub fn pending(p: Pending) -> Exact {
        let (under, bytes) = p.args.under();
        let depth = 1 + under;
        if depth > MAX_PENDING_DEPTH {
            let form = (p.run)(&p.op, &deref(&p.args.refs()), &p.kind).filter(is_exact);
            return match form {
                Some(m) => Exact::known(m),
                None => Exact::Float,
            };
        }
        let bytes = clamp(NODE_BYTES + u64::from(bytes));
        Exact::Later(Rc::new(Later {
            form: OnceCell::new(),
            make: Cell::new(Some(Make::Op(p))),
            depth,
            bytes,
        }))
    }
    /// A form computed by `make` when first asked for (None: no exact
    /// form); for the rarer paths, where a closure costs nothing that
    /// matters.
    pub fn later(make: impl FnOnce() -> Option<Mat> + 'static) -> Exact {
        Exact::Later(Rc::new(Later {
            form: OnceCell::new(),
            make: Cell::new(Some(Make::Fn(Box::new(make)))),
            depth: 0,
            bytes: clamp(NODE_BYTES + CLOSURE_BYTES),
        }))
    }
    /// About how many bytes this exact form holds beyond the value it
    /// belongs to, as the memory budget counts them (`eval::env::numbers`,
    /// 8 bytes a number): none for a float, numbers as typed or a
    /// fraction or fractions held inline; for a recipe, its node, its
    /// operands' values
    /// and the recipes under them that no one else holds; for a form
    /// known at once, its terms (an estimate: 96 bytes a term). Fixed
    /// when the form is made (a form worked out later, kept beside its
    /// recipe, is not counted), so that the bindings' count stays what it
    /// was when they were bound.
    #[inline]
    pub fn weight(&self) -> u64 {
        match self {
            Exact::Later(l) => u64::from(l.bytes),
            _ => 0,
        }
    }
    /// `f` of the recipe this value was made by, when it has no exact
    /// form but was made by an operation over operands that may have one
    /// (`cos(1e-9)`, `sin(1)^2`): what `==` bounds in high precision
    /// (`decide::certify`). None when it has an exact form (ask
    /// [`Exact::form`] first), is a float, or was made otherwise.
    pub fn with_recipe<R>(&self, f: impl FnOnce(&Pending) -> R) -> Option<R> {
        let Exact::Later(l) = self else { return None };
        if !matches!(l.form.get(), Some(None)) {
            return None;
        }
        self.peek_recipe(f)
    }
    /// `f` of the recipe this value was made by, while it is kept: before
    /// its form is asked for, or after it was found missing ([`Exact::with_recipe`]
    /// gives the second only). Reading it computes nothing: it is how a
    /// call asks what its operand was made by (`log` of `exp`,
    /// `decide::log_exp`) without working out the operand's form.
    pub fn peek_recipe<R>(&self, f: impl FnOnce(&Pending) -> R) -> Option<R> {
        let Exact::Later(l) = self else { return None };
        let make = l.make.take();
        let out = match &make {
            Some(Make::Op(p)) => Some(f(p)),
            _ => None,
        };
        l.make.set(make);
        out
    }
    /// The address of the form this value shares with its copies (the
    /// same number read twice, `a == a`); None for a float or as typed.
    pub fn identity(&self) -> Option<*const ()> {
        match self {
            Exact::Later(l) => Some(Rc::as_ptr(l).cast()),
            _ => None,
        }
    }
    /// True when no exact form is known (nothing to ask).
    #[inline]
    pub fn is_float(&self) -> bool {
        matches!(self, Exact::Float)
    }
    /// The exact form of numbers `m` carrying this: None for a float.
    pub fn form(&self, m: &Num) -> Option<Mat> {
        match self {
            Exact::Float => None,
            Exact::Typed => typed(m),
            Exact::Ratio(r) => Some(Mat::scalar(Expr::constant(Coef::rat(r.rat())))),
            Exact::Ratios(rs) => Some(rs.form()),
            Exact::Later(l) => l
                .form
                .get_or_init(|| {
                    // (a form asks for its operands' forms: a chain of
                    // closures, `Exact::later`, has no depth bound, so the
                    // stack grows on the heap where it runs low)
                    stacker::maybe_grow(64 * 1024, 1024 * 1024, || {
                        let m = match l.make.take()? {
                            Make::Op(p) => {
                                let m = (p.run)(&p.op, &deref(&p.args.refs()), &p.kind)
                                    .filter(is_exact);
                                // (no exact form: the recipe is kept, for
                                // `==` to bound the value, `decide::certify`)
                                if m.is_none() {
                                    l.make.set(Some(Make::Op(p)));
                                }
                                m?
                            }
                            Make::Fn(f) => f()?,
                        };
                        is_exact(&m).then(|| Box::new(m))
                    })
                })
                .as_deref()
                .cloned(),
        }
    }
}

/// True when every entry is an exact number: exact coefficients over π
/// alone (no symbol, no kept call, no float).
pub fn is_exact(m: &Mat) -> bool {
    m.data.iter().all(|e| {
        e.terms
            .iter()
            .all(|(mono, c)| c.is_exact() && mono.iter().all(|(v, _)| matches!(v, Var::Pi)))
    })
}

/// The exact form of numbers as typed: each entry the decimal its float
/// prints as (the shortest that reads back), None for inf or NaN.
pub fn typed(m: &Num) -> Option<Mat> {
    let (r, c) = m.shape();
    let mut data = Vec::with_capacity(r * c);
    for i in 0..r {
        for j in 0..c {
            data.push(Expr::constant(Coef::rat(decimal(m[(i, j)])?)));
        }
    }
    Some(Mat {
        rows: r,
        cols: c,
        data,
    })
}

/// The decimal a number literal writes (`0.866`, `.5`, `1.5e-13`,
/// `10000000000000000001`), exactly; None for other text.
pub fn written(text: &str) -> Option<Rat> {
    let (mantissa, exp) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().ok()?),
        None => (text, 0),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if !int.bytes().chain(frac.bytes()).all(|b| b.is_ascii_digit()) || int.len() + frac.len() == 0 {
        return None;
    }
    let digits: num_bigint::BigInt = format!("{int}{frac}").parse().ok()?;
    let exp = exp.checked_sub(i32::try_from(frac.len()).ok()?)?;
    // (a literal far beyond a float's range is a float anyway)
    (exp.unsigned_abs() < 2000).then(|| Rat::decimal(&digits, exp))
}

/// The token of a number literal in the text its node spans: `(x)` and
/// `{x}` are x spanning their brackets (the parser), so `(pi)`,
/// `( 1e-400 )` and `((pi),)` are read as `pi` and `1e-400`, not as the
/// float's decimals.
pub fn literal_token(text: &str) -> &str {
    let mut t = text;
    loop {
        let s = t.trim_start_matches(|c: char| c.is_whitespace() || c == '(' || c == '{');
        match s.strip_prefix('#') {
            // (a comment inside the brackets, to the end of its line)
            Some(c) => t = c.split_once('\n').map_or("", |(_, rest)| rest),
            None => {
                t = s;
                break;
            }
        }
    }
    let end = t
        .find(|c: char| c.is_whitespace() || matches!(c, ')' | '}' | ',' | '#'))
        .unwrap_or(t.len());
    &t[..end]
}

/// The decimal a float was typed as ([`Rat::typed`]).
pub fn decimal(x: f64) -> Option<Rat> {
    Rat::typed(x)
}

/// True when `r` is a decimal that `--digits` printing shows as typed (a
/// denominator of 2s and 5s only, at most 12 places).
pub fn is_short_decimal(r: &Rat) -> bool {
    let (_, den) = r.parts();
    let mut d = den;
    let (two, five) = (num_bigint::BigInt::from(2), num_bigint::BigInt::from(5));
    let zero = num_bigint::BigInt::from(0);
    let mut places = 0;
    while &d % &two == zero || &d % &five == zero {
        if &d % &two == zero {
            d /= &two;
        } else {
            d /= &five;
        }
        places += 1;
    }
    d == num_bigint::BigInt::from(1) && places <= 12
}

/// The exact form of a scalar that no decimal is (1/3, √2, π/6) as it
/// prints: a tree over symbols shows it so, not as digits that are
/// another number (`a^(1/3)` printed `a^0.3333333333333333`). None for a
/// decimal as typed (0.5), a float, or no scalar.
pub fn not_decimal_text(v: &Value) -> Option<String> {
    let m = v.exact_form().filter(|m| m.data.len() == 1)?;
    let e = &m.data[0];
    let decimal = e
        .as_const()
        .and_then(|c| c.as_rat())
        .is_some_and(|r| is_decimal(&r));
    (!decimal).then(|| crate::sym::print::expr(e, Default::default()))
}

/// True when `r` is a decimal: a denominator of 2s and 5s only.
pub fn is_decimal(r: &Rat) -> bool {
    let (_, mut d) = r.parts();
    let (two, five) = (num_bigint::BigInt::from(2), num_bigint::BigInt::from(5));
    let zero = num_bigint::BigInt::from(0);
    while &d % &two == zero {
        d /= &two;
    }
    while &d % &five == zero {
        d /= &five;
    }
    d == num_bigint::BigInt::from(1)
}

/// True when the exact form of a value prints as its decimals anyway:
/// every entry an integer or a typed decimal that its float `floats` at
/// `digits` decimals shows exactly (`0.866`,
/// `1e20`; not `0.12345` at 4 digits, nor 10²⁰ + 1): `--exact` then
/// prints the value as usual.
pub fn prints_as_decimals(m: &Mat, digits: usize, floats: &Num) -> bool {
    floats.shape() == (m.rows, m.cols)
        && m.data.iter().enumerate().all(|(k, e)| {
            match e.as_const().and_then(|c| c.as_rat()) {
                // (the float printed, not the exact value's: they differ
                // where floats cancelled, (0.1 − 10¹³) + 10¹³)
                Some(r) => {
                    let x = floats[(k / m.cols, k % m.cols)];
                    (r.is_typed() || r.is_integer())
                        && is_short_decimal(&r)
                        && reads_as(&super::number::fmt_num(x, digits), &r)
                }
                None => false,
            }
        })
}

/// True when `text`, read as a decimal, is exactly `r`.
fn reads_as(text: &str, r: &Rat) -> bool {
    text.parse::<f64>()
        .ok()
        .and_then(Rat::typed)
        .is_some_and(|t| &t == r)
}

/// A decimal `r` as text that reads back as exactly `r`: as numbers print
/// at `digits` decimals when that is exact, else the shortest float text
/// when that is (`0.12345`, `1.5e-13`), else every digit
/// (`100000000000000000001`).
fn decimal_text(r: &Rat, digits: usize) -> String {
    let x = r.to_f64();
    let printed = super::number::fmt_num(x, digits);
    if reads_as(&printed, r) {
        return printed;
    }
    let shortest = format!("{x:?}");
    let shortest = shortest.strip_suffix(".0").unwrap_or(&shortest).to_string();
    if reads_as(&shortest, r) {
        return shortest;
    }
    // every digit
    r.decimal_text().unwrap_or(printed)
}

/// An exact number as `--exact` prints it, so that it reads back: a
/// multiple of π as `π/6`, `-π/2`, `2π/3`; anything else as the symbolic
/// printer writes a constant (`√3/2`, `1/√2`, `1/3`).
pub fn text(e: &Expr, st: crate::sym::print::Style) -> String {
    // A decimal as typed prints as numbers do, to `--digits` places;
    // halves, quarters and fifths stay fractions, as in symbolic output,
    // and so does a fraction computed from integers (1/16, not 0.0625).
    if let Some(r) = e.as_const().and_then(|c| c.as_rat())
        && is_short_decimal(&r)
        && (r.is_typed() || r.is_integer())
        && r.small().is_none_or(|(_, q)| q == 1 || q > 5)
    {
        return decimal_text(&r, st.digits);
    }
    // A decimal of more places prints as it was typed (`1.5e-13`), the
    // shortest text that reads back as it, not as a fraction.
    if let Some(r) = e.as_const().and_then(|c| c.as_rat())
        && is_decimal(&r)
        && !is_short_decimal(&r)
    {
        if Rat::typed(r.to_f64()).is_some_and(|t| t == r) {
            return format!("{:?}", r.to_f64());
        }
        // more digits than a float holds (`1.00000000000000001`): all of them
        if let Some(d) = r.decimal_text().filter(|d| d.len() <= 40) {
            return d;
        }
    }
    if let [(mono, c)] = e.terms.iter().collect::<Vec<_>>().as_slice()
        && let [(Var::Pi, 1)] = mono.as_slice()
        && let Some((p, q)) = c.as_rat().and_then(|r| r.small())
    {
        let sign = if p < 0 { "-" } else { "" };
        let p = p.unsigned_abs();
        let num = if p == 1 { String::new() } else { p.to_string() };
        return if q == 1 {
            format!("{sign}{num}π")
        } else {
            format!("{sign}{num}π/{q}")
        };
    }
    crate::sym::print::expr(e, st)
}

/// A matrix of exact numbers as `--exact` prints it: a number alone, a
/// vector `(a, b, c)`, a matrix with right-aligned columns starting at
/// column `indent` (as numbers print, with [`text`] for each entry).
pub fn block(m: &Mat, st: crate::sym::print::Style, indent: usize, one_line: bool) -> String {
    let cells: Vec<String> = m.data.iter().map(|e| text(e, st)).collect();
    match (m.rows, m.cols) {
        (1, 1) => cells[0].clone(),
        (_, 1) => format!("({})", cells.join(", ")),
        (1, _) => format!("({}).T", cells.join(", ")),
        _ if one_line => {
            let rows: Vec<String> = cells.chunks(m.cols).map(|r| r.join(", ")).collect();
            format!("[{}]", rows.join("; "))
        }
        _ => {
            let w = |s: &String| s.chars().count();
            let widths: Vec<usize> = (0..m.cols)
                .map(|j| {
                    (0..m.rows)
                        .map(|i| w(&cells[i * m.cols + j]))
                        .max()
                        .unwrap_or(0)
                })
                .collect();
            let mut out = String::from("[");
            for i in 0..m.rows {
                if i > 0 {
                    out.push('\n');
                    out.push_str(&" ".repeat(indent + 1));
                }
                for j in 0..m.cols {
                    let c = &cells[i * m.cols + j];
                    out.push_str(&" ".repeat(widths[j] - w(c)));
                    out.push_str(c);
                    if j + 1 < m.cols {
                        out.push_str(", ");
                    }
                }
            }
            out.push(']');
            out
        }
    }
}

#[cfg(test)]
mod tests;
