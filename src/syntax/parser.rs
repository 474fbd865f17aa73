//! One statement's text → [`Stmt`], through the pest grammar.
//!
//! The grammar (`grammar/chasles.pest`) gives an expression as a flat
//! sequence of operands and operators; a Pratt parser builds the tree. Every
//! step is fallible — a malformed pair becomes a diagnostic, never a panic —
//! and the depth of the tree is bounded by [`MAX_DEPTH`]: operator chains are
//! measured before the (recursive) Pratt parser runs, and every node built
//! checks its own depth.

use std::cell::Cell;
use std::sync::LazyLock;

use pest::Parser as _;
use pest::iterators::Pair;
use pest::pratt_parser::{Assoc, Op, PrattParser};

use super::MAX_DEPTH;
use super::ast::{BinOp, Expr, ExprKind, Ident, IndexArg, Span, Stmt, StmtKind, UnOp};
use super::grammar::{ChaslesParser, Rule};
use super::rules::{self, too_deep};
use crate::diagnostics::{Diagnostic, ErrorKind};

/// Precedence levels, loosest first; the same order as [`PRATT`].
const PREC_CMP: u8 = 0;
const PREC_RANGE: u8 = 1;
const PREC_ADD: u8 = 2;
const PREC_MUL: u8 = 3;
const PREC_PREFIX: u8 = 4;
const PREC_POW: u8 = 5;

static PRATT: LazyLock<PrattParser<Rule>> = LazyLock::new(|| {
    PrattParser::new()
        .op(Op::infix(Rule::eq, Assoc::Left)
            | Op::infix(Rule::approx, Assoc::Left)
            | Op::infix(Rule::lt, Assoc::Left)
            | Op::infix(Rule::le, Assoc::Left)
            | Op::infix(Rule::gt, Assoc::Left)
            | Op::infix(Rule::ge, Assoc::Left))
        .op(Op::infix(Rule::range_op, Assoc::Left))
        .op(Op::infix(Rule::add, Assoc::Left) | Op::infix(Rule::sub, Assoc::Left))
        .op(Op::infix(Rule::mul, Assoc::Left)
            | Op::infix(Rule::div, Assoc::Left)
            | Op::infix(Rule::juxt, Assoc::Left)
            | Op::infix(Rule::dot_op, Assoc::Left)
            | Op::infix(Rule::cross_op, Assoc::Left)
            | Op::infix(Rule::starstar, Assoc::Left))
        .op(Op::prefix(Rule::neg) | Op::prefix(Rule::pos))
        .op(Op::infix(Rule::pow, Assoc::Right))
        .op(Op::postfix(Rule::index)
            | Op::postfix(Rule::member)
            | Op::postfix(Rule::degrees)
            | Op::postfix(Rule::transpose_mark)
            | Op::postfix(Rule::superscript))
});

/// Parses `chunk`, the blanked text of the statement at `span`.
pub(crate) fn parse_chunk(chunk: &str, span: Span) -> Result<Stmt, Diagnostic> {
    let cx = Cx {
        off: span.start,
        above: Cell::new(0),
    };
    let mut pairs = match ChaslesParser::parse(Rule::statement, chunk) {
        Ok(pairs) => pairs,
        Err(_) => {
            return Err(rules::pest_error(
                parse_with_detail(chunk),
                chunk,
                span.start,
            ));
        }
    };
    let stmt = pairs.next().ok_or_else(|| cx.internal(span))?;
    let form = stmt
        .into_inner()
        .find(|p| p.as_rule() != Rule::EOI)
        .ok_or_else(|| cx.internal(span))?;
    let kind = cx.statement(form)?;
    Ok(Stmt {
        kind,
        span,
        silent: false,
    })
}

/// Parses again with pest's error details (which rules were tried where),
/// for the message of a statement that failed. Details cost about 40% of
/// parse speed, so a successful parse runs without them. The setting is
/// process-wide: a lock keeps detailed re-parses from switching it off
/// under each other.
fn parse_with_detail(chunk: &str) -> pest::error::Error<Rule> {
    static DETAIL: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _guard = DETAIL.lock().unwrap_or_else(|e| e.into_inner());
    pest::set_error_detail(true);
    let result = ChaslesParser::parse(Rule::statement, chunk);
    pest::set_error_detail(false);
    match result {
        Err(e) => e,
        Ok(_) => pest::error::Error::new_from_pos(
            pest::error::ErrorVariant::CustomError {
                message: "the statement parses only with error details on".into(),
            },
            pest::Position::from_start(chunk),
        ),
    }
}

