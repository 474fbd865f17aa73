//! `explain EXPR` (LANGUAGE.md §14): the book's steps for a value. The
//! statement evaluates EXPR as a bare expression would; this module then
//! reads which algorithm made the value (the call at the top of EXPR, a
//! product of framed factors, a mechanism) and asks [`crate::lie::steps`]
//! for that algorithm's steps on the same inputs. The last step's value is
//! the statement's value itself.
//!
//! Submodules: `chain` (frame chains: which subscripts cancel, in
//! order), `symbolic` (closed forms over symbols, Prop. 3.16),
//! `calculus` (twists from Ṫ, (3.69)–(3.75); `diff` node by node).

mod calculus;
mod chain;
mod symbolic;

use chain::inverse_of as chain_inverse;

use super::interp::{Interp, Typed};
use super::value::Value;
use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::steps::orient::Euler;
use crate::lie::steps::{self, Quantity, Step};
use crate::lie::{LieGroup, Mat3, Mat4, SE3, SO3, Vec3, Vec6};
use crate::syntax::ast::{Expr, ExprKind};

/// One step as the front ends show it: [`Step`] with its value as a
/// language value (and, in a frame chain, the frames it maps).
#[derive(Debug, Clone)]
pub struct Shown {
    /// The book's equation (`"3.54"`), proposition, definition or section.
    pub reference: &'static str,
    /// The stable name (LANGUAGE.md §14: `trace`, `theta`, `omega_hat`, …).
    pub name: String,
    /// The formula in Unicode.
    pub text: String,
    /// The formula in LaTeX.
    pub latex: String,
    /// Which formula chasles used instead of the book's and why.
    pub note: Option<String>,
    /// This case's value.
    pub value: Value,
    /// The frames of the value (`["a", "b"]` for {a}←{b}), in a chain.
    pub frames: Vec<String>,
}

impl Shown {
    /// A step computed here (not recorded by `lie::steps`): no note, no
    /// frames.
    fn new(
        reference: &'static str,
        name: &str,
        text: String,
        latex: String,
        value: Value,
    ) -> Shown {
        Shown {
            reference,
            name: name.to_string(),
            text,
            latex,
            note: None,
            value,
            frames: Vec::new(),
        }
    }

    fn of(s: Step) -> Shown {
        Shown {
            reference: s.reference,
            name: s.name.to_string(),
            text: s.text,
            latex: s.latex,
            note: s.note,
            value: quantity(&s.value),
            frames: Vec::new(),
        }
    }
}

/// A step's quantity as a value of the kind the book calls it.
fn quantity(q: &Quantity) -> Value {
    match q {
        Quantity::Scalar(x) => Value::scalar(*x),
        Quantity::Vector3(v) => Value::num(Kind::Vector(Some(3)), v),
        Quantity::Vector4(v) => Value::num(Kind::Vector(Some(4)), v),
        Quantity::Vector6(v) => Value::num(Kind::Vector(Some(6)), v),
        Quantity::Wrench(v) => Value::num(Kind::Wrench, v),
        Quantity::Screw(v) => Value::num(Kind::Screw, v),
        Quantity::Rotation(m) => Value::of(Kind::SO3, *m),
        Quantity::So3(m) => Value::of(Kind::So3, *m),
        Quantity::Matrix3(m) => Value::of(Kind::Matrix(Some(3), Some(3)), *m),
        Quantity::Transform(m) => Value::of(Kind::SE3, *m),
        Quantity::Se3(m) => Value::of(Kind::Se3, *m),
        Quantity::Adjoint(m) => Value::num(Kind::Adjoint { transposed: false }, m),
        Quantity::Matrix6(m) => Value::num(Kind::Matrix(Some(6), Some(6)), m),
        Quantity::Case(c) => Value::Str((*c).into()),
    }
}

/// What `explain` covers, for its refusal and `:help explain`.
pub const COVERS: &str = "explain covers log / MatrixLog3 / MatrixLog6 (§3.2.3.3, §3.3.3.2), exp / MatrixExp3 / \
     MatrixExp6 (3.51, Prop. 3.16), inv / RotInv / TransInv (3.64), Ad (Def. 3.6), ScrewToAxis / screw / \
     screw_params (§3.3.2.2), Ad(T_ab).T * F_a (3.99), euler_zyx / euler_zxz / rpy / quat / cayley, \
     products of framed values (the subscript cancellation rule), twists from Ṫ (inv(T) Ṫ, Ṫ inv(T), \
     (3.69)–(3.75)), diff (the rule at each node), mechanisms (Grübler, (2.4)) and exp of a screw \
     axis times a symbol (Prop. 3.16)";

