"""A matplotlib backend drawing through splinefig's exact-area rasterizer.

    import matplotlib
    matplotlib.use("module://splinefig.matplotlib")      # or
    fig.savefig("plot.png", backend="module://splinefig.matplotlib")

Every path, marker, collection, image and text of a figure becomes an item of one
splinefig.Scene, rasterized at once with exact area coverage (a stroke is the union of its
pieces; the bytes are the same for any thread count). Text is drawn as the unhinted glyph
outlines of matplotlib's own TextToPath, placed by the metrics matplotlib lays it out with, so
a PNG does not depend on the FreeType hinting of the machine. Compositing blends sRGB-encoded
values, as AGG does; ``blend="linear"`` (a savefig keyword, or ``BLEND`` below, or the
environment variable SPLINEFIG_MPL_BLEND) blends in linear light instead.

An image drawn with ``interpolation="none"`` is resampled by splinefig's resampler when a kernel
is named (``kernel="catmull-rom"`` as a savefig keyword, ``KERNEL``, the ``kernel(...)`` context
manager or SPLINEFIG_MPL_KERNEL): matplotlib hands over its source pixels and transform, and
the picture is exactly ``splinefig.resample`` of them to the image's size in device pixels.
See docs/matplotlib.md.
"""
from __future__ import annotations

import contextlib
import functools
import math
import os
from typing import Any, Iterator, Optional, Union

import numpy as np

import matplotlib as mpl
from matplotlib import cbook
from matplotlib.backend_bases import (FigureCanvasBase, FigureManagerBase, RendererBase, _Backend)
from matplotlib.path import Path
from matplotlib.textpath import TextToPath
from matplotlib.transforms import Affine2D

from . import Basis, Kernel, Scene, _choice, _kernel, _srgb_ints_to_linear, resample

__all__ = ["FigureCanvasSplinefig", "RendererSplinefig", "FigureCanvas", "FigureManager", "BLEND", "THREADS",
           "KERNEL", "KERNEL_EDGE", "KERNEL_INTERPOLATING", "PNG_LEVEL", "kernel"]

#: The default blend space: "srgb" (as AGG) or "linear"; SPLINEFIG_MPL_BLEND overrides it.
BLEND = "srgb"
#: Rasterizer threads (0: all cores). The bytes do not depend on it.
THREADS = 0
#: The reconstruction filter of images drawn with interpolation="none": None (matplotlib's own
#: resampling, as AGG) or a kernel spec ("catmull-rom", "cardinal:a=0.3", "bspline",
#: "beta:b1=2,b2=0", "lanczos3", ...), a splinefig.Kernel or Basis; SPLINEFIG_MPL_KERNEL
#: names one when this is None.
KERNEL: Union[None, str, Kernel, Basis] = None
#: The resampler's edge mode for those images: "clamp", "mirror", "wrap" or "black".
KERNEL_EDGE = "clamp"
#: Whether an approximating kernel (bspline, beta, ...) is made to interpolate the source
#: pixels first (`splinefig resample --interpolating`).
KERNEL_INTERPOLATING = False

_CAPS = {"butt": "butt", "round": "round", "projecting": "square"}
_HATCH_SIZE = 72  # points: matplotlib's hatch tile is one inch square, as in AGG


def _linear(rgba) -> tuple:
    """matplotlib's sRGB floats (straight alpha) -> the linear-light floats Scene takes."""
    c = tuple(float(v) for v in np.asarray(rgba, dtype=np.float64).ravel()[:4])
    return _linear_of(c)


@functools.lru_cache(maxsize=4096)
def _linear_of(c: tuple) -> tuple:
    # A collection draws the same few colours thousands of times: each is converted once.
    def lin(v):
        v = min(max(v, 0.0), 1.0)
        return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4
    a = c[3] if len(c) > 3 else 1.0
    return (lin(c[0]), lin(c[1]), lin(c[2]), min(max(a, 0.0), 1.0))


def _blend_of(value: Optional[str]) -> str:
    b = value if value is not None else os.environ.get("SPLINEFIG_MPL_BLEND") or BLEND
    if b not in ("srgb", "linear"):
        raise ValueError(f"blend: unknown value '{b}' (known: srgb, linear)")
    return b


class _ImageKernel:
    """A resolved kernel choice: the kernel, its spec as given, the edge mode, the prefilter."""

    def __init__(self, k: Kernel, spec: str, edge: str, interpolating: bool) -> None:
        self.k, self.spec, self.edge, self.interpolating = k, spec, edge, interpolating


def _kernel_of(value: Any, edge: Optional[str], interpolating: Optional[bool]) -> Optional[_ImageKernel]:
    """The kernel choice of a draw: the keyword, else KERNEL, else $SPLINEFIG_MPL_KERNEL; False (or
    an empty variable) is matplotlib's own resampling. Checked here, before anything is drawn: a
    bad spec, edge mode, or a prefilter the kernel has no stable inverse for is a ValueError
    naming the keyword."""
    v = value if value is not None else KERNEL
    if v is None:
        v = os.environ.get("SPLINEFIG_MPL_KERNEL") or None
    if v is None or v is False:
        return None
    k = _kernel(v, "kernel")
    e = _choice(KERNEL_EDGE if edge is None else edge, "kernel_edge", ("clamp", "mirror", "wrap", "black"))
    i = KERNEL_INTERPOLATING if interpolating is None else interpolating
    if not isinstance(i, (bool, np.bool_)):
        raise TypeError(f"kernel_interpolating: expected True or False, got {type(i).__name__}")
    if i:
        try:  # the prefilter's stability is the kernel's: a 3 x 3 picture says it now
            resample(np.zeros((3, 3), np.float32), size=(3, 3), filter=k, edge=e, interpolating=True, threads=1)
        except ValueError as err:
            raise ValueError(f"kernel_interpolating: {err}") from None
    return _ImageKernel(k, v if isinstance(v, str) else repr(v), e, bool(i))


@contextlib.contextmanager
def kernel(spec: Union[str, Kernel, Basis], *, edge: str = "clamp", interpolating: bool = False) -> Iterator[None]:
    """Within the block, images drawn with interpolation="none" are resampled with this kernel
    (KERNEL, KERNEL_EDGE and KERNEL_INTERPOLATING set, and restored after):

        with splinefig.matplotlib.kernel("catmull-rom"):
            fig.savefig("plot.png", backend="module://splinefig.matplotlib")
    """
    global KERNEL, KERNEL_EDGE, KERNEL_INTERPOLATING
    _kernel_of(spec, edge, interpolating)  # a bad choice is refused at the with statement
    old = KERNEL, KERNEL_EDGE, KERNEL_INTERPOLATING
    KERNEL, KERNEL_EDGE, KERNEL_INTERPOLATING = spec, edge, interpolating
    try:
        yield
    finally:
        KERNEL, KERNEL_EDGE, KERNEL_INTERPOLATING = old


def _round_half_away(v: float) -> int:
    return int(math.floor(v + 0.5) if v >= 0 else math.ceil(v - 0.5))


def _edge_indices(j: np.ndarray, n: int, edge: str) -> np.ndarray:
    """Source indices of extended positions j under an edge mode (-1: black), as the resampler
    reads them (docs/resample.md)."""
    if edge == "clamp":
        return np.clip(j, 0, n - 1)
    if edge == "wrap":
        return np.mod(j, n)
    if edge == "mirror":
        r = np.mod(j, 2 * n)
        return np.where(r < n, r, 2 * n - 1 - r)
    return np.where((j >= 0) & (j < n), j, -1)


def _prefiltered(src: np.ndarray, ik: "_ImageKernel") -> np.ndarray:
    """The coefficients that make an approximating kernel interpolate src (float64, (h, w, c)):
    along every row and then every column, solve k(1) c[i-1] + k(0) c[i] + k(-1) c[i+1] = p[i]
    with c extended by the edge mode (docs/resample.md, --interpolating)."""
    from . import _core
    s = np.asarray(_core.kernel_values(ik.k, np.array([-1.0, 0.0, 1.0])), dtype=np.float64)
    s = s / s.sum()
    left, centre, right = s[0], s[1], s[2]  # the coefficients of c[i+1], c[i], c[i-1]
    c = np.array(src, dtype=np.float64)
    for axis in (1, 0):
        c = np.moveaxis(c, axis, 0)
        n = c.shape[0]
        if ik.edge == "wrap":
            row = np.zeros(n)
            row[0] += centre
            row[1 % n] += right
            row[-1 % n] += left
            c = np.real(np.fft.ifft(np.fft.fft(c, axis=0) / np.fft.fft(row)[(slice(None),) + (None,) * (c.ndim - 1)], axis=0))
        else:
            # Tridiagonal (Thomas): sub-diagonal right, diagonal centre, super-diagonal left; clamp
            # and mirror extend c by c[-1] = c[0], c[n] = c[n-1], black by zeros.
            diag = np.full(n, centre)
            if ik.edge != "black":
                diag[0] += right
                diag[-1] += left
            cp = np.zeros(n)
            d = np.empty_like(c)
            cp[0] = left / diag[0] if n > 1 else 0.0
            d[0] = c[0] / diag[0]
            for i in range(1, n):
                den = diag[i] - right * cp[i - 1]
                cp[i] = left / den
                d[i] = (c[i] - right * d[i - 1]) / den
            for i in range(n - 2, -1, -1):
                d[i] -= cp[i] * d[i + 1]
            c = d
        c = np.moveaxis(c, 0, axis)
    return c


