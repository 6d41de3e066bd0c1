"""splinefig from Python: exact spline kernels, curve evaluation, exact-area rendering,
resampling and idiff-compatible image comparison, with numpy arrays in and out.

The C++ library does the work (``splinefig._core``); this layer checks arguments (a wrong
dtype, shape or value raises ``TypeError`` or ``ValueError`` naming the argument), converts
them without copying where the layout allows, and documents the functions. Images are numpy
arrays of shape (h, w) or (h, w, c), float32, rows top to bottom; the renderer's are (h, w, 4)
RGBA in linear light with associated alpha. See docs/python.md.
"""
from __future__ import annotations

import dataclasses
import math
import os
import threading
from typing import Any, Callable, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core, _paths

__version__ = _core.version

__all__ = [
    "Basis", "Kernel", "kernel", "kernel_derivative", "response", "fourier", "report",
    "evaluate", "sample_count", "arclength_points", "arclength", "interpolate",
    "Scene", "RasterReport", "RasterReportItem", "render_spec", "render_figure", "figure_names", "specs_dir",
    "resample", "image_buffer", "compare", "difference_image", "triptych", "read_image", "write_image",
    "Image",
]

Kernel = _core.Kernel


class Image(np.ndarray):
    """An image array as render_spec, render_figure, Scene.render and read_image return it: a
    numpy float32 array in every respect, which also knows whether its values are linear light
    or sRGB-encoded (`encoding`), and so shows itself in a notebook (IPython, Jupyter): its
    _repr_png_ is the PNG that write_image writes (8-bit sRGB, straight alpha). An array that
    is not an image of 1 to 4 channels (a slice, a reduction) shows as an array. A figure from
    render_spec or render_figure also shows as SVG (_repr_svg_: the file `splinefig render -o
    FIG.svg` writes, drawn from the same spec when it is asked for), so a notebook may show
    its exact vector form; any array computed from it has none."""

    _svg_source: Optional[Callable[[], str]] = None

    def __new__(cls, array: Any, encoding: str = "linear") -> "Image":
        obj = np.asarray(array).view(cls)
        obj.encoding = _choice(encoding, "encoding", ("linear", "srgb"))
        return obj

    def __array_finalize__(self, obj: Any) -> None:
        self.encoding = getattr(obj, "encoding", "linear")
        self._svg_source = None  # a slice, a copy or arithmetic is no longer the figure

    def _repr_svg_(self) -> Optional[str]:
        if self._svg_source is None:
            return None
        try:
            return self._svg_source()
        except ValueError:  # the spec or a file it reads changed since: the PNG still shows
            return None

    def _repr_png_(self) -> Optional[bytes]:
        channels = 1 if self.ndim == 2 else (self.shape[2] if self.ndim == 3 else 0)
        if (self.dtype.kind != "f" or not 1 <= channels <= 4 or self.shape[0] < 1 or self.shape[1] < 1
                or self.size > (1 << 30)):
            return None
        import tempfile
        with tempfile.TemporaryDirectory(prefix="splinefig-repr-") as d:
            path = os.path.join(d, "image.png")
            write_image(path, np.asarray(self, dtype=np.float32), encoding=self.encoding)
            with open(path, "rb") as f:
                return f.read()
_PathLike = Union[str, "os.PathLike[str]"]


# ---- argument checks -------------------------------------------------------------------------

def _real(value: Any, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: expected a real number, got {type(value).__name__}")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name}: {v} is not finite")
    return v


def _int(value: Any, name: str, lo: Optional[int] = None, hi: Optional[int] = None) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name}: expected an integer, got {type(value).__name__}")
    v = int(value)
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        bounds = f">= {lo}" if hi is None else f"in [{lo}, {hi}]"
        raise ValueError(f"{name}: {v} is not {bounds}")
    return v


def _no_surrogate(value: str, name: str, what: str) -> str:
    # A lone surrogate (as os.fsdecode makes of undecodable bytes) is no UTF-8: pybind11 would
    # refuse the call as "incompatible function arguments".
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as e:
        raise ValueError(f"{name}: {what} holding a lone surrogate (U+{ord(value[e.start]):04X} at index {e.start}), "
                         "which is not UTF-8") from None
    return value


def _str(value: Any, name: str) -> str:
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a string, got {type(value).__name__}")
    return _no_surrogate(value, name, "a string")


def _choice(value: Any, name: str, known: Sequence[str]) -> str:
    v = _str(value, name)
    if v not in known:
        raise ValueError(f"{name}: unknown value '{v}' (known: {', '.join(known)})")
    return v


def _numeric(value: Any, name: str, dtype: Any) -> np.ndarray:
    """value as a C-contiguous array of dtype: no copy when it already is one."""
    if isinstance(value, (str, bytes)):
        raise TypeError(f"{name}: expected numbers, got {type(value).__name__}")
    try:
        a = np.asarray(value)
    except Exception as e:  # ragged lists and the like
        raise ValueError(f"{name}: not an array of numbers ({e})") from None
    if a.dtype == object or not (np.issubdtype(a.dtype, np.number) or a.dtype == np.bool_) \
            or np.issubdtype(a.dtype, np.complexfloating):
        raise TypeError(f"{name}: expected real numbers, got an array of {a.dtype}")
    return np.asarray(a, dtype=dtype, order="C")


def _points(value: Any, name: str, min_dim: int = 1) -> np.ndarray:
    a = _numeric(value, name, np.float64)
    if a.ndim != 2 or a.shape[1] < min_dim:
        raise ValueError(f"{name}: expected an (n, d) array of points, got shape {a.shape}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name}: contains a value that is not finite")
    return a