/// Where the statement sits in the source.
pub(crate) struct Cx {
    /// Byte offset of the statement in the whole source.
    pub off: usize,
    /// How many tree levels lie above the expression being built (open
    /// operators and brackets of the enclosing expressions). Bounds the
    /// recursion of the Pratt parser across nested brackets.
    above: Cell<usize>,
}

pub(super) type Built = Result<(Expr, usize), Diagnostic>;

/// How a pair takes part in the operator sequence of an expression.
enum Role {
    Prefix,
    Operand,
    Postfix,
    Infix { prec: u8, right: bool },
}

fn role(rule: Rule) -> Role {
    match rule {
        Rule::neg | Rule::pos => Role::Prefix,
        Rule::eq | Rule::approx | Rule::lt | Rule::le | Rule::gt | Rule::ge => Role::Infix {
            prec: PREC_CMP,
            right: false,
        },
        Rule::range_op => Role::Infix {
            prec: PREC_RANGE,
            right: false,
        },
        Rule::add | Rule::sub => Role::Infix {
            prec: PREC_ADD,
            right: false,
        },
        Rule::mul | Rule::div | Rule::juxt | Rule::starstar | Rule::dot_op | Rule::cross_op => {
            Role::Infix {
                prec: PREC_MUL,
                right: false,
            }
        }
        Rule::pow => Role::Infix {
            prec: PREC_POW,
            right: true,
        },
        Rule::index | Rule::member | Rule::degrees | Rule::transpose_mark | Rule::superscript => {
            Role::Postfix
        }
        _ => Role::Operand,
    }
}

pub(super) fn check_depth(depth: usize, span: Span) -> Result<(), Diagnostic> {
    if depth > MAX_DEPTH {
        Err(too_deep(span))
    } else {
        Ok(())
    }
}

impl Cx {
    pub(crate) fn span(&self, s: pest::Span<'_>) -> Span {
        Span::new(self.off + s.start(), self.off + s.end())
    }

    pub(super) fn internal(&self, span: Span) -> Diagnostic {
        Diagnostic::error(ErrorKind::Syntax, span, "internal parser error")
    }

    pub(super) fn unexpected(&self, pair: &Pair<'_, Rule>) -> Diagnostic {
        Diagnostic::error(
            ErrorKind::Syntax,
            self.span(pair.as_span()),
            format!("internal parser error: unexpected {:?}", pair.as_rule()),
        )
    }

    pub(super) fn ident(&self, pair: Pair<'_, Rule>) -> Result<Ident, Diagnostic> {
        if pair.as_rule() != Rule::ident {
            return Err(self.unexpected(&pair));
        }
        Ok(Ident {
            name: pair.as_str().into(),
            span: self.span(pair.as_span()),
        })
    }

