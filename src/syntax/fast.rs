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
//! queue, no backtracking state, no rule calls per character. Operands are
//! told apart by their first byte, keywords and names are matched byte by
//! byte, and lists are gathered on a [`Stack`] kept between statements.
//! It also notes which of the passes after parsing (`spacing`, `rewrite`)
//! the statement needs ([`Passes`]); the same test checks that a skipped
//! pass would have done nothing.

use super::MAX_DEPTH;
use super::ast::{BinOp, CmpOp, Expr, ExprKind, Ident, Span, Stmt, StmtKind, UnOp};
use super::name::Recent;
use lex::{is_ws, xid_start};

mod atoms;
mod lex;
mod plain;
#[cfg(test)]
mod tests;

/// At most this many operators, postfixes and brackets per statement, so
/// that both the tree depth and the recursion stay below [`MAX_DEPTH`]
/// (the pest path reports the limit). Each node the parser builds spends
/// one unit and adds at most two levels (a superscript `x²` is two: the
/// power and its exponent), and a leaf is at most three deep (`[1 -2]`,
/// `deg`), so a tree is at most `2 BUDGET + 3` deep: with 98, 199, within
/// the limit. The tree's depth is therefore never counted.
const BUDGET: usize = 98;

/// The bound of [`BUDGET`]'s comment, checked when compiled.
const _: () = assert!(2 * BUDGET + 3 <= MAX_DEPTH);

/// Pratt binding powers, as in `parser.rs`'s `PRATT` (10 per level).
const BP_CMP: u8 = 5;
const BP_ADD: u8 = 10;
const BP_MUL: u8 = 20;
const BP_PREFIX: u8 = 30;
const BP_POW: u8 = 40;

/// Room for the elements of lists and rows while they are parsed, kept
/// from one statement to the next so that each list is allocated once, at
/// its final length.
#[derive(Default)]
pub(crate) struct Stack {
    items: Vec<Expr>,
    rows: Vec<Vec<Expr>>,
    /// The names made so far, found again without the global table.
    names: Recent,
    /// The passes the last statement parsed needs.
    pub passes: Passes,
    /// Where the last statement read from the source ends: its newline or
    /// `;`, or the source's length ([`parse_statement_in`]).
    pub end: usize,
    /// Where the parser stopped in the last statement's text, and the
    /// budget it spent.
    stop: usize,
    spent: usize,
}

/// Which of the passes after parsing can change or refuse a statement:
/// `spacing` only looks at juxtapositions, `sin θ`, brackets and names
/// with digits; `rewrite` only at `^` and brackets in brackets. A
/// statement with none of these skips them.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Passes {
    pub spacing: bool,
    pub rewrite: bool,
}

impl Passes {
    /// Both passes (the pest path, which does not tell).
    pub const ALL: Passes = Passes {
        spacing: true,
        rewrite: true,
    };
}

/// Parses the statement at `span` of `text`, or `None` to leave it to pest.
/// `chunk` is the statement's text (comments blanked), `span` its place in
/// the source; `stack` is reused across statements and tells afterwards
/// which passes the statement needs.
pub(crate) fn parse_statement_with(chunk: &str, span: Span, stack: &mut Stack) -> Option<Stmt> {
    let stmt = statement_in(chunk, span.start, stack)?;
    (stack.stop == chunk.len()).then_some(stmt)
}

/// The splitter's work done by the parser: parses the statement that
/// starts at or after `from` in `src` (after blank lines, `;` and comment
/// lines) straight from the source, and leaves in `stack.end` the offset
/// of the newline or `;` that ends it (or the source's length). `None`
/// where the splitter and [`parse_statement_with`] must decide: at the end
/// of the source, and wherever the splitter would have changed the text (a
/// newline inside `( )`, a string), reported an error, or not let the fast
/// path take the statement (nested deeper than `FAST_DEPTH`, longer than
/// `MAX_STATEMENT_BYTES`). Only called where the splitter stands at the
/// start of a statement with nothing open.
#[inline(always)]
pub(crate) fn parse_statement_in(src: &str, from: usize, stack: &mut Stack) -> Option<Stmt> {
    let s = src.as_bytes();
    let mut start = from;
    loop {
        match s.get(start) {
            Some(&b) if is_ws(b) || b == b'\n' || b == b';' => start += 1,
            Some(b'#') => start = line_end(s, start),
            Some(_) => break,
            None => return None,
        }
    }
    let text = &src[start..];
    let stmt = statement_in(text, start, stack)?;
    let stop = stack.stop;
    stack.end = start
        + match text.as_bytes().get(stop) {
            None | Some(b'\n' | b';') => stop,
            // A comment after the statement, blanked by the splitter.
            Some(b'#') => line_end(text.as_bytes(), stop),
            Some(_) => return None,
        };
    let len = stmt.span.end - start;
    // Each bracket the parser opens costs budget (a plain `[1 2]` row
    // inside brackets excepted), so few spent means shallow.
    if len > super::MAX_STATEMENT_BYTES
        || (stack.spent + 1 > super::FAST_DEPTH
            && nesting(&text.as_bytes()[..len]) > super::FAST_DEPTH)
    {
        return None;
    }
    Some(stmt)
}

