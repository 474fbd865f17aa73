//! A mechanism of links and joints, its degrees of freedom by Grübler's
//! formula (Proposition 2.1, equation (2.4)) and, for an open chain, the
//! topology of its C-space (§2.3.1).

use std::fmt;

use super::joint::{Joint, JointType, Space};

/// Largest count, link number or leg number accepted in a spec; anything
/// bigger is a typo, not a mechanism.
pub const MAX_COUNT: i64 = 1_000_000;

/// Longest compound joint or leg chain accepted (in letters).
pub const MAX_LETTERS: usize = 1_000;

/// Which written item of a `mech < … >` spec an error is about, so the
/// language layer can put the caret under it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MechPart {
    /// The `links N` item (or its absence).
    Links,
    /// The joint group at this index of the `joints` list (0-based).
    Joint(usize),
    /// The `legs K CHAIN` item.
    Legs,
    /// The space word `planar`, `spatial` or `spherical` (or its absence).
    Space,
    /// The spec as a whole.
    Whole,
}

/// An error in a mechanism spec: the item it is about, a message, and an
/// optional `help:` line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MechError {
    /// Which written item is wrong.
    pub part: MechPart,
    /// What is wrong, in the book's terms.
    pub message: String,
    /// How to fix it, where that helps.
    pub help: Option<String>,
}

impl MechError {
    fn new(part: MechPart, message: impl Into<String>) -> MechError {
        MechError {
            part,
            message: message.into(),
            help: None,
        }
    }

    fn help(mut self, help: impl Into<String>) -> MechError {
        self.help = Some(help.into());
        self
    }
}

impl fmt::Display for MechError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)?;
        if let Some(h) = &self.help {
            write!(f, " (help: {h})")?;
        }
        Ok(())
    }
}

impl std::error::Error for MechError {}

/// A parallel mechanism written as `legs K CHAIN` (Examples 2.5 and 2.6,
/// Exercises 6, 10, 11, 15): a fixed platform (ground) and a moving platform
/// joined by `K` identical legs, each a serial chain of separate joints.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Legs {
    /// `K`, the number of legs.
    pub count: i64,
    /// The joints of one leg, from the fixed platform to the moving one.
    pub chain: Vec<JointType>,
}

impl Legs {
    /// The chain's letters, e.g. `UPS`.
    pub fn chain_text(&self) -> String {
        self.chain.iter().map(|k| k.letter()).collect()
    }
}

/// A mechanism: `N` links (ground counted as a link), `J` joints, each
/// joint `i` providing `f_i` freedoms, moving in a space with `m` freedoms
/// per rigid body (Proposition 2.1).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mechanism {
    pub(super) space: Space,
    /// The joint groups: as written for `joints`, one group per chain
    /// letter (with count `K`) for `legs`.
    pub(super) groups: Vec<(i64, Joint)>,
    pub(super) legs: Option<Legs>,
    pub(super) n: i64,
    pub(super) j: i64,
    pub(super) sum_f: i64,
    pub(super) dof: i64,
}

fn too_big(what: &str, value: i64) -> String {
    format!("{what} {value} is absurdly large (at most {MAX_COUNT})")
}

/// The letters of a joint group or leg chain, checked against Table 2.1
/// and the space. `part` is where errors point; `what` names the item.
fn parse_letters(
    letters: &str,
    space: Space,
    part: MechPart,
    what: &str,
) -> Result<Vec<JointType>, MechError> {
    let letters = letters.trim();
    if letters.is_empty() {
        return Err(MechError::new(part, format!("{what} has no joint letters"))
            .help("write joints by their letters in Table 2.1: R P H C U S"));
    }
    if letters.chars().count() > MAX_LETTERS {
        return Err(MechError::new(
            part,
            format!("{what} has more than {MAX_LETTERS} joint letters"),
        ));
    }
    // A contact joint by its name (Exercises 2.17–2.19).
    if let Some(contact) = JointType::contact(letters) {
        if !contact.allowed_in(space) {
            return Err(not_in_space(contact, space, part));
        }
        return Ok(vec![contact]);
    }
    if let Some(e) = contact_word(letters, part) {
        return Err(e);
    }
    let mut kinds = Vec::new();
    for c in letters.chars() {
        let Some(kind) = JointType::from_letter(c) else {
            return Err(MechError::new(
                part,
                format!(
                    "unknown joint letter `{c}` in `{letters}`: the joints of Table 2.1 are R P H C U S"
                ),
            )
            .help(
                "R revolute, P prismatic, H screw (helical), C cylindrical, U universal, S spherical; point contacts are `rolling` and `sliding`",
            ));
        };
        if !kind.allowed_in(space) {
            return Err(not_in_space(kind, space, part));
        }
        kinds.push(kind);
    }
    Ok(kinds)
}

