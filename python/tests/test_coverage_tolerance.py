"""Scene(coverage_tolerance=...): the default, its checks, and a dense stroke drawn at the default
tolerance (from its pieces, docs/renderer.md) against the same stroke swept exactly (0)."""
import numpy as np
import pytest

import splinefig


def test_default_and_checks():
    assert splinefig.Scene(8, 8).coverage_tolerance == 1.0 / 1024
    assert splinefig.Scene(8, 8, coverage_tolerance=0).coverage_tolerance == 0
    for bad in (-1e-9, 1.5, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="coverage_tolerance"):
            splinefig.Scene(8, 8, coverage_tolerance=bad)
    with pytest.raises(TypeError, match="coverage_tolerance"):
        splinefig.Scene(8, 8, coverage_tolerance="fine")


def test_dense_stroke_matches_the_exact_sweep():
    rng = np.random.default_rng(7)
    points = rng.uniform(-2, 130, size=(2500, 2))
    images = []
    for tolerance in (1.0 / 1024, 0.0):
        s = splinefig.Scene(128, 128, background=(0, 0, 0, 0), coverage_tolerance=tolerance)
        s.polyline(points, color=(1, 1, 1, 1), width=1.0)
        images.append(s.render())
    dense, exact = images
    alpha = exact[..., 3]
    # The stroke is dense: most pixels solid, some between.
    assert (alpha == 1).mean() > 0.5 and ((alpha > 0) & (alpha < 1)).sum() > 100
    assert np.abs(dense - exact).max() <= 1e-6
