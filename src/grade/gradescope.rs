//! A run's asserts as Gradescope's `results.json` (LANGUAGE.md §14; the
//! fields Gradescope's autograder documents): `score` (the points earned
//! over every script), `max_score`, and `tests[]`, one per assert, with
//! `name`, `score`, `max_score`, `status` (`passed` or `failed`) and
//! `output` (the failure as stderr shows it). `output` at the top says
//! which scripts stopped.

use serde_json::{Value as J, json};

use super::{Suite, Verdict};

/// A number of points as JSON: whole numbers without a fraction.
fn points(x: f64) -> J {
    if x == x.trunc() && x.abs() < 1e15 {
        json!(x as i64)
    } else {
        json!(x)
    }
}

/// The `results.json` of `suites`, pretty-printed.
pub fn write(suites: &[Suite]) -> String {
    let mut tests = Vec::new();
    let (mut score, mut max) = (0.0, 0.0);
    let mut stopped = Vec::new();
    for s in suites {
        let (got, of) = s.score();
        score += got;
        max += of;
        if let Some(why) = &s.stopped {
            stopped.push(format!("{}: stopped: {why}", s.file));
        }
        for c in &s.cases {
            let (status, output) = match &c.verdict {
                Verdict::Passed => ("passed", String::new()),
                Verdict::Failed(text) | Verdict::NotRun(text) => ("failed", text.clone()),
            };
            tests.push(json!({
                "name": c.name,
                "score": points(c.score()),
                "max_score": points(c.points),
                "status": status,
                "output": output,
                "number": format!("{}:{}", s.file, c.line),
            }));
        }
    }
    let mut out = json!({
        "score": points(score),
        "max_score": points(max),
        "tests": tests,
    });
    if !stopped.is_empty() {
        out["output"] = json!(stopped.join("\n"));
    }
    let mut text = serde_json::to_string_pretty(&out).unwrap_or_default();
    text.push('\n');
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_score_adds_the_points_of_the_asserts_that_held() {
        let mut s = Suite::new(
            "hw.chs",
            "assert 1 == 1  # (a) [2 pts]\nassert 1 == 2  # (b) [0.5 pts]\n",
        );
        s.cases[0].verdict = Verdict::Passed;
        s.cases[1].verdict = Verdict::Failed("hw.chs:2:8: assert error: no\n".into());
        s.finish(0.1);
        let j: J = serde_json::from_str(&write(&[s])).expect("JSON");
        assert_eq!(j["score"], 2);
        assert_eq!(j["max_score"], 2.5);
        assert_eq!(j["tests"][0]["name"], "(a)");
        assert_eq!(j["tests"][0]["status"], "passed");
        assert_eq!(j["tests"][1]["score"], 0);
        assert_eq!(j["tests"][1]["max_score"], 0.5);
        assert_eq!(j["tests"][1]["status"], "failed");
        assert_eq!(j["tests"][1]["output"], "hw.chs:2:8: assert error: no\n");
        assert!(j.get("output").is_none());
    }
}
