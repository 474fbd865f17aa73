//! The derivatives of the inverse maps of a rotation by their rates:
//! Euler angles (ZYX, ZXZ), roll–pitch–yaw, the unit quaternion and the
//! Cayley–Rodrigues parameters (§3.3.2 and Appendix B). Their closed forms
//! over symbols hold on a branch (`sym::branch`: `sin(u) > 0`, angles in
//! (−π, π]); the derivative of the closed form, read at numbers off that
//! branch, is the other branch's formula evaluated where it does not hold
//! (`diff(euler_zxz(Rotx(u)), u)` at u = −1 printed (0, 1, 0); the angles
//! there are (π, 1, π) = (π, −u, π), so the derivative is (0, −1, 0)).
//! The rates below are right on every branch: each is computed from the
//! angles the numbers give (the map replayed, as typed first) and the
//! angular velocity of R,
//!
//!   ω_s = so3ToVec(Ṙ Rᵀ) (3.48),   ω_b = so3ToVec(Rᵀ Ṙ) (3.49),
//!
//! with ω_s = M(angles) (ȧ, ḃ, ċ) for the Euler angles (M's columns the
//! joint axes in the fixed frame), q̇ = ½ q ⊗ (0, ω_b) for the
//! quaternion, and ṙ = (q̇_v q_w − q_v q̇_w)/q_w² for r = q_v/q_w. At
//! gimbal lock M is singular and the rate is refused with the inverse's
//! error, as there is no derivative there.

use std::rc::Rc;

use super::build::{arith, matrix, node_k, number};
use crate::check::ty::Kind;
use crate::syntax::ast::BinOp;
use crate::values::ops::Sel;
use crate::values::recipe::{Operation, Recipe, Step};

const V3: Kind = Kind::Vector(Some(3));
const M3: Kind = Kind::Matrix(Some(3), Some(3));

/// The rate of `name(R)` (`map` the recipe of that call, `dr` of Ṙ), or
/// None for a map not covered here.
pub(super) fn of(
    name: &str,
    map: &Rc<Recipe>,
    rot: &Rc<Recipe>,
    dr: Rc<Recipe>,
) -> Option<Rc<Recipe>> {
    let unit = |i: usize| {
        let mut e = [0.0; 3];
        e[i] = 1.0;
        matrix(3, 1, &e, V3)
    };
    let (x, y, z) = (unit(0), unit(1), unit(2));
    let angle = |i: usize| index(map, &[i]);
    let columns = match name {
        // R = Rz(a) Ry(b) Rx(c): ω_s = ẑ ȧ + Rz(a) ŷ ḃ + Rz(a) Ry(b) x̂ ċ
        "euler_zyx" => {
            let rz = rot_about("Rotz", angle(1)?)?;
            let rzy = arith(BinOp::Mul, rz.clone(), rot_about("Roty", angle(2)?)?)?;
            [z, arith(BinOp::Mul, rz, y)?, arith(BinOp::Mul, rzy, x)?]
        }
        // R = Rz(a) Rx(b) Rz(c): ω_s = ẑ ȧ + Rz(a) x̂ ḃ + Rz(a) Rx(b) ẑ ċ
        "euler_zxz" => {
            let rz = rot_about("Rotz", angle(1)?)?;
            let rzx = arith(BinOp::Mul, rz.clone(), rot_about("Rotx", angle(2)?)?)?;
            [
                z.clone(),
                arith(BinOp::Mul, rz, x)?,
                arith(BinOp::Mul, rzx, z)?,
            ]
        }
        // (roll, pitch, yaw), R = Rz(yaw) Ry(pitch) Rx(roll)
        "rpy" => {
            let rz = rot_about("Rotz", angle(3)?)?;
            let rzy = arith(BinOp::Mul, rz.clone(), rot_about("Roty", angle(2)?)?)?;
            [arith(BinOp::Mul, rzy, x)?, arith(BinOp::Mul, rz, y)?, z]
        }
        "quat" => return quat_rate(map, rot, dr),
        "cayley" => {
            let q = node_k(
                Step::Op(Operation::Call("quat")),
                vec![rot.clone()],
                Kind::Vector(Some(4)),
            )?;
            let dq = quat_rate(&q, rot, dr)?;
            let (w, dw) = (index(&q, &[1])?, index(&dq, &[1])?);
            let v =
                |q: &Rc<Recipe>| vector((2..=4).map(|i| index(q, &[i])).collect::<Option<_>>()?);
            let top = arith(
                BinOp::Sub,
                arith(BinOp::Mul, v(&dq)?, w.clone())?,
                arith(BinOp::Mul, v(&q)?, dw)?,
            )?;
            return arith(BinOp::Div, top, arith(BinOp::Pow, w, number(2.0))?);
        }
        _ => return None,
    };
    let m = node_k(
        Step::Op(Operation::Block(Box::new([3]))),
        columns.to_vec(),
        M3,
    )?;
    let m_inv = node_k(Step::Op(Operation::Call("inv")), vec![m], M3)?;
    let rt = node_k(Step::Op(Operation::Transpose), vec![rot.clone()], M3)?;
    arith(BinOp::Mul, m_inv, unskew(arith(BinOp::Mul, dr, rt)?)?)
}

