//! Input hygiene and numbers for graders (issue 23, LANGUAGE.md §1):
//! arguments that are not UTF-8 are errors (exit 2, bytes shown escaped),
//! files are read under the same cap as stdin, a byte-order mark is
//! skipped, control characters never reach the terminal raw, a long line
//! is echoed as a window around the caret, and `inv`/`det` are judged by
//! conditioning, not by the size of the determinant.

use std::time::Instant;

mod common;
use common::{LIMIT, chasles, run_with, scratch};

/// No byte of `bytes` is a control character other than newline.
fn no_raw_controls(bytes: &[u8]) -> bool {
    bytes
        .iter()
        .all(|&b| b == b'\n' || !(b < 0x20 || b == 0x7f))
}

#[cfg(unix)]
#[test]
fn arguments_that_are_not_utf8_are_errors_not_panics() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let out = run_with(
        &[OsStr::new("run"), OsStr::from_bytes(b"bad\xff.chs")],
        None,
        LIMIT,
    );
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(
        out.stderr
            .contains("cannot read 'bad\\xff.chs': no such file"),
        "{}",
        out.stderr
    );
    let out = run_with(
        &[OsStr::new("-e"), OsStr::from_bytes(b"x = \"\xff\"")],
        None,
        LIMIT,
    );
    assert_eq!(out.code, Some(2), "{}", out.stderr);
    assert!(
        out.stderr.contains(
            "-e: the statements are not UTF-8 text (invalid byte at offset 5): x = \"\\xff\""
        ),
        "{}",
        out.stderr
    );
    // A script whose name is not UTF-8 runs, and its errors name it escaped.
    let dir = scratch("names");
    let name = dir.join(OsStr::from_bytes(b"ok\xff\x1b.chs"));
    std::fs::write(&name, "x = 1\ny = nope\n").unwrap();
    let out = run_with(&[OsStr::new("run"), name.as_os_str()], None, LIMIT);
    assert_eq!(out.code, Some(1));
    assert_eq!(out.stdout, "x = 1\n");
    assert!(
        out.stderr.contains("ok\\xff\\x1b.chs:2:5: name error"),
        "{}",
        out.stderr
    );
    assert!(no_raw_controls(&out.stderr_bytes), "{}", out.stderr);
    // Bad values for flags are usage errors, shown without raw controls.
    let out = chasles(&["--frames", "\x07\x1b[2J", "-e", "1"], None);
    assert_eq!(out.code, Some(2));
    assert!(no_raw_controls(&out.stderr_bytes), "{:?}", out.stderr);
    assert!(!out.stderr.contains("panicked"));
}

#[cfg(unix)]
#[test]
fn files_are_read_under_the_stdin_cap() {
    let start = Instant::now();
    let out = chasles(&["run", "/dev/zero"], None);
    assert_eq!(out.code, Some(2));
    assert!(
        out.stderr.contains(
            "'/dev/zero' is more than 104857600 bytes; scripts are limited to 104857600 bytes"
        ),
        "{}",
        out.stderr
    );
    assert!(start.elapsed().as_secs() < 30, "{:?}", start.elapsed());
}

#[test]
fn a_leading_byte_order_mark_is_skipped() {
    let dir = scratch("bom");
    let f = dir.join("bom.chs");
    std::fs::write(&f, "\u{feff}x = 1\ny = x + 1\n").unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, "x = 1\ny = 2\n");
    // An error after a BOM is at the right column.
    std::fs::write(&f, "\u{feff}x = nope\n").unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    assert!(
        out.stderr.contains("bom.chs:1:5: name error"),
        "{}",
        out.stderr
    );
    let out = chasles(&["run", "-"], Some("\u{feff}z = 3\n".as_bytes()));
    assert_eq!(out.stdout, "z = 3\n");
    let out = chasles(&["-e", "\u{feff}w = 4"], None);
    assert_eq!(out.stdout, "w = 4\n");
}

