//! The LaTeX that chasles prints for a symbolic scalar (LANGUAGE.md §7,
//! `--latex`, JSON's `"latex"`), read back as chasles source, so that the
//! differential test can evaluate it against the value (issue 35: the
//! LaTeX of `1/tan(t)` was `\frac{1}{\left(\cos t\right) \sin t}`). Only
//! what the printer writes is read: `\frac`, `\sqrt`, `\left( \right)`,
//! `\operatorname`, the trigonometric functions with a power and a one-token
//! or bracketed argument, `\dot{q}_1`, `\pi`, powers and subscripts.

/// The source text of `latex`; None where it holds something not read here.
pub fn source(latex: &str) -> Option<String> {
    let chars: Vec<char> = latex.chars().collect();
    let mut r = Reader { s: &chars, at: 0 };
    let out = r.sequence(None)?;
    (r.at == chars.len()).then_some(out)
}

struct Reader<'a> {
    s: &'a [char],
    at: usize,
}

const TRIG: [&str; 6] = ["sin", "cos", "tan", "cot", "sec", "csc"];

impl Reader<'_> {
    fn peek(&self) -> Option<char> {
        self.s.get(self.at).copied()
    }

    fn spaces(&mut self) {
        while self.peek() == Some(' ') {
            self.at += 1;
        }
    }

    /// Items up to `end` (consumed) or the end of the text.
    fn sequence(&mut self, end: Option<char>) -> Option<String> {
        let mut out = String::new();
        loop {
            match self.peek() {
                None => return end.is_none().then_some(out),
                Some(c) if Some(c) == end => {
                    self.at += 1;
                    return Some(out);
                }
                Some(_) => out += &self.item()?,
            }
        }
    }

    /// `{…}` as a parenthesized expression.
    fn group(&mut self) -> Option<String> {
        self.spaces();
        if self.peek()? != '{' {
            return None;
        }
        self.at += 1;
        Some(format!("({})", self.sequence(Some('}'))?))
    }

    /// The raw letters of `{…}` (a name).
    fn word_group(&mut self) -> Option<String> {
        if self.peek()? != '{' {
            return None;
        }
        let end = self.s[self.at..].iter().position(|c| *c == '}')? + self.at;
        let w: String = self.s[self.at + 1..end].iter().collect();
        self.at = end + 1;
        Some(w)
    }

    /// A subscript `_1` or `_{12}`, as the digits it appends.
    fn subscript(&mut self) -> Option<String> {
        if self.peek() != Some('_') {
            return Some(String::new());
        }
        self.at += 1;
        match self.peek()? {
            '{' => self.word_group(),
            c => {
                self.at += 1;
                Some(c.to_string())
            }
        }
    }

    fn command(&mut self) -> Option<String> {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
            self.at += 1;
        }
        let name: String = self.s[start..self.at].iter().collect();
        Some(match name.as_str() {
            "frac" => format!("({}/{})", self.group()?, self.group()?),
            "sqrt" => format!("sqrt{}", self.group()?),
            "left" | "right" => {
                let c = self.peek()?;
                self.at += 1;
                c.to_string()
            }
            "operatorname" => self.word_group()?,
            // `\exp\left(…\right)`: the name, then its bracket
            "exp" if self.s[self.at..].starts_with(&['\\', 'l', 'e', 'f', 't', '(']) => {
                "exp".into()
            }
            "pi" => "pi".into(),
            "cdot" => "*".into(),
            "dot" | "ddot" => {
                let base = self.word_group()?;
                let sub = self.subscript()?;
                let dots = if name == "dot" { "'" } else { "''" };
                format!("{base}{sub}{dots}")
            }
            f if TRIG.contains(&f) => {
                let power = match self.peek() {
                    Some('^') => {
                        self.at += 1;
                        Some(self.group()?)
                    }
                    _ => None,
                };
                self.spaces();
                let arg = match self.peek()? {
                    '(' => {
                        self.at += 1;
                        format!("({})", self.sequence(Some(')'))?)
                    }
                    _ => format!("({})", self.atom()?),
                };
                match power {
                    Some(p) => format!("{f}{arg}^{p}"),
                    None => format!("{f}{arg}"),
                }
            }
            _ => return None,
        })
    }

    /// One token: a name with its subscript, a number, or a command.
    fn atom(&mut self) -> Option<String> {
        let c = self.peek()?;
        if c == '\\' {
            self.at += 1;
            return self.command();
        }
        if c.is_ascii_alphanumeric() || c == '.' {
            let start = self.at;
            while self
                .peek()
                .is_some_and(|c| c.is_ascii_alphanumeric() || c == '.')
            {
                self.at += 1;
            }
            let word: String = self.s[start..self.at].iter().collect();
            return Some(word + &self.subscript()?);
        }
        None
    }

    fn item(&mut self) -> Option<String> {
        match self.peek()? {
            '{' => self.group(),
            '^' => {
                self.at += 1;
                match self.peek()? {
                    '{' => Some(format!("^{}", self.group()?)),
                    c => {
                        self.at += 1;
                        Some(format!("^{c}"))
                    }
                }
            }
            c @ (' ' | '+' | '-' | '(' | ')' | ',' | '/') => {
                self.at += 1;
                Some(c.to_string())
            }
            _ => self.atom(),
        }
    }
}

#[test]
fn the_printers_latex_reads_back() {
    for (latex, want) in [
        ("\\cot t", "cot(t)"),
        (
            "\\frac{1}{\\left(2 \\cos a + b\\right)}",
            "((1)/((2 cos(a) + b)))",
        ),
        ("\\tan^{2} b", "tan(b)^(2)"),
        ("2 q_1 \\dot{q}_1", "2 q1 q1'"),
        ("\\ddot{q}_{2}", "q2''"),
        ("\\sin(2 a + \\frac{\\pi}{6})", "sin(2 a + ((pi)/(6)))"),
        ("\\operatorname{atan2}\\left(a, b\\right)", "atan2(a, b)"),
        (
            "\\exp\\left(\\left(\\frac{1}{2} - \\frac{\\sqrt{5}}{2}\\right) t\\right)",
            "exp((((1)/(2)) - ((sqrt(5))/(2))) t)",
        ),
        ("\\sqrt{1 + a} a^{2}", "sqrt(1 + a) a^(2)"),
    ] {
        assert_eq!(source(latex).as_deref(), Some(want), "{latex}");
    }
    assert_eq!(source("\\begin{bmatrix}"), None);
}
