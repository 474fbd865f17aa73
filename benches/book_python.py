#!/usr/bin/env python3
"""The book's own Python library (modern_robotics) next to chasles.

1. Calls per second of single operations, on the same inputs as
   benches/lie.rs, to compare with `cargo bench --bench lie`.
2. Side by side in one run: issue 14's script of N statements (blocks of
   T_ab = exp([S] 0.1), T_bc = exp([S] 0.2), T_ac = T_ab * T_bc,
   X = log(T_ac), V_a = Ad(T_ab) * (1, 2, 3, 4, 5, 6), every result printed)
   in Python with modern_robotics, and the same script through the chasles
   binary as a whole process; prints both times and the ratio.

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


def python_script(n, out):
    """The same n statements with the book's library, printing every result."""
    mr, np = book()
    np.set_printoptions(precision=4, suppress=True)
    S = np.array([0.0, 0.0, 1.0, 0.0, 2.0, 0.0])
    print("S =", S, file=out)
    T_ab = T_bc = T_ac = None
    for i in range(n - 1):
        k = i % len(LINES)
        if k == 0:
            T_ab = mr.MatrixExp6(mr.VecTose3(S * 0.1))
            print("T_ab =", T_ab, file=out)
        elif k == 1:
            T_bc = mr.MatrixExp6(mr.VecTose3(S * 0.2))
            print("T_bc =", T_bc, file=out)
        elif k == 2:
            T_ac = T_ab @ T_bc
            print("T_ac =", T_ac, file=out)
        elif k == 3:
            print("X =", mr.MatrixLog6(T_ac), file=out)
        else:
            print("V_a =", mr.Adjoint(T_ab) @ np.array([1, 2, 3, 4, 5, 6.0]), file=out)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    here = os.path.dirname(os.path.abspath(__file__))
    binary = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "target", "release", "chasles")
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "screw.chs")
        with open(path, "w") as f:
            f.write(script(n))
        t0 = time.perf_counter()
        python_script(n, io.StringIO())
        py = time.perf_counter() - t0
        runs = []
        for _ in range(3):
            t0 = time.perf_counter()
            subprocess.run([binary, "run", path], stdout=subprocess.DEVNULL, check=True)
            runs.append(time.perf_counter() - t0)
        ch = min(runs)
    print(f"script of {n} statements, every result printed:")
    print(f"  book's Python library  {py:8.3f} s")
    print(f"  chasles (whole process) {ch:7.3f} s")
    print(f"  ratio                  {py / ch:8.1f}x")


if __name__ == "__main__":
    single_operations()
    main()
