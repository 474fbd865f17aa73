//! Symbolic expressions over `given` names (LANGUAGE.md §7): products of
//! transforms simplify (inverse pairs and identities cancel) and print as
//! the book writes them, `T_ab T_bc T_cd`.

use std::fmt;

use super::value::Value;

/// An expression over symbols. Products are kept flat so that
/// `inv(T_ab) * T_ab` cancels to `I`.
#[derive(Debug, Clone)]
pub enum Sym {
    /// A `given` name.
    Name(String),
    /// A number or matrix inside a symbolic expression, printed compactly.
    Const(Box<Value>, String),
    /// The identity (what cancelled products leave).
    Identity,
    Product(Vec<Sym>),
    Inv(Box<Sym>),
    Neg(Box<Sym>),
    Add(Box<Sym>, Box<Sym>),
    Sub(Box<Sym>, Box<Sym>),
    Div(Box<Sym>, Box<Sym>),
    Pow(Box<Sym>, Box<Sym>),
    /// `[x]`, the book's bracket.
    Bracket(Box<Sym>),
    Transpose(Box<Sym>),
    Member(Box<Sym>, String),
    Call(String, Vec<Sym>),
    /// A matrix literal with a symbol among its entries, `[1, theta; 0, 1]`,
    /// row by row (MATLAB block concatenation, LANGUAGE.md §4).
    Block(Vec<Vec<Sym>>),
}

impl PartialEq for Sym {
    /// Structural equality; constants compare by their printed text.
    fn eq(&self, other: &Sym) -> bool {
        use Sym::*;
        match (self, other) {
            (Name(a), Name(b)) => a == b,
            (Const(_, a), Const(_, b)) => a == b,
            (Identity, Identity) => true,
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
            _ => false,
        }
    }
}

/// The largest symbolic expression kept, in nodes and in depth: beyond it
/// a statement is a domain error. Without a bound, `x = x * x + t`
/// repeated doubles the expression each time (memory and time explode),
/// and printing a very deep one would exhaust the stack.
pub const MAX_SYM_NODES: usize = 10_000;
pub const MAX_SYM_DEPTH: usize = 1_000;

impl Sym {
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
                Sym::Name(_) | Sym::Const(..) | Sym::Identity => {}
                Sym::Product(v) | Sym::Call(_, v) => todo.extend(v.iter().map(|c| (c, depth + 1))),
                Sym::Block(rows) => todo.extend(rows.iter().flatten().map(|c| (c, depth + 1))),
                Sym::Inv(a)
                | Sym::Neg(a)
                | Sym::Bracket(a)
                | Sym::Transpose(a)
                | Sym::Member(a, _) => todo.push((a, depth + 1)),
                Sym::Add(a, b) | Sym::Sub(a, b) | Sym::Div(a, b) | Sym::Pow(a, b) => {
                    todo.push((a, depth + 1));
                    todo.push((b, depth + 1));
                }
            }
        }
        false
    }

    /// The inverse, pushed through products: inv(A B) = inv(B) inv(A).
    pub fn inverse(self) -> Sym {
        match self {
            Sym::Inv(x) => *x,
            Sym::Identity => Sym::Identity,
            Sym::Product(fs) => Sym::product(fs.into_iter().rev().map(Sym::inverse).collect()),
            other => Sym::Inv(Box::new(other)),
        }
    }

    /// The transpose, pushed through products: (A B)ᵀ = Bᵀ Aᵀ, so that the
    /// power (Ad(T_ab) V_b)ᵀ Ad(inv(T_ab))ᵀ F_b simplifies to V_bᵀ F_b
    /// (3.98); (Aᵀ)ᵀ = A and Iᵀ = I.
    pub fn transpose(self) -> Sym {
        match self {
            Sym::Transpose(x) => *x,
            Sym::Identity => Sym::Identity,
            Sym::Product(fs) => Sym::product(fs.into_iter().rev().map(Sym::transpose).collect()),
            other => Sym::Transpose(Box::new(other)),
        }
    }

    /// `a b`, flattened and simplified.
    pub fn times(a: Sym, b: Sym) -> Sym {
        Sym::product(vec![a, b])
    }

    /// A simplified product: nested products flattened, identities dropped,
    /// adjacent `X inv(X)` pairs cancelled.
    pub fn product(factors: Vec<Sym>) -> Sym {
        let mut out: Vec<Sym> = Vec::new();
        let mut stack: Vec<Sym> = factors.into_iter().rev().collect();
        while let Some(f) = stack.pop() {
            match f {
                Sym::Product(inner) => stack.extend(inner.into_iter().rev()),
                Sym::Identity => {}
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
            0 => Sym::Identity,
            1 => out.pop().unwrap_or(Sym::Identity),
            _ => Sym::Product(out),
        }
    }

    /// True when `self other` is the identity: `X inv(X)`, `Ad(X) Ad(inv(X))`
    /// ([Ad_T]⁻¹ = [Ad_T⁻¹], §3.3.2), and their transposes.
    fn cancels(&self, other: &Sym) -> bool {
        let inverse_pair = |a: &Sym, b: &Sym| match (a, b) {
            (Sym::Inv(x), y) | (y, Sym::Inv(x)) => **x == *y,
            _ => false,
        };
        match (self, other) {
            (Sym::Call(f, a), Sym::Call(g, b))
                if is_adjoint(f) && is_adjoint(g) && a.len() == 1 && b.len() == 1 =>
            {
                inverse_pair(&a[0], &b[0])
            }
            (Sym::Transpose(a), Sym::Transpose(b)) => a.cancels(b),
            (a, b) => inverse_pair(a, b),
        }
    }

    fn needs_parens_in_product(&self) -> bool {
        matches!(
            self,
            Sym::Add(..) | Sym::Sub(..) | Sym::Neg(_) | Sym::Div(..)
        )
    }
}

