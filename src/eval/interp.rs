//! The interpreter: one pass over each statement that infers every
//! expression's kind and frames (the check of LANGUAGE.md §6) and, in
//! [`Mode::Run`], computes its value through the Lie-group core. `chasles
//! check` runs the same pass in [`Mode::Check`], with no numbers.

use super::env::{Binding, Env, FrameMode, Mode};
use super::value::{UserFn, Value};
use crate::check::bind;
use crate::check::rules::RuleError;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Span, Stmt, StmtKind};

/// A checked (and, when running, evaluated) expression.
#[derive(Debug, Clone)]
pub struct Typed {
    pub ty: Ty,
    pub val: Option<Value>,
}

/// What a successful statement produced, for printing.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub span: Span,
    /// The bound names (one for `x = ..`, several for `(a, b) = ..`,
    /// none for a bare expression).
    pub names: Vec<String>,
    pub ty: Ty,
    pub val: Option<Value>,
    /// Extra text printed before the value (`derive` prints its chain).
    pub note: Option<String>,
    /// False for statements that print nothing (`given`, function definitions).
    pub prints: bool,
    /// For `(a, b) = ..`, the type of each bound part, with the frames it
    /// took from the value or from its name; empty otherwise.
    pub parts: Vec<Ty>,
}

/// Runs statements against an environment.
pub struct Interp<'a> {
    pub env: &'a mut Env,
    pub src: &'a str,
    pub mode: Mode,
    pub frames: FrameMode,
    /// Warnings of the current statement.
    pub warnings: Vec<Diagnostic>,
    pub(super) depth: usize,
}

/// How deep user functions may call each other.
pub const MAX_CALL_DEPTH: usize = 64;