def _image(value: Any, name: str, srgb_ints: bool = False) -> np.ndarray:
    """An (h, w) or (h, w, c) float32/float64 image as C-contiguous float32. With srgb_ints,
    a uint8 or uint16 array too: sRGB-encoded values with straight alpha (a PNG's, PIL's),
    decoded to linear light with associated alpha as read_image(linear=True) decodes a file."""
    a = np.asarray(value) if not isinstance(value, (str, bytes)) else None
    ints = srgb_ints and a is not None and a.dtype in (np.uint8, np.uint16)
    if a is None or (a.dtype not in (np.float32, np.float64) and not ints):
        what = type(value).__name__ if a is None else f"dtype {a.dtype}"
        also = ", or a uint8 or uint16 one of sRGB values" if srgb_ints else ""
        raise TypeError(f"{name}: expected a float32 or float64 array{also}, got {what}")
    if a.ndim not in (2, 3) or a.shape[0] < 1 or a.shape[1] < 1 or (a.ndim == 3 and a.shape[2] < 1):
        raise ValueError(f"{name}: expected an (h, w) or (h, w, c) image, got shape {a.shape}")
    return _srgb_ints_to_linear(a) if ints else np.ascontiguousarray(a, dtype=np.float32)


def _srgb_ints_to_linear(a: np.ndarray) -> np.ndarray:
    # The sRGB curve of every code (v / 255 or v / 65535) in double, as image/src/srgb.cpp
    # computes it; colour times the straight alpha (the last of 2 or 4 channels), rounded once.
    top = float(np.iinfo(a.dtype).max)
    v = np.arange(int(top) + 1, dtype=np.float64) / top
    curve = np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
    out = curve[a]
    if a.ndim == 3 and a.shape[2] in (2, 4):
        alpha = a[..., -1:] / top
        out[..., :-1] *= alpha
        out[..., -1:] = alpha
    return np.ascontiguousarray(out, dtype=np.float32)


def _kernel(value: Any, name: str = "basis") -> "Kernel":
    if isinstance(value, Kernel):
        return value
    if isinstance(value, Basis):
        return _core.basis_kernel(value._b)
    if isinstance(value, str):
        _str(value, name)
        try:
            return _core.parse_kernel(value)
        except ValueError as e:
            raise ValueError(f"{name}: {e}") from None
    raise TypeError(f"{name}: expected a Basis, a Kernel or a spec string, got {type(value).__name__}")


def _basis(value: Any, name: str = "basis") -> "Basis":
    if isinstance(value, Basis):
        return value
    if isinstance(value, str):
        return Basis.parse(value, _name=name)
    raise TypeError(f"{name}: expected a Basis or a spec string, got {type(value).__name__}")


def _color(value: Any, name: str) -> tuple:
    """'#rrggbb[aa]' (sRGB) or 3 or 4 linear-light floats -> a linear RGBA tuple."""
    if isinstance(value, str):
        c = _core.parse_hex_color(_str(value, name))
        if c is None:
            raise ValueError(f"{name}: '{value}' is not #rrggbb or #rrggbbaa")
        return tuple(c)
    a = _numeric(value, name, np.float64).ravel()
    if a.size not in (3, 4):
        raise ValueError(f"{name}: expected 3 or 4 channel values, got {a.size}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name}: contains a value that is not finite")
    return tuple(float(v) for v in a) + ((1.0,) if a.size == 3 else ())


def _stroke_args(width: Any, join: str, cap: str, miter_limit: Any, dashes: Sequence[float], dash_offset: Any) -> tuple:
    """A stroke's arguments as the library takes them, converted only: the library checks
    their values (a width >= 0, a miter limit >= 1, a valid dash pattern) and says what is wrong."""
    return (_real(width, "width"), _choice(join, "join", ("miter", "round", "bevel")),
            _choice(cap, "cap", ("butt", "round", "square")), _real(miter_limit, "miter_limit"),
            [_real(d, "dashes") for d in dashes], _real(dash_offset, "dash_offset"))


# The highest degree of uniform_bspline, as the library checks it (spline/src/basis.cpp).
_MAX_UNIFORM_DEGREE = 20


def _library(name: str, f, *args):
    """Calls f, prefixing the library's message with the argument it concerns."""
    try:
        return f(*args)
    except ValueError as e:
        raise ValueError(f"{name}: {e}") from None


# ---- spline core -----------------------------------------------------------------------------

