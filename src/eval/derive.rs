//! `derive T_ce` (LANGUAGE.md §6): a breadth-first search over the known
//! transforms — numeric or `given` — for a chain of frames from {c} to {e},
//! using inverses where an edge points the other way.

use std::collections::{HashMap, VecDeque};

use super::graph::FrameGraph;
use super::interp::{Interp, Typed};
use super::ops;
use super::value::Value;
use crate::check::ty::{Frame, Frames, Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::apply::Op;
use crate::syntax::ast::{BinOp, Ident};
use crate::syntax::ident::{NameFrames, base_name, name_frames};

/// One step of a chain: a known name, used as is or inverted.
#[derive(Debug, Clone)]
struct Step {
    name: String,
    inverted: bool,
}

impl Interp<'_> {
    /// Finds and evaluates a chain for `target`; returns its text and value.
    pub(super) fn derive(&mut self, target: &Ident) -> Result<(String, Typed), Diagnostic> {
        let NameFrames::Pair(from, to) = name_frames(&target.name) else {
            return Err(Diagnostic::error(
                ErrorKind::Name,
                target.span,
                format!(
                    "derive needs a name with two frames, like T_ce; '{}' has none",
                    target.name
                ),
            ));
        };
        let rotations = base_name(&target.name).starts_with('R');
        // Edges: x → y for each X_xy, both ways.
        let mut edges: HashMap<String, Vec<(String, Step)>> = HashMap::new();
        // The target itself is left out, so that a second `derive T_ce`
        // shows the chain again rather than `T_ce = T_ce`; it is the
        // answer only when nothing else connects its frames.
        for e in FrameGraph::of(self.env).edges {
            let fits = match e.kind {
                Kind::SE3 | Kind::SE2 => !rotations,
                Kind::SO3 | Kind::SO2 => rotations,
                _ => false,
            };
            if !fits || e.name == target.name {
                continue;
            }
            let (from_frame, to_frame) = (e.from.to_string(), e.to.to_string());
            edges.entry(from_frame.clone()).or_default().push((
                to_frame.clone(),
                Step {
                    name: e.name.clone(),
                    inverted: false,
                },
            ));
            edges.entry(to_frame).or_default().push((
                from_frame,
                Step {
                    name: e.name,
                    inverted: true,
                },
            ));
        }
        if from == to {
            return Ok(self.derived_identity(&edges, &from, rotations));
        }
        let itself = self.env.get(target.name).map(|_| {
            vec![Step {
                name: String::from(target.name),
                inverted: false,
            }]
        });
        let Some(steps) = shortest_path(&edges, &from, &to).or(itself) else {
            let reach = |f: &str| {
                let mut r: Vec<String> = reachable(&edges, f);
                r.sort();
                r.iter()
                    .map(|x| format!("{{{x}}}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            return Err(Diagnostic::error(
                ErrorKind::Frame,
                target.span,
                format!("no chain of known transforms from {{{from}}} to {{{to}}}"),
            )
            .with_help(format!(
                "from {{{from}}} the known transforms reach {}; from {{{to}}} they reach {}",
                reach(&from),
                reach(&to)
            )));
        };
        let text = steps
            .iter()
            .map(|s| {
                if s.inverted {
                    format!("inv({})", s.name)
                } else {
                    s.name.clone()
                }
            })
            .collect::<Vec<_>>()
            .join(" * ");
        let kind = self
            .env
            .get(&steps[0].name)
            .expect("a step is a bound name")
            .ty
            .kind;
        let ty = Ty::new(kind, Frames::Pair(Frame::named(&from), Frame::named(&to)));
        if self.mode == super::env::Mode::Check {
            return Ok((text, Typed::new(ty, None)));
        }
        let mut acc: Option<Value> = None;
        for s in &steps {
            let b = self.env.get(&s.name).expect("a step is a bound name");
            let v = crate::calculus::substitute::current(b.bound(), self.env, &mut self.warnings)
                .map_err(|e| {
                    Diagnostic::error(
                        ErrorKind::Domain,
                        target.span,
                        format!("{} with the numbers bound since: {}", s.name, e.0),
                    )
                })?
                .ok_or_else(|| {
                    Diagnostic::error(
                        ErrorKind::Name,
                        target.span,
                        format!("{} has no value", s.name),
                    )
                })?;
            let v = match (&v, s.inverted) {
                (Value::Sym(x), true) => Value::Sym(x.clone().inverse()),
                (Value::Formula { kind, m, .. }, true) => super::formula::inverse(kind, m)
                    .map(|m| super::formula::make(kind, m))
                    .ok_or_else(|| {
                        Diagnostic::error(ErrorKind::Domain, target.span, "no symbolic inverse")
                    })?,
                (_, true) => ops::inverse(&v).map_err(|m| Op::Inverse.failure(m, target.span))?,
                _ => v,
            };
            acc = Some(match acc {
                None => v,
                // (a numeric identity beside symbols is no factor)
                Some(a)
                    if let Some(o) = crate::seam::transform::identity_factor(
                        BinOp::Mul,
                        (&a, &kind),
                        (&v, &kind),
                    ) =>
                {
                    o
                }
                Some(Value::Sym(a)) => {
                    Value::Sym(super::value::Sym::times(a, crate::seam::apply::to_sym(&v)))
                }
                Some(a) if v.is_symbolic() => Value::Sym(super::value::Sym::times(
                    crate::seam::apply::to_sym(&a),
                    crate::seam::apply::to_sym(&v),
                )),
                Some(a) if super::formula::applies(&[&a, &v]) => {
                    super::formula::binary(crate::syntax::ast::BinOp::Mul, &a, &v, &kind)
                        .map_err(|m| Diagnostic::error(ErrorKind::Domain, target.span, m))?
                }
                Some(a) => ops::mul(&a, &v, &kind)
                    .map_err(|m| Op::Arith(BinOp::Mul).failure(m, target.span))?,
            });
        }
        Ok((text, Typed::new(ty, acc)))
    }
}

impl Interp<'_> {
    /// `derive T_cc`: the empty chain, the identity I of {c} to itself,
    /// of the size of the transforms that reach {c} (SE(3) or SO(3) when
    /// none does, as `T_` or `R_` says).
    fn derived_identity(
        &self,
        edges: &HashMap<String, Vec<(String, Step)>>,
        frame: &str,
        rotations: bool,
    ) -> (String, Typed) {
        let kind = edges
            .get(frame)
            .and_then(|es| es.first())
            .and_then(|(_, s)| self.env.get(&s.name))
            .map(|b| b.ty.kind)
            .unwrap_or(if rotations { Kind::SO3 } else { Kind::SE3 });
        let n = match kind {
            Kind::SE3 => 4,
            Kind::SO2 => 2,
            _ => 3,
        };
        let f = Frame::named(frame);
        let ty = Ty::new(kind, Frames::Pair(f, f));
        let val = (self.mode != super::env::Mode::Check).then(|| Value::Num {
            kind,
            m: crate::values::num::Num::identity(n),
            exact: crate::values::exact::Exact::Typed,
        });
        ("I".to_string(), Typed::new(ty, val))
    }
}

