"""Images drawn by the matplotlib backend with splinefig's kernels (imshow(interpolation="none")
and kernel= at savefig): against splinefig.resample called directly on the same pixels and
size, against `splinefig resample` on the same PNG, and against the peers that share a kernel
(SciPy's cubic B-spline zoom and affine_transform, OpenImageIO's catmull-rom resize).

Every comparison is of 8-bit output with a value computed outside the backend and encoded by
the IEC 61966-2-1 formula here. Tolerances: 1 level of 255. The library's arithmetic is float32
and the peers' float32 or float64, so the linear values agree to about 1e-6; after the sRGB
curve a value that lands near a half level may round either way, hence one level, and the
count of such values is bounded too (a fault moves many values by many levels)."""
import io
import os
import re

import numpy as np
import pytest

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.transforms import Affine2D  # noqa: E402
from PIL import Image  # noqa: E402

import splinefig  # noqa: E402
from polygon_area import area, clip_convex  # noqa: E402

BACKEND = "module://splinefig.matplotlib"


def png(fig, **kw):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", backend=BACKEND, **kw)
    buf.seek(0)
    return np.asarray(Image.open(buf).convert("RGBA")).astype(np.int32)


def encode(linear):
    """Linear light (associated alpha, opaque here) to 8-bit sRGB codes, by the standard's formula."""
    v = np.clip(np.asarray(linear, dtype=np.float64), 0.0, 1.0)
    return np.round(255 * np.where(v <= 0.0031308, 12.92 * v, 1.055 * v ** (1 / 2.4) - 0.055)).astype(np.int32)


def decode(codes):
    v = np.asarray(codes, dtype=np.float64) / 255
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


