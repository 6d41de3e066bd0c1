"""Bad arguments: a TypeError or ValueError whose message names the argument, never a crash."""
import math

import numpy as np
import pytest

import splinefig
from splinefig import Basis

K = np.array([[0.0, 0], [1, 1], [2, 0], [3, 1], [4, 0]])
IMG = np.zeros((8, 8, 3), np.float32)

CASES = [
    # (call, exception, message pattern)
    (lambda: Basis.parse("nosuch"), ValueError, r"spec: .*nosuch"),
    (lambda: Basis.parse("cardinal:a=x"), ValueError, r"spec: "),
    (lambda: Basis.parse("cardinal:q=1"), ValueError, r"spec: .*q"),
    (lambda: Basis.parse(3), TypeError, r"spec: expected a string"),
    (lambda: Basis.cardinal("a"), TypeError, r"^a: "),
    (lambda: Basis.cardinal(math.nan), ValueError, r"^a: .*not finite"),
    (lambda: Basis.beta(-1, 0), ValueError, r"b1, b2: "),
    (lambda: Basis.uniform_bspline(0), ValueError, r"degree: 0"),
    (lambda: Basis.uniform_bspline(2.5), TypeError, r"degree: expected an integer"),
    (lambda: Basis(3), TypeError, r"Basis.parse"),
    (lambda: splinefig.kernel("nosuch", 0.0), ValueError, r"basis: .*nosuch"),
    (lambda: splinefig.kernel(3, 0.0), TypeError, r"basis: expected a Basis"),
    (lambda: splinefig.kernel("bspline", "x"), TypeError, r"^x: "),
    (lambda: splinefig.kernel("bspline", [1, "a"]), TypeError, r"^x: "),
    (lambda: splinefig.kernel("bspline", [[1], [1, 2]]), ValueError, r"^x: "),
    (lambda: splinefig.kernel("bspline", np.array([1j])), TypeError, r"^x: "),
    (lambda: splinefig.kernel("bspline", [1.0], out=np.empty(2)), ValueError, r"^out: shape"),
    (lambda: splinefig.kernel("bspline", [1.0], out=np.empty(1, np.float32)), TypeError, r"^out: "),
    (lambda: splinefig.kernel_derivative("lanczos3", 0.5), ValueError, r"basis: .*lanczos3"),
    (lambda: splinefig.kernel_derivative("bspline", 0.5, order=-1), ValueError, r"order: "),
    (lambda: splinefig.response("bspline", None), TypeError, r"freqs: "),
    (lambda: splinefig.report([1]), TypeError, r"basis: "),
    (lambda: splinefig.evaluate([1, 2, 3], "bspline"), ValueError, r"knots: expected an \(n, d\)"),
    (lambda: splinefig.evaluate(K[:2], "bspline"), ValueError, r"knots: "),
    (lambda: splinefig.evaluate(np.array([[0.0, math.inf]] * 5), "bspline"), ValueError, r"knots: .*not finite"),
    (lambda: splinefig.evaluate(K, "bspline", grain=0), ValueError, r"grain: 0"),
    (lambda: splinefig.evaluate(K, "bspline", grain=1.5), TypeError, r"grain: "),
    (lambda: splinefig.evaluate(K, "bspline", ends="twice"), ValueError, r"ends: unknown value 'twice'"),
    (lambda: splinefig.evaluate(K, "bspline", derivative=3), ValueError, r"derivative: 3"),
    (lambda: splinefig.evaluate(K, "nosuch"), ValueError, r"basis: "),
    (lambda: splinefig.evaluate(K, "bspline", out=np.empty((3, 2))), ValueError, r"out: shape"),
    (lambda: splinefig.arclength_points(K, "bspline", count=1), ValueError, r"count: 1"),
    (lambda: splinefig.arclength_points(K, "bspline", count=5, method="exact"), ValueError, r"method: "),
    (lambda: splinefig.interpolate(K[:1]), ValueError, r"points: 1 given"),
    (lambda: splinefig.interpolate(K, ends="periodic"), ValueError, r"points: .*repeat the first"),
    (lambda: splinefig.interpolate(K, start_velocity=[1, 1]), ValueError, r"start_velocity: applies only"),
    (lambda: splinefig.interpolate(K, ends="clamped", end_velocity=[1, 1, 1]), ValueError, r"end_velocity: expected 2"),
    (lambda: splinefig.interpolate(K, output="svg"), ValueError, r"output: "),
    (lambda: splinefig.Scene(0, 10), ValueError, r"width: 0"),
    (lambda: splinefig.Scene(10, 10, filter="lanczos3"), ValueError, r"filter: "),
    (lambda: splinefig.Scene(10, 10, background="red"), ValueError, r"background: 'red'"),
    (lambda: splinefig.Scene(10, 10, background=(1, 2)), ValueError, r"background: expected 3 or 4"),
    (lambda: splinefig.Scene(10, 10).polyline([[0, 0, 0]]), ValueError, r"points: expected an \(n, 2\)"),
    (lambda: splinefig.Scene(10, 10).polyline([[0, 0], [1, 1]], width=-1), ValueError, r"stroke width -1 is negative"),
    (lambda: splinefig.Scene(10, 10).polyline([[0, 0], [1, 1]], miter_limit=0.5), ValueError, r"miter limit 0.5 is below 1"),
    (lambda: splinefig.Scene(10, 10).polyline([[0, 0], [1, 1]], join="sharp"), ValueError, r"join: "),
    (lambda: splinefig.Scene(10, 10).polyline([[0, 0], [1, 1]], dashes=[-1]), ValueError, r"dash length -1 is negative"),
    (lambda: splinefig.Scene(10, 10).stroke_path([[0, 0], [1, 1]], dashes=[0, 0]), ValueError, r"period 0 px is below 0.001 px"),
    (lambda: splinefig.Scene(10, 10).fill([[0, 0], [1, 1], [0, 1]], rule="odd"), ValueError, r"rule: "),
    (lambda: splinefig.Scene(10, 10).circle((1, 1), -1, fill="#000000"), ValueError, r"radius: "),
    (lambda: splinefig.Scene(10, 10).circle((1, 1), 1), ValueError, r"fill, stroke: "),
    (lambda: splinefig.Scene(10, 10).markers([[1, 1]], shape="star"), ValueError, r"shape: "),
    (lambda: splinefig.Scene(10, 10).text(5, (1, 1)), TypeError, r"text: "),
    (lambda: splinefig.Scene(10, 10).text("a", (1, 1), halign="middle"), ValueError, r"halign: "),
    (lambda: splinefig.Scene(10, 10).render(threads=-1), ValueError, r"threads: "),
    (lambda: splinefig.render_figure("nosuch"), ValueError, r"name: no built-in figure 'nosuch'"),
    (lambda: splinefig.render_figure("../bias"), ValueError, r"name: "),
    (lambda: splinefig.render_spec("/nonexistent.toml"), ValueError, r"nonexistent"),
    (lambda: splinefig.render_spec(3), TypeError, r"spec: expected a path"),
    (lambda: splinefig.render_spec("x", text="[canvas]\nwidth = 10\n", scale=0), ValueError, r"scale: "),
    (lambda: splinefig.resample(IMG), ValueError, r"size, scale: give exactly one"),
    (lambda: splinefig.resample(IMG, size=(4, 4), scale=2), ValueError, r"size, scale: "),
    (lambda: splinefig.resample(IMG.astype(np.int32), size=(4, 4)), TypeError, r"image: expected a float32 or float64 array, or a uint8 or uint16 one of sRGB values, got dtype int32"),
    (lambda: splinefig.resample([[1]], size=(4, 4)), TypeError, r"image: "),
    (lambda: splinefig.resample(np.zeros(5, np.float32), size=(4, 4)), ValueError, r"image: .*shape \(5,\)"),
    (lambda: splinefig.resample(np.zeros((0, 4), np.float32), size=(4, 4)), ValueError, r"image: "),
    (lambda: splinefig.resample(IMG, size=(0, 4)), ValueError, r"size: 0"),
    (lambda: splinefig.resample(IMG, size="4x4"), TypeError, r"size: "),
    (lambda: splinefig.resample(IMG, scale=0.01), ValueError, r"scale: the width of 8 pixels becomes 0"),
    (lambda: splinefig.resample(IMG, scale=-1), ValueError, r"scale: must be positive"),
    (lambda: splinefig.resample(IMG, size=(4, 4), filter="nosuch"), ValueError, r"filter: "),
    (lambda: splinefig.resample(IMG, size=(4, 4), edge="reflect"), ValueError, r"edge: "),
    (lambda: splinefig.resample(IMG, size=(4, 4), filter="beta:b1=5", interpolating=True), ValueError, r"filter: .*no stable inverse"),
    (lambda: splinefig.image_buffer(0, 4), ValueError, r"height: 0"),
    (lambda: splinefig.image_buffer(4, 4, 0), ValueError, r"channels: 0"),
    (lambda: splinefig.image_buffer(65536, 65536, 1), ValueError, r"over the limit"),
    (lambda: splinefig.compare(IMG, "/nonexistent.png"), OSError, r"nonexistent"),
    (lambda: splinefig.compare(IMG, IMG, fail=-1), ValueError, r"fail: "),
    # Past the largest float, as `splinefig diff --fail 1e39` refuses it; inf only for the hard limits.
    (lambda: splinefig.compare(IMG, IMG, fail=1e39), ValueError, r"fail: must be a number in \[0, 3.4028235e\+38\] \(a float\), got 1e\+39"),
    (lambda: splinefig.compare(IMG, IMG, warn=math.inf), ValueError, r"warn: must be a number in "),
    (lambda: splinefig.compare(IMG, IMG, hardwarn=-1e300), ValueError, r"hardwarn: .*, or inf for none, got -1e\+300"),
    (lambda: splinefig.compare(IMG, IMG, failpercent=101), ValueError, r"failpercent: "),
    (lambda: splinefig.compare(IMG, IMG, shift=65), ValueError, r"shift: 65"),
    (lambda: splinefig.compare(IMG, IMG, ssim=2), ValueError, r"ssim: "),
    (lambda: splinefig.compare(IMG, IMG, flip="a"), TypeError, r"flip: "),
    (lambda: splinefig.compare(IMG, IMG, linear=1), TypeError, r"linear: "),
    (lambda: splinefig.compare(IMG, IMG, failthresh=1), TypeError, r"unknown option failthresh"),
    (lambda: splinefig.compare(IMG, 3), TypeError, r"^b: "),
    (lambda: splinefig.compare(IMG, IMG, mask=np.ones((4, 4), np.float32)), ValueError, r"mask: "),
    (lambda: splinefig.difference_image(IMG, IMG[:4]), ValueError, r"a, b: shapes"),
    (lambda: splinefig.read_image("/nonexistent.png"), OSError, r"nonexistent"),
    (lambda: splinefig.write_image("/tmp/x.bmp", IMG), OSError, r"x.bmp"),
    (lambda: splinefig.write_image("/tmp/x.png", IMG, bits=12), ValueError, r"bits: 12"),
    (lambda: splinefig.write_image("/tmp/x.png", IMG, encoding="gamma"), ValueError, r"encoding: "),
]


