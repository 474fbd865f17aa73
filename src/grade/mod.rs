//! Grading (LANGUAGE.md §14): every `assert` of a script run is a test
//! case. Its name is the assert's trailing comment (`assert T ≈ T_book  #
//! (a) the camera [2 pts]`) or `FILE:LINE`; `[N pts]` in that comment sets
//! its points (default 1). A script that stops (an error, the time or
//! memory budget, a file that cannot be read) fails its remaining asserts
//! with the message. One [`Suite`] per script; [`junit`] and
//! [`gradescope`] write a run's suites as one report.

pub mod gradescope;
pub mod junit;

use crate::diagnostics::render;
use crate::session::Report;
use crate::syntax::ast::StmtKind;

/// The report formats of `--report` (LANGUAGE.md §1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// JUnit XML: one `testsuite` per file, one `testcase` per assert.
    Junit,
    /// Gradescope's `results.json`: `score` and `tests[]`.
    Gradescope,
}

impl Format {
    /// `junit` or `gradescope`, as typed after `--report`.
    pub fn parse(s: &str) -> Option<Format> {
        match s {
            "junit" => Some(Format::Junit),
            "gradescope" => Some(Format::Gradescope),
            _ => None,
        }
    }

    /// The report of `suites` in this format, as the file's text.
    pub fn write(self, suites: &[Suite]) -> String {
        match self {
            Format::Junit => junit::write(suites),
            Format::Gradescope => gradescope::write(suites),
        }
    }
}

/// How one assert ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// It ran and held.
    Passed,
    /// It ran and did not hold, or failed to evaluate: the diagnostic as
    /// stderr shows it.
    Failed(String),
    /// It never ran: the script stopped before it (the reason).
    NotRun(String),
}

/// One assert of a script: a test case.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// The trailing comment without its `[N pts]`, else `FILE:LINE`.
    pub name: String,
    /// The 1-based line where the assert starts.
    pub line: usize,
    /// `[N pts]` of its comment, else 1.
    pub points: f64,
    /// Whether it held, failed or never ran.
    pub verdict: Verdict,
    /// Its place among the script's statements (0-based): the session
    /// reports each statement once, in order.
    statement: usize,
}

impl Case {
    /// The points earned: all of them when it passed, none otherwise.
    pub fn score(&self) -> f64 {
        if self.verdict == Verdict::Passed {
            self.points
        } else {
            0.0
        }
    }
}

/// The test cases of one script of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct Suite {
    /// The file as named in messages.
    pub file: String,
    /// Its asserts, in the order of the script.
    pub cases: Vec<Case>,
    /// Why the script stopped before its end (its first error without
    /// `--keep-going`, a spent budget, an unreadable file), if it did.
    pub stopped: Option<String>,
    /// The seconds the script took.
    pub seconds: f64,
    /// The statements reported so far.
    seen: usize,
    /// The first case whose statement has not been reported yet (the
    /// cases are in the order of their statements, which are reported in
    /// order: each report looks at one case, not at all of them).
    next: usize,
}

impl Suite {
    /// The asserts of `src` (file `file`), none of them run yet.
    pub fn new(file: &str, src: &str) -> Suite {
        let mut cases = Vec::new();
        // (lines counted on from the assert before: statements come in
        // order, so a script of many asserts is read once, not once each)
        let (mut counted, mut line) = (0, 1);
        for (statement, parsed) in crate::syntax::statements(src).enumerate() {
            let Ok(stmt) = parsed else { continue };
            if let StmtKind::Assert(_) = stmt.kind {
                let start = stmt.span.start.min(src.len()).max(counted);
                line += src[counted..start].matches('\n').count();
                counted = start;
                let end = stmt.span.end.min(src.len());
                let rest = &src[end..];
                let rest = &rest[..rest.find('\n').unwrap_or(rest.len())];
                let (name, points) = comment(rest);
                cases.push(Case {
                    name: name.unwrap_or_else(|| format!("{file}:{line}")),
                    line,
                    points,
                    verdict: Verdict::NotRun(String::new()),
                    statement,
                });
            }
        }
        Suite {
            file: file.to_string(),
            cases,
            stopped: None,
            seconds: 0.0,
            seen: 0,
            next: 0,
        }
    }

