//! Friendly syntax errors from pest's.
//!
//! Every grammar rule has a human name in [`rule_name`], one exhaustive
//! `match` (as Tera does): adding a rule to the grammar does not compile
//! until it is named. A pest error becomes `expected X or Y, found 'c'`
//! with the caret on the offending character (the last character when the
//! statement ended too early), plus a `help:` line where one helps.

use pest::error::{ErrorVariant, InputLocation};

use super::MAX_DEPTH;
use super::ast::{CmpOp, Span};
use super::grammar::Rule;
use crate::diagnostics::{Diagnostic, ErrorKind};

/// The error for a statement nested deeper than [`MAX_DEPTH`].
pub(crate) fn too_deep(span: Span) -> Diagnostic {
    Diagnostic::error(
        ErrorKind::Syntax,
        span,
        format!("expression nested too deeply (limit {MAX_DEPTH})"),
    )
    .with_help("split it into several statements with intermediate names")
}

/// The statement being reported on: its text and its offset in the source.
struct Cx<'a> {
    off: usize,
    text: &'a str,
}

const EXPRESSION: &str = "an expression";
const OPERATOR: &str = "an operator";
const END: &str = "end of input";
const MECH_ITEM: &str = "a mech item (links N, joints .., legs N CHAIN, planar/spatial/spherical)";

/// What a rule is called in an error message.
pub(crate) fn rule_name(rule: Rule) -> &'static str {
    match rule {
        Rule::EOI => END,
        Rule::WHITESPACE => "a space",
        Rule::statement => "a statement",
        Rule::given_stmt => "a `given` statement",
        Rule::given_name => "a name (or a function of time, `theta(t)`)",
        Rule::derive_stmt => "a `derive` statement",
        Rule::assert_stmt => "an `assert` statement",
        Rule::explain_stmt => "an `explain` statement",
        Rule::fn_def => "a function definition",
        Rule::params => "a parameter name",
        Rule::destructure => "a destructuring assignment",
        Rule::assign => "an assignment",
        Rule::given_type => "a type such as SE3 or SE(3)",
        Rule::sup_group => "a superscript {..}",
        Rule::expr
        | Rule::prefix_op
        | Rule::neg
        | Rule::pos
        | Rule::operand
        | Rule::primary
        | Rule::root
        | Rule::root_arg
        | Rule::call
        | Rule::paren
        | Rule::brackets
        | Rule::row
        | Rule::bool_lit
        | Rule::number
        | Rule::pi
        | Rule::mech
        | Rule::bare_call
        | Rule::bare_fn
        | Rule::bare_arg
        | Rule::deg_unit
        | Rule::plain_row
        | Rule::plain_list
        | Rule::plain_number
        | Rule::kw_mech
        | Rule::juxt_start
        | Rule::index_arg => EXPRESSION,
        Rule::infix_op
        | Rule::add
        | Rule::sub
        | Rule::starstar
        | Rule::mul
        | Rule::div
        | Rule::pow
        | Rule::range_op
        | Rule::eq
        | Rule::approx
        | Rule::lt
        | Rule::le
        | Rule::gt
        | Rule::ge
        | Rule::dot_op
        | Rule::cross_op
        | Rule::juxt
        | Rule::postfix
        | Rule::index
        | Rule::member
        | Rule::degrees
        | Rule::transpose_mark
        | Rule::superscript => OPERATOR,
        Rule::all => "':'",
        Rule::call_args => "'('",
        Rule::row_sep => "';' or a new line",
        Rule::mech_sep => "';'",
        Rule::mech_item
        | Rule::mech_links
        | Rule::mech_joints
        | Rule::mech_legs
        | Rule::mech_space
        | Rule::mech_unknown
        | Rule::mech_keyword
        | Rule::kw_links
        | Rule::kw_joints
        | Rule::kw_legs => MECH_ITEM,
        Rule::joint | Rule::joint_count | Rule::joint_letters => {
            "a joint such as R, P, 8R, RP or 6 sliding"
        }
        Rule::mech_count
        | Rule::legs_count
        | Rule::mech_term
        | Rule::mech_factor
        | Rule::mech_decimal
        | Rule::mech_name => "a whole number",
        Rule::mech_op | Rule::mech_infix | Rule::mech_juxt => OPERATOR,
        Rule::chain => "the joints of a leg, such as UPS",
        Rule::int => "a whole number",
        Rule::ident => "a name",
        Rule::brace_subscript | Rule::frame_word => "a frame name",
        Rule::keyword => "a keyword",
        Rule::kw_given => "`given`",
        Rule::kw_derive => "`derive`",
        Rule::kw_assert => "`assert`",
        Rule::kw_explain => "`explain`",
        Rule::comp_tail | Rule::kw_for => "`for`",
        Rule::comp_var => "a name and `in`",
        Rule::kw_in => "`in`",
        Rule::string => "a string",
    }
}

