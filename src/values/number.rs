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
        // An integer below 1e15 is exactly an i64, and prints as `{r:.0}` would.
        if r < 0.0 {
            out.push('-');
        }
        return push_digits(out, r.abs() as u64, 0);
    }
    let tiny = 0.5 * 10f64.powi(-(digits.min(300) as i32));
    if x.abs() >= 1e15 || (digits > 0 && x.abs() < tiny) {
        return out.push_str(&sci(x, digits));
    }
    if fixed_fast(out, x, digits) {
        return;
    }
    let s = format!("{x:.digits$}");
    let s = trim(&s);
    out.push_str(if s == "-0" { "0" } else { &s });
}

/// `x` rounded to `digits` decimals with integer arithmetic — much faster
/// than the exact float formatter, and the same text except at exact
/// decimal ties. False (and nothing written) when the scaled value does not
/// fit exactly.
fn fixed_fast(out: &mut String, x: f64, digits: usize) -> bool {
    if digits > 9 {
        return false;
    }
    let scale = 10u64.pow(digits as u32);
    let scaled = (x.abs() * scale as f64).round();
    if scaled >= 9.0e15 {
        return false;
    }
    let n = scaled as u64;
    let (int, mut frac) = (n / scale, n % scale);
    if x < 0.0 && n != 0 {
        out.push('-');
    }
    push_digits(out, int, 0);
    if frac != 0 {
        let mut width = digits;
        while frac % 10 == 0 {
            frac /= 10;
            width -= 1;
        }
        out.push('.');
        push_digits(out, frac, width);
    }
    true
}

/// The decimal digits of `n`, zero-padded to `width`, without the
/// formatting machinery (this is the inner loop of printing a matrix).
fn push_digits(out: &mut String, mut n: u64, width: usize) {
    let mut buf = [b'0'; 24];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    i = i.min(buf.len().saturating_sub(width));
    out.reserve(buf.len() - i);
    out.extend(buf[i..].iter().map(|&b| char::from(b)));
}

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
    }
}