    fn statement(&self, form: Pair<'_, Rule>) -> Result<StmtKind, Diagnostic> {
        let whole = self.span(form.as_span());
        match form.as_rule() {
            Rule::expr => Ok(StmtKind::Expr(self.expr(form)?.0)),
            Rule::assign => {
                let mut it = form.into_inner();
                let target = self.ident(it.next().ok_or_else(|| self.internal(whole))?)?;
                let value = self.expr(it.next().ok_or_else(|| self.internal(whole))?)?.0;
                Ok(StmtKind::Assign { target, value })
            }
            Rule::destructure => {
                let mut targets = Vec::new();
                let mut value = None;
                for p in form.into_inner() {
                    match p.as_rule() {
                        Rule::ident => targets.push(self.ident(p)?),
                        Rule::expr => value = Some(self.expr(p)?.0),
                        _ => return Err(self.unexpected(&p)),
                    }
                }
                let value = value.ok_or_else(|| self.internal(whole))?;
                Ok(StmtKind::Destructure { targets, value })
            }
            Rule::fn_def => {
                let mut name = None;
                let mut params = Vec::new();
                let mut body = None;
                for p in form.into_inner() {
                    match p.as_rule() {
                        Rule::ident => name = Some(self.ident(p)?),
                        Rule::params => {
                            for q in p.into_inner() {
                                params.push(self.ident(q)?);
                            }
                        }
                        Rule::expr => body = Some(self.expr(p)?.0),
                        _ => return Err(self.unexpected(&p)),
                    }
                }
                match (name, body) {
                    (Some(name), Some(body)) => Ok(StmtKind::FnDef {
                        name,
                        params: params.into_boxed_slice(),
                        body,
                    }),
                    _ => Err(self.internal(whole)),
                }
            }
            Rule::given_stmt => {
                let (mut names, mut times, mut ty) = (Vec::new(), Vec::new(), None);
                for p in form.into_inner() {
                    match p.as_rule() {
                        Rule::kw_given => {}
                        Rule::given_type => ty = Some(self.given_type(&p)),
                        _ => {
                            let mut parts = p.into_inner().map(|x| self.ident(x));
                            names.push(parts.next().ok_or_else(|| self.internal(whole))??);
                            times.push(parts.next().transpose()?); // `theta(t)`
                        }
                    }
                }
                // `given α, β`: scalars (a type is needed only for other kinds).
                let ty = ty.unwrap_or_else(|| Ident {
                    name: "scalar".into(),
                    span: whole,
                });
                Ok(StmtKind::Given { names, ty, times })
            }
            Rule::assert_stmt => match form.into_inner().find(|p| p.as_rule() == Rule::expr) {
                Some(p) => Ok(StmtKind::Assert(self.expr(p)?.0)),
                None => Err(self.internal(whole)),
            },
            Rule::explain_stmt => match form.into_inner().find(|p| p.as_rule() == Rule::expr) {
                Some(p) => Ok(StmtKind::Explain(self.expr(p)?.0)),
                None => Err(self.internal(whole)),
            },
            Rule::derive_stmt => {
                let p = form
                    .into_inner()
                    .find(|p| p.as_rule() == Rule::ident)
                    .ok_or_else(|| self.internal(whole))?;
                Ok(StmtKind::Derive {
                    target: self.ident(p)?,
                })
            }
            _ => Err(self.unexpected(&form)),
        }
    }

    /// An `expr` pair → its tree and depth.
    pub(super) fn expr(&self, pair: Pair<'_, Rule>) -> Built {
        let whole = self.span(pair.as_span());
        let children: Vec<Pair<'_, Rule>> = pair.into_inner().collect();

        // Juxtaposition: see `check_juxtaposition`.
        for (k, child) in children.iter().enumerate() {
            match child.as_rule() {
                Rule::juxt => {
                    let (Some(left), Some(right)) =
                        (children.get(k.wrapping_sub(1)), children.get(k + 1))
                    else {
                        return Err(self.unexpected(child));
                    };
                    self.check_juxtaposition(left, right)?;
                }
                Rule::starstar => {
                    return Err(Diagnostic::error(
                        ErrorKind::Syntax,
                        self.span(child.as_span()),
                        "`**` is not an operator",
                    )
                    .with_help("use ^ for powers: x^2"));
                }
                _ => {}
            }
        }

        // The flat operator sequence the Pratt parser reads.
        let mut stream: Vec<Pair<'_, Rule>> = Vec::with_capacity(children.len());
        for child in children {
            if child.as_rule() == Rule::operand {
                stream.extend(child.into_inner());
            } else {
                stream.push(child);
            }
        }
        let above = self.check_sequence(&stream, whole)?;
        let mut next_operand = 0;
        // Levels above the operand last built, for its index arguments.
        let last_above = Cell::new(self.above.get());

        PRATT
            .map_primary(|p| {
                let here = above.get(next_operand).copied().unwrap_or(0);
                next_operand += 1;
                last_above.set(here);
                self.nested(here, || self.primary(p))
            })
            .map_prefix(|op, rhs| {
                let (operand, d) = rhs?;
                let span = self.span(op.as_span()).join(operand.span);
                check_depth(d + 1, self.span(op.as_span()))?;
                let op = match op.as_rule() {
                    Rule::neg => UnOp::Neg,
                    Rule::pos => UnOp::Pos,
                    _ => return Err(self.unexpected(&op)),
                };
                let kind = ExprKind::Unary {
                    op,
                    operand: Box::new(operand),
                };
                Ok((Expr { kind, span }, d + 1))
            })
            .map_postfix(|lhs, op| {
                let (base, d) = lhs?;
                self.nested(last_above.get(), || self.postfix(base, d, op))
            })
            .map_infix(|lhs, op, rhs| {
                let (l, dl) = lhs?;
                let (r, dr) = rhs?;
                let depth = dl.max(dr) + 1;
                let op_span = self.span(op.as_span());
                check_depth(depth, op_span)?;
                if op.as_rule() == Rule::range_op {
                    return Ok((super::ranges::range(l, r, op_span)?, depth));
                }
                if let Some(op) = rules::cmp_op(op.as_rule()) {
                    return Ok((Expr::compare(op, l, r, op_span), depth));
                }
                // `a · b`, `a × b`: the book's dot and cross products.
                let (l, r) = match self.product_call(op.as_rule(), l, r, op_span) {
                    Ok(call) => return Ok((call, depth)),
                    Err(operands) => operands,
                };
                let (bop, implicit, op_span) = match op.as_rule() {
                    Rule::add => (BinOp::Add, false, op_span),
                    Rule::sub => (BinOp::Sub, false, op_span),
                    Rule::mul => (BinOp::Mul, false, op_span),
                    Rule::div => (BinOp::Div, false, op_span),
                    Rule::pow => (BinOp::Pow, false, op_span),
                    Rule::juxt => (
                        BinOp::Mul,
                        true,
                        Span::new(l.span.end, r.span.start.max(l.span.end)),
                    ),
                    _ => return Err(self.unexpected(&op)),
                };
                let span = l.span.join(r.span);
                let kind = ExprKind::Binary {
                    op: bop,
                    lhs: Box::new(l),
                    rhs: Box::new(r),
                    op_span,
                    implicit,
                };
                Ok((Expr { kind, span }, depth))
            })
            .parse(stream.into_iter())
    }

