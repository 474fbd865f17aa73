//! A run's asserts as JUnit XML (LANGUAGE.md §14), the format of Ant's
//! `XMLJUnitResultFormatter` that CI servers and autograders read:
//! `testsuites` holding one `testsuite` per script, one `testcase` per
//! assert (`classname` the file, `name` the case's), a `failure` for an
//! assert that did not hold and an `error` for one the script never ran.
//! Points are kept as the case's `points` property.

use super::{Suite, Verdict};

/// `s` as XML text or attribute value: `& < > " '` as entities, and the
/// characters XML 1.0 cannot hold (controls but tab, newline, return) as
/// `\xNN`.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' | '\r' => out.push(c),
            c if (c as u32) < 0x20 || c == '\u{fffe}' || c == '\u{ffff}' => {
                out.push_str(&format!("\\x{:02x}", c as u32));
            }
            c => out.push(c),
        }
    }
    out
}

/// The first line of a rendered diagnostic (`FILE:LINE:COL: kind error:
/// message`), for a `message` attribute.
fn headline(text: &str) -> &str {
    text.lines().next().unwrap_or("")
}

/// The JUnit XML of `suites`.
pub fn write(suites: &[Suite]) -> String {
    let count =
        |s: &Suite, f: fn(&Verdict) -> bool| s.cases.iter().filter(|c| f(&c.verdict)).count();
    let failed = |v: &Verdict| matches!(v, Verdict::Failed(_));
    let not_run = |v: &Verdict| matches!(v, Verdict::NotRun(_));
    let total = |f: fn(&Verdict) -> bool| suites.iter().map(|s| count(s, f)).sum::<usize>();
    let mut x = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    x.push_str(&format!(
        "<testsuites name=\"chasles\" tests=\"{}\" failures=\"{}\" errors=\"{}\" time=\"{:.3}\">\n",
        total(|_| true),
        total(failed),
        total(not_run),
        suites.iter().map(|s| s.seconds).sum::<f64>(),
    ));
    for (id, s) in suites.iter().enumerate() {
        let (score, max) = s.score();
        x.push_str(&format!(
            "  <testsuite name=\"{}\" id=\"{id}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"0\" time=\"{:.3}\">\n",
            escape(&s.file),
            s.cases.len(),
            count(s, failed),
            count(s, not_run),
            s.seconds,
        ));
        x.push_str(&format!(
            "    <properties>\n      <property name=\"score\" value=\"{score}\"/>\n      <property name=\"max_score\" value=\"{max}\"/>\n    </properties>\n"
        ));
        for c in &s.cases {
            x.push_str(&format!(
                "    <testcase name=\"{}\" classname=\"{}\" time=\"0\">\n",
                escape(&c.name),
                escape(&s.file),
            ));
            x.push_str(&format!(
                "      <properties>\n        <property name=\"line\" value=\"{}\"/>\n        <property name=\"points\" value=\"{}\"/>\n      </properties>\n",
                c.line, c.points
            ));
            match &c.verdict {
                Verdict::Passed => {}
                Verdict::Failed(text) => x.push_str(&format!(
                    "      <failure message=\"{}\" type=\"assert\">{}</failure>\n",
                    escape(headline(text)),
                    escape(text)
                )),
                Verdict::NotRun(why) => x.push_str(&format!(
                    "      <error message=\"{}\" type=\"stopped\">{}</error>\n",
                    escape(headline(why)),
                    escape(why)
                )),
            }
            x.push_str("    </testcase>\n");
        }
        if let Some(why) = &s.stopped {
            x.push_str(&format!(
                "    <system-err>{}</system-err>\n",
                escape(&format!("{}: stopped: {why}", s.file))
            ));
        }
        x.push_str("  </testsuite>\n");
    }
    x.push_str("</testsuites>\n");
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_escaped_for_xml() {
        assert_eq!(
            escape("a < b & \"c\"\u{1b}[0m"),
            "a &lt; b &amp; &quot;c&quot;\\x1b[0m"
        );
    }

    #[test]
    fn each_assert_is_a_testcase_with_its_verdict() {
        let mut s = Suite::new(
            "hw.chs",
            "assert 1 == 1  # (a) [2 pts]\nassert 1 == 2\nassert 3 == 3\n",
        );
        s.cases[0].verdict = Verdict::Passed;
        s.cases[1].verdict = Verdict::Failed("hw.chs:2:8: assert error: 1 ≠ 2\n".into());
        s.stop("hw.chs:2:8: assert error: 1 ≠ 2".into());
        s.finish(0.25);
        let xml = write(&[s]);
        assert!(xml.contains("<testsuites name=\"chasles\" tests=\"3\" failures=\"1\" errors=\"1\" time=\"0.250\">"), "{xml}");
        assert!(
            xml.contains("<testcase name=\"(a)\" classname=\"hw.chs\""),
            "{xml}"
        );
        assert!(
            xml.contains("<failure message=\"hw.chs:2:8: assert error: 1 ≠ 2\" type=\"assert\">"),
            "{xml}"
        );
        assert!(
            xml.contains("<error message=\"not run: the script stopped: hw.chs:2:8"),
            "{xml}"
        );
        assert!(
            xml.contains("<property name=\"score\" value=\"2\"/>"),
            "{xml}"
        );
        assert!(
            xml.contains("<property name=\"max_score\" value=\"4\"/>"),
            "{xml}"
        );
    }
}