impl<'a> Interp<'a> {
    pub fn new(env: &'a mut Env, src: &'a str, mode: Mode, frames: FrameMode) -> Interp<'a> {
        Interp {
            env,
            src,
            mode,
            frames,
            warnings: Vec::new(),
            depth: 0,
        }
    }

    /// The source text of a span.
    pub(super) fn text(&self, span: Span) -> &'a str {
        self.src.get(span.start..span.end).unwrap_or("")
    }

    /// Turns a rule failure into a diagnostic, or — for a frame mismatch
    /// under `--frames warn|off` — into a warning (returns Ok(())).
    pub(super) fn rule_failure(
        &mut self,
        e: RuleError,
        span: Span,
        lhs: Option<Span>,
        rhs: Option<Span>,
        op: Option<Span>,
    ) -> Result<(), Diagnostic> {
        let kind = e.kind.unwrap_or(ErrorKind::Type);
        let mut d = Diagnostic::error(kind, op.unwrap_or(span), e.message.clone());
        if let (Some(l), false) = (lhs, e.lhs.is_empty()) {
            d = d.with_label(l, e.lhs.clone());
        }
        if let (Some(r), false) = (rhs, e.rhs.is_empty()) {
            d = d.with_label(r, e.rhs.clone());
        }
        if !e.op.is_empty() {
            d = d.with_primary_label(e.op.clone());
        }
        if let Some(h) = e.help {
            d = d.with_help(h);
        }
        if kind == ErrorKind::Frame {
            match self.frames {
                FrameMode::Strict => {}
                FrameMode::Warn => {
                    d.severity = crate::diagnostics::Severity::Warning;
                    self.warnings.push(d);
                    return Ok(());
                }
                FrameMode::Off => return Ok(()),
            }
        }
        Err(d)
    }

    /// Binds a checked value to `name` (statements call this only after
    /// they have succeeded).
    fn bind_value(&mut self, name: &str, t: &Typed) {
        self.env.set(
            name,
            Binding {
                ty: t.ty.clone(),
                val: t.val.clone(),
                symbolic: false,
            },
        );
    }

    /// Runs one statement. On error nothing is bound.
    pub fn stmt(&mut self, s: &Stmt) -> Result<Outcome, Diagnostic> {
        self.warnings.clear();
        let out = |names: Vec<String>, t: Typed| Outcome {
            span: s.span,
            names,
            ty: t.ty,
            val: t.val,
            note: None,
            prints: true,
            parts: Vec::new(),
        };
        match &s.kind {
            StmtKind::Expr(e) => {
                let t = self.expr(e)?;
                if t.ty.kind != Kind::Function {
                    self.bind_value("ans", &t);
                }
                Ok(out(vec![], t))
            }
            StmtKind::Assign { target, value } => {
                let t = self.expr(value)?;
                let t = self.bind_checked(&target.name, t, target.span, value.span)?;
                self.bind_value(&target.name, &t);
                Ok(out(vec![target.name.clone()], t))
            }
            StmtKind::Destructure { targets, value } => {
                let t = self.expr(value)?;
                let parts = self.split_tuple(&t, targets.len(), value.span)?;
                let mut bound = Vec::new();
                for (target, part) in targets.iter().zip(parts) {
                    bound.push(self.bind_checked(&target.name, part, target.span, value.span)?);
                }
                for (target, b) in targets.iter().zip(&bound) {
                    self.bind_value(&target.name, b);
                }
                let names = targets.iter().map(|t| t.name.clone()).collect();
                let ty = Ty::plain(Kind::Tuple(
                    bound.iter().map(|b| b.ty.kind.clone()).collect(),
                ));
                let val = bound
                    .iter()
                    .map(|b| b.val.clone())
                    .collect::<Option<Vec<_>>>()
                    .map(Value::Tuple);
                let mut o = out(names, Typed { ty, val });
                o.parts = bound.into_iter().map(|b| b.ty).collect();
                Ok(o)
            }
            StmtKind::Given { names, ty } => {
                let kind = given_kind(&ty.name).ok_or_else(|| {
                    Diagnostic::error(
                        ErrorKind::Type,
                        ty.span,
                        format!("unknown type '{}'", ty.name),
                    )
                    .with_help(
                        "given types: scalar vec3 vec6 SO3 SE3 SO2 SE2 so3 se3 twist screw wrench",
                    )
                })?;
                for n in names {
                    let frames = bind::claimed_frames(&n.name, &kind);
                    self.env.set(
                        &n.name,
                        Binding {
                            ty: Ty::new(kind.clone(), frames),
                            val: Some(Value::Sym(super::symbolic::Sym::Name(n.name.clone()))),
                            symbolic: true,
                        },
                    );
                }
                let mut o = out(
                    vec![],
                    Typed {
                        ty: Ty::plain(kind),
                        val: None,
                    },
                );
                o.prints = false;
                Ok(o)
            }
            StmtKind::FnDef { name, params, body } => {
                if crate::builtins::lookup(&name.name).is_some() {
                    return Err(Diagnostic::error(
                        ErrorKind::Name,
                        name.span,
                        format!("'{}' is a builtin function", name.name),
                    )
                    .with_help("choose another name for your function"));
                }
                let f = UserFn {
                    name: name.name.clone(),
                    params: params.iter().map(|p| p.name.clone()).collect(),
                    body: body.clone(),
                };
                self.env.fns.insert(name.name.clone(), std::rc::Rc::new(f));
                let mut o = out(
                    vec![],
                    Typed {
                        ty: Ty::plain(Kind::Function),
                        val: None,
                    },
                );
                o.prints = false;
                Ok(o)
            }
            StmtKind::Derive { target } => {
                let (chain, t) = self.derive(target)?;
                self.bind_value(&target.name, &t);
                let mut o = out(vec![target.name.clone()], t);
                o.note = Some(format!("{} = {chain}", target.name));
                Ok(o)
            }
        }
    }

    /// Checks a binding's name against the value's frames (§3) and gives
    /// the value the kind its name implies (`V_b` a twist, `F_a` a wrench).
    fn bind_checked(
        &mut self,
        name: &str,
        t: Typed,
        name_span: Span,
        value_span: Span,
    ) -> Result<Typed, Diagnostic> {
        let ty = match bind::bind(name, &t.ty) {
            Ok(ty) => ty,
            Err(e) => {
                self.rule_failure(e, value_span, Some(name_span), Some(value_span), None)?;
                let claim = bind::claimed_frames(name, &t.ty.kind);
                Ty::new(bind::named_kind(name, &t.ty.kind), claim)
            }
        };
        let val = t.val.map(|v| match v {
            Value::Num { m, .. } if ty.kind != Kind::Unknown => Value::Num {
                kind: ty.kind.clone(),
                m,
            },
            other => other,
        });
        Ok(Typed { ty, val })
    }

    /// The parts of a tuple (or the entries of a vector) for destructuring.
    fn split_tuple(&self, t: &Typed, n: usize, span: Span) -> Result<Vec<Typed>, Diagnostic> {
        let kinds: Vec<Kind> = match &t.ty.kind {
            Kind::Tuple(ks) => ks.clone(),
            // A list's length is known only from its value.
            Kind::List(k) => match &t.val {
                Some(Value::List(vs)) => vs.iter().map(Value::kind).collect(),
                _ => vec![(**k).clone(); n],
            },
            Kind::Vector(Some(len)) => vec![Kind::Scalar; *len],
            Kind::Unknown | Kind::Vector(None) => vec![Kind::Unknown; n],
            k => {
                return Err(Diagnostic::error(
                    ErrorKind::Type,
                    span,
                    format!("cannot destructure a {k} into {n} names"),
                )
                .with_help("destructuring takes a tuple, e.g. (w, theta) = AxisAng3(expc)"));
            }
        };
        if kinds.len() != n {
            return Err(Diagnostic::error(
                ErrorKind::Arity,
                span,
                format!(
                    "the value has {} parts but {n} names are given",
                    kinds.len()
                ),
            ));
        }
        let vals: Vec<Option<Value>> = match &t.val {
            Some(Value::Tuple(vs)) => vs.iter().cloned().map(Some).collect(),
            Some(Value::List(vs)) => vs.iter().cloned().map(Some).collect(),
            Some(Value::Num { m, .. }) => m.iter().map(|x| Some(Value::scalar(*x))).collect(),
            _ => vec![None; n],
        };
        Ok(kinds
            .into_iter()
            .zip(vals)
            .map(|(k, v)| {
                let frames = t.ty.frames.part(&k);
                let k = v.as_ref().map_or(k, Value::kind);
                Typed {
                    ty: Ty::new(k, frames),
                    val: v,
                }
            })
            .collect())
    }
}

/// The kinds `given` accepts (LANGUAGE.md §7).
pub fn given_kind(name: &str) -> Option<Kind> {
    Some(match name {
        "scalar" => Kind::Scalar,
        "vec3" => Kind::Vector(Some(3)),
        "vec6" => Kind::Vector(Some(6)),
        "SO3" => Kind::SO3,
        "SE3" => Kind::SE3,
        "SO2" => Kind::SO2,
        "SE2" => Kind::SE2,
        "so3" => Kind::So3,
        "se3" => Kind::Se3,
        "twist" => Kind::Twist,
        "screw" => Kind::Screw,
        "wrench" => Kind::Wrench,
        _ => return None,
    })
}