def _taps(ik: "_ImageKernel", fac: float) -> int:
    """Taps per axis of the direct sums with the kernel widened by fac."""
    lo, hi = ik.k.support
    return int(math.ceil((hi - lo) * fac)) + 2


def _kernel_sums(src: np.ndarray, inv: np.ndarray, f: tuple, box: tuple, ik: "_ImageKernel",
                 sign: tuple = (1.0, 1.0)) -> np.ndarray:
    """The resampler's sum evaluated directly for the canvas pixels of box (x0, y0, x1, y1): pixel
    (X, Y)'s centre maps by inv (2 x 3) to the source position (u, v), and its value is
    sum_ij wx_i wy_j p[j, i] with wx_i = k(sx (u - (i + 1/2)) / fx) normalised to sum 1 (wy
    likewise; sx = -1 runs the kernel against the axis, as resampling the flipped source
    does), positions outside the source read by the edge mode. src: (h, w, 4) linear,
    associated alpha."""
    from . import _core
    h, w = src.shape[:2]
    coef = _prefiltered(src, ik) if ik.interpolating else np.asarray(src, dtype=np.float64)
    x0, y0, x1, y1 = box
    yy, xx = np.mgrid[y0:y1, x0:x1].astype(np.float64) + 0.5
    u = inv[0, 0] * xx + inv[0, 1] * yy + inv[0, 2]
    v = inv[1, 0] * xx + inv[1, 1] * yy + inv[1, 2]
    lo, hi = ik.k.support

    def weights(pos, fac, sgn, n):
        # Taps where sgn (pos - (j + 1/2)) / fac lies in the support [lo, hi).
        top = hi if sgn > 0 else -lo
        first = np.floor(pos - 0.5 - top * fac)
        taps = _taps(ik, fac)
        j = first[..., None] + np.arange(taps)
        arg = sgn * (pos[..., None] - (j + 0.5)) / fac
        wt = np.asarray(_core.kernel_values(ik.k, np.ascontiguousarray(arg.ravel()))).reshape(j.shape)
        total = wt.sum(axis=-1, keepdims=True)
        wt = np.divide(wt, total, out=np.zeros_like(wt), where=total != 0)
        return _edge_indices(j.astype(np.int64), n, ik.edge), wt

    ix, wx = weights(u, f[0], sign[0], w)
    iy, wy = weights(v, f[1], sign[1], h)
    out = np.zeros(u.shape + (src.shape[2],), dtype=np.float64)
    for b in range(iy.shape[-1]):
        rows = iy[..., b]
        for a_ in range(ix.shape[-1]):
            cols = ix[..., a_]
            wgt = wy[..., b] * wx[..., a_]
            ok = (rows >= 0) & (cols >= 0)
            val = coef[np.where(ok, rows, 0), np.where(ok, cols, 0)]
            out += np.where(ok, wgt, 0.0)[..., None] * val
    return out


_HINTING_FACTOR = 8  # matplotlib's default text.hinting_factor

_TEXT_RC = tuple(k for k in dict.keys(mpl.rcParams) if k.startswith(("font.", "mathtext.")))


class _CachedTextToPath(TextToPath):
    """TextToPath whose outlines are kept: a figure draws the same tick labels at every save.
    The key is the string, the font properties and every font and mathtext setting (TeX is not
    kept). One instance serves every renderer, so its mathtext parser's own cache is kept too."""

    _SIZE = 2048

    def __init__(self) -> None:
        super().__init__()
        self._paths: dict = {}

    @staticmethod
    def key(prop, s, ismath) -> tuple:
        rc = tuple(tuple(v) if isinstance(v, list) else v for v in (dict.get(mpl.rcParams, k) for k in _TEXT_RC))
        return (s, bool(ismath), tuple(prop.get_family()), prop.get_style(), prop.get_variant(), prop.get_weight(),
                prop.get_stretch(), prop.get_size_in_points(), prop.get_file(), prop.get_math_fontfamily(), rc)

    def kept(self, key, make):
        got = self._paths.get(key)
        if got is None:
            got = make()
            if len(self._paths) >= self._SIZE:
                self._paths.pop(next(iter(self._paths)))
            self._paths[key] = got
        return got

    def get_text_path(self, prop, s, ismath=False):
        if ismath == "TeX":
            return super().get_text_path(prop, s, ismath=ismath)

        def make():
            verts, codes = super(_CachedTextToPath, self).get_text_path(prop, s, ismath=ismath)
            verts, codes = np.array(verts, dtype=np.float64), np.array(codes, dtype=np.uint8)
            verts.flags.writeable = codes.flags.writeable = False
            return verts, codes
        return self.kept(("path",) + self.key(prop, s, ismath), make)


# A marker's picture (its fill and stroke rasterized once) by its outline, colours and blend
# space: tick marks are the same few markers in every figure and every save.
_STAMPS: dict = {}

# One for every renderer: a canvas makes a renderer per draw (AGG's canvas keeps its renderer,
# and so its caches).
_TEXT2PATH = _CachedTextToPath()


class _unhinted:
    """Fonts loaded at the default hinting factor while text is measured or outlined:
    TextToPath loads glyphs unhinted, but FreeType's advances depend on the factor."""

    def __enter__(self):
        self.old = mpl.rcParams["text.hinting_factor"]
        if self.old != _HINTING_FACTOR:
            dict.__setitem__(mpl.rcParams, "text.hinting_factor", _HINTING_FACTOR)

    def __exit__(self, *exc):
        if self.old != _HINTING_FACTOR:
            dict.__setitem__(mpl.rcParams, "text.hinting_factor", self.old)
        return False


# A marker outline's exact extents (Path.get_extents solves for its curves' extrema, about half a
# millisecond) by its vertices and codes: every tick of an axis is one draw_markers call with the
# same outline.
_EXTENTS: dict = {}


def _extents(path: Path):
    key = (path.vertices.tobytes(), None if path.codes is None else path.codes.tobytes())
    ext = _EXTENTS.get(key)
    if ext is None:
        if len(_EXTENTS) >= 256:
            _EXTENTS.pop(next(iter(_EXTENTS)))
        ext = _EXTENTS[key] = path.get_extents().frozen()
    return ext


def _snaps(path: Path, snap) -> bool:
    """Whether AGG's path snapper moves this path's vertices to the pixel grid: always for
    snap=True, never for False, and for None only a path of at most 1024 vertices made of
    horizontal and vertical lines."""
    if snap is not None:
        return bool(snap)
    v, codes = path.vertices, path.codes
    if len(v) == 0 or len(v) > 1024:
        return False
    if codes is None:
        codes = np.full(len(v), Path.LINETO, np.uint8)
        codes[0] = Path.MOVETO
    for i in range(1, len(v)):
        c = codes[i]
        if c in (Path.CURVE3, Path.CURVE4):
            return False
        if c == Path.LINETO and abs(v[i][0] - v[i - 1][0]) >= 1e-4 and abs(v[i][1] - v[i - 1][1]) >= 1e-4:
            return False
    return True


class _Target:
    """Where items go: the figure's scene (main, clipped by the scene's clip to `box` for shapes;
    rasters are cropped to it), or a clip layer (a scene over an integer rectangle of the canvas,
    composited into the figure's scene when it is closed). x0, y0: the scene's origin on the
    canvas; box: the canvas rectangle (x0, y0, x1, y1) items are clipped to."""

    def __init__(self, scene: Scene, x0: int = 0, y0: int = 0, key: Any = None, clip_path: Any = None,
                 masked: bool = False, box: Optional[tuple] = None, main: bool = False) -> None:
        self.scene, self.core, self.x0, self.y0, self.key, self.clip_path = scene, scene._s, x0, y0, key, clip_path
        self.masked = masked  # clip_path is applied as a coverage mask when the layer is closed
        self.box = box if box is not None else (x0, y0, x0 + scene.width, y0 + scene.height)
        self.main = main
        self.items = 0


