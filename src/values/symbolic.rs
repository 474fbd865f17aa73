//! Symbolic expressions over `given` names (LANGUAGE.md §7): products of
//! transforms simplify (inverse pairs and identities cancel) and print as
//! the book writes them, `T_ab T_bc T_cd`. The tree is generic over the
//! values it holds as constants (the evaluator's `Value`), so this module
//! needs nothing from the value layer.

use std::fmt;

/// What a function is to the algebra of symbols (LANGUAGE.md §7): an
/// inverse (`inv`, `RotInv`, `TransInv`: `inv(inv(X)) = X`, and
/// `inv(T_ab) T_ab` cancels), the adjoint map (`Ad(X) Ad(inv(X))` cancels,
/// §3.3.2), or neither. The builtin table gives each builtin its role.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Neither: the call is kept as written and cancels with nothing.
    Plain,
    /// An inverse, `X⁻¹`: `inv(inv(X)) = X`, and `X inv(X)` cancels.
    Inverse,
    /// The adjoint map `[Ad_T]` (Definition 3.6): `Ad(X) Ad(inv(X))` cancels, as
    /// `[Ad_T]⁻¹ = [Ad_{T⁻¹}]`.
    Adjoint,
}

/// A builtin applied in a symbolic expression: the name it was called by
/// (printed as written, `Ad` or `Adjoint`) and its [`Role`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fun {
    /// The builtin's name as called, printed back as written.
    pub name: &'static str,
    /// How the builtin simplifies in products.
    pub role: Role,
}

/// A part of a value named by a member (LANGUAGE.md §4): the rotation
/// `T.R` and position `T.p` of a transform (3.62), the angular and linear
/// parts `V.w`, `V.v` of a twist (3.70) and `F.m`, `F.f` of a wrench (3.95).
/// (`.T` is the transpose, an operation of its own.)
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// `T.R`: the rotation R ∈ SO(3) of T = (R, p) (3.62).
    R,
    /// `T.p`: the position p ∈ ℝ³ of T = (R, p) (3.62).
    P,
    /// `V.w`: the angular velocity ω of a twist V = (ω, v) (3.70).
    W,
    /// `V.v`: the linear part v of a twist V = (ω, v) (3.70).
    V,
    /// `F.m`: the moment m of a wrench F = (m, f) (3.97).
    M,
    /// `F.f`: the force f of a wrench F = (m, f) (3.97).
    F,
}

impl Part {
    /// The part a member name names; None for `.T` and unknown names.
    pub fn of(name: &str) -> Option<Part> {
        Some(match name {
            "R" => Part::R,
            "p" => Part::P,
            "w" => Part::W,
            "v" => Part::V,
            "m" => Part::M,
            "f" => Part::F,
            _ => return None,
        })
    }

    /// The member's name, `R` of `T.R`.
    pub fn name(self) -> &'static str {
        match self {
            Part::R => "R",
            Part::P => "p",
            Part::W => "w",
            Part::V => "v",
            Part::M => "m",
            Part::F => "f",
        }
    }
}

