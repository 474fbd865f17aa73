//! Values for people (LANGUAGE.md §10): matrices in aligned columns that
//! parse back (`[1, 0; 0, 1]` with one row per line), vectors as the book
//! writes them `(1, 2, 3)`, and the type and frames after the value.

use crate::check::ty::{Frames, Kind, Ty};
use crate::eval::interp::Outcome;
use crate::values::format::write_inline;
pub use crate::values::format::{Style, inline};
use crate::values::num::Num;
use crate::values::number::Ascii;
use crate::values::value::Value;
use std::fmt::Write;

/// The label of a list: `list of 5 SE(3) {s}←{b'}`; of given names'
/// symbols, which know no kind, the list's (`list of 2 SO(3)`).
fn list_label(ty: &Ty, vs: &[Value]) -> String {
    let kind = match (crate::values::value::common_kind(vs), ty.kind) {
        (k, Kind::List(s, _)) if k.has_unknown() => *s,
        (k, _) => k,
    };
    let n = vs.len();
    let what = match kind {
        _ if n == 0 => "empty list".to_string(),
        Kind::Scalar if n == 1 => "list of 1 number".to_string(),
        Kind::Unknown if n == 1 => "list of 1 value".to_string(),
        Kind::Unknown => format!("list of {n} values"),
        k => Kind::list(k)
            .to_string()
            .replacen("list of ", &format!("list of {n} "), 1),
    };
    match ty.frames.is_none() {
        true => what,
        false => format!("{what} {}", ty.frames),
    }
}

/// A list whose items are matrices: one item per block, numbered (the
/// first three and the last two of more than twelve).
fn list_block(prefix: &str, ty: &Ty, vs: &[Value], style: Style) -> String {
    let mut out = format!("{prefix}{}:", list_label(ty, vs));
    let numbered: Vec<(usize, &Value)> = vs.iter().enumerate().collect();
    let shown: Vec<&(usize, &Value)> = if numbered.len() > 12 {
        numbered[..3]
            .iter()
            .chain(numbered[numbered.len() - 2..].iter())
            .collect()
    } else {
        numbered.iter().collect()
    };
    let mut last = 0;
    for (i, v) in shown {
        if *i > last + 1 {
            out.push_str("\n  …");
        }
        last = *i;
        let head = format!("  [{}] ", i + 1);
        let body = match v {
            Value::Num { m, .. } if m.ncols() > 1 && m.nrows() > 1 => {
                matrix_block(m, style, head.chars().count())
            }
            other => inline(other, style),
        };
        out.push('\n');
        out.push_str(&head);
        out.push_str(&body);
    }
    out
}

/// A matrix in aligned columns, decimal points lined up, one row per line;
/// `indent` is the column where the `[` stands.
pub fn matrix_block(m: &Num, style: impl Into<Style>, indent: usize) -> String {
    let mut out = String::new();
    write_matrix_block(&mut out, m, style.into(), indent);
    out
}

/// Width of a cell's text in characters (`√`, `π` are one each).
pub(super) fn width(s: &str) -> usize {
    if s.is_ascii() {
        s.len()
    } else {
        s.chars().count()
    }
}

/// Reusable scratch space of [`write_matrix_block`]: the cells' text, the
/// cells' (start, end, integer width, fraction width) in it, and the
/// column widths.
#[derive(Default)]
struct Scratch {
    buf: String,
    cells: Vec<(usize, usize, usize, usize)>,
    int_w: Vec<usize>,
    frac_w: Vec<usize>,
    /// The block [`align_ascii`] assembles.
    bytes: Vec<u8>,
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::default();
}

/// [`matrix_block`], appended to `out`: the cells are written once into
/// one buffer (reused from call to call), then aligned.
fn write_matrix_block(out: &mut String, m: &Num, style: Style, indent: usize) {
    // Decimals are ASCII, so widths are byte counts and the block is
    // built as bytes (exact forms print as formulas, not here).
    SCRATCH.with(|s| match s.try_borrow_mut() {
        Ok(mut s) => align_ascii(out, m, style.digits, indent, &mut s),
        Err(_) => align(out, m, style, indent, &mut Scratch::default()),
    });
}

