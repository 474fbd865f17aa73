//! The book's transform written as a block over symbols, `[R, p; 0, 1]`
//! with R in SO(3) (3.62), and its algebra in closed form: the inverse
//! (3.64) T⁻¹ = `[Rᵀ, -Rᵀ p; 0, 1]`, the product (3.63 applied twice)
//! `[R₁, p₁; 0, 1] [R₂, p₂; 0, 1]` = `[R₁R₂, R₁p₂ + p₁; 0, 1]`, and the
//! parts `T.R` = R, `T.p` = p. So `inv(T) T` is `I` (RᵀR = I for the
//! rotation block, Rᵀp − Rᵀp = 0).

use super::apply::{Op, to_sym};
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::symbolic::Part;
use crate::values::value::{Sym, Value};

/// The other factor of a product over symbols whose one factor is a
/// numeric identity matrix (`T_ab * T_bc` with `T_bc = eye(4)` is `T_ab`,
/// §7: printed simplified, as `inv(T_ab) * T_ab` is `I`); not when the
/// other factor may be a scalar (`det(T) * eye(3)` is a matrix). The
/// operands with their checked kinds.
pub(crate) fn identity_factor(op: BinOp, a: (&Value, &Kind), b: (&Value, &Kind)) -> Option<Value> {
    let identity = |v: &Value| match v {
        Value::Num { m, .. } => m.shape().0 >= 2 && m.is_identity(0.0),
        _ => false,
    };
    if op != BinOp::Mul {
        return None;
    }
    [(a, b), (b, a)]
        .into_iter()
        .find(|((i, _), (o, k))| matches!(o, Value::Sym(_)) && !k.maybe_scalar() && identity(i))
        .map(|(_, (o, _))| o.clone())
}

/// Operation `op` on `args` (its result typed `kind`) in closed form over
/// transform blocks: the inverse of a block typed SE(3) (`inv(T)`,
/// `T^-1`), the product of two typed SE(3), a block times a point. None
/// for any other operation or operand.
pub(super) fn of_op(op: Op, args: &[&Value], kind: &Kind) -> Option<Sym> {
    let inverse = match (op, args) {
        (Op::Inverse, [_]) => true,
        // (the book's own name for it, 3.6: `TransInv`)
        (Op::Call(b, _), [_]) => matches!(b.name, "inv" | "TransInv"),
        (Op::Arith(BinOp::Pow), [_, e]) => e.as_scalar() == Some(-1.0),
        _ => false,
    };
    match (kind, args) {
        (Kind::SE3, [Value::Sym(s), ..]) if inverse => inverse_of(s),
        (Kind::SE3, [Value::Sym(a), Value::Sym(b)]) if matches!(op, Op::Arith(BinOp::Mul)) => {
            product(a, b)
        }
        (Kind::Vector(Some(3)), [Value::Sym(a), q]) if matches!(op, Op::Arith(BinOp::Mul)) => {
            point(a, &to_sym(q))
        }
        (Kind::SO3 | Kind::SO2, [Value::Sym(a), Value::Sym(b)])
            if matches!(op, Op::Arith(BinOp::Mul)) =>
        {
            rotations(a, b)
        }
        _ => None,
    }
}

/// The product `a b` of two rotations (typed SO(3) or SO(2), so each
/// factor of either is one) with `Xᵀ X` and `X Xᵀ` cancelled where they
/// meet: Rᵀ = R⁻¹ (Prop. 3.3), so `R R^T` prints `I` as `R inv(R)` does.
/// None when nothing cancels (the product is formed as usual).
fn rotations(a: &Sym, b: &Sym) -> Option<Sym> {
    let factors = |s: &Sym| match s {
        Sym::Product(fs) => fs.clone(),
        Sym::Identity(_) => Vec::new(),
        other => vec![other.clone()],
    };
    let (mut left, right) = (factors(a), factors(b));
    let mut right = right.into_iter().peekable();
    let mut cancelled = false;
    while let (Some(x), Some(y)) = (left.last(), right.peek()) {
        let transposes = |x: &Sym, y: &Sym| matches!(x, Sym::Transpose(i) if **i == *y);
        if !(transposes(x, y) || transposes(y, x)) {
            break;
        }
        left.pop();
        right.next();
        cancelled = true;
    }
    cancelled.then(|| Sym::product(left.into_iter().chain(right).collect()))
}

/// Whether `s` is the constant number `x` (the literal `0` or `1` of a
/// transform's last row).
fn is_const(s: &Sym, x: f64) -> bool {
    matches!(s, Sym::Const(v, _) if v.as_scalar() == Some(x))
}

/// The blocks R and p and the last row of `[R, p; 0, 1]` (or `[R, p; 0,
/// 0, 0, 1]`); None for any other shape.
fn parts(s: &Sym) -> Option<(&Sym, &Sym, &Vec<Sym>)> {
    let Sym::Block(rows) = s else { return None };
    let [top, bottom] = rows.as_slice() else {
        return None;
    };
    let [r, p] = top.as_slice() else { return None };
    match bottom.as_slice() {
        [z, o] if is_const(z, 0.0) && is_const(o, 1.0) => {}
        [a, b, c, o]
            if is_const(a, 0.0) && is_const(b, 0.0) && is_const(c, 0.0) && is_const(o, 1.0) => {}
        _ => return None,
    }
    Some((r, p, bottom))
}

