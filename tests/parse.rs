//! Parser tests: precedence, juxtaposition, statements, spans, mech
//! literals, statement splitting, error messages, nesting limits, and a
//! property test that no input panics the parser.

use chasles::diagnostics::Diagnostic;
use chasles::syntax::ast::{BinOp, CmpOp, Expr, ExprKind, IndexArg, Span, Stmt, StmtKind, UnOp};
use chasles::syntax::{MAX_DEPTH, needs_more_input, parse_program};

/// An expression as an s-expression: `(* 2 pi)`, juxtaposition `(j* 2 pi)`.
fn sexp(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Number(x) if *x == std::f64::consts::PI => "π".into(),
        ExprKind::Number(x) => format!("{x}"),
        ExprKind::Bool(b) => format!("{b}"),
        ExprKind::Var(v) => v.to_string(),
        ExprKind::Unary { op, operand } => {
            let op = match op {
                UnOp::Neg => "neg",
                UnOp::Pos => "pos",
            };
            format!("({op} {})", sexp(operand))
        }
        ExprKind::Binary {
            op,
            lhs,
            rhs,
            implicit,
            ..
        } => {
            let op = match op {
                BinOp::Add => "+",
                BinOp::Sub => "-",
                BinOp::Mul if *implicit => "j*",
                BinOp::Mul => "*",
                BinOp::Div => "/",
                BinOp::Pow => "^",
            };
            format!("({op} {} {})", sexp(lhs), sexp(rhs))
        }
        ExprKind::Degrees(x) => format!("(deg {})", sexp(x)),
        ExprKind::Compare { op, lhs, rhs, .. } => {
            let op = match op {
                CmpOp::Approx => "~=",
                other => other.text(),
            };
            format!("({op} {} {})", sexp(lhs), sexp(rhs))
        }
        ExprKind::Call { func, args } => {
            let args: Vec<String> = args.iter().map(sexp).collect();
            format!("{}({})", func.name, args.join(", "))
        }
        ExprKind::Member { base, member } => format!("(. {} {})", sexp(base), member.name),
        ExprKind::Index { base, args } => {
            let args: Vec<String> = args
                .iter()
                .map(|a| match a {
                    IndexArg::Expr(e) => sexp(e),
                    IndexArg::All(_) => ":".into(),
                })
                .collect();
            format!("(idx {} {})", sexp(base), args.join(" "))
        }
        ExprKind::Paren(items) => {
            let items: Vec<String> = items.iter().map(sexp).collect();
            format!("({})", items.join(", "))
        }
        ExprKind::Brackets(rows) => {
            let rows: Vec<String> = rows
                .iter()
                .map(|r| r.iter().map(sexp).collect::<Vec<_>>().join(", "))
                .collect();
            format!("[{}]", rows.join("; "))
        }
        ExprKind::Mech(m) => format!("{m:?}"),
        ExprKind::Str(t) => format!("{t:?}"),
        ExprKind::Range { start, step, end } => match step {
            Some(h) => format!("(: {} {} {})", sexp(start), sexp(h), sexp(end)),
            None => format!("(: {} {})", sexp(start), sexp(end)),
        },
        ExprKind::Comprehension { body, vars } => {
            let vars: Vec<String> = vars
                .iter()
                .map(|(n, r)| format!("{} in {}", n.name, sexp(r)))
                .collect();
            format!("[{} for {}]", sexp(body), vars.join(", "))
        }
    }
}

fn stmt_sexp(s: &Stmt) -> String {
    match &s.kind {
        StmtKind::Expr(e) => sexp(e),
        StmtKind::Assign { target, value } => format!("{} = {}", target.name, sexp(value)),
        StmtKind::Destructure { targets, value } => {
            let t: Vec<&str> = targets.iter().map(|t| t.name.as_str()).collect();
            format!("({}) = {}", t.join(", "), sexp(value))
        }
        StmtKind::Given { names, ty, times } => {
            let n: Vec<String> = names
                .iter()
                .zip(times)
                .map(|(t, time)| match time {
                    Some(x) => format!("{}({})", t.name, x.name),
                    None => t.name.to_string(),
                })
                .collect();
            format!("given {} : {}", n.join(", "), ty.name)
        }
        StmtKind::FnDef { name, params, body } => {
            let p: Vec<&str> = params.iter().map(|t| t.name.as_str()).collect();
            format!("fn {}({}) = {}", name.name, p.join(", "), sexp(body))
        }
        StmtKind::Derive { target } => format!("derive {}", target.name),
        StmtKind::Assert(e) => format!("assert {}", sexp(e)),
        StmtKind::Explain(e) => format!("explain {}", sexp(e)),
    }
}

/// Parses one statement, panicking with the message on error.
fn one(src: &str) -> Stmt {
    let mut all = parse_program(src);
    assert_eq!(all.len(), 1, "{src:?} should be one statement");
    match all.remove(0) {
        Ok(s) => s,
        Err(e) => panic!(
            "{src:?}: {} at {:?} (help: {:?})",
            e.message, e.span, e.help
        ),
    }
}

#[allow(dead_code)] // helper for the parser tests
fn p(src: &str) -> String {
    stmt_sexp(&one(src))
}

#[allow(dead_code)] // helper for the parser tests
fn expr(src: &str) -> Expr {
    match one(src).kind {
        StmtKind::Expr(e) => e,
        other => panic!("not an expression: {other:?}"),
    }
}

