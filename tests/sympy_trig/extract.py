#!/usr/bin/env python3
"""Extracts the identities of SymPy's own trigonometric tests into
`tests/sympy_trig/identities.tsv`, the table `tests/sympy_suite.rs` runs
through chasles (issue 35: "an in-project test drawn from SymPy's own trig
tests ... a generated table that names each source file and line").

Run from the repository root with SymPy installed (any recent version; the
table names the version it was made from):

    python3 tests/sympy_trig/extract.py [--out tests/sympy_trig/identities.tsv]

What it takes: every `assert A == B` (and `assert f(A) == B` with f a
simplifier: trigsimp, fu, simplify, TR1..TR22, ...) of

    sympy/simplify/tests/test_trigsimp.py
    sympy/simplify/tests/test_fu.py
    sympy/simplify/tests/test_simplify.py
    sympy/functions/elementary/tests/test_trigonometric.py

whose two sides are written (in the test's source text, before SymPy's
automatic evaluation) with numbers, pi, symbols, + - * / ^ and the
functions chasles has (sin cos tan cot sec csc asin acos atan sqrt exp
log). Each is translated from the source text to chasles' syntax, and
kept only if SymPy finds the two sides equal at five random real points
(so it is an identity of real numbers where both sides are defined, not
one that needs a symbol's assumptions), and not equal as written text.

Columns: source (file:line), symbols (comma-separated), lhs, rhs, form
(`rhs` when the assert was f(A) == B with f a simplifier: B is SymPy's
expected simplified form of A; `-` otherwise).
"""

import argparse
import ast
import os
import random
import sys

import sympy as sp

FILES = [
    "simplify/tests/test_trigsimp.py",
    "simplify/tests/test_fu.py",
    "simplify/tests/test_simplify.py",
    "functions/elementary/tests/test_trigonometric.py",
]

FUNCS = {"sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "sqrt", "exp", "log"}
SIMPLIFIERS = {
    "trigsimp", "fu", "simplify", "futrig", "exptrigsimp", "ratsimp", "expand_trig",
    "cancel", "factor", "expand", "together", "nsimplify", "trig_split", "L", "hyper_as_trig",
} | {f"TR{i}" for i in range(0, 23)} | {"TR2i", "TR10i", "TR11i", "TR111", "TRmorrie", "TR14", "TR22", "TRpower"}
NAMES = set("abcdfghkmnpqrstuvwxyz") | {"theta", "phi", "alpha", "beta", "gamma", "x1", "x2", "y1", "y2"}


class Skip(Exception):
    pass


def tr(node, syms):
    """Python source node -> chasles text (raises Skip outside the subset)."""
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise Skip
        if isinstance(node.value, float):
            raise Skip  # a decimal is exact in chasles; SymPy's tests mean it as a float
        return str(node.value)
    if isinstance(node, ast.Name):
        if node.id == "pi":
            return "pi"
        if node.id == "E":
            return "exp(1)"
        if node.id in NAMES:
            syms.add(node.id)
            return node.id
        raise Skip
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "S":
        return {"Half": "(1/2)", "One": "1", "Zero": "0", "Pi": "pi", "NegativeOne": "(-1)"}.get(node.attr) or _skip()
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        inner = tr(node.operand, syms)
        return f"(-{inner})" if isinstance(node.op, ast.USub) else inner
    if isinstance(node, ast.BinOp):
        ops = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "^"}
        op = ops.get(type(node.op))
        if op is None:
            raise Skip
        return f"({tr(node.left, syms)} {op} {tr(node.right, syms)})"
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.keywords:
        f = node.func.id
        if f in FUNCS and len(node.args) == 1:
            return f"{f}({strip(tr(node.args[0], syms))})"
        if f in ("S", "Integer", "Float", "sympify") and len(node.args) == 1:
            a = node.args[0]
            if isinstance(a, ast.Constant) and isinstance(a.value, str):
                try:
                    float(sp.Rational(a.value))
                except Exception:
                    raise Skip
                return f"({a.value})"
            return tr(a, syms)
        if f == "Rational" and len(node.args) == 2:
            return f"({tr(node.args[0], syms)}/{tr(node.args[1], syms)})"
        if f == "Pow" and len(node.args) == 2:
            return f"({tr(node.args[0], syms)} ^ {tr(node.args[1], syms)})"
        if f in ("Mul", "Add") and node.args:
            op = " * " if f == "Mul" else " + "
            return "(" + op.join(tr(a, syms) for a in node.args) + ")"
    raise Skip


def _skip():
    raise Skip


def strip(s):
    """One pair of outer parentheses dropped where they enclose everything."""
    if s.startswith("(") and s.endswith(")"):
        depth = 0
        for i, c in enumerate(s):
            depth += c == "("
            depth -= c == ")"
            if depth == 0 and i < len(s) - 1:
                return s
        return s[1:-1]
    return s


def value(text, syms, point):
    """The chasles text read back by SymPy at a point (the check is of the
    translation, not of the test's source)."""
    local = {n: sp.Symbol(n) for n in syms}
    local.update({f: getattr(sp, f) for f in FUNCS})
    local["pi"] = sp.pi
    e = sp.sympify(text.replace("^", "**"), locals=local, rational=True)
    return complex(e.subs({local[n]: v for n, v in point.items()}).evalf(30))


def identity(lhs, rhs, syms, rng):
    agree = 0
    for _ in range(12):
        point = {n: sp.Rational(rng.randint(-2900, 2900), 1000) for n in syms}
        try:
            a, b = value(lhs, syms, point), value(rhs, syms, point)
        except Exception:
            continue
        if any(map(lambda z: z != z or abs(z) > 1e12, (a, b))):
            continue
        if abs(a.imag) > 1e-12 or abs(b.imag) > 1e-12:
            return False  # complex somewhere on the reals: not for chasles
        if abs(a - b) > 1e-9 * max(1.0, abs(a)):
            return False
        agree += 1
        if agree == 5 or not syms:
            return True
    return False


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="tests/sympy_trig/identities.tsv")
    args = ap.parse_args()
    root = os.path.dirname(sp.__file__)
    rng = random.Random(35)
    rows, seen = [], set()
    for rel in FILES:
        src = open(os.path.join(root, rel), encoding="utf-8").read()
        for node in ast.walk(ast.parse(src)):
            if not (isinstance(node, ast.Assert) and isinstance(node.test, ast.Compare)):
                continue
            t = node.test
            if len(t.ops) != 1 or not isinstance(t.ops[0], ast.Eq):
                continue
            left, right, form = t.left, t.comparators[0], False
            while isinstance(left, ast.Call) and isinstance(left.func, ast.Name) and left.func.id in SIMPLIFIERS:
                if not left.args:
                    break
                left, form = left.args[0], True
            syms = set()
            try:
                lhs, rhs = strip(tr(left, syms)), strip(tr(right, syms))
            except Skip:
                continue
            if lhs == rhs or (lhs, rhs) in seen:
                continue
            if not identity(lhs, rhs, sorted(syms), rng):
                continue
            seen.add((lhs, rhs))
            rows.append((f"sympy/{rel}:{node.lineno}", ",".join(sorted(syms)), lhs, rhs, "rhs" if form else "-"))
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(f"# SymPy {sp.__version__}: made by tests/sympy_trig/extract.py; do not edit by hand\n")
        f.write("source\tsymbols\tlhs\trhs\tform\n")
        for r in rows:
            f.write("\t".join(r) + "\n")
    print(f"{len(rows)} identities -> {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
