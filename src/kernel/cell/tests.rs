//! A notebook session without sockets: bindings across cells, rich
//! outputs, errors with the terminal's diagnostic, commands in a cell,
//! completion, inspection and completeness.

use super::*;

/// Runs a cell, returning its outputs and result.
fn run(nb: &mut Notebook, code: &str) -> (Vec<Output>, Result<(), Failure>) {
    let mut outs = Vec::new();
    let r = nb.execute(code, true, &mut |o| outs.push(o));
    (outs, r)
}

fn data(outs: &[Output]) -> Vec<&Map<String, J>> {
    outs.iter()
        .filter_map(|o| match o {
            Output::Data(d) => Some(d),
            _ => None,
        })
        .collect()
}

#[test]
fn bindings_persist_across_cells_and_errors() {
    let mut nb = Notebook::new();
    let (_, r) = run(
        &mut nb,
        "T_ab = RpToTrans(Rotz(30 deg), (1, 2, 0))\nT_bc = Trans((0, 0, 1))",
    );
    assert!(r.is_ok());
    let (outs, r) = run(&mut nb, "x = 2\nT_ab * inv(T_bc)\ny = 3");
    let f = r.expect_err("a frame error");
    assert_eq!(f.ename, "frame");
    assert!(f.evalue.contains("frames do not cancel"), "{}", f.evalue);
    // The terminal's diagnostic: the cell as the file, the line, carets.
    assert!(f.traceback[0].starts_with("In[2]:2:"), "{:?}", f.traceback);
    assert!(
        f.traceback.iter().any(|l| l.contains('^')),
        "{:?}",
        f.traceback
    );
    assert!(matches!(outs.last(), Some(Output::Error(_))));
    // x bound before the error stays; y after it never ran.
    let (outs, r) = run(&mut nb, "x + 1");
    assert!(r.is_ok());
    assert_eq!(data(&outs)[0]["text/plain"], "3");
    let (_, r) = run(&mut nb, "y");
    assert_eq!(r.expect_err("y is unbound").ename, "name");
    assert_eq!(nb.history.len(), 4);
}

#[test]
fn a_transform_shows_latex_json_and_text() {
    let mut nb = Notebook::new();
    let (outs, _) = run(&mut nb, "T_sb = RpToTrans(Rotz(90 deg), (1, 2, 0))");
    let d = data(&outs)[0];
    let plain = d["text/plain"].as_str().expect("text");
    assert!(plain.starts_with("T_sb = [0, -1, 0, 1"), "{plain}");
    assert!(plain.ends_with(": SE(3) {s}←{b}"), "{plain}");
    let latex = d["text/latex"].as_str().expect("latex");
    assert_eq!(
        latex,
        "$T_{sb} = \\begin{bmatrix} 0 & -1 & 0 & 1 \\\\ 1 & 0 & 0 & 2 \\\\ 0 & 0 & 1 & 0 \\\\ 0 & 0 & 0 & 1 \\end{bmatrix} \\quad \\text{SE(3)}\\ \\{s\\}\\leftarrow \\{b\\}$"
    );
    let j = &d["application/json"];
    assert_eq!(j["type"], "SE3");
    assert_eq!(j["frames"], json!(["s", "b"]));
    // Full precision, as `--json` prints it.
    assert_eq!(j["value"][0][1], json!(-1));
    assert_eq!(j["value"][1][3], json!(2));
}

#[test]
fn the_json_output_carries_the_statements_notes() {
    let mut nb = Notebook::new();
    let (outs, r) = run(&mut nb, "given t : scalar\natan2(sin(t), cos(t))\n1 + 1");
    assert!(r.is_ok());
    let d = data(&outs);
    let j = &d[0]["application/json"];
    assert_eq!(j["value"], "t");
    assert_eq!(
        j["warnings"],
        json!([{"kind": "note", "message": "atan2 of symbolic arguments: the closed form on the branch t in (−π, π]"}])
    );
    // a statement with no note has no key, as in `--json`
    assert_eq!(d[1]["application/json"]["value"], json!(2));
    assert!(d[1]["application/json"].get("warnings").is_none());
}

#[test]
fn a_symbolic_value_shows_a_bmatrix() {
    let mut nb = Notebook::new();
    let (outs, _) = run(&mut nb, "given t : scalar\nRotz(t)");
    let latex = data(&outs)[0]["text/latex"].as_str().expect("latex");
    assert!(latex.starts_with("$\\begin{bmatrix}"), "{latex}");
    assert!(latex.contains("\\cos"), "{latex}");
}

