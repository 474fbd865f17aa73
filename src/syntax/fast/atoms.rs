//! The fast path's operands: atoms (numbers, names, calls, `sin θ`, `deg`,
//! `( )`, `[ ]`, `{ }` superscripts) with their postfix operators (`[i]`,
//! `.T`, `ᵀ`, `²`, `deg`), as the grammar's `operand`, `primary`,
//! `bare_call`, `postfix`, `paren`, `sup_group`, `brackets` and `index`
//! rules read them.

use super::{Built, P};
use crate::syntax::ast::{Expr, ExprKind, Ident, IndexArg};

/// The scalar functions the book writes without parentheses (`bare_fn`).
fn is_bare_fn(word: &[u8]) -> bool {
    matches!(
        word,
        [b'a', b's', b'i', b'n']
            | [b'a', b'c', b'o', b's']
            | [b'a', b't', b'a', b'n']
            | [b's', b'i', b'n']
            | [b'c', b'o', b's']
            | [b't', b'a', b'n']
            | [b'c', b'o', b't']
            | [b's', b'e', b'c']
            | [b'c', b's', b'c']
            | [b's', b'q', b'r', b't']
    )
}

/// The value of the number literal `text` (as the grammar's `number`
/// reads it), the same `f64` as `str::parse`: digits with at most one
/// point and fifteen digits are an exact integer divided by an exact power
/// of ten, one correctly rounded operation (Clinger's fast path); anything
/// else (exponents, long literals) goes to `parse`.
pub(super) fn number_value(text: &str) -> Option<f64> {
    const POW10: [f64; 16] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
    ];
    let bytes = text.as_bytes();
    if bytes.len() > 15 {
        return text.parse().ok();
    }
    let (mut m, mut frac, mut point) = (0u64, 0usize, false);
    for &b in bytes {
        match b {
            b'0'..=b'9' => {
                m = m * 10 + u64::from(b - b'0');
                frac += usize::from(point);
            }
            b'.' if !point => point = true,
            _ => return text.parse().ok(),
        }
    }
    Some(m as f64 / POW10[frac])
}

/// The elements of `v` from `mark` on, moved into a vector of their own
/// allocated at its length; one element (`log(T_ac)`, `[S]`) is moved
/// without `split_off`'s call to `memcpy`.
#[inline(always)]
fn split_tail<T>(v: &mut Vec<T>, mark: usize) -> Vec<T> {
    if v.len() == mark + 1
        && let Some(last) = v.pop()
    {
        return vec![last];
    }
    v.split_off(mark)
}

/// What [`P::name_operand`] read.
enum Named {
    /// A name alone: the whole operand.
    Var(Expr),
    /// A call, which postfix operators may follow.
    Call(Expr),
    /// Neither: [`P::word`] decides.
    Other,
}