    /// A script that could not be read (`message` says why): its asserts,
    /// found in the bytes read as far as they are text, all fail with the
    /// message; with none found, one case named after the file, of no
    /// points, fails with it.
    pub fn unreadable(file: &str, bytes: Option<&[u8]>, message: &str) -> Suite {
        let text = bytes.map(String::from_utf8_lossy).unwrap_or_default();
        let mut suite = Suite::new(file, &text);
        if suite.cases.is_empty() {
            suite.cases.push(Case {
                name: file.to_string(),
                line: 0,
                points: 0.0,
                verdict: Verdict::NotRun(String::new()),
                statement: usize::MAX,
            });
        }
        suite.stop(message.to_string());
        suite
    }

    /// Notes the report of the script's next statement (call it for each,
    /// in order): an assert's report settles its case (the rendered error
    /// when it failed).
    pub fn observe(&mut self, report: &Report, src: &str) {
        let statement = self.seen;
        self.seen += 1;
        while self
            .cases
            .get(self.next)
            .is_some_and(|c| c.statement < statement)
        {
            self.next += 1;
        }
        let Some(case) = self
            .cases
            .get_mut(self.next)
            .filter(|c| c.statement == statement)
        else {
            return;
        };
        case.verdict = match &report.result {
            Ok(_) => Verdict::Passed,
            Err(d) => Verdict::Failed(render::text_from(d, &self.file, src, report.anchor)),
        };
    }

    /// The script stopped for `reason`: every assert not run yet fails
    /// with it.
    pub fn stop(&mut self, reason: String) {
        for c in &mut self.cases {
            if let Verdict::NotRun(why) = &mut c.verdict
                && why.is_empty()
            {
                *why = format!("not run: the script stopped: {reason}");
            }
        }
        self.stopped = Some(reason);
    }

    /// Closes the suite after its run: asserts that were never reported
    /// fail as not run.
    pub fn finish(&mut self, seconds: f64) {
        self.seconds = seconds;
        for c in &mut self.cases {
            if let Verdict::NotRun(why) = &mut c.verdict
                && why.is_empty()
            {
                *why = "not run".into();
            }
        }
    }

    /// The points earned and the points there were.
    pub fn score(&self) -> (f64, f64) {
        self.cases
            .iter()
            .fold((0.0, 0.0), |(s, m), c| (s + c.score(), m + c.points))
    }
}

