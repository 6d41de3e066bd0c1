"""Rendering, resampling and comparison: pinned to exact coverage, the CLI (the same bits, read
back through OpenImageIO's own Python bindings), OpenImageIO's resize and compare, and SSIM
computed here from its definition."""
import json
import os
import sys
import threading

import numpy as np
import pytest

import splinefig
from splinefig import _core

from conftest import SOURCE_DIR


def oiio_read(oiio, path):
    buf = oiio.ImageBuf(str(path))
    assert not buf.has_error, buf.geterror()
    return buf.get_pixels(oiio.FLOAT)


def oiio_write(oiio, path, array):
    h, w = array.shape[:2]
    c = array.shape[2] if array.ndim == 3 else 1
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, c, "float"))
    assert buf.set_pixels(oiio.ROI(), np.ascontiguousarray(array, dtype=np.float32))
    assert buf.write(str(path)), buf.geterror()


# ---- rendering -------------------------------------------------------------------------------

def test_exact_area_coverage():
    s = splinefig.Scene(8, 6, background="#ffffff")
    s.fill([(1, 1), (4, 1), (4, 3), (1, 3)], color=(0, 0, 0))       # whole pixels
    s.fill([(5.5, 0), (7, 0), (7, 2), (5.5, 2)], color=(0, 0, 0))   # column 5 half covered
    img = s.render()
    assert img.shape == (6, 8, 4) and img.dtype == np.float32
    assert np.all(img[1:3, 1:4, :3] == 0) and np.all(img[..., 3] == 1)
    assert np.all(img[0:2, 5, :3] == 0.5) and np.all(img[0:2, 6, :3] == 0)
    untouched = np.ones((6, 8), bool)
    untouched[1:3, 1:4] = untouched[0:2, 5:7] = False
    assert np.all(img[untouched][:, :3] == 1)


def test_scene_items_and_threads():
    s = splinefig.Scene(64, 48, background=(1, 1, 1, 0), filter="bspline")
    s.polyline([(4, 4), (60, 40), (8, 40)], color="#cc0000", width=2.5, join="round", cap="round", dashes=[6, 3])
    s.circle((32, 24), 10, fill="#0000ff80", stroke="#000000", width=1.5)
    s.markers([(10, 10), (50, 10)], shape="diamond", size=7, color="#00aa00")
    s.text("Ag", (20, 30), size=16, color="#000000")
    one = s.render(threads=1)
    assert np.array_equal(one, s.render(threads=3))  # the same bytes for any thread count
    # Nearly opaque ink (the B-spline filter's support, +-2 px, reaches past the 7 px diamond's
    # edges even at its centre, so no pixel is exactly 1) and an untouched transparent corner.
    assert 0.999 < one[..., 3].max() <= 1 and one[0, 63, 3] == 0


def test_render_figure_is_the_clis(cli, oiio, tmp_path):
    out = tmp_path / "bias.exr"
    cli(["render", os.path.join(SOURCE_DIR, "figures", "specs", "bias.toml"), "-o", out])
    got = splinefig.render_figure("bias")
    assert got.shape[2] == 4 and got.dtype == np.float32
    assert np.array_equal(got, oiio_read(oiio, out))
    assert "bias" in splinefig.figure_names()


def test_render_spec_text_and_scale():
    text = '[canvas]\nwidth = 40\nheight = 30\n\n[[polyline]]\npoints = [[2, 2], [38, 28]]\nwidth = 2\n'
    img = splinefig.render_spec("inline", text=text)
    assert img.shape == (30, 40, 4)
    assert splinefig.render_spec("inline", text=text, scale=2).shape == (60, 80, 4)
    with pytest.raises(ValueError, match="inline"):
        splinefig.render_spec("inline", text="[canvas]\nwidth = -4\n")


# ---- resampling ------------------------------------------------------------------------------

@pytest.mark.parametrize("filt,edge,interp,size", [
    ("catmull-rom", "clamp", False, (37, 23)), ("bspline", "mirror", True, (80, 50)),
    ("beta:b1=2,b2=1", "wrap", False, (12, 9)), ("lanczos3", "black", False, (61, 20)), ("box", "clamp", False, (20, 15))])
def test_resample_is_the_clis(cli, oiio, tmp_path, rng, filt, edge, interp, size):
    src = rng.uniform(0, 1, size=(30, 40, 3)).astype(np.float32)
    oiio_write(oiio, tmp_path / "in.exr", src)
    args = ["resample", tmp_path / "in.exr", "-o", tmp_path / "out.exr", "--size", f"{size[0]}x{size[1]}",
            "--filter", filt, "--edge", edge] + (["--interpolating"] if interp else [])
    cli(args)
    ours = splinefig.resample(src, size=size, filter=filt, edge=edge, interpolating=interp)
    assert ours.shape == (size[1], size[0], 3) and ours.dtype == np.float32
    assert np.array_equal(ours, oiio_read(oiio, tmp_path / "out.exr"))


