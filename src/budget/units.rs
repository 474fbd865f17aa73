//! Sizes and durations as people write and read them: the numbers of the
//! budget's errors (`1,200,000,000 numbers (9.6 GB)`) and the SIZE and
//! SECONDS of `--max-memory` and `--timeout` (LANGUAGE.md §1).

use std::time::Duration;

/// `1200000000` as `1,200,000,000`.
pub fn count(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// A size in bytes for people: `9.6 GB`, `400 MB`, `800 kB`.
pub fn bytes(n: u64) -> String {
    let units = [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")];
    let x = n as f64;
    for (size, unit) in units {
        if x >= size {
            let v = x / size;
            return if v >= 100.0 || v.fract() < 0.05 {
                format!("{v:.0} {unit}")
            } else {
                format!("{v:.1} {unit}")
            };
        }
    }
    format!("{n} bytes")
}

/// A duration for people: `2 s`, `0.5 s`, `30 ms`.
pub(super) fn seconds(d: Duration) -> String {
    if d < Duration::from_secs(1) {
        format!("{} ms", d.as_millis())
    } else {
        let s = d.as_secs_f64();
        if s.fract() == 0.0 {
            format!("{s} s")
        } else {
            format!("{s:.1} s")
        }
    }
}

/// `--max-memory`'s SIZE: bytes, or a number with `k`, `M`, `G` or `T`
/// (powers of 1000; `KiB`, `MiB`, `GiB` for powers of 1024; a trailing
/// `B` is optional): `512M`, `2G`, `1.5GB`, `100000000`.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let x: f64 = num.parse().map_err(|_| {
        format!("'{text}' is not a size: write bytes or a number with k, M, G (512M, 2G)")
    })?;
    let scale = match unit.trim().to_ascii_lowercase().as_str() {
        "" | "b" => 1.0,
        "k" | "kb" => 1e3,
        "m" | "mb" => 1e6,
        "g" | "gb" => 1e9,
        "t" | "tb" => 1e12,
        "kib" => 1024.0,
        "mib" => 1024.0 * 1024.0,
        "gib" => 1024.0 * 1024.0 * 1024.0,
        "tib" => 1024.0 * 1024.0 * 1024.0 * 1024.0,
        _ => {
            return Err(format!(
                "'{text}': unknown unit '{unit}' (use k, M, G or T: 512M, 2G)"
            ));
        }
    };
    let b = x * scale;
    if !(b.is_finite() && b >= 1.0) {
        return Err(format!("'{text}' is not a size of at least one byte"));
    }
    Ok(b.min(u64::MAX as f64) as u64)
}

/// `--timeout`'s SECONDS: a positive number of seconds (`2`, `0.5`).
pub fn parse_seconds(text: &str) -> Result<Duration, String> {
    let x: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("'{text}' is not a number of seconds (e.g. 10 or 0.5)"))?;
    if !(x.is_finite() && x > 0.0 && x < 1e9) {
        return Err(format!("'{text}' is not a positive number of seconds"));
    }
    Ok(Duration::from_secs_f64(x))
}
