//! Numbers for people (LANGUAGE.md §10): `--digits N` decimals with
//! trailing zeros trimmed, `-0` as `0`, values within 1e-12 of an integer
//! as the integer, scientific notation for very large or small numbers.

/// Formats `x` with at most `digits` decimals.
pub fn fmt_num(x: f64, digits: usize) -> String {
    let mut s = String::new();
    write_num(&mut s, x, digits);
    s
}

/// [`fmt_num`], appended to `out` (no allocation of its own on the
/// common paths).
pub fn write_num(out: &mut String, x: f64, digits: usize) {
    let mut buf = Ascii::default();
    if buf.fixed(x, digits) {
        // A few ASCII bytes: pushed one by one, cheaper than a copy.
        for &b in buf.bytes() {
            out.push(char::from(b));
        }
        return;
    }
    if x.is_nan() {
        return out.push_str("NaN");
    }
    if x.is_infinite() {
        return out.push_str(if x > 0.0 { "inf" } else { "-inf" });
    }
    if digits >= 17 {
        // Full precision: the shortest text that reads back as the same f64
        // (no snapping to integers; -0 is still written 0).
        return if x == 0.0 {
            out.push('0')
        } else {
            out.push_str(&trim_point_zero(format!("{x:?}")))
        };
    }
    let r = x.round();
    if (x - r).abs() <= 1e-12 * r.abs().max(1.0) && r.abs() < 1e15 {
        // An integer below 1e15 prints as `{r:.0}` would.
        if r < 0.0 {
            out.push('-');
        }
        return out.push_str(&(r.abs() as u64).to_string());
    }
    let tiny = 0.5 * 10f64.powi(-(digits.min(300) as i32));
    if x.abs() >= 1e15 || (digits > 0 && x.abs() < tiny) {
        return out.push_str(&sci(x, digits));
    }
    let s = format!("{x:.digits$}");
    let s = trim(&s);
    out.push_str(if s == "-0" { "0" } else { &s });
}

/// Most numbers [`write_tuple`] writes at once.
const TUPLE: usize = 8;

/// `(x₁, x₂, …)` followed by `close` (`)`, or `).T` for a row), appended
/// to `out` as [`write_num`] would write each number, when there are at
/// most eight numbers, all in [`Ascii::fixed`]'s common case; false, with
/// nothing written, otherwise. The text is assembled on the stack and
/// copied once.
pub fn write_tuple(out: &mut String, xs: &[f64], digits: usize, close: &str) -> bool {
    let n = xs.len();
    if n == 0 || n > TUPLE || close.len() > 4 {
        return false;
    }
    let mut cells = [Ascii::default(); TUPLE];
    for (cell, &x) in cells.iter_mut().zip(xs) {
        if !cell.fixed(x, digits) {
            return false;
        }
    }
    // Left to right: each cell is copied as its whole padded buffer (a
    // copy of constant size) from where its text starts; the spaces it
    // carries fall only where the text to its right is written afterwards.
    const W: usize = Ascii::WIDTH;
    let mut buf = [b' '; TUPLE * (W + 2) + 8];
    buf[0] = b'(';
    let mut at = 1;
    for (k, cell) in cells[..n].iter().enumerate() {
        if k > 0 {
            buf[at] = b',';
            at += 2;
        }
        buf[at..at + W].copy_from_slice(cell.padded());
        at += cell.len();
    }
    for &b in close.as_bytes() {
        buf[at] = b;
        at += 1;
    }
    // Every byte is ASCII: digits, '.', '-', spaces, brackets, commas. The
    // check runs over whole 16-byte blocks (the spaces after the text),
    // which is cheaper than its byte-by-byte tail.
    let checked = ((at + 15) & !15).min(buf.len());
    let text = std::str::from_utf8(&buf[..checked]).unwrap_or_default();
    out.push_str(text.get(..at).unwrap_or_default());
    true
}

/// The text of one number in the common case, built in a buffer on the
/// stack: the inner loop of printing a matrix, with no float formatter,
/// no libm call and no allocation.
#[derive(Clone, Copy)]
pub struct Ascii {
    /// The text from the first byte, spaces after it. At most 18 bytes
    /// are written: an integer below 1e15 with its sign, or below 9e6
    /// with 9 decimals.
    buf: [u8; 24],
    /// Bytes of the text.
    len: u8,
    /// Bytes before the decimal point (all of them without one).
    int: u8,
}

