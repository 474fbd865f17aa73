//! Binding a statement's value to its name (LANGUAGE.md §3, §5): the
//! name checked against the value's frames and kind (`T_ab` a transform
//! from {a} to {b}, `V_b` a twist), a matrix near SO(3) or SE(3) taken as
//! it is, projected or refused by its distance, and the value stored in
//! the session, copied or moved.

use super::env::Stored;
use super::interp::{Interp, Typed};
use super::value::Value;
use crate::check::bind;
use crate::check::rules::RuleError;
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::syntax::ast::{Name, Span};

impl Interp<'_> {
    /// Binds a checked value to `name` (statements call this only after
    /// they have succeeded).
    #[inline]
    pub(super) fn bind_value(&mut self, name: Name, t: &Typed) {
        self.bind_from(name, &t.ty, t.val.as_deref().map(Stored::Copied));
    }

    /// [`Interp::bind_value`] of a value given (moved into the binding) or
    /// lent (copied).
    #[inline]
    pub(super) fn bind_from(&mut self, name: Name, ty: &Ty, val: Option<Stored<'_>>) {
        if self.env.numbers_read.is_empty() {
            self.env.set_made(name, ty, val, &[]);
            return;
        }
        let mut absorbed: Vec<Name> = self.env.numbers_read.iter().map(|(s, _)| *s).collect();
        absorbed.sort_unstable_by_key(|n| n.as_str());
        absorbed.dedup();
        self.env.set_made(name, ty, val, &absorbed);
    }

    /// Checks a binding's name against the value's frames (§3) and gives
    /// the value the kind its name implies (`V_b` a twist, `F_a` a wrench).
    #[inline(always)]
    pub(super) fn bind_checked(
        &mut self,
        name: crate::syntax::name::Name,
        t: &mut Typed,
        name_span: Span,
        value_span: Span,
    ) -> Result<(), Diagnostic> {
        // Lists, pictures and strings take no frames from their names (§12):
        // theirs come from what they hold.
        if matches!(t.ty.kind, Kind::List(..) | Kind::Picture | Kind::Text) {
            return Ok(());
        }
        let claim = self.env.claim(name);
        match bind::bind_in_place(&name, &claim, &mut t.ty) {
            Ok(None) => {}
            Ok(Some(w)) => self.rule_warning(w, value_span, name_span),
            Err(e) => {
                self.rule_failure(e, value_span, Some(name_span), Some(value_span), None)?;
            }
        }
        // (a name declared by `given` holds its declared kind: §7)
        let declared = match self.env.has_givens() {
            true => self.declared(name, &t.ty.kind, name_span, value_span)?,
            false => None,
        };
        if let Some(group) = declared {
            t.ty.kind = group;
        }
        let ty = t.ty.kind;
        // (The value first: checking has none, and kinds compare by a call.)
        if let Some(Value::Num { m, kind, exact }) = t.val.as_deref_mut()
            && ty != Kind::Unknown
        {
            if ty.is_group() && *kind != ty {
                let owned = std::mem::replace(m, crate::values::num::Num::Scalar(0.0));
                let before = owned.clone();
                let why = match declared {
                    Some(_) => Why::Declared,
                    None => Why::Named,
                };
                *m = self.group_at_binding(&name, &ty, why, owned, exact, value_span)?;
                // Numbers moved onto the group are no longer what was typed.
                if *m != before {
                    *exact = Default::default();
                }
            }
            *kind = ty;
        } else if let Some(Value::Formula { kind, .. }) = t.val.as_deref_mut()
            && ty != Kind::Unknown
            && !ty.is_group()
        {
            // the book's names label symbolic 6-vectors as they do numbers
            // (`S2 = (0, 0, 1, 0, -L1, 0)` is a screw axis, §5)
            *kind = ty;
        }
        if matches!(ty, Kind::Matrix(Some(4), Some(4))) {
            self.transform_lookalike(&name, t, value_span);
        }
        Ok(())
    }

    /// A warning from a binding rule (the name renames a moved frame).
    fn rule_warning(&mut self, e: RuleError, value_span: Span, name_span: Span) {
        let e = e.into_refusal();
        let kind = e.kind.unwrap_or(ErrorKind::Frame);
        let mut d = Diagnostic::warning(kind, name_span, e.message);
        if !e.rhs.is_empty() {
            d = d.with_label(value_span, e.rhs);
        }
        if let Some(h) = e.help {
            d = d.with_help(h);
        }
        self.frames.warning(d, &mut self.warnings);
    }

    /// `R_sb = M`, `T_ab = M`: the name asserts the group (LANGUAGE.md §5).
    /// Within 1e-9 the matrix is taken as it is (exactly in the group, when
    /// it has an exact form); within 1e-2 it is projected
    /// (ProjectToSO3/SE3, §3.6) with a warning giving the distance; farther
    /// is a domain error giving the distance (DistanceToSO3/SE3).
    /// The kind `name` was declared with by `given name : kind`
    /// (LANGUAGE.md §7), which a value bound to it later must have, as if
    /// its numbers had been typed first: the same shape, or a type error
    /// (`given x : scalar; x = (1, 2, 3)`), so that nothing computed from
    /// the declaration (`R R^T = I` of `given R : SO3`) is silently wrong
    /// of the numbers. For a group, the group itself is returned: the
    /// numbers are then checked at the binding as a rotation's or
    /// transform's name checks them (`given R : SO3; R = M`). None for a
    /// name not so declared, or a value of the declared kind already.
    #[inline(never)]
    fn declared(
        &self,
        name: Name,
        kind: &Kind,
        name_span: Span,
        value_span: Span,
    ) -> Result<Option<Kind>, Diagnostic> {
        let Some(declared) = self.env.given(name).map(|b| b.ty.kind) else {
            return Ok(None);
        };
        if declared == *kind {
            return Ok(None);
        }
        let (Some(want), Some(got)) = (declared.shape(), kind.shape()) else {
            return Ok(None);
        };
        let known = |(r, c): (Option<usize>, Option<usize>)| r.is_some() && c.is_some();
        if !known(want) || !known(got) || want == got {
            return Ok(declared.is_group().then_some(declared));
        }
        Err(Diagnostic::error(
            ErrorKind::Type,
            value_span,
            format!(
                "{name} was declared {} (given {name} : {}), but the value is {}",
                declared.a(),
                super::interp::given_spelling(&declared).unwrap_or("…"),
                kind.a()
            ),
        )
        .with_label(name_span, format!("declared {}", declared.a()))
        .with_help(format!(
            "values worked out from {name} assumed {}: declare it again for the new kind (given {name} : …), or bind the value to another name",
            declared.a()
        )))
    }

    fn group_at_binding(
        &mut self,
        name: &str,
        kind: &Kind,
        why: Why,
        m: crate::values::num::Num,
        exact: &crate::values::exact::Exact,
        span: Span,
    ) -> Result<crate::values::num::Num, Diagnostic> {
        use super::convert::{Group, Membership};
        use crate::values::exact_mat::membership;
        let group = match kind {
            Kind::SO3 => Group::SO3,
            Kind::SE3 => Group::SE3,
            Kind::SO2 => Group::SO2,
            Kind::SE2 => Group::SE2,
            _ => return Ok(m),
        };
        if m.shape() != (group.size(), group.size()) {
            return Ok(m);
        }
        let measure = format!("DistanceTo{}", group.name().replace(['(', ')'], ""));
        let fmt = |d: f64| crate::values::number::fmt_num(d, 4);
        match membership(&m, exact, group) {
            Membership::Exact(x) => Ok(x),
            Membership::Projected(p, d) => {
                self.warnings.push(
                    Diagnostic::warning(
                        ErrorKind::Domain,
                        span,
                        format!(
                            "{}, and the matrix is {:.2e} from {} ({measure}); projected to the nearest element",
                            why.subject(name, group),
                            d,
                            group.name()
                        ),
                    )
                    .with_help("book values are rounded to 3 digits: within 1e-2 the name's group is assumed (ProjectTo, §3.6)"),
                );
                Ok(p)
            }
            Membership::Outside { distance, det } => Err(Diagnostic::error(
                ErrorKind::Domain,
                span,
                format!(
                    "{}, but {}",
                    why.subject(name, group),
                    match (det <= 0.0, group) {
                        (true, Group::SO3 | Group::SO2) =>
                            format!("its determinant is {} (a rotation's is 1)", fmt(det)),
                        (true, _) => format!(
                            "its rotation block's determinant is {} (a rotation's is 1)",
                            fmt(det)
                        ),
                        (false, _) => format!(
                            "the matrix is {} from {} ({measure})",
                            match distance {
                                // (near the limit of 1e-2, digits enough to see it passed)
                                d if d < 0.1 => format!("{d:.3e}"),
                                d if d.is_finite() => fmt(d),
                                _ => "infinitely far".into(),
                            },
                            group.name()
                        ),
                    }
                ),
            )
            .with_help(match why {
                Why::Named => format!(
                    "a matrix within 1e-2 of {} is projected onto it; check the entries, or bind it to a name that is not a rotation or transform (M{})",
                    group.name(),
                    name.strip_prefix(crate::syntax::ident::base_name(name)).unwrap_or("")
                ),
                Why::Declared => format!(
                    "a matrix within 1e-2 of {} is projected onto it; check the entries, or bind the matrix to another name (values worked out from {name} assumed {})",
                    group.name(),
                    group.name()
                ),
            })),
        }
    }
}

/// Why a matrix bound to a name must be in a group (LANGUAGE.md §5, §7).
#[derive(Clone, Copy)]
enum Why {
    /// The book's letter and frames name it one (`R_sb`, `T_ab`).
    Named,
    /// `given name : SO3` declared it one.
    Declared,
}

impl Why {
    /// The message's subject: "R_ab names a rotation matrix", "R was
    /// declared an SO(3)".
    fn subject(self, name: &str, group: super::convert::Group) -> String {
        match self {
            Why::Named => format!("{name} names {}", group.noun()),
            Why::Declared => format!("{name} was declared an {}", group.name()),
        }
    }
}
