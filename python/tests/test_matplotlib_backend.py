"""The matplotlib backend (splinefig.matplotlib) against AGG, against hand-computed coverage,
and for the same bytes whatever the thread count or FreeType's hinting settings.

AGG is the independent oracle: the same figure drawn by both must agree everywhere but at the
edges AGG approximates (its coverage and its hinted text); an exact rectangle checks the
splinefig side by hand."""
import io

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from PIL import Image  # noqa: E402
from polygon_area import area, clip_convex  # noqa: E402

ndimage = pytest.importorskip("scipy.ndimage")

BACKEND = "module://splinefig.matplotlib"


def png(fig, backend=None, **kw):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", backend=backend, **kw)
    buf.seek(0)
    return np.asarray(Image.open(buf).convert("RGBA")).astype(np.int32)


def line_plot():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 10, 1000)
    ax.plot(x, np.sin(x), label="sin")
    ax.plot(x, np.cos(x), "--", lw=2, label="cos")
    ax.legend()
    return fig


def scatter():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    rng = np.random.default_rng(0)
    ax.scatter(rng.normal(size=2000), rng.normal(size=2000), c=rng.uniform(size=2000), s=12, alpha=0.5)
    return fig


def markers():
    # One colour and size: matplotlib draws these through draw_markers, at whole pixels.
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    rng = np.random.default_rng(2)
    ax.scatter(rng.uniform(size=1500), rng.uniform(size=1500), s=20)
    ax.plot(rng.uniform(size=40), rng.uniform(size=40), "s", ms=6, mfc="C1", mec="k", mew=1.5, alpha=0.7)
    ax.plot(np.linspace(0, 1, 30), rng.uniform(size=30), "D--", ms=5)
    return fig


def fill_between():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 10, 500)
    ax.fill_between(x, np.sin(x), np.sin(x) + 1, alpha=0.4)
    ax.fill_between(x, np.cos(x) - 1, np.cos(x), color="C2", alpha=0.6)
    return fig


def imshow():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    ax.imshow(np.random.default_rng(1).uniform(size=(20, 30)), cmap="viridis")
    return fig


def text_and_mathtext():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    ax.set_title(r"Title with $\alpha^2 + \sum_{i=0}^{n} \frac{x_i}{2}$")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(r"$\sqrt{\beta}$ (m)")
    ax.text(0.1, 0.5, "Some text, rotated", rotation=30, fontsize=14)
    ax.text(0.5, 0.2, r"$\int_0^\infty e^{-x^2}\,dx = \frac{\sqrt{\pi}}{2}$", fontsize=16)
    return fig


def clipped_path():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(-5, 15, 400)
    ax.plot(x, 3 * np.sin(x), lw=3)  # runs past the axes: clipped by the clip box
    ax.set_xlim(0, 10)
    ax.set_ylim(-2, 2)
    line, = ax.plot(x, np.cos(x), lw=4, color="C3")
    circle = mpl.patches.Circle((5, 0), 1.5, transform=ax.transData, facecolor="none")
    ax.add_patch(circle)
    line.set_clip_path(circle)
    return fig


def scatter_1e4():
    # 10^4 markers of one colour: draw_markers, one picture composited at whole pixels.
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    rng = np.random.default_rng(1)
    ax.scatter(rng.normal(size=10000), rng.normal(size=10000), s=10)
    return fig


def clip_and_hatch():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 10, 400)
    line, = ax.plot(x, np.cos(x), lw=4, color="C3")
    circle = mpl.patches.Circle((5, 0), 1.5, transform=ax.transData, facecolor="none")
    ax.add_patch(circle)
    line.set_clip_path(circle)
    ax.bar([1, 2, 3, 4], [0.5, 0.8, 0.3, 0.9], hatch="//", fill=False)
    ax.bar([6, 7], [0.6, 0.4], hatch="x", color="C2", alpha=0.5)
    return fig


