//! `chasles lsp` (LANGUAGE.md §15) driven over stdio as an editor drives
//! it: the real binary, Content-Length framed JSON-RPC, every wait bounded
//! so that a silent server fails the test instead of hanging it.

mod common;

use std::io::{Read, Write};
use std::path::Path;
use std::process::Stdio;
use std::time::{Duration, Instant};

use common::lsp::{Client, WAIT};
use serde_json::{Value, json};

const URI: &str = "file:///work/frames.chs";

/// This file's steps over the shared client ([`common::lsp`]): one
/// document, `URI`.
impl Client {
    /// Starts `chasles lsp` in `dir` and initializes it.
    fn start(dir: &Path) -> (Client, Value) {
        Client::start_with(Some(dir), &["lsp"])
    }

    /// The diagnostics published for `URI` at `version`.
    fn diagnostics(&mut self, version: i64) -> Vec<Value> {
        self.diagnostics_of(URI, version)
    }

    fn open(&mut self, text: &str) {
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": URI, "languageId": "chasles", "version": 1, "text": text}}),
        );
    }

    /// Replaces line `line`, columns `from..to` (UTF-16 units), by `text`.
    fn edit(&mut self, version: i64, line: u32, from: u32, to: u32, text: &str) {
        self.notify(
            "textDocument/didChange",
            json!({
                "textDocument": {"uri": URI, "version": version},
                "contentChanges": [{
                    "range": {"start": {"line": line, "character": from}, "end": {"line": line, "character": to}},
                    "text": text,
                }],
            }),
        );
    }

    fn at(&mut self, method: &str, line: u32, character: u32) -> Value {
        self.request(
            method,
            json!({"textDocument": {"uri": URI}, "position": {"line": line, "character": character}}),
        )
    }

    /// `shutdown` then `exit`: the exit code.
    fn stop(mut self) -> i32 {
        assert_eq!(self.request("shutdown", Value::Null), Value::Null);
        self.notify("exit", Value::Null);
        self.exit_code("`exit`")
    }
}

const SCRIPT: &str = "\
given T_ab, T_cb : SE3
T_bc = inv(T_cb)
R_sb = Rotz(30 deg)
T_ac = T_ab * T_cb
w_b = (0, 0, 1)
";

