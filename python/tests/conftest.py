"""Shared fixtures: the CLI binary (the same bits the module must give), a numpy random source,
and the peers (SciPy, OpenImageIO's Python bindings) as imports that skip when missing."""
import os
import shutil
import subprocess

import numpy as np
import pytest

pytest_plugins = ["pytester"]

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.normpath(os.path.join(HERE, "..", ".."))


def _find_cli():
    exe = os.environ.get("SPLINEFIG_EXE")
    if exe:
        return exe if os.access(exe, os.X_OK) else None
    import splinefig
    # The build tree: build/python/splinefig/_core*.so next to build/cli/splinefig.
    cand = os.path.normpath(os.path.join(os.path.dirname(splinefig.__file__), "..", "..", "cli", "splinefig"))
    return cand if os.access(cand, os.X_OK) else shutil.which("splinefig")


@pytest.fixture(scope="session")
def cli():
    """run(args, input=None) -> CompletedProcess of the splinefig CLI; skips when it is missing."""
    exe = _find_cli()
    if not exe:
        pytest.skip("the splinefig CLI was not found (set SPLINEFIG_EXE)")

    def run(args, input=None, check=True):
        return subprocess.run([exe] + [str(a) for a in args], input=input, capture_output=True, text=True, check=check)

    run.exe = exe
    return run


@pytest.fixture
def rng():
    return np.random.default_rng(20261201)


@pytest.fixture(scope="session")
def scipy_interpolate():
    return pytest.importorskip("scipy.interpolate")


@pytest.fixture(scope="session")
def oiio():
    return pytest.importorskip("OpenImageIO")


def parse_csv(text):
    """The CLI's CSV points, parsed back exactly (it prints shortest round-trip doubles)."""
    rows = [[float(v) for v in line.split(",")] for line in text.splitlines() if line.strip()]
    return np.array(rows, dtype=np.float64)


def csv_of(points):
    return "".join(",".join(repr(float(v)) for v in p) + "\n" for p in np.asarray(points))
