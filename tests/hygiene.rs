//! Input hygiene and numbers for graders (issue 23, LANGUAGE.md §1):
//! arguments that are not UTF-8 are errors (exit 2, bytes shown escaped),
//! files are read under the same cap as stdin, a byte-order mark is
//! skipped, control characters never reach the terminal raw, a long line
//! is echoed as a window around the caret, and `inv`/`det` are judged by
//! conditioning, not by the size of the determinant.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

struct Out {
    code: Option<i32>,
    stdout: Vec<u8>,
    stderr: Vec<u8>,
}

impl Out {
    fn out(&self) -> String {
        String::from_utf8_lossy(&self.stdout).into_owned()
    }
    fn err(&self) -> String {
        String::from_utf8_lossy(&self.stderr).into_owned()
    }
}

fn chasles<S: AsRef<std::ffi::OsStr>>(args: &[S], stdin: Option<&[u8]>) -> Out {
    let mut child = Command::new(env!("CARGO_BIN_EXE_chasles"))
        .args(args)
        .env("NO_COLOR", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut pipe = child.stdin.take().expect("stdin");
    let input = stdin.map(<[u8]>::to_vec).unwrap_or_default();
    let feeder = std::thread::spawn(move || {
        let _ = pipe.write_all(&input);
    });
    let out = child.wait_with_output().expect("the binary ends");
    let _ = feeder.join();
    Out {
        code: out.status.code(),
        stdout: out.stdout,
        stderr: out.stderr,
    }
}

fn scratch(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("hygiene-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("a temporary folder");
    d
}

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
    let out = chasles(
        &[OsStr::new("run"), OsStr::from_bytes(b"bad\xff.chs")],
        None,
    );
    assert_eq!(out.code, Some(2), "{}", out.err());
    assert!(
        out.err()
            .contains("cannot read 'bad\\xff.chs': no such file"),
        "{}",
        out.err()
    );
    let out = chasles(
        &[OsStr::new("-e"), OsStr::from_bytes(b"x = \"\xff\"")],
        None,
    );
    assert_eq!(out.code, Some(2), "{}", out.err());
    assert!(
        out.err().contains(
            "-e: the statements are not UTF-8 text (invalid byte at offset 5): x = \"\\xff\""
        ),
        "{}",
        out.err()
    );
    // A script whose name is not UTF-8 runs, and its errors name it escaped.
    let dir = scratch("names");
    let name = dir.join(OsStr::from_bytes(b"ok\xff\x1b.chs"));
    std::fs::write(&name, "x = 1\ny = nope\n").unwrap();
    let out = chasles(&[OsStr::new("run"), name.as_os_str()], None);
    assert_eq!(out.code, Some(1));
    assert_eq!(out.out(), "x = 1\n");
    assert!(
        out.err().contains("ok\\xff\\x1b.chs:2:5: name error"),
        "{}",
        out.err()
    );
    assert!(no_raw_controls(&out.stderr), "{}", out.err());
    // Bad values for flags are usage errors, shown without raw controls.
    let out = chasles(&["--frames", "\x07\x1b[2J", "-e", "1"], None);
    assert_eq!(out.code, Some(2));
    assert!(no_raw_controls(&out.stderr), "{:?}", out.err());
    assert!(!out.err().contains("panicked"));
}

#[cfg(unix)]
#[test]
fn files_are_read_under_the_stdin_cap() {
    let start = Instant::now();
    let out = chasles(&["run", "/dev/zero"], None);
    assert_eq!(out.code, Some(2));
    assert!(
        out.err().contains(
            "'/dev/zero' is more than 104857600 bytes; scripts are limited to 104857600 bytes"
        ),
        "{}",
        out.err()
    );
    assert!(start.elapsed().as_secs() < 30, "{:?}", start.elapsed());
}

#[test]
fn a_leading_byte_order_mark_is_skipped() {
    let dir = scratch("bom");
    let f = dir.join("bom.chs");
    std::fs::write(&f, "\u{feff}x = 1\ny = x + 1\n").unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    assert_eq!(out.code, Some(0), "{}", out.err());
    assert_eq!(out.out(), "x = 1\ny = 2\n");
    // An error after a BOM is at the right column.
    std::fs::write(&f, "\u{feff}x = nope\n").unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    assert!(
        out.err().contains("bom.chs:1:5: name error"),
        "{}",
        out.err()
    );
    let out = chasles(&["run", "-"], Some("\u{feff}z = 3\n".as_bytes()));
    assert_eq!(out.out(), "z = 3\n");
    let out = chasles(&["-e", "\u{feff}w = 4"], None);
    assert_eq!(out.out(), "w = 4\n");
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
        (b"q = nope\r\n", "q = nope"),
        (b"\x9b = 1\n", ""),
    ];
    for (src, echoed) in cases {
        let f = dir.join("c.chs");
        std::fs::write(&f, src).unwrap();
        let out = chasles(&["run", f.to_str().unwrap()], None);
        assert!(matches!(out.code, Some(1 | 2)), "{:?}: {}", src, out.err());
        assert!(no_raw_controls(&out.stderr), "{:?}: {:?}", src, out.err());
        assert!(out.err().contains(echoed), "{:?}: {}", src, out.err());
        assert!(!out.err().contains("panicked"));
    }
    // -e as well, and the caret still under what it labels.
    let out = chasles(&["-e", "\x1b[2J + nope"], None);
    let err = out.err();
    assert!(no_raw_controls(&out.stderr), "{err:?}");
    assert!(err.contains("<-e>:1:2: syntax error"), "{err}");
    assert!(err.contains("1 │ \\x1b[2J + nope\n"), "{err}");
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
    assert!(out.stderr.len() < 1_000, "{} bytes", out.stderr.len());
    assert!(out.err().contains("statement too long"), "{}", out.err());
    // An unknown name in the middle of a 300 kB line: the window shows it
    // with the caret under it.
    let line = format!(
        "x = [{}nope{}]\n",
        "1, ".repeat(50_000),
        ", 1".repeat(50_000)
    );
    std::fs::write(&f, &line).unwrap();
    let out = chasles(&["run", f.to_str().unwrap()], None);
    let err = out.err();
    assert_eq!(out.code, Some(1), "{err}");
    assert!(out.stderr.len() < 1_500, "{} bytes", out.stderr.len());
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
    let last = out.out().lines().last().unwrap_or("").to_string();
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
    (rows, out.err())
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
    assert_eq!(out.code, Some(0), "{}", out.err());
    let last = out.out().lines().last().unwrap().to_string();
    let j: serde_json::Value = serde_json::from_str(&last).unwrap();
    assert!(j["value"].as_f64().unwrap() < 1e-12, "{last}");
    // Singular only when it is; a warning when ill-conditioned.
    let out = chasles(&["-e", "inv([1, 2; 2, 4])"], None);
    assert!(
        out.err().contains("the matrix is singular (determinant 0)"),
        "{}",
        out.err()
    );
    let out = chasles(&["-e", "inv([1, 2, 3; 4, 5, 6; 7, 8, 9])"], None);
    assert!(
        out.err().contains("singular to working precision"),
        "{}",
        out.err()
    );
    let out = chasles(&["-e", "inv([1, 1; 1, 1 + 1e-11])"], None);
    assert_eq!(out.code, Some(0));
    assert!(
        out.err().contains("warning: the matrix is ill-conditioned"),
        "{}",
        out.err()
    );
}

#[test]
fn determinants_warn_when_they_underflow() {
    let out = chasles(&["-e", "det(1e-200*eye(3))"], None);
    assert_eq!(out.code, Some(0));
    assert_eq!(out.out(), "0\n");
    assert!(
        out.err()
            .contains("warning: the determinant underflows: it is about 1e-600"),
        "{}",
        out.err()
    );
    let out = chasles(&["-e", "det(1e200*eye(3))"], None);
    assert!(
        out.err().contains("warning: the result is infinite"),
        "{}",
        out.err()
    );
    let out = chasles(&["-e", "det([1, 2; 2, 4])"], None);
    assert_eq!((out.out().as_str(), out.err().as_str()), ("0\n", ""));
}
