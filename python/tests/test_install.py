"""`cmake --install` puts an importable package under the prefix, with the built-in specs
found from its place and the pytest plugin enabled by its entry point."""
import os
import shutil
import subprocess
import sys

import pytest

import splinefig


def _build_dir():
    d = os.path.normpath(os.path.join(os.path.dirname(splinefig.__file__), "..", ".."))
    return d if os.path.isfile(os.path.join(d, "CMakeCache.txt")) else None


def test_an_installed_package_imports_renders_and_plugs_in(tmp_path):
    build = _build_dir()
    if build is None:
        pytest.skip("splinefig is not imported from a build tree")
    cmake = shutil.which("cmake")
    if cmake is None:
        pytest.skip("cmake is not installed")
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", build, "--prefix", str(prefix)], check=True, capture_output=True)
    sites = [os.path.join(root) for root, dirs, _ in os.walk(prefix) if "splinefig" in dirs
             and os.path.isfile(os.path.join(root, "splinefig", "__init__.py"))]
    assert len(sites) == 1, sites
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SPLINEFIG_SPECS_DIR")}
    env["PYTHONPATH"] = sites[0]
    code = ("import splinefig, importlib.metadata as m; "
            "assert splinefig.__file__.startswith(%r), splinefig.__file__; "
            "print(splinefig.render_figure('bias').shape); "
            "print(sorted(e.value for e in m.entry_points(group='pytest11') if e.name.startswith('splinefig')))") % str(prefix)
    out = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path, check=True, capture_output=True, text=True).stdout
    assert out.splitlines() == ["(500, 800, 4)", "['splinefig.pytest_plugin']"]
    # Installed, the plugin needs no -p.
    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "test_fixture.py").write_text("def test_fixture(splinefig_image):\n    assert splinefig_image\n")
    for extra in ([], ["-p", "splinefig.pytest_plugin"]):  # and naming it as well does no harm
        r = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"] + extra + ["test_fixture.py"],
                           env=env, cwd=tmp_path / "t", capture_output=True, text=True)
        assert r.returncode == 0, r.stdout + r.stderr