/// Labels of a completion list, ordered as the client sorts them.
fn labels(items: &Value) -> Vec<String> {
    let mut items = items.as_array().expect("a completion array").clone();
    items.sort_by_key(|i| {
        i["sortText"]
            .as_str()
            .unwrap_or(i["label"].as_str().unwrap())
            .to_string()
    });
    items
        .iter()
        .map(|i| i["label"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn a_frame_error_appears_and_disappears_as_the_line_is_edited() {
    let dir = common::scratch("frames");
    let (mut c, init) = Client::start(&dir);
    let caps = &init["capabilities"];
    assert_eq!(caps["textDocumentSync"], json!(2), "incremental sync");
    assert_eq!(caps["hoverProvider"], json!(true));
    assert_eq!(caps["definitionProvider"], json!(true));
    assert_eq!(caps["documentSymbolProvider"], json!(true));
    assert_eq!(init["serverInfo"]["name"], "chasles");

    c.open(SCRIPT);
    let d = c.diagnostics(1);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "frame");
    assert_eq!(d[0]["severity"], json!(1));
    assert_eq!(d[0]["message"], "frames do not cancel");
    // The caret is the `*` of line 4 (0-based line 3, column 12).
    assert_eq!(
        d[0]["range"],
        json!({"start": {"line": 3, "character": 12}, "end": {"line": 3, "character": 13}})
    );
    let related: Vec<&str> = d[0]["relatedInformation"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["message"].as_str().unwrap())
        .collect();
    assert!(related.contains(&"{b} in {c}"), "{related:?}");
    assert!(
        related
            .iter()
            .any(|m| m.starts_with("help:") && m.contains("inv(T_cb) = T_bc")),
        "{related:?}"
    );

    // Fix it: T_cb → T_bc (columns 14..18 of line 3).
    c.edit(2, 3, 14, 18, "T_bc");
    assert_eq!(c.diagnostics(2), Vec::<Value>::new());
    // Break it again in a second way: a rotation times a transform.
    c.edit(3, 3, 7, 11, "R_sb");
    let d = c.diagnostics(3);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "type");
    c.edit(4, 3, 7, 11, "T_ab");
    assert_eq!(c.diagnostics(4), Vec::<Value>::new());

    // Hover: a binding's type and frames; a builtin's :help text.
    let h = c.at("textDocument/hover", 3, 1);
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("SE(3) {a}←{c}"), "{text}");
    assert!(text.contains("maps coordinates in {c} to {a}"), "{text}");
    // T_ac is made of given symbols: its value is the product, kept
    // symbolic, with T_bc's own value inv(T_cb).
    assert!(text.contains("= `T_ab inv(T_cb)`"), "{text}");
    let h = c.at("textDocument/hover", 2, 1);
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("SO(3) {s}←{b}"), "{text}");
    assert!(text.contains("= `[0.866"), "R_sb's value: {text}");
    assert_eq!(
        h["range"],
        json!({"start": {"line": 2, "character": 0}, "end": {"line": 2, "character": 4}})
    );
    let h = c.at("textDocument/hover", 2, 9);
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("Rotz(θ)") || text.contains("Rotz("), "{text}");
    assert!(text.contains("3.2"), "the book's section: {text}");

    // Go to definition: T_bc read on line 4 was bound on line 2.
    let loc = c.at("textDocument/definition", 3, 15);
    assert_eq!(loc["uri"], URI);
    assert_eq!(
        loc["range"],
        json!({"start": {"line": 1, "character": 0}, "end": {"line": 1, "character": 4}})
    );
    // A given's definition is its name in the `given` line.
    let loc = c.at("textDocument/definition", 3, 8);
    assert_eq!(loc["range"]["start"], json!({"line": 0, "character": 6}));

    // Completion after `MatrixLo`, then after `T_ab * `.
    c.edit(5, 5, 0, 0, "MatrixLo");
    let items = c.at("textDocument/completion", 5, 8);
    let l = labels(&items);
    assert!(
        l.contains(&"MatrixLog3".into()) && l.contains(&"MatrixLog6".into()),
        "{l:?}"
    );
    assert!(
        l.iter().all(|n| n.to_lowercase().starts_with("matrixlo")),
        "{l:?}"
    );
    let six = items
        .as_array()
        .unwrap()
        .iter()
        .find(|i| i["label"] == "MatrixLog6")
        .unwrap();
    assert!(
        six["detail"].as_str().unwrap().starts_with("MatrixLog6("),
        "{six}"
    );
    c.edit(6, 5, 0, 8, "x = T_ab * ");
    let l = labels(&c.at("textDocument/completion", 5, 11));
    // {b} is T_ab's inner frame: T_bc (outer {b}) comes before the others.
    assert_eq!(l[0], "T_bc", "{l:?}");
    assert!(
        l.contains(&"T_ac".into()) && l.contains(&"Rotz".into()),
        "{l:?}"
    );
    let l = labels(&c.at("textDocument/completion", 5, 0));
    assert!(l.contains(&"given".into()), "{l:?}");
    c.edit(7, 5, 0, 11, "given q : S");
    let l = labels(&c.at("textDocument/completion", 5, 11));
    assert_eq!(
        l,
        [
            "SE2", "SE3", "SO2", "SO3", "scalar", "screw", "se2", "se3", "so2", "so3"
        ]
    );
    c.edit(8, 5, 0, 11, ":");
    let l = labels(&c.at("textDocument/completion", 5, 1));
    assert!(
        l.contains(&":help".into()) && l.contains(&":vars".into()),
        "{l:?}"
    );

    // Document symbols: every binding, with its type.
    let s = c.request(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": URI}}),
    );
    let names: Vec<&str> = s
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["T_ab", "T_cb", "T_bc", "R_sb", "T_ac", "w_b"]);
    assert_eq!(s.as_array().unwrap()[4]["detail"], "SE(3) {a}←{c}");

    assert_eq!(c.stop(), 0);
}