def gouraud():
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 1, 8)
    X, Y = np.meshgrid(x, x)
    ax.pcolormesh(X, Y, np.sin(3 * X) * Y, shading="gouraud")
    return fig


# (figure, largest mean |difference| in 8-bit levels over all pixels and channels, how far from
# an edge of AGG's picture a large difference may be: 3 px for text, whose hinted metrics move
# AGG's mathtext rules and glyphs by up to that much)
FIGURES = [(line_plot, 1.0, 2), (scatter, 0.7, 2), (markers, 1.0, 2), (fill_between, 1.0, 2), (imshow, 0.7, 2),
           (text_and_mathtext, 2.5, 3), (clipped_path, 0.7, 2), (scatter_1e4, 0.7, 2), (clip_and_hatch, 1.0, 2),
           (gouraud, 1.0, 2)]


def edges(img, radius=2):
    """Pixels within `radius` of a place where AGG's picture changes in any channel (an edge of
    anything, also of an orange mark on white, whose red channel does not change)."""
    size = 3
    local = np.max([ndimage.maximum_filter(img[:, :, c], size) - ndimage.minimum_filter(img[:, :, c], size)
                    for c in range(3)], axis=0)
    return ndimage.binary_dilation(local > 8, iterations=radius)


@pytest.mark.parametrize("make, mean_limit, radius", FIGURES, ids=[f[0].__name__ for f in FIGURES])
def test_agrees_with_agg(make, mean_limit, radius):
    fig = make()
    agg = png(fig)
    ours = png(fig, BACKEND)
    plt.close(fig)
    assert agg.shape == ours.shape
    d = np.abs(agg - ours)
    mean, big = d.mean(), d.max(axis=2) > 48
    away = big & ~edges(agg, radius)
    print(f"{make.__name__}: mean {mean:.3f} max {d.max()} large {big.sum()} px, away from AGG's edges {away.sum()}")
    assert mean < mean_limit
    # Every large difference is at an edge of AGG's picture, where its coverage (or its hinted
    # glyph) is approximate; the flat areas agree.
    assert away.sum() == 0, np.argwhere(away)[:10]


def test_dense_line_differs_from_agg_only_where_agg_closes_gaps(monkeypatch):
    """A noisy line of 10^5 points (a dense, self-crossing stroke): the large differences away
    from AGG's edges are pixels where the exact union of the stroke's pieces leaves a gap inside
    the band, which AGG, filling its outline by the nonzero rule, closes. Each such pixel's
    coverage is checked against the independent definition of a round-joined stroke: the points
    within half the width of the polyline, sampled 32 x 32 in the pixel."""
    import splinefig.matplotlib as backend

    strokes = []
    emit = backend.RendererSplinefig._emit

    def recording(self, t, path, fill, stroke, rule="nonzero"):
        if stroke is not None and len(path.vertices) > 5000:
            strokes.append((np.array(path.vertices) + (t.x0, t.y0), stroke["width"], stroke["join"]))
        emit(self, t, path, fill, stroke, rule)

    monkeypatch.setattr(backend.RendererSplinefig, "_emit", recording)
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    x = np.linspace(0, 10, 100000)
    ax.plot(x, np.sin(x) + 0.1 * np.random.default_rng(0).normal(size=x.size), lw=1, color="k")
    agg = png(fig)
    ours = png(fig, BACKEND)
    plt.close(fig)
    (v, _, join), = strokes  # the line's vertices in pixels, as matplotlib prepares them for AGG too
    assert join == "round"
    width = 1 * 100 / 72  # lw = 1 point at 100 dpi
    d = np.abs(agg - ours)
    mean, big = d.mean(), d.max(axis=2) > 48
    away = np.argwhere(big & ~edges(agg, 3))
    print(f"dense line: mean {mean:.3f}, large {big.sum()} px, away from AGG's edges {len(away)}")
    assert mean < 1.5
    assert 1 <= len(away) < 20  # the gaps exist (seeded data), so the check below is not empty
    a, b = v[:-1], v[1:]
    n = 32
    for row, col in away:
        near = ((np.minimum(a[:, 0], b[:, 0]) < col + 1 + width) & (np.maximum(a[:, 0], b[:, 0]) > col - width)
                & (np.minimum(a[:, 1], b[:, 1]) < row + 1 + width) & (np.maximum(a[:, 1], b[:, 1]) > row - width))
        sa, sb = a[near], b[near]
        ab = sb - sa
        inside = 0
        for i in range(n):
            for j in range(n):
                p = np.array([col + (i + 0.5) / n, row + (j + 0.5) / n])
                t = np.clip(((p - sa) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-300), 0, 1)
                inside += np.sqrt(((p - sa - t[:, None] * ab) ** 2).sum(1)).min() <= width / 2
        want = inside / n**2
        assert agg[row, col, 0] < 8 and want < 0.9  # AGG covers it, the stroke does not
        assert abs((255 - ours[row, col, 0]) / 255 - want) < 0.03, (row, col, want, ours[row, col, 0])