/// Literal tokens worth naming when pest expected them.
const TOKENS: &[&str] = &[")", "]", ",", ":", ";", "=", "(", "<", ">"];

/// Orders the entries of an "expected …" list.
fn rank(name: &str) -> u8 {
    match name {
        EXPRESSION => 0,
        "a name" => 1,
        OPERATOR => 2,
        END => 9,
        _ if name.starts_with('\'') => 5,
        _ => 3,
    }
}

/// A pest error in the statement `text` (at byte `off` of the source) →
/// a syntax diagnostic pointing into the whole source.
pub(crate) fn pest_error(err: pest::error::Error<Rule>, text: &str, off: usize) -> Diagnostic {
    let cx = &Cx { off, text };
    let mut pos = match err.location {
        InputLocation::Pos(p) => p,
        InputLocation::Span((s, _)) => s,
    };
    let mut names: Vec<&str> = Vec::new();
    let mut tokens: Vec<String> = Vec::new();
    match &err.variant {
        ErrorVariant::ParsingError { positives, .. } => {
            names.extend(positives.iter().map(|r| rule_name(*r)));
        }
        ErrorVariant::CustomError { message } => {
            let span = char_span(cx, pos);
            if message.contains("limit") {
                return too_deep(span);
            }
            return Diagnostic::error(ErrorKind::Syntax, span, message.clone());
        }
    }
    // With error detail on, pest knows the farthest position it reached and
    // what it expected there (rules and literal tokens) — more precise than
    // the rule-only positives.
    if let Some(attempts) = err.parse_attempts() {
        if attempts.max_position > pos {
            // The positives are from an earlier position; use the rules
            // that failed at the farthest one, but not whole statements or
            // bracketed groups (their closing token is in the tokens).
            names.clear();
            pos = attempts.max_position;
            for stack in attempts.call_stacks() {
                if let Some(rule) = stack.deepest.get_rule()
                    && !is_container(*rule)
                {
                    names.push(rule_name(*rule));
                }
            }
        }
        if attempts.max_position == pos {
            for t in attempts.expected_tokens() {
                let t = t.to_string();
                if TOKENS.contains(&t.as_str()) {
                    tokens.push(format!("'{t}'"));
                }
            }
        }
    }
    let pos = pos.min(cx.text.len());
    let found_char = cx.text.get(pos..).and_then(|s| s.chars().next());
    let span = char_span(cx, pos);

    let mut names: Vec<String> = names
        .into_iter()
        // At the start, a statement is expected: say "an expression". Later
        // pest names the whole statement only as a fallback.
        .filter(|n| pos == 0 || *n != "a statement")
        .map(|n| if n == "a statement" { EXPRESSION } else { n })
        .map(str::to_string)
        .collect();
    names.extend(tokens);
    names.sort_by(|a, b| (rank(a), a).cmp(&(rank(b), b)));
    names.dedup();
    // A `(` is already part of "an expression" and of "an operator".
    if names.iter().any(|n| n == EXPRESSION || n == OPERATOR) {
        names.retain(|n| n != "'('" && n != "a name");
    }
    // A range's `:` and the orders `<`, `>` are operators (`0:4`, `a < b`).
    if names.iter().any(|n| n == OPERATOR) {
        names.retain(|n| n != "':'" && n != "'<'" && n != "'>'");
    }
    // A count in a mechanism (`links N`, `legs (n) UPS`) is "a whole number".
    if names.iter().any(|n| n == "a whole number") {
        names.retain(|n| n != "'('");
    }
    if found_char.is_none() {
        names.retain(|n| n != END);
    }
    // Right after a word, a name cannot start (it would continue the word):
    // pest's attempt there comes from a keyword's lookahead.
    let after_word = cx.text[..pos]
        .chars()
        .next_back()
        .is_some_and(|c| c.is_alphanumeric() || c == '_');
    if after_word && names.len() > 1 {
        names.retain(|n| n != "a name");
    }

    let found = match found_char {
        None => "end of input".to_string(),
        Some('\n') => "end of line".to_string(),
        Some(' ' | '\t') => "a space".to_string(),
        Some(c) if let Some(what) = invisible(c) => format!("{what} (U+{:04X})", c as u32),
        Some(c) => format!("'{c}'"),
    };
    let message = if names.is_empty() {
        format!("unexpected {found}")
    } else {
        format!("expected {}, found {found}", or_list(&names))
    };
    let diag = Diagnostic::error(ErrorKind::Syntax, span, message);
    match help(cx.text, pos, found_char, &names) {
        Some(h) => diag.with_help(h),
        None => diag,
    }
}