impl Default for Ascii {
    fn default() -> Ascii {
        Ascii {
            buf: [b' '; 24],
            len: 0,
            int: 0,
        }
    }
}

impl Ascii {
    /// The length of [`Ascii::padded`].
    pub const WIDTH: usize = 24;

    /// Writes [`fmt_num`]'s text of `x` when `x` is finite, below 1e15,
    /// not in scientific notation and `digits ≤ 9` (the same text, byte
    /// for byte), and says whether it did. `x` is rounded to `digits`
    /// decimals with integer arithmetic; values within 1e-12 of an
    /// integer print as the integer. Writes into a fresh (default) buffer.
    #[inline]
    pub fn fixed(&mut self, x: f64, digits: usize) -> bool {
        if x == 0.0 {
            // Zero (and -0) is written 0: a third of a transform's entries.
            self.buf[0] = b'0';
            self.len = 1;
            self.int = 1;
            return true;
        }
        self.fixed_nonzero(x, digits)
    }

    /// [`Ascii::fixed`] of a nonzero `x`. The common case (at most 8
    /// decimals, below 1e7 with a fraction or an integer below 1e11) has
    /// its rounding decided once: `n = round(|x|·10^digits)`, the integer
    /// part `n / 10^digits` and the fraction's eight digits written as one
    /// word, its trailing zeros counted in that word. Such a number is
    /// never within 1e-12 of an integer unless the fraction is 0 (it is at
    /// least 0.49·10^−digits away and the tolerance below 0.1·10^−digits +
    /// 1e-12), so the test for one is not needed there.
    fn fixed_nonzero(&mut self, x: f64, digits: usize) -> bool {
        let a = x.abs();
        if digits <= 8 && (digits == 0 || a >= TINY[digits]) {
            let scaled = a * POW10F[digits];
            if scaled < 1e11 {
                let n = round_abs(scaled) as u64;
                let scale = POW10[digits];
                let (int, frac) = (n / scale, n % scale);
                if frac == 0 || int < 10_000_000 {
                    let mut at = 0;
                    if x < 0.0 && n != 0 {
                        self.buf[0] = b'-';
                        at = 1;
                    }
                    at = put_int_at(&mut self.buf, at, int);
                    self.int = at as u8;
                    if frac != 0 {
                        let word = fraction_word(frac, digits);
                        self.buf[at] = b'.';
                        self.buf[at + 1..at + 9].copy_from_slice(&word.0.to_le_bytes());
                        at += 1 + word.1;
                    }
                    self.len = at as u8;
                    return true;
                }
            }
        }
        if a <= 1e-12 && digits <= 9 {
            // Within 1e-12 of 0 (rounding noise): the integer 0, unsigned.
            self.buf[0] = b'0';
            self.len = 1;
            self.int = 1;
            return true;
        }
        self.fixed_general(x, digits)
    }

    /// [`Ascii::fixed`] of every other nonzero `x`, in the order of
    /// [`write_num`]'s tests: an integer within 1e-12, scientific notation
    /// for what rounds to 0, then the decimals (right to left in a
    /// scratch buffer, then moved to the front).
    #[cold]
    fn fixed_general(&mut self, x: f64, digits: usize) -> bool {
        let a = x.abs();
        if digits > 9 || a.is_nan() || a >= 1e15 {
            return false;
        }
        let mut buf = [b' '; 24];
        let (start, point);
        let r = round_abs(a);
        let rf = r as f64;
        if (a - rf).abs() <= 1e-12 * rf.max(1.0) && r < 1_000_000_000_000_000 {
            let mut i = put_int(&mut buf, 24, r as u64);
            if x < 0.0 && r != 0 {
                i -= 1;
                buf[i] = b'-';
            }
            (start, point) = (i, 24);
        } else {
            if digits > 0 && a < TINY[digits] {
                return false;
            }
            let scaled = a * POW10F[digits];
            // Below 9e15 (< 2⁵³) the rounding is exact and agrees with `round`.
            if scaled >= 9.0e15 {
                return false;
            }
            let n = round_abs(scaled) as u64;
            let scale = POW10[digits];
            let (int, mut frac) = (n / scale, n % scale);
            let mut i = 24;
            if frac != 0 {
                let mut width = digits;
                while frac % 10 == 0 {
                    frac /= 10;
                    width -= 1;
                }
                i = put_int(&mut buf, i, frac);
                while 24 - i < width {
                    i -= 1;
                    buf[i] = b'0';
                }
                i -= 1;
                buf[i] = b'.';
            }
            point = i;
            i = put_int(&mut buf, i, int);
            if x < 0.0 && n != 0 {
                i -= 1;
                buf[i] = b'-';
            }
            start = i;
        }
        self.buf[..24 - start].copy_from_slice(&buf[start..]);
        self.len = (24 - start) as u8;
        self.int = (point - start) as u8;
        true
    }

