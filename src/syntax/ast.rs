//! The abstract syntax tree of a chasles program.
//!
//! Every node carries a [`Span`] (byte offsets into the source), so every
//! later stage — the frame checker, the evaluator, the diagnostics — can point
//! at the text the user typed. The tree is deliberately small: the book's
//! notation (juxtaposition, `[w]`, `30 deg`) is resolved by the parser into
//! ordinary products, brackets and calls.

pub use super::name::Name;
pub use crate::span::Span;

/// A name as written, e.g. `T_sb`, `theta_1`, `T_{world,cam}`, `ω_s`.
/// Frame subscripts are read from the text by [`super::ident::name_frames`].
#[derive(Debug, Clone, PartialEq)]
pub struct Ident {
    /// The name, interned, with its subscripts as typed.
    pub name: Name,
    /// Where the name is written in the source.
    pub span: Span,
}

/// One statement of a script or one REPL entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Stmt {
    /// What the statement does: evaluate, bind, declare, define, assert….
    pub kind: StmtKind,
    /// The whole statement, without its terminator.
    pub span: Span,
    /// Ended by `;` (LANGUAGE.md §3): evaluated and bound, but its value
    /// is not printed, as in MATLAB and Julia. Errors, warnings and notes
    /// still print.
    pub silent: bool,
}

/// The forms a statement takes (LANGUAGE.md §3).
#[derive(Debug, Clone, PartialEq)]
pub enum StmtKind {
    /// `expr` — evaluate and print.
    Expr(Expr),
    /// `name = expr` — bind; the name's frame subscript is checked against
    /// the value's frames.
    Assign {
        /// The name bound, e.g. `T_sb`.
        target: Ident,
        /// The right-hand side.
        value: Expr,
    },
    /// `(w, theta) = axis_ang3(expc)` — destructure a tuple of any arity.
    Destructure {
        /// The names on the left, one per element of the tuple, in order.
        targets: Vec<Ident>,
        /// The right-hand side, which must give a tuple of as many elements.
        value: Expr,
    },
    /// `given T_ab, T_bc : SE3` — symbols with a type and frames, no numbers.
    /// `ty` is the type name as written (`scalar vec3 vec6 SO3 SE3 SO2 SE2
    /// so3 se3 twist screw wrench`); the checker validates it.
    /// `times[i]` is the time variable of a function of time,
    /// `given theta(t) : scalar` (§7).
    Given {
        /// The symbols declared, e.g. `T_ab`, `T_bc`.
        names: Vec<Ident>,
        /// The type name after `:`, as written.
        ty: Ident,
        /// One per name: `Some(t)` for `theta(t)`, `None` for a constant.
        times: Vec<Option<Ident>>,
    },
    /// `f(x, y) = expr` — a user function. The parameters are a boxed
    /// slice (two words, not a vector's three) so that a statement fits in
    /// 128 bytes and moves without a call to `memcpy`.
    FnDef {
        /// The function's name, `f`.
        name: Ident,
        /// The parameter names in order, `x, y`.
        params: Box<[Ident]>,
        /// The right-hand side, evaluated at each call with the parameters
        /// bound to the arguments.
        body: Expr,
    },
    /// `derive T_ce` — search the known transforms for a chain from {c} to {e}.
    Derive {
        /// The transform to find, whose subscript names its two frames.
        target: Ident,
    },
    /// `assert cond` — stops the script (an `assert` error) when `cond` is
    /// false, showing both sides of a comparison (LANGUAGE.md §3).
    Assert(Expr),
    /// `explain expr` — the value of `expr` with the book's steps that
    /// compute it (LANGUAGE.md §14).
    Explain(Expr),
}

/// An expression node with its span.
#[derive(Debug, Clone, PartialEq)]
pub struct Expr {
    /// What the expression is: literal, name, operation, call….
    pub kind: ExprKind,
    /// The whole expression's text.
    pub span: Span,
}

/// A prefix operator on one operand.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UnOp {
    /// `-x`
    Neg,
    /// `+x`
    Pos,
}