#[test]
fn a_picture_is_inline_svg_and_only_save_writes_a_file() {
    let dir = std::env::temp_dir().join(format!("chasles-nb-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let cwd = std::env::current_dir().expect("cwd");
    // (a `pic.svg` left in the checkout by something else is not this
    // cell's: what it must not do is write one)
    let stamp = || {
        std::fs::metadata(cwd.join("pic.svg"))
            .and_then(|m| m.modified())
            .ok()
    };
    let before = stamp();
    let mut nb = Notebook::new();
    let (outs, r) = run(
        &mut nb,
        "T_sa = RpToTrans(Rotz(1), (1, 0, 0))\npic = draw(T_sa)",
    );
    assert!(r.is_ok(), "{r:?}");
    let svg = data(&outs)[1]["image/svg+xml"].as_str().expect("svg");
    assert!(
        svg.trim_start().starts_with("<svg"),
        "{}",
        &svg[..40.min(svg.len())]
    );
    assert_eq!(stamp(), before, "a printed picture writes no file");
    let file = dir.join("saved.svg");
    let code = format!("save(pic, \"{}\")", file.display());
    let (outs, r) = run(&mut nb, &code);
    assert!(r.is_ok(), "{r:?}");
    assert!(file.is_file(), "save writes");
    assert!(data(&outs)[0].contains_key("image/svg+xml"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn commands_work_in_a_cell() {
    let mut nb = Notebook::new();
    let (outs, _) = run(&mut nb, ":exact\nRotz(30 deg)");
    assert!(
        matches!(&outs[0], Output::Stream { stderr: false, text } if text.contains("exact: on"))
    );
    let plain = data(&outs)[0]["text/plain"].as_str().expect("text");
    assert!(plain.contains("√3/2"), "{plain}");
    let latex = data(&outs)[0]["text/latex"].as_str().expect("latex");
    assert!(latex.contains("\\frac{\\sqrt{3}}{2}"), "{latex}");
    let (outs, _) = run(&mut nb, ":digits 2\n:exact off\npi");
    assert_eq!(data(&outs)[0]["text/plain"], "3.14");
    let (outs, _) = run(&mut nb, "help Rotz");
    assert!(matches!(&outs[0], Output::Stream { text, .. } if text.starts_with("Rotz(")));
}

#[test]
fn a_command_line_after_statements_runs_in_order_with_cell_line_numbers() {
    let mut nb = Notebook::new();
    let (outs, r) = run(&mut nb, "a = 1\n:vars\nb = c");
    let f = r.expect_err("c is unbound");
    assert!(f.traceback[0].starts_with("In[1]:3:"), "{:?}", f.traceback);
    assert!(matches!(&outs[1], Output::Stream { text, .. } if text.contains("a : ")));
}

#[test]
fn completion_inspection_and_completeness() {
    let mut nb = Notebook::new();
    assert!(run(&mut nb, "theta_1 = 1").1.is_ok());
    let (matches, start, end, _) = nb.complete("x = MatrixL", 11);
    assert!(matches.contains(&"MatrixLog3(".to_string()), "{matches:?}");
    assert_eq!((start, end), (4, 11));
    let (matches, ..) = nb.complete("θ = 1\ntheta_", 13);
    assert_eq!(matches, ["theta_1"]);
    let (matches, ..) = nb.complete(":ex", 3);
    assert!(matches.contains(&":exact".to_string()), "{matches:?}");
    let help = nb.inspect("MatrixExp6([S] θ)", 3).expect("help");
    assert!(help.starts_with("MatrixExp6("), "{help}");
    let help = nb
        .inspect("Ad(T_sb) * V_b", 3)
        .expect("help inside the call");
    assert!(help.contains("Adjoint"), "{help}");
    assert!(nb.inspect("zzz", 1).is_none());
    assert!(Notebook::is_complete("T = [1, 0; 0, 1]"));
    assert!(!Notebook::is_complete("T = [1, 0\n0, 1"));
    assert!(!Notebook::is_complete("exp([S] (theta"));
    assert!(Notebook::is_complete(":exact"));
    // A bracket in a command line opens nothing: the cell runs as it is
    // (it was incomplete, the console waiting for a `)` never needed).
    assert!(Notebook::is_complete(":help (\nx = 1"));
    assert!(!Notebook::is_complete(":help (\nx = (1"));
    assert!(!Notebook::is_complete("x = 1\n:exact\ny = [1, 2"));
}

#[test]
fn an_interrupt_stops_a_long_cell_and_keeps_the_session() {
    let mut nb = Notebook::new();
    assert!(run(&mut nb, "x = 5").1.is_ok());
    let stop = nb.interrupter();
    let t = std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_millis(300));
        stop.interrupt();
    });
    let started = std::time::Instant::now();
    let (outs, r) = run(
        &mut nb,
        "y = 1\nlen([det(k*eye(60)) for k in 1:20000])\nz = 2",
    );
    let _ = t.join();
    assert!(started.elapsed().as_secs() < 10, "{:?}", started.elapsed());
    assert_eq!(r.expect_err("interrupted").ename, "interrupted");
    assert!(matches!(outs.last(), Some(Output::Error(_))));
    let (outs, r) = run(&mut nb, "x + y");
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(data(&outs)[0]["text/plain"], "6");
    assert!(run(&mut nb, "z").1.is_err(), "z comes after the interrupt");
    // An interrupt while no cell runs stops nothing.
    nb.interrupter().interrupt();
    assert!(run(&mut nb, "x").1.is_ok());
}