/// [`align`] for decimals and at most 36 cells (up to 6×6): each cell
/// written once on the stack by [`Ascii::fixed`], the block assembled as
/// bytes and appended in one copy. The same text as [`align`], which
/// takes over when a cell is not in [`Ascii::fixed`]'s common case.
fn align_ascii(out: &mut String, m: &Num, digits: usize, indent: usize, s: &mut Scratch) {
    // The cells live on the stack, in as small an array as fits; the
    // shapes printed most (transforms, rotations, adjoints) get a copy of
    // the loops with their shape known.
    match m.shape() {
        (4, 4) => align_cells::<16>(out, m, (4, 4), digits, indent, s),
        (3, 3) => align_cells::<16>(out, m, (3, 3), digits, indent, s),
        (6, 6) => align_cells::<36>(out, m, (6, 6), digits, indent, s),
        (r, c) if r * c <= 16 => align_cells::<16>(out, m, (r, c), digits, indent, s),
        (r, c) if r * c <= 36 => align_cells::<36>(out, m, (r, c), digits, indent, s),
        _ => align(out, m, digits.into(), indent, s),
    }
}

/// [`align_ascii`] with room for `N` cells, for a matrix of `shape`.
#[inline(always)]
fn align_cells<const N: usize>(
    out: &mut String,
    m: &Num,
    (nrows, ncols): (usize, usize),
    digits: usize,
    indent: usize,
    s: &mut Scratch,
) {
    let xs = m.as_slice();
    if xs.len() != nrows * ncols || xs.len() > N || ncols > 6 || nrows == 0 {
        return align(out, m, digits.into(), indent, s);
    }
    // The cells in row order, and each column's widest integer part and
    // fraction (from the point on).
    let mut cells = [Ascii::default(); N];
    let (mut int_w, mut frac_w) = ([0usize; 6], [0usize; 6]);
    for (j, column) in xs.chunks_exact(nrows).enumerate() {
        for (r, &x) in column.iter().enumerate() {
            let cell = &mut cells[r * ncols + j];
            if !cell.fixed(x, digits) {
                return align(out, m, digits.into(), indent, s);
            }
            int_w[j] = int_w[j].max(cell.int_width());
            frac_w[j] = frac_w[j].max(cell.frac_width());
        }
    }
    // Where each column's decimal points stand, counted from the row's
    // first cell (a row ends with its last cell's text).
    let mut point = [0usize; 6];
    let mut at = 0;
    for j in 0..ncols {
        point[j] = at + int_w[j];
        at = point[j] + frac_w[j] + 2;
    }
    // The block is laid out left to right in spaces, with `W` bytes of
    // room after it: a cell is copied as its whole padded buffer (a copy
    // of constant size) from where its text starts, so the spaces it
    // carries fall only where text to its right is written afterwards:
    // the cells to its right, the commas, the line breaks and the `]`.
    const W: usize = Ascii::WIDTH;
    let block = &mut s.bytes;
    block.clear();
    block.resize(2 + nrows * (at + indent) + W, b' ');
    let b = block.as_mut_slice();
    b[0] = b'[';
    let mut first = 1;
    for (r, row) in cells[..nrows * ncols].chunks_exact(ncols).enumerate() {
        if r > 0 {
            // `first` is where the row above ended.
            b[first] = b'\n';
            first += indent + 2;
        }
        let mut end = first;
        for (j, cell) in row.iter().enumerate() {
            let start = first + point[j] - cell.int_width();
            b[start..start + W].copy_from_slice(cell.padded());
            end = start + cell.len();
            if j + 1 < ncols {
                b[end] = b',';
            }
        }
        first = end;
    }
    b[first] = b']';
    out.push_str(ascii_text(b, first + 1));
}

/// The first `len` bytes of `b` as text: every byte is ASCII (digits,
/// '.', '-', spaces, brackets, commas, line breaks) and `b` has at least
/// 15 spaces after them, so the check of the text runs over whole 16-byte
/// blocks (its byte-by-byte tail is most of its cost on short texts).
fn ascii_text(b: &[u8], len: usize) -> &str {
    let checked = (len + 15) & !15;
    let text = std::str::from_utf8(&b[..checked.min(b.len())]).unwrap_or_default();
    text.get(..len).unwrap_or_default()
}

