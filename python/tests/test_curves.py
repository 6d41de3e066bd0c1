"""Curve evaluation, arc length and interpolation: pinned to SciPy's BSpline and
make_interp_spline, the memo's matrix form evaluated here, and the CLI (the same bits)."""
import numpy as np
import pytest

import splinefig
from splinefig import Basis

from conftest import csv_of, parse_csv


@pytest.fixture
def knots(rng):
    return rng.uniform(-10, 10, size=(9, 2))


def test_open_bspline_is_scipys_bspline(scipy_interpolate, knots):
    n, grain = len(knots), 8
    ours = splinefig.evaluate(knots, "bspline", grain=grain)
    assert ours.shape == ((n - 3) * grain + 1, 2)
    ref = scipy_interpolate.BSpline(np.arange(n + 4, dtype=float), knots, 3)
    t = np.arange((n - 3) * grain + 1) / grain
    np.testing.assert_allclose(ours, ref(t + 3), rtol=0, atol=1e-12)
    for d in (1, 2):
        np.testing.assert_allclose(splinefig.evaluate(knots, "bspline", grain=grain, derivative=d),
                                   ref.derivative(d)(t + 3), rtol=0, atol=1e-11)


def test_catmull_rom_is_the_memos_matrix_form(knots):
    M = np.array([[-1, 3, -3, 1], [2, -5, 4, -1], [-1, 0, 1, 0], [0, 2, 0, 0]]) / 2  # the memo's C
    grain = 5
    ours = splinefig.evaluate(knots, Basis.catmull_rom(), grain=grain)
    rows = []
    for i in range(len(knots) - 3):
        for j in range(grain):
            u = j / grain
            rows.append(np.array([u**3, u**2, u, 1]) @ M @ knots[i:i + 4])
    rows.append(np.array([1, 1, 1, 1]) @ M @ knots[-4:])
    np.testing.assert_allclose(ours, np.array(rows), rtol=0, atol=1e-12)
    # Interpolating: the pieces' ends are the inner knots.
    np.testing.assert_allclose(ours[::grain], knots[1:-1], rtol=0, atol=1e-13)


@pytest.mark.parametrize("basis", ["bspline", "catmull-rom", "beta:b1=2,b2=3", "uniform-bspline:degree=5"])
@pytest.mark.parametrize("ends", ["open", "double", "closed"])
def test_evaluate_is_the_clis(cli, knots, basis, ends):
    for d in (0, 1, 2):
        want = parse_csv(cli(["eval", "--basis", basis, "--grain", "7", "--ends", ends, "--derivative", d],
                             input=csv_of(knots)).stdout)
        assert np.array_equal(splinefig.evaluate(knots, basis, grain=7, ends=ends, derivative=d), want)


def test_evaluate_any_dimension_and_out(rng):
    k = rng.normal(size=(6, 5))
    p = splinefig.evaluate(k, "bspline", grain=3)
    assert p.shape == (3 * 3 + 1, 5)
    out = np.empty((splinefig.sample_count(k, "bspline", grain=3), 5))
    assert splinefig.evaluate(k, "bspline", grain=3, out=out) is out and np.array_equal(out, p)
    assert np.array_equal(splinefig.evaluate(k.tolist(), "bspline", grain=3), p)


def test_arclength_points_on_a_line_are_evenly_spaced():
    # Collinear, evenly spaced knots: the B-spline is the line at constant speed.
    k = np.stack([np.arange(8.0), 2 * np.arange(8.0)], axis=1)
    p, t = splinefig.arclength_points(k, "bspline", count=11, return_parameters=True)
    want = np.linspace(1, 6, 11)
    np.testing.assert_allclose(p, np.stack([want, 2 * want], axis=1), rtol=0, atol=1e-12)
    np.testing.assert_allclose(t, np.linspace(0, 5, 11), rtol=0, atol=1e-12)
    assert splinefig.arclength(k, "bspline") == pytest.approx(5 * np.sqrt(5), rel=1e-14)


def test_arclength_is_scipys_quadrature_of_the_speed(scipy_interpolate, knots):
    from scipy.integrate import quad
    n = len(knots)
    speed = scipy_interpolate.BSpline(np.arange(n + 4, dtype=float), knots, 3).derivative()
    total = sum(quad(lambda x: np.hypot(*speed(x)), a, a + 1, epsabs=0, epsrel=1e-13, limit=200)[0] for a in range(3, n))
    assert splinefig.arclength(knots, "bspline") == pytest.approx(total, rel=1e-11)
    p, t = splinefig.arclength_points(knots, "bspline", count=6, return_parameters=True)
    for j in range(1, 5):  # the length from 0 to t_j is j/5 of the total
        s = quad(lambda x: np.hypot(*speed(x)), 3, 3 + t[j], epsabs=0, epsrel=1e-13, limit=400)[0]
        assert s == pytest.approx(total * j / 5, rel=1e-9)