def test_resample_scale_rounds_as_the_cli(cli, oiio, tmp_path, rng):
    src = rng.uniform(0, 1, size=(10, 30, 3)).astype(np.float32)
    oiio_write(oiio, tmp_path / "in.exr", src)
    cli(["resample", tmp_path / "in.exr", "-o", tmp_path / "out.exr", "--scale", "0.25,1.45", "--filter", "tent"])
    ours = splinefig.resample(src, scale=(0.25, 1.45), filter="tent")  # 7.5 -> 8, 14.5 -> 15
    assert ours.shape == (15, 8, 3)
    assert np.array_equal(ours, oiio_read(oiio, tmp_path / "out.exr"))


@pytest.mark.parametrize("ours,theirs", [("catmull-rom", "catmull-rom"), ("bspline", "bspline"), ("tent", "triangle"),
                                         ("lanczos3", "lanczos3")])
@pytest.mark.parametrize("sw,sh,dw,dh", [(16, 16, 40, 40), (48, 40, 12, 10), (20, 30, 50, 45), (40, 24, 10, 24)])
def test_resample_agrees_with_openimageio_resize(oiio, rng, ours, theirs, sw, sh, dw, dh):
    # Where the semantics are the same (clamped edges, symmetric kernels): to 1e-5.
    src = rng.uniform(0, 1, size=(sh, sw, 2)).astype(np.float32)
    buf = oiio.ImageBuf(oiio.ImageSpec(sw, sh, 2, "float"))
    buf.set_pixels(oiio.ROI(), src)
    ref = oiio.ImageBufAlgo.resize(buf, theirs, roi=oiio.ROI(0, dw, 0, dh, 0, 1, 0, 2), nthreads=1).get_pixels(oiio.FLOAT)
    got = splinefig.resample(src, size=(dw, dh), filter=ours, threads=1)
    assert np.max(np.abs(got - ref)) <= 1e-5


def test_resample_shapes_dtypes_and_threads(rng):
    g = rng.uniform(0, 1, size=(33, 47))
    out = splinefig.resample(g, size=(20, 70))
    assert out.shape == (70, 20) and out.dtype == np.float64
    f32 = splinefig.resample(g.astype(np.float32), size=(20, 70))
    assert np.array_equal(out, f32.astype(np.float64))  # float64 in: the float32 arithmetic, widened
    rgba = rng.uniform(0, 1, size=(64, 64, 4)).astype(np.float32)
    one = splinefig.resample(rgba, scale=1.7, threads=1)
    assert np.array_equal(one, splinefig.resample(rgba, scale=1.7, threads=4))
    assert np.array_equal(one, splinefig.resample(np.asfortranarray(rgba), scale=1.7))  # any layout
    assert f32.base is not None and f32.flags.owndata is False  # the library's image itself, not a copy


def test_resample_reads_splinefigs_own_arrays_in_place(rng):
    buf = splinefig.image_buffer(40, 30, 3)
    assert buf.shape == (40, 30, 3) and buf.dtype == np.float32 and not buf.any()
    buf[...] = rng.uniform(size=buf.shape)
    copy = np.array(buf)  # a plain numpy array: read in place as well
    assert np.array_equal(splinefig.resample(buf, size=(13, 17)), splinefig.resample(copy, size=(13, 17)))
    # Parts of it: rows (still C-contiguous, read in place) and channels (copied), the same results.
    assert np.array_equal(splinefig.resample(buf[5:], size=(13, 17)), splinefig.resample(copy[5:], size=(13, 17)))
    assert np.array_equal(splinefig.resample(buf[..., :2], size=(9, 9)), splinefig.resample(copy[..., :2], size=(9, 9)))
    g = splinefig.image_buffer(20, 10)
    assert g.shape == (20, 10)
    g[...] = rng.uniform(size=g.shape)
    assert np.array_equal(splinefig.resample(g, size=(7, 7)), splinefig.resample(np.array(g), size=(7, 7)))
    # Chained calls: the renderer's and resampler's results are read in place too.
    img = splinefig.Scene(32, 32).fill([(4, 4), (28, 4), (16, 28)], color="#3366cc").render()
    assert np.array_equal(splinefig.resample(splinefig.resample(img, scale=2), scale=0.5),
                          splinefig.resample(np.array(splinefig.resample(img, scale=2)), scale=0.5))