#[test]
fn a_script_that_would_run_for_minutes_and_write_files_is_only_checked() {
    let dir = common::scratch("effects");
    let (mut c, _) = Client::start(&dir);
    // Run, each grid below is a million transforms (seconds each, and the
    // last is a frame error); the pictures would be written as pic.svg and
    // saved.svg.
    let mut text = String::new();
    for i in 0..6 {
        text.push_str(&format!(
            "g{i} = [MatrixExp6(VecTose3((0, 0, 1, a, b, {i}))) for a in 1:1000, b in 1:1000]\n"
        ));
    }
    text.push_str("pic = draw(Rotz(pi/4))\npic\nsave(draw(Rotz(1)), \"saved.svg\")\n");
    text.push_str("given T_ab, T_cb : SE3\nT_ab T_cb\n");
    let start = Instant::now();
    c.open(&text);
    let d = c.diagnostics(1);
    let took = start.elapsed();
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "frame");
    assert_eq!(d[0]["range"]["start"]["line"], json!(10));
    // Checked without numbers: far below the seconds each grid takes to run.
    assert!(took < Duration::from_secs(20), "checking took {took:?}");
    let h = c.at("textDocument/hover", 0, 0);
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("list"), "{text}");
    // Its value would take seconds: the hover says it was not computed.
    assert!(text.contains("value not computed"), "{text}");
    let took = start.elapsed();
    assert!(took < Duration::from_secs(20), "hover took {took:?}");
    // `save`'s help shows its example, save(draw(Rotz(pi/4)), "rotz.svg"),
    // evaluated without writing rotz.svg.
    let h = c.at("textDocument/hover", 8, 1);
    let text = h["contents"]["value"].as_str().unwrap();
    assert!(text.contains("\"rotz.svg\")"), "{text}");
    assert_eq!(c.stop(), 0);
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(left.is_empty(), "the server wrote {left:?}");
}