@pytest.mark.parametrize("spacing", ["arclength", "polygon"])
def test_arclength_points_are_the_clis(cli, knots, spacing):
    # --grain is the polygon method's; the CLI refuses it with arclength, where it has no effect.
    grain = ["--grain", 9] if spacing == "polygon" else []
    want = parse_csv(cli(["eval", "--basis", "catmull-rom", "--spacing", spacing, "--count", 13] + grain,
                         input=csv_of(knots)).stdout)
    method = "accurate" if spacing == "arclength" else "polygon"
    assert np.array_equal(splinefig.arclength_points(knots, "catmull-rom", count=13, method=method, grain=9), want)


@pytest.fixture
def data(rng):
    return rng.uniform(-5, 5, size=(8, 3))


def _scipy_curve(si, data, grain, bc):
    n = len(data) - 1
    return si.make_interp_spline(np.arange(n + 1.0), data, k=3, bc_type=bc)(np.arange(n * grain + 1) / grain)


def test_relaxed_interpolation_is_scipys_natural_spline(scipy_interpolate, data):
    ours = splinefig.interpolate(data, grain=6)
    np.testing.assert_allclose(ours, _scipy_curve(scipy_interpolate, data, 6, "natural"), rtol=0, atol=1e-12)


def test_clamped_interpolation_is_scipys(scipy_interpolate, data):
    v, w = np.array([1.0, -2.0, 0.5]), np.array([0.0, 3.0, -1.0])
    ours = splinefig.interpolate(data, ends="clamped", start_velocity=v, end_velocity=w, grain=6)
    ref = _scipy_curve(scipy_interpolate, data, 6, ([(1, v)], [(1, w)]))
    np.testing.assert_allclose(ours, ref, rtol=0, atol=1e-12)


def test_periodic_interpolation_is_scipys(scipy_interpolate, data):
    data[-1] = data[0]
    ours = splinefig.interpolate(data, ends="periodic", grain=6)
    np.testing.assert_allclose(ours, _scipy_curve(scipy_interpolate, data, 6, "periodic"), rtol=0, atol=1e-12)


def test_interpolation_outputs(scipy_interpolate, data):
    n = len(data) - 1
    b = splinefig.interpolate(data, output="bspline")
    assert b.shape == (n + 1, 3)
    # The joints S_i = (B_{i-1} + 4 B_i + B_{i+1}) / 6, ends B_0 = S_0, B_n = S_n (relaxed).
    np.testing.assert_allclose((b[:-2] + 4 * b[1:-1] + b[2:]) / 6, data[1:-1], atol=1e-12)
    z = splinefig.interpolate(data, output="bezier")
    assert z.shape == (n, 4, 3)
    np.testing.assert_array_equal(z[:, 0], data[:-1])
    np.testing.assert_array_equal(z[:, 3], data[1:])
    ref = scipy_interpolate.make_interp_spline(np.arange(n + 1.0), data, k=3, bc_type="natural")
    np.testing.assert_allclose(3 * (z[:, 1] - z[:, 0]), ref.derivative()(np.arange(n)), atol=1e-11)


@pytest.mark.parametrize("output", ["curve", "bspline", "bezier"])
@pytest.mark.parametrize("ends", ["relaxed", "clamped", "periodic"])
def test_interpolate_is_the_clis(cli, data, output, ends):
    if ends == "periodic":
        data[-1] = data[0]
    # --grain is for --output curve only (the CLI refuses it elsewhere, where it has no effect).
    args = ["interp", "--ends", ends, "--output", output] + (["--grain", 5] if output == "curve" else [])
    kw = {}
    if ends == "clamped":
        args += ["--start-velocity", "1,2,3", "--end-velocity", "-1,0,0.5"]
        kw = dict(start_velocity=[1, 2, 3], end_velocity=[-1, 0, 0.5])
    want = parse_csv(cli(args, input=csv_of(data)).stdout)
    got = splinefig.interpolate(data, ends=ends, output=output, grain=5, **kw)
    assert np.array_equal(got.reshape(want.shape), want)
