"""Overhead of the Python layer: each workload timed through splinefig and through the C++
library called directly (splinefig_python_overhead, built next to the module, the same inputs),
and the ratio. Goals: kernel (10^6 points) and evaluate (10^5 knots) within 1.5x, resample
(2048^2 RGB float32) within 1.2x.

Each time is the best of REPS calls; the C++ program and the Python calls alternate ROUNDS
times and each keeps its best, so that both see the same load on a shared machine.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/overhead.py [--build build] [--reps 5] [--rounds 3]
"""
import argparse
import os
import subprocess
import sys
import time

import numpy as np

import splinefig


def best_of(reps, f, clock=time.perf_counter):
    """The least time over reps calls of f, by clock (wall time; time.process_time for the CPU
    time of every thread of the process)."""
    best = float("inf")
    for _ in range(reps):
        t0 = clock()
        f()
        best = min(best, clock() - t0)
    return best


def cpp(exe, what, n, reps):
    out = subprocess.run([exe, what, str(n), str(reps)], check=True, capture_output=True, text=True).stdout
    return [tuple(float(v) for v in line.split()) for line in out.splitlines()]


def one_round(exe, reps):
    """[(name, python seconds, C++ seconds, goal)] for every workload."""
    rows = []

    n = 10**6
    x = -2.5 + 5.0 * np.arange(n) / (n - 1)
    k = splinefig.Basis.catmull_rom()
    (c, csum), = cpp(exe, "kernel", n, reps)
    assert np.isclose(splinefig.kernel(k, x).sum(), csum, rtol=1e-12, atol=0), "kernel: not the C++ workload"
    rows.append(("kernel, 1e6 points", best_of(reps, lambda: splinefig.kernel(k, x)), c, 1.5))
    out = np.empty_like(x)  # the C++ loop writes into a buffer allocated once; so does out=
    rows.append(("kernel, 1e6 points, out=", best_of(reps, lambda: splinefig.kernel(k, x, out=out)), c, 1.5))

    n = 10**5
    i = np.arange(n, dtype=np.float64)
    knots = np.stack([np.sin(0.001 * i) * 100.0, np.cos(0.0007 * i) * 50.0 + 0.01 * i], axis=1)
    (c, csum), (c2, csum2) = cpp(exe, "evaluate", n, reps)
    assert np.isclose(splinefig.evaluate(knots, "bspline", grain=16).sum(), csum, rtol=1e-12, atol=0)
    rows.append(("evaluate, 1e5 knots, grain 16", best_of(reps, lambda: splinefig.evaluate(knots, "bspline", grain=16)), c, 1.5))
    buf = np.empty((splinefig.sample_count(knots, "bspline", grain=16), 2))
    py = best_of(reps, lambda: splinefig.evaluate(knots, "bspline", grain=16, out=buf))
    assert np.isclose(buf.sum(), csum2, rtol=1e-12, atol=0)
    rows.append(("evaluate, 1e5 knots, grain 16, out=", py, c2, 1.5))

    n = 2048
    img = (((np.arange(n * n * 3, dtype=np.int64) * 7919) % 1000).astype(np.float32) / np.float32(1000)).reshape(n, n, 3)
    own = splinefig.image_buffer(n, n, 3)  # the same pixels in an array the library holds
    own[...] = img
    for (c, csum), d in zip(cpp(exe, "resample", n, reps), (n // 2, 3 * n // 2)):
        for src, how in ((img, "numpy array (in place)"), (own, "image_buffer (in place)"),
                         (np.asfortranarray(img), "Fortran-order array (copied)")):
            got = splinefig.resample(src, size=(d, d), filter="catmull-rom").astype(np.float64).sum()
            assert np.isclose(got, csum, rtol=1e-9, atol=0)
            py = best_of(reps, lambda: splinefig.resample(src, size=(d, d), filter="catmull-rom"))
            rows.append((f"resample 2048^2 RGB -> {d}^2, {how}", py, c, 1.2))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(os.path.dirname(__file__), "..", "..", "build"))
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args()
    exe = os.path.join(args.build, "python", "splinefig_python_overhead")
    best = None
    for _ in range(args.rounds):
        rows = one_round(exe, args.reps)
        best = rows if best is None else [(n, min(p, bp), min(c, bc), g) for (n, p, c, g), (_, bp, bc, _) in zip(rows, best)]

    print(f"{'workload':52} {'python s':>10} {'C++ s':>10} {'ratio':>7} {'goal':>6}")
    ok = True
    for name, py, c, goal in best:
        r = py / c
        ok = ok and (r <= goal or "copied" in name)
        print(f"{name:52} {py:10.4f} {c:10.4f} {r:7.3f} {goal:6.2f}{'' if r <= goal else '  OVER'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
