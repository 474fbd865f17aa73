//! Arguments of a builtin call at run time: typed accessors that read a
//! value as a 3-vector, a rotation, a transform…, with errors pointing at
//! the argument and warnings for projected near-group matrices.

use nalgebra::{DMatrix, DVector};

use crate::values::num::Num;

use crate::check::ty::Kind;
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::lie::{LieGroup, Mat2, Mat3, Mat4, SE2, SE3, SO2, SO3, Vec3, Vec4, Vec6, so3};
use crate::mech::Mechanism;
use crate::syntax::ast::Span;
use crate::values::convert::{Group, Membership};
use crate::values::domain::Decided;
use crate::values::exact::Exact;
use crate::values::exact_mat::{Entries, membership};
use crate::values::value::Value;

/// A static argument error: which argument (None: the whole call), the
/// error kind and the message. The interpreter adds the span and signature.
#[derive(Debug, Clone)]
pub struct ArgError {
    /// The 0-based argument at fault; None for the call as a whole.
    pub arg: Option<usize>,
    /// The kind of error (usually a type error).
    pub kind: ErrorKind,
    /// The message a user sees.
    pub message: String,
}

impl ArgError {
    /// A type error about argument `i`.
    pub fn type_of(i: usize, message: impl Into<String>) -> ArgError {
        ArgError {
            arg: Some(i),
            kind: ErrorKind::Type,
            message: message.into(),
        }
    }
}

/// Where each argument of a call stands in the text, for its messages:
/// held inline for up to four arguments, so that a call allocates nothing
/// for them (most builtins take one or two).
#[derive(Debug, Clone, Default)]
pub struct Spans {
    len: usize,
    first: [Span; 4],
    rest: Vec<Span>,
}

impl Spans {
    /// `n` arguments standing at one `span` (a tuple argument spread
    /// into its parts).
    pub fn repeat(span: Span, n: usize) -> Spans {
        let first = [span; 4];
        Spans {
            len: n,
            first,
            rest: vec![span; n.saturating_sub(first.len())],
        }
    }

    /// Where argument `i` stands, if the call has one.
    pub fn get(&self, i: usize) -> Option<Span> {
        if i >= self.len {
            None
        } else if i < self.first.len() {
            Some(self.first[i])
        } else {
            self.rest.get(i - self.first.len()).copied()
        }
    }
}

impl FromIterator<Span> for Spans {
    fn from_iter<I: IntoIterator<Item = Span>>(iter: I) -> Spans {
        let mut spans = Spans::default();
        for span in iter {
            match spans.first.get_mut(spans.len) {
                Some(slot) => *slot = span,
                None => spans.rest.push(span),
            }
            spans.len += 1;
        }
        spans
    }
}

/// The evaluated arguments of one call.
pub struct Args<'a> {
    /// The builtin's book name ([`super::Builtin::name`]), for messages.
    pub name: &'static str,
    /// Its signature, shown as help under an argument error.
    pub signature: &'static str,
    /// The argument values in order.
    pub vals: Vec<Value>,
    /// Where each argument stands in the text.
    pub spans: Spans,
    /// The whole call, for errors about no one argument.
    pub call_span: Span,
    /// Where warnings go (a near-group matrix projected, a conditioning
    /// note), shown with the result.
    pub warnings: &'a mut Vec<Diagnostic>,
    /// Each argument's static kind and frames, and its source text (what
    /// `draw` labels and frames a picture with); empty where unknown.
    pub typed: Vec<(crate::check::ty::Ty, String)>,
    /// The θ = π decision of a logarithm by certified arithmetic on a
    /// rotation's recipe, where it has no exact form (the evaluator's,
    /// `decide::turn`, which `builtins` cannot name); None: by its floats.
    pub certified_turn: Option<fn(&Value) -> Option<so3::HalfTurn>>,
    /// A matrix's entries by certified arithmetic on its recipe, where it
    /// has no exact form (`decide::turn::entries`); None: by its floats.
    pub certified_entries: Option<fn(&Value) -> Option<Entries>>,
}