class RendererSplinefig(RendererBase):
    """Draws a figure into one splinefig Scene (pixels, y down, as AGG's buffer)."""

    def __init__(self, width: float, height: float, dpi: float, *, blend: Optional[str] = None, threads: Optional[int] = None,
                 kernel: Union[None, bool, str, Kernel, Basis] = None, kernel_edge: Optional[str] = None,
                 kernel_interpolating: Optional[bool] = None) -> None:
        super().__init__()
        self.image_kernel = _kernel_of(kernel, kernel_edge, kernel_interpolating)
        self.dpi = dpi
        self.width = int(math.ceil(width))
        self.height = int(math.ceil(height))
        self.blend = _blend_of(blend)
        self.threads = THREADS if threads is None else int(threads)
        self.scene = Scene(max(self.width, 1), max(self.height, 1), background=(1.0, 1.0, 1.0, 0.0), blend=self.blend)
        self._text2path = _TEXT2PATH
        self._flip_t = Affine2D().scale(1, -1).translate(0, self.height)  # display space -> pixels, y down
        self._main = _Target(self.scene, main=True)
        self._boxed: dict = {}  # box -> the main scene's target clipped to it
        self._main_clip: Optional[tuple] = None  # the box the main scene clips shapes to now
        self._layer: Optional[_Target] = None

    # ---- matplotlib's questions ---------------------------------------------------------
    def get_canvas_width_height(self):
        return self.width, self.height

    def points_to_pixels(self, points):
        return points * self.dpi / 72

    def flipy(self):
        return True

    def option_image_nocomposite(self):
        return True  # as AGG: each image is drawn by itself

    def option_scale_image(self):
        # Images arrive resampled to the canvas's pixels by matplotlib, but for those drawn with
        # interpolation="none" when a kernel is chosen: they come as their source pixels with
        # their transform, and draw_image resamples them.
        return self.image_kernel is not None

    # ---- clipping ---------------------------------------------------------------------
    def _clip_box(self, gc):
        """The clip rectangle as AGG takes it: rounded to whole pixels, within the canvas; None
        when it is the whole canvas or absent."""
        r = gc.get_clip_rectangle()
        if r is None:
            return None
        x1, y1, x2, y2 = r.extents
        if (x1, y1, x2, y2) == (0, 0, 0, 0):
            return None
        H = self.height
        box = (max(int(math.floor(x1 + 0.5)), 0), max(int(math.floor(H - y2 + 0.5)), 0),
               min(int(math.floor(x2 + 0.5)), self.width), min(int(math.floor(H - y1 + 0.5)), H))
        return box

    def _target(self, gc, raster: bool = False) -> Optional[_Target]:
        """The target for gc's clip, or None when nothing can show. A clip rectangle (whole
        pixels) clips the main scene's shapes exactly (the scene's clip) and crops its rasters,
        which is the same picture as drawing them into a layer over the rectangle. A clip path
        gives a layer: paths and text are clipped by it exactly (the layer's scene intersects
        them with it); rasters (images, Gouraud meshes), which the renderer does not clip, go to
        a layer multiplied by the clip path's exact coverage."""
        box = self._clip_box(gc)
        cp, cp_trans = gc.get_clip_path()
        full = (0, 0, self.width, self.height)
        if box is not None and (box[2] <= box[0] or box[3] <= box[1]):
            return None
        if cp is None:
            self._close_layer()
            if box is None or box == full:
                return self._main
            t = self._boxed.get(box)
            if t is None:
                t = self._boxed[box] = _Target(self.scene, box=box, main=True)
            return t
        clip_path = cp.cleaned(cp_trans + self._flip(), remove_nans=True, curves=True)
        if box is None:
            box = full
        masked = raster
        key = (box, clip_path.vertices.tobytes(), clip_path.codes.tobytes(), masked)
        if self._layer is not None and self._layer.key == key:
            return self._layer
        self._close_layer()
        w, h = box[2] - box[0], box[3] - box[1]
        self._layer = _Target(Scene(w, h, background=(0.0, 0.0, 0.0, 0.0), blend=self.blend), box[0], box[1], key, clip_path,
                              masked)
        if not masked:
            v = np.ascontiguousarray(clip_path.vertices - (box[0], box[1]), dtype=np.float64)
            self._layer.core.set_clip(v, self._codes(clip_path), "nonzero")
        return self._layer

    def _for_shapes(self, t: _Target) -> None:
        """Sets the main scene's clip to t's box before shapes are added to it."""
        if not t.main:
            return
        box = None if t.box == (0, 0, self.width, self.height) else t.box
        if box == self._main_clip:
            return
        if box is None:
            self.scene._s.clear_clip()
        else:
            x0, y0, x1, y1 = box
            v = np.array([(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)], dtype=np.float64)
            self.scene._s.set_clip(v, np.array([1, 2, 2, 2, 79], np.uint8), "nonzero")
        self._main_clip = box

    def _for_rasters(self, t: _Target) -> None:
        """Clears the main scene's clip before rasters (cropped to t's box) are added to it."""
        if t.main and self._main_clip is not None:
            self.scene._s.clear_clip()
            self._main_clip = None

    def _composite(self, into: _Target, t: _Target, mask: Optional[np.ndarray] = None) -> None:
        """Draws target t's picture (times mask, a per-pixel coverage) into `into` at t's place."""
        im = t.core.render(self._threads_for(t.scene))
        if mask is not None:
            im = im * mask[:, :, None]
        self._picture(into, im, t.x0, t.y0)

    def _picture(self, into: _Target, im: np.ndarray, x0: int, y0: int) -> None:
        """Composites a picture (float32, associated alpha, in the blend space's values, as a
        scene renders it) into `into` at canvas pixel (x0, y0)."""
        x0, y0 = x0 - into.x0, y0 - into.y0
        self._for_rasters(into)
        clipped = into.clip_path is not None and not into.masked
        if clipped:  # a layer whose scene clips: the picture (already clipped) goes in unclipped
            into.core.clear_clip()
        # In the blend space's values, as rendered: no round trip through linear light.
        into.core.images(np.ascontiguousarray(im, dtype=np.float32), np.array([[x0, y0]], dtype=np.float64),
                         "srgb" if self.blend == "srgb" else "linear")
        if clipped:
            into.core.set_clip(np.ascontiguousarray(into.clip_path.vertices - (into.x0, into.y0), dtype=np.float64),
                               self._codes(into.clip_path), "nonzero")
        into.items += 1

    def _coverage(self, path: Path, x0: int, y0: int, w: int, h: int, rule: str = "nonzero",
                  clip: Optional[Path] = None) -> np.ndarray:
        """The exact area coverage of a filled path (canvas pixels), intersected with the clip path
        when there is one, over a w x h rectangle at (x0, y0)."""
        s = Scene(w, h, background=(0.0, 0.0, 0.0, 0.0))
        if clip is not None:
            s._s.set_clip(np.ascontiguousarray(clip.vertices - (x0, y0), dtype=np.float64), self._codes(clip), "nonzero")
        v = np.ascontiguousarray(path.vertices - (x0, y0), dtype=np.float64)
        s._s.fill_path(v, self._codes(path), rule, (1.0, 1.0, 1.0, 1.0))
        return s._s.render(self._threads_for(s))[:, :, 3]

    def _threads_for(self, scene: Scene) -> int:
        """Threads for rendering a picture apart (a layer, a mask): one for a small one, where
        starting threads costs more than they save; the bytes are the same either way."""
        return 1 if scene.width * scene.height <= 1 << 16 else self.threads

    def _close_layer(self) -> None:
        t, self._layer = self._layer, None
        if t is None or t.items == 0:
            return
        mask = None
        if t.masked:
            h, w = t.scene.height, t.scene.width
            mask = self._coverage(t.clip_path, t.x0, t.y0, w, h)
        self._composite(self._main, t, mask)

    def finish(self) -> None:
        self._close_layer()

    # ---- drawing ----------------------------------------------------------------------
    @staticmethod
    def _codes(path: Path) -> np.ndarray:
        if path.codes is None:
            return np.zeros(0, np.uint8)
        return np.ascontiguousarray(path.codes, dtype=np.uint8)

    def _flip(self):
        return self._flip_t

    def _stroke_style(self, gc) -> Optional[dict]:
        lw = self.points_to_pixels(gc.get_linewidth())
        rgba = gc.get_rgb()
        if not lw > 0 or len(rgba) > 3 and rgba[3] <= 0:
            return None
        offset, dashes = gc.get_dashes()
        ds = []
        if dashes is not None and len(dashes):
            ds = [float(self.points_to_pixels(d)) for d in dashes]
            if sum(ds) <= 0:
                ds = []
        return dict(width=float(lw), join=gc.get_joinstyle(), cap=_CAPS.get(gc.get_capstyle(), "butt"), miter_limit=4.0,
                    dashes=ds, dash_offset=float(self.points_to_pixels(offset or 0.0)), color=_linear(rgba))

    def _fill_color(self, gc, rgbFace) -> Optional[tuple]:
        if rgbFace is None:
            return None
        c = list(rgbFace)
        if gc.get_forced_alpha() or len(c) == 3:
            c = c[:3] + [gc.get_alpha()]
        if c[3] <= 0:
            return None
        return _linear(c)

    def _emit(self, t: _Target, path: Path, fill, stroke, rule: str = "nonzero") -> None:
        v = path.vertices
        if len(v) == 0:
            return
        self._for_shapes(t)
        if t.x0 or t.y0:
            v = v - (t.x0, t.y0)
        v = np.ascontiguousarray(v, dtype=np.float64)
        c = self._codes(path)
        if fill is not None:
            t.core.fill_path(v, c, rule, fill)
            t.items += 1
        if stroke is not None:
            t.core.stroke_path(v, c, stroke["color"], stroke["width"], stroke["join"], stroke["cap"], stroke["miter_limit"],
                               stroke["dashes"], stroke["dash_offset"])
            t.items += 1

    def _prepared(self, gc, path: Path, transform, fill, stroke, snap=None) -> Path:
        """The path in canvas pixels as AGG prepares it: NaNs removed, snapped (gc's snap, path.snap),
        simplified when only stroked (path.simplify), long strokes clipped to the canvas."""
        lw = float(self.points_to_pixels(gc.get_linewidth()))  # AGG snaps by gc's width, drawn or not
        return self._prepared_lw(path, transform, fill, stroke, lw, gc.get_snap() if snap is None else snap,
                                 hatch=gc.get_hatch_path() is not None, sketch=gc.get_sketch_params())

    def _prepared_lw(self, path: Path, transform, fill, stroke, lw: float, snap, hatch: bool = False, sketch=None) -> Path:
        trans = transform + self._flip()
        clip = None
        if fill is None and not hatch and stroke is not None and not stroke["dashes"]:
            m = 4 * lw + 16
            clip = (-m, -m, self.width + m, self.height + m)
        simplify = path.should_simplify and fill is None and not hatch
        return path.cleaned(trans, remove_nans=True, clip=clip, simplify=simplify, curves=True,
                            stroke_width=lw, snap=snap, sketch=sketch)

    def draw_path(self, gc, path, transform, rgbFace=None):
        t = self._target(gc)
        if t is None:
            return
        fill = self._fill_color(gc, rgbFace)
        stroke = self._stroke_style(gc)
        hatch = gc.get_hatch_path()
        if fill is None and stroke is None and hatch is None:
            return
        p = self._prepared(gc, path, transform, fill, stroke)
        self._emit(t, p, fill, None)
        if hatch is not None:
            self._hatch(gc, t, p, hatch)
        self._emit(t, p, None, stroke)

    def _hatch(self, gc, t: _Target, p: Path, hatch: Path) -> None:
        """The hatch pattern (one-inch tiles from the canvas origin, as AGG) inside the filled path."""
        ext = p.get_extents()
        x0 = max(int(math.floor(ext.x0)), t.box[0])
        y0 = max(int(math.floor(ext.y0)), t.box[1])
        x1 = min(int(math.ceil(ext.x1)), t.box[2])
        y1 = min(int(math.ceil(ext.y1)), t.box[3])
        if x1 <= x0 or y1 <= y0:
            return
        size = int(self.points_to_pixels(_HATCH_SIZE))
        if size < 1:
            return
        lw = float(self.points_to_pixels(mpl.rcParams["hatch.linewidth"]))
        color = _linear(gc.get_hatch_color())
        tile = hatch.transformed(Affine2D().scale(size, size).scale(1, -1).translate(0, size))
        key = ("hatch", size, tile.vertices.tobytes(), self._codes(tile).tobytes(), lw, color, self.blend)
        pattern = _STAMPS.get(key)
        if pattern is None:
            # One tile, drawn into a scene of its size, which cuts the lines that run past it (as
            # AGG draws its hatch into a tile buffer): filled, then stroked with square caps.
            scene = Scene(size, size, background=(0.0, 0.0, 0.0, 0.0), blend=self.blend)
            v, codes = np.ascontiguousarray(tile.vertices, dtype=np.float64), self._codes(tile)
            scene._s.fill_path(v, codes, "nonzero", color)
            if lw > 0:
                scene._s.stroke_path(v, codes, color, lw, "miter", "square", 4.0, [], 0.0)
            pattern = np.ascontiguousarray(scene._s.render(self._threads_for(scene)), dtype=np.float32)
            pattern.flags.writeable = False
            if len(_STAMPS) >= 256:
                _STAMPS.pop(next(iter(_STAMPS)))
            _STAMPS[key] = pattern
        # The tiles repeat from the canvas origin; the part over the path's pixels, times the
        # path's exact coverage.
        w, h = x1 - x0, y1 - y0
        ox, oy = x0 % size, y0 % size
        reps = ((oy + h + size - 1) // size, (ox + w + size - 1) // size, 1)
        im = np.tile(pattern, reps)[oy:oy + h, ox:ox + w]
        mask = self._coverage(p, x0, y0, w, h, clip=None if t.masked else t.clip_path)
        self._picture(t, im * mask[:, :, None], x0, y0)

    def draw_path_collection(self, gc, master_transform, paths, all_transforms, offsets, offset_trans, facecolors,
                             edgecolors, linewidths, linestyles, antialiaseds, urls, offset_position):
        """RendererBase's loop (the same items, colours, widths and dashes, in the same order,
        each its own fill and stroke), without a graphics context and a transform per item: a
        path that is not snapped to the pixel grid is prepared once and moved to each offset."""
        if gc.get_hatch_path() is not None or gc.get_sketch_params() is not None:
            return super().draw_path_collection(gc, master_transform, paths, all_transforms, offsets, offset_trans,
                                                facecolors, edgecolors, linewidths, linestyles, antialiaseds, urls,
                                                offset_position)
        path_ids = list(self._iter_collection_raw_paths(master_transform, paths, all_transforms))
        Npaths, Noffsets = len(path_ids), len(offsets)
        N = max(Npaths, Noffsets)
        Nfc, Nec, Nlw, Nls = len(facecolors), len(edgecolors), len(linewidths), len(linestyles)
        if (Nfc == 0 and Nec == 0) or Npaths == 0:
            return
        t = self._target(gc)
        if t is None:
            return
        toffsets = np.asarray(offset_trans.transform(offsets), dtype=np.float64).reshape(-1, 2) if Noffsets else None
        forced, alpha = gc.get_forced_alpha(), gc.get_alpha()
        snap = gc.get_snap()
        # gc0's state, which RendererBase's loop changes item by item and keeps for the next.
        lw_pt = 0.0 if Nec == 0 else gc.get_linewidth()
        dash_off, dash_list = gc.get_dashes()
        stroke_rgba = tuple(gc.get_rgb())
        flip = self._flip()
        styles: dict = {}
        bases: dict = {}
        self._gc_join, self._gc_cap = gc.get_joinstyle(), _CAPS.get(gc.get_capstyle(), "butt")
        core = t.core
        self._for_shapes(t)

        def stroke_of(lw_pt, dash_off, dash_list, rgba):
            key = (lw_pt, dash_off, None if dash_list is None else tuple(dash_list), rgba)
            st = styles.get(key, False)
            if st is False:
                lw = self.points_to_pixels(lw_pt)
                st = None
                if lw > 0 and not (len(rgba) > 3 and rgba[3] <= 0):
                    ds = []
                    if dash_list is not None and len(dash_list):
                        ds = [float(self.points_to_pixels(d)) for d in dash_list]
                        if sum(ds) <= 0:
                            ds = []
                    st = (_linear_of(tuple(float(v) for v in rgba)), float(lw), gc.get_joinstyle(),
                          _CAPS.get(gc.get_capstyle(), "butt"), 4.0, ds, float(self.points_to_pixels(dash_off or 0.0)))
                styles[key] = st
            return st

        if self._collection_at_once(t, path_ids, N, toffsets, facecolors, edgecolors, linewidths, linestyles, forced, alpha,
                                    lw_pt, dash_off, dash_list, snap):
            return
        for i in range(N):
            path, transform = path_ids[i % Npaths]
            xo = yo = 0.0
            if Noffsets:
                xo, yo = toffsets[i % Noffsets]
                if not (math.isfinite(xo) and math.isfinite(yo)):
                    continue
            if Nec:
                if Nlw:
                    lw_pt = linewidths[i % Nlw]
                if Nls:
                    dash_off, dash_list = linestyles[i % Nls]
                ec = edgecolors[i % Nec]
                if len(ec) == 4 and ec[3] == 0.0:
                    lw_pt = 0
                else:
                    ec = mpl.colors.to_rgba(tuple(ec) if isinstance(ec, np.ndarray) else ec)
                    stroke_rgba = ec[:3] + (alpha,) if forced else ec
            fill = None
            if Nfc:
                fc = facecolors[i % Nfc]
                if not (len(fc) == 4 and fc[3] == 0):
                    c = tuple(float(v) for v in fc)
                    if forced or len(c) == 3:
                        c = c[:3] + (alpha,)
                    if c[3] > 0:
                        fill = _linear_of(c)
            stroke = stroke_of(lw_pt, dash_off, dash_list, stroke_rgba)
            if fill is None and stroke is None:
                continue
            lw = float(self.points_to_pixels(lw_pt))
            key = (i % Npaths, fill is None, stroke is None or bool(stroke[5]), lw)
            base = bases.get(key)
            if base is None:
                # Prepared at the origin as draw_path prepares it; a path that the grid snapping
                # moves (which depends on where it lies) or that is simplified is prepared per item.
                simplify = path.should_simplify and fill is None
                p = path.cleaned(transform + flip, remove_nans=True, simplify=simplify, curves=True, stroke_width=lw,
                                 snap=snap)
                movable = not simplify and not _snaps(p, snap)
                base = bases[key] = (movable, np.ascontiguousarray(p.vertices, dtype=np.float64), self._codes(p))
            movable, v, codes = base
            if movable:
                if xo != 0 or yo != 0:
                    v = v + (xo, -yo)
            else:
                tr = transform.frozen().translate(xo, yo) if xo != 0 or yo != 0 else transform
                st = None if stroke is None else dict(width=stroke[1], dashes=stroke[5])
                p = self._prepared_lw(path, tr, fill, st, lw, snap)
                v, codes = np.ascontiguousarray(p.vertices, dtype=np.float64), self._codes(p)
            if len(v) == 0:
                continue
            if t.x0 or t.y0:
                v = v - (t.x0, t.y0)
            if fill is not None:
                core.fill_path(v, codes, "nonzero", fill)
                t.items += 1
            if stroke is not None:
                core.stroke_path(v, codes, *stroke)
                t.items += 1

    def _collection_at_once(self, t, path_ids, N, toffsets, facecolors, edgecolors, linewidths, linestyles, forced, alpha,
                            lw_pt, dash_off, dash_list, snap) -> bool:
        """The loop of draw_path_collection in one call to the scene, for one path that is moved,
        not reshaped, from item to item (not snapped, not simplified) under one dash pattern:
        the same items, colours and widths. False when the collection is not of that kind."""
        if len(path_ids) != 1 or len(linestyles) > 1 or N < 2:
            return False
        path, transform = path_ids[0]
        if path.should_simplify:
            return False
        Nfc, Nec, Nlw = len(facecolors), len(edgecolors), len(linewidths)
        ec = np.asarray(edgecolors, dtype=np.float64).reshape(-1, 4) if Nec else np.zeros((0, 4))
        fc = np.asarray(facecolors, dtype=np.float64).reshape(-1, 4) if Nfc else np.zeros((0, 4))
        if Nec and Nlw == 0 and (ec[:, 3] == 0).any():
            return False  # a transparent edge sets gc0's width to 0 for the items after it too
        if len(linestyles):
            dash_off, dash_list = linestyles[0]
        lw0 = float(self.points_to_pixels(lw_pt))
        p = path.cleaned(transform + self._flip(), remove_nans=True, curves=True, stroke_width=lw0, snap=snap)
        if _snaps(p, snap):
            return False
        idx = np.arange(N)
        if toffsets is not None:
            offs = toffsets[idx % len(toffsets)]
            ok = np.isfinite(offs).all(axis=1)
            idx, offs = idx[ok], offs[ok] * (1.0, -1.0)
        else:
            offs = np.zeros((N, 2))
        n = len(idx)

        def linear(c):
            rgb = np.clip(c[:, :3], 0.0, 1.0)
            rgb = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
            return np.column_stack([rgb, np.clip(c[:, 3], 0.0, 1.0)])

        fills = np.full((n, 4), -1.0)
        if Nfc:
            c = fc[idx % Nfc]
            keep = c[:, 3] != 0
            if forced:
                c = c.copy()
                c[:, 3] = alpha
            keep &= c[:, 3] > 0
            fills[keep] = linear(c[keep])
        strokes = np.full((n, 4), -1.0)
        widths = np.zeros(n)
        if Nec:
            c = ec[idx % Nec]
            lws = np.asarray(linewidths, dtype=np.float64)[idx % Nlw] if Nlw else np.full(n, float(lw_pt))
            lws = np.where(c[:, 3] == 0.0, 0.0, lws)
            if forced:
                c = c.copy()
                c[:, 3] = alpha
            widths = lws * (self.dpi / 72)
            keep = (widths > 0) & (c[:, 3] > 0)
            strokes[keep] = linear(c[keep])
            widths = np.where(keep, widths, 0.0)
        ds = []
        if dash_list is not None and len(dash_list):
            ds = [float(self.points_to_pixels(d)) for d in dash_list]
            if sum(ds) <= 0:
                ds = []
        self._for_shapes(t)
        t.core.path_items(np.ascontiguousarray(p.vertices, dtype=np.float64), self._codes(p), np.ascontiguousarray(offs),
                          fills, strokes, np.ascontiguousarray(widths), "nonzero", self._gc_join, self._gc_cap, 4.0, ds,
                          float(self.points_to_pixels(dash_off or 0.0)), float(t.x0), float(t.y0))
        t.items += 2 * n
        return True

    def draw_markers(self, gc, marker_path, marker_trans, path, trans, rgbFace=None):
        """One outline, prepared once, drawn at each vertex of path (at the nearest whole pixel,
        as AGG places markers); each marker is its own item, so overlapping markers blend."""
        t = self._target(gc)
        if t is None:
            return
        fill = self._fill_color(gc, rgbFace)
        stroke = self._stroke_style(gc)
        if fill is None and stroke is None:
            return
        lw = float(self.points_to_pixels(gc.get_linewidth()))
        mp = marker_path.cleaned(marker_trans + Affine2D().scale(1, -1), remove_nans=True, curves=True, stroke_width=lw,
                                 snap=gc.get_snap())
        if len(mp.vertices) == 0:
            return
        codes = self._codes(mp)
        mv = mp.vertices
        if not _snaps(mp, gc.get_snap()):
            # As AGG: a marker that is not snapped has its origin at a pixel centre, so that
            # circles look centred on their point.
            mv = mv + 0.5
        pts = path.cleaned(trans + self._flip(), remove_nans=True, curves=True)
        verts = pts.vertices
        if pts.codes is not None:
            # Each segment's end point (control points excluded), as iter_segments gives them.
            pcodes = pts.codes
            stop = np.flatnonzero(pcodes == Path.STOP)
            if len(stop):
                pcodes, verts = pcodes[:stop[0]], verts[:stop[0]]
            if not ((pcodes == Path.CURVE3) | (pcodes == Path.CURVE4)).any():
                verts = verts[pcodes != Path.CLOSEPOLY]  # every other vertex ends its segment
            else:
                ends = []
                i, n = 0, len(pcodes)
                step = {Path.MOVETO: 1, Path.LINETO: 1, Path.CURVE3: 2, Path.CURVE4: 3}
                while i < n:
                    c = int(pcodes[i])
                    if c == Path.CLOSEPOLY:
                        i += 1
                        continue
                    k = step.get(c, 1)
                    ends.append(i + k - 1)
                    i += k
                verts = verts[ends] if ends else verts[:0]
        ext = _extents(mp)
        margin = (stroke["width"] * 4 if stroke is not None else 0) + 2
        W, H = self.width, self.height
        # AGG moves the positions by half a pixel and truncates: each marker goes to the nearest
        # whole pixel.
        offs = np.floor(verts + 0.5)
        vis = ((offs[:, 0] + ext.x1 + margin >= 0) & (offs[:, 0] + ext.x0 - margin <= W)
               & (offs[:, 1] + ext.y1 + margin >= 0) & (offs[:, 1] + ext.y0 - margin <= H))
        offs = offs[vis] - (t.x0, t.y0)
        core = t.core
        if len(offs) and t.clip_path is None:
            # Every marker sits at a whole-pixel offset of the same outline, so each covers its
            # pixels exactly as the first does: the marker is rasterized once (its stroke over its
            # fill over nothing, which over is associative with) and that picture is composited
            # at each place, as AGG blits its marker's scanlines. The picture is kept across
            # draws, so a single marker goes this way too: an axis's ticks are one draw_markers
            # call each, the same few pictures in every figure and every save.
            x0 = int(math.floor(ext.x0 - margin))
            y0 = int(math.floor(ext.y0 - margin))
            w = int(math.ceil(ext.x1 + margin)) - x0
            h = int(math.ceil(ext.y1 + margin)) - y0
            v = np.ascontiguousarray(mv - (x0, y0), dtype=np.float64)
            key = (w, h, v.tobytes(), codes.tobytes(), fill, None if stroke is None else tuple(map(repr, stroke.values())),
                   self.blend)
            im = _STAMPS.get(key)
            if im is None:
                stamp = _Target(Scene(w, h, background=(0.0, 0.0, 0.0, 0.0), blend=self.blend))
                self._emit(stamp, Path(v, mp.codes), fill, stroke)
                im = np.ascontiguousarray(stamp.core.render(1), dtype=np.float32)  # in the blend space's values
                im.flags.writeable = False
                if len(_STAMPS) >= 256:
                    _STAMPS.pop(next(iter(_STAMPS)))
                _STAMPS[key] = im
            self._stamps(t, im, offs + (x0, y0))
            return
        self._for_shapes(t)
        for ox, oy in offs:
            v = mv + (ox, oy)
            if fill is not None:
                core.fill_path(v, codes, "nonzero", fill)
            if stroke is not None:
                core.stroke_path(v, codes, stroke["color"], stroke["width"], stroke["join"], stroke["cap"], stroke["miter_limit"],
                                 stroke["dashes"], stroke["dash_offset"])
        t.items += len(offs)

    def _stamps(self, t: _Target, im: np.ndarray, origins: np.ndarray) -> None:
        """Picture im (float32, the blend space's values) composited at each whole-pixel origin
        (t's coordinates), cropped to t's box: the pictures inside it in one call, the few
        across its edge one by one."""
        enc = "srgb" if self.blend == "srgb" else "linear"
        h, w = im.shape[:2]
        bx0, by0, bx1, by1 = (t.box[0] - t.x0, t.box[1] - t.y0, t.box[2] - t.x0, t.box[3] - t.y0)
        ox, oy = origins[:, 0], origins[:, 1]
        inside = (ox >= bx0) & (oy >= by0) & (ox + w <= bx1) & (oy + h <= by1)
        self._for_rasters(t)
        if inside.any():  # one item: the copies composited in order, then onto the canvas
            t.core.stamps(im, np.ascontiguousarray(origins[inside], dtype=np.float64), enc)
        for x, y in origins[~inside]:
            x, y = int(x), int(y)
            cx0, cy0, cx1, cy1 = max(x, bx0), max(y, by0), min(x + w, bx1), min(y + h, by1)
            if cx1 > cx0 and cy1 > cy0:
                crop = np.ascontiguousarray(im[cy0 - y:cy1 - y, cx0 - x:cx1 - x])
                t.core.images(crop, np.array([[cx0, cy0]], dtype=np.float64), enc)
        t.items += len(origins)

    def draw_gouraud_triangles(self, gc, triangles_array, colors_array, transform):
        """Triangles with colours interpolated linearly (in the blend space's values, as AGG
        interpolates sRGB values) from their corners, sampled at pixel centres and weighted by
        each triangle's exact area coverage. The triangles of one call are summed before they
        are composited, so the seams of a mesh that tiles the plane are exact (no light lines)."""
        t = self._target(gc, raster=True)
        if t is None:
            return
        tri = np.asarray(triangles_array, dtype=np.float64).reshape(-1, 3, 2)
        cols = np.asarray(colors_array, dtype=np.float64).reshape(-1, 3, 4)
        if len(tri) == 0:
            return
        pts = (transform + self._flip()).transform(tri.reshape(-1, 2)).reshape(-1, 3, 2)
        ok = np.isfinite(pts).all(axis=(1, 2))
        pts, cols = pts[ok], cols[ok]
        if len(pts) == 0:
            return
        tx0, ty0 = t.x0, t.y0
        x0 = max(int(math.floor(pts[:, :, 0].min())), t.box[0])
        y0 = max(int(math.floor(pts[:, :, 1].min())), t.box[1])
        x1 = min(int(math.ceil(pts[:, :, 0].max())), t.box[2])
        y1 = min(int(math.ceil(pts[:, :, 1].max())), t.box[3])
        if x1 <= x0 or y1 <= y0:
            return
        acc = np.zeros((y1 - y0, x1 - x0, 4), np.float64)
        alpha = gc.get_alpha() if gc.get_forced_alpha() else 1.0
        srgb = self.blend == "srgb"
        for p, c in zip(pts, cols):
            bx0, by0 = max(int(math.floor(p[:, 0].min())), x0), max(int(math.floor(p[:, 1].min())), y0)
            bx1, by1 = min(int(math.ceil(p[:, 0].max())), x1), min(int(math.ceil(p[:, 1].max())), y1)
            if bx1 <= bx0 or by1 <= by0:
                continue
            (ax, ay), (bx, by), (cx, cy) = p
            det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
            if det == 0:
                continue
            cov = self._coverage(Path(np.vstack([p, p[:1]]), [1, 2, 2, 79]), bx0, by0, bx1 - bx0, by1 - by0)
            yy, xx = np.mgrid[by0:by1, bx0:bx1] + 0.5
            w1 = ((xx - ax) * (cy - ay) - (cx - ax) * (yy - ay)) / det
            w2 = ((bx - ax) * (yy - ay) - (xx - ax) * (by - ay)) / det
            w0 = 1 - w1 - w2
            rgba = w0[..., None] * c[0] + w1[..., None] * c[1] + w2[..., None] * c[2]
            rgba = np.clip(rgba, 0.0, 1.0)
            a = rgba[..., 3] * alpha
            rgb = rgba[..., :3]
            if not srgb:
                rgb = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
            k = (a * cov)[..., None]
            acc[by0 - y0:by1 - y0, bx0 - x0:bx1 - x0, :3] += rgb * k
            acc[by0 - y0:by1 - y0, bx0 - x0:bx1 - x0, 3] += k[..., 0]
        acc = np.ascontiguousarray(np.minimum(acc, 1.0), dtype=np.float32)
        self._for_rasters(t)
        t.core.images(acc, np.array([[x0 - tx0, y0 - ty0]], dtype=np.float64), "srgb" if srgb else "linear")
        t.items += 1

    def draw_image(self, gc, x, y, im, transform=None):
        if transform is not None:
            self._draw_image_kernel(gc, x, y, im, transform)
            return
        t = self._target(gc, raster=True)
        if t is None:
            return
        a = np.asarray(im)[::-1]  # matplotlib hands the rows bottom to top
        if a.ndim != 3 or a.shape[2] != 4 or a.size == 0:
            return
        h, w = a.shape[:2]
        alpha = gc.get_alpha()
        if alpha is not None and alpha < 1:
            a = a.copy()
            a[:, :, 3] = np.round(a[:, :, 3] * float(alpha)).astype(np.uint8)
        # Whole pixels, as AGG places images: x, y rounded half away from zero, then truncated.
        rx, ry = (math.floor(v + 0.5) if v >= 0 else math.ceil(v - 0.5) for v in (x, y))
        x0 = int(rx)
        y0 = int(self.height - (ry + h))
        # Cropped to the target's box (whole pixels, so the same picture as a clipped one).
        cx0, cy0, cx1, cy1 = max(x0, t.box[0]), max(y0, t.box[1]), min(x0 + w, t.box[2]), min(y0 + h, t.box[3])
        if cx1 <= cx0 or cy1 <= cy0:
            return
        a = a[cy0 - y0:cy1 - y0, cx0 - x0:cx1 - x0]
        self._for_rasters(t)
        if self.blend == "srgb":
            # The sRGB values as they are (associated alpha), composited without a round trip
            # through linear light.
            f = a.astype(np.float32) / np.float32(255)
            f[:, :, :3] *= f[:, :, 3:]
            t.core.images(f, np.array([[cx0 - t.x0, cy0 - t.y0]], dtype=np.float64), "srgb")
        else:
            t.core.image(np.ascontiguousarray(a, dtype=np.uint8), cx0 - t.x0, cy0 - t.y0, cx1 - t.x0, cy1 - t.y0, "nearest")
        t.items += 1

    # ---- images resampled with a splinefig kernel ------------------------------------------
    _DIRECT_LIMIT = 1 << 24  # device pixels of an image resampled whole before it is cropped
    _DIRECT_WORK = 1 << 24   # pixels times taps of the sums evaluated directly (about 2 s of CPU)

    def _resample_whole(self, dw: int, dh: int) -> bool:
        """Whether an axis-aligned image of dw x dh canvas pixels is resampled whole and then
        cropped (bounded by 2^24 pixels or four canvases), or only its visible pixels summed."""
        return dw <= 65536 and dh <= 65536 and dw * dh <= max(self._DIRECT_LIMIT, 4 * self.width * self.height)

    def _draw_image_kernel(self, gc, x, y, im, transform) -> None:
        """An image drawn with interpolation="none" while a kernel is chosen: im holds its source
        pixels (matplotlib's colours, uint8 sRGB with straight alpha, row 0 at v = 0 of the unit
        square), transform maps the unit square to canvas pixels (y up) from (x, y).

        Axis-aligned (scaled, translated, flipped): the image's rectangle is rounded to whole
        pixels (its left and bottom edges as AGG rounds an image's place, its width and height
        to the nearest whole number) and the source resampled to exactly that size by
        splinefig.resample, in linear light as `splinefig resample` does, then cropped to the
        clip rectangle. Rotated or skewed: each canvas pixel is the same kernel sum evaluated at
        the source position its centre maps to, times the area of the pixel the image covers."""
        t = self._target(gc, raster=True)
        if t is None:
            return
        a = np.asarray(im)
        if a.ndim != 3 or a.shape[2] != 4 or a.size == 0:
            return
        if a.dtype != np.uint8:
            a = np.round(np.clip(np.asarray(a, dtype=np.float64), 0.0, 1.0) * 255).astype(np.uint8)
        ik = self.image_kernel
        h, w = a.shape[:2]
        H = self.height
        m = transform.frozen().get_matrix()
        # Source pixel coordinates (i, j) (pixel (i, j) covers [i, i+1] x [j, j+1]) to canvas
        # pixels, y down: P = A (i, j) + p0.
        A = np.array([[m[0, 0] / w, m[0, 1] / h], [-m[1, 0] / w, -m[1, 1] / h]], dtype=np.float64)
        p0 = np.array([x + m[0, 2], H - (y + m[1, 2])], dtype=np.float64)
        if not (np.isfinite(A).all() and np.isfinite(p0).all()):
            return
        det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]
        if det == 0:
            return
        big = float(np.abs(A).max())
        alpha = gc.get_alpha()
        alpha = 1.0 if alpha is None else float(alpha)
        if abs(A[0, 1]) <= 1e-9 * big and abs(A[1, 0]) <= 1e-9 * big:
            src = a[:, ::-1] if A[0, 0] < 0 else a   # the source as it shows: left to right,
            src = src[::-1] if A[1, 1] < 0 else src  # top to bottom
            left, right = sorted((p0[0], p0[0] + A[0, 0] * w))
            top, bottom = sorted((p0[1], p0[1] + A[1, 1] * h))
            dw = max(1, _round_half_away(right - left))
            dh = max(1, _round_half_away(bottom - top))
            x0 = _round_half_away(left)
            y0 = H - _round_half_away(H - bottom) - dh
            cx0, cy0 = max(x0, t.box[0]), max(y0, t.box[1])
            cx1, cy1 = min(x0 + dw, t.box[2]), min(y0 + dh, t.box[3])
            if cx1 <= cx0 or cy1 <= cy0:
                return
            if self._resample_whole(dw, dh):
                out = resample(np.ascontiguousarray(src), size=(dw, dh), filter=ik.k, edge=ik.edge,
                               interpolating=ik.interpolating, threads=self.threads)
                out = out[cy0 - y0:cy1 - y0, cx0 - x0:cx1 - x0]
            else:
                # Much larger than the canvas (an image zoomed far in): the same sums, for the
                # visible pixels only. Output pixel X's centre maps to the source position
                # (X - x0 + 1/2) S / D, as in the resampler.
                inv = np.array([[w / dw, 0.0, -x0 * w / dw], [0.0, h / dh, -y0 * h / dh]])
                out = _kernel_sums(_srgb_ints_to_linear(np.ascontiguousarray(src)), inv, (max(1.0, w / dw), max(1.0, h / dh)),
                                   (cx0, cy0, cx1, cy1), ik)
        else:
            corners = p0 + np.array([[0, 0], [w, 0], [0, h], [w, h]], dtype=np.float64) @ A.T
            cx0 = max(int(math.floor(corners[:, 0].min())), t.box[0])
            cy0 = max(int(math.floor(corners[:, 1].min())), t.box[1])
            cx1 = min(int(math.ceil(corners[:, 0].max())), t.box[2])
            cy1 = min(int(math.ceil(corners[:, 1].max())), t.box[3])
            if cx1 <= cx0 or cy1 <= cy0:
                return
            Ai = np.array([[A[1, 1], -A[0, 1]], [-A[1, 0], A[0, 0]]]) / det
            inv = np.column_stack([Ai, -Ai @ p0])
            # Widened along each source axis by how much it is reduced, as the resampler widens;
            # an asymmetric kernel oriented along each axis as its picture on the canvas runs
            # (right or down by its larger component), as a flipped image's is.
            f = (max(1.0, 1.0 / math.hypot(A[0, 0], A[1, 0])), max(1.0, 1.0 / math.hypot(A[0, 1], A[1, 1])))
            sign = tuple(1.0 if (A[0, k] if abs(A[0, k]) >= abs(A[1, k]) else A[1, k]) > 0 else -1.0 for k in (0, 1))
            box = (cx0, cy0, cx1, cy1)
            if (cx1 - cx0) * (cy1 - cy0) * _taps(ik, f[0]) * _taps(ik, f[1]) <= self._DIRECT_WORK:
                out = _kernel_sums(_srgb_ints_to_linear(a), inv, f, box, ik, sign=sign)
            else:
                # Reduced far (a large image turned onto few pixels): the source is first reduced
                # along its own axes by the resampler to about one pixel per canvas pixel (sides
                # ceil(w / fx) and ceil(h / fy), the kernel oriented as below), and the sums are
                # taken on that picture, so that work and memory stay bounded by the canvas.
                nw, nh = max(1, math.ceil(w / f[0])), max(1, math.ceil(h / f[1]))
                turned = a[:, ::-1] if sign[0] < 0 else a
                turned = turned[::-1] if sign[1] < 0 else turned
                small = resample(np.ascontiguousarray(turned), size=(nw, nh), filter=ik.k, edge=ik.edge,
                                 interpolating=ik.interpolating, threads=self.threads)
                small = small[:, ::-1] if sign[0] < 0 else small
                small = small[::-1] if sign[1] < 0 else small
                inv = np.diag([nw / w, nh / h]) @ inv
                f = (max(1.0, f[0] * nw / w), max(1.0, f[1] * nh / h))
                out = _kernel_sums(np.ascontiguousarray(small), inv, f, box, ik, sign=sign)
            # The image's parallelogram covers each pixel by its exact area: its edges are
            # antialiased as a filled path's (a pixel's value is the sum at its centre, read
            # by the edge mode where the centre is outside, times that area).
            quad = Path(corners[[0, 1, 3, 2, 0]], [Path.MOVETO, Path.LINETO, Path.LINETO, Path.LINETO, Path.CLOSEPOLY])
            out *= self._coverage(quad, cx0, cy0, cx1 - cx0, cy1 - cy0)[:, :, None]
        out = np.array(out, dtype=np.float32)
        if alpha < 1:
            out *= np.float32(alpha)
        # Within what a pixel can hold: alpha in [0, 1], colour in [0, alpha] (a kernel with
        # negative lobes overshoots; the resampler's PNG output is clamped the same way).
        np.clip(out[:, :, 3], 0.0, 1.0, out=out[:, :, 3])
        out[:, :, :3] = np.clip(out[:, :, :3], 0.0, out[:, :, 3:])
        self._for_rasters(t)
        t.core.images(np.ascontiguousarray(out), np.array([[cx0 - t.x0, cy0 - t.y0]], dtype=np.float64), "linear")
        t.items += 1

    def get_text_width_height_descent(self, s, prop, ismath):
        """RendererBase's metrics (TextToPath's unhinted font, mathtext's path parser) at the
        default hinting factor, so the layout does not change with text.hinting_factor; kept
        with the outlines (matplotlib keeps them per renderer, and a canvas makes one per draw)."""
        def make():
            with _unhinted():
                return super(RendererSplinefig, self).get_text_width_height_descent(s, prop, ismath)
        if ismath == "TeX":
            return make()
        return self._text2path.kept(("size", self.dpi) + _CachedTextToPath.key(prop, s, ismath), make)

    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        """The glyph outlines of matplotlib's TextToPath (unhinted), filled; never snapped."""
        t = self._target(gc)
        if t is None:
            return
        with _unhinted():
            path, transform = self._get_text_path_transform(x, y, s, prop, angle, ismath)
        fill = self._fill_color(gc, gc.get_rgb())
        if fill is None or len(path.vertices) == 0:
            return
        p = path.cleaned(transform + self._flip(), remove_nans=True, curves=True, snap=False)
        self._emit(t, p, fill, None)

    def draw_tex(self, gc, x, y, s, prop, angle, *, mtext=None):
        # TeX's glyph outlines, as RendererBase lays them out (needs a TeX installation).
        self.draw_text(gc, x, y, s, prop, angle, ismath="TeX", mtext=mtext)

    def clear(self) -> None:
        self.scene = Scene(max(self.width, 1), max(self.height, 1), background=(1.0, 1.0, 1.0, 0.0), blend=self.blend)
        self._main = _Target(self.scene, main=True)
        self._boxed = {}
        self._main_clip = None
        self._layer = None

    def rgba8(self) -> np.ndarray:
        """The picture: (h, w, 4) uint8, sRGB, straight alpha, as AGG's buffer holds it."""
        self.finish()
        return self.scene.render_rgba8(threads=self.threads)


