"""pytest plugin: image tests against baselines, in pytest-mpl's spirit.

Enable it with ``pytest -p splinefig.pytest_plugin`` (an installed splinefig enables it through
its entry point). A test asks for the ``splinefig_image`` fixture and checks an image: an
array, an image file, or a figure spec (``.toml``) to render::

    def test_square(splinefig_image):
        scene = splinefig.Scene(32, 32).fill([(8, 8), (24, 8), (24, 24), (8, 24)], color="#3366cc")
        splinefig_image.check(scene.render())              # baseline: baseline/test_square.png

    @pytest.mark.splinefig(fail=0.004, failpercent=0.1)     # options of splinefig.compare
    def test_bias(splinefig_image):
        splinefig_image.check(splinefig.render_figure("bias"), name="bias.png")

Baselines live in ``baseline/`` next to the test file (``--splinefig-baseline-dir`` or the
marker's ``baseline_dir=`` say otherwise). A ``.png`` baseline is compared with the actual
image written as an 8-bit PNG, exactly as ``splinefig diff actual.png baseline.png`` compares;
a ``.exr`` one in float. An array is linear light (float32 or float64), or sRGB values with
straight alpha (uint8 or uint16, a PIL array or a PNG's codes), decoded with the sRGB curve.
``--splinefig-update`` writes the baselines instead of comparing.

A failed check keeps its evidence: ``actual``, ``expected`` (the baseline's bytes), ``diff`` and
``triptych`` (expected | actual | diff) images in ``<results>/<test node id>/``, where
<results> is ``.splinefig-results/`` under pytest's rootdir or ``--splinefig-results DIR``; the
failure message names them by absolute path, and the end of the run lists the failures. A
passing check writes nothing.
"""
from __future__ import annotations

import hashlib
import os
import re
import shutil
import tempfile
from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import pytest

import splinefig

_OPTIONS = set(splinefig._COMPARE_DEFAULTS) | {"baseline_dir"}


def pytest_addoption(parser):
    g = parser.getgroup("splinefig", "image comparison with splinefig")
    g.addoption("--splinefig-update", action="store_true", default=False,
                help="write the baselines of image checks instead of comparing with them")
    g.addoption("--splinefig-results", metavar="DIR", default=None,
                help="where failed image checks leave their actual, expected, diff and triptych images, "
                     "DIR/<test node id>/ (default: .splinefig-results/ under the rootdir)")
    g.addoption("--splinefig-baseline-dir", metavar="DIR", default=None,
                help="the baseline directory (default: baseline/ next to each test file)")


class _State:
    def __init__(self) -> None:
        self.failures: List[tuple] = []
        self.updated: List[str] = []


def pytest_configure(config):
    config.addinivalue_line("markers", "splinefig(**options): options of the splinefig_image fixture's "
                            "checks (baseline_dir= and the keyword arguments of splinefig.compare)")
    config._splinefig = _State()


def _stem(nodeid: str) -> str:
    name = nodeid.split("::")[-1]
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_")


def _node_dir(nodeid: str) -> str:
    """The test node id as one directory name: 'tests/test_a.py::test_b[x/y]' gives
    'tests_test_a.py_test_b_x_y'; a long one is cut and keeps a hash of the whole id."""
    name = re.sub(r"[^A-Za-z0-9_.-]+", "_", nodeid).strip("_.") or "test"
    if len(name) > 120:
        name = name[:100] + "-" + hashlib.sha1(nodeid.encode()).hexdigest()[:12]
    return name


def _results_root(config) -> str:
    root = config.getoption("splinefig_results")
    if root:
        return os.path.abspath(os.path.join(str(config.invocation_params.dir), root))
    return os.path.join(str(config.rootpath), ".splinefig-results")