/// A word a student types for a point contact (`6 contact`, `1 point`,
/// `roll`): not read as letters (`contact` is no C joint) but answered
/// with the two contact joints of Exercises 2.17–2.19.
fn contact_word(word: &str, part: MechPart) -> Option<MechError> {
    let lower = word.to_ascii_lowercase();
    let meant = match lower.as_str() {
        "roll" | "rolls" | "rolled" | "nonslip" | "noslipping" => Some("rolling"),
        "slide" | "slides" | "slip" | "slips" | "slipping" | "smooth" => Some("sliding"),
        "contact" | "contacts" | "point" | "points" | "pointcontact" | "pointcontacts" => None,
        _ => return None,
    };
    let both = "a point contact is `rolling` (no slip: f = 1 planar, 3 spatial) or `sliding` (frictionless: f = 2 planar, 5 spatial), Exercises 2.17–2.19";
    let e = match meant {
        Some(m) => MechError::new(
            part,
            format!("`{word}` is no joint of Table 2.1: did you mean `{m}`?"),
        ),
        None => MechError::new(
            part,
            format!(
                "`{word}` is no joint of Table 2.1: say which point contact, `rolling` or `sliding`"
            ),
        ),
    };
    Some(e.help(both))
}

fn not_in_space(kind: JointType, space: Space, part: MechPart) -> MechError {
    let l = kind.symbol();
    let name = kind.name();
    match space {
        Space::Planar => MechError::new(
            part,
            format!(
                "a {name} joint ({l}) does not exist in a planar mechanism: Table 2.1 lists only R and P between planar rigid bodies ({l}: N/A)"
            ),
        )
        .help("planar joints are R and P; write `spatial` for H, C, U or S"),
        Space::Spherical => MechError::new(
            part,
            format!(
                "a {name} joint ({l}) does not belong in a spherical mechanism: every link only rotates about the common point, so its joints are revolute (R) with axes through that point"
            ),
        )
        .help("write `spatial` for a mechanism with other joints"),
        // Every joint of Table 2.1 exists between spatial bodies.
        Space::Spatial => MechError::new(part, format!("{name} joint ({l})")),
    }
}

/// A compound joint (`RRRP`, the book's RP pair of Example 2.1 grown
/// longer) read as ONE joint, when that leaves too few joints to connect
/// the links (`J < N − 1`): the book also names a serial chain by its
/// letters ("an RRRP open chain", the SCARA of Example 2.7), and the two
/// readings give different counts (`links 5; joints RRRP; spatial` is
/// 6(5 − 1 − 1) + 4 = 22 read as one joint, 4 read as four), so the spec
/// is refused with both readings rather than answered with one.
fn compound_leaves_links_apart(
    groups: &[(i64, Joint)],
    space: Space,
    n: i128,
    j: i128,
) -> Option<MechError> {
    if j >= n - 1 {
        return None;
    }
    let (i, (count, joint)) = groups
        .iter()
        .enumerate()
        .find(|(_, (_, jt))| jt.kinds.len() > 1)?;
    let letters = joint.letters();
    let apart = joint
        .kinds
        .iter()
        .map(|k| k.symbol())
        .collect::<Vec<_>>()
        .join(" ");
    let written = group_text(*count, &letters);
    let f = joint.freedoms_in(space);
    let s = if j == 1 { "" } else { "s" };
    Some(
        MechError::new(
            MechPart::Joint(i),
            format!(
                "`{written}` is read as {} (as the RP pair of example 2.1), which leaves J = {j} joint{s} for N = {n} links: too few to connect them (J < N − 1 = {})",
                if *count == 1 {
                    format!("one compound joint with f = {f}")
                } else {
                    format!("{count} compound joints with f = {f} each")
                },
                n - 1
            ),
        )
        .help(format!(
            "a chain of separate joints is written with spaces, `{apart}` (an {letters} open chain, example 2.7); a compound joint connects just two links"
        )),
    )
}

/// Written count and letters, e.g. `8R`, `P`, `7RP`, `6 sliding`.
pub(super) fn group_text(count: i64, letters: &str) -> String {
    if count == 1 {
        letters.to_string()
    } else if letters.starts_with(|c: char| c.is_ascii_lowercase()) {
        format!("{count} {letters}")
    } else {
        format!("{count}{letters}")
    }
}

/// An integer with a true minus sign, as in the book's typeset formulas.
pub(super) fn signed(v: i64) -> String {
    if v < 0 {
        format!("−{}", v.unsigned_abs())
    } else {
        v.to_string()
    }
}

