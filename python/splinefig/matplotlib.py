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
environment variable SPLINEFIG_MPL_BLEND) blends in linear light instead. See docs/matplotlib.md.
"""
from __future__ import annotations

import functools
import math
import os
from typing import Any, Optional

import numpy as np

import matplotlib as mpl
from matplotlib import cbook
from matplotlib.backend_bases import (FigureCanvasBase, FigureManagerBase, RendererBase, _Backend)
from matplotlib.path import Path
from matplotlib.transforms import Affine2D

from . import Scene, _core

__all__ = ["FigureCanvasSplinefig", "RendererSplinefig", "FigureCanvas", "FigureManager", "BLEND", "THREADS"]

#: The default blend space: "srgb" (as AGG) or "linear"; SPLINEFIG_MPL_BLEND overrides it.
BLEND = "srgb"
#: Rasterizer threads (0: all cores). The bytes do not depend on it.
THREADS = 0

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


_HINTING_FACTOR = 8  # matplotlib's default text.hinting_factor


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
    """Where items go: the figure's scene, or a clip layer (a scene over an integer rectangle of
    the canvas, composited into the figure's scene when it is closed)."""

    def __init__(self, scene: Scene, x0: int = 0, y0: int = 0, key: Any = None, clip_path: Any = None,
                 masked: bool = False) -> None:
        self.scene, self.core, self.x0, self.y0, self.key, self.clip_path = scene, scene._s, x0, y0, key, clip_path
        self.masked = masked  # clip_path is applied as a coverage mask when the layer is closed
        self.items = 0