class Basis:
    """A uniform polynomial spline basis: its (degree+1) x (degree+1) matrix M, rows ordered
    u^degree .. u^0 (the memo's U = [u^3 u^2 u 1])."""

    __slots__ = ("_b",)

    def __init__(self, _b: Any) -> None:
        if not isinstance(_b, _core.Basis):
            raise TypeError("use Basis.parse(spec) or a constructor such as Basis.cardinal(a)")
        self._b = _b

    @staticmethod
    def parse(spec: str, *, _name: str = "spec") -> "Basis":
        """NAME[:key=value,...], e.g. "beta:b1=2,b2=0" (docs/spline.md)."""
        return Basis(_library(_name, _core.parse_basis, _str(spec, _name)))

    @staticmethod
    def known() -> list:
        return [n.strip() for n in _core.known_bases().split(",")]

    @staticmethod
    def catmull_rom() -> "Basis":
        return Basis(_core.catmull_rom())

    @staticmethod
    def cardinal(a: float) -> "Basis":
        return Basis(_library("a", _core.cardinal, _real(a, "a")))

    @staticmethod
    def bspline() -> "Basis":
        return Basis(_core.bspline())

    @staticmethod
    def tensioned_bspline(a: float) -> "Basis":
        return Basis(_library("a", _core.tensioned_bspline, _real(a, "a")))

    @staticmethod
    def beta(b1: float, b2: float) -> "Basis":
        return Basis(_library("b1, b2", _core.beta, _real(b1, "b1"), _real(b2, "b2")))

    @staticmethod
    def uniform_bspline(degree: int) -> "Basis":
        return Basis(_library("degree", _core.uniform_bspline, _int(degree, "degree", 1, _MAX_UNIFORM_DEGREE)))

    @staticmethod
    def mitchell_netravali(b: float = 1 / 3, c: float = 1 / 3) -> "Basis":
        return Basis(_library("b, c", _core.mitchell_netravali, _real(b, "b"), _real(c, "c")))

    @property
    def family(self) -> str:
        return self._b.family

    @property
    def spec(self) -> str:
        return self._b.spec

    @property
    def degree(self) -> int:
        return self._b.degree

    @property
    def matrix(self) -> np.ndarray:
        """A new (degree+1, degree+1) float64 array."""
        return self._b.matrix

    @property
    def support(self) -> tuple:
        return self._b.support

    def kernel(self) -> "Kernel":
        """The basis function as a Kernel object (make it once for many calls)."""
        return _core.basis_kernel(self._b)

    def __eq__(self, other: object) -> bool:
        """The same matrix (so the same curves), whatever the spec says."""
        return isinstance(other, Basis) and self._b == other._b

    def __hash__(self) -> int:
        return hash(self.matrix.tobytes())

    def __repr__(self) -> str:
        return f"Basis.parse('{self.spec}')"


def _out(out: Any, shape: tuple) -> np.ndarray:
    if not isinstance(out, np.ndarray) or out.dtype != np.float64 or not out.flags.c_contiguous \
            or not out.flags.writeable:
        raise TypeError("out: expected a writeable C-contiguous float64 array")
    if out.shape != shape:
        raise ValueError(f"out: shape {out.shape}, expected {shape}")
    return out


def kernel(basis: Any, x: Any, *, out: Optional[np.ndarray] = None) -> np.ndarray:
    """k(x) of a basis (or a filter spec: box, tent, lanczos3) for every element of x, any shape;
    a float64 array of x's shape (written into `out` when given)."""
    k = _kernel(basis)
    xa = _numeric(x, "x", np.float64)
    if out is None:
        return _core.kernel_values(k, xa)
    _core.kernel_values_into(k, xa, _out(out, xa.shape))
    return out


def kernel_derivative(basis: Any, x: Any, order: int = 1) -> np.ndarray:
    """The order-th derivative of k at every element of x (the piece to the right at a knot)."""
    k = _kernel(basis)
    return _library("basis", _core.kernel_derivative, k, _numeric(x, "x", np.float64), _int(order, "order", 0))


def response(basis: Any, freqs: Any) -> np.ndarray:
    """|K(f)|, f in cycles per sample, for every element of freqs."""
    return _core.response(_kernel(basis), _numeric(freqs, "freqs", np.float64))


def fourier(basis: Any, freqs: Any) -> np.ndarray:
    """K(f) = integral k(s) exp(-2 pi i f s) ds as complex128, for every element of freqs."""
    return _core.fourier(_kernel(basis), _numeric(freqs, "freqs", np.float64))


def report(basis: Any) -> dict:
    """The filter analysis as a dict (the keys of `splinefig kernel --report`; "text" holds
    its lines)."""
    return _core.report(_kernel(basis))


_ENDS = ("open", "double", "doubled", "closed")


def evaluate(knots: Any, basis: Any, *, grain: int = 16, ends: str = "open", derivative: int = 0,
             out: Optional[np.ndarray] = None) -> np.ndarray:
    """The curve through (or near) an (n, d) array of knots, `grain` points per piece plus the
    end point: an (m, d) float64 array, as `splinefig eval` prints it (written into `out`
    when given; sample_count() gives m)."""
    k = _points(knots, "knots")
    b = _basis(basis)
    g = _int(grain, "grain", 1, 1 << 24)
    e = _choice(ends, "ends", _ENDS)
    d = _int(derivative, "derivative", 0, 2)
    if out is None:
        return _library("knots", _core.evaluate, k, b._b, g, e, d)
    _out(out, (sample_count(k, b, grain=g, ends=e), k.shape[1]))
    _library("knots", _core.evaluate_into, k, b._b, g, e, d, out)
    return out


def sample_count(knots: Any, basis: Any, *, grain: int = 16, ends: str = "open") -> int:
    """The number of points evaluate() gives: segments * grain + 1."""
    return _library("knots", _core.sample_count, _points(knots, "knots"), _basis(basis)._b,
                    _int(grain, "grain", 1, 1 << 24), _choice(ends, "ends", _ENDS))


def arclength_points(knots: Any, basis: Any, *, count: int, ends: str = "open", method: str = "accurate",
                     grain: int = 16, derivative: int = 0, return_parameters: bool = False):
    """`count` points evenly spaced in arc length along the curve: a (count, d) array (and the
    parameters t when return_parameters). method "accurate" (adaptive quadrature) or
    "polygon" (the memo's chords of the curve sampled at `grain`)."""
    k = _points(knots, "knots")
    b = _basis(basis)
    c = _int(count, "count", 2, 1 << 26)
    e = _choice(ends, "ends", _ENDS)
    m = _choice(method, "method", ("accurate", "polygon"))
    g = _int(grain, "grain", 1, 1 << 24)
    d = _int(derivative, "derivative", 0, 2)
    pts, t = _library("knots", _core.arclength_points, k, b._b, c, e, m, g, d)
    return (pts, t) if return_parameters else pts