@pytest.mark.parametrize("marker", ["o", "h", "s", "^", "+"])
@pytest.mark.parametrize("frac", [0.2, 0.5, 0.7])
def test_markers_go_where_agg_puts_them(marker, frac):
    """A marker at a position with fractional part `frac` has its ink centred where AGG centres
    it: AGG rounds the position to the nearest pixel and, for a marker it does not snap to the
    grid (circles, hexagons), puts the marker's origin at that pixel's centre."""
    centres = {}
    for backend in (None, BACKEND):
        fig = plt.figure(figsize=(1, 1), dpi=100)
        ax = fig.add_axes([0, 0, 1, 1])
        ax.set_xlim(0, 100)
        ax.set_ylim(0, 100)
        ax.axis("off")
        ax.plot([50 + frac], [50 + frac], marker, ms=10, mew=1, color="k")
        ink = 255.0 - png(fig, backend)[:, :, 0]
        plt.close(fig)
        ys, xs = np.indices(ink.shape)
        centres[backend] = ((ink * xs).sum() / ink.sum(), (ink * ys).sum() / ink.sum())
    assert np.allclose(centres[BACKEND], centres[None], atol=0.05), centres


def test_exact_rectangle_by_hand():
    # A black rectangle from x = 10.25 to 50.75 and y = 20.5 to 70 (pixels from the top-left),
    # unsnapped, on white: a pixel's value is 255 * (1 - covered area), by hand.
    fig = plt.figure(figsize=(1, 1), dpi=100)
    rect = mpl.patches.Rectangle((10.25, 100 - 70), 40.5, 49.5, transform=None, facecolor="black", edgecolor="none",
                                 snap=False)
    fig.add_artist(rect)
    im = png(fig, BACKEND)
    plt.close(fig)
    assert im[40, 10, 0] == 64    # left column: 3/4 covered
    assert im[40, 50, 0] == 64    # right column: 3/4 covered
    assert im[20, 30, 0] == 128   # top row: 1/2 covered (127.5 rounds to 128)
    assert im[20, 10, 0] == 159   # corner: 3/8 covered, 255 * 5/8 = 159.4
    assert im[40, 30, 0] == 0 and im[70, 30, 0] == 255 and im[40, 9, 0] == 255 and im[40, 51, 0] == 255


def test_linear_blend_option():
    # Half-covered black over white: sRGB blending gives 255 / 2, linear light the sRGB code
    # of 0.5 (188), by the sRGB curve.
    fig = plt.figure(figsize=(1, 1), dpi=100)
    fig.add_artist(mpl.patches.Rectangle((10.5, 10), 40, 40, transform=None, facecolor="black", edgecolor="none", snap=False))
    srgb = png(fig, BACKEND)
    linear = png(fig, BACKEND, blend="linear")
    plt.close(fig)
    assert srgb[70, 10, 0] == 128
    assert linear[70, 10, 0] == round(255 * (1.055 * 0.5 ** (1 / 2.4) - 0.055))