    /// The text written (ASCII: digits, '.', '-').
    #[inline]
    pub fn bytes(&self) -> &[u8] {
        &self.buf[..usize::from(self.len)]
    }
    /// The text from the first byte of [`Ascii::WIDTH`] bytes, spaces
    /// after it.
    #[inline]
    pub fn padded(&self) -> &[u8; 24] {
        &self.buf
    }
    /// Bytes of the text.
    #[inline]
    pub fn len(&self) -> usize {
        usize::from(self.len)
    }
    /// True before anything is written.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// Characters before the decimal point (all of them without one).
    #[inline]
    pub fn int_width(&self) -> usize {
        usize::from(self.int)
    }
    /// Characters from the decimal point on (0 without one).
    #[inline]
    pub fn frac_width(&self) -> usize {
        usize::from(self.len - self.int)
    }
}

/// `a` in `[0, 2⁶³)` rounded half away from zero, exactly as `a.round()`:
/// the truncation and the fraction `a − ⌊a⌋` are exact.
#[inline]
fn round_abs(a: f64) -> i64 {
    let t = a as i64;
    t + i64::from(a - t as f64 >= 0.5)
}

/// The decimals `f` of `digits` (`0 < f < 10^digits`, `digits ≤ 8`) as
/// eight bytes, first digit in the low byte, the trailing zeros and the
/// bytes after the last digit turned to spaces; and how many digits are
/// left. Four or fewer decimals (the default) take half the work.
#[inline]
fn fraction_word(f: u64, digits: usize) -> (u64, usize) {
    const ZEROS: u64 = 0x3030_3030_3030_3030;
    const SPACES: u64 = 0x2020_2020_2020_2020;
    if digits <= 4 {
        let f = (f * POW10[4 - digits]) as usize;
        let word = u32::from(PAIR16[f / 100]) | u32::from(PAIR16[f % 100]) << 16;
        // A '0' byte xor '0' is 0: the high zero bytes are the trailing
        // zeros (fewer than 4, as f > 0).
        let zeros = ((word ^ ZEROS as u32).leading_zeros() / 8) as usize;
        let keep = u32::MAX >> (8 * zeros);
        let word = u64::from(word & keep | SPACES as u32 & !keep) | SPACES << 32;
        return (word, 4 - zeros);
    }
    let f = f * POW10[8 - digits];
    let (hi, lo) = ((f / 10_000) as usize, (f % 10_000) as usize);
    let word = u64::from(PAIR16[hi / 100])
        | u64::from(PAIR16[hi % 100]) << 16
        | u64::from(PAIR16[lo / 100]) << 32
        | u64::from(PAIR16[lo % 100]) << 48;
    let zeros = ((word ^ ZEROS).leading_zeros() / 8) as usize;
    let keep = u64::MAX >> (8 * zeros);
    (word & keep | SPACES & !keep, 8 - zeros)
}

/// Writes the decimal digits of `n` into `buf` from `at`; returns where
/// they end.
#[inline]
fn put_int_at(buf: &mut [u8; 24], at: usize, n: u64) -> usize {
    if n < 10 {
        buf[at] = b'0' + n as u8;
        return at + 1;
    }
    let mut end = at + 2;
    let mut m = n / 100;
    while m > 0 {
        end += 1;
        m /= 10;
    }
    put_int(buf, end, n);
    end
}

/// Writes the decimal digits of `n` into `buf` so that they end at `end`
/// (two at a time, from a table); returns where they start.
#[inline]
fn put_int(buf: &mut [u8; 24], end: usize, mut n: u64) -> usize {
    let mut i = end;
    while n >= 100 {
        i -= 2;
        buf[i..i + 2].copy_from_slice(&PAIR16[(n % 100) as usize].to_le_bytes());
        n /= 100;
    }
    if n >= 10 {
        i -= 2;
        buf[i..i + 2].copy_from_slice(&PAIR16[n as usize].to_le_bytes());
    } else {
        i -= 1;
        buf[i] = b'0' + n as u8;
    }
    i
}