/// Numbers of a value as a fixed 3-vector, 6-vector, 3×3 or 4×4 matrix.
fn mat<const R: usize, const C: usize>(v: &Value) -> Option<nalgebra::SMatrix<f64, R, C>> {
    match v {
        Value::Num { m, .. } if m.shape() == (R, C) => Some(
            nalgebra::SMatrix::<f64, R, C>::from_column_slice(m.as_slice()),
        ),
        _ => None,
    }
}

/// A rotation as the builtins read it: projected when it is only near
/// SO(3) (LANGUAGE.md §5).
fn rotation(v: &Value) -> Option<Mat3> {
    let m = mat::<3, 3>(v)?;
    Some(if SO3::distance(&m) <= 1e-9 {
        m
    } else {
        *SO3::project(&m).matrix()
    })
}

/// A transform as the builtins read it (see [`rotation`]).
fn transform(v: &Value) -> Option<Mat4> {
    let m = mat::<4, 4>(v)?;
    Some(if SE3::distance(&m) <= 1e-9 {
        m
    } else {
        *SE3::project(&m).matrix()
    })
}

/// An SE(2) matrix (by its kind, or a 3×3 that is not a rotation and
/// reads as one as `log` reads it, LANGUAGE.md §5) embedded in SE(3), as Example 3.4 does.
fn planar(v: &Value) -> Option<Mat4> {
    let m = mat::<3, 3>(v)?;
    let read = || {
        let Value::Num { m, .. } = v else {
            return false;
        };
        crate::values::convert::read_3x3(m).0 == crate::values::convert::Group::SE2
    };
    if !(v.kind() == Kind::SE2 || (v.kind() != Kind::SO3 && read())) {
        return None;
    }
    let mut t = Mat4::identity();
    t[(0, 0)] = m[(0, 0)];
    t[(0, 1)] = m[(0, 1)];
    t[(1, 0)] = m[(1, 0)];
    t[(1, 1)] = m[(1, 1)];
    t[(0, 3)] = m[(0, 2)];
    t[(1, 3)] = m[(1, 2)];
    Some(t)
}

/// Whether a 3×3 block is skew-symmetric (to rounding): an element of so(3).
fn skew(m: &Mat3) -> bool {
    (m + m.transpose()).amax() <= 1e-12 * m.amax().max(1.0)
}

/// A 3-vector or the vee of an so(3) matrix (exponential coordinates);
/// None for a 3×3 matrix that is not in so(3) (its exp is not (3.51)).
fn expc3(v: &Value) -> Option<Vec3> {
    mat::<3, 1>(v).or_else(|| {
        mat::<3, 3>(v)
            .filter(skew)
            .map(|m| crate::lie::so3::vee(&m))
    })
}

/// A 6-vector or the vee of an se(3) matrix; None for a 4×4 matrix that
/// is not in se(3) (its exp is not Prop. 3.16).
fn expc6(v: &Value) -> Option<Vec6> {
    mat::<6, 1>(v).or_else(|| {
        mat::<4, 4>(v)
            .filter(|m| {
                skew(&m.fixed_view::<3, 3>(0, 0).into_owned()) && (0..4).all(|j| m[(3, j)] == 0.0)
            })
            .map(|m| crate::lie::se3::vee(&m))
    })
}