def arclength(knots: Any, basis: Any, *, ends: str = "open") -> float:
    """The curve's length (adaptive Gauss-Kronrod, relative tolerance 1e-13)."""
    return _library("knots", _core.arclength, _points(knots, "knots"), _basis(basis)._b, _choice(ends, "ends", _ENDS))


def interpolate(points: Any, *, ends: str = "relaxed", start_velocity: Any = None, end_velocity: Any = None,
                output: str = "curve", grain: int = 16) -> np.ndarray:
    """The cubic spline through the (n+1, d) data points (seed 003): output "curve" gives
    n*grain+1 points, "bspline" the n+1 B-spline control points, "bezier" an (n, 4, d) array
    of the Bezier pieces. ends: relaxed, clamped (with start_velocity / end_velocity, zero by
    default) or periodic (the last point repeats the first)."""
    s = _points(points, "points")
    e = _choice(ends, "ends", ("relaxed", "clamped", "periodic"))
    o = _choice(output, "output", ("curve", "bspline", "bezier"))
    g = _int(grain, "grain", 1, 1000000)
    dim = s.shape[1]
    need = 3 if e == "periodic" else 2
    if s.shape[0] < need:
        raise ValueError(f"points: {s.shape[0]} given, ends '{e}' needs at least {need}")
    vel = []
    for name, v in (("start_velocity", start_velocity), ("end_velocity", end_velocity)):
        if v is not None and e != "clamped":
            raise ValueError(f"{name}: applies only to ends 'clamped'")
        a = np.zeros(dim) if v is None else _numeric(v, name, np.float64).ravel()
        if a.size != dim or not np.isfinite(a).all():
            raise ValueError(f"{name}: expected {dim} finite coordinates, got {a.size}")
        vel.append(a)
    if e == "periodic" and not np.array_equal(s[0], s[-1]):
        raise ValueError(f"points: ends 'periodic' needs the last point to repeat the first (point {s.shape[0]} differs)")
    out = _library("points", _core.interpolate, s, e, vel[0], vel[1], o, g)
    if not np.isfinite(out).all():
        # The spline is linear in its data: from finite data, a value that is not finite means the
        # solve or the curve overflowed. Name the coordinate of largest magnitude, as
        # `splinefig interp` does (the data point counted from 1).
        k = int(np.argmax(np.abs(s)))
        what, big = f"data point {k // dim + 1}", float(np.abs(s).ravel()[k])
        for name, v in (("start_velocity", vel[0]), ("end_velocity", vel[1])):
            if v.size and float(np.abs(v).max()) > big:
                what, big = name, float(np.abs(v).max())
        raise ValueError(f"points: the spline overflows the range of a double: {what} (a coordinate {big!r}) "
                         "is too large to interpolate")
    return out


# ---- rendering -------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class RasterReportItem:
    """An item with bands resolved from its pieces: its index in drawing order (from 0), the
    bands of rows it touches, and how many of them were resolved from its pieces."""
    index: int
    bands: int
    piece_bands: int


@dataclasses.dataclass(frozen=True)
class RasterReport:
    """How a render resolved the scene (Scene.raster_report): `items` lists only the items
    with bands drawn from their pieces, within `tolerance`; the rest were swept exactly."""
    tolerance: float
    band_rows: int
    items: Tuple[RasterReportItem, ...]

    @property
    def exact(self) -> bool:
        """True when every band of every item was swept exactly."""
        return not self.items


def _raster_report(d: Dict[str, Any]) -> RasterReport:
    return RasterReport(float(d["tolerance"]), int(d["band_rows"]),
                        tuple(RasterReportItem(int(i["index"]), int(i["bands"]), int(i["piece_bands"])) for i in d["items"]))