/// `00`, `01`, …, `99` as two bytes each (the first digit in the low
/// byte): two digits at a time.
const PAIR16: [u16; 100] = {
    let mut t = [0u16; 100];
    let mut k = 0;
    while k < 100 {
        t[k] = (b'0' + (k / 10) as u8) as u16 | ((b'0' + (k % 10) as u8) as u16) << 8;
        k += 1;
    }
    t
};

/// Half a unit in the last of `d` decimals, `0.5·10^−d` for `d = 0..=9`
/// (bit for bit `0.5 * 10f64.powi(-d)`, a test checks): the smallest
/// magnitude that does not round to 0 (below it, scientific notation).
const TINY: [f64; 10] = [0.5, 0.05, 0.005, 5e-4, 5e-5, 5e-6, 5e-7, 5e-8, 5e-9, 5e-10];

/// [`POW10`] as floats (exact: all below 2⁵³).
const POW10F: [f64; 10] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];

/// Powers of ten `10^0 ..= 10^9`.
const POW10: [u64; 10] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
    1_000_000_000,
];

/// `2.0` → `2` (Rust's shortest form keeps a `.0` on whole numbers).
fn trim_point_zero(s: String) -> String {
    match s.strip_suffix(".0") {
        Some(t) => t.to_string(),
        None => s,
    }
}

fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

