"""savefig to PNG of an image resampled by a kernel: matplotlib's own (AGG's bicubic filter,
through the AGG canvas and through splinefig's backend without a kernel) against splinefig's
resampler (interpolation="none" with kernel="catmull-rom"), in one process, for an image that
fills an axes (axis-aligned: the library's separable passes), a reduced one, and one turned by
30 degrees (the direct sums of the backend, in numpy).

Each time is the best of REPS saves, the three ways alternating ROUNDS times (overhead.py's
rule), wall-clock and the CPU time of the process (all its threads).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/matplotlib_kernel.py [--reps 3] [--rounds 2]
"""
import argparse
import io
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.transforms import Affine2D  # noqa: E402

from overhead import best_of  # noqa: E402

BACKEND = "module://splinefig.matplotlib"


def figure(shape, turn=0.0):
    def make(interpolation):
        fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
        im = ax.imshow(np.random.default_rng(1).uniform(size=shape), cmap="viridis", interpolation=interpolation)
        if turn:
            h, w = shape
            im.set_transform(Affine2D().rotate_deg_around(w / 2, h / 2, turn) + ax.transData)
        return fig
    make.__name__ = f"imshow {shape[1]}x{shape[0]}" + (f", turned {turn:g} degrees" if turn else "")
    return make


FIGURES = [figure((40, 60)), figure((200, 300)), figure((1200, 1800)), figure((200, 300), turn=30)]


def save(fig, backend, **kw):
    fig.savefig(io.BytesIO(), format="png", backend=backend, **kw)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--rounds", type=int, default=2)
    a = ap.parse_args()
    print(f"load average at start: {os.getloadavg()[0]:.2f}")
    print("| figure | AGG bicubic (s) | splinefig, matplotlib's bicubic (s) | splinefig, catmull-rom kernel (s) "
          "| AGG CPU (s) | bicubic CPU (s) | kernel CPU (s) |")
    print("|---|---|---|---|---|---|---|")
    for make in FIGURES:
        bicubic, none = make("bicubic"), make("none")
        ways = [lambda: save(bicubic, None), lambda: save(bicubic, BACKEND),
                lambda: save(none, BACKEND, kernel="catmull-rom")]
        for w in ways:
            w()  # warm: fonts, caches, the module
        wall = [float("inf")] * 3
        cpu = [float("inf")] * 3
        for _ in range(a.rounds):
            for i, w in enumerate(ways):
                wall[i] = min(wall[i], best_of(a.reps, w))
                cpu[i] = min(cpu[i], best_of(a.reps, w, clock=time.process_time))
        plt.close(bicubic)
        plt.close(none)
        print(f"| {make.__name__} | " + " | ".join(f"{t:.4f}" for t in wall + cpu) + " |")
    print(f"load average at end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