class Scene:
    """A drawing of width x height pixels ((0, 0) the top-left corner, y down), rasterized
    exactly (area coverage, or a spline pixel filter) into linear-light RGBA. Colours are
    "#rrggbb[aa]" (sRGB) or 3 or 4 linear-light floats with straight alpha."""

    def __init__(self, width: int, height: int, *, background: Any = (1.0, 1.0, 1.0, 1.0), filter: Any = "box",
                 blend: str = "linear", coverage_tolerance: float = 1.0 / 1024) -> None:
        """blend: "linear" (light, the default) or "srgb" (the encoded values blended, as AGG and
        browsers do; render() then returns sRGB-encoded associated-alpha values).
        coverage_tolerance: the coverage error accepted in a pixel where a dense stroke is drawn
        from its pieces, in [0, 1]; 0 sweeps every item exactly and refuses one past the work
        limit (docs/renderer.md, "Dense strokes")."""
        w = _int(width, "width", 1, 32768)
        h = _int(height, "height", 1, 32768)
        if w * h > (1 << 28):
            raise ValueError(f"width, height: {w}x{h} is more than 2^28 pixels")
        b = _choice(blend, "blend", ("linear", "srgb"))
        self._s = _library("filter", _core.Scene, w, h, _color(background, "background"), _kernel(filter, "filter"))
        self._s.blend = b
        t = _real(coverage_tolerance, "coverage_tolerance")
        if not 0 <= t <= 1:
            raise ValueError(f"coverage_tolerance: {t!r} is not in [0, 1] (0: exact)")
        self._s.coverage_tolerance = t
        # render() runs without the interpreter's lock: adding items meanwhile from another
        # thread waits for it instead of changing the display list under the rasterizer.
        self._lock = threading.Lock()
        self._report: Optional[RasterReport] = None

    @property
    def width(self) -> int:
        return self._s.width

    @property
    def height(self) -> int:
        return self._s.height

    @property
    def blend(self) -> str:
        """The blend space: "linear" or "srgb"."""
        return self._s.blend

    @property
    def raster_report(self) -> Optional["RasterReport"]:
        """How the last render drew the picture (None before the first): the tolerance in
        force and the items (numbered from 0 in drawing order) that had bands of rows resolved
        from their pieces within it; every other band and item was swept exactly."""
        return self._report

    @property
    def coverage_tolerance(self) -> float:
        """The coverage error accepted where a dense stroke is drawn from its pieces (0: exact)."""
        return self._s.coverage_tolerance

    @staticmethod
    def _path_args(vertices: Any, codes: Any) -> tuple:
        v = _points(vertices, "vertices", 2)
        if v.shape[1] != 2:
            raise ValueError(f"vertices: expected an (n, 2) array, got shape {v.shape}")
        if codes is None:
            c = np.zeros(0, np.uint8)
        else:
            c = _numeric(codes, "codes", np.int64).ravel()
            if c.size != v.shape[0]:
                raise ValueError(f"codes: {c.size} codes for {v.shape[0]} vertices")
            if c.size and (c.min() < 0 or c.max() > 255):
                raise ValueError("codes: a code outside 0..255")
            c = c.astype(np.uint8)
        return v, c

    def fill_path(self, vertices: Any, codes: Any = None, *, color: Any = "#000000", rule: str = "nonzero") -> "Scene":
        """Fills a path of lines and Bezier curves: (n, 2) vertices with matplotlib's path codes
        (1 move, 2 line, 3 quadratic: control then end, 4 cubic: two controls then end,
        79 close, 0 stop; None: one polyline), kept exact until the rasterizer flattens it
        within 1e-4 px."""
        v, c = self._path_args(vertices, codes)
        r, col = _choice(rule, "rule", ("nonzero", "evenodd")), _color(color, "color")
        with self._lock:
            _library("codes", self._s.fill_path, v, c, r, col)
        return self

    def set_clip(self, vertices: Any, codes: Any = None, *, rule: str = "nonzero") -> "Scene":
        """Clips every shape and text item added from now on to the region a path (vertices and
        codes as fill_path) encloses under `rule`, exactly, until clear_clip(). Images cannot
        be added while a clip is set."""
        v, c = self._path_args(vertices, codes)
        r = _choice(rule, "rule", ("nonzero", "evenodd"))
        with self._lock:
            _library("codes", self._s.set_clip, v, c, r)
        return self

    def clear_clip(self) -> "Scene":
        """Ends the clip set by set_clip: later items are not clipped."""
        with self._lock:
            self._s.clear_clip()
        return self

    def stroke_path(self, vertices: Any, codes: Any = None, *, color: Any = "#000000", width: float = 1.0,
                    join: str = "miter", cap: str = "butt", miter_limit: float = 4.0,
                    dashes: Sequence[float] = (), dash_offset: float = 0.0) -> "Scene":
        """Strokes a path (vertices and codes as fill_path) as the union of its pieces."""
        v, c = self._path_args(vertices, codes)
        args = (v, c, _color(color, "color")) + _stroke_args(width, join, cap, miter_limit, dashes, dash_offset)
        with self._lock:
            _library("stroke_path", self._s.stroke_path, *args)
        return self

    def image(self, rgba: Any, p0: Any, p1: Any, *, sampling: str = "nearest") -> "Scene":
        """Draws an (h, w, 4) RGBA image into the rectangle with corners p0 and p1: uint8 is
        sRGB with straight alpha (as matplotlib and PIL hold it), float32 linear light with
        associated alpha (as render() gives in linear blend space). A canvas pixel whose centre
        is inside samples the image there ("nearest" or "bilinear")."""
        a = np.asarray(rgba) if not isinstance(rgba, (str, bytes)) else None
        if a is None or a.dtype not in (np.uint8, np.float32, np.float64):
            raise TypeError(f"rgba: expected a uint8 or float32 array, got {type(rgba).__name__ if a is None else a.dtype}")
        if a.ndim != 3 or a.shape[2] != 4 or a.shape[0] < 1 or a.shape[1] < 1:
            raise ValueError(f"rgba: expected an (h, w, 4) array, got shape {a.shape}")
        a = np.ascontiguousarray(a, dtype=np.uint8 if a.dtype == np.uint8 else np.float32)
        if a.dtype == np.float32 and not np.isfinite(a).all():
            raise ValueError("rgba: contains a value that is not finite")
        corners = []
        for name, p in (("p0", p0), ("p1", p1)):
            q = _numeric(p, name, np.float64).ravel()
            if q.size != 2 or not np.isfinite(q).all():
                raise ValueError(f"{name}: expected 2 finite coordinates")
            corners.append(q)
        smp = _choice(sampling, "sampling", ("nearest", "bilinear"))
        with self._lock:
            _library("rgba", self._s.image, a, corners[0][0], corners[0][1], corners[1][0], corners[1][1], smp)
        return self

    def polyline(self, points: Any, *, color: Any = "#000000", width: float = 1.0, closed: bool = False,
                 join: str = "miter", cap: str = "butt", miter_limit: float = 4.0,
                 dashes: Sequence[float] = (), dash_offset: float = 0.0) -> "Scene":
        p = _points(points, "points", 2)
        if p.shape[1] != 2:
            raise ValueError(f"points: expected an (n, 2) array, got shape {p.shape}")
        args = (p, bool(closed), _color(color, "color")) + _stroke_args(width, join, cap, miter_limit, dashes, dash_offset)
        with self._lock:
            _library("polyline", self._s.polyline, *args)
        return self

    def fill(self, contours: Any, *, color: Any = "#000000", rule: str = "nonzero") -> "Scene":
        """Fills one (n, 2) contour or a list of them."""
        if isinstance(contours, np.ndarray) and contours.ndim == 2:
            contours = [contours]
        elif isinstance(contours, (list, tuple)) and contours and np.ndim(contours[0]) == 1:
            contours = [contours]
        cs = []
        for c in contours:
            p = _points(c, "contours", 2)
            if p.shape[1] != 2:
                raise ValueError(f"contours: expected (n, 2) arrays, got shape {p.shape}")
            cs.append(p)
        r, c = _choice(rule, "rule", ("nonzero", "evenodd")), _color(color, "color")
        with self._lock:
            _library("contours", self._s.fill, cs, r, c)
        return self

    def circle(self, centre: Any, radius: float, *, fill: Any = None, stroke: Any = None, width: float = 1.0) -> "Scene":
        c = _numeric(centre, "centre", np.float64).ravel()
        if c.size != 2 or not np.isfinite(c).all():
            raise ValueError("centre: expected 2 finite coordinates")
        r = _real(radius, "radius")
        if r <= 0:
            raise ValueError(f"radius: {r} is not positive")
        if fill is None and stroke is None:
            raise ValueError("fill, stroke: give at least one colour")
        fc = None if fill is None else _color(fill, "fill")
        sc = None if stroke is None else _color(stroke, "stroke")
        wd = _real(width, "width")
        if sc is not None and wd <= 0:
            raise ValueError(f"width: {wd} is not positive")
        with self._lock:
            if fc is not None:
                self._s.fill_circle(c[0], c[1], r, fc)
            if sc is not None:
                self._s.stroke_circle(c[0], c[1], r, sc, wd)
        return self

    def markers(self, points: Any, *, shape: str = "circle", size: float = 6.0, color: Any = "#000000") -> "Scene":
        p = _points(points, "points", 2)
        if p.shape[1] != 2:
            raise ValueError(f"points: expected an (n, 2) array, got shape {p.shape}")
        s = _real(size, "size")
        if s <= 0:
            raise ValueError(f"size: {s} is not positive")
        shp, col = _choice(shape, "shape", ("circle", "square", "diamond", "cross", "plus")), _color(color, "color")
        with self._lock:
            self._s.markers(p, shp, s, col)
        return self

    def text(self, text: str, at: Any, *, size: float = 14.0, color: Any = "#000000", halign: str = "left",
             valign: str = "baseline", family: str = "sans", weight: str = "normal", italic: bool = False,
             angle: float = 0.0) -> "Scene":
        a = _numeric(at, "at", np.float64).ravel()
        if a.size != 2 or not np.isfinite(a).all():
            raise ValueError("at: expected 2 finite coordinates")
        s = _real(size, "size")
        if s <= 0:
            raise ValueError(f"size: {s} is not positive")
        args = (_str(text, "text"), a[0], a[1], s, _color(color, "color"), _choice(halign, "halign", ("left", "center", "right")),
                _choice(valign, "valign", ("baseline", "middle", "top", "bottom")),
                _choice(family, "family", ("sans", "serif", "mono")), _choice(weight, "weight", ("normal", "bold")),
                bool(italic), _real(angle, "angle"))
        with self._lock:
            _library("text", self._s.text, *args)
        return self

    def render(self, *, threads: int = 0) -> np.ndarray:
        """The picture: an (h, w, 4) float32 array, associated alpha, linear light (or
        sRGB-encoded values for blend="srgb")."""
        t = _int(threads, "threads", 0, 256)
        with self._lock:
            im, report = self._s.render_reported(t)
            self._report = _raster_report(report)
            return Image(im, self._s.blend)

    def render_rgba8(self, *, threads: int = 0, clear: Sequence[int] = (255, 255, 255)) -> np.ndarray:
        """The picture as an (h, w, 4) uint8 array, sRGB with straight alpha (a PNG's or
        matplotlib's buffer); a pixel of alpha 0 gets the colour `clear`."""
        t = _int(threads, "threads", 0, 256)
        cl = [_int(v, "clear", 0, 255) for v in clear]
        if len(cl) != 3:
            raise ValueError(f"clear: expected 3 channel values, got {len(cl)}")
        with self._lock:
            im, report = self._s.render_rgba8_reported(t, cl)
            self._report = _raster_report(report)
            return im

    def save(self, path: _PathLike, *, threads: int = 0) -> None:
        """Renders and writes .png (8-bit sRGB) or .exr (float linear)."""
        im = self.render(threads=threads)
        if self.blend == "srgb":
            im = _core.srgb_to_linear_rgba(im)
        write_image(path, im)


