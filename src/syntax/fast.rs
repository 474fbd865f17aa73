//! A fast path for ordinary statements: a hand-written recursive-descent
//! parser for most of the grammar, run before pest.
//!
//! It follows `grammar/chasles.pest` and the tree building of `parser.rs`
//! rule by rule (the same ordered choices, the same whitespace, the same
//! spans and precedence) and produces the same [`Stmt`]. It gives up — returns
//! `None` — whenever it is not sure: at any syntax error, at anything the
//! grammar would backtrack over, and at the rare forms it leaves to pest
//! (`given`, `derive`, `mech < >`, braced subscripts `T_{a,b}`, `**`, deep or
//! long operator chains). The caller then parses the statement with pest,
//! which gives the error messages. So this parser must never accept a
//! statement pest rejects nor build a different tree; the test
//! `fast_path_agrees_with_pest` compares the two.
//!
//! It is some ten times faster than pest plus the Pratt builder: no parse
//! queue, no backtracking state, no rule calls per character.

use super::MAX_DEPTH;
use super::ast::{BinOp, Expr, ExprKind, Ident, IndexArg, Span, Stmt, StmtKind, UnOp};

/// At most this many operators, postfixes and brackets per statement, so
/// that both the tree depth and the recursion stay far below
/// [`MAX_DEPTH`] (the pest path reports the limit).
const BUDGET: usize = 100;

/// Pratt binding powers, as in `parser.rs`'s `PRATT` (10 per level).
const BP_ADD: u8 = 10;
const BP_MUL: u8 = 20;
const BP_PREFIX: u8 = 30;
const BP_POW: u8 = 40;

/// The grammar rule an operand starts or ends with (the first and last
/// inner pair of pest's `operand`), for the juxtaposition check.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Number,
    Pi,
    Degrees,
    Brackets,
    Paren,
    Ident,
    Call,
    Bool,
    Index,
    Member,
}

/// Parses the statement at `span` of `text`, or `None` to leave it to pest.
/// `chunk` is the statement's text (comments blanked), `span` its place in
/// the source.
pub(crate) fn parse_statement(chunk: &str, span: Span) -> Option<Stmt> {
    let src = chunk;
    if src.starts_with("given") || src.starts_with("derive") {
        return None;
    }
    let mut p = P {
        src,
        s: src.as_bytes(),
        pos: 0,
        off: span.start,
        budget: BUDGET,
        last: Kind::Number,
        juxt_left: None,
    };
    let kind = p.statement()?;
    p.ws();
    (p.pos == p.s.len()).then_some(Stmt { kind, span })
}

type Built = Option<(Expr, usize)>;

struct P<'a> {
    src: &'a str,
    s: &'a [u8],
    pos: usize,
    /// Offset of the statement in the source.
    off: usize,
    budget: usize,
    /// The last kind of the operand parsed last.
    last: Kind,
    /// Set by a juxtaposition: the last kind of its left operand, checked
    /// against the first kind of the next operand.
    juxt_left: Option<Kind>,
}

fn is_ws(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\x0C')
}

fn xid_start(c: char) -> bool {
    if c.is_ascii() {
        c.is_ascii_alphabetic()
    } else {
        pest::unicode::XID_START(c)
    }
}

fn xid_continue(c: char) -> bool {
    if c.is_ascii() {
        c.is_ascii_alphanumeric() || c == '_'
    } else {
        pest::unicode::XID_CONTINUE(c)
    }
}

const KEYWORDS: [&str; 8] = ["pi", "π", "deg", "true", "false", "given", "derive", "mech"];

