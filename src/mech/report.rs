//! What a mechanism prints: Grübler's formula (2.4) with its numbers
//! substituted, the C-space topology of an open chain (§2.3.1), the notes
//! on lower bounds and structures, and the JSON form.

use std::fmt;

use super::joint::{Factor, JointType, Space};
use super::mechanism::{Mechanism, group_text, signed};

impl Mechanism {
    /// Grübler's formula (2.4) with the numbers substituted, e.g.
    /// `dof = 3(4 − 1 − 4) + 4·1 = 1`.
    ///
    /// Σ f_i is written the way the book writes it in Examples 2.3, 2.5 and
    /// 2.6: the joints grouped by their freedoms `f`, ascending, each group
    /// as `count·f` — `8R P` gives `9·1` (Example 2.3(i): "9(1)"),
    /// `7R RP` gives `7·1 + 1·2`, `6U 6P 6S` gives `6·1 + 6·2 + 6·3`.
    /// With no joints the sum is written `0`. Minus signs are `−`.
    pub fn formula(&self) -> String {
        // Contacts (Exercises 2.18–2.19) are their own terms, after the joints.
        let mut by_f: Vec<((bool, i64), i128)> = Vec::new();
        for (count, joint) in &self.groups {
            let f = (joint.is_contact(), joint.freedoms_in(self.space));
            match by_f.iter_mut().find(|(g, _)| *g == f) {
                Some((_, c)) => *c += i128::from(*count),
                None => by_f.push((f, i128::from(*count))),
            }
        }
        by_f.sort_by_key(|&(f, _)| f);
        let sum = if by_f.is_empty() {
            "0".to_string()
        } else {
            by_f.iter()
                .map(|((_, f), c)| format!("{c}·{f}"))
                .collect::<Vec<_>>()
                .join(" + ")
        };
        format!(
            "dof = {}({} − 1 − {}) + {} = {}",
            self.m(),
            self.n,
            self.j,
            sum,
            signed(self.dof)
        )
    }

    /// The topology of the C-space where this can be read off the joints
    /// (§2.3.1), else `None` (closed chains: their C-space is cut out by
    /// loop-closure equations, §2.4).
    ///
    /// - An open chain, `J = N − 1` (a serial chain or tree from ground —
    ///   links assumed connected): the product of the joints' own C-spaces,
    ///   R → `S^1`, P and H → `R^1`, C → `S^1 × R^1`, U → `T^2`, S → `SO(3)`
    ///   (the rotations, Chapter 3). Like factors are collected, in order of
    ///   first appearance, as the book writes them: `n` circles are `T^n`
    ///   (one is `S^1`), `k` lines `R^k`: RRRP → `T^3 × R^1`,
    ///   PR → `R^1 × S^1`, 2R → `T^2`.
    /// - A single free rigid body (`links 2`, no joints): planar
    ///   `R^2 × S^1`; spatial `R^3 × SO(3)`; spherical `SO(3)`. The book's
    ///   §2.3.1 writes the spatial one `R^3 × S^2 × S^1`, counting the three
    ///   rotation coordinates of §2.1 as a point on `S^2` and an angle; that
    ///   product has the right dimension but is not the space of rotations
    ///   `SO(3)`, so the spherical joint and the free body are written with
    ///   `SO(3)` alike (a note says so).
    pub fn topology(&self) -> Option<String> {
        if self.j == 0 && self.n == 2 {
            return Some(
                match self.space {
                    Space::Planar => "R^2 × S^1",
                    Space::Spatial => "R^3 × SO(3)",
                    Space::Spherical => "SO(3)",
                }
                .to_string(),
            );
        }
        if self.j == 0 || self.j != self.n - 1 || self.groups.iter().any(|(_, j)| j.is_contact()) {
            return None;
        }
        // Count factors: each group contributes count × its factors.
        let mut order: Vec<Factor> = Vec::new();
        let mut totals: Vec<i128> = Vec::new();
        let mut add = |f: Factor, n: i128| match order.iter().position(|&g| g == f) {
            Some(i) => totals[i] += n,
            None => {
                order.push(f);
                totals.push(n);
            }
        };
        match &self.legs {
            Some(l) => {
                for kind in &l.chain {
                    for &f in kind.factors() {
                        add(f, i128::from(l.count));
                    }
                }
            }
            None => {
                for (count, jt) in &self.groups {
                    for kind in &jt.kinds {
                        for &f in kind.factors() {
                            add(f, i128::from(*count));
                        }
                    }
                }
            }
        }
        let parts: Vec<String> = order
            .iter()
            .zip(&totals)
            .map(|(f, &n)| match (f, n) {
                (Factor::Circle, 1) => "S^1".to_string(),
                (Factor::Circle, n) => format!("T^{n}"),
                (Factor::Line, n) => format!("R^{n}"),
                (Factor::Rotations, 1) => "SO(3)".to_string(),
                (Factor::Rotations, n) => format!("SO(3)^{n}"),
            })
            .collect();
        Some(parts.join(" × "))
    }