/// Statements and bracketed groups: when pest stopped inside one, what it
/// wanted is its next token, not the rule itself.
fn is_container(rule: Rule) -> bool {
    matches!(
        rule,
        Rule::statement
            | Rule::given_stmt
            | Rule::given_name
            | Rule::derive_stmt
            | Rule::assert_stmt
            | Rule::explain_stmt
            | Rule::fn_def
            | Rule::destructure
            | Rule::assign
            | Rule::mech
            | Rule::paren
            | Rule::brackets
            | Rule::call_args
            | Rule::index
    )
}

/// The character at `pos` of the statement, or its last character when
/// `pos` is the end.
fn char_span(cx: &Cx<'_>, pos: usize) -> Span {
    let pos = pos.min(cx.text.len());
    match cx.text.get(pos..).and_then(|s| s.chars().next()) {
        Some(c) => Span::new(cx.off + pos, cx.off + pos + c.len_utf8()),
        None => {
            let last = cx.text.chars().next_back().map_or(0, char::len_utf8);
            let end = cx.off + cx.text.len();
            Span::new(end - last, end)
        }
    }
}

/// `a, b or c`
fn or_list(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} or {last}", init.join(", ")),
    }
}

/// What an invisible or space-like character is, named where printing it
/// would show nothing or a plain-looking space (a no-break space copied
/// from a PDF of the book).
fn invisible(c: char) -> Option<&'static str> {
    Some(match c {
        '\u{a0}' | '\u{202f}' => "a no-break space",
        '\u{2000}'..='\u{200a}' => "a typographic space",
        '\u{200b}' => "a zero-width space",
        '\u{200c}' | '\u{200d}' | '\u{2060}' => "a zero-width joiner",
        '\u{feff}' => "a zero-width no-break space (a byte-order mark)",
        '\u{3000}' => "an ideographic space",
        _ => return None,
    })
}