impl Args<'_> {
    /// How many arguments the call has.
    pub fn len(&self) -> usize {
        self.vals.len()
    }
    /// True for a call with no arguments, `f()`.
    pub fn is_empty(&self) -> bool {
        self.vals.is_empty()
    }

    fn span(&self, i: usize) -> Span {
        self.spans.get(i).unwrap_or(self.call_span)
    }

    /// An error of `kind` pointing at argument `i`.
    pub fn error(&self, i: usize, kind: ErrorKind, message: impl Into<String>) -> Diagnostic {
        Diagnostic::error(kind, self.span(i), message)
            .with_help(format!("signature: {}", self.signature))
    }

    /// A domain error about the whole call.
    pub fn domain(&self, message: impl Into<String>) -> Diagnostic {
        Diagnostic::error(ErrorKind::Domain, self.call_span, message)
    }

    fn wrong(&self, i: usize, want: &str) -> Diagnostic {
        let found = self.vals.get(i).map_or(Kind::Unknown, Value::kind);
        self.error(
            i,
            ErrorKind::Type,
            format!(
                "argument {} of {} must be {}, not {}",
                i + 1,
                self.name,
                article(want),
                found.a()
            ),
        )
    }

    /// The value of argument `i`.
    pub fn value(&self, i: usize) -> &Value {
        &self.vals[i]
    }

    /// Argument `i` as a number.
    pub fn scalar(&self, i: usize) -> Result<f64, Diagnostic> {
        self.vals[i]
            .as_scalar()
            .ok_or_else(|| self.wrong(i, "scalar"))
    }

    /// Argument `i` as a number to decide on: by its exact form when it
    /// has one ([`Decided`]: `sqrt`, `acos`, the poles of `tan`, `atan2`,
    /// `log` and sizes decide by it, never by a float far from it).
    pub fn decided(&self, i: usize) -> Result<Decided, Diagnostic> {
        Decided::of(&self.vals[i]).ok_or_else(|| self.wrong(i, "scalar"))
    }

    /// Argument `i` as a whole number in `lo..=hi` (decided by its exact
    /// form when it has one: `zeros(sqrt(2)^2, 1)` is 2 by 1).
    pub fn int(&self, i: usize, lo: i64, hi: i64) -> Result<i64, Diagnostic> {
        let x = self.decided(i)?.value();
        if x.fract() != 0.0 || !x.is_finite() || x < lo as f64 || x > hi as f64 {
            return Err(self.error(
                i,
                ErrorKind::Domain,
                format!("expected a whole number from {lo} to {hi}, got {x}"),
            ));
        }
        Ok(x as i64)
    }

    /// Argument `i` as a matrix of any shape.
    pub fn mat(&self, i: usize) -> Result<&Num, Diagnostic> {
        self.vals[i]
            .as_matrix()
            .ok_or_else(|| self.wrong(i, "matrix"))
    }

    /// Argument `i` as a square matrix.
    pub fn square(&self, i: usize) -> Result<&Num, Diagnostic> {
        let m = self.mat(i)?;
        if !m.is_square() {
            return Err(self.error(
                i,
                ErrorKind::Type,
                format!(
                    "{} needs a square matrix, not {}×{}",
                    self.name,
                    m.nrows(),
                    m.ncols()
                ),
            ));
        }
        Ok(m)
    }

    /// Argument `i` as a column vector of any length; one whose floats
    /// are all within rounding of 0 is read at the floats nearest its
    /// exact entries when it has an exact form (the zero vector exactly:
    /// `(0.1 + 0.2, 0, 0) − (0.3, 0, 0)` is (5.6e-17, 0, 0) in floats, and
    /// a zero axis, angle or direction is decided by 0, not by 5.6e-17).
    pub fn vec(&self, i: usize) -> Result<DVector<f64>, Diagnostic> {
        let m = self.mat(i)?;
        if m.ncols() != 1 {
            return Err(self.wrong(i, "vector"));
        }
        Ok(match self.small(i) {
            Some(x) => DVector::from_vec(x),
            None => DVector::from_column_slice(m.as_slice()),
        })
    }

    /// The floats nearest the exact entries of argument `i` when its
    /// floats are all within rounding of 0 and it has an exact form
    /// ([`crate::values::exact_mat::small_entries`]).
    fn small(&self, i: usize) -> Option<Vec<f64>> {
        crate::values::exact_mat::small_entries(self.vals.get(i)?)
    }

    fn vec_n(&self, i: usize, n: usize) -> Result<DVector<f64>, Diagnostic> {
        let v = self
            .vec(i)
            .map_err(|_| self.wrong(i, &format!("{n}-vector")))?;
        if v.len() != n {
            return Err(self.wrong(i, &format!("{n}-vector")));
        }
        Ok(v)
    }

    /// Argument `i` as a 3-vector (ω, v, p, ω̂θ), read as [`Args::vec`] does.
    pub fn vec3(&self, i: usize) -> Result<Vec3, Diagnostic> {
        match self.vals[i].as_matrix() {
            Some(Num::V3(v)) => Ok(self.small(i).map_or(*v, |x| Vec3::from_column_slice(&x))),
            _ => Ok(Vec3::from_iterator(self.vec_n(i, 3)?.iter().copied())),
        }
    }
    /// Argument `i` as a 4-vector (a quaternion).
    pub fn vec4(&self, i: usize) -> Result<Vec4, Diagnostic> {
        match self.vals[i].as_matrix() {
            Some(Num::V4(v)) => Ok(*v),
            _ => Ok(Vec4::from_iterator(self.vec_n(i, 4)?.iter().copied())),
        }
    }
    /// Argument `i` as a 6-vector (a twist, screw axis or wrench), read as
    /// [`Args::vec`] does.
    pub fn vec6(&self, i: usize) -> Result<Vec6, Diagnostic> {
        match self.vals[i].as_matrix() {
            Some(Num::V6(v)) => Ok(self.small(i).map_or(*v, |x| Vec6::from_column_slice(&x))),
            _ => Ok(Vec6::from_iterator(self.vec_n(i, 6)?.iter().copied())),
        }
    }

    /// Argument `i` read as an element of `group`: projected with a warning
    /// when close, a domain error with the distance when not.
    pub fn group(&mut self, i: usize, group: Group) -> Result<Num, Diagnostic> {
        let n = group.size();
        let m = self.mat(i).map_err(|_| self.wrong(i, group.name()))?;
        if m.nrows() != n || m.ncols() != n {
            return Err(self.wrong(i, group.name()));
        }
        if matches!(&self.vals[i], Value::Num { kind, .. } if *kind == group.kind()) {
            return Ok(m.clone());
        }
        let span = self.span(i);
        let m = m.clone();
        let exact = match &self.vals[i] {
            Value::Num { exact, .. } => exact.clone(),
            _ => Default::default(),
        };
        read_group(&m, &exact, group, span, self.warnings)
    }

    /// `MatrixLog3` of argument `i` read as a rotation (§3.2.3.3): at θ
    /// within rounding of π, the branch is decided by R's exact form when
    /// it has one (θ = π exactly when tr R = −1; else the skew part's sign).
    pub fn so3_log(&mut self, i: usize) -> Result<Vec3, Diagnostic> {
        let r = self.so3(i)?;
        Ok(match self.half_turn(i) {
            Some(d) => so3::log_decided(r.matrix(), &d),
            None => r.log(),
        })
    }

    /// `MatrixLog6` of argument `i` read as a transform (§3.3.3.2), the
    /// rotation's branch decided as in [`Args::so3_log`].
    pub fn se3_log(&mut self, i: usize) -> Result<Vec6, Diagnostic> {
        let t = self.se3(i)?;
        Ok(match self.half_turn(i) {
            Some(d) => crate::lie::se3::log_decided(t.matrix(), &d),
            None => t.log(),
        })
    }

    /// The entries of argument `i` as decisions read them: by its exact
    /// form, else by certified arithmetic on its recipe
    /// ([`Args::certified_entries`]); None for a float.
    pub fn entries(&self, i: usize) -> Option<Entries> {
        let v = self.vals.get(i)?;
        crate::values::exact_mat::exact_entries(v).or_else(|| self.certified_entries?(v))
    }

    /// The θ = π decision of argument `i`'s logarithm by its exact form
    /// ([`crate::values::exact_mat::half_turn`]), when it was read as it
    /// is (not projected: the exact form is of the matrix as given); else
    /// by certified arithmetic on its recipe ([`Args::certified_turn`]).
    pub fn half_turn(&self, i: usize) -> Option<so3::HalfTurn> {
        let v = self.vals.get(i)?;
        // (both ways start by asking whether the floats are near a half
        // turn: asked once here, as almost every logarithm is not)
        if !crate::values::exact_mat::near_half_turn(v) {
            return None;
        }
        crate::values::exact_mat::half_turn(v).or_else(|| self.certified_turn?(v))
    }

    /// Argument `i` as a rotation R ∈ SO(3) (§3.2.1), read per `read_group` (LANGUAGE.md §5).
    pub fn so3(&mut self, i: usize) -> Result<SO3, Diagnostic> {
        Ok(SO3::assume(match self.group(i, Group::SO3)? {
            Num::M3(m) => *m,
            m => Mat3::from_column_slice(m.as_slice()),
        }))
    }
    /// Argument `i` as a transform T ∈ SE(3) (§3.3.1), read per `read_group` (LANGUAGE.md §5).
    pub fn se3(&mut self, i: usize) -> Result<SE3, Diagnostic> {
        Ok(SE3::assume(match self.group(i, Group::SE3)? {
            Num::M4(m) => *m,
            m => Mat4::from_column_slice(m.as_slice()),
        }))
    }
    /// Argument `i` as a planar rotation ∈ SO(2), read per `read_group` (LANGUAGE.md §5).
    pub fn so2(&mut self, i: usize) -> Result<SO2, Diagnostic> {
        Ok(SO2::assume(Mat2::from_column_slice(
            self.group(i, Group::SO2)?.as_slice(),
        )))
    }
    /// Argument `i` as a planar transform ∈ SE(2), read per `read_group` (LANGUAGE.md §5).
    pub fn se2(&mut self, i: usize) -> Result<SE2, Diagnostic> {
        Ok(SE2::assume(Mat3::from_column_slice(
            self.group(i, Group::SE2)?.as_slice(),
        )))
    }

    /// Exponential coordinates ω̂θ: a 3-vector, or an so(3) matrix (vee'd).
    pub fn expc3(&self, i: usize) -> Result<Vec3, Diagnostic> {
        let m = self.mat(i)?;
        match m.shape() {
            (3, 1) => self.vec3(i),
            (3, 3) => {
                let m3 = Mat3::from_column_slice(m.as_slice());
                self.check_skew(i, (m3 + m3.transpose()).abs().max(), m3.abs().max())?;
                Ok(so3::vee(&m3))
            }
            _ => Err(self.wrong(i, "3-vector or so(3) matrix")),
        }
    }

    /// Exponential coordinates Sθ: a 6-vector, or an se(3) matrix (vee'd).
    pub fn expc6(&self, i: usize) -> Result<Vec6, Diagnostic> {
        let m = self.mat(i)?;
        match m.shape() {
            (6, 1) => self.vec6(i),
            (4, 4) => {
                let m4 = Mat4::from_column_slice(m.as_slice());
                let w = m4.fixed_view::<3, 3>(0, 0).into_owned();
                let asym = (w + w.transpose()).abs().max().max(m4.row(3).abs().max());
                self.check_skew(i, asym, m4.abs().max())?;
                Ok(crate::lie::se3::vee(&m4))
            }
            _ => Err(self.wrong(i, "6-vector or se(3) matrix")),
        }
    }

    fn check_skew(&self, i: usize, asym: f64, scale: f64) -> Result<(), Diagnostic> {
        if asym > 1e-9 * scale.max(1.0) {
            return Err(self.error(
                i,
                ErrorKind::Domain,
                format!("not in the Lie algebra: the symmetric part is {asym:.3e} (it must be 0)"),
            ));
        }
        Ok(())
    }

    /// Argument `i` as a mechanism.
    pub fn mech(&self, i: usize) -> Result<&Mechanism, Diagnostic> {
        match &self.vals[i] {
            Value::Mech(m) => Ok(m),
            _ => Err(self.wrong(i, "mechanism")),
        }
    }
}