/// Parses one statement that must fail.
#[allow(dead_code)] // helper for the parser tests
fn err(src: &str) -> Diagnostic {
    let mut all = parse_program(src);
    assert_eq!(all.len(), 1, "{src:?} should be one statement");
    match all.remove(0) {
        Ok(s) => panic!("{src:?} parsed as {}", stmt_sexp(&s)),
        Err(e) => e,
    }
}

// ---------------------------------------------------------------------------
// Precedence
// ---------------------------------------------------------------------------

#[test]
fn precedence() {
    let table = [
        ("-2^2", "(neg (^ 2 2))"),
        ("2^3^2", "(^ 2 (^ 3 2))"),
        ("T^-1", "(^ T (neg 1))"),
        ("2^-1", "(^ 2 (neg 1))"),
        ("2^-1 * 3", "(* (^ 2 (neg 1)) 3)"),
        ("1-2-3", "(- (- 1 2) 3)"),
        ("1 - 2 * 3", "(- 1 (* 2 3))"),
        ("8 / 2 / 2", "(/ (/ 8 2) 2)"),
        ("2 pi / 3", "(/ (j* 2 π) 3)"),
        ("[S] theta * 2", "(* (j* [S] theta) 2)"),
        ("a / 2 pi", "(j* (/ a 2) π)"),
        ("-x.T", "(neg (. x T))"),
        ("-x^2", "(neg (^ x 2))"),
        ("+x", "(pos x)"),
        ("--x", "(neg (neg x))"),
        ("2 * -x", "(* 2 (neg x))"),
        ("x[1]^2", "(^ (idx x 1) 2)"),
        ("2 * 30 deg", "(* 2 (deg 30))"),
        ("-30 deg", "(neg (deg 30))"),
        ("T_ab * T_bc * T_cd", "(* (* T_ab T_bc) T_cd)"),
        ("inv(T_ab) * T_ab", "(* inv(T_ab) T_ab)"),
        ("(T_ab * T_bc).T", "(. (* T_ab T_bc) T)"),
        ("Ad(T_ab).T * F_a", "(* (. Ad(T_ab) T) F_a)"),
    ];
    for (src, want) in table {
        assert_eq!(p(src), want, "{src}");
    }
}

// ---------------------------------------------------------------------------
// Juxtaposition
// ---------------------------------------------------------------------------

#[test]
fn juxtaposition_after_numbers_and_brackets() {
    let table = [
        ("2 pi", "(j* 2 π)"),
        ("2pi", "(j* 2 π)"),
        ("2 x", "(j* 2 x)"),
        ("[S] theta", "(j* [S] theta)"),
        ("[w] (pi/2)", "(j* [w] (/ π 2))"),
        ("[S_1] theta_1", "(j* [S_1] theta_1)"),
        ("exp([S] theta)", "exp((j* [S] theta))"),
        ("0.5 [w]", "(j* 0.5 [w])"),
        ("2[w]", "(j* 2 [w])"),
        ("[S] [w]", "(j* [S] [w])"),
        ("(a + b) c", "(j* (+ a b) c)"),
        ("2 pi r^2", "(j* (j* 2 π) (^ r 2))"),
        ("30 deg x", "(j* (deg 30) x)"),
        ("2 sin(x)", "(j* 2 sin(x))"),
    ];
    for (src, want) in table {
        assert_eq!(p(src), want, "{src}");
    }
}

#[test]
fn juxtaposition_after_names_multiplies() {
    // The book writes products side by side everywhere (LANGUAGE.md §4).
    for (src, want) in [
        ("a b", "(j* a b)"),
        ("T_sb T_bc", "(j* T_sb T_bc)"),
        ("x 2", "(j* x 2)"),
        ("f(x) y", "(j* f(x) y)"),
        ("x (1, 2) y", "(j* x(1, 2) y)"),
        ("x[1] y", "(j* (idx x 1) y)"),
        (
            "exp([S_1] t_1) exp([S_2] t_2)",
            "(j* exp((j* [S_1] t_1)) exp((j* [S_2] t_2)))",
        ),
        ("x.T y", "(j* (. x T) y)"),
        ("sin(θ) [w]", "(j* sin(θ) [w])"),
    ] {
        assert_eq!(p(src), want, "{src}");
    }
    // A bracket of numbers after a name, with a space: index or product?
    let e = err("R [1, 2]");
    assert_eq!(e.message, "`R [1, 2]` reads two ways");
    assert_eq!(
        e.help.as_deref(),
        Some("write R[1, 2] to index, or R * [1, 2] to multiply")
    );
    // Three entries cannot be an index: a product.
    assert_eq!(p("R [1, 0, 0]"), "(j* R [1, 0, 0])");
    // Two numbers side by side are neither.
    let e = err("x = 1 0");
    assert_eq!(e.message, "missing operator between `1` and `0`");
    let e = err("[1 0 x]");
    assert_eq!(
        e.message,
        "`1 0` inside brackets is ambiguous (MATLAB reads two entries)"
    );
}