def busy():
    fig, axes = plt.subplots(1, 2, figsize=(6, 3), dpi=100)
    rng = np.random.default_rng(2)
    axes[0].scatter(rng.normal(size=500), rng.normal(size=500), alpha=0.3)
    axes[0].set_title(r"$\alpha_i^2$ and text")
    axes[1].plot(np.cumsum(rng.normal(size=3000)), lw=0.7)
    axes[1].fill_between(np.arange(100), 0, 20, hatch="//", alpha=0.3)
    return fig


def test_same_bytes_for_1_to_4_threads():
    # The PNG files themselves, byte for byte, for every thread count from 1 to 4 and for the
    # default (all cores), in both blend spaces.
    fig = busy()
    for blend in ("srgb", "linear"):
        files = set()
        for threads in (1, 2, 3, 4, 0):
            buf = io.BytesIO()
            fig.savefig(buf, format="png", backend=BACKEND, threads=threads, blend=blend)
            files.add(buf.getvalue())
        assert len(files) == 1, blend
    plt.close(fig)


def test_same_bytes_for_any_hinting():
    # AGG's text changes with FreeType's hinting; the glyph outlines drawn here do not.
    outs, aggs = [], []
    for hinting, factor in (("force_autohint", 8), ("no_hinting", 1), ("native", 8)):
        with mpl.rc_context({"text.hinting": hinting, "text.hinting_factor": factor}):
            fig = text_and_mathtext()
            outs.append(png(fig, BACKEND).tobytes())
            aggs.append(png(fig).tobytes())
            plt.close(fig)
    assert len(set(aggs)) > 1  # the settings do change AGG's picture
    assert len(set(outs)) == 1


def test_buffer_rgba_and_transparent():
    from splinefig.matplotlib import FigureCanvasSplinefig

    fig = mpl.figure.Figure(figsize=(2, 1), dpi=50)
    canvas = FigureCanvasSplinefig(fig)
    canvas.draw()
    buf = np.asarray(canvas.buffer_rgba())
    assert buf.shape == (50, 100, 4) and buf.dtype == np.uint8 and (buf == 255).all()  # white facecolor
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], lw=8)
    t = png(fig, BACKEND, transparent=True)
    assert (t[:, :, 3] == 0).any() and (t[:, :, 3] == 255).any()
    tight = png(fig, BACKEND, bbox_inches="tight", dpi=100)
    ref = png(fig, bbox_inches="tight", dpi=100)
    assert tight.shape == ref.shape


def test_scene_paths_by_hand():
    import splinefig

    # The rasterizer flattens curves within 1e-4 px, so an area may be short by up to 1e-4 px
    # times the curve's length (under 40 px here): 4e-3.
    # A parabolic segment: the quadratic from (2, 10) with control (10, -6) to (18, 10), closed by
    # its chord, has 2/3 of the area of the triangle of its three points (Archimedes): 2/3 * 128.
    s = splinefig.Scene(24, 16, background=(0, 0, 0, 0))
    s.fill_path([(2, 10), (10, -6), (18, 10), (0, 0)], [1, 3, 3, 79], color=(1, 1, 1, 1))
    assert abs(float(s.render()[:, :, 3].sum()) - 2 / 3 * 128) < 4e-3
    # A cubic (0,0) (0,h) (L,h) (L,0) closed by its chord: y = 3h t(1-t), x = L(3t^2 - 2t^3), so
    # the area is the integral of y dx = 18 h L * integral of t^2 (1-t)^2 dt = 18/30 h L = 0.6 h L.
    s = splinefig.Scene(24, 16, background=(0, 0, 0, 0), blend="srgb")
    s.fill_path([(2, 14), (2, 2), (22, 2), (22, 14), (0, 0)], [1, 4, 4, 4, 79], color=(1, 1, 1, 1))
    assert abs(float(s.render()[:, :, 3].sum()) - 0.6 * 20 * 12) < 4e-3
    with pytest.raises(ValueError, match="codes: unknown path code 5 at vertex 1"):
        splinefig.Scene(8, 8).fill_path([(0, 0), (1, 1)], [1, 5])
    with pytest.raises(ValueError, match="runs past the last vertex"):
        splinefig.Scene(8, 8).stroke_path([(0, 0), (1, 1), (2, 2)], [1, 4, 4])
    with pytest.raises(ValueError, match="blend: unknown value 'gamma'"):
        splinefig.Scene(8, 8, blend="gamma")