/// Reads `m` (of the right shape, carrying `exact`) as an element of
/// `group` per LANGUAGE.md §5, decided by its exact form where its floats
/// are within rounding of the group ([`membership`]).
pub fn read_group(
    m: &Num,
    exact: &Exact,
    group: Group,
    span: Span,
    warnings: &mut Vec<Diagnostic>,
) -> Result<Num, Diagnostic> {
    match membership(m, exact, group) {
        Membership::Exact(x) => Ok(x),
        Membership::Projected(p, d) => {
            warnings.push(
                Diagnostic::warning(
                    ErrorKind::Domain,
                    span,
                    format!(
                        "not exactly in {}: distance {d:.2e}; projected to the nearest element",
                        group.name()
                    ),
                )
                .with_help("book values are rounded; ProjectToSO3/ProjectToSE3 (§3.6) is applied"),
            );
            Ok(p)
        }
        Membership::Outside { distance, det } => {
            let gap = orthogonality_gap(m, group);
            let why = if !gap.is_finite() {
                "it has entries that are not finite".to_string()
            } else if det <= 0.0 {
                format!(
                    "det = {} (must be +1), ‖RᵀR − I‖ = {}",
                    crate::values::number::fmt_num(det, 4),
                    crate::values::number::fmt_num(gap, 4)
                )
            } else {
                format!(
                    "distance from {} is {}",
                    group.name(),
                    crate::values::number::fmt_num(distance, 4)
                )
            };
            Err(Diagnostic::error(ErrorKind::Domain, span, format!("not {}: {why}", group.noun())).with_help(format!(
                "{} needs RᵀR = I and det R = +1 (within 1e-2 it is projected, with a warning); see DistanceTo{}",
                group.name(),
                group.name().replace(['(', ')'], "")
            )))
        }
    }
}

/// ‖RᵀR − I‖_F of the rotation block.
fn orthogonality_gap(m: &Num, group: Group) -> f64 {
    let k = if matches!(group, Group::SO2 | Group::SE2) {
        2
    } else {
        3
    };
    let m = m.to_dmatrix();
    let r = m.view((0, 0), (k, k));
    (r.transpose() * r - DMatrix::<f64>::identity(k, k)).norm()
}

/// `a 3-vector`, `an SO(3)`.
pub fn article(what: &str) -> String {
    // "an SO(3)", "an se(3)" (letters read as "ess"), but "a square matrix".
    let lie = ["SO", "SE", "so(", "se("]
        .iter()
        .any(|p| what.starts_with(p));
    let vowel = lie || what.starts_with(['a', 'e', 'i', 'o', 'u', '8']);
    format!("{} {what}", if vowel { "an" } else { "a" })
}