def source(h=12, w=16, seed=7):
    """An opaque RGB source with sharp features (noise and a bar), as uint8 RGBA."""
    rng = np.random.default_rng(seed)
    rgb = (rng.uniform(size=(h, w, 3)) * 255).astype(np.uint8)
    rgb[h // 3, :, :] = (255, 0, 40)
    return np.dstack([rgb, np.full((h, w), 255, np.uint8)])


def canvas(width, height):
    """A figure of width x height pixels whose axes fill it and whose data coordinates are the
    canvas pixels (x right, y down), without axis decorations."""
    fig = plt.figure(figsize=(width / 64, height / 64), dpi=64)  # sizes exact in binary
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_axis_off()
    return fig, ax


def show(ax, rgba, width, height, transform=None, interpolation="none", **kw):
    """rgba on ax, source pixel (i, j) over the data square [i, i+1] x [j, j+1]: without a
    transform the image fills the axes; with one, the data coordinates are the canvas's pixels
    (x right, y down) and transform takes source pixel coordinates there."""
    h, w = rgba.shape[:2]
    im = ax.imshow(rgba, interpolation=interpolation, origin="upper", extent=(0, w, h, 0), aspect="auto", **kw)
    if transform is None:
        ax.set_xlim(0, w)
        ax.set_ylim(h, 0)
    else:
        ax.set_xlim(0, width)
        ax.set_ylim(height, 0)
        im.set_transform(transform + ax.transData)
    return im


def close_to(actual, expected, what, max_off=0.01):
    d = np.abs(actual - expected)
    assert d.max() <= 1, f"{what}: max difference {d.max()} levels at {np.unravel_index(d.argmax(), d.shape)}"
    assert (d > 0).mean() <= max_off, f"{what}: {(d > 0).mean():.2%} of the values are off by one"


KERNELS = ["catmull-rom", "bspline", "cardinal:a=0.3", "tensioned-bspline:a=0.5", "beta:b1=2,b2=0", "beta:b1=1,b2=8",
           "lanczos3", "tent"]


@pytest.mark.parametrize("spec", KERNELS)
@pytest.mark.parametrize("size", [(240, 180), (200, 150), (31, 22), (13, 7)])
def test_the_resampler_on_the_same_pixels(spec, size):
    # An image filling the canvas, enlarged (15x, 12.5x), reduced to non-integer ratios and to
    # a few pixels: the picture is splinefig.resample of the source to the canvas's size with
    # the kernel (an asymmetric Beta-spline keeps its left-to-right orientation).
    W, H = size
    src = source()
    fig, ax = canvas(W, H)
    show(ax, src, W, H)
    got = png(fig, kernel=spec)
    plt.close(fig)
    ref = splinefig.resample(src, size=(W, H), filter=spec)  # uint8: decoded as `resample` decodes a PNG
    close_to(got[:, :, :3], encode(ref[:, :, :3]), spec)
    assert (got[:, :, 3] == 255).all()


@pytest.mark.parametrize("spec,edge,interp", [("catmull-rom", "clamp", False), ("bspline", "clamp", True),
                                               ("bspline", "wrap", True), ("beta:b1=2,b2=0", "mirror", False),
                                               ("tensioned-bspline:a=0.5", "black", True)])
@pytest.mark.parametrize("size", [(200, 150), (13, 7)])
def test_the_visible_pixels_alone_give_the_same(monkeypatch, spec, edge, interp, size):
    # An image far larger than the canvas (zoomed in) has only its visible pixels computed, by
    # the same sums evaluated directly (and the prefilter solved in numpy): forced here on an
    # image that fills the canvas, the picture is still the resampler's. With edge "black" the
    # edges lose alpha: the transparent PNG's alpha channel is compared (straight alpha, 8 bits).
    import splinefig.matplotlib as backend

    monkeypatch.setattr(backend.RendererSplinefig, "_resample_whole", lambda self, dw, dh: False)
    W, H = size
    src = source()
    fig, ax = canvas(W, H)
    show(ax, src, W, H)
    got = png(fig, kernel=spec, kernel_edge=edge, kernel_interpolating=interp, transparent=edge == "black")
    plt.close(fig)
    ref = splinefig.resample(src, size=(W, H), filter=spec, edge=edge, interpolating=interp)
    if edge == "black":
        close_to(got[:, :, 3], np.round(255 * np.clip(ref[:, :, 3], 0, 1)).astype(np.int32), spec)
    else:
        close_to(got[:, :, :3], encode(ref[:, :, :3]), spec)


def test_flips_and_the_prefilter():
    # origin="lower" and a reversed x extent show the source upside down and mirrored: the
    # picture is the resampler's of the source as shown (an asymmetric kernel would tell the
    # orders apart). kernel_interpolating is `resample --interpolating`; edges as kernel_edge.
    W, H = 200, 150
    src = source()
    h, w = src.shape[:2]
    for spec, edge, interp in (("beta:b1=2,b2=0", "clamp", False), ("bspline", "mirror", True),
                               ("tensioned-bspline:a=0.5", "clamp", True), ("catmull-rom", "wrap", False)):
        fig = plt.figure(figsize=(W / 64, H / 64), dpi=64)
        ax = fig.add_axes([0, 0, 1, 1])
        ax.set_axis_off()
        ax.imshow(src, interpolation="none", origin="lower", extent=(w, 0, 0, h), aspect="auto")
        ax.set_xlim(0, w)
        ax.set_ylim(0, h)
        got = png(fig, kernel=spec, kernel_edge=edge, kernel_interpolating=interp)
        plt.close(fig)
        shown = np.ascontiguousarray(src[::-1, ::-1])
        ref = splinefig.resample(shown, size=(W, H), filter=spec, edge=edge, interpolating=interp)
        close_to(got[:, :, :3], encode(ref[:, :, :3]), f"{spec} {edge} {interp}")


def test_the_command_line_on_the_same_png(tmp_path, cli):
    # `splinefig resample src.png --size WxH --filter SPEC`, the file's bytes decoded by PIL.
    W, H = 200, 150
    src = source()
    Image.fromarray(src[:, :, :3]).save(tmp_path / "src.png")
    for spec in ("catmull-rom", "cardinal:a=0.8", "beta:b1=2,b2=0"):
        cli(["resample", tmp_path / "src.png", "-o", tmp_path / "out.png", "--size", f"{W}x{H}", "--filter", spec])
        ref = np.asarray(Image.open(tmp_path / "out.png").convert("RGB")).astype(np.int32)
        fig, ax = canvas(W, H)
        show(ax, src, W, H)
        got = png(fig, kernel=spec)
        plt.close(fig)
        close_to(got[:, :, :3], ref, spec)


def test_in_a_plot_the_image_fills_the_clip_rectangle():
    # An ordinary imshow in an axes with ticks. matplotlib hands the image over stretched to a
    # whole number of pixels from the axes' corner (ceil of the axes' width and height, as it
    # sizes AGG's image); its left and bottom edges are rounded as AGG places an image. That
    # rectangle is the resampler's picture of the source at that size, cropped to the axes' box
    # (rounded as AGG rounds clip boxes), and everything outside the box is as without a kernel.
    src = source(20, 30)
    fig, ax = plt.subplots(figsize=(6, 4), dpi=100)
    ax.imshow(src, interpolation="none")
    got = png(fig, kernel="catmull-rom")
    plain = png(fig)
    plt.close(fig)
    x0, y0, x1, y1 = ax.bbox.extents  # the axes, y up
    H = got.shape[0]
    dw, dh = int(np.ceil(x1 - x0)), int(np.ceil(y1 - y0))
    left = int(np.floor(x0 + 0.5))
    top = H - int(np.floor(y0 + 0.5)) - dh
    ref = splinefig.resample(src, size=(dw, dh), filter="catmull-rom")
    bx0, bx1 = int(np.floor(x0 + 0.5)), int(np.floor(x1 + 0.5))
    by0, by1 = H - int(np.floor(y1 + 0.5)), H - int(np.floor(y0 + 0.5))
    # The spines are drawn over the box's edge pixels: compared 2 pixels in from it.
    m = 2
    close_to(got[by0 + m:by1 - m, bx0 + m:bx1 - m, :3],
             encode(ref[by0 + m - top:by1 - m - top, bx0 + m - left:bx1 - m - left, :3]), "catmull-rom in axes")
    outside = np.ones(got.shape[:2], bool)
    outside[by0:by1, bx0:bx1] = False
    assert np.array_equal(got[outside], plain[outside])


def test_alpha_multiplies_the_resampled_image():
    # imshow(alpha=0.5) over the white figure: sRGB blending, as AGG, gives code c/2 + 255/2.
    W, H = 160, 120
    src = source()
    fig, ax = canvas(W, H)
    show(ax, src, W, H, alpha=0.5)
    got = png(fig, kernel="catmull-rom")
    plt.close(fig)
    ref = splinefig.resample(src, size=(W, H), filter="catmull-rom")
    srgb = encode(ref[:, :, :3]) / 255.0
    # The exact value may lie at a half level (c odd): allow the rounding of either side.
    assert np.abs(got[:, :, :3] - 255 * (0.5 * srgb + 0.5)).max() <= 1.0


def test_scipy_cubic_bspline_zoom(rng):
    # SciPy's order-3 spline zoom is the interpolating cubic B-spline; grid_mode=True maps pixel
    # centres as the resampler does (x = (i + 1/2) S/D - 1/2 in its index coordinates) and
    # mode "grid-mirror" is the half-sample symmetric extension of mirror. Enlarging only
    # (SciPy does not widen the kernel when reducing).
    ndimage = pytest.importorskip("scipy.ndimage")
    W, H = 173, 131
    src = source()
    h, w = src.shape[:2]
    fig, ax = canvas(W, H)
    show(ax, src, W, H)
    got = png(fig, kernel="bspline", kernel_edge="mirror", kernel_interpolating=True)
    plt.close(fig)
    lin = decode(src[:, :, :3])
    ref = np.stack([ndimage.zoom(lin[:, :, c], (H / h, W / w), order=3, mode="grid-mirror", grid_mode=True,
                                 prefilter=True) for c in range(3)], axis=2)
    assert ref.shape == (H, W, 3)
    close_to(got[:, :, :3], encode(ref), "scipy zoom")


def test_openimageio_catmull_rom_resize(oiio):
    # OpenImageIO's resize with its catmull-rom filter: the same pixel-centre mapping, clamped
    # edges, weights normalised per axis (docs/resample.md: agrees to 1e-5 when x is enlarged at
    # least as much as y).
    W, H = 240, 150
    src = source()
    h, w = src.shape[:2]
    fig, ax = canvas(W, H)
    show(ax, src, W, H)
    got = png(fig, kernel="catmull-rom")
    plt.close(fig)
    lin = np.ascontiguousarray(decode(src[:, :, :3]), dtype=np.float32)
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(0, w, 0, h, 0, 1, 0, 3), lin)
    out = oiio.ImageBufAlgo.resize(buf, "catmull-rom", roi=oiio.ROI(0, W, 0, H, 0, 1, 0, 3))
    ref = np.asarray(out.get_pixels(oiio.FLOAT)).reshape(H, W, 3)
    close_to(got[:, :, :3], encode(ref), "oiio catmull-rom")