/// q̇ = ½ q ⊗ (0, ω_b), ω_b = so3ToVec(Rᵀ Ṙ), for q the quaternion of R
/// as the numbers give it (either sign: both satisfy it).
fn quat_rate(q: &Rc<Recipe>, rot: &Rc<Recipe>, dr: Rc<Recipe>) -> Option<Rc<Recipe>> {
    let rt = node_k(Step::Op(Operation::Transpose), vec![rot.clone()], M3)?;
    let wb = unskew(arith(BinOp::Mul, rt, dr)?)?;
    let mut parts = vec![number(0.0)];
    for i in 1..=3 {
        parts.push(index(&wb, &[i])?);
    }
    let pure = vector(parts)?;
    let prod = node_k(
        Step::Op(Operation::Call("quat_mul")),
        vec![q.clone(), pure],
        Kind::Vector(Some(4)),
    )?;
    arith(BinOp::Mul, number(0.5), prod)
}

/// The vector of a skew-symmetric [ω] read from its entries
/// (ω₁ = W₃₂, ω₂ = W₁₃, ω₃ = W₂₁), so that a product of rotations whose
/// floats are skew only to rounding is read, not refused.
fn unskew(w: Rc<Recipe>) -> Option<Rc<Recipe>> {
    vector(vec![
        index(&w, &[3, 2])?,
        index(&w, &[1, 3])?,
        index(&w, &[2, 1])?,
    ])
}

/// `Rotx(θ)`, `Roty(θ)` or `Rotz(θ)`.
fn rot_about(name: &'static str, angle: Rc<Recipe>) -> Option<Rc<Recipe>> {
    node_k(Step::Op(Operation::Call(name)), vec![angle], Kind::SO3)
}

/// `x[i]` or `x[i, j]` (1-based), a scalar.
fn index(x: &Rc<Recipe>, at: &[usize]) -> Option<Rc<Recipe>> {
    let sels = at.iter().map(|i| Sel::At(*i as f64)).collect();
    node_k(
        Step::Op(Operation::Index(sels)),
        vec![x.clone()],
        Kind::Scalar,
    )
}

/// `(x₁, …, xₙ)` of scalars.
fn vector(xs: Vec<Rc<Recipe>>) -> Option<Rc<Recipe>> {
    let n = xs.len();
    node_k(Step::Op(Operation::Vector), xs, Kind::Vector(Some(n)))
}

/// d det(M) = Σ_j det(M with its column j replaced by dM's): Jacobi's
/// formula, as n determinants of matrices of numbers once they are bound
/// (the expanded derivative of a determinant of large entries cancels in
/// floats: diff(det([-2, -3, E; …]), b) with E a 15th power was right to 9
/// digits only, matrix differential seed 821460).
pub(super) fn det(m: &Rc<Recipe>, dm: &Rc<Recipe>, n: usize) -> Option<Rc<Recipe>> {
    if !(2..=6).contains(&n) {
        return None;
    }
    let column = |x: &Rc<Recipe>, j: usize| {
        node_k(
            Step::Op(Operation::Index(Box::new([Sel::All, Sel::At(j as f64)]))),
            vec![x.clone()],
            Kind::Vector(Some(n)),
        )
    };
    let mut sum: Option<Rc<Recipe>> = None;
    for j in 1..=n {
        let columns = (1..=n)
            .map(|k| column(if k == j { dm } else { m }, k))
            .collect::<Option<Vec<_>>>()?;
        let mj = node_k(
            Step::Op(Operation::Block(Box::new([n]))),
            columns,
            Kind::Matrix(Some(n), Some(n)),
        )?;
        let d = node_k(Step::Op(Operation::Call("det")), vec![mj], Kind::Scalar)?;
        sum = Some(match sum {
            None => d,
            Some(s) => arith(BinOp::Add, s, d)?,
        });
    }
    sum
}