class ImageCheck:
    """The ``splinefig_image`` fixture: ``check(image, name=None, **options)``."""

    def __init__(self, request) -> None:
        self._request = request
        self._config = request.config
        marker = request.node.get_closest_marker("splinefig")
        self._marker = dict(marker.kwargs) if marker else {}
        unknown = set(self._marker) - _OPTIONS
        if unknown:
            raise pytest.UsageError(f"@pytest.mark.splinefig: unknown option {', '.join(sorted(unknown))}")
        self._count = 0

    def baseline_dir(self) -> str:
        d = self._marker.get("baseline_dir") or self._config.getoption("splinefig_baseline_dir")
        test_dir = os.path.dirname(str(self._request.node.fspath))
        return os.path.join(test_dir, d) if d else os.path.join(test_dir, "baseline")

    def check(self, image: Any, name: Optional[str] = None, **options: Any) -> dict:
        """Compares `image` (an array: linear float, or sRGB uint8/uint16 with straight alpha; an
        image file; or a .toml spec) with the baseline `name`
        (default: the test's name, .png); returns splinefig.compare's result. Fails the test
        on a "failure" verdict; warnings pass."""
        actual = self._actual(image)
        if name is None:
            self._count += 1
            name = _stem(self._request.node.nodeid) + ("" if self._count == 1 else f"-{self._count}") + ".png"
        ext = os.path.splitext(name)[1].lower()
        if ext not in (".png", ".exr"):
            raise ValueError(f"name: baseline '{name}' is not .png or .exr")
        opts = {k: v for k, v in self._marker.items() if k != "baseline_dir"}
        opts.update(options)
        baseline = os.path.join(self.baseline_dir(), name)
        state = self._config._splinefig
        if self._config.getoption("splinefig_update"):
            os.makedirs(os.path.dirname(baseline), exist_ok=True)
            splinefig.write_image(baseline, actual)
            state.updated.append(baseline)
            return {"verdict": "match", "updated": baseline}
        if not os.path.isfile(baseline):
            pytest.fail(f"splinefig: baseline {baseline} is missing (run pytest with --splinefig-update to write it)",
                        pytrace=False)
        with tempfile.TemporaryDirectory() as tmp:
            written = os.path.join(tmp, "actual" + ext)
            splinefig.write_image(written, actual)
            result = splinefig.compare(baseline, written, **opts)
            if result["verdict"] != "failure":
                return result
            where, kept = self._artefacts(baseline, written, result, ext)
        # The report names the kept copy of the actual image, not the scratch file just removed.
        text = result["text"].replace(written, kept["actual"])
        line = (f"{name}: max error {result['max_error']:.6g} at {result['max_pixel']}, "
                f"{result['nfail']} of {result['npels']} pixels over fail={opts.get('fail', 1e-6):g}"
                + "".join(f"; {f}" for f in result["failures"]))
        state.failures.append((self._request.node.nodeid, line, where))
        files = "".join(f"\n    {k + ':':10}{v}" for k, v in kept.items())
        pytest.fail(f"splinefig image check failed: {line}\n  artefacts: {where}{files}\n{text}", pytrace=False)

    def _actual(self, image: Any) -> np.ndarray:
        if isinstance(image, (str, os.PathLike)):
            path = os.fspath(image)
            if path.endswith(".toml"):
                return splinefig.render_spec(path)
            return splinefig.read_image(path, linear=True)
        return splinefig._image(image, "image", srgb_ints=True)

    def _artefacts(self, baseline: str, written: str, result: dict, ext: str) -> Tuple[str, Dict[str, str]]:
        """Keeps a failure's images in <results>/<node id>/ (what an earlier failure of the
        test left there is replaced); returns the directory and the files by role."""
        d = os.path.join(_results_root(self._config), _node_dir(self._request.node.nodeid))
        if os.path.isdir(d) and not os.path.islink(d):
            shutil.rmtree(d)
        os.makedirs(d, exist_ok=True)
        kept = {"expected": os.path.join(d, "expected" + ext), "actual": os.path.join(d, "actual" + ext),
                "diff": os.path.join(d, "diff.png"), "triptych": os.path.join(d, "triptych.png")}
        shutil.copyfile(baseline, kept["expected"])
        shutil.copyfile(written, kept["actual"])
        # The pictures of the images as compared (union window and channels), scaled so that
        # the largest difference is white (diff) or the top of the colour map (triptych).
        a, b, srgb, scale = result["_a"], result["_b"], result["_srgb"], result["_scale"]
        splinefig.write_image(kept["diff"], splinefig.difference_image(a, b, scale=scale), encoding="srgb")
        splinefig.write_image(kept["triptych"], splinefig._core.triptych(a, srgb, b, srgb, scale), encoding="srgb")
        return d, kept


@pytest.fixture
def splinefig_image(request) -> ImageCheck:
    """Checks images against baselines (see splinefig.pytest_plugin)."""
    return ImageCheck(request)


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    state = getattr(config, "_splinefig", None)
    if state is None:
        return
    if state.updated:
        terminalreporter.section("splinefig baselines written")
        for p in state.updated:
            terminalreporter.write_line(p)
    if state.failures:
        terminalreporter.section("splinefig image check failures")
        for nodeid, line, where in state.failures:
            terminalreporter.write_line(f"{nodeid}: {line} [{where}]")