#[test]
fn syntax_and_domain_errors_and_warnings_under_the_command_line_flags() {
    let dir = common::scratch("kinds");
    // `--frames warn` before `lsp` applies: a frame mismatch is a warning.
    let (mut c, _) = Client::start_with(Some(&dir), &["--frames", "warn", "lsp"]);
    c.open(
        "dof(mech < links 4; joints 4S; planar >)\nx = (1, 2\ny = 1\ngiven T_ab, T_cb : SE3\nT_ab * T_cb\n",
    );
    let d = c.diagnostics(1);
    let seen: Vec<(u64, &str, u64)> = d
        .iter()
        .map(|d| {
            (
                d["range"]["start"]["line"].as_u64().unwrap(),
                d["code"].as_str().unwrap(),
                d["severity"].as_u64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        seen,
        [(0, "domain", 1), (1, "syntax", 1), (4, "frame", 2)],
        "{d:?}"
    );
    assert!(
        d[0]["message"]
            .as_str()
            .unwrap()
            .contains("spherical joint (S)"),
        "{d:?}"
    );
    assert_eq!(d[1]["message"], "unclosed '(' opened here");
    // A control character in a message is escaped as `chasles check`
    // shows it (the message held a raw NUL).
    c.edit(2, 0, 0, 0, "x = 1\0\n");
    let d = c.diagnostics(2);
    assert_eq!(
        d[0]["message"], "expected an operator or end of input, found '\\0'",
        "{d:?}"
    );
    assert_eq!(c.stop(), 0);
}

/// A leading byte-order mark is skipped as `chasles check` skips it (it
/// was "expected an expression, found '\u{feff}'" on line 1, and every
/// binding after it unknown); positions still count it, as the editor does.
#[test]
fn a_leading_byte_order_mark_is_skipped() {
    let dir = common::scratch("bom");
    let (mut c, _) = Client::start(&dir);
    c.open("\u{feff}x = 1 + (1, 2)\ny = 2\n");
    let d = c.diagnostics(1);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["message"], "cannot add a scalar and a 2-vector");
    assert_eq!(d[0]["range"]["start"], json!({"line": 0, "character": 7}));
    assert_eq!(c.stop(), 0);
}

#[test]
fn changes_typed_quickly_are_checked_once() {
    let dir = common::scratch("debounce");
    let (mut c, _) = Client::start(&dir);
    c.open("given T_ab, T_cb : SE3\nx = 1\n");
    assert_eq!(c.diagnostics(1), Vec::<Value>::new());
    // Three keystrokes in one write, well inside the debounce: `T_ab * T_cb`
    // typed as three changes; one check, of the last version.
    let mut burst = String::new();
    for (v, (from, text)) in [(0, "T_ab"), (4, " * "), (7, "T_cb")]
        .into_iter()
        .enumerate()
    {
        let body = json!({
            "jsonrpc": "2.0",
            "method": "textDocument/didChange",
            "params": {
                "textDocument": {"uri": URI, "version": v + 2},
                "contentChanges": [{
                    "range": {"start": {"line": 2, "character": from}, "end": {"line": 2, "character": from}},
                    "text": text,
                }],
            },
        })
        .to_string();
        burst.push_str(&format!("Content-Length: {}\r\n\r\n{body}", body.len()));
    }
    c.stdin.write_all(burst.as_bytes()).unwrap();
    c.stdin.flush().unwrap();
    let d = c.diagnostics(4);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0]["code"], "frame");
    assert_eq!(d[0]["range"]["start"], json!({"line": 2, "character": 5}));
    let early: Vec<&Value> = c
        .pending
        .iter()
        .filter(|v| v["method"] == "textDocument/publishDiagnostics")
        .collect();
    assert!(
        early.is_empty(),
        "versions 2 and 3 were checked too: {early:?}"
    );
    assert_eq!(c.stop(), 0);
}

#[test]
fn exit_without_shutdown_is_an_error_and_a_bad_request_is_answered() {
    let dir = common::scratch("exit");
    let (mut c, _) = Client::start(&dir);
    c.next_id += 1;
    let id = c.next_id;
    c.send(json!({"jsonrpc": "2.0", "id": id, "method": "textDocument/formatting", "params": {}}));
    let v = c.next("an error reply");
    assert_eq!(v["id"], json!(id));
    assert_eq!(v["error"]["code"], json!(-32601));
    // Hover on a document never opened: no answer, no crash.
    assert_eq!(c.at("textDocument/hover", 0, 0), Value::Null);
    c.notify("exit", Value::Null);
    assert_eq!(c.exit_code("`exit`"), 1);
}