#: zlib's level for the PNG files print_png writes itself (1: fastest; 9: smallest).
PNG_LEVEL = 1
_IDAT_MAX = 1 << 30  # bytes of compressed data in one IDAT chunk


def _png(rgba: np.ndarray, dpi: float, metadata: Optional[dict], level: int = PNG_LEVEL) -> bytes:
    """A PNG file of an (h, w, 4) uint8 RGBA picture, with the chunks matplotlib's PIL writer
    gives it (tEXt or iTXt for the metadata, "Software" by default; pHYs for the dpi), made here:
    every row with the Up filter (its difference from the row above, which a plot's flat areas
    and vertical edges make mostly zeros) and one zlib stream at `level`. Pillow tries its five
    filters on every row and compresses at level 6, several times slower for a file 10-20%
    smaller."""
    import struct
    import zlib

    from PIL.PngImagePlugin import PngInfo

    h, w = rgba.shape[:2]
    info = PngInfo()  # the text chunks exactly as matplotlib makes them for PIL
    meta = {"Software": f"Matplotlib version{mpl.__version__}, https://matplotlib.org/", **(metadata or {})}
    for k, v in meta.items():
        if v is not None:
            info.add_text(k, v)
    rows = np.ascontiguousarray(rgba, dtype=np.uint8).reshape(h, w * 4)
    filtered = np.empty((h, w * 4 + 1), np.uint8)
    filtered[:, 0] = 2  # Up
    filtered[:1, 1:] = rows[:1]
    np.subtract(rows[1:], rows[:-1], out=filtered[1:, 1:])  # modulo 256, as the filter is defined

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    ppm = int(dpi / 0.0254 + 0.5)  # pixels per metre, rounded as Pillow rounds them
    parts = [b"\x89PNG\r\n\x1a\n", chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))]
    parts += [chunk(c[0], c[1]) for c in info.chunks]
    parts.append(chunk(b"pHYs", struct.pack(">IIB", ppm, ppm, 1)))
    data = zlib.compress(filtered.tobytes(), level)
    # A chunk's length is 31 bits: a larger stream goes into consecutive IDAT chunks.
    parts += [chunk(b"IDAT", data[i:i + _IDAT_MAX]) for i in range(0, len(data), _IDAT_MAX)]
    parts.append(chunk(b"IEND", b""))
    return b"".join(parts)