fn align(out: &mut String, m: &Num, style: Style, indent: usize, s: &mut Scratch) {
    let (nrows, ncols) = m.shape();
    let Scratch {
        buf,
        cells,
        int_w,
        frac_w,
        ..
    } = s;
    buf.clear();
    cells.clear();
    int_w.clear();
    int_w.resize(ncols, 0);
    frac_w.clear();
    frac_w.resize(ncols, 0);
    for r in 0..nrows {
        for (j, (iw, fw)) in int_w.iter_mut().zip(frac_w.iter_mut()).enumerate() {
            let start = buf.len();
            style.write(buf, m[(r, j)]);
            let split = buf.as_bytes()[start..]
                .iter()
                .position(|&b| b == b'.' || b == b'e')
                .map_or(buf.len(), |k| start + k);
            let (wi, wf) = (width(&buf[start..split]), width(&buf[split..]));
            cells.push((start, buf.len(), wi, wf));
            *iw = (*iw).max(wi);
            *fw = (*fw).max(wf);
        }
    }
    out.reserve(buf.len() + nrows * (2 * ncols + indent + 2) + 2);
    out.push('[');
    // Padding is a few spaces at a time: pushed one by one into the
    // reserved string, which is cheaper than copying slices.
    let pad = |out: &mut String, n: usize| {
        for _ in 0..n {
            out.push(' ');
        }
    };
    for r in 0..nrows {
        if r > 0 {
            out.push('\n');
            pad(out, indent + 1);
        }
        for j in 0..ncols {
            let (start, end, wi, wf) = cells[r * ncols + j];
            pad(out, int_w[j] - wi);
            out.push_str(&buf[start..end]);
            if j + 1 < ncols {
                out.push(',');
                pad(out, frac_w[j] - wf + 1);
            }
        }
    }
    out.push(']');
}

/// The type label: `SE(3) {a}←{c}`; empty for plain numbers and bools.
pub fn type_label(ty: &Ty, val: Option<&Value>) -> String {
    let mut out = String::new();
    write_type_label(&mut out, ty, val);
    out
}

/// [`type_label`], appended to `out`; false when the label is empty.
fn write_type_label(out: &mut String, ty: &Ty, val: Option<&Value>) -> bool {
    let owned;
    let kind = match val {
        Some(Value::Num { kind, .. }) => kind,
        None | Some(Value::Sym(_)) => &ty.kind,
        Some(v) => {
            owned = v.kind();
            &owned
        }
    };
    match kind {
        Kind::Scalar | Kind::Bool if ty.frames.is_none() => false,
        Kind::Mechanism | Kind::Function | Kind::Picture | Kind::Text => false,
        Kind::Tuple(_) => false,
        // As `Ty`'s Display: the kind, then the frames if any.
        k => {
            match kind_name(k) {
                Some(name) => write_label_text(out, name, &ty.frames),
                None => {
                    let _ = write!(out, "{k}");
                    if !ty.frames.is_none() {
                        out.push(' ');
                        ty.frames.write_to(out);
                    }
                }
            }
            true
        }
    }
}

/// `name`, then the frames if any.
fn write_label_text(out: &mut String, name: &str, frames: &Frames) {
    out.push_str(name);
    if !frames.is_none() {
        out.push(' ');
        frames.write_to(out);
    }
}

/// The book's name of a kind without parts, as `Kind`'s `Display` writes
/// it (without the formatting machinery; a test checks they agree).
fn kind_name(k: &Kind) -> Option<&'static str> {
    Some(match k {
        Kind::Scalar => "scalar",
        Kind::SO3 => "SO(3)",
        Kind::SE3 => "SE(3)",
        Kind::So3 => "so(3)",
        Kind::Se3 => "se(3)",
        Kind::SO2 => "SO(2)",
        Kind::SE2 => "SE(2)",
        Kind::So2 => "so(2)",
        Kind::Se2 => "se(2)",
        Kind::Twist => "twist",
        Kind::Screw => "screw axis",
        Kind::Wrench => "wrench",
        Kind::Adjoint { transposed: false } => "adjoint",
        Kind::Adjoint { transposed: true } => "adjoint transpose",
        _ => return None,
    })
}