impl Mechanism {
    /// Builds a mechanism from a `mech < … >` spec (LANGUAGE.md §9).
    ///
    /// - `space`: `Some("planar" | "spatial" | "spherical")`; required, since
    ///   `m` changes the answer for every closed chain.
    /// - `links`: `Some(N)` from `links N`, ground included (Proposition 2.1).
    /// - `joints`: the groups as written, `(count, letters)`: `(8, "R")` is
    ///   eight separate R joints, `(1, "RP")` one compound RP joint with
    ///   `f = 2` (Examples 2.1(ii), 2.3(ii)), `(8, "RP")` eight RP joints.
    /// - `legs`: `Some((K, "UPS"))` from `legs K CHAIN`: a parallel mechanism
    ///   of `K` legs, each the serial chain of *separate* joints `U`, `P`,
    ///   `S` between ground and a moving platform, so
    ///   `N = 2 + K·(len − 1)` and `J = K·len` (Example 2.6: `N = 14`,
    ///   `J = 18`). `legs` replaces `joints`; if `links` is also given it
    ///   must equal that `N`.
    ///
    /// With `links N` and no joints at all, only `N = 2` is accepted: a
    /// single free rigid body (§2.1), `dof = m`.
    ///
    /// Counts, `N` and `K` must lie in `1..=1_000_000`; all arithmetic is
    /// done in `i128`, so no spec can overflow or panic.
    pub fn from_spec(
        space: Option<&str>,
        links: Option<i64>,
        joints: &[(i64, &str)],
        legs: Option<(i64, &str)>,
    ) -> Result<Mechanism, MechError> {
        let space = match space {
            None => {
                return Err(MechError::new(
                    MechPart::Space,
                    "the mechanism's space is missing: say planar, spatial or spherical",
                )
                .help("m = 3 for planar and spherical mechanisms, 6 for spatial ones (Proposition 2.1)"));
            }
            Some(word) => Space::parse(word).ok_or_else(|| {
                MechError::new(
                    MechPart::Space,
                    format!(
                        "unknown space `{}`: say planar, spatial or spherical",
                        word.trim()
                    ),
                )
            })?,
        };
        let m = space.m();

        if let Some(n) = links {
            if n <= 0 {
                return Err(MechError::new(
                    MechPart::Links,
                    format!("links {n}: a mechanism has at least one link (the ground)"),
                )
                .help("N counts every link, ground included (Proposition 2.1)"));
            }
            if n > MAX_COUNT {
                return Err(MechError::new(MechPart::Links, too_big("links", n)));
            }
        }

        let mut groups: Vec<(i64, Joint)> = Vec::new();
        let legs_info = match legs {
            Some((k, chain_text)) => {
                if !joints.is_empty() {
                    return Err(MechError::new(
                        MechPart::Legs,
                        "both `joints` and `legs` given: the legs already are the joints",
                    )
                    .help("write either `joints …` with `links N`, or `legs K CHAIN`"));
                }
                if k <= 0 {
                    return Err(MechError::new(
                        MechPart::Legs,
                        format!("legs {k}: a parallel mechanism has at least one leg"),
                    ));
                }
                if k > MAX_COUNT {
                    return Err(MechError::new(MechPart::Legs, too_big("legs", k)));
                }
                let chain = parse_letters(chain_text, space, MechPart::Legs, "the leg chain")?;
                Some(Legs { count: k, chain })
            }
            None => None,
        };

        for (i, &(count, letters)) in joints.iter().enumerate() {
            let part = MechPart::Joint(i);
            if count <= 0 {
                return Err(MechError::new(
                    part,
                    format!(
                        "joint count {count} in `{count}{}`: a count must be at least 1",
                        letters.trim()
                    ),
                ));
            }
            if count > MAX_COUNT {
                return Err(MechError::new(part, too_big("joint count", count)));
            }
            let kinds = parse_letters(letters, space, part, "a joint")?;
            let joint = Joint { kinds };
            if joint.freedoms_in(space) > m {
                return Err(MechError::new(
                    part,
                    format!(
                        "the compound joint {} would provide f = {} freedoms, more than a {space} rigid body has (m = {m})",
                        joint.letters(),
                        joint.freedoms_in(space)
                    ),
                )
                .help("separate joints are written with spaces: `R P`, not `RP`"));
            }
            groups.push((count, joint));
        }

        // N, J and Σf in i128: no spec can overflow.
        let (n, j, sum_f): (i128, i128, i128) = match &legs_info {
            Some(l) => {
                let k = i128::from(l.count);
                let len = l.chain.len() as i128;
                let n = 2 + k * (len - 1);
                if let Some(written) = links
                    && i128::from(written) != n
                {
                    return Err(MechError::new(
                        MechPart::Links,
                        format!(
                            "links {written} disagrees with legs {} {}: that parallel mechanism has N = 2 + {}·({} − 1) = {n} links (fixed and moving platform, {} per leg)",
                            l.count,
                            l.chain_text(),
                            l.count,
                            len,
                            len - 1
                        ),
                    )
                    .help("leave out `links`: legs K CHAIN determines N"));
                }
                // One group per letter of the chain, K joints each.
                for &kind in &l.chain {
                    match groups.iter_mut().find(|(_, jt)| jt.kinds == [kind]) {
                        Some((c, _)) => *c += l.count,
                        None => groups.push((l.count, Joint::single(kind))),
                    }
                }
                let f: i128 = l
                    .chain
                    .iter()
                    .map(|t| i128::from(t.freedoms_in(space)))
                    .sum();
                (n, k * len, k * f)
            }
            None => {
                let Some(n) = links else {
                    if groups.is_empty() {
                        return Err(MechError::new(
                            MechPart::Whole,
                            "no links and no joints: nothing to count",
                        )
                        .help(
                            "write e.g. `links 4; joints 4R; planar`, or `legs 6 UPS; spatial`",
                        ));
                    }
                    return Err(MechError::new(MechPart::Links, "the number of links is missing: write `links N`")
                        .help("N counts every link, ground included; an open chain of J joints has N = J + 1"));
                };
                if groups.is_empty() && n != 2 {
                    return Err(MechError::new(
                        MechPart::Whole,
                        format!("no joints: links {n} with nothing connecting them"),
                    )
                    .help("write the joints, e.g. `joints 4R`; a single free rigid body is `links 2` with no joints"));
                }
                let j: i128 = groups.iter().map(|(c, _)| i128::from(*c)).sum();
                // (a joint connects two links: the ground alone has none)
                if n == 1 && j > 0 {
                    return Err(MechError::new(
                        MechPart::Links,
                        format!(
                            "links 1 with {j} joint{}: a joint connects two links, and the ground is the only one",
                            if j == 1 { "" } else { "s" }
                        ),
                    )
                    .help("N counts every link, ground included: one joint on the ground is `links 2; joints R`"));
                }
                if let Some(e) = compound_leaves_links_apart(&groups, space, i128::from(n), j) {
                    return Err(e);
                }
                let f: i128 = groups
                    .iter()
                    .map(|(c, jt)| i128::from(*c) * i128::from(jt.freedoms_in(space)))
                    .sum();
                (i128::from(n), j, f)
            }
        };
        let dof = i128::from(m) * (n - 1 - j) + sum_f;
        let fit = |v: i128| {
            i64::try_from(v)
                .map_err(|_| MechError::new(MechPart::Whole, "the mechanism is too large to count"))
        };

        Ok(Mechanism {
            space,
            groups,
            legs: legs_info,
            n: fit(n)?,
            j: fit(j)?,
            sum_f: fit(sum_f)?,
            dof: fit(dof)?,
        })
    }