class FigureCanvasSplinefig(FigureCanvasBase):
    """A canvas whose PNG, raw and RGBA output is rasterized by splinefig."""

    filetypes = {"png": "Portable Network Graphics", "raw": "Raw RGBA bitmap", "rgba": "Raw RGBA bitmap"}
    fixed_dpi = None

    def __init__(self, figure=None) -> None:
        super().__init__(figure)
        self._buffer: Optional[np.ndarray] = None
        self.renderer: Optional[RendererSplinefig] = None

    def get_default_filetype(self):
        return "png"

    def get_renderer(self, *, blend: Optional[str] = None, threads: Optional[int] = None,
                     kernel: Union[None, bool, str, Kernel, Basis] = None, kernel_edge: Optional[str] = None,
                     kernel_interpolating: Optional[bool] = None) -> RendererSplinefig:
        w, h = self.figure.bbox.size
        self.renderer = RendererSplinefig(w, h, self.figure.dpi, blend=blend, threads=threads, kernel=kernel,
                                          kernel_edge=kernel_edge, kernel_interpolating=kernel_interpolating)
        return self.renderer

    def draw(self, *, blend: Optional[str] = None, threads: Optional[int] = None,
             kernel: Union[None, bool, str, Kernel, Basis] = None, kernel_edge: Optional[str] = None,
             kernel_interpolating: Optional[bool] = None) -> None:
        r = self.get_renderer(blend=blend, threads=threads, kernel=kernel, kernel_edge=kernel_edge,
                              kernel_interpolating=kernel_interpolating)
        self.figure.draw(r)
        self._buffer = r.rgba8()
        super().draw()

    def buffer_rgba(self):
        """The last drawing as a memoryview of (h, w, 4) uint8 RGBA (straight alpha)."""
        if self._buffer is None:
            self.draw()
        return memoryview(self._buffer)

    def print_raw(self, filename_or_obj, *, blend: Optional[str] = None, threads: Optional[int] = None,
                  kernel: Union[None, bool, str, Kernel, Basis] = None, kernel_edge: Optional[str] = None,
                  kernel_interpolating: Optional[bool] = None, **kwargs):
        self.draw(blend=blend, threads=threads, kernel=kernel, kernel_edge=kernel_edge,
                  kernel_interpolating=kernel_interpolating)
        with cbook.open_file_cm(filename_or_obj, "wb") as fh:
            fh.write(self._buffer.tobytes())

    print_rgba = print_raw

    def print_png(self, filename_or_obj, *, metadata=None, pil_kwargs=None, blend: Optional[str] = None,
                  threads: Optional[int] = None, kernel: Union[None, bool, str, Kernel, Basis] = None,
                  kernel_edge: Optional[str] = None, kernel_interpolating: Optional[bool] = None, **kwargs):
        """Writes the figure as a PNG with matplotlib's metadata and dpi chunks, compressed at
        zlib level PNG_LEVEL with the Up row filter (_png); with pil_kwargs, through matplotlib's
        PIL writer, as AGG's canvas writes it. blend: "srgb" or "linear" (default BLEND); threads:
        rasterizer threads; kernel, kernel_edge, kernel_interpolating: the resampling of
        interpolation="none" images (default KERNEL, KERNEL_EDGE, KERNEL_INTERPOLATING; False:
        matplotlib's own)."""
        self.draw(blend=blend, threads=threads, kernel=kernel, kernel_edge=kernel_edge,
                  kernel_interpolating=kernel_interpolating)
        if pil_kwargs is not None:
            mpl.image.imsave(filename_or_obj, self._buffer, format="png", origin="upper", dpi=self.figure.dpi,
                             metadata=metadata, pil_kwargs=pil_kwargs)
            return
        data = _png(self._buffer, self.figure.dpi, metadata)  # whole before the file is opened
        with cbook.open_file_cm(filename_or_obj, "wb") as fh:
            fh.write(data)


FigureCanvas = FigureCanvasSplinefig
FigureManager = FigureManagerBase


@_Backend.export
class _BackendSplinefig(_Backend):
    FigureCanvas = FigureCanvasSplinefig
    FigureManager = FigureManagerBase
