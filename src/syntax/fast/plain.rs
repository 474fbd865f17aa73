//! The fast path's `plain_row`: pasted numpy and MATLAB output, plain
//! numbers separated by spaces (`0 -1 0`) or rows of them
//! (`[ 0. -1.] [ 1.  0.]`), matched as the grammar matches them.

use super::P;
use crate::syntax::ast::{BinOp, Expr, ExprKind, UnOp};

/// Start and end of each number of each row.
type Rows = Vec<Vec<(usize, usize)>>;

impl P<'_> {
    /// A `plain_row` at the current position: its rows, and the position
    /// moved past it; `None` (position kept) where it does not match.
    pub(super) fn plain_rows(&mut self) -> Option<Vec<Vec<Expr>>> {
        // A plain number starts with a sign, a digit or `.`, a plain list
        // with `[`: anything else (`[S]`, `[R, p]`) is ruled out at once.
        if !matches!(
            self.byte(self.pos),
            Some(b'+' | b'-' | 0xE2 | b'0'..=b'9' | b'.' | b'[')
        ) {
            return None;
        }
        let (end, rows) = self
            .plain_numbers_at(self.pos)
            .or_else(|| self.plain_lists_at(self.pos))?;
        self.pos = end;
        Some(
            rows.into_iter()
                .map(|row| {
                    row.into_iter()
                        .map(|(a, b)| self.plain_number(a, b))
                        .collect()
                })
                .collect(),
        )
    }

    fn ws_end(&self, mut at: usize) -> usize {
        while self.byte(at).is_some_and(super::is_ws) {
            at += 1;
        }
        at
    }

    /// `&(WHITESPACE* ~ (row_sep | "]"))`
    fn row_ends(&self, at: usize) -> bool {
        matches!(self.byte(self.ws_end(at)), Some(b';' | b'\n' | b']'))
    }

    /// `plain_number`: `("-" | "+")? ~ number`.
    fn plain_number_at(&self, at: usize) -> Option<usize> {
        let digits = at + self.sign_at(at).map_or(0, |(_, w)| w);
        self.number_at(digits)
    }

    /// `plain_number ~ (WHITESPACE+ ~ plain_number)+`, then the row's end.
    fn plain_numbers_at(&self, at: usize) -> Option<(usize, Rows)> {
        let mut end = self.plain_number_at(at)?;
        let mut row = vec![(at, end)];
        loop {
            let next = self.ws_end(end);
            match self.plain_number_at(next) {
                Some(e) if next > end => {
                    row.push((next, e));
                    end = e;
                }
                _ => break,
            }
        }
        (row.len() >= 2 && self.row_ends(end)).then(|| (end, vec![row]))
    }

    /// `plain_list ~ (WHITESPACE* ~ plain_list)+`, then the row's end.
    fn plain_lists_at(&self, at: usize) -> Option<(usize, Rows)> {
        let (mut end, first) = self.plain_list_at(at)?;
        let mut rows = vec![first];
        while let Some((e, row)) = self.plain_list_at(self.ws_end(end)) {
            rows.push(row);
            end = e;
        }
        (rows.len() >= 2 && self.row_ends(end)).then_some((end, rows))
    }

    /// `"[" ~ WS* ~ plain_number ~ ((WS* ~ "," ~ WS* | WS+) ~ plain_number)* ~ WS* ~ "]"`
    fn plain_list_at(&self, at: usize) -> Option<(usize, Vec<(usize, usize)>)> {
        if self.byte(at) != Some(b'[') {
            return None;
        }
        let first = self.ws_end(at + 1);
        let mut end = self.plain_number_at(first)?;
        let mut row = vec![(first, end)];
        loop {
            let gap = self.ws_end(end);
            let next = if self.byte(gap) == Some(b',') {
                self.ws_end(gap + 1)
            } else if gap > end {
                gap
            } else {
                break;
            };
            match self.plain_number_at(next) {
                Some(e) => {
                    row.push((next, e));
                    end = e;
                }
                None => break,
            }
        }
        let close = self.ws_end(end);
        (self.byte(close) == Some(b']')).then_some((close + 1, row))
    }

    /// The number at `start..end`, with its sign (as `book.rs` builds it).
    fn plain_number(&self, start: usize, end: usize) -> Expr {
        let sign = self.sign_at(start);
        let op = sign.map(|(op, _)| {
            if op == BinOp::Add {
                UnOp::Pos
            } else {
                UnOp::Neg
            }
        });
        let digits = start + sign.map_or(0, |(_, w)| w);
        let value = super::atoms::number_value(&self.src[digits..end]).unwrap_or(f64::NAN);
        let number = Expr {
            kind: ExprKind::Number(value),
            span: self.span(digits, end),
        };
        match op {
            None => number,
            Some(op) => Expr {
                kind: ExprKind::Unary {
                    op,
                    operand: Box::new(number),
                },
                span: self.span(start, end),
            },
        }
    }
}
