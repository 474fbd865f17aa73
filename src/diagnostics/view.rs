//! The source lines a diagnostic echoes, made safe to print: control
//! characters escaped (`\0`, `\x1b`: a script must not be able to move the
//! cursor or recolour the terminal of whoever reads its errors), and a line
//! longer than [`MAX_LINE`] bytes cut to windows of [`CONTEXT`] bytes
//! around the spans on it, with `…` where text was left out (an error in a
//! 10 MB line echoes a few hundred bytes). The spans are carried over to
//! the new text, so carets still point at what they labelled.

use super::escape;

/// Lines up to this many bytes are echoed whole.
pub const MAX_LINE: usize = 240;

/// Bytes kept on each side of a span on a long line.
pub const CONTEXT: usize = 80;

/// The largest char boundary of `s` at or below `i`.
fn floor(s: &str, i: usize) -> usize {
    let mut i = i.min(s.len());
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The text of `src[base..end]` (whole lines) as echoed, and where each of
/// `points` (offsets into `src`, within `base..=end`) lies in it.
pub fn view(src: &str, base: usize, end: usize, points: &[usize]) -> (String, Vec<usize>) {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_by_key(|&i| points[i]);
    let mut pending = order.into_iter().peekable();
    let mut mapped = vec![0; points.len()];
    let mut out = String::new();
    // Every point at or before `pos` lies at `at` in the output.
    let mut settle = |pos: usize, at: usize, mapped: &mut Vec<usize>| {
        while let Some(&i) = pending.peek() {
            if points[i] > pos {
                break;
            }
            mapped[i] = at;
            pending.next();
        }
    };
    let mut start = base;
    while start <= end {
        let stop = src[start..end].find('\n').map_or(end, |i| start + i);
        let parts = pieces(src, start, stop, points);
        for &(from, to, gap_before) in &parts {
            if gap_before {
                settle(from - 1, out.len(), &mut mapped);
                out.push('…');
            }
            for (i, c) in src[from..to].char_indices() {
                settle(from + i, out.len(), &mut mapped);
                match c {
                    '\t' => out.push('\t'),
                    // a CRLF line's break, not a character of the line
                    '\r' if from + i + 1 == stop => {}
                    c => out.push_str(&escape::controls(c.encode_utf8(&mut [0; 4]))),
                }
            }
        }
        if let Some(&(_, to, _)) = parts.last()
            && to < stop
        {
            settle(to, out.len(), &mut mapped);
            out.push('…');
        }
        settle(stop, out.len(), &mut mapped);
        if stop >= end {
            break;
        }
        out.push('\n');
        start = stop + 1;
    }
    settle(usize::MAX, out.len(), &mut mapped);
    (out, mapped)
}

/// The parts of the line `src[start..stop]` to echo: all of it when short,
/// else windows around the points on it (merged where they overlap), each
/// with whether text was left out before it.
fn pieces(src: &str, start: usize, stop: usize, points: &[usize]) -> Vec<(usize, usize, bool)> {
    if stop - start <= MAX_LINE {
        return vec![(start, stop, false)];
    }
    let mut on: Vec<usize> = points
        .iter()
        .copied()
        .filter(|&p| p >= start && p <= stop)
        .collect();
    if on.is_empty() {
        on.push(start);
    }
    on.sort_unstable();
    let mut windows: Vec<(usize, usize)> = Vec::new();
    for p in on {
        let lo = floor(src, p.saturating_sub(CONTEXT).max(start));
        let hi = floor(src, (p + CONTEXT).min(stop));
        match windows.last_mut() {
            Some(last) if lo <= last.1 => last.1 = last.1.max(hi),
            _ => windows.push((lo, hi)),
        }
    }
    let mut prev = start;
    windows
        .into_iter()
        .map(|(lo, hi)| {
            let gap = lo > prev;
            prev = hi;
            (lo, hi, gap)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_lines_are_kept_with_controls_escaped() {
        let src = "x = \"a\x1bb\"\ny\0 = 1";
        let (text, at) = view(src, 0, src.len(), &[4, 9, 11, 12]);
        assert_eq!(text, "x = \"a\\x1bb\"\ny\\0 = 1");
        // The quote, the end of line 1, the NUL, the space after it.
        assert_eq!(at, [4, 12, 14, 16]);
    }

    #[test]
    fn long_lines_are_cut_around_the_spans() {
        let line = format!("{}BAD{}", "a".repeat(10_000), "b".repeat(10_000));
        let (text, at) = view(&line, 0, line.len(), &[10_000, 10_003]);
        assert!(text.len() < 2 * CONTEXT + 20, "{}", text.len());
        assert!(text.starts_with('…') && text.ends_with('…'), "{text}");
        assert_eq!(&text[at[0]..at[1]], "BAD");
        // Two spans far apart: two windows.
        let (text, at) = view(&line, 0, line.len(), &[5, 19_990]);
        assert_eq!(text.matches('…').count(), 1, "{text}");
        assert_eq!(&text[at[0]..at[0] + 1], "a");
        assert_eq!(&text[at[1]..at[1] + 1], "b");
    }
}