impl Interp<'_> {
    /// The steps of `explain e`, whose value (already computed) is `t`.
    pub(super) fn explain(&mut self, e: &Expr, t: &Typed) -> Result<Vec<Shown>, Diagnostic> {
        let Some(value) = t.value() else {
            // Checking, no numbers: what has no algorithm by its shape
            // alone is refused as `run` refuses it (`check` reports every
            // error it can decide, LANGUAGE.md §1).
            return match no_algorithm_by_shape(e, t) {
                true => Err(refusal(e)),
                false => Ok(Vec::new()),
            };
        };
        let mut steps = match self.steps_of(e, value)? {
            Some(s) => s,
            None => return Err(refusal(e)),
        };
        // A tuple's parts are the last steps (q, ŝ, h; the angles): the
        // tuple itself is the last step.
        if let Value::Tuple(parts) = value {
            let reference = steps.last().map_or("3.6", |s| s.reference);
            let same = steps.last().and_then(|s| numbers(&s.value)) == numbers(value)
                && steps
                    .last()
                    .is_some_and(|s| !matches!(s.value, Value::Tuple(_)));
            if !same || parts.len() == 3 && steps.last().is_some_and(|s| s.name == "h") {
                steps.push(Shown {
                    reference,
                    name: "value".to_string(),
                    text: "the result, part by part".to_string(),
                    latex: String::new(),
                    note: None,
                    value: value.clone(),
                    frames: Vec::new(),
                });
            }
        }
        // The last step is the value itself (LANGUAGE.md §14).
        if let Some(last) = steps.last_mut() {
            let shape = |v: &Value| v.as_matrix().map(|m| m.shape());
            if shape(&last.value) == shape(value) && !same_numbers(&last.value, value) {
                last.note = Some(
                    "chasles computes this value from the exact form of the input (its closed \
                     form), so it may differ in the last digits from the floating-point steps above"
                        .to_string(),
                );
            }
            last.value = value.clone();
            if last.frames.is_empty() {
                last.frames = t.ty.frames.to_list();
            }
        }
        Ok(steps)
    }

    /// The steps of the algorithm that computes `e`, None when no
    /// algorithm of the book is at its top.
    fn steps_of(&mut self, e: &Expr, value: &Value) -> Result<Option<Vec<Shown>>, Diagnostic> {
        if let Value::Mech(m) = value {
            let mut steps = mechanism(m);
            steps.push(Shown {
                reference: "2.2",
                name: "mechanism".to_string(),
                text: format!(
                    "the mechanism: joints {}, {}",
                    m.joints_text(),
                    m.space().name()
                ),
                latex: r"\text{the mechanism}".to_string(),
                note: None,
                value: value.clone(),
                frames: Vec::new(),
            });
            return Ok(Some(steps));
        }
        if let Some(call) = self.euler_call(e) {
            return self.steps_of(&call, value); // e^x is exp(x) (§4)
        }
        match &e.kind {
            ExprKind::Paren(items) if items.len() == 1 => self.steps_of(&items[0], value),
            ExprKind::Call { func, args } => {
                let Some(b) = crate::builtins::lookup(&func.name) else {
                    return Ok(None);
                };
                if b.name == "diff" {
                    return self.diff_steps(args);
                }
                if has_symbols(value) {
                    return match args.first() {
                        Some(a) => self.symbolic_steps(b.name, a, value),
                        None => Ok(None),
                    };
                }
                let exprs = args;
                let args = self.quiet_values(exprs)?;
                if let (true, Some(Value::Mech(m))) = (b.name == "dof", args.first()) {
                    return Ok(Some(mechanism(m)));
                }
                if args.iter().any(has_symbols) {
                    return Ok(None);
                }
                Ok(call_steps(b.name, &args).map(|s| s.into_iter().map(Shown::of).collect()))
            }
            ExprKind::Binary { .. } => match self.twist_steps(e, value) {
                Some(steps) => Ok(Some(steps)),
                None => self.chain_steps(e),
            },
            _ => Ok(None),
        }
    }

    /// The values of `args`, evaluated again without repeating their
    /// warnings (the statement has reported them once).
    fn quiet_values(&mut self, args: &[Expr]) -> Result<Vec<Value>, Diagnostic> {
        let warned = self.warnings.len();
        let units = self.env.units_noted.len();
        let mut out = Vec::with_capacity(args.len());
        for a in args {
            let t = self.expr(a);
            match t {
                Ok(t) => out.push(t.value().cloned().unwrap_or(Value::Bool(false))),
                Err(e) => {
                    self.warnings.truncate(warned);
                    return Err(e);
                }
            }
        }
        self.warnings.truncate(warned);
        self.env.units_noted.truncate(units);
        Ok(out)
    }
}

/// The block `rows × cols` of a numeric or symbolic matrix, as `kind`.
pub(super) fn block(
    v: &Value,
    rows: std::ops::Range<usize>,
    cols: std::ops::Range<usize>,
    kind: Kind,
) -> Option<Value> {
    match v {
        Value::Num { m, .. } => {
            let d = m.to_dmatrix();
            let b = d.view((rows.start, cols.start), (rows.len(), cols.len()));
            Some(Value::num(kind, &b))
        }
        Value::Formula { m, .. } => Some(super::formula::make(&kind, m.block(rows, cols))),
        _ => None,
    }
}

