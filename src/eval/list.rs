//! Ranges, lists and list comprehensions (LANGUAGE.md §12): `0:4`,
//! `0:pi/8:pi` as MATLAB writes them (the end included within rounding),
//! and `[expr for k in r]`, `[expr for a in r1, b in r2]` (a outermost).
//! A list holds values of any kind; it prints, indexes from 1,
//! destructures, and is what `draw` takes for a path of frames (exercise
//! 3.48) or a workspace (exercise 2.25). Arithmetic never applies to a list
//! as a whole: a function applies to its elements through a comprehension.

use std::rc::Rc;

use super::env::{Binding, Mode};
use super::interp::{Interp, Typed};
use super::value::{Value, common_kind};
use crate::check::ty::{Kind, Ty};
use crate::diagnostics::{Diagnostic, ErrorKind};
use crate::seam::range::{MAX_LIST, RangeFail, count, items};
use crate::syntax::ast::{Expr, ExprKind, Ident, Span};

/// The most items that the comprehensions of one statement may evaluate
/// (twice the longest list), nested ones and the ranges they make
/// included: `[[a b for a in 0:999] for b in 0:99999]` is refused rather
/// than run for minutes.
pub const MAX_WORK: usize = 2_000_000;

thread_local! {
    /// (comprehensions open, items evaluated since the outermost opened).
    static WORK: std::cell::Cell<(usize, usize)> = const { std::cell::Cell::new((0, 0)) };
}

/// Counts `n` items against [`MAX_WORK`] while a comprehension is open.
fn spend(n: usize, span: Span) -> Result<(), Diagnostic> {
    WORK.with(|w| {
        let (open, done) = w.get();
        if open == 0 {
            return Ok(());
        }
        let done = done.saturating_add(n);
        w.set((open, done));
        if done > MAX_WORK {
            Err(Diagnostic::error(
                ErrorKind::Domain,
                span,
                format!("the comprehensions would evaluate more than {MAX_WORK} items"),
            )
            .with_help("nest fewer comprehensions or use larger steps"))
        } else {
            Ok(())
        }
    })
}

fn too_long(span: Span, n: f64) -> Diagnostic {
    Diagnostic::error(ErrorKind::Domain, span, RangeFail::TooLong(n).to_string())
        .with_help("use a larger step, e.g. 0:0.01:1 has 101 items")
}

/// The help for arithmetic on a list, a picture or a string.
pub fn elementwise_help(k: &Kind) -> Option<String> {
    match k {
        Kind::List(..) => Some(
            "a list is not a vector: apply the operation to each element, [2 * x for x in xs]"
                .into(),
        ),
        Kind::Picture | Kind::Text => Some(format!("{} takes no arithmetic", k.a())),
        _ => None,
    }
}

/// `len(v)` of a vector over symbols (`given v : vec3`, `(1, 2, a)`): its
/// count, which needs no numbers — the kind checked gives it, as the
/// numbers typed first would; and the other calls a `given` kind decides
/// (`det` of a rotation is 1, `trace` of an so(3) is 0:
/// [`crate::builtins::known_by_kind`]). None for anything else.
pub(super) fn symbolic_len(
    b: &crate::builtins::Builtin,
    tys: &[crate::check::ty::Ty],
    vals: &[Value],
) -> Option<Value> {
    if let Some(v) = crate::builtins::known_by_kind(b.name, vals, tys) {
        return Some(v);
    }
    let ([ty], [v]) = (tys, vals) else {
        return None;
    };
    if b.name != "len" || !crate::values::recipe::holds_symbols(v) {
        return None;
    }
    let n = match ty.kind {
        Kind::Vector(Some(n)) => n,
        Kind::Twist | Kind::Screw | Kind::Wrench => 6,
        _ => return None,
    };
    Some(Value::scalar(n as f64))
}