def _path(value: Any, name: str) -> str:
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if not isinstance(value, str):
        raise TypeError(f"{name}: expected a path, got {type(value).__name__}")
    if "\0" in value:
        # The C library would cut the path there: write_image("a\0b.png") wrote a file "a".
        raise ValueError(f"{name}: a path holding a NUL character")
    return _no_surrogate(value, name, "a path")


def specs_dir() -> str:
    """The directory of the built-in figure specs ($SPLINEFIG_SPECS_DIR if set)."""
    return os.environ.get("SPLINEFIG_SPECS_DIR") or _paths.specs_dir


def figure_names() -> list:
    """The names of the built-in figures."""
    d = specs_dir()
    return sorted(f[:-5] for f in os.listdir(d) if f.endswith(".toml")) if os.path.isdir(d) else []


def render_spec(spec: Any, *, scale: float = 1.0, threads: int = 0, text: Optional[str] = None) -> np.ndarray:
    """Renders a TOML figure spec file (docs/spec.md), or the spec given as `text` (then `spec`
    is its name in messages): an (h, w, 4) float32 array, linear light, as `splinefig render`
    draws it (blended as the spec's [canvas] blend says, sRGB by default; the linear decode of
    that, the values of its EXR)."""
    s = _real(scale, "scale")
    if s <= 0:
        raise ValueError(f"scale: {s} is not positive")
    t = _int(threads, "threads", 0, 256)
    if text is not None:
        name = _str(spec, "spec") if spec is not None else "<text>"
        source = _str(text, "text")
        image = Image(_core.render_spec_text(source, name, ".", s, t))
        here = os.getcwd()  # where its relative files were read from
        image._svg_source = lambda: _core.spec_svg_text(source, name, here, s)
        return image
    path = _path(spec, "spec")
    image = Image(_core.render_spec_file(path, s, t))
    where = os.path.abspath(path)
    image._svg_source = lambda: _core.spec_svg_file(where, s)
    return image