/// One value with its label, after `prefix` (e.g. `T_ac = `).
pub fn show_value(prefix: &str, ty: &Ty, v: &Value, style: impl Into<Style>) -> String {
    let mut out = String::new();
    write_value(&mut out, prefix, ty, v, style.into());
    out
}

/// [`show_value`], appended to `out`.
fn write_value(out: &mut String, prefix: &str, ty: &Ty, v: &Value, style: Style) {
    match v {
        Value::List(vs)
            if vs
                .iter()
                .any(|x| matches!(x, Value::Num { m, .. } if m.ncols() > 1 && m.nrows() > 1)) =>
        {
            out.push_str(&list_block(prefix, ty, vs, style));
            return;
        }
        Value::List(vs) => {
            out.push_str(prefix);
            write_inline(out, v, style);
            out.push_str("  : ");
            out.push_str(&list_label(ty, vs));
            return;
        }
        Value::Num { .. } => {
            out.push_str(prefix);
            return write_number(out, width(prefix), ty, v, style);
        }
        Value::Formula { m, .. } => {
            out.push_str(&super::formula::name_prefix(prefix, style));
            match crate::values::waiting::text(v, style) {
                Some(t) => out.push_str(&t),
                None => out.push_str(&super::formula::block(m, style, width(prefix))),
            }
        }
        Value::Mech(mech) => {
            if !prefix.is_empty() {
                out.push_str(prefix.trim_end());
                out.push('\n');
            }
            let _ = write!(out, "{mech}");
            return;
        }
        _ => {
            out.push_str(prefix);
            write_inline(out, v, style);
        }
    }
    write_label(out, ty, v, style);
}

/// A number, vector or matrix after its prefix (which ends at column
/// `indent`), then its label.
fn write_number(out: &mut String, indent: usize, ty: &Ty, v: &Value, style: Style) {
    if let Some(t) = crate::values::format::exact_text(v, style) {
        t.write(out, style, indent, false);
        return write_label(out, ty, v, style);
    }
    match v {
        Value::Num { m, .. } => write_decimals(out, m, style, indent),
        _ => write_inline(out, v, style),
    }
    write_label(out, ty, v, style);
}

/// A value's numbers as decimals, after a prefix ending at column
/// `indent`: a matrix as an aligned block, anything else inline (what
/// [`write_number`] writes when no exact form is printed, and what
/// [`super::later`] writes on the writing thread).
pub(super) fn write_decimals(out: &mut String, m: &Num, style: Style, indent: usize) {
    if m.ncols() > 1 && m.nrows() > 1 {
        write_matrix_block(out, m, style, indent)
    } else {
        crate::values::format::write_numbers(out, m, style)
    }
}

/// `  : SE(3) {a}←{b}` after a value (nothing for plain numbers).
pub(super) fn write_label(out: &mut String, ty: &Ty, v: &Value, style: Style) {
    let at = out.len();
    // In LaTeX the label is a comment, so the line stays valid LaTeX (§7).
    let latex = style.sym == crate::sym::print::Mode::Latex && matches!(v, Value::Formula { .. });
    out.push_str(if latex { "  % " } else { "  : " });
    if !write_type_label(out, ty, Some(v)) {
        out.truncate(at);
    }
}

/// The text printed for a statement's outcome (empty when it prints nothing).
pub fn show_outcome(o: &Outcome, style: impl Into<Style>) -> String {
    // Room for a 4×4 matrix with its name and label, so printing one
    // rarely grows the string.
    let mut out = String::with_capacity(192);
    write_outcome(&mut out, o, style.into());
    out
}

