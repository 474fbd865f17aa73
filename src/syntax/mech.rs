//! The body of a `mech < ... >` literal → [`MechSpec`] (chapter 2).
//!
//! Items come in any order; each of `links`, `joints`, `legs` and the space
//! may appear once. Joint letters are kept as written and unknown items are
//! kept with their spans: [`crate::mech`] validates them.

use pest::iterators::Pair;

use super::ast::{BinOp, Expr, ExprKind, JointGroupSyntax, MechSpec, Span};
use super::grammar::Rule;
use super::parser::Cx;
use crate::diagnostics::{Diagnostic, ErrorKind};

impl Cx {
    fn int(&self, pair: &Pair<'_, Rule>) -> Result<i64, Diagnostic> {
        pair.as_str().parse::<i64>().map_err(|_| {
            Diagnostic::error(
                ErrorKind::Syntax,
                self.span(pair.as_span()),
                format!("number too large: {}", pair.as_str()),
            )
        })
    }

    /// A `mech_count` or `legs_count`: a whole number as `(n, None)`;
    /// anything else (`N`, `2 n + 1`, `(k)`) as `(0, Some(expr))`, `*` and
    /// juxtaposition before `+ -`.
    fn count(&self, pair: Pair<'_, Rule>) -> Result<(i64, Option<Expr>), Diagnostic> {
        let parts: Vec<Pair<'_, Rule>> = pair.into_inner().collect();
        if let [one] = parts.as_slice()
            && one.as_rule() == Rule::int
        {
            return Ok((self.int(one)?, None));
        }
        // Terms of the sum, each a product; signs between them.
        let mut sum: Option<Expr> = None;
        let mut product: Option<Expr> = None;
        let mut sign = BinOp::Add;
        // (`2 n`: a product written side by side, as the parser marks it)
        let mut implicit = false;
        let join = |op: BinOp, l: Expr, r: Expr, op_span: Span, implicit: bool| {
            let span = l.span.join(r.span);
            let kind = ExprKind::Binary {
                op,
                lhs: Box::new(l),
                rhs: Box::new(r),
                op_span,
                implicit,
            };
            Expr { kind, span }
        };
        let mut op_span = Span::new(0, 0);
        for p in parts {
            let span = self.span(p.as_span());
            let term = match p.as_rule() {
                Rule::mech_juxt => {
                    (op_span, implicit) = (span, true);
                    continue;
                }
                Rule::mech_op => {
                    op_span = span;
                    match p.as_str() {
                        "*" => implicit = false,
                        op => {
                            if let Some(t) = product.take() {
                                sum = Some(match sum.take() {
                                    Some(s) => join(sign, s, t, op_span, false),
                                    None => t,
                                });
                            }
                            sign = if op == "-" { BinOp::Sub } else { BinOp::Add };
                        }
                    }
                    continue;
                }
                Rule::int => Expr {
                    kind: ExprKind::Number(self.int(&p)? as f64),
                    span,
                },
                Rule::mech_decimal => Expr {
                    kind: ExprKind::Number(p.as_str().parse().map_err(|_| self.internal(span))?),
                    span,
                },
                Rule::mech_name => Expr {
                    kind: ExprKind::Var(p.as_str().into()),
                    span,
                },
                _ => self.primary(p)?.0,
            };
            product = Some(match product.take() {
                Some(l) => join(BinOp::Mul, l, term, op_span, implicit),
                None => term,
            });
        }
        let last = product.ok_or_else(|| self.internal(op_span))?;
        Ok((
            0,
            Some(match sum {
                Some(s) => join(sign, s, last, op_span, false),
                None => last,
            }),
        ))
    }

    pub(super) fn mech(&self, pair: Pair<'_, Rule>) -> Result<MechSpec, Diagnostic> {
        let mut spec = MechSpec {
            links: None,
            links_expr: None,
            joints: Vec::new(),
            legs: None,
            legs_expr: None,
            space: None,
            unknown: Vec::new(),
        };
        let mut joints_at: Option<Span> = None;
        for item in pair.into_inner() {
            let span = self.span(item.as_span());
            let first = |prev: Option<Span>, what: &str| match prev {
                Some(prev) => Err(Diagnostic::error(
                    ErrorKind::Syntax,
                    span,
                    format!("`{what}` appears twice in this mech"),
                )
                .with_label(prev, "first given here")),
                None => Ok(()),
            };
            match item.as_rule() {
                Rule::kw_mech => {}
                Rule::mech_links => {
                    first(spec.links.as_ref().map(|l| l.1), "links")?;
                    let n = item
                        .into_inner()
                        .find(|p| p.as_rule() == Rule::mech_count)
                        .ok_or_else(|| self.internal(span))?;
                    let (n, e) = self.count(n)?;
                    spec.links = Some((n, span));
                    spec.links_expr = e;
                }
                Rule::mech_joints => {
                    first(joints_at, "joints")?;
                    joints_at = Some(span);
                    for j in item.into_inner().filter(|p| p.as_rule() == Rule::joint) {
                        let text = j.as_str();
                        let joint_span = self.span(j.as_span());
                        let (mut count, mut count_expr, mut letters) = (1, None, "");
                        for part in j.into_inner() {
                            match part.as_rule() {
                                Rule::joint_letters => letters = part.as_str(),
                                _ => match (part.as_str(), part.into_inner().next()) {
                                    // `(n)R`: an expression in parentheses.
                                    (_, Some(paren)) => {
                                        count = 0;
                                        count_expr = Some(self.primary(paren)?.0);
                                    }
                                    (digits, None) => {
                                        count = digits.trim().parse::<i64>().map_err(|_| {
                                            Diagnostic::error(
                                                ErrorKind::Syntax,
                                                joint_span,
                                                format!("joint count too large: {text}"),
                                            )
                                        })?;
                                    }
                                },
                            }
                        }
                        spec.joints.push(JointGroupSyntax {
                            count,
                            count_expr,
                            letters: letters.to_string(),
                            span: joint_span,
                        });
                    }
                }
                Rule::mech_legs => {
                    first(spec.legs.as_ref().map(|l| l.2), "legs")?;
                    let mut it = item.into_inner().filter(|p| p.as_rule() != Rule::kw_legs);
                    // (`legs_count`: its last factor is followed by the chain)
                    let (Some(n), Some(chain)) = (it.next(), it.next()) else {
                        return Err(self.internal(span));
                    };
                    let (k, e) = self.count(n)?;
                    spec.legs = Some((k, chain.as_str().to_string(), span));
                    spec.legs_expr = e;
                }
                Rule::mech_space => {
                    first(spec.space.as_ref().map(|s| s.1), "planar/spatial/spherical")?;
                    spec.space = Some((item.as_str().to_string(), span));
                }
                Rule::mech_unknown => {
                    let text = item.as_str().trim_end();
                    let span = Span::new(span.start, span.start + text.len());
                    spec.unknown.push((text.to_string(), span));
                }
                _ => return Err(self.unexpected(&item)),
            }
        }
        Ok(spec)
    }
}