/// An expression over symbols, holding constants of type `C`. Products are
/// kept flat so that `inv(T_ab) * T_ab` cancels to `I`.
#[derive(Debug, Clone)]
pub enum Tree<C> {
    /// A `given` name.
    Name(String),
    /// A number or matrix inside a symbolic expression, with its compact
    /// text (for printing only; constants compare by value).
    Const(Box<C>, String),
    /// The identity (what cancelled products leave), with the `given`
    /// names of the operands it cancelled from when it is all an
    /// operation left (`inv(T) * T`: T; `crate::seam::apply`), so that it
    /// is the numbers' identity once they all have numbers (§7); empty
    /// elsewhere. Identities compare equal whatever their names.
    Identity(Vec<String>),
    /// The product of two or more factors in order, `T_ab T_bc`: flat (no
    /// factor is a product or the identity), adjacent inverse pairs
    /// cancelled; built by [`Tree::product`].
    Product(Vec<Tree<C>>),
    /// `inv(X)`, the inverse X⁻¹ of one factor (products are inverted
    /// factor by factor by [`Tree::inverse`]); printed `inv(X)`.
    Inv(Box<Tree<C>>),
    /// `-x`.
    Neg(Box<Tree<C>>),
    /// `a + b`.
    Add(Box<Tree<C>>, Box<Tree<C>>),
    /// `a - b`.
    Sub(Box<Tree<C>>, Box<Tree<C>>),
    /// `a / b`.
    Div(Box<Tree<C>>, Box<Tree<C>>),
    /// `a ^ b`, base then exponent.
    Pow(Box<Tree<C>>, Box<Tree<C>>),
    /// `[x]`, the book's bracket.
    Bracket(Box<Tree<C>>),
    /// `x.T`, the transpose (pushed through products by
    /// [`Tree::transpose`]).
    Transpose(Box<Tree<C>>),
    /// `T.R`, `V.w`, …: a part of a symbolic value.
    Member(Box<Tree<C>>, Part),
    /// A builtin applied to symbolic arguments, `Ad(T_ab)`.
    Call(Fun, Vec<Tree<C>>),
    /// A matrix literal with a symbol among its entries, `[1, theta; 0, 1]`,
    /// row by row (MATLAB block concatenation, LANGUAGE.md §4).
    Block(Vec<Vec<Tree<C>>>),
    /// A vector `(a, b, c)` with a symbol among its entries.
    Vector(Vec<Tree<C>>),
    /// `x[i]`, `M[i, j]`, `M[:, j]` (1-based; `None` is `:`).
    Index(Box<Tree<C>>, Vec<Option<f64>>),
    /// `a == b`, `a ≈ b`, … of sides that cannot be compared without
    /// numbers (`given R1, R2 : SO3; R1 == R2`): a bool that waits, decided
    /// as typed first once the sides are numbers (LANGUAGE.md §7).
    Compare(crate::syntax::ast::CmpOp, Box<Tree<C>>, Box<Tree<C>>),
}

impl<C: PartialEq> PartialEq for Tree<C> {
    /// Structural equality; constants compare by value.
    fn eq(&self, other: &Tree<C>) -> bool {
        use Tree::*;
        match (self, other) {
            (Name(a), Name(b)) => a == b,
            (Const(a, _), Const(b, _)) => a == b,
            (Vector(a), Vector(b)) => a == b,
            (Index(a, i), Index(b, j)) => a == b && i == j,
            (Identity(_), Identity(_)) => true,
            (Product(a), Product(b)) => a == b,
            (Inv(a), Inv(b))
            | (Neg(a), Neg(b))
            | (Bracket(a), Bracket(b))
            | (Transpose(a), Transpose(b)) => a == b,
            (Add(a, b), Add(c, d))
            | (Sub(a, b), Sub(c, d))
            | (Div(a, b), Div(c, d))
            | (Pow(a, b), Pow(c, d)) => a == c && b == d,
            (Member(a, m), Member(b, n)) => a == b && m == n,
            (Call(f, a), Call(g, b)) => f == g && a == b,
            (Block(a), Block(b)) => a == b,
            (Compare(o, a, b), Compare(p, c, d)) => o == p && a == c && b == d,
            _ => false,
        }
    }
}

/// The largest symbolic expression kept, in nodes and in depth: beyond it
/// a statement is a domain error. Without a bound, `x = x * x + t`
/// repeated doubles the expression each time (memory and time explode),
/// and printing a very deep one would exhaust the stack.
pub const MAX_SYM_NODES: usize = 10_000;
/// The deepest symbolic expression kept (nesting levels), the other half
/// of the bound of [`MAX_SYM_NODES`].
pub const MAX_SYM_DEPTH: usize = 1_000;

impl<C> Tree<C> {
    /// The identity `I`, cancelled from no names.
    pub fn identity() -> Tree<C> {
        Tree::Identity(Vec::new())
    }
}

