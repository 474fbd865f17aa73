//! Reading back what `--exact` prints (LANGUAGE.md §1, §10), with the
//! oracle's numbers ([`super::hp`]) and none of the engine's code: a
//! number alone, a vector `(a, b)`, a matrix `[a, b\n c, d]`; each entry
//! a sum of products of integers, decimals (`0.866`, `1.5e-13`, `1e20`),
//! `√k`, `π`, powers `^n`, quotients and parentheses, with juxtaposition
//! as a product (`2π/3`, `5000000000000√2`).

use super::hp::H;
use num_bigint::BigInt;

/// What an entry printed as: its value, and whether the text claims an
/// exact form (a root, π or a fraction) rather than a rounded decimal.
#[derive(Debug, Clone)]
pub struct Read {
    pub value: H,
    pub claims_exact: bool,
}

/// The entries of a printed value (the text before any `  : kind`), in
/// reading order (rows of a matrix one after the other). After `≈ `, the
/// closed forms a float is a rounding of: none claims to be the value.
pub fn entries(text: &str) -> Result<Vec<Read>, String> {
    let body = text.split("  :").next().unwrap_or("").trim();
    if let Some(rounded) = body.strip_prefix("≈ ") {
        let mut read = entries(rounded)?;
        read.iter_mut().for_each(|r| r.claims_exact = false);
        return Ok(read);
    }
    let inner = if let Some(b) = body.strip_prefix('[').and_then(|b| b.strip_suffix(']')) {
        b.to_string()
    } else if body.starts_with('(') && body.ends_with(')') && top_level_comma(body) {
        body[1..body.len() - 1].to_string()
    } else {
        body.to_string()
    };
    split_entries(&inner)
        .iter()
        .map(|e| read(e.trim()))
        .collect::<Result<Vec<_>, _>>()
}

/// True when `(…)` holds a comma outside inner parentheses: a vector, not
/// a parenthesized number.
fn top_level_comma(body: &str) -> bool {
    let mut depth = 0;
    for ch in body[1..body.len() - 1].chars() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => return true,
            _ => {}
        }
    }
    false
}

/// Entries separated by commas and newlines outside parentheses.
fn split_entries(s: &str) -> Vec<String> {
    let (mut out, mut cur, mut depth) = (Vec::new(), String::new(), 0);
    for ch in s.chars() {
        match ch {
            '(' => {
                depth += 1;
                cur.push(ch)
            }
            ')' => {
                depth -= 1;
                cur.push(ch)
            }
            ',' | '\n' | ';' if depth == 0 => {
                if !cur.trim().is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
            }
            _ => cur.push(ch),
        }
    }
    if !cur.trim().is_empty() {
        out.push(cur);
    }
    out
}

/// One printed number.
pub fn read(s: &str) -> Result<Read, String> {
    let chars: Vec<char> = s.chars().filter(|c| !c.is_whitespace()).collect();
    let mut p = Parser {
        s: chars,
        i: 0,
        exact: false,
    };
    let v = p.sum()?;
    if p.i != p.s.len() {
        return Err(format!("cannot read `{s}` at {}", p.i));
    }
    Ok(Read {
        value: v,
        claims_exact: p.exact,
    })
}

struct Parser {
    s: Vec<char>,
    i: usize,
    exact: bool,
}

impl Parser {
    fn peek(&self) -> Option<char> {
        self.s.get(self.i).copied()
    }
    fn sum(&mut self) -> Result<H, String> {
        let mut v = self.product()?;
        while let Some(c) = self.peek() {
            match c {
                '+' => {
                    self.i += 1;
                    v = v.add(&self.product()?);
                }
                '-' => {
                    self.i += 1;
                    v = v.sub(&self.product()?);
                }
                _ => break,
            }
        }
        Ok(v)
    }
    fn product(&mut self) -> Result<H, String> {
        let mut v = self.unary()?;
        loop {
            match self.peek() {
                Some('*' | '·') => {
                    self.i += 1;
                    v = v.mul(&self.unary()?);
                }
                Some('/') => {
                    self.i += 1;
                    self.exact = true;
                    let d = self.unary()?;
                    v = v.div(&d).ok_or("division by 0")?;
                }
                Some(c) if c == '(' || c == '√' || c == 'π' || c.is_ascii_digit() => {
                    v = v.mul(&self.power()?);
                }
                _ => return Ok(v),
            }
        }
    }
    fn unary(&mut self) -> Result<H, String> {
        if self.peek() == Some('-') {
            self.i += 1;
            return Ok(self.unary()?.neg());
        }
        self.power()
    }
    fn power(&mut self) -> Result<H, String> {
        let base = self.atom()?;
        if self.peek() == Some('^') {
            self.i += 1;
            let neg = self.peek() == Some('-');
            if neg {
                self.i += 1;
            }
            let start = self.i;
            while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                self.i += 1;
            }
            let n: u32 = self.s[start..self.i]
                .iter()
                .collect::<String>()
                .parse()
                .map_err(|_| "a power")?;
            let p = base.powi(n);
            return if neg {
                H::int(1).div(&p).ok_or_else(|| "0^-n".to_string())
            } else {
                Ok(p)
            };
        }
        Ok(base)
    }
    fn atom(&mut self) -> Result<H, String> {
        match self.peek() {
            Some('(') => {
                self.i += 1;
                let v = self.sum()?;
                if self.peek() != Some(')') {
                    return Err("unclosed (".into());
                }
                self.i += 1;
                Ok(v)
            }
            Some('√') => {
                self.i += 1;
                self.exact = true;
                self.atom()?.sqrt().ok_or_else(|| "√ of a negative".into())
            }
            Some('π') => {
                self.i += 1;
                self.exact = true;
                Ok(H::pi())
            }
            Some(c) if c.is_ascii_digit() => self.number(),
            other => Err(format!("unexpected {other:?} at {}", self.i)),
        }
    }
    /// `123`, `0.866`, `1.5e-13`, `1e20`: exactly the decimal written.
    fn number(&mut self) -> Result<H, String> {
        let start = self.i;
        while self.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
            self.i += 1;
        }
        let mant: String = self.s[start..self.i].iter().collect();
        let mut exp = 0i32;
        if self.peek() == Some('e') {
            self.i += 1;
            let es = self.i;
            if matches!(self.peek(), Some('-' | '+')) {
                self.i += 1;
            }
            while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                self.i += 1;
            }
            exp = self.s[es..self.i]
                .iter()
                .collect::<String>()
                .parse()
                .map_err(|_| "an exponent")?;
        }
        let (int, frac) = mant.split_once('.').unwrap_or((&mant, ""));
        let digits: BigInt = format!("{int}{frac}").parse().map_err(|_| "digits")?;
        let scale = exp - frac.len() as i32;
        // (exactly digits·10^scale, within a unit of the last place)
        let ten = |k: i32| BigInt::from(10).pow(k.max(0).unsigned_abs());
        Ok(H::frac(&(digits * ten(scale)), &ten(-scale)))
    }
}