@pytest.mark.parametrize("spec,scale", [("catmull-rom", 10), ("bspline", 7), ("beta:b1=2,b2=0", 10), ("catmull-rom", 0.5)])
def test_a_quarter_turn_is_the_resampler_of_the_turned_source(spec, scale):
    # Rotated by 90 degrees (a transform with no scaling on the diagonal, so the direct path):
    # with x right and y down, (u, v) -> (h - v, u) moves source pixel (i, j) to the canvas
    # square at column h - 1 - j, row i: the canvas shows S[Y, X] = src[h - 1 - X, Y], the
    # source turned a quarter clockwise, np.rot90(src, -1). Reduced by 2 as well (the kernel is
    # widened along each source axis as the resampler widens it).
    src = source(12, 16) if scale >= 1 else source(40, 30)
    h, w = src.shape[:2]
    W, H = round(h * scale), round(w * scale)
    fig, ax = canvas(W, H)
    turn = Affine2D.from_values(0, scale, -scale, 0, h * scale, 0)  # (u, v) -> (s (h - v), s u)
    show(ax, src, W, H, transform=turn)
    got = png(fig, kernel=spec)
    plt.close(fig)
    ref = splinefig.resample(np.ascontiguousarray(np.rot90(src, -1)), size=(W, H), filter=spec)
    close_to(got[:, :, :3], encode(ref[:, :, :3]), f"{spec} turned")


