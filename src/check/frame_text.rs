//! How frame tags print (LANGUAGE.md §6, §10): `{a}`, `{b'}`, `{a}←{b}`,
//! `displacement in {a}`, written straight into the output text (every
//! printed value's label) and through `Display` for messages.

use std::fmt;

use super::ty::{Frame, Frames};

impl Frame {
    /// The primes printed after the name: as the name wrote it, with one
    /// more once moved further.
    fn primes(&self) -> u32 {
        match self.written {
            at if at > 0 && self.moved == at => at,
            at if at > 0 && self.moved > at => at + 1,
            _ => u32::from(self.moved > 0),
        }
    }

    /// [`Frame`]'s `Display` text appended to `out`, without the
    /// formatting machinery (printing a value's label).
    pub fn write_to(&self, out: &mut String) {
        let name = self.name.as_str();
        match name.as_bytes() {
            // Most frames are one letter: pushed without a copy.
            &[b] => out.push(char::from(b)),
            _ => out.push_str(name),
        }
        if self.written > 0 || self.moved > 0 {
            for _ in 0..self.primes() {
                out.push('\'');
            }
        }
    }
}

impl fmt::Display for Frame {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name.as_str())?;
        for _ in 0..self.primes() {
            f.write_str("'")?;
        }
        Ok(())
    }
}

impl Frames {
    /// [`Frames`]' `Display` text appended to `out`, without the
    /// formatting machinery (every printed value's label).
    pub fn write_to(&self, out: &mut String) {
        let braced = |out: &mut String, a: &Frame| {
            out.push('{');
            a.write_to(out);
            out.push('}');
        };
        if let Some(a) = self.displacement_frame() {
            out.push_str("displacement in ");
            return braced(out, a);
        }
        match self {
            Frames::None => {}
            Frames::One(a) => braced(out, a),
            Frames::Pair(a, b) => {
                out.push('{');
                a.write_to(out);
                out.push_str("}←{");
                b.write_to(out);
                out.push('}');
            }
            Frames::Disp(a) => {
                out.push_str("displacement in ");
                braced(out, a);
            }
            Frames::Transposed(a, b) => {
                out.push('(');
                braced(out, a);
                out.push('←');
                braced(out, b);
                out.push_str(")ᵀ");
            }
        }
    }
}

impl fmt::Display for Frames {
    /// `{a}`, `{a}←{b}`, `displacement in {a}`; empty when untagged.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut s = String::new();
        self.write_to(&mut s);
        f.write_str(&s)
    }
}