    /// The degrees of freedom by Grübler's formula (2.4),
    /// `dof = m(N − 1 − J) + Σ f_i`; only a lower bound when the joint
    /// constraints are dependent (see [`Mechanism::is_lower_bound`]).
    pub fn dof(&self) -> i64 {
        self.dof
    }

    /// `m`, the freedoms of one rigid body: 3 planar or spherical, 6 spatial.
    pub fn m(&self) -> i64 {
        self.space.m()
    }

    /// The space the mechanism moves in.
    pub fn space(&self) -> Space {
        self.space
    }

    /// `N`, the number of links, ground included (Proposition 2.1).
    pub fn links(&self) -> i64 {
        self.n
    }

    /// `J`, the number of joints (a compound joint such as RP counts once).
    pub fn joint_count(&self) -> i64 {
        self.j
    }

    /// `Σ f_i`, the freedoms provided by all the joints.
    pub fn sum_f(&self) -> i64 {
        self.sum_f
    }

    /// `Σ c_i = Σ (m − f_i) = mJ − Σ f_i`, the joint constraints of (2.4).
    pub fn sum_c(&self) -> i64 {
        self.m() * self.j - self.sum_f
    }

    /// The joint groups: as written for `joints`; for `legs K CHAIN` one
    /// group per joint type of the chain with its total count.
    pub fn joint_groups(&self) -> &[(i64, Joint)] {
        &self.groups
    }

    /// The legs of a parallel mechanism written as `legs K CHAIN`.
    pub fn legs(&self) -> Option<&Legs> {
        self.legs.as_ref()
    }

    /// A closed-chain mechanism (§2.2.2): it has a closed loop, which for
    /// connected links means `J > N − 1` (every `legs` mechanism with two or
    /// more legs).
    pub fn is_closed_chain(&self) -> bool {
        self.j > self.n - 1
    }

    /// Whether the result is only a lower bound on the true dof: Grübler's
    /// formula assumes independent joint constraints, which a closed chain
    /// may violate (Proposition 2.1, Example 2.4).
    pub fn is_lower_bound(&self) -> bool {
        self.is_closed_chain()
    }
}
