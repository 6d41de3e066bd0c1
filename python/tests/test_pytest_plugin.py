"""The pytest plugin, run on small test files by pytester: baselines written on request,
matches pass, differences fail with artefacts and a summary, missing baselines fail."""
import os

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
    d = results / "test_square"
    assert sorted(os.listdir(d)) == ["actual.png", "diff.png", "expected.png", "triptych.png"]
    trip = splinefig.read_image(d / "triptych.png")
    assert trip.shape == (16, 3 * 24 + 4, 3)
    diff = splinefig.read_image(d / "diff.png")
    assert diff.max() == 1 and diff[0, 0].max() == 0  # scaled by 1 / max error
    assert sorted(os.listdir(results / "test_exr")) == ["actual.exr", "diff.png", "expected.exr", "triptych.png"]


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