/// An arithmetic operator on two operands; its meaning (matrix product,
/// composition of transforms, scaling) depends on the operands' kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BinOp {
    /// `a + b`.
    Add,
    /// `a - b`.
    Sub,
    /// `*`, and juxtaposition (`2 pi`, `[S] theta`) with `implicit: true`.
    Mul,
    /// `a / b`.
    Div,
    /// `^`, right-associative; `T^-1` is the inverse.
    Pow,
}

impl Expr {
    /// `lhs op rhs` for a comparison, spanning both sides.
    pub fn compare(op: CmpOp, lhs: Expr, rhs: Expr, op_span: Span) -> Expr {
        let span = lhs.span.join(rhs.span);
        let kind = ExprKind::Compare {
            op,
            lhs: Box::new(lhs),
            rhs: Box::new(rhs),
            op_span,
        };
        Expr { kind, span }
    }
}

/// A comparison operator (LANGUAGE.md §3); both give a bool.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CmpOp {
    /// `a == b`: exactly equal (decided symbolically for symbolic sides).
    Eq,
    /// `a ≈ b`, typed `~=`: equal within 1e-9 relative.
    Approx,
    /// `a < b` on scalars.
    Lt,
    /// `a <= b` (`≤`) on scalars.
    Le,
    /// `a > b` on scalars.
    Gt,
    /// `a >= b` (`≥`) on scalars.
    Ge,
}

impl CmpOp {
    /// An order (`<`, `<=`, `>`, `>=`) rather than an equality.
    pub fn is_order(self) -> bool {
        matches!(self, CmpOp::Lt | CmpOp::Le | CmpOp::Gt | CmpOp::Ge)
    }

    /// The operator as typed (`≈` for `~=`).
    pub fn text(self) -> &'static str {
        match self {
            CmpOp::Eq => "==",
            CmpOp::Approx => "≈",
            CmpOp::Lt => "<",
            CmpOp::Le => "<=",
            CmpOp::Gt => ">",
            CmpOp::Ge => ">=",
        }
    }
}

/// One subscript of an index expression: `M[i, :]`.
#[derive(Debug, Clone, PartialEq)]
pub enum IndexArg {
    /// An expression giving a 1-based index.
    Expr(Expr),
    /// `:` — the whole row or column.
    All(Span),
}

/// The forms an expression takes; the book's notation is already resolved
/// into these by the parser.
#[derive(Debug, Clone, PartialEq)]
pub enum ExprKind {
    /// A numeric literal, `pi`/`π` already resolved to 3.14159….
    Number(f64),
    /// `true` / `false`.
    Bool(bool),
    /// A name (variable, symbol, or `ans`).
    Var(Name),
    /// `-x`, `+x`.
    Unary {
        /// Which sign.
        op: UnOp,
        /// The expression it applies to.
        operand: Box<Expr>,
    },
    /// `a + b`, `a * b`, `a b` (implicit), `a ^ b`.
    Binary {
        /// Which operator.
        op: BinOp,
        /// The left operand.
        lhs: Box<Expr>,
        /// The right operand.
        rhs: Box<Expr>,
        /// The operator token; for juxtaposition, the gap between operands.
        op_span: Span,
        /// True for juxtaposition (`2 pi`, `[S] theta`).
        implicit: bool,
    },
    /// `a == b`, `a ≈ b`: a bool. Looser than every other operator.
    Compare {
        /// Which comparison.
        op: CmpOp,
        /// The left side.
        lhs: Box<Expr>,
        /// The right side.
        rhs: Box<Expr>,
        /// The operator token.
        op_span: Span,
    },
    /// `x deg` or `x°`: degrees to radians.
    Degrees(Box<Expr>),
    /// `f(a, b)`.
    Call {
        /// The function's name: a builtin or a user function.
        func: Ident,
        /// The arguments in order.
        args: Vec<Expr>,
    },
    /// `x.T`, `T.R`, `T.p`, `V.w`, `V.v`, `F.m`, `F.f`.
    Member {
        /// The value read from, `T` in `T.R`.
        base: Box<Expr>,
        /// The part's name after the dot, `R` in `T.R`.
        member: Ident,
    },
    /// `x[i]`, `M[i, j]`, `M[:, j]` — 1-based.
    Index {
        /// The vector, matrix or list indexed.
        base: Box<Expr>,
        /// The subscripts between the brackets: one, or row and column.
        args: Vec<IndexArg>,
    },
    /// `(a, b, c)` with two or more elements: a vector when all are scalars
    /// (as the book writes them), a tuple otherwise. `(x)` is just `x`.
    Paren(Vec<Expr>),
    /// `[ ... ]`: rows of elements, rows split by `;` or newline.
    /// One element → the book's bracket `[w]`, `[V]` (or a 1-vector);
    /// one row of scalars → a column vector; otherwise MATLAB block
    /// concatenation (`[R, p; 0, 0, 0, 1]`).
    Brackets(Vec<Vec<Expr>>),
    /// `mech < links 4; joints R R R R; planar >` (chapter 2). Boxed: it
    /// is rare and large, and every other node is moved by value.
    Mech(Box<MechSpec>),
    /// `"name.svg"`: a string (file names for `save`, picture titles).
    Str(String),
    /// `0:4`, `0:pi/8:pi`: a MATLAB range (LANGUAGE.md §12), `start:end`
    /// or `start:step:end`, inclusive of the end within rounding.
    Range {
        /// The first element.
        start: Box<Expr>,
        /// The middle of `start:step:end`; `None` for `start:end` (step 1).
        step: Option<Box<Expr>>,
        /// The last element, included when the steps reach it.
        end: Box<Expr>,
    },
    /// `[body for k in r]`, `[body for a in r1, b in r2]`: a list
    /// comprehension over ranges or lists, the first variable outermost.
    Comprehension {
        /// The expression evaluated for each element.
        body: Box<Expr>,
        /// Each `name in source` in order, the first outermost.
        vars: Vec<(Ident, Expr)>,
    },
}

