//! Long symbolic expressions on lines (LANGUAGE.md §7 printing): a sum is
//! broken before a `+` or `-` where its line would pass the width, and a
//! term too long for a line — a factored group of a tilted chain's entry,
//! `((…) cos(t3) + …) cos(t2)` — is broken the same way inside its groups,
//! each continuation line under the first term of its group.

use super::print::text_width;

/// Signed terms joined, broken before a `+` or `-` where a line would pass
/// `width`, continuation lines indented by `indent`.
pub fn join(ts: &[(bool, String)], width: usize, indent: usize) -> String {
    join_from(ts, width, indent, 0)
}

/// [`join`] of a sum whose first line starts at column `start` of the
/// screen (after `x = ` or `[`): where a term is broken inside its groups,
/// their continuation lines are indented under their first terms.
pub fn join_from(ts: &[(bool, String)], width: usize, indent: usize, start: usize) -> String {
    if ts.is_empty() {
        return "0".into();
    }
    let mut out = String::new();
    let mut line = 0usize;
    for (i, (neg, body)) in ts.iter().enumerate() {
        let piece = match (i, neg) {
            (0, false) => body.clone(),
            (0, true) => format!("-{body}"),
            (_, false) => format!(" + {body}"),
            (_, true) => format!(" - {body}"),
        };
        let (col, p) = if i > 0 && line + text_width(&piece) > width {
            out.push('\n');
            out.push_str(&" ".repeat(indent));
            (indent, piece.trim_start())
        } else {
            (line, piece.as_str())
        };
        // a term too long for the line breaks inside its groups
        // (the first line counts from 0, the others from the screen's edge)
        let shift = if out.contains('\n') { 0 } else { start };
        let p = wrap(p, col + shift, width.saturating_add(shift));
        line = match p.rsplit_once('\n') {
            Some((_, last)) => text_width(last),
            None => col + text_width(&p),
        };
        out.push_str(&p);
    }
    out
}

/// A term that starts at column `col` broken where it would pass `width`,
/// before a `+` or `-` inside a group's parentheses (not inside a call's
/// argument, `cos(t1 + t2)`, nor a denominator) whose term up to the next
/// one of its group does not fit on the line, each continuation line
/// indented under the first term of its group: the rule [`join`] follows
/// for the terms of a sum, applied inside each factored group.
fn wrap(piece: &str, col: usize, width: usize) -> String {
    if width == usize::MAX || col + text_width(piece) <= width {
        return piece.to_string();
    }
    // each ` + ` / ` - ` directly inside a group, and where its term ends:
    // at the next one of the same group or at the group's `)`
    let b = piece.as_bytes();
    let mut groups: Vec<(bool, Option<usize>)> = Vec::new();
    let mut breaks: Vec<(usize, usize)> = Vec::new();
    // the last terms of closed groups: they end with what follows the `)`
    // (`… - 0.03 sin(t5)) cos(t2 + t6)`), at the next break
    let mut tails: Vec<usize> = Vec::new();
    for (i, &c) in b.iter().enumerate() {
        match c {
            b'(' => {
                let before = i.checked_sub(1).map(|j| b[j]);
                let call = before.is_some_and(|x| x.is_ascii_alphanumeric() || x == b'/');
                groups.push((!call, None));
            }
            b')' => {
                if let Some((_, Some(k))) = groups.pop() {
                    tails.push(k);
                }
            }
            b' ' if matches!(b.get(i + 1), Some(b'+' | b'-')) && b.get(i + 2) == Some(&b' ') => {
                if let Some((true, last)) = groups.last_mut() {
                    for k in last.iter().chain(&tails) {
                        breaks[*k].1 = i;
                    }
                    tails.clear();
                    *last = Some(breaks.len());
                    breaks.push((i, piece.len()));
                }
            }
            _ => {}
        }
    }
    let mut out = String::new();
    let (mut line, mut from) = (col, 0);
    // the column after each open `(` on the output
    let mut opened: Vec<usize> = Vec::new();
    let ends = breaks
        .iter()
        .map(|x| x.0)
        .chain(std::iter::once(piece.len()));
    for (k, end) in ends.enumerate() {
        let mut seg = &piece[from..end];
        if k > 0 {
            let (at, term_end) = breaks[k - 1];
            let indent = opened.last().copied().unwrap_or(col);
            if line > indent && line + text_width(&piece[at..term_end]) > width {
                out.push('\n');
                out.push_str(&" ".repeat(indent));
                line = indent;
                seg = seg.trim_start();
            }
        }
        for ch in seg.chars() {
            match ch {
                '(' => opened.push(line + 1),
                ')' => {
                    opened.pop();
                }
                _ => {}
            }
            line += text_width(ch.encode_utf8(&mut [0; 4]));
            out.push(ch);
        }
        from = end;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The text with its line breaks and their indents taken out.
    fn flat(s: &str) -> String {
        s.lines().map(str::trim_start).collect::<Vec<_>>().join(" ")
    }

    #[test]
    fn a_long_group_breaks_inside_under_its_first_term() {
        let piece = "((aaaa + bbbb cos(t3 + t4) + cccc) cos(t2) - (dddd + eeee) sin(t2)) cos(t1)";
        let out = wrap(piece, 4, 40);
        // from column 4: `+ cccc` under `aaaa`, `- (dddd` under `(aaaa`
        assert_eq!(
            out,
            "((aaaa + bbbb cos(t3 + t4)\n      + cccc) cos(t2)\n     - (dddd + eeee) sin(t2)) cos(t1)"
        );
        assert_eq!(flat(&out), piece);
        // a call's argument and a denominator are never broken
        let piece = "(aaaa cos(t1 + t2 + t3 + t4) + 1/(bbbb + cccc + dddd)) cos(t5)";
        for w in [10, 20, 30] {
            let out = wrap(piece, 0, w);
            assert_eq!(flat(&out), piece);
            assert!(
                out.contains("cos(t1 + t2 + t3 + t4)") && out.contains("1/(bbbb + cccc + dddd)")
            );
        }
        // what fits is left alone
        assert_eq!(wrap(piece, 0, 100), piece);
        assert_eq!(wrap(piece, 0, usize::MAX), piece);
    }
}
