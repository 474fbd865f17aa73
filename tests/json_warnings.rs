//! The JSON `warnings` field (LANGUAGE.md §1): every note and warning text
//! output prints for a statement is in that statement's JSON object as
//! `{"kind": "note"|"warning", "message", "help"?}`, and nothing else is.
//! Checked on chosen statements (branch notes, gimbal lock, rounding, a
//! near-SE(3) matrix, an error's warnings) and against every example
//! script: the notes of its text run and the warnings of its JSON run are
//! the same, statement by statement.

mod common;
use common::{json_lines, run};
use serde_json::{Value as J, json};

/// The JSON objects of `src` run with `--json` (keep going).
fn objects(src: &str) -> Vec<J> {
    let (_, out, _) = run(&["--json", "--keep-going", "-e", src]);
    json_lines(&out)
}

#[test]
fn a_branch_note_is_in_the_json_object() {
    let lines = objects("given t : scalar\ny = atan2(sin(t), cos(t))\n");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert_eq!(lines[0]["line"], 2);
    assert_eq!(lines[0]["value"], "t");
    assert_eq!(
        lines[0]["warnings"],
        json!([{"kind": "note", "message": "atan2 of symbolic arguments: the closed form on the branch t in (−π, π]"}])
    );
}

#[test]
fn statements_without_notes_have_no_warnings_key() {
    let lines = objects("x = 1 + 1\nRotz(pi/2)\n");
    assert_eq!(lines.len(), 2);
    for l in &lines {
        assert!(l.get("warnings").is_none(), "{l}");
    }
    assert_eq!(lines[0]["value"], 2);
}

#[test]
fn gimbal_lock_and_near_se3_are_warnings() {
    let lines = objects(
        "euler_zyx(Roty(pi/2))\nA = [1, 0, 0, 1; 0, 1, 0, 0; 0, 0, 2, 0; 0, 0, 0, 1]\nDistanceToSE3(A)\n",
    );
    let w = &lines[0]["warnings"];
    assert_eq!(w[0]["kind"], "warning", "{w}");
    assert!(
        w[0]["message"].as_str().unwrap().starts_with("gimbal lock"),
        "{w}"
    );
    // the value is still the book's: b = π/2, c = 0
    let b = lines[0]["value"][1].as_f64().unwrap();
    assert!(
        (b - std::f64::consts::FRAC_PI_2).abs() < 1e-12,
        "{}",
        lines[0]
    );
    // the near-SE(3) warning is on A's own line, with its help
    let w = &lines[1]["warnings"][0];
    assert_eq!(w["kind"], "warning", "{}", lines[1]);
    assert_eq!(
        w["message"],
        "A looks like a transform (last row 0, 0, 0, 1) but is not one: it is 3 from SE(3) (DistanceToSE3)"
    );
    assert!(w["help"].as_str().unwrap().contains("Prop. 3.1"), "{w}");
    assert_eq!(lines[2]["value"], 3);
    assert!(lines[2].get("warnings").is_none(), "{}", lines[2]);
}

#[test]
fn a_rounding_note_and_its_help_are_carried() {
    let lines = objects("x = exp([(0.1, 0.2, 0.3)])\nx[1,1]^2 + x[2,1]^2 + x[3,1]^2 == 1\n");
    let w = &lines[1]["warnings"];
    assert_eq!(lines[1]["value"], false);
    assert_eq!(w[0]["kind"], "note", "{w}");
    assert!(
        w[0]["message"]
            .as_str()
            .unwrap()
            .contains("differ by rounding only"),
        "{w}"
    );
    // a help, when the note has one, is a string; absent otherwise
    if let Some(h) = w[0].get("help") {
        assert!(h.is_string(), "{w}");
    }
}

#[test]
fn an_error_object_carries_the_statements_warnings() {
    // --frames warn: the frame warning, then the statement's own error
    let (_, out, _) = run(&[
        "--json",
        "--frames",
        "warn",
        "-e",
        "T_ab = Trans((1, 0, 0))\nT_cb = Trans((0, 1, 0))\ndet(T_ab * T_cb) + sqrt(-1)\n",
    ]);
    let lines = json_lines(&out);
    let last = lines.last().unwrap();
    assert_eq!(last["error"]["kind"], "domain", "{last}");
    assert_eq!(last["warnings"][0]["kind"], "warning", "{last}");
    assert!(
        last["warnings"][0]["message"]
            .as_str()
            .unwrap()
            .contains("frames do not cancel"),
        "{last}"
    );
    assert_eq!(
        last["warnings"][0]["help"],
        "X_xy maps coordinates in {y} to {x}; did you mean inv(T_cb) = T_bc?"
    );
}