/// Whether a value holds symbols (a symbolic name or a formula).
fn has_symbols(v: &Value) -> bool {
    match v {
        Value::Sym(_) | Value::Formula { .. } => true,
        Value::Tuple(vs) => vs.iter().any(has_symbols),
        _ => false,
    }
}

/// The numbers of a value in order (a tuple's parts one after another).
fn numbers(v: &Value) -> Option<Vec<f64>> {
    match v {
        Value::Num { m, .. } => Some(m.as_slice().to_vec()),
        Value::Tuple(vs) => {
            let mut out = Vec::new();
            for x in vs {
                out.extend(numbers(x)?);
            }
            Some(out)
        }
        _ => None,
    }
}

/// Whether two values hold the same numbers bit for bit.
fn same_numbers(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Num { m: x, .. }, Value::Num { m: y, .. }) => {
            x.shape() == y.shape()
                && x.as_slice()
                    .iter()
                    .zip(y.as_slice())
                    .all(|(p, q)| p.to_bits() == q.to_bits() || (*p == 0.0 && *q == 0.0))
        }
        (Value::Tuple(x), Value::Tuple(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same_numbers(p, q))
        }
        _ => a == b,
    }
}

/// Whether `e` has no book algorithm whatever its numbers: at its top (in
/// parentheses) neither a builtin's call nor an operator (`explain x`,
/// `explain 2`, `explain -R`, `explain f(1)` of a user function), and not
/// a mechanism ([`Interp::steps_of`] finds no steps for it, whatever the
/// values).
fn no_algorithm_by_shape(e: &Expr, t: &Typed) -> bool {
    let mut top = e;
    while let ExprKind::Paren(items) = &top.kind
        && items.len() == 1
    {
        top = &items[0];
    }
    let algorithm = match &top.kind {
        ExprKind::Call { func, .. } => crate::builtins::lookup(&func.name).is_some(),
        ExprKind::Binary { .. } => true,
        _ => false,
    };
    !algorithm && t.ty.kind != Kind::Mechanism && t.ty.kind != Kind::Function
}

/// The error for an expression with no book algorithm at its top.
fn refusal(e: &Expr) -> Diagnostic {
    let what = match &e.kind {
        ExprKind::Var(n) => format!(
            "'{n}' is a name: explain shows how an expression is computed, not a stored value"
        ),
        _ => "explain has no book algorithm for this expression".to_string(),
    };
    Diagnostic::error(ErrorKind::Type, e.span, what).with_help(COVERS)
}

/// The steps of a builtin call on numbers, by the builtin's name.
fn call_steps(name: &str, args: &[Value]) -> Option<Vec<Step>> {
    let a0 = args.first()?;
    let half = half_turn(a0);
    Some(match name {
        "log" => {
            if let Some(t) = a0
                .as_matrix()
                .filter(|m| m.shape() == (4, 4))
                .and(transform(a0))
            {
                steps::log::log6(&t, half.as_ref())
            } else if let Some(t) = planar(a0) {
                let mut out = vec![Step::new(
                    "3.3.3.2",
                    "T",
                    "SE(2) as SE(3): [R, p; 0, 1] with R = Rot(ẑ, φ), p = (x, y, 0) (Example 3.4)",
                    r"T = \begin{bmatrix} R & p \\ 0 & 1 \end{bmatrix}",
                    Quantity::Transform(t),
                )];
                out.extend(steps::log::log6(&t, None));
                if let Some(last) = out.last_mut() {
                    last.name = "se2";
                    last.text =
                        "log T = [S]θ, read back in the plane: [[ω]θ, (vθ)ₓᵧ; 0, 0] (Example 3.4)"
                            .into();
                }
                out
            } else {
                steps::log::log3(&rotation(a0)?, half.as_ref())
            }
        }
        "MatrixLog3" => steps::log::matrix_log3(&rotation(a0)?, half.as_ref()),
        "MatrixLog6" => steps::log::matrix_log6(&transform(a0)?, half.as_ref()),
        "exp" | "MatrixExp3" | "MatrixExp6" => match a0.as_matrix()?.shape() {
            (3, 3) | (3, 1) if name != "MatrixExp6" => steps::exp::exp3(&expc3(a0)?),
            (4, 4) | (6, 1) if name != "MatrixExp3" => steps::exp::exp6(&expc6(a0)?),
            _ => return None,
        },
        "inv" | "RotInv" | "TransInv" => match a0.as_matrix()?.shape() {
            (3, 3) if a0.kind() == Kind::SO3 || name == "RotInv" => {
                steps::motion::inv3(&rotation(a0)?)
            }
            (4, 4) if a0.kind() == Kind::SE3 || name == "TransInv" => {
                steps::motion::inv6(&transform(a0)?)
            }
            _ => return None,
        },
        "Adjoint" => steps::motion::adjoint(&transform(a0)?),
        "Rot" => {
            let (axis, theta) = (mat::<3, 1>(a0)?, args.get(1)?.as_scalar()?);
            let n = axis.norm();
            if !(n > 0.0 && n.is_finite()) {
                return None;
            }
            steps::exp::exp3(&(axis * (theta / n)))
        }
        // (h = ±∞ is the pure translation (0, ±ŝ), for both)
        "ScrewToAxis" | "screw" => {
            let (q, s, h) = (
                mat::<3, 1>(a0)?,
                mat::<3, 1>(args.get(1)?)?,
                args.get(2)?.as_scalar()?,
            );
            let n = s.norm();
            if n == 0.0 || !n.is_finite() {
                return None;
            }
            steps::motion::screw_axis(&q, &(s / n), h)
        }
        "screw_params" => steps::motion::screw_params(&mat::<6, 1>(a0)?),
        "euler_zyx" => euler(a0, Euler::Zyx)?,
        "euler_zxz" => euler(a0, Euler::Zxz)?,
        "rpy" => euler(a0, Euler::Rpy)?,
        "quat" => steps::orient::quat(&rotation(a0)?),
        "cayley" => steps::orient::cayley(&rotation(a0)?),
        _ => return None,
    })
}

