//! The fast path's operands: atoms (numbers, names, calls, `( )`, `[ ]`)
//! with their postfix operators, as the grammar's `operand`, `primary`,
//! `postfix`, `paren`, `brackets` and `index` rules read them.

use super::{Built, Kind, P};
use crate::syntax::MAX_DEPTH;
use crate::syntax::ast::{Expr, ExprKind, IndexArg};

impl P<'_> {
    pub(super) fn leaf(&self, kind: ExprKind, start: usize, end: usize) -> (Expr, usize) {
        let span = self.span(start, end);
        (Expr { kind, span }, 1)
    }

    /// `operand`: an atom with its postfix operators. Sets `self.last`.
    pub(super) fn operand(&mut self) -> Built {
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

    pub(super) fn degrees(&mut self, base: Expr, d: usize, start: usize, end: usize) -> Built {
        self.spend()?;
        self.pos = end;
        let span = base.span.join(self.span(start, end));
        let kind = ExprKind::Degrees(Box::new(base));
        Some((Expr { kind, span }, d + 1))
    }

    /// Comma-separated expressions up to `close`, with an optional final
    /// comma; at least one unless `empty_ok`. Leaves `pos` after `close`.
    pub(super) fn list(&mut self, close: u8, empty_ok: bool) -> Option<(Vec<Expr>, usize)> {
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

    pub(super) fn call_args(&mut self) -> Option<(Vec<Expr>, usize)> {
        self.spend()?;
        self.list(b')', true)
    }

    pub(super) fn paren(&mut self) -> Built {
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

    pub(super) fn index(&mut self, base: Expr, depth: usize) -> Built {
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
