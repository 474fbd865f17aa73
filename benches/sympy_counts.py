#!/usr/bin/env python3
"""Issue 21's size aim: sin/cos calls and terms of chasles' printed forward
kinematics against SymPy's `simplify`, entry by entry, for planar nR arms
(n = 2..8, symbolic lengths), the UR5 (benches/ur5.chs) and a 6-joint chain
with tilted axes. Run from the repository root after `cargo build --release`:

    python3 benches/sympy_counts.py [--chasles target/release/chasles] [--timeout 300]

Counts: a sin/cos call is one sin or cos node (sin(t)^2 is one call); terms
are the top-level summands of each entry. Totals over the 12 entries of the
top three rows of T.
"""

import argparse
import json
import re
import signal
import subprocess
import sys
import time

import sympy as sp


def chains():
    """(name, [(w, v)], M) with exact entries (strings SymPy and chasles read alike)."""
    out = []
    for n in range(2, 9):
        axes = []
        for i in range(n):
            reach = " + ".join(f"L{j + 1}" for j in range(i)) or "0"
            axes.append((("0", "0", "1"), ("0", f"-({reach})", "0")))
        total = " + ".join(f"L{j + 1}" for j in range(n))
        m = [["1", "0", "0", total], ["0", "1", "0", "0"], ["0", "0", "1", "0"], ["0", "0", "0", "1"]]
        out.append((f"planar {n}R", axes, m, [f"L{j + 1}" for j in range(n)]))
    w1, w2, l1, l2, h1, h2 = "0.109", "0.082", "0.425", "0.392", "0.089", "0.095"
    ur5 = [
        (("0", "0", "1"), ("0", "0", "0")),
        (("0", "1", "0"), (f"-{h1}", "0", "0")),
        (("0", "1", "0"), (f"-{h1}", "0", l1)),
        (("0", "1", "0"), (f"-{h1}", "0", f"{l1} + {l2}")),
        (("0", "0", "-1"), (f"-{w1}", f"{l1} + {l2}", "0")),
        (("0", "1", "0"), (f"{h2} - {h1}", "0", f"{l1} + {l2}")),
    ]
    m = [["-1", "0", "0", f"{l1} + {l2}"], ["0", "0", "1", f"{w1} + {w2}"],
         ["0", "1", "0", f"{h1} - {h2}"], ["0", "0", "0", "1"]]
    out.append(("UR5", ur5, m, []))
    # tilted unit axes with exact lengths, points q_i on the axes: v = -w x q
    tilted_w = [("1/3", "2/3", "2/3"), ("2/3", "1/3", "-2/3"), ("2/3", "-2/3", "1/3"),
                ("0", "0", "1"), ("1", "0", "0"), ("0", "1", "0")]
    qs = [(0, 0, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (2, 1, 1), (2, 1, 0)]
    tilted = []
    for w, q in zip(tilted_w, qs):
        ws = [sp.Rational(x) for x in w]
        v = [-c for c in sp.Matrix(ws).cross(sp.Matrix(q))]
        tilted.append((w, tuple(str(x) for x in v)))
    m = [["1", "0", "0", "2"], ["0", "1", "0", "1"], ["0", "0", "1", "0"], ["0", "0", "0", "1"]]
    out.append(("tilted 6R", tilted, m, []))
    return out


def sympy_fk(axes, m):
    ts = sp.symbols(f"t1:{len(axes) + 1}", real=True)
    env = {f"L{i}": sp.Symbol(f"L{i}", real=True) for i in range(1, 9)}
    rd = lambda s: sp.nsimplify(sp.sympify(s, locals=env), rational=True)
    t = sp.eye(4)
    for (w, v), th in zip(axes, ts):
        w = sp.Matrix([rd(x) for x in w])
        v = sp.Matrix([rd(x) for x in v])
        k = sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        r = sp.eye(3) + sp.sin(th) * k + (1 - sp.cos(th)) * k * k
        g = sp.eye(3) * th + (1 - sp.cos(th)) * k + (th - sp.sin(th)) * k * k
        e = sp.eye(4)
        e[:3, :3] = r
        e[:3, 3] = g * v
        t = t * e
    return t * sp.Matrix([[rd(x) for x in row] for row in m])


def counts_sympy(e):
    calls = e.count(sp.sin) + e.count(sp.cos)
    terms = len(sp.Add.make_args(e)) if e != 0 else 0
    return calls, terms


def split_top(s, seps):
    out, depth, cur = [], 0, ""
    for ch in s:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if depth == 0 and ch in seps:
            out.append(cur)
            cur = ""
            continue
        cur += ch
    out.append(cur)
    return out


def counts_text(entry):
    calls = len(re.findall(r"\b(sin|cos)\(", entry))
    e = entry.strip()
    if e == "0":
        return calls, 0
    # terms: top-level " + " / " - " separators
    pieces = split_top(e.replace(" + ", "\x01").replace(" - ", "\x01"), "\x01")
    return calls, len([p for p in pieces if p.strip()])


def chasles_fk(binary, name, axes, m, lengths):
    n = len(axes)
    lines = [f"given {', '.join(f't{i + 1}' for i in range(n))} : scalar"]
    if lengths:
        lines.append(f"given {', '.join(lengths)} : scalar")
    for i, (w, v) in enumerate(axes):
        lines.append(f"S{i + 1} = ({', '.join('(' + x + ')' for x in w + v)})")
    lines.append("M = [" + "; ".join(", ".join("(" + x + ")" for x in row) for row in m) + "]")
    lines.append("T = " + " ".join(f"exp([S{i + 1}] t{i + 1})" for i in range(n)) + " M")
    src = "\n".join(lines)
    start = time.time()
    out = subprocess.run([binary, "--json", "-e", src], capture_output=True, text=True)
    dt = time.time() - start
    last = [json.loads(l) for l in out.stdout.splitlines() if l.strip()][-1]
    if "error" in last:
        return None, dt, last["error"]["message"]
    rows = split_top(last["value"].strip()[1:-1], ";")
    entries = [split_top(r, ",") for r in rows[:3]]
    return [[counts_text(e) for e in row] for row in entries], dt, None


class Timeout(Exception):
    pass


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--chasles", default="target/release/chasles")
    ap.add_argument("--timeout", type=int, default=300)
    args = ap.parse_args()
    signal.signal(signal.SIGALRM, lambda *_: (_ for _ in ()).throw(Timeout()))
    print("| chain | chasles sin/cos calls | SymPy | chasles terms | SymPy | chasles time | SymPy simplify |")
    print("|---|---|---|---|---|---|---|")
    for name, axes, m, lengths in chains():
        ours, dt, err = chasles_fk(args.chasles, name, axes, m, lengths)
        if ours is None:
            c_calls, c_terms = f"refused: {err}", "—"
        else:
            c_calls = sum(c for row in ours for c, _ in row)
            c_terms = sum(t for row in ours for _, t in row)
        start = time.time()
        signal.alarm(args.timeout)
        try:
            t = sympy_fk(axes, m)
            s_calls = s_terms = 0
            for i in range(3):
                for j in range(4):
                    e = sp.simplify(t[i, j])
                    c, k = counts_sympy(e)
                    s_calls += c
                    s_terms += k
            sdt = f"{time.time() - start:.1f} s"
        except Timeout:
            s_calls = s_terms = "—"
            sdt = f"> {args.timeout} s"
        signal.alarm(0)
        print(f"| {name} | {c_calls} | {s_calls} | {c_terms} | {s_terms} | {dt * 1000:.0f} ms | {sdt} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
