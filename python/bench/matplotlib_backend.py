"""savefig to PNG through matplotlib's AGG and through splinefig's backend, the same figures in
one process: line plots of 10^3, 10^5 and 10^6 points, scatters of 10^4 markers (one colour,
which matplotlib draws with draw_markers, and a colour per point, drawn path by path),
fill_between, imshow, a text- and mathtext-heavy figure, and a figure with a clip path and
hatches. Goals: splinefig at least as fast as AGG on each, and at least 1.5x on the 10^6-point
line plot.

Each time is the best of REPS saves; the two backends alternate ROUNDS times and each keeps its
best, so that both see the same load on a shared machine. Two times are kept: wall-clock, and
the CPU time of the process (all its threads), which a loaded machine disturbs less. Threads:
all cores (the backend's default, splinefig.matplotlib.THREADS = 0), or --threads N.

    PYTHONPATH=build/python /usr/bin/python3 python/bench/matplotlib_backend.py [--reps 3] [--rounds 2] [--threads N]
"""
import argparse
import io
import os
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from overhead import best_of  # noqa: E402  (the timing rule of the benches beside this one)

BACKEND = "module://splinefig.matplotlib"


def line(n):
    def make():
        fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
        x = np.linspace(0, 10, n)
        ax.plot(x, np.sin(x) + 0.1 * np.random.default_rng(0).normal(size=n), lw=1)
        return fig
    make.__name__ = f"line, {n:.0e} points"
    return make


def scatter_one_colour():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    rng = np.random.default_rng(1)
    ax.scatter(rng.normal(size=10000), rng.normal(size=10000), s=10)
    return fig


def scatter_colours():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    rng = np.random.default_rng(1)
    ax.scatter(rng.normal(size=10000), rng.normal(size=10000), c=rng.uniform(size=10000), s=10, alpha=0.5)
    return fig


def fill_between():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 10, 500)
    ax.fill_between(x, np.sin(x), np.sin(x) + 1, alpha=0.4)
    ax.fill_between(x, np.cos(x) - 1, np.cos(x), color="C2", alpha=0.6)
    return fig


def imshow():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    ax.imshow(np.random.default_rng(1).uniform(size=(200, 300)), cmap="viridis")
    return fig


def text_and_mathtext():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    ax.set_title(r"Title with $\alpha^2 + \sum_{i=0}^{n} \frac{x_i}{2}$")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(r"$\sqrt{\beta}$ (m)")
    for k in range(8):
        ax.text(0.05, 0.1 + 0.1 * k, f"Label {k}: the quick brown fox, $x_{k}^2$", fontsize=9)
    return fig


def clip_and_hatch():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 10, 400)
    line, = ax.plot(x, np.cos(x), lw=4, color="C3")
    circle = matplotlib.patches.Circle((5, 0), 1.5, transform=ax.transData, facecolor="none")
    ax.add_patch(circle)
    line.set_clip_path(circle)
    ax.bar([1, 2, 3, 4], [0.5, 0.8, 0.3, 0.9], hatch="//", fill=False)
    return fig


FIGURES = [line(1000), line(100000), line(1000000), scatter_one_colour, scatter_colours, fill_between, imshow,
           text_and_mathtext, clip_and_hatch]


def save(fig, backend):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", backend=backend)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--threads", type=int, default=None)
    a = ap.parse_args()
    if a.threads is not None:
        import splinefig.matplotlib
        splinefig.matplotlib.THREADS = a.threads
    print(f"load average at start: {os.getloadavg()[0]:.2f}")
    print("| figure | AGG (s) | splinefig (s) | AGG / splinefig | AGG CPU (s) | splinefig CPU (s) | CPU ratio | goal |")
    print("|---|---|---|---|---|---|---|---|")
    for make in FIGURES:
        fig = make()
        save(fig, None)  # warm both: fonts, caches, the module
        save(fig, BACKEND)
        agg = ours = agg_cpu = ours_cpu = float("inf")
        for _ in range(a.rounds):
            agg = min(agg, best_of(a.reps, lambda: save(fig, None)))
            ours = min(ours, best_of(a.reps, lambda: save(fig, BACKEND)))
            agg_cpu = min(agg_cpu, best_of(a.reps, lambda: save(fig, None), clock=time.process_time))
            ours_cpu = min(ours_cpu, best_of(a.reps, lambda: save(fig, BACKEND), clock=time.process_time))
        plt.close(fig)
        goal = 1.5 if "1e+06" in make.__name__ else 1.0
        mark = "" if agg / ours >= goal else " *"
        print(f"| {make.__name__} | {agg:.4f} | {ours:.4f} | {agg / ours:.2f}x{mark} | {agg_cpu:.4f} | {ours_cpu:.4f} | "
              f"{agg_cpu / ours_cpu:.2f}x | {goal}x |")
    print(f"load average at end: {os.getloadavg()[0]:.2f}   (* below the goal)")


if __name__ == "__main__":
    main()