#[test]
fn matlab_sign_in_brackets_is_an_error() {
    // `[1 -2]` is two entries in MATLAB and 1 − 2 here: refused, with the
    // caret on the sign and both fixes.
    for (src, col, what) in [
        ("[1 -x]", 3, "`1 -x`"),
        ("[x -1 -2]", 3, "`x -1`"),
        ("[x -1, 0]", 3, "`x -1`"),
        ("[1, 2; 3 +4, 5]", 9, "`3 +4`"),
        ("[2 pi -1]", 2, "`2 pi`"),
    ] {
        let e = err(src);
        assert_eq!(
            e.message,
            format!("{what} inside brackets is ambiguous (MATLAB reads two entries)"),
            "{src}"
        );
        assert_eq!(e.span.start, col, "{src}");
    }
    assert_eq!(
        err("[1 -x]").help.as_deref(),
        Some("write `1, -x` for two entries or `1 - x` for the difference")
    );
    assert_eq!(
        err("[2 pi]").help.as_deref(),
        Some("write `2, pi` for two entries or `2 * pi` for the product")
    );
    // Plain numbers read as MATLAB prints them.
    assert_eq!(p("[1 -2]"), "[1, (neg 2)]");
    assert_eq!(p("[1 -2 -3]"), "[1, (neg 2), (neg 3)]");
    // Spaced both sides or neither, a comma, or outside a bracket row: fine.
    for (src, want) in [
        ("[1 - 2]", "[(- 1 2)]"),
        ("[1-2]", "[(- 1 2)]"),
        ("[1, -2]", "[1, (neg 2)]"),
        ("[2*(1 -2)]", "[(* 2 (- 1 2))]"),
        ("(1 -2, 3)", "((- 1 2), 3)"),
        ("2 -1", "(- 2 1)"),
    ] {
        assert_eq!(p(src), want, "{src}");
    }
}

#[test]
fn index_needs_no_space() {
    assert_eq!(p("T_sb[1, 2]"), "(idx T_sb 1 2)");
    assert_eq!(p("M[i, :]"), "(idx M i :)");
    assert_eq!(p("M[:, j]"), "(idx M : j)");
    assert_eq!(p("(1, 2, 3)[2]"), "(idx (1, 2, 3) 2)");
    assert_eq!(p("[1, 2][1]"), "(idx [1, 2] 1)");
    assert_eq!(p("f(x)[1]"), "(idx f(x) 1)");
    assert_eq!(p("M[1][2]"), "(idx (idx M 1) 2)");
    assert_eq!(p("x[i + 1]"), "(idx x (+ i 1))");
}

// ---------------------------------------------------------------------------
// Atoms
// ---------------------------------------------------------------------------

#[test]
fn numbers_and_constants() {
    let table = [
        ("2", "2"),
        ("0.866", "0.866"),
        ("1e-3", "0.001"),
        ("2.5E+2", "250"),
        (".5", "0.5"),
        ("pi", "π"),
        ("π", "π"),
        ("true", "true"),
        ("false", "false"),
        ("30 deg", "(deg 30)"),
        ("30°", "(deg 30)"),
        ("30deg", "(deg 30)"),
        ("x deg", "(deg x)"),
        ("Rotz(30 deg)", "Rotz((deg 30))"),
    ];
    for (src, want) in table {
        assert_eq!(p(src), want, "{src}");
    }
}

#[test]
fn names() {
    for name in [
        "T_sb",
        "T_sb'",
        "theta_1",
        "x_max",
        "θ",
        "ω_s",
        "T_{world,cam}",
        "p_{cam}",
        "R_sa'",
        "ans",
    ] {
        assert_eq!(p(name), name);
    }
    // Reserved words are not names.
    for src in ["deg = 1", "pi = 3", "given = 3", "mech = 1"] {
        err(src);
    }
}

#[test]
fn vectors_matrices_and_tuples() {
    let table = [
        ("(1, 2, 3)", "(1, 2, 3)"),
        ("(x)", "x"),
        ("((x))", "x"),
        ("(1, 2, 3,)", "(1, 2, 3)"),
        ("[1, 2, 3]", "[1, 2, 3]"),
        ("[w]", "[w]"),
        ("[]", "[]"),
        ("[1, 0; 0, 1]", "[1, 0; 0, 1]"),
        ("[1, 0;\n 0, 1]", "[1, 0; 0, 1]"),
        ("[1, 0\n 0, 1]", "[1, 0; 0, 1]"),
        ("[\n  1, 0\n  0, 1\n]", "[1, 0; 0, 1]"),
        ("[1, 0;\n\n 0, 1;]", "[1, 0; 0, 1]"),
        ("[1, 2,\n 3, 4,\n]", "[1, 2, 3, 4]"),
        ("[1, 2\n 3, 4,\n]", "[1, 2; 3, 4]"),
        ("[R, p; 0, 0, 0, 1]", "[R, p; 0, 0, 0, 1]"),
        ("[1, 0 # first row\n 0, 1] # done", "[1, 0; 0, 1]"),
        ("(1,\n 2,\n 3)", "(1, 2, 3)"),
        ("f()", "f()"),
        ("f(a, b)", "f(a, b)"),
        ("sin (x)", "sin(x)"),
        ("f(\n  a,\n  b\n)", "f(a, b)"),
    ];
    for (src, want) in table {
        assert_eq!(p(src), want, "{src:?}");
    }
}

// ---------------------------------------------------------------------------
// Statements
// ---------------------------------------------------------------------------