def test_clip_path_is_exact():
    # A triangle clipped by another (a clip path, not a box): each pixel's alpha is the area of
    # the two triangles' intersection in it, found here by Sutherland-Hodgman. Multiplying the
    # triangle's coverage by the clip's (the pixel-mask way) is off where both edges cross a pixel.
    W, H = 40, 30
    shape = [(3.3, 2.1), (37.2, 6.4), (12.6, 27.7)]   # pixels, y up (matplotlib's display space)
    clip = [(8.7, 1.2), (35.9, 14.3), (4.1, 25.6)]
    fig = plt.figure(figsize=(W / 100, H / 100), dpi=100)
    tri = mpl.patches.Polygon(shape, closed=True, transform=None, facecolor="black", edgecolor="none", snap=False)
    cut = mpl.patches.Polygon(clip, closed=True, transform=None)
    fig.add_artist(tri)
    tri.set_clip_path(cut)
    im = png(fig, BACKEND, transparent=True)
    plt.close(fig)
    inter = clip_convex(shape, clip)
    worst = 0.0
    for row in range(H):
        for col in range(W):
            y0 = H - row - 1  # the pixel's bottom in display space
            square = [(col, y0), (col + 1, y0), (col + 1, y0 + 1), (col, y0 + 1)]
            part = clip_convex(inter, square)
            want = area(part) if len(part) >= 3 else 0.0
            worst = max(worst, abs(im[row, col, 3] / 255 - want))
    assert worst <= 0.5 / 255 + 1e-9


PYTEST_MPL_TEST = '''
import matplotlib.pyplot as plt
import pytest


@pytest.mark.mpl_image_compare(backend="module://splinefig.matplotlib", tolerance=0)
def test_plot():
    fig, ax = plt.subplots(figsize=(3, 2), dpi=100)
    ax.plot([1, 3, 2], color="COLOUR", label="data")
    ax.set_title(r"$\\alpha^2$ text")
    ax.legend()
    return fig
'''


def test_pytest_mpl_workflow(tmp_path):
    """docs/matplotlib.md's pytest-mpl workflow, run as a project would: the baseline is written
    through the backend once, a run compares with it at tolerance 0 and passes (so the backend
    gives the same bytes on a second draw in another process), and the same test drawing a
    different colour fails."""
    pytest.importorskip("pytest_mpl")
    import os
    import subprocess
    import sys

    import splinefig

    # The package this test imports, also for the runs in tmp_path (a relative PYTHONPATH would
    # not reach it from there).
    here = os.path.dirname(os.path.dirname(os.path.abspath(splinefig.__file__)))
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join(filter(None, [here, os.environ.get("PYTHONPATH")])))

    def run(colour, *args):
        (tmp_path / "test_plot.py").write_text(PYTEST_MPL_TEST.replace("COLOUR", colour))
        return subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *args, "test_plot.py"],
                              cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)

    r = run("C0", "--mpl-generate-path=baseline")
    assert r.returncode == 0, r.stdout + r.stderr
    baseline = tmp_path / "baseline" / "test_plot.png"
    assert baseline.is_file()
    ours = np.asarray(Image.open(baseline).convert("RGBA"))
    assert ours.shape[:2] == (200, 300)
    assert len(np.unique(ours.reshape(-1, 4), axis=0)) > 10  # a drawn figure, not a blank one
    # The baseline is the backend's picture (drawn here again, in this process, in the style
    # pytest-mpl applies by default), not AGG's.
    with plt.style.context("classic"):
        fig, ax = plt.subplots(figsize=(3, 2), dpi=100)
        ax.plot([1, 3, 2], color="C0", label="data")
        ax.set_title(r"$\alpha^2$ text")
        ax.legend()
        assert np.array_equal(png(fig, BACKEND), ours.astype(np.int32))
        assert not np.array_equal(png(fig), ours.astype(np.int32))
        plt.close(fig)
    r = run("C0", "--mpl", "--mpl-baseline-path=baseline")
    assert r.returncode == 0, r.stdout + r.stderr
    r = run("C3", "--mpl", "--mpl-baseline-path=baseline")
    assert r.returncode != 0 and "Error: Image files did not match" in r.stdout, r.stdout + r.stderr


