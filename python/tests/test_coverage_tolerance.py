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
    images, reports = [], []
    for tolerance in (1.0 / 1024, 0.0):
        s = splinefig.Scene(128, 128, background=(0, 0, 0, 0), coverage_tolerance=tolerance)
        assert s.raster_report is None
        s.polyline([(0, 0), (3, 3)], color=(1, 0, 0, 1), width=1.0)  # item 0: a short line, swept exactly
        s.polyline(points, color=(1, 1, 1, 1), width=1.0)  # item 1: dense
        images.append(s.render())
        reports.append(s.raster_report)
    dense, exact = images
    # The report says which item was drawn from its pieces (128 rows: 8 bands of 16), and that
    # nothing was at tolerance 0.
    r = reports[0]
    assert r.tolerance == 1.0 / 1024 and r.band_rows == 16 and not r.exact
    assert [i.index for i in r.items] == [1] and r.items[0].bands == 8 and 1 <= r.items[0].piece_bands <= 8
    assert reports[1].exact and reports[1].tolerance == 0
    alpha = exact[..., 3]
    # The stroke is dense: most pixels solid, some between.
    assert (alpha == 1).mean() > 0.5 and ((alpha > 0) & (alpha < 1)).sum() > 100
    assert np.abs(dense - exact).max() <= 1e-6