#[test]
fn statement_forms() {
    let table = [
        ("x = 1", "x = 1"),
        ("T_ad = T_ab * T_bd", "T_ad = (* T_ab T_bd)"),
        (
            "T_sb' = exp([S] theta) * T_sb",
            "T_sb' = (* exp((j* [S] theta)) T_sb)",
        ),
        (
            "(w, theta) = axis_ang3(expc)",
            "(w, theta) = axis_ang3(expc)",
        ),
        ("(q, s, h) = screw_params(S)", "(q, s, h) = screw_params(S)"),
        ("given T_ab, T_bc : SE3", "given T_ab, T_bc : SE3"),
        ("given theta : scalar", "given theta : scalar"),
        ("f(x, y) = x^2 + y", "fn f(x, y) = (+ (^ x 2) y)"),
        ("g() = 1", "fn g() = 1"),
        ("derive T_ce", "derive T_ce"),
        (
            "m = mech < links 4; joints 4R; planar >",
            "m = MechSpec { links: Some((4, Span { start: 11, end: 18 })), links_expr: None, joints: [JointGroupSyntax { count: 4, count_expr: None, letters: \"R\", span: Span { start: 27, end: 29 } }], legs: None, legs_expr: None, space: Some((\"planar\", Span { start: 31, end: 37 })), unknown: [] }",
        ),
        ("(1, 2)", "(1, 2)"),
        ("f(1, 2)", "f(1, 2)"),
    ];
    for (src, want) in table {
        assert_eq!(p(src), want, "{src}");
    }
}

#[test]
fn given_declares_functions_of_time() {
    let s = one("given theta(t), L1 : scalar");
    let StmtKind::Given { names, times, .. } = s.kind else {
        panic!("not given")
    };
    assert_eq!(names[0].name, "theta");
    assert_eq!(times[0].as_ref().map(|t| t.name.as_str()), Some("t"));
    assert_eq!(times[0].as_ref().map(|t| t.span), Some(Span::new(12, 13)));
    assert!(times[1].is_none());
}

#[test]
fn statement_idents_have_spans() {
    let s = one("given T_ab, T_bc : SE3");
    let StmtKind::Given { names, ty, times } = s.kind else {
        panic!("not given")
    };
    assert!(times.iter().all(Option::is_none));
    assert_eq!(names[0].span, Span::new(6, 10));
    assert_eq!(names[1].span, Span::new(12, 16));
    assert_eq!(ty.span, Span::new(19, 22));
    let s = one("(w, theta) = axis_ang3(expc)");
    let StmtKind::Destructure { targets, value } = s.kind else {
        panic!("not destructure")
    };
    assert_eq!(targets[1].span, Span::new(4, 9));
    assert_eq!(value.span, Span::new(13, 28));
}

// ---------------------------------------------------------------------------
// Spans
// ---------------------------------------------------------------------------

#[test]
fn spans_are_byte_ranges_into_the_source() {
    let e = expr("T_ab * T_bc");
    assert_eq!(e.span, Span::new(0, 11));
    let ExprKind::Binary {
        lhs,
        rhs,
        op_span,
        implicit,
        ..
    } = &e.kind
    else {
        panic!()
    };
    assert_eq!(
        (lhs.span, rhs.span, *op_span, *implicit),
        (Span::new(0, 4), Span::new(7, 11), Span::new(5, 6), false)
    );

    // Juxtaposition: the operator span is the gap.
    let e = expr("2  pi");
    let ExprKind::Binary {
        op_span, implicit, ..
    } = &e.kind
    else {
        panic!()
    };
    assert_eq!((*op_span, *implicit), (Span::new(1, 3), true));

    // `(x)` spans its parentheses; calls, members and indices their text.
    assert_eq!(expr("(x) ").span, Span::new(0, 3));
    assert_eq!(expr("(a + b) * c").span, Span::new(0, 11));
    assert_eq!(expr("Rotz(30 deg)").span, Span::new(0, 12));
    assert_eq!(expr("T_sb.R").span, Span::new(0, 6));
    assert_eq!(expr("M[1, :]").span, Span::new(0, 7));
    assert_eq!(expr("-x").span, Span::new(0, 2));

    // Unicode: offsets are bytes.
    let s = one("θ = 30°");
    assert_eq!(s.span, Span::new(0, 9));
    let StmtKind::Assign { target, value } = s.kind else {
        panic!()
    };
    assert_eq!(target.span, Span::new(0, 2));
    assert_eq!(value.span, Span::new(5, 9));

    // Later statements are offset into the whole source.
    let all = parse_program("# setup\nx = 1;  y = T_ab * T_bc  # comment\n");
    let spans: Vec<Span> = all.iter().map(|s| s.as_ref().unwrap().span).collect();
    assert_eq!(spans, [Span::new(8, 13), Span::new(16, 31)]);
    let StmtKind::Assign { value, .. } = &all[1].as_ref().unwrap().kind else {
        panic!()
    };
    let ExprKind::Binary { op_span, .. } = &value.kind else {
        panic!()
    };
    assert_eq!(*op_span, Span::new(25, 26));
}

// ---------------------------------------------------------------------------
// Mechanisms
// ---------------------------------------------------------------------------

fn mech(src: &str) -> chasles::syntax::ast::MechSpec {
    match expr(src).kind {
        ExprKind::Mech(m) => *m,
        other => panic!("{src}: not a mech: {other:?}"),
    }
}

fn joints(m: &chasles::syntax::ast::MechSpec) -> Vec<(i64, &str)> {
    m.joints
        .iter()
        .map(|j| (j.count, j.letters.as_str()))
        .collect()
}