/// [`show_outcome`] appended to `out` (a batch run reuses one buffer for
/// every statement: no string made and freed per statement).
pub fn write_outcome(out: &mut String, o: &Outcome, style: Style) {
    if !o.prints {
        return;
    }
    // `explain`: the steps, the last of which is the value (§14).
    if let Some(steps) = o.steps.as_deref() {
        out.push_str(&if style.sym == crate::sym::print::Mode::Latex {
            super::steps::latex(steps, style)
        } else {
            super::steps::text(steps, style)
        });
        return;
    }
    if let Some(note) = &o.note {
        out.push_str(note);
        out.push('\n');
    }
    let Some(v) = o.val.as_deref() else {
        // check mode: the type only
        let names = o.names.join(", ");
        let label = o.ty.to_string();
        out.push_str(&if names.is_empty() {
            label
        } else {
            format!("{names} : {label}")
        });
        return;
    };
    match (o.names.len(), v) {
        (0, Value::Tuple(items)) => {
            let labelled = o.labels.len() == items.len();
            let parts: Vec<String> = items
                .iter()
                .enumerate()
                .map(|(i, x)| {
                    let k = x.kind();
                    let prefix = if labelled {
                        format!("{} = ", o.labels[i])
                    } else {
                        String::new()
                    };
                    show_value(&prefix, &Ty::new(k, o.ty.frames.part(&k)), x, style)
                })
                .collect();
            out.push_str(&parts.join("\n"));
        }
        (0, _) => write_value(out, "", &o.ty, v, style),
        (1, Value::Num { .. }) => {
            // `T_ab = ` written in place (no prefix string).
            let name = &o.names[0];
            out.push_str(name);
            out.push_str(" = ");
            write_number(out, width(name) + 3, &o.ty, v, style);
        }
        (1, _) => {
            let mut prefix = String::with_capacity(o.names[0].len() + 3);
            prefix.push_str(&o.names[0]);
            prefix.push_str(" = ");
            write_value(out, &prefix, &o.ty, v, style);
        }
        (_, Value::Tuple(items)) => {
            let parts: Vec<String> = o
                .names
                .iter()
                .zip(items)
                .enumerate()
                .map(|(i, (n, x))| {
                    let ty = o
                        .parts
                        .get(i)
                        .cloned()
                        .unwrap_or_else(|| Ty::plain(x.kind()));
                    show_value(&format!("{n} = "), &ty, x, style)
                })
                .collect();
            out.push_str(&parts.join("\n"));
        }
        _ => write_value(out, "", &o.ty, v, style),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kind_names_are_the_display_names() {
        let kinds = [
            Kind::Scalar,
            Kind::SO3,
            Kind::SE3,
            Kind::So3,
            Kind::Se3,
            Kind::SO2,
            Kind::SE2,
            Kind::So2,
            Kind::Se2,
            Kind::Twist,
            Kind::Screw,
            Kind::Wrench,
            Kind::Adjoint { transposed: false },
            Kind::Adjoint { transposed: true },
        ];
        for k in kinds {
            assert_eq!(kind_name(&k), Some(k.to_string().as_str()));
        }
        assert_eq!(kind_name(&Kind::Vector(Some(3))), None);
    }

    /// The block laid out from fixed-size copies is the block [`align`]
    /// writes cell by cell, for every shape up to 6×6, any indent, and
    /// entries of every width and sign.
    #[test]
    fn fast_layout_is_the_plain_layout() {
        let entries = [
            0.0,
            1.0,
            -1.0,
            0.995,
            -0.0998,
            0.1997,
            12.5,
            -123.25,
            3e-17,
            0.05,
            -7.0,
            1234567.891,
        ];
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        for rows in 2..=6 {
            for cols in 2..=6 {
                for trial in 0..20 {
                    let xs: Vec<f64> = (0..rows * cols)
                        .map(|_| {
                            seed ^= seed << 13;
                            seed ^= seed >> 7;
                            seed ^= seed << 17;
                            entries[(seed % entries.len() as u64) as usize]
                        })
                        .collect();
                    let m = Num::from_slice(rows, cols, &xs);
                    let (indent, digits) = (trial % 9, [4, 2, 0, 6][trial % 4]);
                    let mut plain = String::from("ab");
                    align(
                        &mut plain,
                        &m,
                        digits.into(),
                        indent,
                        &mut Scratch::default(),
                    );
                    let mut fast = String::from("ab");
                    align_ascii(&mut fast, &m, digits, indent, &mut Scratch::default());
                    assert_eq!(fast, plain, "{rows}x{cols} {xs:?}");
                }
            }
        }
        let t = Num::from_slice(2, 2, &[0.995, 0.0998, -0.0998, 0.995]);
        assert_eq!(
            matrix_block(&t, 4, 7),
            "[0.995,  -0.0998\n        0.0998,  0.995]"
        );
    }
}