impl<C: Clone + PartialEq> Tree<C> {
    /// True when the expression has more than [`MAX_SYM_NODES`] nodes or is
    /// deeper than [`MAX_SYM_DEPTH`] (counted without recursion, stopping
    /// at the limit).
    pub fn too_large(&self) -> bool {
        let mut todo = vec![(self, 1)];
        let mut nodes = 0;
        while let Some((s, depth)) = todo.pop() {
            nodes += 1;
            if nodes > MAX_SYM_NODES || depth > MAX_SYM_DEPTH {
                return true;
            }
            match s {
                Tree::Name(_) | Tree::Const(..) | Tree::Identity(_) => {}
                Tree::Product(v) | Tree::Call(_, v) | Tree::Vector(v) => {
                    todo.extend(v.iter().map(|c| (c, depth + 1)))
                }
                Tree::Index(a, _) => todo.push((a, depth + 1)),
                Tree::Block(rows) => todo.extend(rows.iter().flatten().map(|c| (c, depth + 1))),
                Tree::Inv(a)
                | Tree::Neg(a)
                | Tree::Bracket(a)
                | Tree::Transpose(a)
                | Tree::Member(a, _) => todo.push((a, depth + 1)),
                Tree::Add(a, b)
                | Tree::Sub(a, b)
                | Tree::Div(a, b)
                | Tree::Pow(a, b)
                | Tree::Compare(_, a, b) => {
                    todo.push((a, depth + 1));
                    todo.push((b, depth + 1));
                }
            }
        }
        false
    }

    /// The operands of this node (none for a leaf).
    pub fn children(&self) -> Vec<&Tree<C>> {
        match self {
            Tree::Name(_) | Tree::Const(..) | Tree::Identity(_) => Vec::new(),
            Tree::Product(v) | Tree::Call(_, v) | Tree::Vector(v) => v.iter().collect(),
            Tree::Block(rows) => rows.iter().flatten().collect(),
            Tree::Inv(a)
            | Tree::Neg(a)
            | Tree::Bracket(a)
            | Tree::Transpose(a)
            | Tree::Member(a, _)
            | Tree::Index(a, _) => vec![a],
            Tree::Add(a, b)
            | Tree::Sub(a, b)
            | Tree::Div(a, b)
            | Tree::Pow(a, b)
            | Tree::Compare(_, a, b) => vec![a, b],
        }
    }

    /// Whether `f` holds for some node of the tree (this one or below).
    pub fn any(&self, f: &mut impl FnMut(&Tree<C>) -> bool) -> bool {
        let mut todo = vec![self];
        while let Some(t) = todo.pop() {
            if f(t) {
                return true;
            }
            todo.extend(t.children());
        }
        false
    }

    /// The inverse, pushed through products: inv(A B) = inv(B) inv(A).
    pub fn inverse(self) -> Tree<C> {
        match self {
            Tree::Inv(x) => *x,
            Tree::Identity(ns) => Tree::Identity(ns),
            Tree::Product(fs) => Tree::product(fs.into_iter().rev().map(Tree::inverse).collect()),
            other => Tree::Inv(Box::new(other)),
        }
    }

    /// The transpose, pushed through products: (A B)ᵀ = Bᵀ Aᵀ, so that the
    /// power (Ad(T_ab) V_b)ᵀ Ad(inv(T_ab))ᵀ F_b simplifies to V_bᵀ F_b
    /// (3.98); (Aᵀ)ᵀ = A and Iᵀ = I.
    pub fn transpose(self) -> Tree<C> {
        match self {
            Tree::Transpose(x) => *x,
            Tree::Identity(ns) => Tree::Identity(ns),
            Tree::Product(fs) => Tree::product(fs.into_iter().rev().map(Tree::transpose).collect()),
            other => Tree::Transpose(Box::new(other)),
        }
    }

    /// `a b`, flattened and simplified.
    pub fn times(a: Tree<C>, b: Tree<C>) -> Tree<C> {
        Tree::product(vec![a, b])
    }

    /// A simplified product: nested products flattened, identities dropped,
    /// adjacent `X inv(X)` pairs cancelled.
    pub fn product(factors: Vec<Tree<C>>) -> Tree<C> {
        let mut out: Vec<Tree<C>> = Vec::new();
        let mut stack: Vec<Tree<C>> = factors.into_iter().rev().collect();
        while let Some(f) = stack.pop() {
            match f {
                Tree::Product(inner) => stack.extend(inner.into_iter().rev()),
                Tree::Identity(_) => {}
                f => {
                    if out.last().is_some_and(|last| last.cancels(&f)) {
                        out.pop();
                    } else {
                        out.push(f);
                    }
                }
            }
        }
        match out.len() {
            0 => Tree::identity(),
            1 => out.pop().unwrap_or_else(Tree::identity),
            _ => Tree::Product(out),
        }
    }

