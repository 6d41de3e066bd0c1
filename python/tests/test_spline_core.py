"""Bases, kernels, the filter analysis: pinned to the memo's exact matrices and rationals,
SciPy's B-splines, closed-form transforms, and the CLI's report."""
from fractions import Fraction as F

import numpy as np
import pytest

import splinefig
from splinefig import Basis

from conftest import parse_csv


def test_the_memos_matrices_exactly():
    assert Basis.catmull_rom().matrix.tolist() == [[-0.5, 1.5, -1.5, 0.5], [1, -2.5, 2, -0.5], [-0.5, 0, 0.5, 0], [0, 1, 0, 0]]
    six = np.array([[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 0, 3, 0], [1, 4, 1, 0]])
    assert np.array_equal(Basis.bspline().matrix * 6, six)
    # C_a: Catmull-Rom is a = 1/2.
    a = 0.25
    ca = [[-a, 2 - a, a - 2, a], [2 * a, a - 3, 3 - 2 * a, -a], [-a, 0, a, 0], [0, 1, 0, 0]]
    assert Basis.cardinal(a).matrix.tolist() == ca
    assert Basis.cardinal(0.5) == Basis.catmull_rom()


def test_parse_and_constructors_agree():
    assert Basis.parse("beta:b1=1,b2=0").matrix.tolist() == Basis.beta(1, 0).matrix.tolist()
    assert np.array_equal(Basis.parse("beta:b1=1,b2=0").matrix, Basis.bspline().matrix)
    b = Basis.parse("beta:b1=2,b2=0")
    assert b.family == "beta" and b.degree == 3 and b.matrix.shape == (4, 4)
    assert Basis.parse(b.spec) == b
    assert Basis.uniform_bspline(5).matrix.shape == (6, 6)
    assert Basis.mitchell_netravali().family == "mitchell-netravali"
    assert Basis.tensioned_bspline(1.0).matrix.shape == (4, 4)
    assert "cardinal" in Basis.known()
    assert Basis.bspline().support == (-2.0, 2.0)
    assert {Basis.bspline(), Basis.parse("bspline")} == {Basis.bspline()}


def test_matrix_is_a_copy():
    b = Basis.bspline()
    m = b.matrix
    m[0, 0] = 99
    assert b.matrix[0, 0] != 99


# Exact values of the cubic basis functions (the memo's matrices, by hand).
EXACT = {
    "bspline": {0: F(2, 3), 1: F(1, 6), -1: F(1, 6), F(1, 2): F(23, 48), F(3, 2): F(1, 48), 2: 0, -2: 0},
    "catmull-rom": {0: 1, 1: 0, F(1, 2): F(9, 16), F(-1, 2): F(9, 16), F(3, 2): F(-1, 16), F(-3, 2): F(-1, 16)},
}


@pytest.mark.parametrize("spec", sorted(EXACT))
def test_kernel_values_are_the_exact_rationals(spec):
    xs = np.array([float(x) for x in EXACT[spec]])
    got = splinefig.kernel(spec, xs)
    want = np.array([float(v) for v in EXACT[spec].values()])
    np.testing.assert_allclose(got, want, rtol=2e-16, atol=1e-17)  # the rationals to one rounding


def test_kernel_keeps_any_shape_and_takes_lists_and_scalars():
    x = np.linspace(-3, 3, 24).reshape(2, 3, 4)
    k = splinefig.kernel(Basis.bspline(), x)
    assert k.shape == (2, 3, 4) and k.dtype == np.float64
    assert np.array_equal(k.ravel(), splinefig.kernel("bspline", x.ravel().tolist()))
    assert splinefig.kernel("bspline", 0.0).shape == ()
    assert splinefig.kernel("bspline", 0) == 2 / 3
    # Non-contiguous and integer inputs are converted.
    assert np.array_equal(splinefig.kernel("bspline", x[:, ::2]), k[:, ::2])
    out = np.empty_like(x)
    assert splinefig.kernel("bspline", x, out=out) is out and np.array_equal(out, k)


@pytest.mark.parametrize("degree", [1, 2, 3, 4, 5])
def test_uniform_bspline_kernels_are_scipys_basis_elements(scipy_interpolate, degree):
    b = Basis.uniform_bspline(degree)
    lo, hi = b.support
    knots = np.arange(lo, hi + 1)
    ref = scipy_interpolate.BSpline.basis_element(knots, extrapolate=False)
    x = np.linspace(lo, hi, 1001)[:-1]
    np.testing.assert_allclose(splinefig.kernel(b, x), ref(x), rtol=0, atol=1e-14)


def test_kernel_derivatives():
    # k(s) = 2/3 - s^2 + |s|^3/2 on [-1, 1]: k'(1/2) = -1 + 3/8, k''(1/2) = -2 + 3/2.
    assert splinefig.kernel_derivative("bspline", 0.5) == -5 / 8
    assert splinefig.kernel_derivative("bspline", 0.5, order=2) == -0.5


def test_response_closed_forms():
    f = np.linspace(0, 3, 60)
    # |K(f)| of box, tent and cubic B-spline: |sinc f|, sinc^2, sinc^4.
    np.testing.assert_allclose(splinefig.response("box", f), np.abs(np.sinc(f)), atol=1e-13)
    np.testing.assert_allclose(splinefig.response("tent", f), np.sinc(f) ** 2, atol=1e-13)
    np.testing.assert_allclose(splinefig.response("bspline", f), np.sinc(f) ** 4, atol=1e-13)
    K = splinefig.fourier("bspline", f.reshape(3, -1))
    assert K.shape == (3, 20) and K.dtype == np.complex128
    np.testing.assert_allclose(K.ravel(), np.sinc(f) ** 4, atol=1e-13)  # even kernel: real


def test_report_is_the_clis(cli):
    for spec in ("bspline", "catmull-rom", "beta:b1=2,b2=0", "lanczos3"):
        r = splinefig.report(spec)
        assert r["text"] == cli(["kernel", "--basis", spec, "--report"]).stdout
    r = splinefig.report(Basis.bspline())
    assert r["integral"] == 1.0 and r["continuity"] == 2 and r["interpolating"] is False
    assert r["mitchell_netravali"] == (1.0, 0.0)
    assert splinefig.report("catmull-rom")["interpolating"] is True
    assert splinefig.report("beta:b1=2,b2=0")["mitchell_netravali"] is None


def test_kernel_is_the_clis(cli):
    rows = parse_csv(cli(["kernel", "--basis", "beta:b1=2,b2=1", "--from", "-2", "--to", "2", "--step", "0.125"]).stdout)
    assert np.array_equal(splinefig.kernel("beta:b1=2,b2=1", rows[:, 0]), rows[:, 1])