def render_figure(name: str, *, scale: float = 1.0, threads: int = 0) -> np.ndarray:
    """A built-in figure by name (e.g. "bias"; figure_names() lists them)."""
    n = _str(name, "name")
    if "\0" in n:
        raise ValueError("name: a name holding a NUL character")
    path = os.path.join(specs_dir(), n + ".toml")
    if "/" in n or not os.path.isfile(path):
        raise ValueError(f"name: no built-in figure '{n}' in {specs_dir()}")
    return render_spec(path, scale=scale, threads=threads)


# ---- images: files, resampling, comparison ---------------------------------------------------

def read_image(path: _PathLike, *, linear: bool = False, return_encoding: bool = False):
    """An image file as an (h, w, c) float32 array: the values as stored (8-bit v/255, sRGB
    PNGs stay encoded, as idiff compares them) or, with linear=True, decoded to linear light
    with associated alpha (as resampling and drawing need)."""
    a, enc = _core.read_image(_path(path, "path"), bool(linear))
    a = Image(a, enc)
    return (a, enc) if return_encoding else a


def write_image(path: _PathLike, image: Any, *, encoding: str = "linear", bits: int = 8, description: str = "") -> None:
    """Writes .png (8 or 16 bits, sRGB-encoded, straight alpha) or .exr/.tif (float32 linear)
    atomically. `encoding` says what the values are: "linear" light or "srgb"-encoded values."""
    a = _image(image, "image")
    e = _choice(encoding, "encoding", ("linear", "srgb"))
    b = _int(bits, "bits")
    if b not in (8, 16):
        raise ValueError(f"bits: {b} is not 8 or 16")
    _core.write_image(_path(path, "path"), a, e == "srgb", b, _str(description, "description"))


def image_buffer(height: int, width: int, channels: Optional[int] = None) -> np.ndarray:
    """A zeroed (height, width, channels) float32 array held by a library image ((height,
    width) when channels is None), for filling in place."""
    h = _int(height, "height", 1, 65536)
    w = _int(width, "width", 1, 65536)
    c = 1 if channels is None else _int(channels, "channels", 1, 64)
    if h * w * c > (1 << 30):
        raise ValueError(f"height, width, channels: {h}x{w}x{c} is over the limit of 2^30 samples")
    return _core.image_buffer(h, w, c, channels is None)


def resample(image: Any, *, size: Any = None, scale: Any = None, filter: Any = "catmull-rom", edge: str = "clamp",
             interpolating: bool = False, threads: int = 0) -> np.ndarray:
    """Resizes an (h, w) or (h, w, c) float32/float64 image with a spline basis function (or
    box, tent, lanczos3) as the reconstruction filter, exactly as `splinefig resample` does:
    size=(width, height), or scale=s or (sx, sy) with the size rounded. The result has the
    input's dtype (the arithmetic is the library's, in float32) and number of axes.
    A C-contiguous float32 array is read in place (it must not change during the call); any
    other (float64, another layout) is converted to one once. A uint8 or uint16 array (PIL's)
    holds sRGB values with straight alpha: it is decoded to linear light first, as
    read_image(linear=True) decodes a PNG, and the result is that linear float32 image."""
    a = _image(image, "image", srgb_ints=True)
    dtype = np.asarray(image).dtype
    dtype = np.float32 if dtype in (np.uint8, np.uint16) else dtype
    h, w = a.shape[0], a.shape[1]
    if (size is None) == (scale is None):
        raise ValueError("size, scale: give exactly one")
    if size is not None:
        if isinstance(size, (str, bytes)) or np.ndim(size) != 1 or len(size) != 2:
            raise TypeError("size: expected (width, height)")
        dw, dh = (_int(v, "size", 1, 65536) for v in size)
    else:
        s = [scale, scale] if np.ndim(scale) == 0 else list(scale)
        if len(s) != 2:
            raise ValueError("scale: expected s or (sx, sy)")
        s = [_real(v, "scale") for v in s]
        if any(v <= 0 for v in s):
            raise ValueError("scale: must be positive")
        dims = []
        for src, f, axis in ((w, s[0], "width"), (h, s[1], "height")):
            x = f * src  # rounded as std::round does: halves away from zero
            d = math.floor(x) + (1 if x - math.floor(x) >= 0.5 else 0)
            if d < 1 or d > 65536:
                raise ValueError(f"scale: the {axis} of {src} pixels becomes {d} (not in 1..65536)")
            dims.append(int(d))
        dw, dh = dims
    c = a.shape[2] if a.ndim == 3 else 1
    if dw * dh * c > (1 << 30):
        raise ValueError(f"size: {dw}x{dh}x{c} is over the limit of 2^30 samples")
    k = _kernel(filter, "filter")
    e = _choice(edge, "edge", ("clamp", "mirror", "wrap", "black"))
    out = _library("filter", _core.resample, a, dw, dh, k, e, bool(interpolating), _int(threads, "threads", 0, 256))
    return out if dtype == np.float32 else out.astype(dtype)