impl P<'_> {
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.off + start, self.off + end)
    }

    fn ws(&mut self) {
        while self.pos < self.s.len() && is_ws(self.s[self.pos]) {
            self.pos += 1;
        }
    }

    fn byte(&self, at: usize) -> Option<u8> {
        self.s.get(at).copied()
    }

    fn char_at(&self, at: usize) -> Option<char> {
        match self.s.get(at) {
            Some(&b) if b.is_ascii() => Some(b as char),
            Some(_) => self.src.get(at..)?.chars().next(),
            None => None,
        }
    }

    /// `!XID_CONTINUE` at `at`.
    fn word_ends(&self, at: usize) -> bool {
        !self.char_at(at).is_some_and(xid_continue)
    }

    /// `word ~ !XID_CONTINUE` at `at`: the end of the word.
    fn keyword_at(&self, at: usize, word: &str) -> Option<usize> {
        let end = at + word.len();
        (self.s.get(at..end) == Some(word.as_bytes()) && self.word_ends(end)).then_some(end)
    }

    fn spend(&mut self) -> Option<()> {
        self.budget = self.budget.checked_sub(1)?;
        Some(())
    }

    /// The grammar's `ident` at `at`: `Some(Some(end))`, `Some(None)` where
    /// pest's `ident` fails, `None` to give up (a braced subscript).
    fn ident_at(&self, at: usize) -> Option<Option<usize>> {
        match self.char_at(at) {
            Some(c) if xid_start(c) => {}
            _ => return Some(None),
        }
        let mut i = at;
        while let Some(c) = self.char_at(i) {
            if c == '_' && self.byte(i + 1) == Some(b'{') {
                return None;
            }
            if !(xid_continue(c) || c == '\'') {
                break;
            }
            i += c.len_utf8();
        }
        // `!keyword`: a keyword not followed by XID_CONTINUE or `'`, i.e.
        // the whole run of name characters.
        let word = &self.src[at..i];
        if KEYWORDS.contains(&word) || word == "for" {
            return Some(None);
        }
        Some(Some(i))
    }

    fn ident(&self, start: usize, end: usize) -> Ident {
        Ident {
            name: self.src[start..end].to_string(),
            span: self.span(start, end),
        }
    }

    /// A name at the current position (after whitespace), or `None`.
    fn name(&mut self) -> Option<Ident> {
        self.ws();
        let start = self.pos;
        let end = self.ident_at(start)??;
        self.pos = end;
        Some(self.ident(start, end))
    }

    fn eat(&mut self, b: u8) -> bool {
        self.ws();
        if self.byte(self.pos) == Some(b) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn statement(&mut self) -> Option<StmtKind> {
        match self.byte(0)? {
            b'(' => {
                if let Some(targets) = self.destructure_head() {
                    let value = self.expr(0)?.0;
                    return Some(StmtKind::Destructure { targets, value });
                }
                self.pos = 0;
            }
            _ => {
                if let Some(end) = self.ident_at(0)? {
                    self.pos = end;
                    self.ws();
                    match self.byte(self.pos) {
                        Some(b'(') => {
                            if let Some(params) = self.fn_def_head() {
                                let name = self.ident(0, end);
                                let body = self.expr(0)?.0;
                                return Some(StmtKind::FnDef { name, params, body });
                            }
                        }
                        Some(b'=') => {
                            self.pos += 1;
                            let target = self.ident(0, end);
                            let value = self.expr(0)?.0;
                            return Some(StmtKind::Assign { target, value });
                        }
                        _ => {}
                    }
                    self.pos = 0;
                }
            }
        }
        Some(StmtKind::Expr(self.expr(0)?.0))
    }

    /// `"(" ~ ident ~ ("," ~ ident)+ ~ ","? ~ ")" ~ "="`, or `None` where
    /// `destructure` fails before its expression.
    fn destructure_head(&mut self) -> Option<Vec<Ident>> {
        self.pos = 1;
        let mut targets = vec![self.name()?];
        while self.eat(b',') {
            match self.name() {
                Some(t) => targets.push(t),
                None => break,
            }
        }
        (targets.len() >= 2 && self.eat(b')') && self.eat(b'=')).then_some(targets)
    }

    /// `"(" ~ params? ~ ")" ~ "="` after the name, or `None` where `fn_def`
    /// fails before its body.
    fn fn_def_head(&mut self) -> Option<Vec<Ident>> {
        self.pos += 1;
        let mut params = Vec::new();
        if let Some(first) = self.name() {
            params.push(first);
            while self.eat(b',') {
                params.push(self.name()?);
            }
        }
        (self.eat(b')') && self.eat(b'=')).then_some(params)
    }

    /// `expr`, Pratt-parsed with binding power `rbp`.
    fn expr(&mut self, rbp: u8) -> Built {
        self.ws();
        let start = self.pos;
        let (mut lhs, mut depth) = match self.byte(start) {
            Some(b @ (b'-' | b'+')) => {
                self.spend()?;
                self.pos += 1;
                self.ws();
                let (operand, d) = self.expr(BP_PREFIX - 1)?;
                let op = if b == b'-' { UnOp::Neg } else { UnOp::Pos };
                let span = self.span(start, start + 1).join(operand.span);
                let kind = ExprKind::Unary {
                    op,
                    operand: Box::new(operand),
                };
                (Expr { kind, span }, d + 1)
            }
            _ => self.operand()?,
        };
        loop {
            let save = self.pos;
            self.ws();
            let at = self.pos;
            let Some(b) = self.byte(at) else {
                self.pos = save;
                break;
            };
            let (op, bp, width) = match b {
                b'+' => (Some(BinOp::Add), BP_ADD, 1),
                b'-' => (Some(BinOp::Sub), BP_ADD, 1),
                b'*' if self.byte(at + 1) == Some(b'*') => return None,
                b'*' => (Some(BinOp::Mul), BP_MUL, 1),
                b'/' => (Some(BinOp::Div), BP_MUL, 1),
                b'^' => (Some(BinOp::Pow), BP_POW, 1),
                _ if self.juxt_start(at) => (None, BP_MUL, 0),
                _ => {
                    self.pos = save;
                    break;
                }
            };
            if rbp >= bp {
                self.pos = save;
                break;
            }
            self.spend()?;
            self.pos = at + width;
            let left_last = self.last;
            if op.is_none() {
                self.juxt_left = Some(left_last);
            }
            let (rhs, dr) = self.expr(if op == Some(BinOp::Pow) { bp - 1 } else { bp })?;
            let (op, implicit, op_span) = match op {
                Some(op) => (op, false, self.span(at, at + 1)),
                None => (
                    BinOp::Mul,
                    true,
                    Span::new(lhs.span.end, rhs.span.start.max(lhs.span.end)),
                ),
            };
            let span = lhs.span.join(rhs.span);
            let kind = ExprKind::Binary {
                op,
                lhs: Box::new(lhs),
                rhs: Box::new(rhs),
                op_span,
                implicit,
            };
            lhs = Expr { kind, span };
            depth = depth.max(dr) + 1;
        }
        (depth <= MAX_DEPTH).then_some((lhs, depth))
    }

    /// `juxt_start`: `"(" | "[" | ASCII_DIGIT | "." ~ ASCII_DIGIT | XID_START`.
    fn juxt_start(&self, at: usize) -> bool {
        match self.byte(at) {
            Some(b'(' | b'[' | b'0'..=b'9') => true,
            Some(b'.') => self.byte(at + 1).is_some_and(|b| b.is_ascii_digit()),
            _ => self.char_at(at).is_some_and(xid_start),
        }
    }

    /// Checks a juxtaposition `left right` as `check_juxtaposition` does,
    /// once the right operand's first pair is known.
    fn check_juxt(&mut self, first: Kind) -> Option<()> {
        if let Some(last) = self.juxt_left.take() {
            let numeric_left = matches!(last, Kind::Number | Kind::Pi | Kind::Degrees);
            let left_ok = numeric_left || matches!(last, Kind::Brackets | Kind::Paren);
            if !left_ok || (numeric_left && first == Kind::Number) {
                return None;
            }
        }
        Some(())
    }

    /// `number`: the end of the literal at `at`, if any.
    fn number_at(&self, at: usize) -> Option<usize> {
        let digits = |mut i: usize| {
            while self.byte(i).is_some_and(|b| b.is_ascii_digit()) {
                i += 1;
            }
            i
        };
        let mut i = digits(at);
        if i > at {
            if self.byte(i) == Some(b'.') {
                let j = digits(i + 1);
                if j > i + 1 {
                    i = j;
                }
            }
        } else if self.byte(at) == Some(b'.') {
            i = digits(at + 1);
            if i == at + 1 {
                return None;
            }
        } else {
            return None;
        }
        if matches!(self.byte(i), Some(b'e' | b'E')) {
            let mut j = i + 1;
            if matches!(self.byte(j), Some(b'+' | b'-')) {
                j += 1;
            }
            let k = digits(j);
            if k > j {
                i = k;
            }
        }
        Some(i)
    }

    /// `degrees` at `at`: its end.
    fn degrees_at(&self, at: usize) -> Option<usize> {
        if self.src[at..].starts_with('°') {
            return Some(at + '°'.len_utf8());
        }
        self.keyword_at(at, "deg")
    }

    fn leaf(&self, kind: ExprKind, start: usize, end: usize) -> (Expr, usize) {
        let span = self.span(start, end);
        (Expr { kind, span }, 1)
    }

    /// `operand`: an atom with its postfix operators. Sets `self.last`.
    fn operand(&mut self) -> Built {
        let start = self.pos;
        // `(number | pi) ~ (WHITESPACE* ~ degrees)*`
        let numeric = if let Some(end) = self.number_at(start) {
            let x = self.src[start..end].parse::<f64>().ok()?;
            Some((ExprKind::Number(x), end, Kind::Number))
        } else {
            self.keyword_at(start, "pi")
                .or_else(|| self.keyword_at(start, "π"))
                .map(|end| (ExprKind::Number(std::f64::consts::PI), end, Kind::Pi))
        };
        if let Some((kind, end, first)) = numeric {
            self.check_juxt(first)?;
            self.pos = end;
            let (mut e, mut d) = self.leaf(kind, start, end);
            let mut last = first;
            loop {
                let save = self.pos;
                self.ws();
                match self.degrees_at(self.pos) {
                    Some(end) => {
                        (e, d) = self.degrees(e, d, self.pos, end)?;
                        last = Kind::Degrees;
                    }
                    None => {
                        self.pos = save;
                        break;
                    }
                }
            }
            self.last = last;
            return Some((e, d));
        }

        // primary = mech | call | bool_lit | ident | paren | brackets
        if self.keyword_at(start, "mech").is_some() {
            return None;
        }
        let name = self.ident_at(start)?;
        let (mut e, mut d, mut last) = 'primary: {
            if let Some(end) = name {
                self.pos = end;
                self.ws();
                if self.byte(self.pos) == Some(b'(') {
                    self.check_juxt(Kind::Call)?;
                    let func = self.ident(start, end);
                    let (args, d) = self.call_args()?;
                    let span = self.span(start, self.pos);
                    let kind = ExprKind::Call { func, args };
                    break 'primary (Expr { kind, span }, d + 1, Kind::Call);
                }
                self.pos = start;
            }
            for (word, value) in [("true", true), ("false", false)] {
                if let Some(end) = self.keyword_at(start, word) {
                    self.check_juxt(Kind::Bool)?;
                    self.pos = end;
                    let (e, d) = self.leaf(ExprKind::Bool(value), start, end);
                    break 'primary (e, d, Kind::Bool);
                }
            }
            if let Some(end) = name {
                self.check_juxt(Kind::Ident)?;
                self.pos = end;
                let var = ExprKind::Var(self.src[start..end].to_string());
                let (e, d) = self.leaf(var, start, end);
                break 'primary (e, d, Kind::Ident);
            }
            match self.byte(start)? {
                b'(' => {
                    self.check_juxt(Kind::Paren)?;
                    let (e, d) = self.paren()?;
                    (e, d, Kind::Paren)
                }
                b'[' => {
                    self.check_juxt(Kind::Brackets)?;
                    let (e, d) = self.brackets()?;
                    (e, d, Kind::Brackets)
                }
                _ => return None,
            }
        };

        // postfix = index | WHITESPACE* ~ (member | degrees)
        loop {
            let at = self.pos;
            if self.byte(at) == Some(b'[') {
                (e, d) = self.index(e, d)?;
                last = Kind::Index;
                continue;
            }
            self.ws();
            let op = self.pos;
            if self.byte(op) == Some(b'.') {
                if let Some(end) = self.ident_at(op + 1)? {
                    self.spend()?;
                    let span = e.span.join(self.span(op, end));
                    let kind = ExprKind::Member {
                        base: Box::new(e),
                        member: self.ident(op + 1, end),
                    };
                    e = Expr { kind, span };
                    d += 1;
                    self.pos = end;
                    last = Kind::Member;
                    continue;
                }
            } else if let Some(end) = self.degrees_at(op) {
                (e, d) = self.degrees(e, d, op, end)?;
                last = Kind::Degrees;
                continue;
            }
            self.pos = at;
            break;
        }
        self.last = last;
        (d <= MAX_DEPTH).then_some((e, d))
    }

    fn degrees(&mut self, base: Expr, d: usize, start: usize, end: usize) -> Built {
        self.spend()?;
        self.pos = end;
        let span = base.span.join(self.span(start, end));
        let kind = ExprKind::Degrees(Box::new(base));
        Some((Expr { kind, span }, d + 1))
    }

    /// Comma-separated expressions up to `close`, with an optional final
    /// comma; at least one unless `empty_ok`. Leaves `pos` after `close`.
    fn list(&mut self, close: u8, empty_ok: bool) -> Option<(Vec<Expr>, usize)> {
        self.pos += 1;
        let mut items = Vec::new();
        let mut depth = 0;
        self.ws();
        if !(empty_ok && self.byte(self.pos) == Some(close)) {
            loop {
                let (e, d) = self.expr(0)?;
                depth = depth.max(d);
                items.push(e);
                if !self.eat(b',') {
                    break;
                }
                self.ws();
                if self.byte(self.pos) == Some(close) {
                    break;
                }
            }
        }
        self.eat(close).then_some((items, depth))
    }

    fn call_args(&mut self) -> Option<(Vec<Expr>, usize)> {
        self.spend()?;
        self.list(b')', true)
    }

    fn paren(&mut self) -> Built {
        self.spend()?;
        let start = self.pos;
        let (mut items, d) = self.list(b')', false)?;
        let span = self.span(start, self.pos);
        if items.len() == 1 {
            let mut e = items.pop()?;
            e.span = span;
            return Some((e, d));
        }
        let kind = ExprKind::Paren(items);
        Some((Expr { kind, span }, d + 1))
    }

    fn index(&mut self, base: Expr, depth: usize) -> Built {
        self.spend()?;
        let start = self.pos;
        self.pos += 1;
        let mut args = Vec::new();
        let mut d = 0;
        loop {
            self.ws();
            if self.byte(self.pos) == Some(b':') {
                args.push(IndexArg::All(self.span(self.pos, self.pos + 1)));
                self.pos += 1;
            } else {
                let (e, ed) = self.expr(0)?;
                d = d.max(ed);
                args.push(IndexArg::Expr(e));
            }
            if !self.eat(b',') {
                break;
            }
        }
        if !self.eat(b']') {
            return None;
        }
        let span = base.span.join(self.span(start, self.pos));
        let kind = ExprKind::Index {
            base: Box::new(base),
            args,
        };
        Some((Expr { kind, span }, (depth + 1).max(d + 1)))
    }

    /// Skips `row_sep`s (`;` or a newline) and whitespace.
    fn row_seps(&mut self) -> bool {
        let mut any = false;
        loop {
            self.ws();
            match self.byte(self.pos) {
                Some(b';' | b'\n') => {
                    self.pos += 1;
                    any = true;
                }
                _ => return any,
            }
        }
    }

    fn brackets(&mut self) -> Built {
        self.spend()?;
        let start = self.pos;
        self.pos += 1;
        let mut rows = Vec::new();
        let mut depth = 0;
        self.row_seps();
        while self.byte(self.pos) != Some(b']') {
            let mut row = Vec::new();
            loop {
                let (e, d) = self.expr(0)?;
                depth = depth.max(d);
                row.push(e);
                if !self.eat(b',') {
                    break;
                }
                self.ws();
                if matches!(self.byte(self.pos), Some(b';' | b'\n' | b']')) {
                    break;
                }
            }
            rows.push(row);
            if !self.row_seps() && self.byte(self.pos) != Some(b']') {
                return None;
            }
        }
        self.pos += 1;
        let span = self.span(start, self.pos);
        let kind = ExprKind::Brackets(rows);
        Some((Expr { kind, span }, depth + 1))
    }
}

