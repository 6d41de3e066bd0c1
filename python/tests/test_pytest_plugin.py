"""The pytest plugin, run on small test files by pytester: baselines written on request,
matches pass, differences fail with artefacts (kept by default, named by absolute path) and a
summary, missing baselines fail, uint8 and uint16 arrays are sRGB values."""
import os
import re

import numpy as np

import splinefig

TESTS = '''
import pytest
import splinefig

def square(colour):
    return splinefig.Scene(24, 16).fill([(4, 4), (20, 4), (20, 12), (4, 12)], color=colour).render()

def test_square(splinefig_image):
    splinefig_image.check(square(COLOUR))

@pytest.mark.splinefig(fail=0.5)
def test_tolerant(splinefig_image):
    splinefig_image.check(square(COLOUR), name="tolerant.png")

def test_exr(splinefig_image):
    splinefig_image.check(square(COLOUR), name="square.exr")
'''


def _write(pytester, colour):
    pytester.makepyfile(test_checked_images=TESTS.replace("COLOUR", repr(colour)))


def test_update_then_match(pytester):
    _write(pytester, "#3366cc")
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update")
    r.assert_outcomes(passed=3)
    r.stdout.fnmatch_lines(["*splinefig baselines written*"])
    base = pytester.path / "baseline"
    assert sorted(os.listdir(base)) == ["square.exr", "test_square.png", "tolerant.png"]
    png = splinefig.read_image(base / "test_square.png")
    assert png.shape == (16, 24, 4) and abs(png[8, 10, 2] - 0xcc / 255) < 1e-6
    pytester.runpytest("-p", "splinefig.pytest_plugin").assert_outcomes(passed=3)


def test_a_difference_fails_with_artefacts_and_a_summary(pytester):
    _write(pytester, "#3366cc")
    pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update").assert_outcomes(passed=3)
    _write(pytester, "#3366cd")
    results = pytester.path / "results"
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-results", str(results))
    r.assert_outcomes(passed=1, failed=2)  # fail=0.5 tolerates one code value
    r.stdout.fnmatch_lines(["*splinefig image check failures*",
                            "test_checked_images.py::test_square: test_square.png: max error 0.00392157 at (4, 4), 128 of 384 pixels*",
                            "test_checked_images.py::test_exr: square.exr: *"])
    d = results / "test_checked_images.py_test_square"
    assert sorted(os.listdir(d)) == ["actual.png", "diff.png", "expected.png", "triptych.png"]
    trip = splinefig.read_image(d / "triptych.png")
    assert trip.shape == (16, 3 * 24 + 4, 3)
    diff = splinefig.read_image(d / "diff.png")
    assert diff.max() == 1 and diff[0, 0].max() == 0  # scaled by 1 / max error
    assert sorted(os.listdir(results / "test_checked_images.py_test_exr")) == ["actual.exr", "diff.png", "expected.exr", "triptych.png"]


def test_a_missing_baseline_fails(pytester):
    _write(pytester, "#3366cc")
    r = pytester.runpytest("-p", "splinefig.pytest_plugin")
    r.assert_outcomes(failed=3)
    r.stdout.fnmatch_lines(["*baseline*test_square.png is missing (run pytest with --splinefig-update*"])


def test_specs_and_files_and_a_baseline_dir(pytester, tmp_path):
    spec = tmp_path / "fig.toml"
    spec.write_text('[canvas]\nwidth = 30\nheight = 20\n\n[[polyline]]\npoints = [[2, 2], [28, 18]]\nwidth = 2\n')
    pytester.makepyfile(test_spec=f'''
import pytest
@pytest.mark.splinefig(baseline_dir="refs")
def test_spec(splinefig_image):
    splinefig_image.check({str(spec)!r})
    splinefig_image.check({str(spec)!r})
''')
    pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update").assert_outcomes(passed=1)
    assert sorted(os.listdir(pytester.path / "refs")) == ["test_spec-2.png", "test_spec.png"]
    pytester.runpytest("-p", "splinefig.pytest_plugin").assert_outcomes(passed=1)
    # A file is checked as its linear pixels: the baseline itself matches.
    pytester.makepyfile(test_file=f'''
def test_file(splinefig_image):
    splinefig_image.check({str(pytester.path / "refs" / "test_spec.png")!r}, name="test_spec.png", baseline_dir=None)
''')
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-baseline-dir", "refs", "test_file.py")
    r.assert_outcomes(failed=1)  # baseline_dir is a marker option, not a check() option
    r.stdout.fnmatch_lines(["*unknown option baseline_dir*"])


def test_unknown_marker_option_is_a_usage_error(pytester):
    pytester.makepyfile(test_m='''
import pytest
@pytest.mark.splinefig(tolerance=1)
def test_m(splinefig_image):
    pass
''')
    r = pytester.runpytest("-p", "splinefig.pytest_plugin")
    assert r.ret != 0
    r.stdout.fnmatch_lines(["*unknown option tolerance*"])