def test_hatch_under_a_clip_path():
    # A hatched square clipped by a circle: nothing outside the circle, and inside it (a pixel
    # away from its edge) the same pixels as the square drawn without the clip.
    def draw(clipped):
        fig = plt.figure(figsize=(2, 2), dpi=100)
        ax = fig.add_axes([0, 0, 1, 1])
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.axis("off")
        square = mpl.patches.Rectangle((0.1, 0.1), 0.8, 0.8, hatch="//", facecolor="none", edgecolor="C0", lw=2)
        ax.add_patch(square)
        if clipped:
            square.set_clip_path(mpl.patches.Circle((0.5, 0.5), 0.3, transform=ax.transData))
        im = png(fig, BACKEND, transparent=True)
        plt.close(fig)
        return im
    clipped, whole = draw(True), draw(False)
    ys, xs = np.indices(clipped.shape[:2]) + 0.5
    r = np.hypot(xs - 100, ys - 100)  # the circle: centre (100, 100) px, radius 60 px
    assert (clipped[r > 61, 3] == 0).all()
    inside = r < 59
    assert (whole[inside, 3] > 0).sum() > 1000  # hatch lines cross the circle
    assert np.array_equal(clipped[inside], whole[inside])


def test_hatch_lines_by_hand():
    # A 200 x 200 px canvas hatched "/" (matplotlib's density 6: in each one-inch tile, lines
    # x - y = k for k in -1, -2/3, ..., 1 in tile units, y up), black, width hatch.linewidth
    # (1 pt), on nothing: the alpha summed over the canvas is the area of the lines' strips within
    # their tiles, each strip clipped to its tile by Sutherland-Hodgman (the strips do not
    # overlap). Lines drawn past their tile, over the next tile's, would add their antialiased
    # edges twice.
    size, w = 100, 100 / 72
    fig = plt.figure(figsize=(2, 2), dpi=100)
    fig.add_artist(mpl.patches.Rectangle((0, 0), 200, 200, transform=None, facecolor="none", edgecolor="black", lw=0,
                                         hatch="/", snap=False))
    im = png(fig, BACKEND, transparent=True)
    plt.close(fig)
    want = 0.0
    for tx in range(2):
        for ty in range(2):
            tile = [(tx * size, ty * size), (tx * size + size, ty * size), (tx * size + size, ty * size + size),
                    (tx * size, ty * size + size)]
            for k in np.linspace(-1, 1, 7):
                # The line through (t, t - k) tile units (y up), in canvas pixels (y down): a long
                # thin rectangle along the direction (1, -1).
                cx, cy = tx * size + size * 0.5, ty * size + size * (1 - (0.5 - k))
                d = np.array([1, -1]) / np.sqrt(2) * 2 * size
                nrm = np.array([1, 1]) / np.sqrt(2) * (w / 2)
                c = np.array([cx, cy])
                strip = [tuple(c - d - nrm), tuple(c + d - nrm), tuple(c + d + nrm), tuple(c - d + nrm)]
                part = clip_convex(strip, tile[::-1] if _area_signed(tile) < 0 else tile)
                want += area(part) if len(part) >= 3 else 0.0
    got = im[:, :, 3].sum() / 255
    print("hatch", got, want)
    assert abs(got - want) < 1e-3 * want + 2, (got, want)


