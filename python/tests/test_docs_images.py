"""docs/images' pictures of the Python package are what the documented code draws today: each is
drawn again by scripts/docs-images (docs/python.md's walkthrough, python/bench/matplotlib_images.py)
and held to the file in docs/images, within a tolerance for a font or matplotlib build that
differs slightly."""
import importlib.machinery
import importlib.util
import os

import numpy as np
import pytest

from conftest import SOURCE_DIR

IMAGES = os.path.join(SOURCE_DIR, "docs", "images")


def _script():
    path = os.path.join(SOURCE_DIR, "scripts", "docs-images")
    loader = importlib.machinery.SourceFileLoader("docs_images", path)
    spec = importlib.util.spec_from_loader("docs_images", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def _rgb(path):
    from PIL import Image

    with Image.open(path) as im:
        return np.asarray(im.convert("RGB")).astype(np.int16)


def _assert_same_picture(drawn, kept):
    """The same size; a mean difference under 0.05 levels and no more than 0.02% of the pixels
    off by more than 8 levels: a rounding or an antialiased edge's shade may differ, a line one
    pixel wider (0.09% of python-kernels.png) or a moved text may not."""
    a, b = _rgb(drawn), _rgb(kept)
    name = os.path.basename(kept)
    assert a.shape == b.shape, f"{name}: docs/images has {b.shape[1]}x{b.shape[0]}, the code draws {a.shape[1]}x{a.shape[0]}"
    d = np.abs(a - b).max(axis=2)
    off = float((d > 8).mean())
    assert d.mean() < 0.05 and off <= 0.0002, (
        f"{name}: docs/images differs from what the documented code draws (mean {d.mean():.3f} levels, "
        f"{100 * off:.2f}% of the pixels off by more than 8, max {int(d.max())}): run scripts/docs-images")


@pytest.fixture(scope="module")
def docs_images():
    pytest.importorskip("matplotlib", reason="matplotlib is not installed: docs/images was not checked against the code")
    pytest.importorskip("scipy.ndimage", reason="SciPy is not installed: docs/images was not checked against the code")
    pytest.importorskip("PIL", reason="Pillow is not installed: docs/images was not checked against the code")
    return _script()


def test_the_walkthrough_pictures_are_what_its_code_draws(docs_images, tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    written = docs_images.walkthrough(str(tmp_path))
    assert sorted(os.path.basename(p) for p in written) == ["python-kernels.png", "python-resample.png"]
    for path in written:
        _assert_same_picture(path, os.path.join(IMAGES, os.path.basename(path)))


def test_the_matplotlib_comparisons_are_what_the_script_draws(docs_images, tmp_path):
    written = docs_images.matplotlib_figures(str(tmp_path))
    assert sorted(os.path.basename(p) for p in written) == ["matplotlib-lines.png", "matplotlib-text.png"]
    for path in written:
        _assert_same_picture(path, os.path.join(IMAGES, os.path.basename(path)))


def test_every_picture_of_the_python_docs_is_one_the_script_draws():
    # docs/python.md and docs/matplotlib.md show no picture of docs/images that the script does not make.
    import re

    script = _script()
    made = set(script.WALKTHROUGH_IMAGES.values()) | set(script.MATPLOTLIB_IMAGES)
    for doc in ("python.md", "matplotlib.md"):
        with open(os.path.join(SOURCE_DIR, "docs", doc), encoding="utf-8") as f:
            shown = set(re.findall(r"\]\(images/([^)]+)\)", f.read()))
        assert shown <= made, f"docs/{doc} shows {sorted(shown - made)}, which scripts/docs-images does not draw"