    /// Runs `f` with `levels` more tree levels above it.
    fn nested<T>(&self, levels: usize, f: impl FnOnce() -> T) -> T {
        let outer = self.above.get();
        self.above.set(outer + levels);
        let out = f();
        self.above.set(outer);
        out
    }

    /// Checks that `stream` alternates operands and operators as the Pratt
    /// parser expects (so it cannot panic) and that its operator stack —
    /// the Pratt parser's recursion depth — stays within [`MAX_DEPTH`]
    /// together with the levels above this expression. Returns, for each
    /// operand in order, the number of operators waiting above it.
    fn check_sequence(
        &self,
        stream: &[Pair<'_, Rule>],
        whole: Span,
    ) -> Result<Vec<usize>, Diagnostic> {
        let above = self.above.get();
        let mut want_operand = true;
        // Precedences of the operators waiting for their right operand.
        let mut pending: Vec<u8> = Vec::new();
        let mut operands = Vec::new();
        for pair in stream {
            match (role(pair.as_rule()), want_operand) {
                (Role::Prefix, true) => pending.push(PREC_PREFIX),
                (Role::Operand, true) => {
                    operands.push(pending.len() + 1);
                    want_operand = false;
                }
                (Role::Postfix, false) => {}
                (Role::Infix { prec, right }, false) => {
                    while let Some(&top) = pending.last() {
                        if top > prec || (top == prec && !right) {
                            pending.pop();
                        } else {
                            break;
                        }
                    }
                    pending.push(prec);
                    want_operand = true;
                }
                _ => return Err(self.unexpected(pair)),
            }
            if above + pending.len() > MAX_DEPTH {
                return Err(too_deep(self.span(pair.as_span())));
            }
        }
        if want_operand {
            return Err(self.internal(whole));
        }
        Ok(operands)
    }

    fn postfix(&self, base: Expr, depth: usize, op: Pair<'_, Rule>) -> Built {
        let op_span = self.span(op.as_span());
        let span = base.span.join(op_span);
        check_depth(depth + 1, op_span)?;
        let kind = match op.as_rule() {
            Rule::degrees => ExprKind::Degrees(Box::new(base)),
            Rule::superscript => {
                let kind = super::ast::superscript_power(base, op.as_str(), op_span);
                return Ok((Expr { kind, span }, depth + 2));
            }
            // `Rᵀ` is `R.T`.
            Rule::transpose_mark => ExprKind::Member {
                base: Box::new(base),
                member: Ident {
                    name: "T".into(),
                    span: op_span,
                },
            },
            Rule::member => {
                let name = op
                    .into_inner()
                    .next()
                    .ok_or_else(|| self.internal(op_span))?;
                ExprKind::Member {
                    base: Box::new(base),
                    member: self.ident(name)?,
                }
            }
            Rule::index => {
                let mut args = Vec::new();
                let mut d = 0;
                for a in op.into_inner() {
                    match a.as_rule() {
                        Rule::all => args.push(IndexArg::All(self.span(a.as_span()))),
                        Rule::expr => {
                            let (e, ed) = self.expr(a)?;
                            d = d.max(ed);
                            args.push(IndexArg::Expr(e));
                        }
                        _ => return Err(self.unexpected(&a)),
                    }
                }
                check_depth(d + 1, op_span)?;
                let kind = ExprKind::Index {
                    base: Box::new(base),
                    args,
                };
                return Ok((Expr { kind, span }, (depth + 1).max(d + 1)));
            }
            _ => return Err(self.unexpected(&op)),
        };
        Ok((Expr { kind, span }, depth + 1))
    }

    /// Elements of `( )`, `[ ]` rows and call arguments.
    fn exprs<'i>(
        &self,
        pairs: impl Iterator<Item = Pair<'i, Rule>>,
    ) -> Result<(Vec<Expr>, usize), Diagnostic> {
        let mut out = Vec::new();
        let mut depth = 0;
        for p in pairs {
            let (e, d) = self.expr(p)?;
            depth = depth.max(d);
            out.push(e);
        }
        Ok((out, depth))
    }