/// The offset of the newline ending the line at `at` (or the length).
fn line_end(s: &[u8], at: usize) -> usize {
    s[at..]
        .iter()
        .position(|&b| b == b'\n')
        .map_or(s.len(), |k| at + k)
}

/// The deepest bracket nesting in `s` (balanced, no strings or comments).
fn nesting(s: &[u8]) -> usize {
    let (mut depth, mut deepest) = (0usize, 0);
    for &b in s {
        match b {
            b'(' | b'[' | b'{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            b')' | b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

/// Parses the statement at the start of `text`, which is at `off` in the
/// source, as far as it goes: the statement spans its tokens, and
/// `stack.stop` is where the parser stopped (after the whitespace that
/// follows), `stack.spent` the budget it used.
#[inline(always)]
fn statement_in(text: &str, off: usize, stack: &mut Stack) -> Option<Stmt> {
    // Left over from a statement given up on.
    stack.items.clear();
    stack.rows.clear();
    stack.passes = Passes::default();
    if matches!(text.as_bytes().first(), Some(b'g' | b'd'))
        && (text.starts_with("given") || text.starts_with("derive"))
    {
        return None;
    }
    let mut p = P {
        src: text,
        s: text.as_bytes(),
        pos: 0,
        off,
        budget: BUDGET,
        sup: false,
        stack,
    };
    let kind = p.statement()?;
    let span = p.span(0, p.pos);
    p.ws();
    p.stack.stop = p.pos;
    p.stack.spent = BUDGET - p.budget;
    Some(Stmt {
        kind,
        span,
        silent: false,
    })
}

type Built = Option<Expr>;

struct P<'a> {
    stack: &'a mut Stack,
    src: &'a str,
    s: &'a [u8],
    pos: usize,
    /// Offset of the statement in the source.
    off: usize,
    budget: usize,
    /// Just after `^`: a `{` opens a superscript group (`sup_group`).
    sup: bool,
}

impl P<'_> {
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.off + start, self.off + end)
    }

    fn ws(&mut self) {
        let mut i = self.pos;
        while let Some(&b) = self.s.get(i)
            && is_ws(b)
        {
            i += 1;
        }
        self.pos = i;
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
    fn spend(&mut self) -> Option<()> {
        self.budget = self.budget.checked_sub(1)?;
        Some(())
    }
    #[inline(always)]
    fn ident(&mut self, start: usize, end: usize) -> Ident {
        Ident {
            name: self.stack.names.name_in(self.src, start, end),
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
        // `assert expr`: pest's `assert_stmt` comes first, so a statement
        // starting with the keyword is an assertion or nothing.
        if self.s.first() == Some(&b'a')
            && let Some(end) = self.keyword_at(0, "assert")
        {
            self.pos = end;
            return Some(StmtKind::Assert(self.expr(0)?));
        }
        // `explain expr` (LANGUAGE.md §14), the same way.
        if self.s.first() == Some(&b'e')
            && let Some(end) = self.keyword_at(0, "explain")
        {
            self.pos = end;
            return Some(StmtKind::Explain(self.expr(0)?));
        }
        match self.byte(0)? {
            b'(' => {
                if let Some(targets) = self.destructure_head() {
                    let value = self.expr(0)?;
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
                                let body = self.expr(0)?;
                                let params = params.into_boxed_slice();
                                return Some(StmtKind::FnDef { name, params, body });
                            }
                        }
                        Some(b'=') if self.byte(self.pos + 1) != Some(b'=') => {
                            self.pos += 1;
                            let target = self.ident(0, end);
                            let value = self.expr(0)?;
                            return Some(StmtKind::Assign { target, value });
                        }
                        _ => {}
                    }
                    self.pos = 0;
                }
            }
        }
        Some(StmtKind::Expr(self.expr(0)?))
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
        let sup = std::mem::take(&mut self.sup);
        let lhs = match self.byte(start) {
            // `R^{T}`, `R^{-1}`: the group is the whole exponent. What
            // reads two ways inside it is left to the spacing pass.
            Some(b'{') if sup => {
                self.stack.passes.spacing = true;
                self.group(b'}')?
            }
            Some(b'-' | b'+') | Some(0xE2) if self.sign_at(start).is_some() => {
                let (op, width) = self.sign_at(start)?;
                self.spend()?;
                self.pos += width;
                self.ws();
                let operand = self.expr(BP_PREFIX - 1)?;
                let op = if op == BinOp::Sub {
                    UnOp::Neg
                } else {
                    UnOp::Pos
                };
                let span = self.span(start, start + width).join(operand.span);
                let kind = ExprKind::Unary {
                    op,
                    operand: Box::new(operand),
                };
                Expr { kind, span }
            }
            _ => self.operand()?,
        };
        self.ops(lhs, rbp)
    }

    /// The operand after a binary operator other than `^`: `expr(rbp)`
    /// without a call of its own where the operand is the whole of it
    /// (`T_bc` in `T_ab * T_bc;`, `0.1` in `exp([S] 0.1)`).
    #[inline(always)]
    fn rhs(&mut self, rbp: u8) -> Built {
        self.ws();
        // A sign (or `−`, `≈`): the full path.
        if matches!(self.byte(self.pos), Some(b'-' | b'+' | 0xE2)) {
            return self.expr(rbp);
        }
        let e = self.operand()?;
        let mut after = self.pos;
        while self.byte(after).is_some_and(is_ws) {
            after += 1;
        }
        if matches!(
            self.byte(after),
            None | Some(b';' | b'\n' | b')' | b',' | b']' | b'}')
        ) {
            return Some(e);
        }
        self.ops(e, rbp)
    }

    /// The operator loop of [`Self::expr`] after its first operand `lhs`.
    #[inline(always)]
    fn ops(&mut self, mut lhs: Expr, rbp: u8) -> Built {
        loop {
            let save = self.pos;
            self.ws();
            let at = self.pos;
            let Some(b) = self.byte(at) else {
                self.pos = save;
                break;
            };
            // What ends an expression most often: no comparison, operator
            // or juxtaposition starts with these.
            if matches!(b, b';' | b'\n' | b')' | b',' | b']' | b'}') {
                self.pos = save;
                break;
            }
            if let Some((op, width)) = self.cmp_at(at) {
                if rbp >= BP_CMP {
                    self.pos = save;
                    break;
                }
                self.spend()?;
                self.pos = at + width;
                self.sup = false;
                let rhs = self.expr(BP_CMP)?;
                lhs = Expr::compare(op, lhs, rhs, self.span(at, at + width));
                continue;
            }
            let (op, bp, width) = match b {
                b'+' | b'-' | 0xE2 if self.sign_at(at).is_some() => {
                    let (op, width) = self.sign_at(at)?;
                    (Some(op), BP_ADD, width)
                }
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
            self.sup = op == Some(BinOp::Pow);
            // `self.sup` is set only after `^`, which `rhs` does not take.
            let rhs = if op == Some(BinOp::Pow) {
                self.expr(bp - 1)?
            } else {
                self.rhs(bp)?
            };
            let (op, implicit, op_span) = match op {
                Some(op) => {
                    self.stack.passes.rewrite |= op == BinOp::Pow;
                    (op, false, self.span(at, at + width))
                }
                None => {
                    self.stack.passes.spacing |= juxtaposition_reads_two_ways(&lhs, &rhs);
                    let gap = Span::new(lhs.span.end, rhs.span.start.max(lhs.span.end));
                    (BinOp::Mul, true, gap)
                }
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
        }
        Some(lhs)
    }

    /// A comparison `==`, `~=` or `≈` at `at`, with its width in bytes.
    fn cmp_at(&self, at: usize) -> Option<(CmpOp, usize)> {
        match self.byte(at)? {
            b'=' if self.byte(at + 1) == Some(b'=') => Some((CmpOp::Eq, 2)),
            b'~' if self.byte(at + 1) == Some(b'=') => Some((CmpOp::Approx, 2)),
            0xE2 if self.src[at..].starts_with('≈') => Some((CmpOp::Approx, 3)),
            _ => None,
        }
    }

    /// `juxt_start`: `"(" | "[" | ASCII_DIGIT | "." ~ ASCII_DIGIT | XID_START`.
    fn juxt_start(&self, at: usize) -> bool {
        match self.byte(at) {
            Some(b'(' | b'[' | b'0'..=b'9') => true,
            Some(b'.') => self.byte(at + 1).is_some_and(|b| b.is_ascii_digit()),
            _ => self.char_at(at).is_some_and(xid_start),
        }
    }
}

/// Whether the juxtaposition `lhs rhs` is one `spacing` may refuse: the
/// operand before the gap a number, degrees or a call (`2 3`, `sin 2 x`),
/// or the one after it a bracket (`R [1, 2]`). Read without regard to
/// parentheses, so it may say yes where `spacing` finds nothing, never
/// the other way round.
fn juxtaposition_reads_two_ways(lhs: &Expr, rhs: &Expr) -> bool {
    let mut last = lhs;
    while let ExprKind::Binary { rhs: x, .. } | ExprKind::Unary { operand: x, .. } = &last.kind {
        last = x;
    }
    let mut first = rhs;
    while let ExprKind::Binary { lhs: x, .. } = &first.kind {
        first = x;
    }
    matches!(
        last.kind,
        ExprKind::Number(_) | ExprKind::Degrees(_) | ExprKind::Call { .. }
    ) || matches!(first.kind, ExprKind::Brackets(_))
}