def _area_signed(poly):
    return 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(poly, poly[1:] + poly[:1]))


def collections():
    fig, ax = plt.subplots(figsize=(4, 3), dpi=100)
    rng = np.random.default_rng(3)
    n = 300
    x, y = rng.normal(size=n), rng.normal(size=n)
    x[7] = np.nan  # a non-finite offset is skipped
    face = rng.uniform(size=(n, 4))
    face[::5, 3] = 0  # transparent faces: no fill
    edge = rng.uniform(size=(n, 4))
    edge[::7, 3] = 0  # transparent edges: no stroke
    ax.scatter(x, y, s=rng.uniform(5, 80, size=n), c=face, edgecolors=edge, linewidths=rng.uniform(0, 2, size=n),
               linestyle=":")
    ax.scatter(x + 1, y, s=30, c=rng.uniform(size=n), alpha=0.4, linestyle="--", linewidths=1.5, edgecolors="k")
    ax.scatter(x - 1, y, marker="s", s=20, c=rng.uniform(size=n))  # squares: snapped, item by item
    ax.fill_between(np.arange(10) * 0.3, 0, 1, color="C3", alpha=0.5, hatch="/")
    return fig


def test_path_collections_as_matplotlibs_loop(monkeypatch):
    # draw_path_collection (a path prepared once and moved, or all items in one call) gives the
    # bytes of RendererBase's own loop over draw_path with its graphics context per item:
    # per-item sizes, colours, transparent faces and edges, widths, forced alpha, dashes, a NaN
    # offset, snapped squares and a hatched collection.
    from matplotlib.backend_bases import RendererBase
    import splinefig.matplotlib as backend

    fig = collections()
    ours = png(fig, BACKEND)
    monkeypatch.setattr(backend.RendererSplinefig, "draw_path_collection", RendererBase.draw_path_collection)
    loop = png(fig, BACKEND)
    plt.close(fig)
    assert np.array_equal(ours, loop), np.argwhere((ours != loop).any(axis=2))[:5]


# docs/matplotlib.md's two side-by-side figures (python/bench/matplotlib_images.py) and the pixels
# it marks: (figure, column, row).
SIDE_BY_SIDE = [("lines", 197, 247), ("lines", 225, 238), ("text", 265, 37), ("text", 269, 36)]


def test_side_by_side_pixels_match_the_exact_oracle():
    """At the pixels the docs' side-by-side images mark, splinefig's value is the one the
    independent oracle computes (every path drawn there clipped to the pixel by Sutherland-Hodgman,
    a stroke as the union of its pieces by inclusion-exclusion, composited over white in sRGB
    values) within one level, where AGG is off by more than 48. (Seen failing with the backend's
    blending forced to linear light.)"""
    import os
    import sys

    from conftest import SOURCE_DIR

    sys.path.insert(0, os.path.join(SOURCE_DIR, "python", "bench"))
    try:
        import matplotlib_images as side
    finally:
        sys.path.pop(0)
    for name in ("lines", "text"):
        fig, _ = getattr(side, name)()
        agg = side.render(fig, None)
        ours, items = side.recorded(fig)
        plt.close(fig)
        for _, col, row in (p for p in SIDE_BY_SIDE if p[0] == name):
            want, covers = side.oracle_value(items, col, row)
            assert any(0.02 < k < 0.98 for k in covers), (name, col, row, covers)  # an edge: partly covered
            assert np.abs(ours[row, col] - want).max() <= 1, (name, col, row, want, ours[row, col])
            assert np.abs(agg[row, col] - want).max() > 48, (name, col, row, want, agg[row, col])