#[test]
fn control_characters_are_shown_escaped() {
    let dir = scratch("controls");
    let cases: &[(&[u8], &str)] = &[
        (b"a\0b = 1\n", "a\\0b = 1"),
        (
            b"y = \"\x1b[2J\x1b]0;pwned\x07\" + 1\n",
            "\\x1b[2J\\x1b]0;pwned\\x07",
        ),
        (b"z = 1 \x1b[31m+ 2\n", "z = 1 \\x1b[31m+ 2"),
        // (the \r of a CRLF ending is the line break, not echoed as `\r`)
        (b"q = nope\r\n", "1 │ q = nope\n"),
        (b"q = 1\r\nq + nope\r\n", "2 │ q + nope\n"),
        (b"\x9b = 1\n", ""),
    ];
    for (src, echoed) in cases {
        let f = dir.join("c.chs");
        std::fs::write(&f, src).unwrap();
        let out = chasles(&["run", f.to_str().unwrap()], None);
        assert!(matches!(out.code, Some(1 | 2)), "{:?}: {}", src, out.stderr);
        assert!(
            no_raw_controls(&out.stderr_bytes),
            "{:?}: {:?}",
            src,
            out.stderr
        );
        assert!(out.stderr.contains(echoed), "{:?}: {}", src, out.stderr);
        assert!(!out.stderr.contains("panicked"));
    }
    // -e as well, and the caret still under what it labels.
    let out = chasles(&["-e", "\x1b[2J + nope"], None);
    let err = out.stderr.clone();
    assert!(no_raw_controls(&out.stderr_bytes), "{err:?}");
    assert!(err.contains("<-e>:1:2: syntax error"), "{err}");
    assert!(err.contains("1 │ \\x1b[2J + nope\n"), "{err}");
    // --json says what the text header says: the message escaped, not a
    // raw NUL or ESC (they were "found '\u0000'" and "(\"\u001b[2J\")").
    let out = chasles(&["--json"], Some(b"x = 1\0\n".as_slice()));
    assert!(
        out.stdout
            .contains(r#""message":"expected an operator or end of input, found '\\0'""#),
        "{}",
        out.stdout
    );
    let out = chasles(&["--json", "-e", "y = \"\x1b[2J\" + 1"], None);
    assert!(out.stdout.contains(r#"(\"\\x1b[2J\")"#), "{}", out.stdout);
    assert!(!out.stdout.contains("\\u001b"), "{}", out.stdout);
}

#[test]
fn a_long_line_is_echoed_as_a_window_around_the_caret() {
    let dir = scratch("long");
    let f = dir.join("long.chs");
    // 10 MB on one line: refused as too long, echoed in a few hundred bytes.
    let line = format!("x = {}1\n", "1 + ".repeat(2_500_000));
    std::fs::write(&f, &line).unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    assert_eq!(out.code, Some(1));
    assert!(
        out.stderr_bytes.len() < 1_000,
        "{} bytes",
        out.stderr_bytes.len()
    );
    assert!(out.stderr.contains("statement too long"), "{}", out.stderr);
    // An unknown name in the middle of a 300 kB line: the window shows it
    // with the caret under it.
    let line = format!(
        "x = [{}nope{}]\n",
        "1, ".repeat(50_000),
        ", 1".repeat(50_000)
    );
    std::fs::write(&f, &line).unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    let err = out.stderr.clone();
    assert_eq!(out.code, Some(1), "{err}");
    assert!(
        out.stderr_bytes.len() < 1_500,
        "{} bytes",
        out.stderr_bytes.len()
    );
    assert!(
        err.contains("long.chs:1:150006: name error: unknown name 'nope'"),
        "{err}"
    );
    assert!(err.contains("┌─ "), "{err}");
    assert!(err.contains(":1:150006\n"), "{err}");
    let lines: Vec<&str> = err.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.contains("nope, 1"))
        .expect("echoed");
    // Columns in characters: the window starts with '…'.
    let caret = lines[at + 1]
        .chars()
        .position(|c| c == '^')
        .expect("a caret");
    let under: String = lines[at].chars().skip(caret).take(4).collect();
    assert_eq!(under, "nope", "{err}");
}

/// The JSON value of `src`'s last statement as a matrix.
fn matrix(src: &str) -> (Vec<Vec<f64>>, String) {
    let out = chasles(&["--json", "-e", src], None);
    let last = out.stdout.lines().last().unwrap_or("").to_string();
    let j: serde_json::Value =
        serde_json::from_str(&last).unwrap_or_else(|e| panic!("{src}: {e}: {last}"));
    let rows = j["value"]
        .as_array()
        .unwrap_or_else(|| panic!("{src}: {last}"))
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        })
        .collect();
    (rows, out.stderr)
}

