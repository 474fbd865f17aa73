//! The body of a `mech < ... >` literal → [`MechSpec`] (chapter 2).
//!
//! Items come in any order; each of `links`, `joints`, `legs` and the space
//! may appear once. Joint letters are kept as written and unknown items are
//! kept with their spans: [`crate::mech`] validates them.

use pest::iterators::Pair;

use super::ast::{JointGroupSyntax, MechSpec, Span};
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

    pub(super) fn mech(&self, pair: Pair<'_, Rule>) -> Result<MechSpec, Diagnostic> {
        let mut spec = MechSpec {
            links: None,
            joints: Vec::new(),
            legs: None,
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
                        .find(|p| p.as_rule() == Rule::int)
                        .ok_or_else(|| self.internal(span))?;
                    spec.links = Some((self.int(&n)?, span));
                }
                Rule::mech_joints => {
                    first(joints_at, "joints")?;
                    joints_at = Some(span);
                    for j in item.into_inner().filter(|p| p.as_rule() == Rule::joint) {
                        let text = j.as_str();
                        let digits = text.len()
                            - text.trim_start_matches(|c: char| c.is_ascii_digit()).len();
                        let count = if digits == 0 {
                            1
                        } else {
                            text[..digits].parse::<i64>().map_err(|_| {
                                Diagnostic::error(
                                    ErrorKind::Syntax,
                                    self.span(j.as_span()),
                                    format!("joint count too large: {text}"),
                                )
                            })?
                        };
                        spec.joints.push(JointGroupSyntax {
                            count,
                            letters: text[digits..].to_string(),
                            span: self.span(j.as_span()),
                        });
                    }
                }
                Rule::mech_legs => {
                    first(spec.legs.as_ref().map(|l| l.2), "legs")?;
                    let mut it = item.into_inner().filter(|p| p.as_rule() != Rule::kw_legs);
                    let (Some(n), Some(chain)) = (it.next(), it.next()) else {
                        return Err(self.internal(span));
                    };
                    spec.legs = Some((self.int(&n)?, chain.as_str().to_string(), span));
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