def _comparable(value: Any, name: str, linear: bool):
    """(float32 array, srgb?, display name) of an array or an image file."""
    if isinstance(value, (str, os.PathLike)):
        p = _path(value, name)
        a, enc = _core.read_image(p, linear)
        return a, enc == "srgb", p
    return _image(value, name), False, name


_FLOAT_MAX = float(np.finfo(np.float32).max)
_COMPARE_DEFAULTS = dict(fail=1e-6, warn=1e-6, failpercent=0.0, warnpercent=0.0, hardfail=math.inf,
                         hardwarn=math.inf, allowfailures=0, linear=False, ignore_alpha=False, shift=0,
                         ssim=None, flip=None, perceptual=False, threads=0)


def compare(a: Any, b: Any, *, mask: Any = None, **options: Any) -> dict:
    """Compares b (actual) with a (expected) as idiff and `splinefig diff` do; a and b are
    arrays or image files. Options (idiff's defaults): fail, warn, failpercent, warnpercent,
    hardfail, hardwarn, allowfailures, linear, ignore_alpha, shift, ssim (minimum), flip
    (maximum mean), perceptual (SSIM and FLIP without thresholds), threads. Returns a dict:
    verdict ("match", "warning", "failure"), idiff_verdict, mean_error, rms_error, psnr,
    max_error, max_pixel, max_channel, nwarn, nfail, npels, nvalues, ssim, flip_mean,
    flip_max, failures, text (idiff's lines) and json (`splinefig diff --json`)."""
    unknown = set(options) - set(_COMPARE_DEFAULTS)
    if unknown:
        raise TypeError(f"compare: unknown option {', '.join(sorted(unknown))}")
    o = dict(_COMPARE_DEFAULTS, **options)
    for k in ("fail", "warn", "hardfail", "hardwarn", "failpercent", "warnpercent"):
        v = o[k]
        if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise TypeError(f"{k}: expected a number, got {type(v).__name__}")
        v = float(v)
        if k.endswith("percent"):
            if not 0 <= v <= 100:
                raise ValueError(f"{k}: must be a percentage in [0, 100], got {v:g}")
        elif not (0 <= v <= _FLOAT_MAX or (v == math.inf and k.startswith("hard"))):
            # The thresholds are floats, as on the command line (`splinefig diff --fail`): a value
            # past the largest float would be compared as inf, which no value can exceed.
            none = ", or inf for none" if k.startswith("hard") else ""
            raise ValueError(f"{k}: must be a number in [0, 3.4028235e+38] (a float){none}, got {v:g}")
        o[k] = v
    o["allowfailures"] = _int(o["allowfailures"], "allowfailures", 0)
    o["shift"] = _int(o["shift"], "shift", 0, 64)
    o["threads"] = _int(o["threads"], "threads", 0, 256)
    for k in ("linear", "ignore_alpha", "perceptual"):
        if not isinstance(o[k], (bool, np.bool_)):
            raise TypeError(f"{k}: expected a bool, got {type(o[k]).__name__}")
        o[k] = bool(o[k])
    if o["ssim"] is not None and not -1 <= _real(o["ssim"], "ssim") <= 1:
        raise ValueError(f"ssim: {o['ssim']} is not in [-1, 1]")
    if o["flip"] is not None and not 0 <= _real(o["flip"], "flip") <= 1:
        raise ValueError(f"flip: {o['flip']} is not in [0, 1]")
    ia, sa, na = _comparable(a, "a", o["linear"])
    ib, sb, nb = _comparable(b, "b", o["linear"])
    m = None
    if mask is not None:
        m = _comparable(mask, "mask", False)[0]
    r = _library("mask", _core.compare, ia, sa, ib, sb, o, m, na, nb)
    r["_scale"] = 1.0 / r["max_error"] if 0 < r["max_error"] < math.inf else 1.0
    return r


def difference_image(a: Any, b: Any, *, scale: float = 1.0) -> np.ndarray:
    """|a - b| * scale per value (a and b of one shape), as `splinefig diff --diff-image`."""
    ia, ib = _image(a, "a"), _image(b, "b")
    if ia.shape != ib.shape:
        raise ValueError(f"a, b: shapes {ia.shape} and {ib.shape} differ")
    return _core.difference_image(ia, ib, _real(scale, "scale"))


def triptych(expected: Any, actual: Any, *, heat_scale: Optional[float] = None) -> np.ndarray:
    """expected | actual | heat map of the difference, sRGB-encoded RGB (write it with
    write_image(..., encoding="srgb")); heat_scale defaults to 1 / the largest difference."""
    r = compare(expected, actual)
    hs = r["_scale"] if heat_scale is None else _real(heat_scale, "heat_scale")
    return _core.triptych(r["_a"], r["_srgb"], r["_b"], r["_srgb"], hs)