def _paths_in(text):
    """Every absolute path the failure text names: quoted, or after 'artefacts:' or a role."""
    quoted = re.findall(r'"(/[^"]+)"', text)
    listed = re.findall(r"^ +(?:artefacts|expected|actual|diff|triptych): +(\S+)$", text, re.M)
    return quoted + listed


def test_a_failure_keeps_its_evidence_in_the_default_results_dir(pytester):
    _write(pytester, "#3366cc")
    pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update").assert_outcomes(passed=3)
    r = pytester.runpytest("-p", "splinefig.pytest_plugin")
    r.assert_outcomes(passed=3)
    assert not (pytester.path / ".splinefig-results").exists()  # a passing check writes nothing
    _write(pytester, "#3366cd")
    r = pytester.runpytest("-p", "splinefig.pytest_plugin")
    r.assert_outcomes(passed=1, failed=2)
    results = pytester.path / ".splinefig-results"  # pytest's rootdir here is pytester.path
    d = results / "test_checked_images.py_test_square"
    assert sorted(os.listdir(results)) == ["test_checked_images.py_test_exr", "test_checked_images.py_test_square"]
    assert sorted(os.listdir(d)) == ["actual.png", "diff.png", "expected.png", "triptych.png"]
    out = r.stdout.str()
    for role in ("expected", "actual", "diff", "triptych"):
        assert f"    {role + ':':10}{d / role}.png" in out
    assert f"  artefacts: {d}" in out
    assert f'Comparing "{pytester.path / "baseline" / "test_square.png"}" and "{d / "actual.png"}"' in out
    # Every path the failure names is absolute and still there after the run.
    named = _paths_in(out)
    assert len(named) >= 2 * 6
    for p in named:
        assert os.path.isabs(p) and os.path.exists(p), p
    # What was kept: the baseline's bytes, and the actual image as the check wrote it (#3366cd:
    # blue 0xcd inside the square, white outside), the triptych of the two and their difference.
    assert (d / "expected.png").read_bytes() == (pytester.path / "baseline" / "test_square.png").read_bytes()
    actual = splinefig.read_image(d / "actual.png")
    assert actual.shape == (16, 24, 4)
    assert round(float(actual[8, 10, 2]) * 255) == 0xcd and round(float(actual[0, 0, 2]) * 255) == 0xff
    assert splinefig.read_image(d / "triptych.png").shape == (16, 3 * 24 + 4, 3)
    assert splinefig.read_image(pytester.path / ".splinefig-results" / "test_checked_images.py_test_exr"
                                / "actual.exr").shape == (16, 24, 4)


def test_results_dir_is_under_the_rootdir_and_said_absolute(pytester, monkeypatch):
    # Started from a subdirectory, the default results go under the rootdir (where pytest.ini
    # is), and a relative --splinefig-results is taken from the starting directory and said
    # as an absolute path.
    pytester.makeini("[pytest]\n")
    _write(pytester, "#3366cc")
    pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update").assert_outcomes(passed=3)
    _write(pytester, "#3366cd")
    sub = pytester.mkdir("sub")
    monkeypatch.chdir(sub)
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "../test_checked_images.py::test_square")
    r.assert_outcomes(failed=1)
    d = pytester.path / ".splinefig-results" / "test_checked_images.py_test_square"
    assert sorted(os.listdir(d)) == ["actual.png", "diff.png", "expected.png", "triptych.png"]
    assert not (sub / ".splinefig-results").exists()
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-results", "res",
                           "../test_checked_images.py::test_square")
    r.assert_outcomes(failed=1)
    d = sub / "res" / "test_checked_images.py_test_square"
    assert f"  artefacts: {d}\n" in r.stdout.str() + "\n"
    assert f"[{d}]" in r.stdout.str()  # the summary at the end of the run
    assert (d / "actual.png").is_file()


def test_one_results_directory_per_test_node_id(pytester):
    # Tests of the same name in two files, and a parametrized test whose id holds a slash, each
    # keep their own images in one directory named by the sanitised node id.
    body = '''
import pytest
import splinefig

@pytest.mark.parametrize("colour", ["#3366cc/#3366cd"])
def test_same(splinefig_image, colour):
    c = colour.split("/")[BASE]
    splinefig_image.check(splinefig.Scene(8, 8).fill([(2, 2), (6, 2), (6, 6)], color=c).render(), name="same.png")
'''
    for d in ("one", "two"):
        pytester.mkpydir(d)
    (pytester.path / "one" / "test_x.py").write_text(body.replace("BASE", "0"))
    (pytester.path / "two" / "test_x.py").write_text(body.replace("BASE", "0"))
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update")
    r.assert_outcomes(passed=2)
    (pytester.path / "one" / "test_x.py").write_text(body.replace("BASE", "1"))
    r = pytester.runpytest("-p", "splinefig.pytest_plugin")
    r.assert_outcomes(passed=1, failed=1)
    (pytester.path / "two" / "test_x.py").write_text(body.replace("BASE", "1"))
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "two")
    r.assert_outcomes(failed=1)
    results = pytester.path / ".splinefig-results"
    names = ["one_test_x.py_test_same_3366cc_3366cd", "two_test_x.py_test_same_3366cc_3366cd"]
    assert sorted(os.listdir(results)) == names
    for n in names:
        assert sorted(os.listdir(results / n)) == ["actual.png", "diff.png", "expected.png", "triptych.png"]