    /// True when `self other` is the identity: `X inv(X)`, `Ad(X) Ad(inv(X))`
    /// ([Ad_T]⁻¹ = [Ad_T⁻¹], §3.3.2), and their transposes.
    fn cancels(&self, other: &Tree<C>) -> bool {
        let inverse_pair = |a: &Tree<C>, b: &Tree<C>| match (a, b) {
            (Tree::Inv(x), y) | (y, Tree::Inv(x)) => **x == *y,
            _ => false,
        };
        match (self, other) {
            (Tree::Call(f, a), Tree::Call(g, b))
                if f.role == Role::Adjoint
                    && g.role == Role::Adjoint
                    && a.len() == 1
                    && b.len() == 1 =>
            {
                inverse_pair(&a[0], &b[0])
            }
            (Tree::Transpose(a), Tree::Transpose(b)) => a.cancels(b),
            (a, b) => inverse_pair(a, b),
        }
    }

    fn needs_parens_in_product(&self) -> bool {
        match self {
            // a symbolic sum among the factors, `exp([S] (t1 + t2)) T_sb`
            Tree::Const(_, text) => {
                !wrapped(text) && (text.contains(" + ") || text.contains(" - "))
            }
            _ => matches!(
                self,
                Tree::Add(..) | Tree::Sub(..) | Tree::Neg(_) | Tree::Div(..)
            ),
        }
    }
}

/// True when the text is one bracket, `(…)` or `[…]`, from its first
/// character to its last.
fn wrapped(text: &str) -> bool {
    let mut depth = 0usize;
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return i + c.len_utf8() == text.len();
                }
            }
            _ if depth == 0 => return false,
            _ => {}
        }
    }
    false
}