#[cfg(test)]
mod tests {
    use super::super::{FAST_DEPTH, parser, split};
    use proptest::prelude::*;

    /// Checks every statement of `src` the fast path takes against pest;
    /// returns how many statements it took and how many pest parsed.
    fn agree(src: &str) -> (usize, usize) {
        let split = split::split(src);
        let (mut fast, mut ok) = (0, 0);
        for chunk in split.chunks.iter().filter(|c| c.error.is_none()) {
            let text = &split.text[chunk.span.start..chunk.span.end];
            let slow = parser::parse_chunk(text, chunk.span);
            ok += usize::from(slow.is_ok());
            if chunk.depth > FAST_DEPTH {
                continue;
            }
            if let Some(stmt) = super::parse_statement(text, chunk.span) {
                fast += 1;
                assert_eq!(Ok(stmt), slow, "{src:?}");
            }
        }
        (fast, ok)
    }

    fn scripts() -> Vec<String> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut dirs = vec![root.join("examples")];
        if let Ok(kinds) = std::fs::read_dir(root.join("tests/errors")) {
            dirs.extend(kinds.flatten().map(|k| k.path()));
        }
        let mut out = Vec::new();
        for dir in dirs {
            for f in std::fs::read_dir(dir).into_iter().flatten().flatten() {
                if f.path().extension().is_some_and(|e| e == "chs") {
                    out.extend(std::fs::read_to_string(f.path()));
                }
            }
        }
        out
    }

    #[test]
    fn fast_path_agrees_with_pest() {
        let (mut fast, mut ok) = (0, 0);
        let scripts = scripts();
        assert!(!scripts.is_empty());
        for src in &scripts {
            let (f, o) = agree(src);
            fast += f;
            ok += o;
        }
        // Most statements of the examples take the fast path.
        assert!(fast * 10 >= ok * 8, "fast path took {fast} of {ok}");
        for src in [
            "T_sb = RpToTrans(Rotz(30 deg), (1, 2, 0))",
            "p_s = T_sb * (1, 0, 0)",
            "x = 2 * 3 + 1",
            "w = MatrixLog3(Rotz(0.1) * Rotx(0.2))",
            "V_s = Ad(T_sb) * (0, 0, 1, 1, 0, 0)",
            "f(x, y) = -x^2 + y'",
            "(w, theta) = axis_ang3(expc)",
            "M = [R, p; 0, 0, 0, 1]\n[1, 2,\n 3]",
            "exp([S] theta) * M[1, :] .T + 2 pi - 30° / θ(1) + true",
        ] {
            let (f, o) = agree(src);
            assert!(f == o && o > 0, "{src:?} takes the slow path");
        }
    }

    const TOKENS: &[&str] = &[
        "(", ")", "[", "]", ",", ";", "+", "-", "*", "/", "^", ".", "'", "deg", "°", "pi", "π",
        "1", "2.5", ".5", "1e", "1e-3", "T_ab", "x", "θ", "=", "==", ":", "true", "false", "given",
        "derive", "mech", "<", ">", "\n", " ", "\t", "_{", "}", "f(", "**", ".T", "_",
    ];

    fn tokens() -> impl Strategy<Value = String> {
        prop::collection::vec((prop::sample::select(TOKENS), prop::bool::ANY), 0..24).prop_map(
            |parts| {
                parts
                    .into_iter()
                    .map(|(t, space)| {
                        if space {
                            format!("{t} ")
                        } else {
                            t.to_string()
                        }
                    })
                    .collect()
            },
        )
    }

    /// Mostly well-formed expressions.
    fn expr() -> impl Strategy<Value = String> {
        let atom = prop::sample::select(
            &[
                "1", "2.5", ".5", "3e2", "pi", "π", "x", "T_sb'", "θ", "true", "30 deg", "30°",
                "M[1, :]", "v.T", "v .R", "f()",
            ][..],
        )
        .prop_map(str::to_string);
        atom.prop_recursive(4, 32, 3, |inner| {
            let op = prop::sample::select(&["+", "-", "*", "/", "^", " ", "", "^-", " - -"][..]);
            prop_oneof![
                (inner.clone(), op, inner.clone()).prop_map(|(a, o, b)| format!("{a}{o}{b}")),
                prop::collection::vec(inner.clone(), 1..3)
                    .prop_map(|v| format!("({})", v.join(", "))),
                prop::collection::vec(inner.clone(), 0..3)
                    .prop_map(|v| format!("[{}]", v.join("; "))),
                prop::collection::vec(inner.clone(), 0..3)
                    .prop_map(|v| format!("g ({},)", v.join(","))),
                (inner.clone(), inner).prop_map(|(a, b)| format!("{a}[{b}] deg")),
            ]
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        #[test]
        fn random_tokens_agree(src in tokens()) {
            agree(&src);
        }

        #[test]
        fn random_expressions_agree(e in expr(), form in 0..4usize) {
            let src = match form {
                0 => e,
                1 => format!("y_1 = {e}"),
                2 => format!("h(a, b) = {e}"),
                _ => format!("(a, b) = {e}"),
            };
            agree(&src);
        }
    }
}