/// The picture and list builtins take numbers only: a symbol is a domain
/// error (there is nothing to draw until the `given` names have numbers).
/// A picture does not wait for numbers as a range does
/// (`crate::values::waiting`): printed, it is written to a file (§12), an
/// effect (`crate::effects`) that must happen where the statement is,
/// not at some later read. `len`, `sum`, `min`, `max` of a range that
/// waits wait too (`waiting::of_range`); `len` of a list of symbolic
/// items is its count, which needs no numbers.
pub(super) fn numbers_only(
    b: &crate::builtins::Builtin,
    vals: &[Value],
    span: Span,
) -> Result<(), Diagnostic> {
    if b.name == "len" && matches!(vals, [Value::List(_)]) {
        return Ok(());
    }
    if b.area == crate::builtins::Area::Pictures
        && vals.iter().any(crate::values::recipe::holds_symbols)
    {
        return Err(Diagnostic::error(
            ErrorKind::Domain,
            span,
            format!("{} needs numbers, not symbols", b.name),
        )
        .with_help("bind numbers to the given names first (§7)"));
    }
    Ok(())
}

/// What a comprehension variable runs over: its items' type, their
/// values when running, and how many there are when checking knows it.
type Domain = (Ty, Option<Vec<Value>>, Option<usize>);

