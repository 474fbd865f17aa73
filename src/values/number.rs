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

/// The text of one number in the common case, built right to left in a
/// buffer on the stack: the inner loop of printing a matrix, with no
/// float formatter, no libm call and no allocation.
#[derive(Clone, Copy)]
pub struct Ascii {
    /// At most 18 bytes are written: an integer below 1e15 with its
    /// sign, or below 9e6 with 9 decimals.
    buf: [u8; 24],
    start: u8,
    /// Where the decimal point is (the end when there is none).
    point: u8,
}

impl Default for Ascii {
    fn default() -> Ascii {
        Ascii {
            buf: [b' '; 24],
            start: 24,
            point: 24,
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
    /// integer print as the integer.
    pub fn fixed(&mut self, x: f64, digits: usize) -> bool {
        self.start = 24;
        self.point = 24;
        if x == 0.0 {
            // Zero (and -0) is written 0: a third of a transform's entries.
            self.push(b'0');
            return true;
        }
        let a = x.abs();
        if digits > 9 || a.is_nan() || a >= 1e15 {
            return false;
        }
        let r = round_abs(a);
        if (a - r as f64).abs() <= 1e-12 * (r as f64).max(1.0) && r < 1_000_000_000_000_000 {
            self.digits(r as u64, 0);
            if x < 0.0 && r != 0 {
                self.push(b'-');
            }
            return true;
        }
        if digits > 0 && a < tiny(digits) {
            return false;
        }
        let scale = POW10[digits];
        let scaled = a * scale as f64;
        // Below 9e15 (< 2⁵³) the rounding is exact and agrees with `round`.
        if scaled >= 9.0e15 {
            return false;
        }
        let n = round_abs(scaled) as u64;
        let (int, mut frac) = (n / scale, n % scale);
        if frac != 0 {
            let mut width = digits;
            while frac % 10 == 0 {
                frac /= 10;
                width -= 1;
            }
            self.digits(frac, width);
            self.push(b'.');
            self.point = self.start;
        }
        self.digits(int, 0);
        if x < 0.0 && n != 0 {
            self.push(b'-');
        }
        true
    }

    #[inline]
    fn push(&mut self, b: u8) {
        self.start -= 1;
        self.buf[usize::from(self.start)] = b;
    }

    /// The decimal digits of `n`, zero-padded to `width`.
    fn digits(&mut self, mut n: u64, width: usize) {
        let end = self.start;
        loop {
            self.push(b'0' + (n % 10) as u8);
            n /= 10;
            if n == 0 {
                break;
            }
        }
        while usize::from(end - self.start) < width {
            self.push(b'0');
        }
    }

    /// The text written (ASCII: digits, '.', '-').
    #[inline]
    pub fn bytes(&self) -> &[u8] {
        &self.buf[usize::from(self.start)..]
    }
    /// The text right-aligned in [`Ascii::WIDTH`] bytes, spaces before it.
    #[inline]
    pub fn padded(&self) -> &[u8; 24] {
        &self.buf
    }
    /// Bytes of the text.
    #[inline]
    pub fn len(&self) -> usize {
        24 - usize::from(self.start)
    }
    /// True before anything is written.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.start == 24
    }
    /// Characters before the decimal point (all of them without one).
    #[inline]
    pub fn int_width(&self) -> usize {
        usize::from(self.point - self.start)
    }
    /// Characters from the decimal point on (0 without one).
    #[inline]
    pub fn frac_width(&self) -> usize {
        24 - usize::from(self.point)
    }
}

/// `a` in `[0, 2⁶³)` rounded half away from zero, exactly as `a.round()`:
/// the truncation and the fraction `a − ⌊a⌋` are exact.
fn round_abs(a: f64) -> i64 {
    let t = a as i64;
    t + i64::from(a - t as f64 >= 0.5)
}

/// Half a unit in the last of `digits` decimals, `0.5·10^−digits`: the
/// smallest magnitude that does not round to 0 (below it, scientific
/// notation). Computed once for the usual `digits`.
fn tiny(digits: usize) -> f64 {
    match TINY.get(digits) {
        Some(t) => *t,
        None => 0.5 * 10f64.powi(-(digits.min(300) as i32)),
    }
}

/// `0.5 * 10f64.powi(-d)` for `d = 0..=9`, bit for bit (a test checks).
const TINY: [f64; 10] = [0.5, 0.05, 0.005, 5e-4, 5e-5, 5e-6, 5e-7, 5e-8, 5e-9, 5e-10];

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
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let unit = (seed >> 11) as f64 / (1u64 << 53) as f64;
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
        for d in 0..10 {
            assert_eq!(tiny(d).to_bits(), (0.5 * 10f64.powi(-(d as i32))).to_bits());
        }
    }
}