class RendererSplinefig(RendererBase):
    """Draws a figure into one splinefig Scene (pixels, y down, as AGG's buffer)."""

    def __init__(self, width: float, height: float, dpi: float, *, blend: Optional[str] = None, threads: Optional[int] = None) -> None:
        super().__init__()
        self.dpi = dpi
        self.width = int(math.ceil(width))
        self.height = int(math.ceil(height))
        self.blend = _blend_of(blend)
        self.threads = THREADS if threads is None else int(threads)
        self.scene = Scene(max(self.width, 1), max(self.height, 1), background=(1.0, 1.0, 1.0, 0.0), blend=self.blend)
        self._main = _Target(self.scene)
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
        return False  # images arrive resampled to the canvas's pixels

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
        """The target for gc's clip, or None when nothing can show. Paths and text are clipped
        by a clip path exactly (the layer's scene intersects them with it); rasters (images,
        Gouraud meshes), which the renderer does not clip, go to a layer multiplied by the clip
        path's exact coverage."""
        box = self._clip_box(gc)
        cp, cp_trans = gc.get_clip_path()
        clip_path = None
        if cp is not None:
            flip = Affine2D().scale(1, -1).translate(0, self.height)
            clip_path = cp.cleaned(cp_trans + flip, remove_nans=True, curves=True)
        if box is None and clip_path is None:
            self._close_layer()
            return self._main
        if box is None:
            box = (0, 0, self.width, self.height)
        if box[2] <= box[0] or box[3] <= box[1]:
            return None
        if clip_path is None and box == (0, 0, self.width, self.height):
            self._close_layer()
            return self._main
        masked = raster and clip_path is not None
        key = (box, None if clip_path is None else (clip_path.vertices.tobytes(), clip_path.codes.tobytes()), masked)
        if self._layer is not None and self._layer.key == key:
            return self._layer
        self._close_layer()
        w, h = box[2] - box[0], box[3] - box[1]
        self._layer = _Target(Scene(w, h, background=(0.0, 0.0, 0.0, 0.0), blend=self.blend), box[0], box[1], key, clip_path,
                              masked)
        if clip_path is not None and not masked:
            v = np.ascontiguousarray(clip_path.vertices - (box[0], box[1]), dtype=np.float64)
            self._layer.core.set_clip(v, self._codes(clip_path), "nonzero")
        return self._layer

    def _composite(self, into: _Target, t: _Target, mask: Optional[np.ndarray] = None) -> None:
        """Draws target t's picture (times mask, a per-pixel coverage) into `into` at t's place."""
        im = t.core.render(self.threads)
        if mask is not None:
            im = im * mask[:, :, None]
        if self.blend == "srgb":
            im = _core.srgb_to_linear_rgba(np.ascontiguousarray(im, dtype=np.float32))
        h, w = im.shape[:2]
        x0, y0 = t.x0 - into.x0, t.y0 - into.y0
        into.core.image(np.ascontiguousarray(im, dtype=np.float32), x0, y0, x0 + w, y0 + h, "nearest")
        into.items += 1

    def _coverage(self, path: Path, x0: int, y0: int, w: int, h: int, rule: str = "nonzero") -> np.ndarray:
        """The exact area coverage of a filled path (canvas pixels) over a w x h rectangle at (x0, y0)."""
        s = Scene(w, h, background=(0.0, 0.0, 0.0, 0.0))
        v = np.ascontiguousarray(path.vertices - (x0, y0), dtype=np.float64)
        s._s.fill_path(v, self._codes(path), rule, (1.0, 1.0, 1.0, 1.0))
        return s._s.render(self.threads)[:, :, 3]

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
        return Affine2D().scale(1, -1).translate(0, self.height)

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
        trans = transform + self._flip()
        lw = float(self.points_to_pixels(gc.get_linewidth()))  # AGG snaps by gc's width, drawn or not
        hatch = gc.get_hatch_path() is not None
        clip = None
        if fill is None and not hatch and stroke is not None and not stroke["dashes"]:
            m = 4 * lw + 16
            clip = (-m, -m, self.width + m, self.height + m)
        simplify = path.should_simplify and fill is None and not hatch
        return path.cleaned(trans, remove_nans=True, clip=clip, simplify=simplify, curves=True,
                            stroke_width=lw, snap=gc.get_snap() if snap is None else snap, sketch=gc.get_sketch_params())

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
        x0 = max(int(math.floor(ext.x0)), t.x0)
        y0 = max(int(math.floor(ext.y0)), t.y0)
        x1 = min(int(math.ceil(ext.x1)), t.x0 + t.scene.width)
        y1 = min(int(math.ceil(ext.y1)), t.y0 + t.scene.height)
        if x1 <= x0 or y1 <= y0:
            return
        size = int(self.points_to_pixels(_HATCH_SIZE))
        if size < 1:
            return
        lw = self.points_to_pixels(mpl.rcParams["hatch.linewidth"])
        color = _linear(gc.get_hatch_color())
        layer = _Target(Scene(x1 - x0, y1 - y0, background=(0.0, 0.0, 0.0, 0.0), blend=self.blend), x0, y0)
        tile = hatch.transformed(Affine2D().scale(size, size).scale(1, -1).translate(0, size))
        codes = self._codes(tile)
        for ty in range(y0 // size, (y1 - 1) // size + 1):
            for tx in range(x0 // size, (x1 - 1) // size + 1):
                v = np.ascontiguousarray(tile.vertices + (tx * size - x0, ty * size - y0), dtype=np.float64)
                layer.core.fill_path(v, codes, "nonzero", color)
                if lw > 0:
                    layer.core.stroke_path(v, codes, color, float(lw), "miter", "butt", 4.0, [], 0.0)
        mask = self._coverage(p, x0, y0, x1 - x0, y1 - y0)
        self._composite(t, layer, mask)

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
            if not np.isin(pcodes, (Path.CURVE3, Path.CURVE4)).any():
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
        ext = mp.get_extents()
        margin = (stroke["width"] * 4 if stroke is not None else 0) + 2
        W, H = self.width, self.height
        # AGG moves the positions by half a pixel and truncates: each marker goes to the nearest
        # whole pixel.
        offs = np.floor(verts + 0.5)
        vis = ((offs[:, 0] + ext.x1 + margin >= 0) & (offs[:, 0] + ext.x0 - margin <= W)
               & (offs[:, 1] + ext.y1 + margin >= 0) & (offs[:, 1] + ext.y0 - margin <= H))
        offs = offs[vis] - (t.x0, t.y0)
        core = t.core
        if len(offs) > 1 and t.clip_path is None:
            # Every marker sits at a whole-pixel offset of the same outline, so each covers its
            # pixels exactly as the first does: the marker is rasterized once (its stroke over its
            # fill over nothing, which over is associative with) and that picture is composited
            # at each place, as AGG blits its marker's scanlines.
            x0 = int(math.floor(ext.x0 - margin))
            y0 = int(math.floor(ext.y0 - margin))
            w = int(math.ceil(ext.x1 + margin)) - x0
            h = int(math.ceil(ext.y1 + margin)) - y0
            stamp = _Target(Scene(w, h, background=(0.0, 0.0, 0.0, 0.0), blend=self.blend))
            self._emit(stamp, Path(mv - (x0, y0), mp.codes), fill, stroke)
            im = stamp.core.render(1)  # in the blend space's values, which the canvas takes as they are
            core.images(np.ascontiguousarray(im, dtype=np.float32), np.ascontiguousarray(offs + (x0, y0), dtype=np.float64),
                        "srgb" if self.blend == "srgb" else "linear")
            t.items += len(offs)
            return
        for ox, oy in offs:
            v = mv + (ox, oy)
            if fill is not None:
                core.fill_path(v, codes, "nonzero", fill)
            if stroke is not None:
                core.stroke_path(v, codes, stroke["color"], stroke["width"], stroke["join"], stroke["cap"], stroke["miter_limit"],
                                 stroke["dashes"], stroke["dash_offset"])
        t.items += len(offs)

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
        tw, th = t.scene.width, t.scene.height
        x0 = max(int(math.floor(pts[:, :, 0].min())), tx0)
        y0 = max(int(math.floor(pts[:, :, 1].min())), ty0)
        x1 = min(int(math.ceil(pts[:, :, 0].max())), tx0 + tw)
        y1 = min(int(math.ceil(pts[:, :, 1].max())), ty0 + th)
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
        acc = np.minimum(acc, 1.0).astype(np.float32)
        if srgb:
            acc = _core.srgb_to_linear_rgba(np.ascontiguousarray(acc))
        t.core.image(np.ascontiguousarray(acc, dtype=np.float32), x0 - tx0, y0 - ty0, x1 - tx0, y1 - ty0, "nearest")
        t.items += 1

    def draw_image(self, gc, x, y, im, transform=None):
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
        x0 = int(rx) - t.x0
        y0 = int(self.height - (ry + h)) - t.y0
        t.core.image(np.ascontiguousarray(a, dtype=np.uint8), x0, y0, x0 + w, y0 + h, "nearest")
        t.items += 1

    def get_text_width_height_descent(self, s, prop, ismath):
        """RendererBase's metrics (TextToPath's unhinted font, mathtext's path parser) at the
        default hinting factor, so the layout does not change with text.hinting_factor."""
        with _unhinted():
            return super().get_text_width_height_descent(s, prop, ismath)

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
        self._main = _Target(self.scene)
        self._layer = None

    def rgba8(self) -> np.ndarray:
        """The picture: (h, w, 4) uint8, sRGB, straight alpha, as AGG's buffer holds it."""
        self.finish()
        return self.scene.render_rgba8(threads=self.threads)


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

    def get_renderer(self, *, blend: Optional[str] = None, threads: Optional[int] = None) -> RendererSplinefig:
        w, h = self.figure.bbox.size
        self.renderer = RendererSplinefig(w, h, self.figure.dpi, blend=blend, threads=threads)
        return self.renderer

    def draw(self, *, blend: Optional[str] = None, threads: Optional[int] = None) -> None:
        r = self.get_renderer(blend=blend, threads=threads)
        self.figure.draw(r)
        self._buffer = r.rgba8()
        super().draw()

    def buffer_rgba(self):
        """The last drawing as a memoryview of (h, w, 4) uint8 RGBA (straight alpha)."""
        if self._buffer is None:
            self.draw()
        return memoryview(self._buffer)

    def print_raw(self, filename_or_obj, *, blend: Optional[str] = None, threads: Optional[int] = None, **kwargs):
        self.draw(blend=blend, threads=threads)
        with cbook.open_file_cm(filename_or_obj, "wb") as fh:
            fh.write(self._buffer.tobytes())

    print_rgba = print_raw

    def print_png(self, filename_or_obj, *, metadata=None, pil_kwargs=None, blend: Optional[str] = None,
                  threads: Optional[int] = None, **kwargs):
        """Writes the figure as a PNG (through matplotlib's PIL writer, as AGG's canvas does);
        blend: "srgb" or "linear" (default BLEND); threads: rasterizer threads."""
        self.draw(blend=blend, threads=threads)
        mpl.image.imsave(filename_or_obj, self._buffer, format="png", origin="upper", dpi=self.figure.dpi,
                         metadata=metadata, pil_kwargs=pil_kwargs)


FigureCanvas = FigureCanvasSplinefig
FigureManager = FigureManagerBase


@_Backend.export
class _BackendSplinefig(_Backend):
    FigureCanvas = FigureCanvasSplinefig
    FigureManager = FigureManagerBase