/// `(kind, message)` of each `FILE:LINE:COL: note|warning: message` header
/// in text output's stderr, with its line.
fn text_notes(stderr: &str) -> Vec<(usize, String, String)> {
    let mut out = Vec::new();
    for l in stderr.lines() {
        for kind in ["note", "warning"] {
            let tag = format!(": {kind}: ");
            if let Some(at) = l.find(&tag) {
                let head: Vec<&str> = l[..at].rsplitn(3, ':').collect();
                if let [_col, line, _file] = head.as_slice()
                    && let Ok(line) = line.parse()
                {
                    out.push((line, kind.to_string(), l[at + tag.len()..].to_string()));
                }
            }
        }
    }
    out
}

#[test]
fn every_examples_notes_are_in_its_json_and_nothing_else() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scripts: Vec<_> = std::fs::read_dir(root.join("examples"))
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "chs"))
        .collect();
    scripts.sort();
    assert!(scripts.len() > 20, "{scripts:?}");
    // (a folder of its own: tests/examples.rs clears its folder first)
    let draw = common::scratch("json-warnings-pictures");
    let draw = draw.to_str().unwrap();
    let mut seen = 0;
    for path in &scripts {
        let p = path.to_str().unwrap();
        let (code, _, err) = run(&["run", "--draw-dir", draw, p]);
        assert_eq!(code, 0, "{p}: {err}");
        let (jcode, jout, _) = run(&["run", "--json", "--draw-dir", draw, p]);
        assert_eq!(jcode, 0, "{p}");
        let text = text_notes(&err);
        let lines = json_lines(&jout);
        // every JSON warning, with the line of the statement it is on
        let mut json: Vec<(usize, String, String)> = Vec::new();
        for l in &lines {
            let n = l["line"].as_u64().unwrap() as usize;
            for w in l
                .get("warnings")
                .and_then(J::as_array)
                .into_iter()
                .flatten()
            {
                let kind = w["kind"].as_str().unwrap().to_string();
                assert!(kind == "note" || kind == "warning", "{p}: {w}");
                json.push((n, kind, w["message"].as_str().unwrap().to_string()));
            }
        }
        assert_eq!(
            text.len(),
            json.len(),
            "{p}:\ntext {text:#?}\njson {json:#?}"
        );
        for ((tl, tk, tm), (jl, jk, jm)) in text.iter().zip(&json) {
            // the note is on the statement's lines (a statement may span
            // several), and says the same thing
            assert!(jl <= tl, "{p}: {tl} {tm} / {jl} {jm}");
            assert_eq!((tk, tm), (jk, jm), "{p}:{tl}");
            let next = lines
                .iter()
                .filter_map(|l| l["line"].as_u64())
                .find(|&n| n as usize > *jl);
            assert!(next.is_none_or(|n| *tl < n as usize), "{p}:{tl}: {tm}");
        }
        seen += text.len();
    }
    // the examples do print notes: the check above is not empty
    assert!(seen >= 30, "{seen} notes in the examples");
}

#[test]
fn a_statement_that_prints_nothing_keeps_its_warnings() {
    // an assert that holds prints no value; its frame warning (text output
    // prints it) comes as an object with the line and the warnings only
    let (code, out, _) = run(&[
        "--json",
        "--frames",
        "warn",
        "-e",
        "T_ab = Trans((1, 0, 0))\nT_cb = Trans((0, 1, 0))\nassert det(T_ab * T_cb) == 1\nx = 2\n",
    ]);
    assert_eq!(code, 0);
    let lines = json_lines(&out);
    assert_eq!(lines.len(), 4, "{out}");
    assert_eq!(lines[2]["line"], 3);
    assert!(lines[2].get("value").is_none(), "{}", lines[2]);
    assert_eq!(lines[2]["warnings"][0]["message"], "frames do not cancel");
    assert_eq!(lines[3]["value"], 2);
}
