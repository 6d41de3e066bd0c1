"""docs/python.md: its python blocks run in order in one namespace (in a scratch directory),
and its pytest example passes with the plugin once its baselines are written."""
import os
import re

import pytest

from conftest import SOURCE_DIR

DOC = os.path.join(SOURCE_DIR, "docs", "python.md")


def _blocks():
    with open(DOC, encoding="utf-8") as f:
        return re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)


def test_the_walkthrough_runs(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    pytest.importorskip("scipy.ndimage")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    blocks = [b for b in _blocks() if not b.startswith("# test_")]
    assert len(blocks) >= 6
    ns = {"__name__": "walkthrough"}
    for i, code in enumerate(blocks):
        exec(compile(code, f"{DOC} python block {i + 1}", "exec"), ns)
    for png in ("kernels.png", "resample.png", "scene.png", "triptych.png"):
        assert (tmp_path / png).stat().st_size > 0


def test_the_pytest_example_passes(pytester):
    tests = [b for b in _blocks() if b.startswith("# test_")]
    assert len(tests) == 1
    name = tests[0].splitlines()[0][2:].strip()
    pytester.makepyfile(**{name[:-3]: tests[0]})
    pytester.runpytest("-p", "splinefig.pytest_plugin", "--splinefig-update").assert_outcomes(passed=2)
    pytester.runpytest("-p", "splinefig.pytest_plugin").assert_outcomes(passed=2)