impl<C: Clone + PartialEq> fmt::Display for Tree<C> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tree::Name(n) => write!(f, "{n}"),
            Tree::Const(_, text) => write!(f, "{text}"),
            Tree::Identity(_) => write!(f, "I"),
            Tree::Product(fs) => {
                for (i, x) in fs.iter().enumerate() {
                    if i > 0 {
                        write!(f, " ")?;
                    }
                    if x.needs_parens_in_product() {
                        write!(f, "({x})")?;
                    } else {
                        write!(f, "{x}")?;
                    }
                }
                Ok(())
            }
            Tree::Inv(x) => write!(f, "inv({x})"),
            Tree::Neg(x) => match **x {
                Tree::Add(..) | Tree::Sub(..) => write!(f, "-({x})"),
                _ => write!(f, "-{x}"),
            },
            Tree::Add(a, b) => write!(f, "{a} + {b}"),
            Tree::Sub(a, b) => match **b {
                Tree::Add(..) | Tree::Sub(..) => write!(f, "{a} - ({b})"),
                _ => write!(f, "{a} - {b}"),
            },
            Tree::Div(a, b) => {
                let wrap =
                    |s: &Tree<C>| matches!(s, Tree::Add(..) | Tree::Sub(..) | Tree::Product(_));
                let (l, r) = (a.to_string(), b.to_string());
                let l = if wrap(a) { format!("({l})") } else { l };
                let r = if wrap(b) || matches!(**b, Tree::Div(..)) {
                    format!("({r})")
                } else {
                    r
                };
                write!(f, "{l}/{r}")
            }
            Tree::Pow(a, b) => {
                // (a sum, product or fraction in the exponent, or a signed
                // or fractional base, is parenthesized: `2^(2 + x)` read
                // back is not `2^2 + x`)
                let plain = |t: &Tree<C>| match t {
                    Tree::Name(_) | Tree::Call(..) => true,
                    Tree::Const(_, text) => {
                        !text.is_empty()
                            && text
                                .chars()
                                .all(|c| c.is_alphanumeric() || c == '_' || c == '.')
                    }
                    _ => false,
                };
                let (l, r) = (a.to_string(), b.to_string());
                let l = if plain(a) && !matches!(**a, Tree::Call(..)) {
                    l
                } else {
                    format!("({l})")
                };
                let r = if plain(b) { r } else { format!("({r})") };
                write!(f, "{l}^{r}")
            }
            Tree::Bracket(x) => write!(f, "[{x}]"),
            Tree::Transpose(x) => match **x {
                Tree::Name(_) | Tree::Call(..) | Tree::Bracket(_) | Tree::Block(_) => {
                    write!(f, "{x}.T")
                }
                _ => write!(f, "({x}).T"),
            },
            Tree::Member(x, m) => match **x {
                Tree::Name(_) | Tree::Call(..) => write!(f, "{x}.{}", m.name()),
                _ => write!(f, "({x}).{}", m.name()),
            },
            Tree::Block(rows) => {
                let rows: Vec<String> = rows
                    .iter()
                    .map(|r| r.iter().map(Tree::to_string).collect::<Vec<_>>().join(", "))
                    .collect();
                write!(f, "[{}]", rows.join("; "))
            }
            Tree::Vector(xs) => {
                let xs: Vec<String> = xs.iter().map(Tree::to_string).collect();
                write!(f, "({})", xs.join(", "))
            }
            Tree::Index(x, sels) => {
                let sels: Vec<String> = sels
                    .iter()
                    .map(|s| s.map_or(":".to_string(), |i| i.to_string()))
                    .collect();
                match **x {
                    Tree::Name(_) | Tree::Call(..) => write!(f, "{x}[{}]", sels.join(", ")),
                    _ => write!(f, "({x})[{}]", sels.join(", ")),
                }
            }
            Tree::Compare(op, a, b) => write!(f, "{a} {} {b}", op.text()),
            Tree::Call(fun, args) => {
                write!(f, "{}(", fun.name)?;
                for (i, a) in args.iter().enumerate() {
                    if i > 0 {
                        write!(f, ", ")?;
                    }
                    write!(f, "{a}")?;
                }
                write!(f, ")")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type Sym = Tree<()>;

    const AD: Fun = Fun {
        name: "Ad",
        role: Role::Adjoint,
    };

    fn n(s: &str) -> Sym {
        Sym::Name(s.into())
    }

    #[test]
    fn inverse_pairs_cancel() {
        let e = Sym::times(n("T_ab").inverse(), n("T_ab"));
        assert_eq!(e.to_string(), "I");
        let chain = Sym::product(vec![n("T_ab"), n("T_bc"), n("T_cd")]);
        assert_eq!(chain.to_string(), "T_ab T_bc T_cd");
    }

    #[test]
    fn adjoints_of_inverse_pairs_cancel() {
        let ad = |x: Sym| Sym::Call(AD, vec![x]);
        let e = Sym::product(vec![ad(n("T_sb").inverse()), ad(n("T_sb")), n("V_b")]);
        assert_eq!(e.to_string(), "V_b");
        let t = |x: Sym| Sym::Transpose(Box::new(x));
        let e = Sym::product(vec![t(ad(n("T_ab").inverse())), t(ad(n("T_ab"))), n("F_a")]);
        assert_eq!(e.to_string(), "F_a");
    }

    #[test]
    fn transpose_of_product_reverses_and_cancels() {
        let ad = |x: Sym| Sym::Call(AD, vec![x]);
        // Power invariance (3.98): V_aᵀF_a with V_a = Ad(T_ab) V_b and
        // F_a = Ad(T_ba)ᵀ F_b.
        let v_a = Sym::times(ad(n("T_ab")), n("V_b"));
        let f_a = Sym::times(ad(n("T_ab").inverse()).transpose(), n("F_b"));
        let power = Sym::times(v_a.transpose(), f_a);
        assert_eq!(power.to_string(), "V_b.T F_b");
        assert_eq!(n("R").transpose().transpose(), n("R"));
        assert_eq!(Sym::identity().transpose().to_string(), "I");
    }

    #[test]
    fn inverse_of_product_reverses_and_cancels() {
        // Example 3.2: inv(T_ad T_db T_bc) T_ad T_de = inv(T_bc) inv(T_db) T_de
        let p = Sym::product(vec![n("T_ad"), n("T_db"), n("T_bc")]).inverse();
        let e = Sym::product(vec![p, n("T_ad"), n("T_de")]);
        assert_eq!(e.to_string(), "inv(T_bc) inv(T_db) T_de");
    }
}
