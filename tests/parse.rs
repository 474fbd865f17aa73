//! Parser tests: precedence, juxtaposition, statements, spans, mech
//! literals, statement splitting, error messages, nesting limits, and a
//! property test that no input panics the parser.

use chasles::diagnostics::Diagnostic;
use chasles::syntax::ast::{BinOp, Expr, ExprKind, IndexArg, Span, Stmt, StmtKind, UnOp};
use chasles::syntax::{MAX_DEPTH, needs_more_input, parse_program};

/// An expression as an s-expression: `(* 2 pi)`, juxtaposition `(j* 2 pi)`.
fn sexp(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Number(x) if *x == std::f64::consts::PI => "π".into(),
        ExprKind::Number(x) => format!("{x}"),
        ExprKind::Bool(b) => format!("{b}"),
        ExprKind::Var(v) => v.clone(),
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
        StmtKind::Given { names, ty } => {
            let n: Vec<&str> = names.iter().map(|t| t.name.as_str()).collect();
            format!("given {} : {}", n.join(", "), ty.name)
        }
        StmtKind::FnDef { name, params, body } => {
            let p: Vec<&str> = params.iter().map(|t| t.name.as_str()).collect();
            format!("fn {}({}) = {}", name.name, p.join(", "), sexp(body))
        }
        StmtKind::Derive { target } => format!("derive {}", target.name),
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
        // A deep mix: every level of brackets holding an operator.
        let mut s = String::from("x");
        for _ in 0..(n / 2 - 1) {
            s = format!("-({s})");
        }
        one(&s);
    });
}
