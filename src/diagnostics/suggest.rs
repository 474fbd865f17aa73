//! "Did you mean …?" by edit distance, for unknown names and functions.

/// Levenshtein distance between two strings (by characters).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(!ca.eq_ignore_ascii_case(cb));
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The closest candidate within a third of the name's length (at least 1),
/// or one that differs only in case or underscores. A candidate that
/// shares nothing with the name (`S` → `I`: every character replaced) is
/// no suggestion.
///
/// The answer depends on the set of candidates only, never on their order:
/// ties (`R_sc` is one edit from both `R_sa` and `R_sb`) go to the shorter,
/// then the first in text order. Callers pass the bindings of a session,
/// kept in a hash map whose order differs from one process to the next, and
/// `chasles check` and `chasles lsp` must name the same suggestion.
pub fn did_you_mean<'a>(name: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let squash = |s: &str| s.to_lowercase().replace('_', "");
    if let Some(c) = candidates
        .iter()
        .filter(|c| squash(c) == squash(name))
        .min_by_key(|c| (c.len(), **c))
    {
        return Some(c);
    }
    let limit = (name.chars().count() / 3).max(1);
    candidates
        .iter()
        .map(|c| (edit_distance(name, c), *c))
        .filter(|(d, c)| *d <= limit && *d < name.chars().count().max(c.chars().count()))
        .min_by_key(|(d, c)| (*d, c.len(), *c))
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_close_names() {
        assert_eq!(
            did_you_mean("MatrixLog", &["MatrixLog3", "MatrixLog6", "Ad"]),
            Some("MatrixLog3")
        );
        assert_eq!(
            did_you_mean("matrixlog6", &["MatrixLog3", "MatrixLog6"]),
            Some("MatrixLog6")
        );
        assert_eq!(did_you_mean("T_ab", &["T_ac", "zzz"]), Some("T_ac"));
        assert_eq!(did_you_mean("qqqq", &["MatrixLog3"]), None);
        assert_eq!(did_you_mean("S", &["I", "e"]), None);
        assert_eq!(did_you_mean("x", &["x1", "I"]), Some("x1"));
    }

    /// A session's bindings come in hash-map order, different in every
    /// process: the suggestion must not depend on it (`chasles check` and
    /// `chasles lsp` named `R_sa` and `R_sb` for one unknown `R_sc`).
    #[test]
    fn ties_do_not_depend_on_the_order_of_the_candidates() {
        let names = ["R_sb", "Rotz", "R_sa", "T_sc", "p_sc"];
        let mut reversed = names;
        reversed.reverse();
        assert_eq!(did_you_mean("R_sc", &names), Some("R_sa"));
        assert_eq!(did_you_mean("R_sc", &reversed), Some("R_sa"));
        assert_eq!(did_you_mean("tab", &["T_ab", "Ta_b"]), Some("T_ab"));
        assert_eq!(did_you_mean("tab", &["Ta_b", "T_ab"]), Some("T_ab"));
    }
}
