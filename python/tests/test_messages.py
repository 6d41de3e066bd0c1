"""One message for each bad input, the same as the command line's where there is one: a lone
surrogate in a string or path (as os.fsdecode makes of undecodable bytes) is a ValueError
naming the argument, not pybind11's "incompatible function arguments"; uniform_bspline's degree
bound is the library's (20), said once; interpolate refuses a spline that overflows a double,
as `splinefig interp` does, instead of returning inf and NaN."""
import os
import subprocess

import numpy as np
import pytest

import splinefig
from splinefig import Basis

SURROGATE = "\udc80"


@pytest.mark.parametrize("call, says", [
    (lambda: splinefig.render_spec("a" + SURROGATE + ".toml"), r"^spec: a path holding a lone surrogate \(U\+DC80 at index 1\)"),
    (lambda: splinefig.read_image(SURROGATE + ".png"), r"^path: a path holding a lone surrogate \(U\+DC80 at index 0\)"),
    (lambda: splinefig.write_image("x" + SURROGATE + ".png", np.zeros((1, 1, 4), np.float32)),
     r"^path: a path holding a lone surrogate"),
    (lambda: Basis.parse("catmull-rom" + SURROGATE), r"^spec: a string holding a lone surrogate \(U\+DC80 at index 11\)"),
    (lambda: splinefig.kernel("tent" + SURROGATE, [0.0]), r"^basis: a string holding a lone surrogate"),
    (lambda: splinefig.Scene(4, 4, background="#ffffff" + SURROGATE), r"^background: a string holding a lone surrogate"),
    (lambda: splinefig.render_spec(text="[canvas]\nwidth = 4\nheight = 4\n", spec=SURROGATE), r"^spec: a string holding"),
])
def test_a_lone_surrogate_is_a_value_error_naming_the_argument(call, says):
    with pytest.raises(ValueError, match=says) as e:
        call()
    assert "incompatible function arguments" not in str(e.value)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("degree", [0, 21, 64, 65])
def test_uniform_bspline_degree_is_one_message_with_the_library_bound(degree):
    with pytest.raises(ValueError) as e:
        Basis.uniform_bspline(degree)
    assert str(e.value) == f"degree: {degree} is not in [1, 20]"


def test_uniform_bspline_degree_20_is_built():
    # The bound is the library's: degree 20 is a basis of 21 x 21 (its highest).
    assert Basis.uniform_bspline(20).matrix.shape == (21, 21)


def _cli_interp(rows, *flags):
    r = subprocess.run([os.environ["SPLINEFIG_EXE"], "interp", *flags], input=rows, capture_output=True, text=True)
    return r.returncode, r.stderr


@pytest.mark.parametrize("points, kw, flags, what, big", [
    ([[0, 0], [1, 1e308], [2, -1e308]], {}, [], "data point 2", "1e+308"),
    ([[0, 0], [1, 1e308], [2, -1e308]], {"output": "bspline"}, ["--output", "bspline"], "data point 2", "1e+308"),
    ([[0, 0], [1, 1]], {"ends": "clamped", "start_velocity": [0, 1.7e308]},
     ["--ends", "clamped", "--start-velocity", "0,1.7e308"], ("start_velocity", "--start-velocity"), "1.7e+308"),
])
def test_interpolate_refuses_an_overflow_as_the_command_line_does(points, kw, flags, what, big):
    py_what, cli_what = what if isinstance(what, tuple) else (what, what)
    with pytest.raises(ValueError) as e:
        splinefig.interpolate(points, **kw)
    assert str(e.value) == (f"points: the spline overflows the range of a double: {py_what} (a coordinate {big}) "
                            "is too large to interpolate")
    if "SPLINEFIG_EXE" in os.environ:  # the peer: the command line refuses the same data
        code, err = _cli_interp("".join(",".join(repr(float(v)) for v in p) + "\n" for p in points), *flags)
        assert code == 2
        assert f"overflows the range of a double: {cli_what} (a coordinate {big}) is too large to interpolate" in err


def test_interpolate_near_the_limit_but_finite_still_works():
    out = splinefig.interpolate([[0, 0], [1, 1e300], [2, 3]])
    assert np.isfinite(out).all()
    # It passes through its data points (every 16th row with the default grain).
    assert out[16, 1] == pytest.approx(1e300, rel=1e-12)