    /// Remarks on the result, in the book's terms: a closed chain gives only
    /// a lower bound (Proposition 2.1, Examples 2.4 and 2.5); `dof ≤ 0` is a
    /// structure by the formula; idle spins of legs with two S joints
    /// (Example 2.6); links not all connected; the free rigid body and the
    /// `SO(3)` convention of [`Mechanism::topology`].
    pub fn notes(&self) -> Vec<String> {
        let mut notes = Vec::new();
        if self.is_closed_chain() {
            notes.push(
                "closed chain, so this is a lower bound: constraints may be dependent (Grübler counts independent constraints; examples 2.4 and 2.5 show it undercounting)"
                    .to_string(),
            );
        }
        if self.dof == 0 {
            notes.push(
                "by the formula a structure (dof ≤ 0): it cannot move unless its constraints are dependent, as for the parallelogram linkage of example 2.4, which moves with one dof"
                    .to_string(),
            );
        } else if self.dof < 0 {
            notes.push(format!(
                "by the formula a structure (dof ≤ 0), overconstrained by {}: special geometry can still let it move, as the Delta robot of example 2.5 (−9 counted naively, 3 in fact)",
                self.dof.unsigned_abs()
            ));
        }
        if let Some(l) = &self.legs {
            let s_joints = l.chain.iter().filter(|&&k| k == JointType::S).count() as i64;
            if s_joints >= 2 && l.count >= 1 {
                // (the links between each two S joints in a row spin alone)
                let total = l.count * (s_joints - 1);
                let spins = if total == 1 {
                    "1 of the dof is this idle spin".to_string()
                } else {
                    format!("{total} of the dof are such idle spins")
                };
                let has = if s_joints == 2 {
                    "two S joints: the links between them can spin about the line through the two ball centres".to_string()
                } else {
                    format!(
                        "{s_joints} S joints: the links between each two in a row can spin about the line through their ball centres, {} spins a leg",
                        s_joints - 1
                    )
                };
                notes.push(format!(
                    "each {} leg has {has} without moving the platform (example 2.6, U replaced by S); {spins}",
                    l.chain_text()
                ));
            }
        }
        if self.j > 0 && self.j < self.n - 1 {
            notes.push(format!(
                "J = {} < N − 1 = {}: the joints cannot connect all the links, so some move as free bodies",
                self.j,
                self.n - 1
            ));
        }
        if self.j == 0 {
            notes.push(format!(
                "no joints: a single free {} rigid body, dof = m = {} (§2.1)",
                self.space,
                self.m()
            ));
        }
        if let Some(t) = self.topology()
            && t.contains("SO(3)")
        {
            notes.push(
                "SO(3) is the space of rotations (Chapter 3); the book's §2.3.1 writes it S^2 × S^1, which counts its three coordinates but is not the same space"
                    .to_string(),
            );
        }
        notes
    }

    /// The joints as written, e.g. `8R P`, `7R RP`, `4R`; for
    /// `legs K CHAIN` the joints that makes, grouped by type in chain order
    /// (`legs 6 UPS` → `6U 6P 6S`, `legs 3 UPU` → `6U 3P`).
    pub fn joints_text(&self) -> String {
        self.groups
            .iter()
            .map(|(c, jt)| group_text(*c, &jt.letters()))
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// The mechanism as a JSON object (LANGUAGE.md §1:
    /// `{"dof":1,"m":3,"links":4,"joints":4,...}`), adding `space`, `sum_f`,
    /// `joints_text`, `legs`, `formula`, `topology`, `closed_chain`,
    /// `lower_bound` and `notes`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "dof": self.dof,
            "m": self.m(),
            "links": self.n,
            "joints": self.j,
            "space": self.space.name(),
            "sum_f": self.sum_f,
            "joints_text": self.joints_text(),
            "legs": self.legs.as_ref().map(|l| serde_json::json!({
                "count": l.count,
                "chain": l.chain_text(),
            })),
            "formula": self.formula(),
            "topology": self.topology(),
            "closed_chain": self.is_closed_chain(),
            "lower_bound": self.is_lower_bound(),
            "notes": self.notes(),
        })
    }
}

impl fmt::Display for Mechanism {
    /// Several lines: the space and `m`, `N`, `J` with the joints, `Σf`,
    /// the substituted formula, the C-space topology where known, notes.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{} mechanism, m = {}", self.space, self.m())?;
        let s = |n: i64| if n == 1 { "" } else { "s" };
        writeln!(f, "  N = {} link{} (ground included)", self.n, s(self.n))?;
        match &self.legs {
            Some(l) => writeln!(
                f,
                "  J = {} joint{}: {} leg{} {} ({})",
                self.j,
                s(self.j),
                l.count,
                s(l.count),
                l.chain_text(),
                self.joints_text()
            )?,
            None if self.j == 0 => writeln!(f, "  J = 0 joints")?,
            None => writeln!(
                f,
                "  J = {} joint{}: {}",
                self.j,
                s(self.j),
                self.joints_text()
            )?,
        }
        writeln!(f, "  Σf = {}", self.sum_f)?;
        write!(f, "  {}", self.formula())?;
        if self.is_lower_bound() {
            write!(f, " (lower bound)")?;
        }
        if let Some(t) = self.topology() {
            write!(f, "\n  C-space: {t}")?;
        }
        for note in self.notes() {
            write!(f, "\n  note: {note}")?;
        }
        Ok(())
    }
}