@pytest.mark.parametrize("call,exc,pattern", CASES, ids=[f"case{i}" for i in range(len(CASES))])
def test_bad_input_is_refused_naming_the_argument(call, exc, pattern):
    with pytest.raises(exc, match=pattern):
        call()


def _png_with_origin(x, y):
    """A 23 x 4 RGB PNG whose oFFs chunk puts its data window at (x, y) pixels."""
    import struct
    import zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    rows = b"".join(b"\x00" + bytes([10 * i] * 23 * 3) for i in range(4))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 23, 4, 8, 2, 0, 0, 0)) +
            chunk(b"oFFs", struct.pack(">iiB", x, y, 0)) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


@pytest.mark.parametrize("x, y", [(0, 2**31 - 1), (2**31 - 1, 0), (0, -2**31), (2**30 + 1, 0)])
def test_read_image_refuses_a_data_window_origin_past_the_limit(tmp_path, x, y):
    # An oFFs origin near INT_MAX overflowed origin + size and read_image returned unwritten
    # memory, different on every call; the limit is 2^30 either way (docs/limits.md).
    path = tmp_path / "far.png"
    path.write_bytes(_png_with_origin(x, y))
    with pytest.raises(OSError, match=rf"data window origin \({x}, {y}\) out of range \(limit 2\^30 either way\)"):
        splinefig.read_image(str(path))


def test_read_image_reads_a_data_window_origin_at_the_limit(tmp_path):
    # At 2^30 the image is read, the same values on every call: row i is 10 i / 255 in sRGB.
    path = tmp_path / "edge.png"
    path.write_bytes(_png_with_origin(2**30, -2**30))
    first = np.array(splinefig.read_image(str(path)))
    assert first.shape[:2] == (4, 23)
    assert np.array_equal(first, np.array(splinefig.read_image(str(path))))
    linear = np.array(splinefig.read_image(str(path), linear=False))
    for i in range(4):
        assert np.allclose(linear[i, :, :3], 10 * i / 255, atol=1e-6)