/// The inverse (3.64) of `[R, p; 0, 1]` (or `[R, p; 0, 0, 0, 1]`), given
/// that the checker typed it a transform in SE(3), so that R is a rotation
/// and Rᵀ = R⁻¹ (3.57): `[Rᵀ, -Rᵀ p; 0, 1]`. None for any other shape.
pub fn inverse_of(s: &Sym) -> Option<Sym> {
    let (r, p, last) = parts(s)?;
    let rt = r.clone().transpose();
    // (−Rᵀ p of an inverse's p = −R'ᵀ p₀ is p₀: inv(inv(T)) is T)
    let moved = match sign(p) {
        (neg, Sym::Product(fs))
            if fs
                .first()
                .is_some_and(|first| inverse_rotations(&rt, first)) =>
        {
            signed(!neg, Sym::product(fs[1..].to_vec()))
        }
        _ => Sym::times(Sym::Neg(Box::new(rt.clone())), p.clone()),
    };
    Some(Sym::Block(vec![vec![rt, moved], last.clone()]))
}

/// `T.R` or `T.p` of the block `[R, p; 0, 1]`: the block itself (3.62).
pub(super) fn member(s: &Sym, part: Part) -> Option<Sym> {
    let (r, p, _) = parts(s)?;
    match part {
        Part::R => Some(r.clone()),
        Part::P => Some(p.clone()),
        _ => None,
    }
}

/// The zero vector, as the block `0` is written.
fn zero() -> Sym {
    Sym::Const(Box::new(Value::scalar(0.0)), "0".into())
}

/// (true, x) for −x, written `-x` or `(-X) y …` (the inverse's −Rᵀp);
/// (false, s) otherwise.
fn sign(s: &Sym) -> (bool, Sym) {
    match s {
        Sym::Neg(x) => (true, (**x).clone()),
        Sym::Product(fs) => match fs.split_first() {
            Some((Sym::Neg(x), rest)) => {
                let mut all = vec![(**x).clone()];
                all.extend(rest.iter().cloned());
                (true, Sym::product(all))
            }
            _ => (false, s.clone()),
        },
        _ => (false, s.clone()),
    }
}

fn signed(neg: bool, s: Sym) -> Sym {
    if is_const(&s, 0.0) || !neg {
        s
    } else {
        Sym::Neg(Box::new(s))
    }
}

/// True when `a b` is I for the rotation blocks a and b: one is the
/// other's transpose or inverse (the blocks are whole rotations, 3.57; a
/// factor of one need not be).
fn inverse_rotations(a: &Sym, b: &Sym) -> bool {
    a.clone().transpose() == *b || b.clone().transpose() == *a || a.clone().inverse() == *b
}

/// R v for the rotation block R: v's leading Rᵀ (or R⁻¹) cancels.
fn rotate(r: &Sym, v: &Sym) -> Sym {
    let (neg, v) = sign(v);
    if is_const(&v, 0.0) {
        return zero();
    }
    if let Sym::Product(fs) = &v
        && let Some((first, rest)) = fs.split_first()
        && inverse_rotations(r, first)
    {
        return signed(neg, Sym::product(rest.to_vec()));
    }
    if matches!(r, Sym::Identity(_)) {
        return signed(neg, v);
    }
    signed(neg, Sym::times(r.clone(), v))
}

/// a + b, with x + (−x) = 0 and 0 + x = x.
fn plus(a: Sym, b: &Sym) -> Sym {
    if is_const(&a, 0.0) {
        return b.clone();
    }
    if is_const(b, 0.0) {
        return a;
    }
    let ((na, xa), (nb, xb)) = (sign(&a), sign(b));
    if na != nb && xa == xb {
        return zero();
    }
    Sym::Add(Box::new(a), Box::new(b.clone()))
}

/// `[A, p; 0, 1] q` = `A q + p`, the point transform (3.2.1's T·q in
/// homogeneous coordinates, true for any block A: no cancellation).
/// None when `a` is not such a block or `q` is itself a block.
fn point(a: &Sym, q: &Sym) -> Option<Sym> {
    let (r, p, _) = parts(a)?;
    if matches!(q, Sym::Block(_)) {
        return None;
    }
    Some(plus(Sym::times(r.clone(), q.clone()), p))
}

/// `[R₁, p₁; 0, 1] [R₂, p₂; 0, 1]` = `[R₁R₂, R₁p₂ + p₁; 0, 1]`, given that
/// the checker typed the product a transform in SE(3) (so both factors
/// are, and R₁, R₂ are rotations); `I` when that is the identity. None
/// when either factor is not such a block.
fn product(a: &Sym, b: &Sym) -> Option<Sym> {
    let (r1, p1, last) = parts(a)?;
    let (r2, p2, _) = parts(b)?;
    let r = if inverse_rotations(r1, r2) {
        Sym::identity()
    } else {
        Sym::times(r1.clone(), r2.clone())
    };
    let p = plus(rotate(r1, p2), p1);
    if matches!(r, Sym::Identity(_)) && is_const(&p, 0.0) {
        return Some(Sym::identity());
    }
    Some(Sym::Block(vec![vec![r, p], last.clone()]))
}