/// The steps of an Euler-type extraction (App. B) with gimbal lock decided
/// as the builtin decides it (by the rotation's exact form or certified
/// entries near the lock), so the steps end at the builtin's angles.
fn euler(a0: &Value, which: Euler) -> Option<Vec<Step>> {
    let r = rotation(a0)?;
    let pair = match which {
        Euler::Zxz => [(0, 2), (1, 2)],
        Euler::Zyx | Euler::Rpy => [(0, 0), (1, 0)],
    };
    let entries =
        || crate::values::exact_mat::exact_entries(a0).or_else(|| crate::decide::turn::entries(a0));
    Some(match crate::builtins::gimbal_reading(&r, pair, entries) {
        Some((x, lock)) => steps::orient::euler(&x, which, Some(lock)),
        None => steps::orient::euler(&r, which, None),
    })
}

/// The θ = π decision of a logarithm's argument as the builtins take it
/// (`Args::half_turn`): by its exact form, else by certified arithmetic on
/// its recipe (Rotz(π − 1e-12) Roty(π − 1e-12) is θ = π − 1e-24, not π),
/// so the steps take the case and the sign of ω̂ the value took.
fn half_turn(v: &Value) -> Option<crate::lie::so3::HalfTurn> {
    crate::values::exact_mat::half_turn(v).or_else(|| crate::decide::turn::half_turn(v))
}

/// Grübler's formula (2.4) with this mechanism's counts.
fn mechanism(m: &crate::mech::Mechanism) -> Vec<Shown> {
    let int = |x: i64| Value::scalar(x as f64);
    let mut out = vec![
        Shown::new(
            "2.4",
            "m",
            format!(
                "m = {} (a {} rigid body's freedoms)",
                m.m(),
                m.space().name()
            ),
            format!(r"m = {}", m.m()),
            int(m.m()),
        ),
        Shown::new(
            "2.4",
            "N",
            "N = the number of links, ground included".into(),
            "N".into(),
            int(m.links()),
        ),
        Shown::new(
            "2.4",
            "J",
            format!("J = the number of joints ({})", m.joints_text()),
            "J".into(),
            int(m.joint_count()),
        ),
        Shown::new(
            "Table 2.1",
            "f_i",
            "Σ fᵢ = the freedoms of the joints (Table 2.1)".into(),
            r"\sum_i f_i".into(),
            int(m.sum_f()),
        ),
    ];
    let mut dof = Shown::new(
        "2.4",
        "dof",
        m.formula(),
        r"\text{dof} = m(N - 1 - J) + \sum_{i=1}^J f_i".into(),
        int(m.dof()),
    );
    let notes = m.notes();
    if !notes.is_empty() {
        dof.note = Some(notes.join("; "));
    }
    out.push(dof);
    out
}
