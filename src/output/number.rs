//! Numbers for people (LANGUAGE.md §10): `--digits N` decimals with
//! trailing zeros trimmed, `-0` as `0`, values within 1e-12 of an integer
//! as the integer, scientific notation for very large or small numbers.

/// Formats `x` with at most `digits` decimals.
pub fn fmt_num(x: f64, digits: usize) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf".into() } else { "-inf".into() };
    }
    let r = x.round();
    if (x - r).abs() <= 1e-12 * r.abs().max(1.0) && r.abs() < 1e15 {
        return if r == 0.0 {
            "0".into()
        } else {
            format!("{r:.0}")
        };
    }
    let tiny = 0.5 * 10f64.powi(-(digits.min(300) as i32));
    if x.abs() >= 1e15 || x.abs() < tiny {
        return sci(x, digits);
    }
    let s = format!("{x:.digits$}");
    let s = trim(&s);
    if s == "-0" { "0".into() } else { s }
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

/// Full precision, shortest round-trip form (for `--digits 17`-like needs).
pub fn fmt_full(x: f64) -> String {
    if x == 0.0 { "0".into() } else { format!("{x}") }
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
    }
}