fn sci(x: f64, digits: usize) -> String {
    let s = format!("{:.*e}", digits.max(1), x);
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{}", trim(m), e),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn book_style_numbers() {
        assert_eq!(fmt_num(0.8660254037844386, 4), "0.866");
        assert_eq!(fmt_num(-0.0, 4), "0");
        assert_eq!(fmt_num(-1e-17, 4), "0");
        assert_eq!(fmt_num(2.0000000000001, 4), "2");
        assert_eq!(fmt_num(std::f64::consts::FRAC_PI_2, 4), "1.5708");
        assert_eq!(fmt_num(std::f64::consts::FRAC_PI_2, 2), "1.57");
        assert_eq!(fmt_num(-0.25, 4), "-0.25");
        assert_eq!(fmt_num(3.2e-7, 4), "3.2e-7");
        assert_eq!(fmt_num(f64::INFINITY, 4), "inf");
        assert_eq!(fmt_num(113.13708498984761, 4), "113.1371");
        assert_eq!(fmt_num(-0.00004, 4), "-4e-5");
        assert_eq!(fmt_num(0.3, 0), "0");
        assert_eq!(fmt_num(0.0509, 4), "0.0509");
        assert_eq!(fmt_num(-2.5, 0), "-3");
        assert_eq!(fmt_num(12.30001, 3), "12.3");
        assert_eq!(fmt_num(1.0005e-3, 3), "0.001");
        assert_eq!(fmt_num(0.0123, 4), "0.0123");
        assert_eq!(fmt_num(-0.000_51, 4), "-0.0005");
        assert_eq!(fmt_num(-7.0, 2), "-7");
        assert_eq!(fmt_num(123_456_789_012_345.0, 4), "123456789012345");
        assert_eq!(fmt_num(-2.000_000_1, 9), "-2.0000001");
        assert_eq!(fmt_num(0.49999999999999994, 0), "0");
        assert_eq!(fmt_num(-0.5, 0), "-1");
        assert_eq!(fmt_num(2.5, 0), "3");
        assert_eq!(fmt_num(-0.4, 0), "0");
        assert_eq!(fmt_num(999_999_999_999_999.4, 4), "999999999999999");
        assert_eq!(fmt_num(5e-5, 4), "0.0001");
        assert_eq!(fmt_num(4.9e-5, 4), "4.9e-5");
    }

    /// The fast paths (exact integer rounding, the table of 0.5·10⁻ᵈ)
    /// write the same text as the plain formatter they replace.
    #[test]
    fn fast_paths_agree_with_the_formatter() {
        fn slow(x: f64, digits: usize) -> String {
            let r = x.round();
            if (x - r).abs() <= 1e-12 * r.abs().max(1.0) && r.abs() < 1e15 {
                return format!("{:.0}", if r == 0.0 { 0.0 } else { r });
            }
            let tiny = 0.5 * 10f64.powi(-(digits.min(300) as i32));
            if x.abs() >= 1e15 || (digits > 0 && x.abs() < tiny) {
                return sci(x, digits);
            }
            let s = format!("{x:.digits$}");
            let s = trim(&s);
            if s == "-0" { "0".into() } else { s }
        }
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        for i in 0..20_000 {
            let unit = uniform(&mut seed);
            let x = (unit - 0.5) * 10f64.powi(i % 13 - 6);
            for digits in [0, 2, 4, 6] {
                let (fast, slow) = (fmt_num(x, digits), slow(x, digits));
                // Exact decimal ties may differ in the last digit (fixed_fast).
                if fast != slow {
                    let tie = (x.abs() * 10f64.powi(digits as i32)).fract() == 0.5;
                    assert!(tie, "{x:?} at {digits}: {fast} vs {slow}");
                }
            }
        }
        for (d, t) in TINY.iter().enumerate() {
            assert_eq!(t.to_bits(), (0.5 * 10f64.powi(-(d as i32))).to_bits());
        }
    }

    /// The next number in [0, 1) of a xorshift generator (repeatable
    /// samples without a crate).
    fn uniform(seed: &mut u64) -> f64 {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Numbers of every kind the fast path of [`Ascii::fixed`] takes or
    /// hands over: random magnitudes, exact decimal ties, near-integers,
    /// values around the tiny and large thresholds.
    fn samples() -> Vec<f64> {
        let mut xs = vec![
            1.0,
            -1.0,
            0.5,
            -0.5,
            2.5,
            0.125,
            -0.125,
            0.0625,
            1e-12,
            -1e-12,
            1.1e-12,
            4.9e-5,
            5e-5,
            5.1e-5,
            0.99995,
            0.999949,
            9999999.99995,
            1e7,
            1e11,
            99999999999.9,
            1e11 + 0.3,
            123456789012.5,
            1e-13,
            -3e-17,
            2.000_000_000_000_1,
            0.49999999999999994,
        ];
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for i in 0..30_000 {
            let unit = uniform(&mut seed);
            let x = (unit - 0.5) * 10f64.powi(i % 30 - 14);
            xs.push(x);
            // Ties at every number of decimals, and near-integers.
            xs.push((x * 1e4).round() / 1e4 + 0.5e-4);
            xs.push(x.round() + (unit - 0.5) * 1e-12 * x.abs().max(1.0));
        }
        xs
    }

    /// The fast path writes, byte for byte, what the whole algorithm
    /// ([`Ascii::fixed_general`], `write_num`'s rules) writes.
    #[test]
    fn fast_path_is_the_general_text() {
        for x in samples() {
            for digits in 0..=10 {
                let (mut fast, mut general) = (Ascii::default(), Ascii::default());
                let ok = fast.fixed(x, digits);
                let ok_general = x == 0.0 || general.fixed_general(x, digits);
                assert_eq!(ok, ok_general, "{x:?} at {digits}");
                if ok && x != 0.0 {
                    assert_eq!(fast.bytes(), general.bytes(), "{x:?} at {digits}");
                    assert_eq!(fast.int_width(), general.int_width(), "{x:?} at {digits}");
                }
                if ok {
                    // Spaces after the text, as the layout copies them.
                    assert!(fast.padded()[fast.len()..].iter().all(|&b| b == b' '));
                }
            }
        }
    }

    /// A tuple is its numbers as `write_num` writes them, joined by `, `.
    #[test]
    fn tuples_join_the_numbers() {
        let xs = samples();
        for (k, chunk) in xs.chunks(7).take(3000).enumerate() {
            let n = 1 + k % chunk.len();
            let part = &chunk[..n];
            let mut out = String::from("v = ");
            let digits = k % 7;
            let close = if k % 2 == 0 { ")" } else { ").T" };
            if write_tuple(&mut out, part, digits, close) {
                let each: Vec<String> = part.iter().map(|&x| fmt_num(x, digits)).collect();
                assert_eq!(out, format!("v = ({}{close}", each.join(", ")));
            } else {
                assert_eq!(out, "v = ");
            }
        }
        let mut out = String::new();
        assert!(write_tuple(&mut out, &[0.7953, 2.0898, 3.0, -0.0], 4, ")"));
        assert_eq!(out, "(0.7953, 2.0898, 3, 0)");
    }
}