impl P<'_> {
    /// The number literal at `at` and its end, as [`Self::number_at`] and
    /// [`number_value`] give them, in one pass over the digits of the
    /// common `12`, `0.25`, `.5` (those two for the rest).
    #[inline(always)]
    pub(super) fn number_value_at(&self, at: usize) -> Option<(f64, usize)> {
        const POW10: [f64; 16] = [
            1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
        ];
        let s = self.s;
        // One digit that nothing continues (`1` in `(1, 2, 3)`): its value.
        if let Some(&d) = s.get(at)
            && d.is_ascii_digit()
            && !matches!(s.get(at + 1), Some(b'0'..=b'9' | b'.' | b'e' | b'E'))
        {
            return Some((f64::from(d - b'0'), at + 1));
        }
        let mut m = 0u64;
        let mut digits = |mut i: usize| {
            while let Some(&b) = s.get(i)
                && b.is_ascii_digit()
            {
                m = m.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
                i += 1;
            }
            i
        };
        let int_end = digits(at);
        let (end, frac) = if s.get(int_end) == Some(&b'.') {
            let after = digits(int_end + 1);
            (after, after - int_end - 1)
        } else {
            (int_end, 0)
        };
        let count = int_end - at + frac;
        // `2.`, `.`, exponents and long literals: the general path.
        if count == 0
            || (end == int_end + 1)
            || count > 15
            || matches!(s.get(end), Some(b'e' | b'E'))
        {
            let end = self.number_at(at)?;
            return Some((number_value(&self.src[at..end])?, end));
        }
        // Below 10¹⁵, so exact as a signed integer (converted in one step).
        Some((m as i64 as f64 / POW10[frac], end))
    }

    pub(super) fn leaf(&self, kind: ExprKind, start: usize, end: usize) -> Expr {
        let span = self.span(start, end);
        Expr { kind, span }
    }

    /// `(number | pi) ~ (WHITESPACE* ~ degrees)*` at the current position.
    #[inline(always)]
    pub(super) fn numeric(&mut self) -> Option<Built> {
        let start = self.pos;
        let (value, end) = match self.byte(start)? {
            b'0'..=b'9' | b'.' => self.number_value_at(start)?,
            b'p' | 0xCF => {
                let end = self
                    .keyword_at(start, "pi")
                    .or_else(|| self.keyword_at(start, "π"))?;
                (std::f64::consts::PI, end)
            }
            _ => return None,
        };
        self.pos = end;
        let e = self.leaf(ExprKind::Number(value), start, end);
        if !self
            .byte(self.pos)
            .is_some_and(|b| super::is_ws(b) || b == b'd' || b == 0xC2)
        {
            // No `deg` or `°` can follow (the common case).
            return Some(Some(e));
        }
        Some(self.units(e))
    }

    /// `(WHITESPACE* ~ degrees)*` after `e`.
    fn units(&mut self, mut e: Expr) -> Built {
        loop {
            let save = self.pos;
            self.ws();
            match self.degrees_at(self.pos) {
                Some(end) => e = self.degrees(e, self.pos, end)?,
                None => {
                    self.pos = save;
                    return Some(e);
                }
            }
        }
    }

    /// `operand`: an atom with its postfix operators.
    pub(super) fn operand(&mut self) -> Built {
        let start = self.pos;
        let first = self.byte(start)?;
        // primary = mech | call | bare_call | bool_lit | ident | paren | brackets | deg_unit,
        // after `numeric`; the first byte rules out most alternatives.
        let mut e = match first {
            b'(' => self.paren()?,
            b'[' => self.brackets()?,
            // `numeric` starts with a digit, `.`, `pi` or `π` (0xCF);
            // a number takes no postfix operators.
            b'0'..=b'9' | b'.' => return self.numeric()?,
            b'p' | 0xCF if let Some(built) = self.numeric() => return built,
            b'a'..=b'z' | b'A'..=b'Z' => match self.name_operand(start)? {
                Named::Var(var) => return Some(var),
                Named::Call(call) => call,
                Named::Other => self.word()?,
            },
            _ => self.word()?,
        };

        // postfix = index | WHITESPACE* ~ (member | degrees | transpose_mark)
        loop {
            let at = self.pos;
            if self.byte(at) == Some(b'[') {
                e = self.index(e)?;
                continue;
            }
            self.ws();
            let op = self.pos;
            match self.byte(op) {
                Some(b'.') => {
                    if let Some(end) = self.ident_at(op + 1)? {
                        let member = self.ident(op + 1, end);
                        e = self.member(e, op, member)?;
                        self.pos = end;
                        continue;
                    }
                }
                // `deg`; the rest (`°`, superscripts, `ᵀ`) are not ASCII.
                Some(b'd' | 0x80..) => {
                    if let Some(end) = self.degrees_at(op) {
                        e = self.degrees(e, op, end)?;
                        continue;
                    } else if let Some(end) = self.superscript_at(op) {
                        self.spend()?;
                        let sup = self.span(op, end);
                        let span = e.span.join(sup);
                        let kind =
                            crate::syntax::ast::superscript_power(e, &self.src[op..end], sup);
                        self.stack.passes.rewrite = true;
                        e = Expr { kind, span };
                        self.pos = end;
                        continue;
                    } else if self.src[op..].starts_with('ᵀ') {
                        let end = op + 'ᵀ'.len_utf8();
                        let member = Ident {
                            name: "T".into(),
                            span: self.span(op, end),
                        };
                        e = self.member(e, op, member)?;
                        self.pos = end;
                        continue;
                    }
                }
                _ => {}
            }
            self.pos = at;
            break;
        }
        Some(e)
    }

    /// The two commonest primaries that start with a name, read once: a
    /// call `f(…)` ([`Self::word`]'s first alternative), and a name that no
    /// call, `sin θ`, postfix or keyword can continue because what follows
    /// it (after blanks) ends an operand or is a binary operator (`T_bc`
    /// in `T_ab * T_bc;`). [`Named::Other`] where it may be something else
    /// (left to `word`); `None` to give up (as `word` does).
    #[inline(always)]
    fn name_operand(&mut self, start: usize) -> Option<Named> {
        let Some(end) = self.ident_at(start)? else {
            return Some(Named::Other);
        };
        let mut after = end;
        while self.byte(after).is_some_and(super::is_ws) {
            after += 1;
        }
        match self.byte(after) {
            Some(b'(') => {
                self.pos = after;
                let func = self.ident(start, end);
                let args = self.call_args()?;
                let span = self.span(start, self.pos);
                let kind = ExprKind::Call { func, args };
                Some(Named::Call(Expr { kind, span }))
            }
            // `true'` is `true` then a stray `'`: left to `word`.
            None
            | Some(
                b';' | b'\n' | b')' | b',' | b']' | b'}' | b'*' | b'/' | b'+' | b'-' | b'=' | b'^',
            ) if !self.s[start..end].contains(&b'\'') => {
                self.pos = end;
                let var = ExprKind::Var(self.stack.names.name_in(self.src, start, end));
                Some(Named::Var(self.leaf(var, start, end)))
            }
            _ => Some(Named::Other),
        }
    }

    /// The primaries that start with a letter (after `pi`): a call,
    /// `sin θ`, `true`, a name, `deg`, in the grammar's order.
    fn word(&mut self) -> Built {
        let start = self.pos;
        if self.keyword_at(start, "mech").is_some() {
            return None;
        }
        let name = self.ident_at(start)?;
        if let Some(end) = name {
            self.pos = end;
            self.ws();
            if self.byte(self.pos) == Some(b'(') {
                let func = self.ident(start, end);
                let args = self.call_args()?;
                let span = self.span(start, self.pos);
                let kind = ExprKind::Call { func, args };
                return Some(Expr { kind, span });
            }
            self.pos = start;
            if let Some(built) = self.bare_call(start, end) {
                return built;
            }
            self.pos = start;
        }
        for (word, value) in [("true", true), ("false", false)] {
            if let Some(end) = self.keyword_at(start, word) {
                self.pos = end;
                return Some(self.leaf(ExprKind::Bool(value), start, end));
            }
        }
        if let Some(end) = name {
            self.pos = end;
            let var = ExprKind::Var(self.stack.names.name_in(self.src, start, end));
            return Some(self.leaf(var, start, end));
        }
        if let Some(end) = self.keyword_at(start, "deg") {
            self.pos = end;
            let one = self.leaf(ExprKind::Number(1.0), start, end);
            let span = one.span;
            let kind = ExprKind::Degrees(Box::new(one));
            return Some(Expr { kind, span });
        }
        None
    }

    fn member(&mut self, e: Expr, op: usize, member: Ident) -> Built {
        self.spend()?;
        let span = e.span.join(self.span(op, member.span.end - self.off));
        let kind = ExprKind::Member {
            base: Box::new(e),
            member,
        };
        Some(Expr { kind, span })
    }

    /// `bare_call` for the name at `start..end`: `sin θ`, `cos 30°`. `None`
    /// when it does not match (the grammar tries the next alternative).
    #[inline(always)]
    fn bare_call(&mut self, start: usize, end: usize) -> Option<Built> {
        if !matches!(end - start, 3 | 4)
            || !self.byte(end).is_some_and(super::is_ws)
            || !is_bare_fn(&self.s[start..end])
        {
            return None;
        }
        self.bare_call_arg(start, end)
    }

    /// [`Self::bare_call`] once the name is a bare function and a space
    /// follows it.
    fn bare_call_arg(&mut self, start: usize, end: usize) -> Option<Built> {
        self.pos = end;
        self.ws();
        let at = self.pos;
        let arg = match self.numeric() {
            Some(built) => built,
            None => {
                let stop = self.ident_at(at)??;
                if self.byte(stop) == Some(b'(') {
                    return None;
                }
                self.pos = stop;
                let var = ExprKind::Var(self.stack.names.name_in(self.src, at, stop));
                let e = self.leaf(var, at, stop);
                self.units(e)
            }
        };
        Some(arg.and_then(|arg| {
            self.spend()?;
            self.stack.passes.spacing = true;
            let func = self.ident(start, end);
            let span = self.span(start, self.pos);
            let kind = ExprKind::Call {
                func,
                args: vec![arg],
            };
            Some(Expr { kind, span })
        }))
    }

    pub(super) fn degrees(&mut self, base: Expr, start: usize, end: usize) -> Built {
        self.spend()?;
        self.pos = end;
        let span = base.span.join(self.span(start, end));
        let kind = ExprKind::Degrees(Box::new(base));
        Some(Expr { kind, span })
    }

    /// Comma-separated expressions up to `close`, with an optional final
    /// comma; at least one unless `empty_ok`. Leaves `pos` after `close`
    /// and the expressions on top of `self.stack`, from the returned mark.
    fn list_on_stack(&mut self, close: u8, empty_ok: bool) -> Option<usize> {
        self.pos += 1;
        let mark = self.stack.items.len();
        self.ws();
        if !(empty_ok && self.byte(self.pos) == Some(close)) {
            loop {
                let e = match self.simple_item(close, false) {
                    Some(e) => e,
                    None => self.expr(0)?,
                };
                self.stack.items.push(e);
                if !self.eat(b',') {
                    break;
                }
                self.ws();
                if self.byte(self.pos) == Some(close) {
                    break;
                }
            }
        }
        self.eat(close).then_some(mark)
    }

    /// An element that is a plain number or name directly followed by `,`
    /// or `close` (`1` in `(1, 2)`, `T_ab` in `Ad(T_ab)`), or by `close`
    /// only when `alone`: the tree `expr(0)` builds for it, without the
    /// operator loop. `None` (position after whitespace) for anything else.
    #[inline(always)]
    fn simple_item(&mut self, close: u8, alone: bool) -> Option<Expr> {
        self.ws();
        let start = self.pos;
        let first = self.byte(start)?;
        let (number, end) = if first.is_ascii_digit() {
            let (value, end) = self.number_value_at(start)?;
            (Some(value), end)
        } else if first.is_ascii_alphabetic() {
            let end = self.ident_at(start)??;
            // `true'` is `true` then a stray `'`: left to the full path.
            if self.s[start..end].contains(&b'\'') {
                return None;
            }
            (None, end)
        } else {
            return None;
        };
        if !matches!(self.byte(end), Some(b) if b == close || (b == b',' && !alone)) {
            return None;
        }
        let kind = match number {
            Some(value) => ExprKind::Number(value),
            None => ExprKind::Var(self.stack.names.name_in(self.src, start, end)),
        };
        self.pos = end;
        self.sup = false;
        Some(self.leaf(kind, start, end))
    }

    /// The expressions above `mark` on the stack, as a vector of their own.
    fn take_from(&mut self, mark: usize) -> Vec<Expr> {
        split_tail(&mut self.stack.items, mark)
    }

    #[inline(always)]
    pub(super) fn call_args(&mut self) -> Option<Vec<Expr>> {
        self.spend()?;
        let mark = self.list_on_stack(b')', true)?;
        Some(self.take_from(mark))
    }

    pub(super) fn paren(&mut self) -> Built {
        self.spend()?;
        let start = self.pos;
        let mark = self.list_on_stack(b')', false)?;
        let span = self.span(start, self.pos);
        if self.stack.items.len() == mark + 1 {
            let mut e = self.stack.items.pop()?;
            e.span = span;
            return Some(e);
        }
        let kind = ExprKind::Paren(self.take_from(mark));
        Some(Expr { kind, span })
    }

    /// `sup_group`: `{ expr }`, the expression spanning its braces.
    pub(super) fn group(&mut self, close: u8) -> Built {
        self.spend()?;
        let start = self.pos;
        self.pos += 1;
        let mut e = self.expr(0)?;
        if !self.eat(close) {
            return None;
        }
        e.span = self.span(start, self.pos);
        Some(e)
    }

    pub(super) fn index(&mut self, base: Expr) -> Built {
        self.spend()?;
        let start = self.pos;
        self.pos += 1;
        let mut args = Vec::new();
        loop {
            self.ws();
            if self.byte(self.pos) == Some(b':') {
                args.push(IndexArg::All(self.span(self.pos, self.pos + 1)));
                self.pos += 1;
            } else {
                let e = self.expr(0)?;
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
        Some(Expr { kind, span })
    }

    /// Skips `row_sep`s (`;` or a newline) and whitespace.
    pub(super) fn row_seps(&mut self) -> bool {
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

    pub(super) fn brackets(&mut self) -> Built {
        self.spend()?;
        let start = self.pos;
        self.pos += 1;
        let rows_mark = self.stack.rows.len();
        self.row_seps();
        // `[S]`, `[w]`: the book's bracket of one name or number, built at
        // once (no plain row has a single number).
        if let Some(e) = self.simple_item(b']', true) {
            self.pos += 1;
            let span = self.span(start, self.pos);
            let kind = ExprKind::Brackets(vec![vec![e]]);
            return Some(Expr { kind, span });
        }
        while self.byte(self.pos) != Some(b']') {
            if let Some(plain) = self.plain_rows() {
                self.stack.rows.extend(plain);
            } else {
                let mark = self.stack.items.len();
                loop {
                    let e = match self.simple_item(b']', false) {
                        Some(e) => e,
                        None => self.expr(0)?,
                    };
                    self.stack.items.push(e);
                    if !self.eat(b',') {
                        break;
                    }
                    // A newline after a comma continues the row.
                    let comma = self.pos;
                    while {
                        self.ws();
                        self.byte(self.pos) == Some(b'\n')
                    } {
                        self.pos += 1;
                    }
                    if matches!(self.byte(self.pos), Some(b';' | b']')) {
                        self.pos = comma;
                        break;
                    }
                }
                let row = self.take_from(mark);
                self.stack.rows.push(row);
            }
            if !self.row_seps() && self.byte(self.pos) != Some(b']') {
                return None;
            }
        }
        self.pos += 1;
        let span = self.span(start, self.pos);
        let rows = split_tail(&mut self.stack.rows, rows_mark);
        for e in rows.iter().flatten() {
            match e.kind {
                // numpy's nested rows `[[1, 2], [3, 4]]` are rewritten.
                ExprKind::Brackets(_) => self.stack.passes.rewrite = true,
                // `[1 -x]`, `[2 pi]`: what reads two ways in brackets is
                // a sum or product at the top of an element.
                ExprKind::Binary { .. } => self.stack.passes.spacing = true,
                _ => {}
            }
        }
        let kind = ExprKind::Brackets(rows);
        Some(Expr { kind, span })
    }
}