def test_scipy_affine_transform_on_a_rotated_image():
    # Turned by atan(3/4) = 36.9 degrees and scaled by 5 ((u, v) -> (4u - 3v, 3u + 4v) + t, exact
    # in binary, with a bounding box of whole pixels so that matplotlib does not stretch it).
    # A pixel the image covers whole is the interpolating cubic B-spline at the source position
    # its centre maps to, as SciPy's map_coordinates (order 3, mode "grid-mirror") computes it;
    # every pixel's alpha (a transparent figure) is the area of it the image covers, found by
    # Sutherland-Hodgman, within half an 8-bit step.
    ndimage = pytest.importorskip("scipy.ndimage")
    src = source(16, 20)
    h, w = src.shape[:2]
    W, H = 160, 170
    M = np.array([[4.0, -3.0, 60.0], [3.0, 4.0, 30.0]])  # (u, v) -> canvas, y down
    fig, ax = canvas(W, H)
    show(ax, src, W, H, transform=Affine2D.from_values(M[0, 0], M[1, 0], M[0, 1], M[1, 1], M[0, 2], M[1, 2]))
    got = png(fig, kernel="bspline", kernel_edge="mirror", kernel_interpolating=True, transparent=True)
    plt.close(fig)
    Mi = np.linalg.inv(M[:, :2])

    def source_at(X, Y):
        return (Mi[0, 0] * (X - M[0, 2]) + Mi[0, 1] * (Y - M[1, 2]), Mi[1, 0] * (X - M[0, 2]) + Mi[1, 1] * (Y - M[1, 2]))

    Yc, Xc = np.mgrid[0:H, 0:W].astype(np.float64)
    u, v = source_at(Xc + 0.5, Yc + 0.5)
    lin = decode(src[:, :, :3])
    ref = np.stack([ndimage.map_coordinates(lin[:, :, k], [v - 0.5, u - 0.5], order=3, mode="grid-mirror", prefilter=True)
                    for k in range(3)], axis=2)
    whole = np.ones((H, W), bool)
    for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)):
        cu, cv = source_at(Xc + dx, Yc + dy)
        whole &= (cu >= 0) & (cu <= w) & (cv >= 0) & (cv <= h)
    assert whole.sum() > 0.2 * W * H
    close_to(got[whole][:, :3], encode(ref[whole]), "rotated")
    # The image's outline, counter-clockwise in these y-down coordinates' mirror (y up).
    quad = [tuple(M[:, :2] @ p + M[:, 2]) for p in ((0, 0), (w, 0), (w, h), (0, h))]
    quad = [(x, -y) for x, y in quad][::-1]
    worst = 0.0
    for row in range(H):
        for col in range(W):
            square = [(col, -row - 1), (col + 1, -row - 1), (col + 1, -row), (col, -row)]
            part = clip_convex(square, quad)
            want = area(part) if len(part) >= 3 else 0.0
            worst = max(worst, abs(got[row, col, 3] / 255 - want))
    assert worst <= 0.5 / 255 + 1e-6