    pub(super) fn primary(&self, pair: Pair<'_, Rule>) -> Built {
        let span = self.span(pair.as_span());
        let leaf = |kind| Ok((Expr { kind, span }, 1));
        match pair.as_rule() {
            Rule::number => match pair.as_str().parse::<f64>() {
                Ok(x) => leaf(ExprKind::Number(x)),
                Err(_) => Err(Diagnostic::error(
                    ErrorKind::Syntax,
                    span,
                    format!("invalid number `{}`", pair.as_str()),
                )),
            },
            Rule::pi => leaf(ExprKind::Number(std::f64::consts::PI)),
            Rule::bool_lit => leaf(ExprKind::Bool(pair.as_str() == "true")),
            Rule::ident => leaf(ExprKind::Var(pair.as_str().into())),
            Rule::call => {
                let mut it = pair.into_inner();
                let func = self.ident(it.next().ok_or_else(|| self.internal(span))?)?;
                let args = it.next().ok_or_else(|| self.internal(span))?;
                let (args, d) = self.exprs(args.into_inner())?;
                check_depth(d + 1, span)?;
                Ok((
                    Expr {
                        kind: ExprKind::Call { func, args },
                        span,
                    },
                    d + 1,
                ))
            }
            Rule::bare_call => self.bare_call(pair),
            // `√2`, `√(x + 1)`: sqrt of the atom after the sign.
            Rule::root => self.root(pair, span),
            Rule::deg_unit => Ok(self.deg_unit(span)),
            Rule::paren | Rule::sup_group => {
                let (mut items, d) = self.exprs(pair.into_inner())?;
                if items.len() == 1 {
                    // `(x)` is x, spanning its parentheses.
                    let mut e = items.pop().ok_or_else(|| self.internal(span))?;
                    e.span = span;
                    return Ok((e, d));
                }
                check_depth(d + 1, span)?;
                Ok((
                    Expr {
                        kind: ExprKind::Paren(items),
                        span,
                    },
                    d + 1,
                ))
            }
            Rule::brackets => {
                let mut rows = Vec::new();
                let mut depth = 0;
                for row in pair.into_inner() {
                    if row.as_rule() == Rule::comp_tail {
                        return self.comprehension(rows, row, depth, span);
                    }
                    let mut inner = row.into_inner().peekable();
                    if let Some(plain) = inner.next_if(|p| p.as_rule() == Rule::plain_row) {
                        depth = depth.max(2);
                        rows.extend(self.plain_rows(plain)?);
                        continue;
                    }
                    let (items, d) = self.exprs(inner)?;
                    depth = depth.max(d);
                    rows.push(items);
                }
                check_depth(depth + 1, span)?;
                Ok((
                    Expr {
                        kind: ExprKind::Brackets(rows),
                        span,
                    },
                    depth + 1,
                ))
            }
            Rule::mech => leaf(ExprKind::Mech(Box::new(self.mech(pair)?))),
            Rule::string => leaf(ExprKind::Str(super::ranges::string(pair.as_str()))),
            _ => Err(self.unexpected(&pair)),
        }
    }
}
