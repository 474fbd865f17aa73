//! Printing later (issue 40): a statement's printed text with the numbers
//! of its value left to be written, so that a batch run can write them on
//! another thread while the next statement is evaluated.
//!
//! A value's numbers live in storage shared within one thread (a
//! transform's 4×4 behind an `Rc`), so what crosses threads is a copy of
//! them — at most 36, a 6×6 adjoint — beside the text around them, the
//! name and the type label, written here. The numbers are then written by
//! the very function [`super::text::write_outcome`] calls (`text::write_decimals`), so the text is
//! the same byte for byte; every other outcome (exact forms under
//! `--exact`, symbols, lists, tuples, pictures, `explain`) is written here
//! whole, as before.

use crate::eval::interp::Outcome;
use crate::values::format::Style;
use crate::values::num::Num;
use crate::values::value::Value;

use super::text;

/// A statement's text for stdout in text mode (LANGUAGE.md §10), perhaps
/// with the numbers of its value still to be written (see the module's
/// comment). Empty when the statement prints nothing. Made to be used
/// again: [`Printed::write`] keeps the text's storage.
#[derive(Default)]
pub struct Printed {
    text: String,
    numbers: Option<Numbers>,
}

/// The numbers of a printed number, vector or matrix, copied out of the
/// value, and where they go in the text.
struct Numbers {
    /// The byte of the text where the numbers go (after `name = `).
    at: usize,
    rows: usize,
    cols: usize,
    /// The entries, column-major (as nalgebra holds them); `rows * cols`
    /// of them are used.
    xs: [f64; MOST],
    /// The column of the matrix's `[` (rows after the first are indented
    /// to it).
    indent: usize,
}

/// The most numbers a value may have and be printed later: a 6×6 matrix.
const MOST: usize = 36;

impl Printed {
    /// The text [`text::write_outcome`] writes for `o`, with the numbers of
    /// a plain number, vector or matrix (`T_ab = [..]  : SE(3) {a}←{b}`)
    /// left to [`Printed::finish`].
    pub fn write(&mut self, o: &Outcome, style: Style) {
        self.clear();
        // The one shape of `write_outcome` that is a prefix, the numbers
        // and a label: no steps, no note, at most one name, decimals.
        if o.prints
            && o.steps.is_none()
            && o.note.is_none()
            && !style.exact
            && let Some(v @ Value::Num { m, .. }) = o.val.as_deref()
            && m.len() <= MOST
        {
            let names = o.names.as_slice();
            let indent = match names {
                [] => 0,
                [name] => {
                    self.text.push_str(name);
                    self.text.push_str(" = ");
                    text::width(name) + 3
                }
                _ => return text::write_outcome(&mut self.text, o, style),
            };
            let (rows, cols) = m.shape();
            let mut xs = [0.0; MOST];
            xs[..m.len()].copy_from_slice(m.as_slice());
            self.numbers = Some(Numbers {
                at: self.text.len(),
                rows,
                cols,
                xs,
                indent,
            });
            return text::write_label(&mut self.text, &o.ty, v, style);
        }
        text::write_outcome(&mut self.text, o, style)
    }

    /// Empty: a statement that prints nothing (its storage kept).
    pub fn clear(&mut self) {
        self.text.clear();
        self.numbers = None;
    }

    /// The bytes of text held (the numbers still to be written not
    /// counted: at most 36 of them).
    pub fn held(&self) -> usize {
        self.text.len()
    }

    /// Whether the statement prints nothing.
    pub fn is_empty(&self) -> bool {
        self.text.is_empty() && self.numbers.is_none()
    }

    /// The whole text, appended to `out`: the numbers written in their
    /// place, as [`text::write_outcome`] writes them (`style` as given to
    /// [`Printed::write`]).
    pub fn finish(&self, out: &mut String, style: Style) {
        let Some(n) = &self.numbers else {
            return out.push_str(&self.text);
        };
        out.push_str(&self.text[..n.at]);
        let m = Num::from_slice(n.rows, n.cols, &n.xs[..n.rows * n.cols]);
        text::write_decimals(out, &m, style, n.indent);
        out.push_str(&self.text[n.at..]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::env::Mode;
    use crate::session::{Session, Settings};

    /// Every statement's text printed later is the text printed now: named
    /// and bare values of every shape (scalars, vectors, rows, 2×2, 3×3,
    /// 4×4, 6×6, larger, empty), frames in the label, booleans, lists,
    /// tuples, symbols, `explain`, check mode, at several digit counts and
    /// with `--exact`.
    #[test]
    fn printing_later_writes_the_same_text() {
        let src = "\
S = (0, 0, 1, 0, 2, 0)
T_ab = exp([S] 0.1)
R_sb = Rotz(0.3)
X = log(T_ab)
V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6)
A = Ad(T_ab)
Ad(T_ab)
x = 1 / 3
1e300 * 7
-0.5
(1, 2).T
B = [1, 2; 3, 4]
C = zeros(7, 7)
E = zeros(0, 3)
t = true
L = [Rotz(a) for a in 1:2]
(u, w) = (1, 2)
(1, 2)
given th : scalar
Rotz(th)
explain log(Rotz(0.5))
p = (1e-14, 2.5, -0.99995, 123456789.123)
Rotz(pi / 2)
";
        for (mode, digits, exact) in [
            (Mode::Run, 4, false),
            (Mode::Run, 1, false),
            (Mode::Run, 12, false),
            (Mode::Run, 4, true),
            (Mode::Check, 4, false),
        ] {
            let settings = Settings {
                digits,
                exact,
                ..Settings::default()
            };
            let style = settings.text_style();
            let mut session = Session::new(settings);
            let (mut statements, mut deferred) = (0, 0);
            session.run(src, mode, true, |r| {
                let Ok(o) = &r.result else {
                    panic!("{:?}", r.result)
                };
                statements += 1;
                let mut now = String::new();
                text::write_outcome(&mut now, o, style);
                let mut printed = Printed::default();
                printed.write(o, style);
                deferred += usize::from(printed.numbers.is_some());
                assert_eq!(printed.is_empty(), now.is_empty(), "{now}");
                let mut later = String::from("before\n");
                printed.finish(&mut later, style);
                assert_eq!(later, format!("before\n{now}"));
            });
            assert_eq!(statements, src.lines().count());
            // Every plain number, vector and matrix of at most 36 entries
            // was printed later (not under `--exact`, not in check mode):
            // all but `C` (49 entries) and the seven other kinds of value.
            let expect = if mode == Mode::Run && !exact { 16 } else { 0 };
            assert_eq!(deferred, expect, "{mode:?} {digits} {exact}");
        }
    }
}