#[test]
fn inverses_of_scaled_matrices_are_accurate() {
    let cases: &[(&str, f64, [[f64; 2]; 2])] = &[
        ("inv(1e200*eye(2))", 1e-200, [[1.0, 0.0], [0.0, 1.0]]),
        ("inv(1e-200*eye(2))", 1e200, [[1.0, 0.0], [0.0, 1.0]]),
        (
            "inv([2, 1; 1, 1]*1e-170)",
            1e170,
            [[1.0, -1.0], [-1.0, 2.0]],
        ),
        (
            "inv([1e-160, 0; 0, 1e-160])",
            1e160,
            [[1.0, 0.0], [0.0, 1.0]],
        ),
    ];
    for (src, scale, want) in cases {
        let (m, err) = matrix(src);
        assert!(err.is_empty(), "{src}: {err}");
        for i in 0..2 {
            for j in 0..2 {
                let w = want[i][j] * scale;
                let rel = (m[i][j] - w).abs() / scale;
                assert!(rel < 1e-12, "{src}[{i}][{j}] = {} want {w}", m[i][j]);
            }
        }
    }
    // 36·I₂₀₀: every diagonal entry 1/36, nothing else.
    let out = chasles(
        &[
            "--json",
            "-e",
            "X = inv(36*eye(200))\nnorm(X*36 - eye(200))",
        ],
        None,
    );
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    let last = out.stdout.lines().last().unwrap().to_string();
    let j: serde_json::Value = serde_json::from_str(&last).unwrap();
    assert!(j["value"].as_f64().unwrap() < 1e-12, "{last}");
    // Singular only when it is; a warning when ill-conditioned.
    let out = chasles(&["-e", "inv([1, 2; 2, 4])"], None);
    assert!(
        out.stderr
            .contains("the matrix is singular (determinant 0)"),
        "{}",
        out.stderr
    );
    let out = chasles(&["-e", "inv([1, 2, 3; 4, 5, 6; 7, 8, 9])"], None);
    assert!(
        out.stderr.contains("singular to working precision"),
        "{}",
        out.stderr
    );
    let out = chasles(&["-e", "inv([1, 1; 1, 1 + 1e-11])"], None);
    assert_eq!(out.code, Some(0));
    assert!(
        out.stderr
            .contains("warning: the matrix is ill-conditioned"),
        "{}",
        out.stderr
    );
}

#[test]
fn determinants_warn_when_they_underflow() {
    let out = chasles(&["-e", "det(1e-200*eye(3))"], None);
    assert_eq!(out.code, Some(0));
    assert_eq!(out.stdout, "0\n");
    assert!(
        out.stderr
            .contains("warning: the determinant underflows: it is about 1e-600"),
        "{}",
        out.stderr
    );
    let out = chasles(&["-e", "det(1e200*eye(3))"], None);
    assert!(
        out.stderr.contains("warning: the result is infinite"),
        "{}",
        out.stderr
    );
    let out = chasles(&["-e", "det([1, 2; 2, 4])"], None);
    assert_eq!((out.stdout.as_str(), out.stderr.as_str()), ("0\n", ""));
}