def test_uint8_and_uint16_arrays_are_srgb_values(pytester):
    # A uint8 (PIL) or uint16 array holds sRGB codes with straight alpha: colour v / 255 (or
    # v / 65535) through the sRGB curve, times alpha. The values, worked by hand from the curve
    # ((v + 0.055) / 1.055) ** 2.4, v / 12.92 at or below 0.04045:
    #   128 -> 0.2158605, 10 -> 0.0030352698, 200 -> 0.5775804, and with alpha 128:
    #   0.2158605 * 128 / 255 = 0.1083537; uint16 32768 -> 0.2140482, 1000 -> 0.0011810388.
    # An .exr baseline of those linear values compares in float (fail=1e-6).
    pytester.makepyfile(test_ints='''
import numpy as np
import pytest
import splinefig

def linear():
    a = np.zeros((2, 3, 4), np.float32)
    a[0, 0] = [0.2158605, 0.0030352698, 0.5775804, 1]
    a[0, 1] = [0.1083537, 0.1083537, 0.1083537, 128 / 255]
    a[0, 2] = [0, 0, 0, 0]
    a[1, :] = [0.2140482, 0.0011810388, 1, 1]
    return a

def codes(dtype):
    a = np.zeros((2, 3, 4), dtype)
    a[0, 0] = [128, 10, 200, 255]
    a[0, 1] = [128, 128, 128, 128]
    a[0, 2] = [200, 200, 200, 0]
    if dtype == np.uint16:
        a[0] *= 257  # v / 255 == 257 v / 65535
        a[1, :] = [32768, 1000, 65535, 65535]
    else:
        a[1, :] = [0, 0, 0, 0]
    return a

def test_write(splinefig_image):
    splinefig_image.check(linear(), name="ints.exr")

def test_uint8(splinefig_image):
    a, b = codes(np.uint8), linear()
    a[1], b[1] = [255, 255, 255, 255], [1, 1, 1, 1]
    splinefig_image.check(b, name="u8.exr")  # ...and u8.exr is written by this check too
    splinefig_image.check(a, name="u8.exr")

def test_uint16(splinefig_image):
    splinefig_image.check(codes(np.uint16), name="ints.exr")

def test_uint8_one_code_off(splinefig_image):
    a = codes(np.uint8)
    a[1] = [255, 255, 255, 255]
    a[0, 0, 0] = 129
    splinefig_image.check(a, name="u8.exr")

def test_png(splinefig_image):
    # The PNG route: the uint8 codes come back as the same codes.
    a = np.full((4, 5, 3), 128, np.uint8)
    a[1, 2] = [0, 10, 255]
    splinefig_image.check(a, name="u8.png")

def test_other_ints(splinefig_image):
    with pytest.raises(TypeError, match="image: expected a float32 or float64 array, or a uint8 or uint16 one "
                                        "of sRGB values, got dtype int32"):
        splinefig_image.check(np.zeros((2, 2), np.int32))
''')
    r = pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update", "-k", "write or test_uint8 and not off")
    r.assert_outcomes(passed=2, deselected=4)
    png = np.full((4, 5, 3), 128, np.uint8)
    png[1, 2] = [0, 10, 255]
    splinefig.write_image(pytester.path / "baseline" / "u8.png", png / 255.0, encoding="srgb")
    r = pytester.runpytest("-p", "splinefig.pytest_plugin")
    r.assert_outcomes(passed=5, failed=1)
    # One code off: 129 -> 0.2195262 (by hand: ((129 / 255 + 0.055) / 1.055) ** 2.4), 0.0036657 more.
    r.stdout.fnmatch_lines(["*test_uint8_one_code_off: u8.exr: max error 0.0036657 at (0, 0), 1 of 6 pixels*"])
    kept = splinefig.read_image(pytester.path / ".splinefig-results" / "test_ints.py_test_uint8_one_code_off"
                                / "actual.exr")
    assert abs(float(kept[0, 0, 0]) - 0.2195262) < 1e-6


def test_resample_takes_uint8_and_uint16_as_srgb():
    # At the same size under the box filter, each pixel is itself: the decoded values, by hand.
    a = np.array([[[128, 10, 200, 255], [128, 128, 128, 128]]], np.uint8)
    want = np.array([[[0.2158605, 0.0030352698, 0.5775804, 1], [0.1083537, 0.1083537, 0.1083537, 128 / 255]]])
    for arr in (a, a.astype(np.uint16) * 257):
        out = splinefig.resample(arr, size=(2, 1), filter="box")
        assert out.dtype == np.float32 and out.shape == (1, 2, 4)
        assert np.abs(out - want).max() < 1e-6
    grey = splinefig.resample(np.array([[32768, 1000]], np.uint16), size=(2, 1), filter="box")
    assert grey.shape == (1, 2) and np.abs(grey - [0.2140482, 0.0011810388]).max() < 1e-6