#[test]
fn mech_literals() {
    let m = mech("mech < links 4; joints R R R R; planar >");
    assert_eq!(m.links.map(|l| l.0), Some(4));
    assert_eq!(joints(&m), [(1, "R"), (1, "R"), (1, "R"), (1, "R")]);
    assert_eq!(m.space.as_ref().map(|s| s.0.as_str()), Some("planar"));
    assert_eq!(m.links.map(|l| l.1), Some(Span::new(7, 14)));
    assert_eq!(m.joints[0].span, Span::new(23, 24));

    let m = mech("mech < links 8; joints 8R P; planar >");
    assert_eq!(joints(&m), [(8, "R"), (1, "P")]);
    let m = mech("mech < links 7; joints 7R RP; planar >");
    assert_eq!(joints(&m), [(7, "R"), (1, "RP")]);
    let m = mech("mech < links 14; joints 6U 6P 6S; spatial >");
    assert_eq!(m.links.map(|l| l.0), Some(14));
    assert_eq!(joints(&m), [(6, "U"), (6, "P"), (6, "S")]);
    let m = mech("mech < legs 6 UPS; spatial >");
    assert_eq!(
        m.legs.as_ref().map(|l| (l.0, l.1.as_str())),
        Some((6, "UPS"))
    );
    assert!(m.links.is_none() && m.joints.is_empty());
    let m = mech("mech < links 4; joints 4R; spherical >");
    assert_eq!(m.space.as_ref().map(|s| s.0.as_str()), Some("spherical"));

    // Any order, newlines as separators, unknown items kept with spans.
    let m = mech("mech <\n  planar\n  joints 4R   # four revolute\n  links 4\n  wheels 3  \n>");
    assert_eq!(m.links.map(|l| l.0), Some(4));
    assert_eq!(joints(&m), [(4, "R")]);
    assert_eq!(m.unknown.len(), 1);
    assert_eq!(m.unknown[0].0, "wheels 3");
    assert_eq!(m.unknown[0].1, Span::new(58, 66));
    // Letters are kept as written; the validator judges them.
    let m = mech("mech<joints 2X q>");
    assert_eq!(joints(&m), [(2, "X"), (1, "q")]);

    // mech is an expression.
    assert!(p("dof(mech<links 4; joints 4R; planar>)").starts_with("dof(MechSpec"));
    assert!(p("m = mech < links 4; joints 4R; planar >").starts_with("m = MechSpec"));
}

#[test]
fn mech_errors() {
    let e = err("mech < links 4; links 5 >");
    assert_eq!(e.message, "`links` appears twice in this mech");
    assert_eq!(e.span, Span::new(16, 23));
    let e = err("mech < links >");
    assert_eq!(e.message, "expected a whole number, found '>'");
    let e = err("mech < links 4 ; planar x >");
    assert_eq!(e.message, "expected ';' or '>', found 'x'");
}

// ---------------------------------------------------------------------------
// Splitting a program into statements
// ---------------------------------------------------------------------------

#[test]
fn programs_split_into_statements() {
    let src = "# Example 3.18\n\
               T_sb = [1, 0, 0, 1\n\
                       0, 1, 0, 2   # second row\n\
                       0, 0, 1, 0\n\
                       0, 0, 0, 1]\n\
               \n\
               w = (0, 0, 1); theta = 30 deg\n\
               ; ;\n\
               V_s = Ad(T_sb) * V_b   # body to space\n";
    let all: Vec<String> = parse_program(src)
        .iter()
        .map(|r| stmt_sexp(r.as_ref().expect("parses")))
        .collect();
    assert_eq!(
        all,
        [
            "T_sb = [1, 0, 0, 1; 0, 1, 0, 2; 0, 0, 1, 0; 0, 0, 0, 1]",
            "w = (0, 0, 1)",
            "theta = (deg 30)",
            "V_s = (* Ad(T_sb) V_b)",
        ]
    );
    assert!(parse_program("").is_empty());
    assert!(parse_program("  # only a comment\n\n;\n").is_empty());
    // `;` inside a comment does not end anything; CRLF line ends work.
    assert_eq!(parse_program("x = 1 # a; b\r\ny = 2\r\n").len(), 2);
}

#[test]
fn one_bad_statement_does_not_hide_the_others() {
    let all = parse_program("a = 1 +\nb = 2; c = )\nd = f(1\ne = [1, 2\n  3, 4]\nf = 3");
    let ok: Vec<bool> = all.iter().map(Result::is_ok).collect();
    assert_eq!(ok, [false, true, false, false, true, true]);
    assert_eq!(all[2].as_ref().unwrap_err().message, "unmatched ')'");
    assert_eq!(
        all[3].as_ref().unwrap_err().message,
        "unclosed '(' opened here"
    );
}

#[test]
fn needs_more_input_while_open() {
    for src in [
        "[1, 2",
        "[1, 2\n 3, 4",
        "f(",
        "x = (1,\n",
        "m = mech <",
        "m = mech < links 4;",
        "T_{world,",
    ] {
        assert!(needs_more_input(src), "{src:?}");
    }
    for src in [
        "",
        "x = 1",
        "[1, 2]",
        ")",
        "x)",
        "[1)",
        "# [",
        "x = 1 # (",
        "a < b",
        "]\n[",
        "[1, 2]\n",
    ] {
        assert!(!needs_more_input(src), "{src:?}");
    }
}