/// `x²`, `R⁻¹`: the power `x ^ 2`, `R ^ -1` written as a superscript (the
/// text `sup` at `span`), for both parsers.
pub(crate) fn superscript_power(base: Expr, sup: &str, span: Span) -> ExprKind {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut n = 0.0;
    for c in sup.chars() {
        if let Some(d) = DIGITS.iter().position(|&x| x == c) {
            n = n * 10.0 + d as f64;
        }
    }
    let minus = sup.starts_with('⁻');
    let digits = Span::new(
        span.start + if minus { '⁻'.len_utf8() } else { 0 },
        span.end,
    );
    let number = Expr {
        kind: ExprKind::Number(n),
        span: digits,
    };
    let rhs = if minus {
        Expr {
            kind: ExprKind::Unary {
                op: UnOp::Neg,
                operand: Box::new(number),
            },
            span,
        }
    } else {
        number
    };
    ExprKind::Binary {
        op: BinOp::Pow,
        lhs: Box::new(base),
        rhs: Box::new(rhs),
        op_span: span,
        implicit: false,
    }
}

/// The body of a `mech < ... >` literal, as written; validated by
/// [`crate::mech`].
#[derive(Debug, Clone, PartialEq)]
pub struct MechSpec {
    /// `links N`; the number is 0 when written as an expression
    /// (`links_expr`).
    pub links: Option<(i64, Span)>,
    /// `links N`, `links 2 n + 1`: the count as an expression over bound
    /// names, evaluated where the mechanism is built.
    pub links_expr: Option<Expr>,
    /// `joints 8R P RP` — each group as written.
    pub joints: Vec<JointGroupSyntax>,
    /// `legs K CHAIN`, e.g. `legs 6 UPS`; K is 0 when written as an
    /// expression (`legs_expr`).
    pub legs: Option<(i64, String, Span)>,
    /// `legs n UPS`: the number of legs as an expression.
    pub legs_expr: Option<Expr>,
    /// `planar`, `spatial` or `spherical` as written.
    pub space: Option<(String, Span)>,
    /// Any other item, kept so the validator can name it in an error.
    pub unknown: Vec<(String, Span)>,
}

/// One joint token: `R`, `8R`, `RP` (a compound joint), `6UPS`.
#[derive(Debug, Clone, PartialEq)]
pub struct JointGroupSyntax {
    /// The leading count (1 when absent, 0 when written as an
    /// expression, `(n)R`).
    pub count: i64,
    /// `(n)R`, `(n - 1) R`: the count as an expression.
    pub count_expr: Option<Expr>,
    /// The joint letters, e.g. `"RP"`.
    pub letters: String,
    /// The whole token, count included.
    pub span: Span,
}