fn shortest_path(
    edges: &HashMap<String, Vec<(String, Step)>>,
    from: &str,
    to: &str,
) -> Option<Vec<Step>> {
    if from == to {
        return None;
    }
    let mut prev: HashMap<String, (String, Step)> = HashMap::new();
    let mut queue = VecDeque::from([from.to_string()]);
    while let Some(x) = queue.pop_front() {
        for (y, step) in edges.get(&x).into_iter().flatten() {
            if y != from && !prev.contains_key(y) {
                prev.insert(y.clone(), (x.clone(), step.clone()));
                if y == to {
                    let mut path = Vec::new();
                    let mut cur = to.to_string();
                    while cur != from {
                        let (p, s) = prev[&cur].clone();
                        path.push(s);
                        cur = p;
                    }
                    path.reverse();
                    return Some(path);
                }
                queue.push_back(y.clone());
            }
        }
    }
    None
}

fn reachable(edges: &HashMap<String, Vec<(String, Step)>>, from: &str) -> Vec<String> {
    let mut seen = vec![from.to_string()];
    let mut queue = VecDeque::from([from.to_string()]);
    while let Some(x) = queue.pop_front() {
        for (y, _) in edges.get(&x).into_iter().flatten() {
            if !seen.contains(y) {
                seen.push(y.clone());
                queue.push_back(y.clone());
            }
        }
    }
    seen
}