// ---------------------------------------------------------------------------
// Error messages
// ---------------------------------------------------------------------------

#[test]
fn friendly_errors() {
    // (source, message, span text, help)
    let table: &[(&str, &str, &str, Option<&str>)] = &[
        (
            "T_sb [1,2]",
            "`T_sb [1,2]` reads two ways",
            "[1,2]",
            Some("write T_sb[1,2] to index, or T_sb * [1,2] to multiply"),
        ),
        (
            "2 ** 3",
            "`**` is not an operator",
            "**",
            Some("use ^ for powers: x^2"),
        ),
        (
            "x = ",
            "expected an expression, found end of input",
            "=",
            None,
        ),
        ("(1 + )", "expected an expression, found ')'", ")", None),
        ("f(1, 2]", "mismatched ']'", "]", None),
        ("x = 1)", "unmatched ')'", ")", None),
        (
            "M = [1, 2",
            "unclosed '[' opened here",
            "[",
            Some("close it with ']'"),
        ),
        (
            "given T_ab SE3",
            "expected '(', ',', ':' or end of input, found 'S'",
            "S",
            Some(
                "the type follows a colon: given T_ab, T_bc : SE3 (scalars need none: given α, β)",
            ),
        ),
        ("x.", "expected a name, found end of input", ".", None),
        (
            "x, y",
            "expected an operator, '=' or end of input, found ','",
            ",",
            Some("to write a vector, put it in parentheses or brackets: (1, 2, 3)"),
        ),
        (
            "1 = x",
            "expected an operator or end of input, found '='",
            "=",
            Some("only a name, a tuple of names `(a, b)` or a function `f(x)` can be assigned to"),
        ),
        (
            "x @ y",
            "expected an operator, '=' or end of input, found '@'",
            "@",
            None,
        ),
        (
            "[1, +\n 2]",
            "expected an expression, found end of line",
            "\n",
            None,
        ),
        (
            "M[1; 2]",
            "an index takes one or two subscripts separated by `,`",
            "[1; 2]",
            Some("write M[i], M[i, j], M[i, :] or M[:, j]"),
        ),
        (
            "θ = 1 +",
            "expected an expression, found end of input",
            "+",
            None,
        ),
    ];
    for &(src, message, at, help) in table {
        let e = err(src);
        assert_eq!(e.message, message, "{src:?}");
        assert_eq!(&src[e.span.start..e.span.end], at, "{src:?}");
        assert_eq!(e.help.as_deref(), help, "{src:?}");
        assert_eq!(e.kind, chasles::diagnostics::ErrorKind::Syntax);
    }
    // The mismatched closer also points at its opener.
    let e = err("f(1, 2]");
    assert_eq!(e.labels[0].span, Span::new(1, 2));
}

