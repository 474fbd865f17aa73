#!/usr/bin/env python3
"""Calls per second of the book's own Python library (modern_robotics), on
the same inputs as benches/lie.rs, to compare with `cargo bench --bench lie`.

    pip install modern_robotics numpy
    python3 benches/book_python.py

Not run in CI (it needs those packages); it only prints figures.
"""
import timeit

import modern_robotics as mr
import numpy as np

v = np.array([0.3, -1.2, 0.7, 1.0, 2.0, -3.0])
se3 = mr.VecTose3(v)
T = mr.MatrixExp6(se3)
so3 = mr.VecToso3(v[:3])
R = T[:3, :3]
N = 20000
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