def _peak_rss_reset():
    """Resets the process's peak resident size (Linux's VmHWM); False where that is not possible."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        return True
    except OSError:
        return False


def _rss_kib(field):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    raise LookupError(field)


def test_resample_reads_a_c_contiguous_float32_array_without_copying_it(rng):
    n = 2048
    src = rng.uniform(size=(n, n, 3)).astype(np.float32)  # 48 MiB, every page resident
    if not _peak_rss_reset():
        pytest.skip("the peak resident size cannot be reset here (/proc/self/clear_refs)")
    before = _rss_kib("VmRSS")
    got = splinefig.resample(src, size=(2, 2), filter="box", threads=1)
    grew = _rss_kib("VmHWM") - before
    assert grew < src.nbytes // 1024 // 4, f"resident size grew by {grew} KiB: the array was copied"
    # The copying path (a Fortran-order array) shows in the same measurement, and gives the same bits.
    fortran = np.asfortranarray(src)
    assert _peak_rss_reset()
    before = _rss_kib("VmRSS")
    assert np.array_equal(splinefig.resample(fortran, size=(2, 2), filter="box", threads=1), got)
    assert _rss_kib("VmHWM") - before > src.nbytes // 1024 // 2


def test_resample_in_place_gives_the_bits_of_the_librarys_own_image(rng):
    src = rng.uniform(-0.2, 1.2, size=(61, 43, 3)).astype(np.float32)
    own = splinefig.image_buffer(61, 43, 3)
    own[...] = src
    # Float32 data at an odd byte address: numpy allows it, the binding copies it to aligned memory.
    raw = bytearray(src.nbytes + 1)
    odd = np.frombuffer(raw, dtype=np.float32, count=src.size, offset=1).reshape(src.shape)
    odd[...] = src
    assert not odd.flags.aligned and odd.flags.c_contiguous
    for kw in (dict(size=(97, 29)), dict(size=(10, 140), filter="bspline", edge="wrap", interpolating=True),
               dict(scale=0.3, filter="lanczos3", edge="black")):
        want = splinefig.resample(own, **kw)
        assert np.array_equal(splinefig.resample(src, **kw), want)
        assert np.array_equal(splinefig.resample(odd, **kw), want)
        assert np.array_equal(splinefig.resample(src[7:], **kw), splinefig.resample(own[7:], **kw))
    assert np.array_equal(src, own)  # read, never written


def test_resample_releases_the_gil():
    # A second Python thread counts while the main thread is inside the call. With a switch
    # interval far longer than the test, the interpreter never takes the lock from the main
    # thread: between reading the count and reading it again after the call, the counter can
    # only move if the call itself let the lock go. No clock decides anything; a call that holds
    # the lock fails every attempt, one that releases it passes unless the counter thread was not
    # scheduled at all during any of the calls.
    src = np.random.default_rng(1).uniform(size=(512, 512, 3)).astype(np.float32)
    k = splinefig.Basis.catmull_rom().kernel()
    count = [0]
    stop = threading.Event()

    def counter():
        while not stop.is_set():
            count[0] += 1
            stop.wait(0.0002)  # blocks, and so lets the lock go, between counts

    old_interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    t = threading.Thread(target=counter)
    t.start()
    try:
        moved = []
        for _ in range(20):
            before = count[0]
            _core.resample(src, 1024, 1024, k, "clamp", False, 1)
            moved.append(count[0] - before)
            if moved[-1] > 0:
                break
    finally:
        stop.set()
        t.join()
        sys.setswitchinterval(old_interval)
    assert moved[-1] > 0, f"the counter thread never ran during a call ({len(moved)} calls)"


# ---- comparison ------------------------------------------------------------------------------

def _pair(rng, shape=(24, 32, 3)):
    a = rng.uniform(0, 1, size=shape).astype(np.float32)
    b = a.copy()
    b[3, 5, 1] += 0.25
    b[10:12, 20:23] -= np.float32(0.003)
    return a, b


def test_compare_has_openimageios_numbers(oiio, rng):
    a, b = _pair(rng)
    r = splinefig.compare(a, b, fail=0.01, warn=0.001)
    bufs = []
    for x in (a, b):
        buf = oiio.ImageBuf(oiio.ImageSpec(32, 24, 3, "float"))
        buf.set_pixels(oiio.ROI(), x)
        bufs.append(buf)
    ref = oiio.ImageBufAlgo.compare(bufs[0], bufs[1], 0.01, 0.001)
    assert r["mean_error"] == pytest.approx(ref.meanerror, rel=1e-6)
    assert r["rms_error"] == pytest.approx(ref.rms_error, rel=1e-6)
    assert r["psnr"] == pytest.approx(ref.PSNR, rel=1e-6)
    assert r["max_error"] == pytest.approx(ref.maxerror, rel=1e-6)
    assert r["max_pixel"] == (ref.maxx, ref.maxy) and r["max_channel"] == ref.maxc
    assert (r["nfail"], r["nwarn"]) == (ref.nfail, ref.nwarn) == (1, 7)
    assert r["verdict"] == "failure"
    assert splinefig.compare(a, a)["verdict"] == "match"
    # idiff 2.4 checks the failures first: none over `fail`, so no warning either.
    assert splinefig.compare(a, b, fail=0.3, warn=0.001)["verdict"] == "match"
    assert splinefig.compare(a, b, fail=0.01, warn=0.001, hardwarn=0.1, failpercent=5, warnpercent=5)["verdict"] == "warning"
    assert splinefig.compare(a, b, fail=0.01, failpercent=1, warnpercent=1)["verdict"] == "match"


def _ssim(a, b):
    """Wang et al. 2004 from the definition: luminance, 11x11 Gaussian (sigma 1.5), valid."""
    def lum(x):
        return x[..., 0] * 0.2126 + x[..., 1] * 0.7152 + x[..., 2] * 0.0722
    g = np.exp(-((np.arange(11) - 5) ** 2) / (2 * 1.5**2))
    win = np.outer(g, g) / np.outer(g, g).sum()
    from numpy.lib.stride_tricks import sliding_window_view as view
    def conv(x):
        return np.einsum("ijkl,kl->ij", view(x, (11, 11)), win)
    x, y = lum(a.astype(np.float64)), lum(b.astype(np.float64))
    mx, my = conv(x), conv(y)
    sxx, syy, sxy = conv(x * x) - mx**2, conv(y * y) - my**2, conv(x * y) - mx * my
    c1, c2 = 0.01**2, 0.03**2
    return np.mean((2 * mx * my + c1) * (2 * sxy + c2) / ((mx**2 + my**2 + c1) * (sxx + syy + c2)))


def test_compare_ssim_from_its_definition(rng):
    a = rng.uniform(0, 1, size=(40, 50, 3)).astype(np.float32)
    b = np.clip(a + rng.normal(0, 0.05, size=a.shape), 0, 1).astype(np.float32)
    r = splinefig.compare(a, b, perceptual=True)
    assert r["ssim"] == pytest.approx(_ssim(a, b), abs=1e-6)
    assert 0 < r["flip_mean"] <= r["flip_max"] <= 1
    assert splinefig.compare(a, a, perceptual=True)["flip_mean"] == 0
    assert splinefig.compare(a, b, ssim=0.9999)["verdict"] == "failure"
    assert splinefig.compare(a[:8, :8], b[:8, :8], perceptual=True)["ssim"] is None  # under 11 x 11


def test_compare_files_is_the_clis(cli, tmp_path, rng):
    a, b = _pair(rng, (30, 30, 4))
    a[..., 3] = b[..., 3] = 1
    pa, pb = tmp_path / "a.png", tmp_path / "b.png"
    splinefig.write_image(pa, a, encoding="srgb")
    splinefig.write_image(pb, b, encoding="srgb")
    for flags, kw in ((["--fail", "0.01"], dict(fail=0.01)), (["--perceptual", "--linear"], dict(perceptual=True, linear=True)),
                      (["--shift", "1", "--ignore-alpha"], dict(shift=1, ignore_alpha=True))):
        run = cli(["diff", "--json"] + flags + [pa, pb], check=False)
        r = splinefig.compare(str(pa), str(pb), **kw)
        assert r["json"] == run.stdout
        assert {"match": 0, "warning": 1, "failure": 2}[r["verdict"]] == run.returncode
        assert json.loads(r["json"])  # valid JSON


def test_difference_and_triptych_pictures(rng, tmp_path):
    a, b = _pair(rng)
    d = splinefig.difference_image(a, b, scale=2)
    np.testing.assert_array_equal(d, np.abs(a - b) * 2)
    t = splinefig.triptych(a, b)
    assert t.shape[0] == 24 and t.shape[1] == 3 * 32 + 4 and t.shape[2] == 3
    splinefig.write_image(tmp_path / "t.png", t, encoding="srgb")
    back = splinefig.read_image(tmp_path / "t.png")
    assert np.max(np.abs(back - t)) <= 0.5 / 255 + 1e-7


def test_image_files_round_trip(oiio, tmp_path, rng):
    a = rng.uniform(0, 1, size=(7, 9, 4)).astype(np.float32)
    splinefig.write_image(tmp_path / "a.exr", a)
    assert np.array_equal(splinefig.read_image(tmp_path / "a.exr"), a)
    assert np.array_equal(oiio_read(oiio, tmp_path / "a.exr"), a)
    img, enc = splinefig.read_image(tmp_path / "a.exr", return_encoding=True)
    assert enc == "linear"