def test_png_writer_against_pillow_and_openimageio(tmp_path, monkeypatch):
    """The backend writes its PNGs itself (Up filter, zlib level 1): read back by Pillow and by
    OpenImageIO, every file gives the canvas's pixels, and the metadata and resolution Pillow
    reads are those of the same figure written through matplotlib's PIL writer (pil_kwargs).
    A long stream is split into IDAT chunks. (Seen failing with the rows left unfiltered under
    the Up filter's byte, with the dpi chunk left out, and with the stream cut at the first
    chunk.)"""
    from splinefig.matplotlib import FigureCanvasSplinefig

    fig = busy()
    canvas = FigureCanvasSplinefig(fig)
    canvas.draw()
    want = np.asarray(canvas.buffer_rgba())
    for dpi, meta in ((100, None), (72, {"Title": "\u03a9mega", "Author": "a, b", "Software": None})):
        ours, pil = tmp_path / f"ours{dpi}.png", tmp_path / f"pil{dpi}.png"
        fig.savefig(ours, backend=BACKEND, dpi=dpi, metadata=meta)
        fig.savefig(pil, backend=BACKEND, dpi=dpi, metadata=meta, pil_kwargs={})
        a, b = Image.open(ours), Image.open(pil)
        assert a.info == b.info and a.mode == "RGBA"
        assert (np.asarray(a) == np.asarray(b)).all()
        if dpi == 100:
            assert (np.asarray(a) == want).all()
            assert a.info["Software"].startswith("Matplotlib version")
        else:
            assert "Software" not in a.info and a.info["Title"] == "\u03a9mega"
        oiio = pytest.importorskip("OpenImageIO")
        got = oiio.ImageBuf(str(ours)).get_pixels(oiio.UINT8)
        assert (got == np.asarray(a)).all()
    # A stream longer than one chunk may hold (2^30 bytes here, 1000 made to stand for it) goes
    # into consecutive IDAT chunks.
    import splinefig.matplotlib as backend
    monkeypatch.setattr(backend, "_IDAT_MAX", 1000)
    split = tmp_path / "split.png"
    fig.savefig(split, backend=BACKEND)
    data = split.read_bytes()
    assert data.count(b"IDAT") > 3 and (np.asarray(Image.open(split)) == want).all()
    plt.close(fig)


def test_scene_stamps_composite_in_order():
    """Scene.stamps (a marker's picture at many whole-pixel places, composited into one item)
    gives the canvas of the copies composited one by one in order, computed here in float64 with
    numpy: overlapping translucent copies of a picture with an empty margin, one across the
    canvas's edge, both encodings. A place between pixels, or places spanning far past the canvas,
    are refused. (Seen failing with the copies composited under the ones before them, and with
    the margin's width left out of the place.)"""
    import splinefig

    rng = np.random.default_rng(5)
    pic = rng.uniform(size=(5, 7, 4)).astype(np.float32)
    pic[:, :, :3] *= pic[:, :, 3:]  # associated alpha
    pic = np.pad(pic, ((1, 2), (2, 1), (0, 0)))  # a margin of nothing, as a marker's picture has
    origins = np.array([(2, 3), (4, 4), (3, 2), (-2, 9), (14, 10), (4, 4)], dtype=np.float64)
    for blend in ("linear", "srgb"):
        s = splinefig.Scene(18, 14, background=(0, 0, 0, 0), blend=blend)
        s._s.stamps(pic, origins, blend)
        got = s._s.render(1)
        want = np.zeros((14, 18, 4))
        for x, y in origins.astype(int):
            for j in range(pic.shape[0]):
                for i in range(pic.shape[1]):
                    if 0 <= x + i < 18 and 0 <= y + j < 14:
                        p = pic[j, i].astype(np.float64)
                        want[y + j, x + i] = p + want[y + j, x + i] * (1 - p[3])
        assert np.abs(got - want).max() < 1e-5, blend
    with pytest.raises(ValueError, match="origins: place 1 is not a whole pixel"):
        splinefig.Scene(8, 8)._s.stamps(pic, np.array([(0, 0), (0.5, 1)]), "linear")
    with pytest.raises(ValueError, match="past the canvas"):
        splinefig.Scene(8, 8)._s.stamps(pic, np.array([(0, 0), (1e6, 1e6)]), "linear")
