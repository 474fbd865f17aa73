#!/usr/bin/env python3
"""The book's own Python library (modern_robotics) next to chasles.

1. Calls per second of single operations, on the same inputs as
   benches/lie.rs, to compare with `cargo bench --bench lie`.
2. Side by side in one run: issue 14's script of N statements (blocks of
   T_ab = exp([S] 0.1), T_bc = exp([S] 0.2), T_ac = T_ab * T_bc,
   X = log(T_ac), V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6), every result printed,
   then the same with every statement silenced by `;`) in Python with
   modern_robotics, and the same script through the chasles binary as a
   whole process; prints both times and the ratio.

    pip install modern_robotics numpy
    cargo build --release
    python3 benches/book_python.py [N] [path/to/chasles]

Not run in CI (it needs those packages); it only prints figures.
"""
import io
import os
import subprocess
import sys
import tempfile
import time
import timeit

N = 20000


def book():
    """The book's library and numpy, imported where they are used: `script(n)`
    needs neither (benches/instructions.sh imports it without them)."""
    import modern_robotics as mr
    import numpy as np

    return mr, np


def single_operations():
    """Calls per second of each core operation (compare `cargo bench --bench lie`)."""
    mr, np = book()
    v = np.array([0.3, -1.2, 0.7, 1.0, 2.0, -3.0])
    se3 = mr.VecTose3(v)
    T = mr.MatrixExp6(se3)
    so3 = mr.VecToso3(v[:3])
    R = T[:3, :3]
    for name, f in [
        ("MatrixExp6", lambda: mr.MatrixExp6(se3)),
        ("MatrixLog6", lambda: mr.MatrixLog6(T)),
        ("MatrixExp3", lambda: mr.MatrixExp3(so3)),
        ("MatrixLog3", lambda: mr.MatrixLog3(R)),
        ("Adjoint", lambda: mr.Adjoint(T)),
        ("TransInv", lambda: mr.TransInv(T)),
    ]:
        best = min(timeit.repeat(f, number=N, repeat=5)) / N
        print(f"{name:12s} {best * 1e6:8.2f} us/call {1 / best:10.0f} calls/s")


LINES = [
    "T_ab = exp([S] 0.1)",
    "T_bc = exp([S] 0.2)",
    "T_ac = T_ab * T_bc",
    "X = log(T_ac)",
    "V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6)",
]


def script(n):
    """The chasles script of n statements (as benches/common/mod.rs)."""
    body = [LINES[i % len(LINES)] for i in range(n - 1)]
    return "S = (0, 0, 1, 0, 2, 0)\n" + "\n".join(body) + "\n"


def silent_script(n):
    """`script(n)` with every statement ended by `;`: the same work, nothing
    printed (LANGUAGE.md §3)."""
    return script(n).replace("\n", ";\n")


def python_script(n, out, show=True):
    """The same n statements with the book's library, printing every result
    (with `show` false, computing the same and printing nothing)."""
    mr, np = book()
    np.set_printoptions(precision=4, suppress=True)
    S = np.array([0.0, 0.0, 1.0, 0.0, 2.0, 0.0])
    say = (lambda *a: print(*a, file=out)) if show else (lambda *a: None)
    say("S =", S)
    T_ab = T_bc = T_ac = None
    for i in range(n - 1):
        k = i % len(LINES)
        if k == 0:
            T_ab = mr.MatrixExp6(mr.VecTose3(S * 0.1))
            say("T_ab =", T_ab)
        elif k == 1:
            T_bc = mr.MatrixExp6(mr.VecTose3(S * 0.2))
            say("T_bc =", T_bc)
        elif k == 2:
            T_ac = T_ab @ T_bc
            say("T_ac =", T_ac)
        elif k == 3:
            say("X =", mr.MatrixLog6(T_ac))
        else:
            say("V_a =", mr.Adjoint(T_ab) @ np.array([1, 2, 3, 4, 5, 6.0]))


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    here = os.path.dirname(os.path.abspath(__file__))
    binary = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "target", "release", "chasles")
    with tempfile.TemporaryDirectory() as d:
        for label, text, show in [
            ("every result printed", script(n), True),
            ("silenced by `;` (nothing printed)", silent_script(n), False),
        ]:
            path = os.path.join(d, "screw.chs")
            with open(path, "w") as f:
                f.write(text)
            t0 = time.perf_counter()
            python_script(n, io.StringIO(), show)
            py = time.perf_counter() - t0
            runs = []
            for _ in range(5):
                t0 = time.perf_counter()
                subprocess.run([binary, "run", path], stdout=subprocess.DEVNULL, check=True)
                runs.append(time.perf_counter() - t0)
            ch = min(runs)
            print(f"script of {n} statements, {label}:")
            print(f"  book's Python library  {py:8.3f} s")
            print(f"  chasles (whole process) {ch:7.3f} s  (best of 5; all: {' '.join(f'{r:.3f}' for r in runs)})")
            print(f"  ratio                  {py / ch:8.1f}x")


if __name__ == "__main__":
    if os.environ.get("SCRIPT_ONLY") is None:
        single_operations()
    main()