/// A debugging aid: `CHASLES_SRC='a b' cargo test --test parse debug_print
/// -- --nocapture` prints how each statement parses. Does nothing otherwise.
#[test]
fn debug_print() {
    if let Ok(src) = std::env::var("CHASLES_SRC") {
        for r in parse_program(&src) {
            match r {
                Ok(s) => println!("OK {}   {:?}", stmt_sexp(&s), s.span),
                Err(e) => println!(
                    "ERR {:?} {:?} | {} | help {:?} | {:?}",
                    e.span,
                    src.get(e.span.start..e.span.end),
                    e.message,
                    e.help,
                    e.labels
                ),
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Nesting limits: errors, never a stack overflow (run on a 2 MB stack).
// ---------------------------------------------------------------------------

/// Runs `f` on a thread with the default test stack size (2 MB).
fn small_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(2 * 1024 * 1024)
        .spawn(f)
        .expect("spawn")
        .join()
        .expect("no panic or overflow");
}

fn too_deep(src: String) -> Diagnostic {
    let mut all = parse_program(&src);
    assert_eq!(all.len(), 1);
    let e = all.remove(0).expect_err("should be too deep");
    assert_eq!(
        e.message,
        format!("expression nested too deeply (limit {MAX_DEPTH})")
    );
    e
}

#[test]
fn deep_parens_and_brackets_are_errors() {
    small_stack(|| {
        let n = 10_000;
        let e = too_deep(format!("{}1{}", "(".repeat(n), ")".repeat(n)));
        assert_eq!(e.span, Span::new(MAX_DEPTH, MAX_DEPTH + 1));
        too_deep(format!("{}1{}", "[".repeat(n), "]".repeat(n)));
        too_deep(format!("x = {}1{}", "f(".repeat(n), ")".repeat(n)));
        // Unclosed as well as closed.
        too_deep("(".repeat(n));
        assert!(!needs_more_input(&"(".repeat(n)));
    });
}

#[test]
fn long_operator_chains_are_errors() {
    small_stack(|| {
        let sum = vec!["1"; 100_000].join("+");
        let e = too_deep(sum);
        // The `+` that makes the tree one level too deep.
        assert_eq!(e.span, Span::new(2 * MAX_DEPTH - 1, 2 * MAX_DEPTH));
        too_deep(vec!["2"; 10_000].join("^"));
        too_deep(format!("{}x", "-".repeat(100_000)));
        too_deep(format!("{}x", "- ".repeat(10_000)));
        too_deep(format!("2^{}", "-2^".repeat(10_000) + "2"));
        too_deep(format!("x{}", "[1]".repeat(10_000)));
        too_deep(format!("x{}", ".T".repeat(10_000)));
        too_deep(vec!["2"; 10_000].join(" * "));
        too_deep(format!("2{}", " (2)".repeat(10_000)));
    });
}

#[test]
fn nesting_up_to_the_limit_parses() {
    small_stack(|| {
        let n = MAX_DEPTH;
        one(&format!("{}1{}", "(".repeat(n), ")".repeat(n)));
        one(&format!("{}1{}", "f(".repeat(n - 1), ")".repeat(n - 1)));
        one(&format!("{}1{}", "[".repeat(n - 1), "]".repeat(n - 1)));
        one(&vec!["1"; n].join("+"));
        one(&vec!["2"; n].join("^"));
        one(&format!("{}x", "-".repeat(n - 1)));
        // Brackets and operator chains together, up to the limit.
        let levels = MAX_DEPTH / 5;
        let chain = format!("{}x{}", "2^2^2^2^(".repeat(levels), ")".repeat(levels));
        one(&chain);
        too_deep(format!(
            "{}x{}",
            "2^2^2^2^2^(".repeat(levels),
            ")".repeat(levels)
        ));
        // A deep mix: every level of brackets holding an operator.
        let mut s = String::from("x");
        for _ in 0..(n / 2 - 1) {
            s = format!("-({s})");
        }
        one(&s);
    });
}

// ---------------------------------------------------------------------------
// No input panics the parser
// ---------------------------------------------------------------------------

mod never_panics {
    use super::*;
    use proptest::prelude::*;

    const TOKENS: &[&str] = &[
        "(", ")", "[", "]", ",", ";", "+", "-", "*", "/", "^", ".", "'", "deg", "°", "pi", "1",
        "2.5", "T_ab", "x", "=", "given", ":", "mech", "<", ">", "R", "P", "#", "\n", " ", "{",
        "}", "_{", "links", "joints", "4R", "planar", "derive", ".5", "1e", "θ", "f(", "**",
        // The book's notation.
        "ᵀ", "^T", "^{", "sin ", "cos", "0.", "1.e", "[[", "I", "T_01", "T_123", "e^", "−", "²",
    ];

    fn program() -> impl Strategy<Value = String> {
        prop::collection::vec((prop::sample::select(TOKENS), prop::bool::ANY), 0..48).prop_map(
            |parts| {
                parts
                    .into_iter()
                    .map(|(t, space)| {
                        if space {
                            format!("{t} ")
                        } else {
                            t.to_string()
                        }
                    })
                    .collect()
            },
        )
    }

    fn check(src: &str) {
        let _ = needs_more_input(src);
        for r in parse_program(src) {
            let span = match &r {
                Ok(s) => s.span,
                Err(e) => e.span,
            };
            assert!(
                span.start <= span.end && span.end <= src.len(),
                "{src:?}: {span:?}"
            );
            assert!(src.is_char_boundary(span.start) && src.is_char_boundary(span.end));
            if let Err(e) = r {
                assert!(!e.message.is_empty());
                assert!(!e.message.contains("internal"), "{src:?}: {}", e.message);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 1500, ..ProptestConfig::default() })]

        #[test]
        fn random_token_strings(src in program()) {
            check(&src);
        }

        #[test]
        fn random_text(src in "\\PC{0,40}") {
            check(&src);
        }
    }
}

/// Comparisons are the loosest operators and chain to the left; `assert`
/// takes one expression (LANGUAGE.md §3).
#[test]
fn comparisons_and_assert() {
    assert_eq!(
        stmt_sexp(&one("a + 1 == b * 2 ~= c")),
        "(~= (== (+ a 1) (* b 2)) c)"
    );
    assert_eq!(stmt_sexp(&one("x = a ≈ b")), "x = (~= a b)");
    assert_eq!(stmt_sexp(&one("assert T ≈ I")), "assert (~= T I)");
    assert_eq!(stmt_sexp(&one("assert(a == b)")), "assert (== a b)");
    // `assert` is not reserved: it can still be a name.
    assert_eq!(stmt_sexp(&one("assert = 3")), "assert = 3");
}

/// `explain EXPR` takes one expression (LANGUAGE.md §14); like `assert`,
/// the word is not reserved.
#[test]
fn explain_statement() {
    assert_eq!(stmt_sexp(&one("explain log(R)")), "explain log(R)");
    assert_eq!(
        stmt_sexp(&one("explain T_ad T_db")),
        "explain (j* T_ad T_db)"
    );
    assert_eq!(stmt_sexp(&one("explain = 3")), "explain = 3");
    assert_eq!(stmt_sexp(&one("explained = 3")), "explained = 3");
}

/// Issue 22: the forms a student types in the second hour, as trees.
#[test]
fn second_hour_forms() {
    // `^T` always transposes, also before a parenthesis (3.64).
    assert_eq!(p("-R^T (p)"), "(neg (j* (. R T) p))");
    assert_eq!(p("R^T(p)"), "(j* (. R T) p)");
    assert_eq!(p("R^T (a, b)"), "(j* (. R T) (a, b))");
    // A value before a parenthesis is left to the evaluator as a call.
    assert_eq!(p("n (n - 1)/2"), "(/ n((- n 1)) 2)");
    // `given α, β`: scalars.
    assert_eq!(p("given α, β"), "given α, β : scalar");
    // `√`: sqrt of the atom after it.
    assert_eq!(p("√2"), "sqrt(2)");
    assert_eq!(p("1/√2"), "(/ 1 sqrt(2))");
    assert_eq!(p("√3/2"), "(/ sqrt(3) 2)");
    assert_eq!(p("3√2/4"), "(/ (j* 3 sqrt(2)) 4)");
    assert_eq!(p("√(x + 1)"), "sqrt((+ x 1))");
    // `·` dot and `×` cross, at the precedence of `*`.
    assert_eq!(p("ŵ·v1"), "dot(ŵ, v1)");
    assert_eq!(p("-s × q + h s"), "(+ cross((neg s), q) (j* h s))");
    // Orders, loosest of all.
    assert_eq!(p("a + 1 < b"), "(< (+ a 1) b)");
    assert_eq!(p("a <= b"), "(<= a b)");
    assert_eq!(p("a ≥ b"), "(>= a b)");
    assert_eq!(p("assert x > 0"), "assert (> x 0)");
    // Python's nested comprehension is the grid.
    assert_eq!(
        p("[f(a, b) for a in r for b in r]"),
        "[f(a, b) for a in r, b in r]"
    );
    // Ranges and `end` index.
    assert_eq!(p("T[1:3, 4]"), "(idx T (: 1 3) 4)");
    assert_eq!(p("v[end]"), "(idx v end)");
}

#[test]
fn mech_counts_and_contacts() {
    let m = mech("mech < links N; joints 7RP, 6 sliding, (k) R; planar >");
    assert!(m.links_expr.is_some());
    assert_eq!(joints(&m), [(7, "RP"), (6, "sliding"), (0, "R")]);
    assert!(m.joints[2].count_expr.is_some());
    let m = mech("mech < legs n UPS; spatial >");
    assert_eq!(m.legs.as_ref().map(|l| l.1.as_str()), Some("UPS"));
    assert!(m.legs_expr.is_some());
    let m = mech("mech < links 2 * n + 1; joints R R; planar >");
    assert!(m.links_expr.is_some());
    // Juxtaposition multiplies in counts as elsewhere (§4), before `+`:
    // `links 2 n + 1` as the README writes it, `n (n - 1)`, `2n`.
    let links = |src: &str| sexp(mech(src).links_expr.as_ref().expect("an expression"));
    assert_eq!(links("mech < links 2 n + 1; planar >"), "(+ (j* 2 n) 1)");
    assert_eq!(links("mech < links 2n+1; planar >"), "(+ (j* 2 n) 1)");
    assert_eq!(
        links("mech < links n (n - 1) + 1 >"),
        "(+ (j* n (- n 1)) 1)"
    );
    assert_eq!(links("mech < links 1 + 2 * n m >"), "(+ 1 (j* (* 2 n) m))");
    // In `legs` the last word is the chain, never a factor.
    let m = mech("mech < legs 2 n UPS; spatial >");
    assert_eq!(m.legs.as_ref().map(|l| l.1.as_str()), Some("UPS"));
    assert_eq!(
        sexp(m.legs_expr.as_ref().expect("an expression")),
        "(j* 2 n)"
    );
    let m = mech("mech < legs n UPS; spatial >");
    assert_eq!(m.legs.as_ref().map(|l| l.1.as_str()), Some("UPS"));
    assert_eq!(sexp(m.legs_expr.as_ref().expect("an expression")), "n");
    // Two numbers side by side are no product.
    let e = err("mech < links 2 3; planar >");
    assert_eq!(e.message, "expected an operator or ';', found '3'");
    // Whole numbers stay numbers.
    let m = mech("mech < links 4; joints R, R, R, R; planar >");
    assert_eq!(m.links.map(|l| l.0), Some(4));
    assert!(m.links_expr.is_none());
    assert_eq!(joints(&m).len(), 4);
}

/// The book's subscripts and superscripts copied as typeset (θ₁, S₂, 2²)
/// are errors whose help spells the name or power chasles reads: the
/// error named the character and nothing more.
#[test]
fn typeset_subscripts_and_superscripts_get_the_spelling() {
    let help = |src: &str| err(src).help.clone().unwrap_or_default();
    let h = help("θ₁ = 30°");
    assert!(h.contains("θ1") && h.contains("θ_1"), "{h}");
    let h = help("S₁₂ = (0, 0, 1, 0, 0, 0)");
    assert!(h.contains("S12") && h.contains("S_12"), "{h}");
    let h = help("x = 2²");
    assert!(h.contains("2^2"), "{h}");
}

/// A no-break space (copied from a PDF of the book) or a zero-width one is
/// named in the syntax error, with its code point and a help: the error
/// said "found ' '", a character that prints as the space it is not.
#[test]
fn invisible_spaces_are_named() {
    for (src, what) in [
        ("x = 1\u{a0}+ 2", "found a no-break space (U+00A0)"),
        ("x = 1 \u{200b}", "found a zero-width space (U+200B)"),
        ("\u{a0}x = 1", "found a no-break space (U+00A0)"),
        ("y = Rotz(\u{2009}1)", "found a typographic space (U+2009)"),
    ] {
        let e = err(src);
        assert!(e.message.ends_with(what), "{src:?}: {}", e.message);
        let help = e.help.clone().unwrap_or_default();
        assert!(
            help.contains("looks like a space but is not one")
                && help.contains("write a plain space"),
            "{src:?}: {help}"
        );
    }
}