/// The TextMate grammar (editors/vscode/) colours every builtin as one: its
/// `builtin` pattern lists exactly the names of the builtin table, longest
/// first. `UPDATE_GRAMMAR=1 cargo test --test lsp editor_grammar` rewrites
/// it from the table (then `node tokenize.js --update` in
/// editors/vscode/test/ for the scopes' snapshots).
#[test]
fn the_editor_grammar_lists_every_builtin() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/editors/vscode/syntaxes/chasles.tmLanguage.json"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let mut g: Value = serde_json::from_str(&text).unwrap();
    let mut names: Vec<String> = chasles::builtins::all_names()
        .into_iter()
        .map(String::from)
        .collect();
    names.sort_by(|a, b| b.len().cmp(&a.len()).then(a.cmp(b)));
    names.dedup();
    let pattern = g["repository"]["builtin"]["match"]
        .as_str()
        .unwrap()
        .to_string();
    let (head, rest) = pattern.split_once("(?:").unwrap();
    let tail = &rest[rest.find(')').unwrap()..];
    let want = format!("{head}(?:{}{tail}", names.join("|"));
    if std::env::var_os("UPDATE_GRAMMAR").is_some() {
        g["repository"]["builtin"]["match"] = Value::String(want);
        let out = serde_json::to_string_pretty(&g).unwrap() + "\n";
        std::fs::write(path, out).unwrap();
        return;
    }
    let listed: Vec<&str> = rest[..rest.find(')').unwrap()].split('|').collect();
    let missing: Vec<&String> = names
        .iter()
        .filter(|n| !listed.contains(&n.as_str()))
        .collect();
    let extra: Vec<&&str> = listed
        .iter()
        .filter(|n| !names.iter().any(|m| m == *n))
        .collect();
    assert!(
        pattern == want,
        "{path}: the builtin pattern lacks {missing:?} and has {extra:?}, or is out of order; \
         rewrite it with UPDATE_GRAMMAR=1 cargo test --test lsp editor_grammar"
    );
    // The file is as the update writes it (so that an update changes only
    // the pattern).
    assert_eq!(text, serde_json::to_string_pretty(&g).unwrap() + "\n");
}

/// A message whose body is not JSON-RPC is answered with JSON-RPC's error
/// (−32700 not JSON, −32600 not a message) and the server goes on: the
/// hover asked after it is answered, and `shutdown` then `exit` end the
/// server with 0.
#[test]
fn a_message_that_is_not_json_is_answered_and_the_server_goes_on() {
    let dir = common::scratch("lsp-not-json");
    let (mut c, _) = Client::start(&dir);
    let body = "hello";
    write!(c.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).unwrap();
    c.send(json!({"id": 41, "params": {}}));
    let answers: Vec<Value> = (0..2).map(|_| c.next("the errors")).collect();
    assert_eq!(answers[0]["error"]["code"], -32700, "{answers:?}");
    assert_eq!(answers[0]["id"], Value::Null);
    assert_eq!(answers[1]["error"]["code"], -32600, "{answers:?}");
    assert_eq!(answers[1]["id"], 41);
    c.open("T_ab = eye(4)\nT_cb = eye(4)\nT_ab * T_cb\n");
    let d = c.diagnostics(1);
    assert!(
        d.iter()
            .any(|d| d["code"] == "frame" && d["range"]["start"]["line"] == 2),
        "{d:?}"
    );
    assert_eq!(c.request("shutdown", Value::Null), Value::Null);
    c.notify("exit", Value::Null);
    assert_eq!(c.exit_code("`exit`"), 0);
}

/// A header that cannot be read leaves no way to find the next message:
/// the connection ends, and the server says why on stderr, the editor's
/// server log, instead of exiting with nothing said.
#[test]
fn a_header_that_cannot_be_read_ends_the_connection_with_a_reason() {
    let dir = common::scratch("lsp-malformed");
    let mut child = common::command(&["lsp"])
        .current_dir(&dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("chasles lsp starts");
    let mut stdin = child.stdin.take().unwrap();
    let frame = |body: &str| format!("Content-Length: {}\r\n\r\n{body}", body.len());
    let init = json!({"jsonrpc": "2.0", "id": 1, "method": "initialize",
        "params": {"processId": null, "rootUri": null, "capabilities": {}}});
    let initialized = json!({"jsonrpc": "2.0", "method": "initialized", "params": {}});
    write!(
        stdin,
        "{}{}Content-Length: five\r\n\r\nhello",
        frame(&init.to_string()),
        frame(&initialized.to_string()),
    )
    .unwrap();
    drop(stdin);
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        assert!(start.elapsed() < WAIT, "chasles lsp did not exit");
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    assert!(!status.success(), "{status:?}");
    assert!(err.contains("chasles lsp: the connection ended"), "{err:?}");
    assert!(err.contains("Content-Length"), "{err:?}");
}