/// Why a builtin defined on SE(3) only (`Ad`, `TransInv`, `MatrixLog6`,
/// `TransToRp`, `displacement`: Definition 3.6, (3.64), §3.3.3.2) refuses
/// a symbolic argument that is not known to be a transform: a 4×4 whose
/// top-left block is not known to be a rotation (`[2 R, p; 0, 1]`), where
/// numbers bound later would be a domain error. Given the call's name as
/// typed, its arguments and their checked kinds: the argument's index
/// and the message, or None when every such argument is a transform, a
/// number or a formula (checked when the call runs, or when its numbers
/// are bound), or not a 4×4.
fn unproven_transform(
    b: &crate::builtins::Builtin,
    called: &str,
    vals: &[Value],
    tys: &[crate::check::ty::Ty],
) -> Option<(usize, String)> {
    use crate::builtins::{Param, Typing};
    let wants = |i: usize| match (&b.typing, b.name) {
        (Typing::Fixed { params, .. }, _) => params.get(i) == Some(&Param::Trans),
        (_, "TransToRp") => i == 0,
        (_, "displacement") => true,
        _ => false,
    };
    let four = |k: &Kind| matches!(k, Kind::Matrix(Some(4), Some(4)));
    vals.iter().zip(tys).enumerate().find_map(|(i, (v, t))| {
        let k = &t.kind;
        // (a formula, numbers with symbols among them, waits for them: its
        // kind is decided from its entries, and its Ad is the arithmetic
        // of Definition 3.6 on them, trusting nothing; with numbers bound
        // later the call is checked as if typed first)
        let unproven = matches!(v, Value::Sym(_)) && four(k);
        (wants(i) && unproven).then(|| {
            (
                i,
                format!(
                    "{} takes a transform in SE(3), and this 4×4 matrix is not known to be one: its top-left block is not known to be a rotation",
                    called
                ),
            )
        })
    })
}

/// `unproven_transform` (above) as the call's domain error, at the argument
/// (`args`, the call's typed arguments with `tys` their checked types;
/// `span` the call's), with the fix as help: state the transform, or
/// build it from a rotation (§3.3.1, (3.62)).
pub fn known(
    b: &crate::builtins::Builtin,
    called: &str,
    vals: &[Value],
    tys: &[crate::check::ty::Ty],
    args: &[crate::syntax::ast::Expr],
    span: crate::syntax::ast::Span,
) -> Result<(), crate::diagnostics::Diagnostic> {
    use crate::diagnostics::{Diagnostic, ErrorKind};
    // (only a symbolic argument can be refused: numbers, the common case,
    // are checked when the call runs)
    if !vals.iter().any(|v| matches!(v, Value::Sym(_))) {
        return Ok(());
    }
    match unproven_transform(b, called, vals, tys) {
        None => Ok(()),
        Some((i, message)) => {
            let at = args.get(i).map_or(span, |a| a.span);
            Err(Diagnostic::error(ErrorKind::Domain, at, message).with_help(
                "state that it is one: `given T : SE3`, or build it as the block `[R, p; 0, 1]` with `given R : SO3` and `given p : vec3`",
            ))
        }
    }
}

/// `s`, the result of an operation on `args`, with the `given` names of
/// the operands when it is all they cancelled to, the identity
/// (`inv(T) * T`, `R^T R`): it is then the numbers' identity once those
/// names all have numbers, as typed first (LANGUAGE.md §7;
/// `crate::calculus::substitute::current`). Any other result as it is.
pub(super) fn cancelled(s: Sym, args: &[&Value]) -> Sym {
    if !matches!(&s, Sym::Identity(ns) if ns.is_empty()) {
        return s;
    }
    let mut names: Vec<String> = Vec::new();
    let mut add = |n: String| {
        if n != "deg" && !names.contains(&n) {
            names.push(n);
        }
    };
    let formula = |v: &Value, add: &mut dyn FnMut(String)| {
        if let Value::Formula { m, .. } = v {
            let mut syms = Vec::new();
            m.data.iter().for_each(|e| e.symbols(&mut syms));
            syms.iter()
                .for_each(|s| add(s.name.to_string() + &"'".repeat(usize::from(s.dots))));
        }
    };
    for a in args {
        match a {
            Value::Sym(t) => {
                t.any(&mut |node| {
                    match node {
                        Sym::Name(n) => add(n.clone()),
                        Sym::Identity(ns) => ns.iter().for_each(|n| add(n.clone())),
                        Sym::Const(v, _) => formula(v, &mut add),
                        _ => {}
                    }
                    false
                });
            }
            v => formula(v, &mut add),
        }
    }
    Sym::Identity(names)
}