fn is_adjoint(name: &str) -> bool {
    matches!(name, "Ad" | "Adjoint" | "adjoint")
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Sym::Name(n) => write!(f, "{n}"),
            Sym::Const(_, text) => write!(f, "{text}"),
            Sym::Identity => write!(f, "I"),
            Sym::Product(fs) => {
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
            Sym::Inv(x) => write!(f, "inv({x})"),
            Sym::Neg(x) => match **x {
                Sym::Add(..) | Sym::Sub(..) => write!(f, "-({x})"),
                _ => write!(f, "-{x}"),
            },
            Sym::Add(a, b) => write!(f, "{a} + {b}"),
            Sym::Sub(a, b) => match **b {
                Sym::Add(..) | Sym::Sub(..) => write!(f, "{a} - ({b})"),
                _ => write!(f, "{a} - {b}"),
            },
            Sym::Div(a, b) => {
                let wrap = |s: &Sym| matches!(s, Sym::Add(..) | Sym::Sub(..) | Sym::Product(_));
                let (l, r) = (a.to_string(), b.to_string());
                let l = if wrap(a) { format!("({l})") } else { l };
                let r = if wrap(b) || matches!(**b, Sym::Div(..)) {
                    format!("({r})")
                } else {
                    r
                };
                write!(f, "{l}/{r}")
            }
            Sym::Pow(a, b) => match **a {
                Sym::Name(_) | Sym::Const(..) => write!(f, "{a}^{b}"),
                _ => write!(f, "({a})^{b}"),
            },
            Sym::Bracket(x) => write!(f, "[{x}]"),
            Sym::Transpose(x) => match **x {
                Sym::Name(_) | Sym::Call(..) | Sym::Bracket(_) | Sym::Block(_) => {
                    write!(f, "{x}.T")
                }
                _ => write!(f, "({x}).T"),
            },
            Sym::Member(x, m) => match **x {
                Sym::Name(_) | Sym::Call(..) => write!(f, "{x}.{m}"),
                _ => write!(f, "({x}).{m}"),
            },
            Sym::Block(rows) => {
                let rows: Vec<String> = rows
                    .iter()
                    .map(|r| r.iter().map(Sym::to_string).collect::<Vec<_>>().join(", "))
                    .collect();
                write!(f, "[{}]", rows.join("; "))
            }
            Sym::Call(name, args) => {
                write!(f, "{name}(")?;
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
        let ad = |x: Sym| Sym::Call("Ad".into(), vec![x]);
        let e = Sym::product(vec![ad(n("T_sb").inverse()), ad(n("T_sb")), n("V_b")]);
        assert_eq!(e.to_string(), "V_b");
        let t = |x: Sym| Sym::Transpose(Box::new(x));
        let e = Sym::product(vec![t(ad(n("T_ab").inverse())), t(ad(n("T_ab"))), n("F_a")]);
        assert_eq!(e.to_string(), "F_a");
    }

    #[test]
    fn transpose_of_product_reverses_and_cancels() {
        let ad = |x: Sym| Sym::Call("Ad".into(), vec![x]);
        // Power invariance (3.98): V_aᵀF_a with V_a = Ad(T_ab) V_b and
        // F_a = Ad(T_ba)ᵀ F_b.
        let v_a = Sym::times(ad(n("T_ab")), n("V_b"));
        let f_a = Sym::times(ad(n("T_ab").inverse()).transpose(), n("F_b"));
        let power = Sym::times(v_a.transpose(), f_a);
        assert_eq!(power.to_string(), "V_b.T F_b");
        assert_eq!(n("R").transpose().transpose(), n("R"));
        assert_eq!(Sym::Identity.transpose().to_string(), "I");
    }

    #[test]
    fn inverse_of_product_reverses_and_cancels() {
        // Example 3.2: inv(T_ad T_db T_bc) T_ad T_de = inv(T_bc) inv(T_db) T_de
        let p = Sym::product(vec![n("T_ad"), n("T_db"), n("T_bc")]).inverse();
        let e = Sym::product(vec![p, n("T_ad"), n("T_de")]);
        assert_eq!(e.to_string(), "inv(T_bc) inv(T_db) T_de");
    }
}