/// The name and points of an assert's trailing text (what follows the
/// statement on its line): a `#` comment names the case, `[N pts]` in it
/// (`pt`, `point`, `points` too) sets the points, else 1.
pub fn comment(rest: &str) -> (Option<String>, f64) {
    let rest = rest.trim_start().trim_start_matches(';').trim_start();
    let Some(text) = rest.strip_prefix('#') else {
        return (None, 1.0);
    };
    let mut text = text.trim().to_string();
    let mut points = 1.0;
    if let Some(open) = text.rfind('[')
        && let Some(len) = text[open..].find(']')
    {
        let inner = &text[open + 1..open + len];
        let mut words = inner.split_whitespace();
        let n = words.next().and_then(|w| w.parse::<f64>().ok());
        let unit = words.next();
        if let (Some(n), Some("pt" | "pts" | "point" | "points"), None) = (n, unit, words.next())
            && n.is_finite()
            && n >= 0.0
        {
            points = n;
            text.replace_range(open..=open + len, "");
            text = text.trim().to_string();
        }
    }
    ((!text.is_empty()).then_some(text), points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_comment_names_the_case_and_sets_its_points() {
        assert_eq!(
            comment("  # (a) the camera [2 pts]"),
            (Some("(a) the camera".into()), 2.0)
        );
        assert_eq!(comment("# [0.5 points] half"), (Some("half".into()), 0.5));
        assert_eq!(
            comment("# (b) [see 3.2]"),
            (Some("(b) [see 3.2]".into()), 1.0)
        );
        assert_eq!(comment("# [3 pts]"), (None, 3.0));
        assert_eq!(comment(""), (None, 1.0));
        assert_eq!(comment("; # (c)"), (Some("(c)".into()), 1.0));
    }

    #[test]
    fn a_suite_finds_each_assert_with_its_line() {
        let src = "x = 1\nassert x == 1  # (a) one [2 pts]\n\nassert x == 2\n";
        let s = Suite::new("hw.chs", src);
        assert_eq!(s.cases.len(), 2);
        assert_eq!((s.cases[0].name.as_str(), s.cases[0].line), ("(a) one", 2));
        assert_eq!(s.cases[0].points, 2.0);
        assert_eq!((s.cases[1].name.as_str(), s.cases[1].line), ("hw.chs:4", 4));
        assert_eq!(s.cases[1].points, 1.0);
    }

    /// The suite of `src` after running it to its end (`--keep-going`),
    /// and whether each of its cases passed.
    fn run_suite(src: &str) -> (Suite, Vec<bool>) {
        use crate::eval::env::Mode;
        use crate::session::{Session, Settings};
        let mut suite = Suite::new("hw.chs", src);
        let mut session = Session::new(Settings::default());
        session.run(src, Mode::Run, true, |r| suite.observe(r, src));
        suite.finish(0.0);
        let passed = suite
            .cases
            .iter()
            .map(|c| c.verdict == Verdict::Passed)
            .collect();
        (suite, passed)
    }

    #[test]
    fn each_report_settles_the_assert_it_is_for() {
        // Two asserts on one line, a binding before one on the same line.
        let src = "x = 1; assert x == 2; assert x == 1  # (b)\ny = 2; assert y == 2\n";
        let (suite, verdicts) = run_suite(src);
        assert_eq!(verdicts, [false, true, true]);
        assert!(
            matches!(&suite.cases[0].verdict, Verdict::Failed(m) if m.starts_with("hw.chs:1:15: assert error")),
            "{:?}",
            suite.cases[0].verdict
        );
        assert_eq!(suite.cases[1].name, "(b)");
        assert_eq!(suite.cases[2].name, "hw.chs:2");
    }

    #[test]
    fn many_asserts_each_get_their_own_report() {
        // Asserts between other statements, every third one false, after
        // a syntax error (a statement too).
        let mut src = String::from("x = 1\nz = 1 +* 2\n");
        let mut want = Vec::new();
        for k in 0..40 {
            src.push_str(&format!("y = {k}; z = y\n"));
            let holds = k % 3 != 0;
            let rhs = if holds { k } else { k + 1 };
            src.push_str(&format!("assert z == {rhs}\n"));
            want.push(holds);
        }
        let (suite, verdicts) = run_suite(&src);
        assert_eq!(verdicts, want);
        for (c, holds) in suite.cases.iter().zip(&want) {
            assert!(*holds || matches!(&c.verdict, Verdict::Failed(_)), "{c:?}");
        }
    }

    #[test]
    fn a_stop_fails_the_asserts_not_run() {
        let mut s = Suite::new("hw.chs", "assert 1 == 1\nassert 2 == 2  # b [3 pts]\n");
        s.cases[0].verdict = Verdict::Passed;
        s.stop("the time budget is spent".into());
        s.finish(0.5);
        assert_eq!(s.score(), (1.0, 4.0));
        assert_eq!(
            s.cases[1].verdict,
            Verdict::NotRun("not run: the script stopped: the time budget is spent".into())
        );
    }

    #[test]
    fn an_unreadable_file_fails_its_asserts() {
        let s = Suite::unreadable("x.chs", Some(b"assert 1 == 1 # a\n\xff"), "not UTF-8");
        assert_eq!(s.cases.len(), 1);
        assert_eq!(s.cases[0].name, "a");
        assert_eq!(s.score(), (0.0, 1.0));
        let none = Suite::unreadable("y.chs", None, "no such file");
        assert_eq!(none.cases[0].name, "y.chs");
        assert_eq!(none.score(), (0.0, 0.0));
    }
}
