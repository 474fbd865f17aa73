//! A symbolic result is the same kind of value as the numeric one (issue
//! 21; LANGUAGE.md §§1, 5, 7): `euler_zyx` of a symbolic rotation is a
//! 3-vector, as it is of numbers — printed with its label, `"kind":
//! "vector"` in JSON — not a tuple. Driven by the one builtin table
//! (`chasles::builtins::table()`): each row's example with one of its
//! numbers made a free symbol `a` must give the kind the example gives with
//! the number typed.

mod common;

use serde_json::Value as J;

/// What a JSON record says the value is: its type, or for a symbolic value
/// the kind it carries (a formula's own, a kept call's from the checker).
fn kind_of(r: &J) -> String {
    let ty = r["type"].as_str().unwrap_or("").to_string();
    if ty == "symbolic" {
        return r["kind"].as_str().unwrap_or("(no kind)").to_string();
    }
    ty
}

/// The last record of `src` in JSON, None when it fails.
fn last(src: &str) -> Option<J> {
    common::try_json(src).ok()?.pop()
}

/// Builtins whose examples read symbols or write files.
fn skipped(name: &str, example: &str) -> bool {
    matches!(name, "diff" | "subs" | "save") || example.contains("given")
}

#[test]
fn every_builtin_on_a_free_symbol_gives_the_kind_numbers_give() {
    let mut found = Vec::new();
    let mut ran = 0;
    for b in chasles::builtins::table() {
        let ex = b.example;
        if skipped(b.name, ex) {
            continue;
        }
        let Some(typed) = last(&format!("y = {ex}")) else {
            continue;
        };
        for &(s, e) in common::literals(ex).iter().take(4) {
            let expr = format!("{}a{}", &ex[..s], &ex[e..]);
            let Some(sym) = last(&format!("given a : scalar\ny = {expr}")) else {
                continue;
            };
            ran += 1;
            if sym["type"] == "tuple" && typed["type"] != "tuple" {
                found.push(format!(
                    "{}: `{expr}` is a tuple, typed first {}",
                    b.name,
                    kind_of(&typed)
                ));
            } else if sym["type"] == "symbolic"
                && kind_of(&sym) != kind_of(&typed)
                // a call kept over its symbols whose kind depends on the
                // numbers (`eye(a)`, `log` of a literal) is a matrix
                && (sym.get("latex").is_some() || kind_of(&sym) != "matrix")
            {
                found.push(format!(
                    "{}: `{expr}` is {}, typed first {}",
                    b.name,
                    kind_of(&sym),
                    kind_of(&typed)
                ));
            }
        }
    }
    assert!(ran > 60, "only {ran} cases");
    assert!(found.is_empty(), "{}", found.join("\n"));
}