impl Interp<'_> {
    /// Lists, pictures or strings as operands of arithmetic: a type error
    /// at `op` naming the first such operand.
    pub(super) fn no_arithmetic(
        &self,
        operands: &[(&Typed, Span)],
        op: Span,
    ) -> Result<(), Diagnostic> {
        for (t, side) in operands {
            // Most operands are numbers: asked first, without a call.
            if !matches!(t.ty.kind, Kind::List(..) | Kind::Picture | Kind::Text) {
                continue;
            }
            let Some(help) = elementwise_help(&t.ty.kind) else {
                continue;
            };
            return Err(Diagnostic::error(
                ErrorKind::Type,
                op,
                format!(
                    "no arithmetic on {} ({})",
                    t.ty.kind.a(),
                    self.text(*side).trim()
                ),
            )
            .with_label(*side, t.ty.kind.to_string())
            .with_help(help));
        }
        Ok(())
    }

    /// A range, comprehension or string literal.
    pub(super) fn list_expr(&mut self, e: &Expr) -> Result<Typed, Diagnostic> {
        match &e.kind {
            ExprKind::Range { start, step, end } => self.range(start, step.as_deref(), end, e.span),
            ExprKind::Comprehension { body, vars } => self.comprehension(body, vars, e.span),
            ExprKind::Str(text) => Ok(self.string(text)),
            _ => Err(self.domain(e.span, "not a list")),
        }
    }

    /// The builtin arguments' kinds and frames with their text (what
    /// `draw` labels and frames its picture with).
    pub(super) fn typed_args(&self, tys: Vec<Ty>, args: &[Expr]) -> Vec<(Ty, String)> {
        tys.into_iter()
            .zip(args)
            .map(|(t, e)| (t, self.text(e.span).trim().to_string()))
            .collect()
    }

    /// `"name.svg"`.
    pub(super) fn string(&self, text: &str) -> Typed {
        Typed::new(
            Ty::plain(Kind::Text),
            self.running().then(|| Value::Str(Rc::from(text))),
        )
    }

    /// One bound of a range: a number, or a scalar made from symbols (the
    /// range then waits for their numbers, `crate::values::waiting`).
    fn bound(&mut self, e: &Expr) -> Result<Option<Value>, Diagnostic> {
        let t = self.expr(e)?;
        if let Some(Value::Sym(s)) = t.val.as_deref() {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                e.span,
                format!("a range takes numbers, not the symbol {s}"),
            )
            .with_help("bind a number to it first (§7)"));
        }
        if !t.ty.kind.maybe_scalar() {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                e.span,
                format!("a range takes numbers, not {}", t.ty.kind.a()),
            )
            .with_help("write start:end or start:step:end, e.g. 0:pi/8:pi"));
        }
        Ok(t.val.map(|v| *v))
    }

    /// `start:end`, `start:step:end`. With a bound made from symbols
    /// (`0:a:1` over a free `a`) the range waits for their numbers, and
    /// is then the list typed first gives ([`crate::seam::range::range_items`]).
    pub(super) fn range(
        &mut self,
        start: &Expr,
        step: Option<&Expr>,
        end: &Expr,
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        let a = self.bound(start)?;
        let h = match step {
            Some(s) => self.bound(s)?,
            // (the step left out is the whole number 1, as typed)
            None => Some(Value::Num {
                kind: Kind::Scalar,
                m: crate::values::num::Num::Scalar(1.0),
                exact: crate::values::exact::Exact::Typed,
            }),
        };
        let b = self.bound(end)?;
        let len = super::slice::literal_len((start, step, end), |e| self.known_number(e));
        let ty = Ty::plain(Kind::list_of_len(Kind::Scalar, len));
        let (Some(a), Some(h), Some(b)) = (a, h, b) else {
            return Ok(Typed::new(ty, None));
        };
        if [&a, &h, &b]
            .iter()
            .any(|v| matches!(v, Value::Formula { .. }))
        {
            return match crate::values::waiting::range(&a, &h, &b, step.is_some()) {
                Some(r) => Ok(Typed::new(ty, Some(r))),
                None => Err(Diagnostic::error(
                    ErrorKind::Type,
                    span,
                    "a range takes numbers: its bounds are not scalars",
                )),
            };
        }
        if [&a, &h, &b].iter().any(|v| v.as_scalar().is_none()) {
            return Ok(Typed::new(ty, None));
        }
        let n = count(&a, &h, &b).map_err(|e| match e {
            RangeFail::ZeroStep => self
                .domain(span, e.to_string())
                .with_help("give a nonzero step: start:step:end"),
            RangeFail::TooLong(n) => too_long(span, n),
            e => self.domain(span, e.to_string()),
        })?;
        spend(n, span)?;
        crate::budget::hold(2 * n as u64)
            .map_err(|stop| super::interp::budget_error(stop, span))?;
        Ok(Typed::new(
            ty,
            Some(Value::List(Rc::new(items(&a, &h, &b, n)))),
        ))
    }

    /// `xs[i]`: the i-th item (from 1), with the list's frames.
    pub(super) fn list_item(
        &mut self,
        t: Typed,
        sels: &[super::ops::Sel],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        let Kind::List(elem, _) = &t.ty.kind else {
            return Err(self.domain(span, "not a list"));
        };
        let [super::ops::Sel::At(i)] = sels else {
            return Err(Diagnostic::error(
                ErrorKind::Type,
                span,
                "a list takes one index: xs[i], counting from 1",
            ));
        };
        let ty = t.ty.item(**elem);
        // (NaN: an index checking has no number for)
        if !i.is_nan() && (i.fract() != 0.0 || !i.is_finite()) {
            return Err(self.domain(
                span,
                crate::values::error::OpError::IndexNotWhole(*i).to_string(),
            ));
        }
        // (a range waiting for numbers has no items yet)
        if let Some(d) = super::slice::unindexable_range(t.val.as_deref(), span) {
            return Err(d);
        }
        let Some(Value::List(items)) = t.val.as_deref() else {
            // (checking: a list's length is known from its items, or from
            // its literal bounds (`(0:4)[9]`, [`Kind::list_len`]); none has
            // an item before its first)
            if let Some(n) = t.ty.kind.list_len()
                && !i.is_nan()
                && !(*i >= 1.0 && *i <= n as f64)
            {
                return Err(self.domain(
                    span,
                    format!("index {i} is outside the list (it has {n} items, counted from 1)"),
                ));
            }
            if *i < 1.0 {
                return Err(self.domain(
                    span,
                    format!("index {i} is outside the list (its items are counted from 1)"),
                ));
            }
            return Ok(Typed::new(ty, None));
        };
        let n = items.len();
        if !(*i >= 1.0 && *i <= n as f64) {
            return Err(self.domain(
                span,
                format!("index {i} is outside the list (it has {n} items, counted from 1)"),
            ));
        }
        let v = items[*i as usize - 1].clone();
        // (a given name's symbol knows no kind of its own: the list's, as
        // checking gives it — `[R_ab for k in 1:2][1]` is an SO(3))
        let kind = match &v {
            v if symbol_made(v) && **elem != Kind::Unknown => **elem,
            v => v.kind(),
        };
        Ok(Typed::new(t.ty.item(kind), Some(v)))
    }

    /// What a comprehension variable runs over: a list's elements or a
    /// vector's entries.
    /// With it, how many items it has when checking knows that without
    /// numbers (`0:4`, `[1, 2, 3]`: [`Kind::list_len`]).
    fn over(&mut self, e: &Expr) -> Result<Domain, Diagnostic> {
        let t = self.expr(e)?;
        let len = match t.ty.kind {
            Kind::Vector(n) => n,
            k => k.list_len(),
        };
        let elem = match &t.ty.kind {
            Kind::List(k, _) => **k,
            Kind::Vector(_) => Kind::Scalar,
            Kind::Unknown => Kind::Unknown,
            k => {
                return Err(Diagnostic::error(
                    ErrorKind::Type,
                    e.span,
                    format!("a comprehension runs over a range or list, not {}", k.a()),
                )
                .with_help("write [f(k) for k in 0:4]"));
            }
        };
        let ty = match &t.ty.kind {
            Kind::List(..) => t.ty.item(elem),
            _ => Ty::plain(elem),
        };
        let vals = match t.val.map(|v| *v) {
            Some(Value::List(vs)) => Some(vs.as_ref().clone()),
            // (a range waiting for numbers has no items to run over yet;
            // a comprehension is evaluated item by item, so it cannot wait)
            Some(v @ Value::Formula { .. }) => {
                return Err(Diagnostic::error(
                    ErrorKind::Domain,
                    e.span,
                    format!(
                        "a comprehension needs numbers to run over: {} waits for {}",
                        crate::values::format::inline(&v, 4),
                        crate::values::waiting::symbols(&v)
                    ),
                )
                .with_help("bind numbers to the given names first, then build the list (§7)"));
            }
            Some(v @ Value::Num { .. }) => Some(crate::seam::shapes::entries(&v)),
            Some(Value::Sym(_)) => {
                return Err(Diagnostic::error(
                    ErrorKind::Type,
                    e.span,
                    "a comprehension runs over numbers, not symbols",
                ));
            }
            _ => None,
        };
        Ok((ty, vals, len))
    }

    /// `[body for a in r1, b in r2]`.
    pub(super) fn comprehension(
        &mut self,
        body: &Expr,
        vars: &[(Ident, Expr)],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        let mut domains = Vec::new();
        // (the number of items, when every domain's is known)
        let mut len = Some(1usize);
        for (name, e) in vars {
            let (ty, vals, n) = self.over(e)?;
            len = len.zip(n).and_then(|(a, b)| a.checked_mul(b));
            domains.push((String::from(name.name), ty, vals));
        }
        let names: Vec<String> = domains.iter().map(|d| d.0.clone()).collect();
        let saved: Vec<(String, Option<Binding>)> = names
            .iter()
            .map(|n| (n.clone(), self.env.get(n).cloned()))
            .collect();
        WORK.with(|w| {
            let (open, done) = w.get();
            w.set((open + 1, if open == 0 { 0 } else { done }));
        });
        let result = self.comprehend(body, &domains, span);
        WORK.with(|w| {
            let (open, done) = w.get();
            w.set((open.saturating_sub(1), done));
        });
        for (n, old) in saved {
            match old {
                Some(b) => self.env.set(&n, b),
                None => {
                    self.env.remove(&n);
                }
            }
        }
        // (its length, known without numbers: `[f(k) for k in 1:3][4]`
        // is refused by checking as by running)
        result.map(|mut t| {
            if let Kind::List(k, None) = t.ty.kind {
                t.ty.kind = Kind::List(k, len.and_then(|n| u32::try_from(n).ok()));
            }
            t
        })
    }

    fn comprehend(
        &mut self,
        body: &Expr,
        domains: &[(String, Ty, Option<Vec<Value>>)],
        span: Span,
    ) -> Result<Typed, Diagnostic> {
        // The body's kind and frames, once, with no numbers.
        let mode = self.mode;
        self.mode = Mode::Check;
        for (n, ty, _) in domains {
            self.env.set(
                n,
                Binding {
                    ty: *ty,
                    val: None,
                    symbolic: false,
                    derived: false,
                    stamp: 0,
                    absorbed: Vec::new(),
                },
            );
        }
        let checked = self.expr(body);
        self.mode = mode;
        let body_ty = checked?;
        let list_ty = |k: Kind| Ty::list_of(body_ty.ty, k);
        if mode == Mode::Check {
            return Ok(Typed::new(list_ty(body_ty.ty.kind), None));
        }
        let Some(lists) = domains
            .iter()
            .map(|d| d.2.as_ref())
            .collect::<Option<Vec<_>>>()
        else {
            return Ok(Typed::new(list_ty(body_ty.ty.kind), None));
        };
        let total: f64 = lists.iter().map(|l| l.len() as f64).product();
        if total > MAX_LIST as f64 {
            return Err(too_long(span, total));
        }
        let mut out = Vec::with_capacity(total as usize);
        let mut at = vec![0usize; lists.len()];
        // The items held so far count against the budget; the finished
        // list is counted by what holds it (an outer list, a binding).
        let mark = crate::budget::held();
        let result = self.comprehend_items(body, domains, &lists, &mut at, &mut out, total, span);
        crate::budget::release_to(mark);
        result?;
        // (a given name's symbol knows no kind of its own: the body's, as
        // checking gives it — `[R_ab for k in 1:2]` is a list of SO(3))
        let symbols = out.iter().any(symbol_made);
        let kind = if out.is_empty() || symbols {
            body_ty.ty.kind
        } else {
            common_kind(&out)
        };
        Ok(Typed::new(list_ty(kind), Some(Value::List(Rc::new(out)))))
    }

    /// The items of a comprehension, in order (the last variable fastest),
    /// each counted against the budget.
    #[allow(clippy::too_many_arguments)]
    fn comprehend_items(
        &mut self,
        body: &Expr,
        domains: &[(String, Ty, Option<Vec<Value>>)],
        lists: &[&Vec<Value>],
        at: &mut [usize],
        out: &mut Vec<Value>,
        total: f64,
        span: Span,
    ) -> Result<(), Diagnostic> {
        let stopped = |stop: crate::budget::Stop| super::interp::budget_error(stop, span);
        let mut numbers = 0u64;
        if total > 0.0 {
            'all: loop {
                for (i, (n, ty, _)) in domains.iter().enumerate() {
                    let v = lists[i][at[i]].clone();
                    // (a tuple keeps its parts' frames)
                    let ty = match (ty.parts, &v) {
                        (Some(_), _) => super::interp::refine_by(*ty, Some(&v)),
                        (None, v) if symbol_made(v) && ty.kind != Kind::Unknown => *ty,
                        (None, _) => Ty::new(v.kind(), ty.frames),
                    };
                    self.env.set(
                        n,
                        Binding {
                            ty,
                            val: Some(v),
                            symbolic: false,
                            derived: false,
                            stamp: 0,
                            absorbed: Vec::new(),
                        },
                    );
                }
                spend(1, span)?;
                crate::budget::check().map_err(stopped)?;
                // The size the whole list would have taken, at the items'
                // mean size so far, names a refusal of the budget.
                let whole =
                    |numbers: u64, done: usize| (numbers as f64 / done as f64 * total) as u64;
                let t = match self.expr(body) {
                    Ok(t) => t,
                    Err(d) => {
                        return Err(match crate::budget::take_refusal() {
                            Some(stop) if !out.is_empty() => {
                                stopped(stop.wanting(whole(numbers, out.len())))
                            }
                            _ => d,
                        });
                    }
                };
                let v = t.val.map_or_else(|| Value::scalar(f64::NAN), |v| *v);
                let n = super::env::numbers(&v) + 1;
                numbers += n;
                if let Err(stop) = crate::budget::hold(n) {
                    return Err(stopped(stop.wanting(whole(numbers, out.len() + 1))));
                }
                out.push(v);
                // The last variable runs fastest: the first is outermost.
                let mut i = lists.len();
                loop {
                    if i == 0 {
                        break 'all;
                    }
                    i -= 1;
                    at[i] += 1;
                    if at[i] < lists[i].len() {
                        break;
                    }
                    at[i] = 0;
                }
            }
        }
        Ok(())
    }
}

/// A given name's symbol, or a tuple holding one: a value that knows no
/// kind of its own (`(T_bc, T_bc)` over given names is a tuple of
/// "values"), whose static kind the list keeps.
fn symbol_made(v: &Value) -> bool {
    match v {
        Value::Sym(_) => true,
        Value::Tuple(parts) => parts.iter().any(symbol_made),
        _ => false,
    }
}