@pytest.mark.parametrize("spec", ["catmull-rom", "bspline"])
def test_a_large_turned_image_is_reduced_first(monkeypatch, spec):
    # A 400x300 image turned by 180 degrees plus the 3-4-5 angle (both source axes run against
    # the canvas's, so the source is turned over before the first stage and back after it) and
    # reduced 4 times: the sums taken directly
    # (6 x 10^4 pixels times 22 x 22 taps) against the work bound forced to 0, where the
    # source is first reduced along its axes by the resampler to about a pixel per canvas pixel
    # and then summed with the kernel unwidened. On smooth data the two agree within 3 levels,
    # 0.2 on average (measured: catmull-rom 2 and 0.013, bspline 3 and 0.099).
    import splinefig.matplotlib as backend

    h, w = 300, 400
    yy, xx = np.mgrid[0:h, 0:w]
    rgb = np.stack([127 + 100 * np.sin(xx / 23.0), 127 + 100 * np.cos(yy / 31.0), 127 + 90 * np.sin((xx + yy) / 41.0)],
                   axis=2).astype(np.uint8)
    src = np.dstack([rgb, np.full((h, w), 255, np.uint8)])
    W, H = 160, 130
    turn = Affine2D.from_values(-0.2, -0.15, 0.15, -0.2, 100.0, 125.0)

    def draw():
        fig, ax = canvas(W, H)
        show(ax, src, W, H, transform=turn)
        got = png(fig, kernel=spec)
        plt.close(fig)
        return got

    direct = draw()
    monkeypatch.setattr(backend.RendererSplinefig, "_DIRECT_WORK", 0)
    reduced = draw()
    d = np.abs(direct - reduced)
    assert d.max() <= 3 and d.mean() <= 0.2, (d.max(), d.mean())
    assert (direct[65, 82, :3] != 255).any()  # the image is there


def test_without_a_kernel_nothing_changes():
    # No kernel: interpolation="none" is matplotlib's (AGG's nearest) as before, the same bytes
    # as kernel=False; with a kernel, an image of another interpolation is the same bytes too.
    src = source()
    fig, axes = plt.subplots(1, 2, figsize=(5, 3), dpi=100)
    axes[0].imshow(src, interpolation="none")
    axes[1].imshow(src[:, :, 0], interpolation="bicubic", cmap="viridis")
    plain = png(fig)
    assert np.array_equal(plain, png(fig, kernel=False))
    kern = png(fig, kernel="catmull-rom")
    plt.close(fig)
    right = int(np.ceil(axes[1].bbox.x0)) - 2
    assert not np.array_equal(kern[:, :right], plain[:, :right])
    assert np.array_equal(kern[:, right + 4:], plain[:, right + 4:])


def test_the_ways_of_choosing_a_kernel(monkeypatch):
    import splinefig.matplotlib as backend

    W, H = 120, 90
    src = source()
    fig, ax = canvas(W, H)
    show(ax, src, W, H)
    by_keyword = png(fig, kernel="bspline")
    with backend.kernel("bspline"):
        assert np.array_equal(png(fig), by_keyword)
        assert not np.array_equal(png(fig, kernel="catmull-rom"), by_keyword)  # the keyword wins
    assert backend.KERNEL is None
    plain = png(fig)
    assert not np.array_equal(plain, by_keyword)
    monkeypatch.setenv("SPLINEFIG_MPL_KERNEL", "bspline")
    assert np.array_equal(png(fig), by_keyword)
    assert np.array_equal(png(fig, kernel=False), plain)
    monkeypatch.delenv("SPLINEFIG_MPL_KERNEL")
    assert np.array_equal(png(fig, kernel=splinefig.Basis.parse("bspline")), by_keyword)
    files = set()
    for threads in (1, 2, 3, 0):
        buf = io.BytesIO()
        fig.savefig(buf, format="png", backend=BACKEND, kernel="catmull-rom", threads=threads)
        files.add(buf.getvalue())
    assert len(files) == 1
    plt.close(fig)


def test_a_bad_choice_is_refused_before_drawing():
    import splinefig.matplotlib as backend

    fig, ax = canvas(40, 30)
    show(ax, source(), 40, 30)
    with pytest.raises(ValueError, match="^kernel: .*nosuch"):
        png(fig, kernel="nosuch")
    with pytest.raises(ValueError, match="^kernel_edge: unknown value 'nearest'"):
        png(fig, kernel="bspline", kernel_edge="nearest")
    with pytest.raises(ValueError, match="^kernel_interpolating: .*"):
        png(fig, kernel="beta:b1=3,b2=0", kernel_interpolating=True)
    with pytest.raises(ValueError, match="^kernel: "):
        with backend.kernel("cardinal:b=1"):
            pass
    assert backend.KERNEL is None
    plt.close(fig)


def test_the_docs_example_runs(tmp_path, monkeypatch):
    # docs/matplotlib.md's example of the section, run as written.
    from conftest import SOURCE_DIR

    with open(os.path.join(SOURCE_DIR, "docs", "matplotlib.md"), encoding="utf-8") as f:
        text = f.read()
    section = text[text.index("## Images resampled with splinefig's kernels"):]
    code = re.search(r"```python\n(.*?)```", section, flags=re.S).group(1)
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/matplotlib.md", "exec"), {"__name__": "docs"})
    pictures = [np.asarray(Image.open(tmp_path / f"{n}.png")) for n in ("catmull-rom", "bspline", "cardinal")]
    assert len({p.tobytes() for p in pictures}) == 3
