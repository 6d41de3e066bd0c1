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
a ``.exr`` one in float. ``--splinefig-update`` writes the baselines instead of comparing;
``--splinefig-results DIR`` keeps actual / expected / diff / triptych images of every failure
under DIR/<test>/, and the end of the run lists the failures.
"""
from __future__ import annotations

import os
import re
import shutil
import tempfile
from typing import Any, List, Optional

import numpy as np
import pytest

import splinefig

_OPTIONS = set(splinefig._COMPARE_DEFAULTS) | {"baseline_dir"}


def pytest_addoption(parser):
    g = parser.getgroup("splinefig", "image comparison with splinefig")
    g.addoption("--splinefig-update", action="store_true", default=False,
                help="write the baselines of image checks instead of comparing with them")
    g.addoption("--splinefig-results", metavar="DIR", default=None,
                help="write actual, expected, diff and triptych images of failed image checks under DIR")
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
        """Compares `image` (an array, an image file or a .toml spec) with the baseline `name`
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
            where = self._artefacts(baseline, written, result, ext)
        line = (f"{name}: max error {result['max_error']:.6g} at {result['max_pixel']}, "
                f"{result['nfail']} of {result['npels']} pixels over fail={opts.get('fail', 1e-6):g}"
                + "".join(f"; {f}" for f in result["failures"]))
        state.failures.append((self._request.node.nodeid, line, where))
        pytest.fail("splinefig image check failed: " + line + (f"\n  artefacts: {where}" if where else "")
                    + "\n" + result["text"], pytrace=False)

    def _actual(self, image: Any) -> np.ndarray:
        if isinstance(image, (str, os.PathLike)):
            path = os.fspath(image)
            if path.endswith(".toml"):
                return splinefig.render_spec(path)
            return splinefig.read_image(path, linear=True)
        return splinefig._image(image, "image")

    def _artefacts(self, baseline: str, written: str, result: dict, ext: str) -> Optional[str]:
        root = self._config.getoption("splinefig_results")
        if not root:
            return None
        d = os.path.join(root, _stem(self._request.node.nodeid))
        os.makedirs(d, exist_ok=True)
        shutil.copyfile(written, os.path.join(d, "actual" + ext))
        shutil.copyfile(baseline, os.path.join(d, "expected" + ext))
        # The pictures of the images as compared (union window and channels), scaled so that
        # the largest difference is white (diff) or the top of the colour map (triptych).
        a, b, srgb, scale = result["_a"], result["_b"], result["_srgb"], result["_scale"]
        splinefig.write_image(os.path.join(d, "diff.png"), splinefig.difference_image(a, b, scale=scale), encoding="srgb")
        splinefig.write_image(os.path.join(d, "triptych.png"), splinefig._core.triptych(a, srgb, b, srgb, scale),
                              encoding="srgb")
        return d


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
            terminalreporter.write_line(f"{nodeid}: {line}" + (f" [{where}]" if where else ""))