/// A hint for common mistakes at `pos`.
fn help(text: &str, pos: usize, found: Option<char>, expected: &[String]) -> Option<String> {
    let before = text.get(..pos).unwrap_or("").trim_end();
    let wants = |s: &str| expected.iter().any(|e| e == s);
    if let Some(what) = found.and_then(invisible) {
        return Some(format!(
            "{what} looks like a space but is not one (text copied from a PDF or a web page carries them): write a plain space, or delete it"
        ));
    }
    match found? {
        c if c.is_alphabetic() && before.starts_with("given") && wants("':'") => Some(
            "the type follows a colon: given T_ab, T_bc : SE3 (scalars need none: given α, β)"
                .into(),
        ),
        '*' if before.ends_with('*') => Some("use ^ for powers: x^2".into()),
        '!' => Some("there is no `!=`: write (a == b) == false".into()),
        '=' if before.ends_with('=') => {
            Some("`==` compares (a bool); to bind a name write `name = expr`".into())
        }
        '=' if before.ends_with("given") => {
            Some("`given` declares symbols: given T_ab, T_bc : SE3".into())
        }
        '=' if before
            .rsplit(['\n', ';'])
            .next()
            .is_some_and(|s| s.trim_start().starts_with("explain ")) =>
        {
            Some(
            "explain takes an expression, not a binding: write `explain log(R)`; to keep the value, bind it on a line of its own, `w = log(R)`"
                .into(),
            )
        }
        '=' if wants(OPERATOR) || wants(END) => Some(
            "only a name, a tuple of names `(a, b)` or a function `f(x)` can be assigned to"
                .into(),
        ),
        ',' if wants(END) => {
            Some("to write a vector, put it in parentheses or brackets: (1, 2, 3)".into())
        }
        ',' if before.rfind("_{") > before.rfind('}') => {
            Some("a braced subscript names one or two frames: T_{world,cam}".into())
        }
        '\'' => Some("`'` is part of a name (T_sb'); to transpose write x^T, xᵀ or x.T".into()),
        '<' | '>' if wants(OPERATOR) || wants(END) => Some(
            "comparisons are `==`, `≈` (typed `~=`), `<`, `<=`, `>`, `>=`; a mechanism is mech < links 4; joints 4R; planar >"
                .into(),
        ),
        '{' | '}' => Some(
            "braces only appear in frame subscripts, T_{world,cam}, and superscripts, R^{T}".into(),
        ),
        // (`2.` with no digit after the point; `2.5` where a whole number
        // is wanted, `joints 2.5R`, is no decimal to mend)
        '.' if before.ends_with(|c: char| c.is_ascii_digit())
            && !text
                .get(pos + 1..)
                .is_some_and(|t| t.starts_with(|c: char| c.is_ascii_digit())) =>
        {
            Some("write decimals with digits after the point: 2.0 or 2".into())
        }
        '.' if before.ends_with(|c: char| c.is_ascii_digit())
            && expected
                .iter()
                .any(|e| e.contains("whole number") || e.contains("joint")) =>
        {
            Some("a count is a whole number: 2, not 2.5".into())
        }
        // (the book's θ₁ and x², copied as typeset)
        '₀'..='₉' => Some(subscript_help(text, pos)),
        '⁰'..='⁹' | '¹' | '²' | '³' => Some(
            "a superscript power follows a name or a bracket (R², [w]³); after a number write 2^2"
                .into(),
        ),
        _ => None,
    }
}

/// The help for a subscript digit at `pos` (the book's θ₁, S₂): the name
/// spelled with plain digits, `θ1` (an index, LANGUAGE.md §2), or with
/// an underscore, `θ_1`.
fn subscript_help(text: &str, pos: usize) -> String {
    let digit = |c: char| ('₀'..='₉').contains(&c);
    let rest = text.get(pos..).unwrap_or("");
    let digits: String = rest
        .chars()
        .take_while(|&c| digit(c))
        .map(|c| char::from(b'0' + (u32::from(c) - u32::from('₀')) as u8))
        .collect();
    let before = text.get(..pos).unwrap_or("");
    let name: String = before
        .chars()
        .rev()
        .take_while(|&c| c.is_alphanumeric() || c == '_')
        .collect::<Vec<_>>()
        .into_iter()
        .rev()
        .collect();
    if name.is_empty() {
        return format!("subscript digits are not part of names or numbers: write {digits}");
    }
    format!(
        "subscript digits are not part of names: write {name}{digits} or {}_{digits}",
        name.trim_end_matches('_')
    )
}

/// The comparison a rule stands for (`==`, `≈`/`~=`), if any.
pub(super) fn cmp_op(rule: Rule) -> Option<CmpOp> {
    match rule {
        Rule::eq => Some(CmpOp::Eq),
        Rule::approx => Some(CmpOp::Approx),
        Rule::lt => Some(CmpOp::Lt),
        Rule::le => Some(CmpOp::Le),
        Rule::gt => Some(CmpOp::Gt),
        Rule::ge => Some(CmpOp::Ge),
        _ => None,
    }
}
