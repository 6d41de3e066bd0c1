"""Two typical figures drawn by matplotlib's AGG and by splinefig's backend at the same dpi, side
by side, with an enlarged crop of the region where they differ most, and the exact coverage of
pixels there by an independent oracle (python/tests/polygon_area.py: Sutherland-Hodgman clipping
and the shoelace area) to say which of the two is right.

    PYTHONPATH=build/python:python/tests /usr/bin/python3 python/bench/matplotlib_images.py [OUT_DIR]

writes OUT_DIR/matplotlib-lines.png and OUT_DIR/matplotlib-text.png (OUT_DIR: docs/images) and
prints, for the pixels it marks, the oracle's value against AGG's and splinefig's.

The oracle: every path the backend hands to the scene is recorded in canvas pixels. A fill's
contours (curves cut into 64 chords each, well under 1e-3 of a pixel's area off) are clipped to
the pixel and their areas summed with their orientation's sign; a stroke (round joins, as
matplotlib's lines) is the union of its segments' rectangles, its joins' discs (256-gons) and its
caps, whose area in the pixel is found by inclusion-exclusion over the pieces' intersections
(each convex, so clipping one by another is exact). The pixel's value is then the items
composited in order over white, in sRGB values as AGG and the backend blend.
"""
import io
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.path import Path  # noqa: E402
from PIL import Image, ImageDraw, ImageFont  # noqa: E402

import splinefig.matplotlib as backend  # noqa: E402
from polygon_area import area, clip_convex  # noqa: E402

BACKEND = "module://splinefig.matplotlib"
ZOOM = 8


def lines():
    """Translucent bands (fill_between), a noisy translucent line that crosses itself many times
    per pixel column, and a smooth thick line."""
    fig, ax = plt.subplots(figsize=(4, 3), dpi=100)
    fig.subplots_adjust(left=0.12, right=0.97, bottom=0.1, top=0.95)
    x = np.linspace(0, 10, 400)
    ax.fill_between(x, np.cos(x) - 0.3, np.cos(x) + 0.3, color="C2", alpha=0.3)
    xn = np.linspace(0, 10, 1500)
    ax.plot(xn, np.sin(xn) + 0.15 * np.random.default_rng(0).normal(size=xn.size), lw=1.5, alpha=0.6)
    ax.plot(x, 0.5 * np.sin(2 * x), lw=3, color="k", alpha=0.8)
    return fig, ax


def text():
    """Text, mathtext and hatched bars."""
    fig, ax = plt.subplots(figsize=(4, 3), dpi=100)
    fig.subplots_adjust(left=0.16, right=0.97, bottom=0.15, top=0.8)
    ax.bar([1, 2, 3], [0.5, 0.9, 0.3], hatch="//", fill=False)
    ax.set_title(r"Energy $E = \sum_{i=0}^{n} \frac{x_i^2}{2}$")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(r"$\sqrt{\beta}$ (m)")
    ax.text(0.6, 0.7, r"$\int_0^\infty e^{-x^2}\,dx$", fontsize=14)
    return fig, ax


def render(fig, back):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", backend=back)
    buf.seek(0)
    return np.asarray(Image.open(buf).convert("RGB")).astype(np.int32)


def recorded(fig):
    """The splinefig picture and what the backend put into the figure's scene, in drawing order:
    ("fill", vertices in canvas pixels, codes, colour), ("stroke", vertices, codes, colour, width,
    join, cap, dashes), or ("raster", x0, y0, x1, y1) for pictures (markers, hatches, images),
    which the oracle does not model."""
    from splinefig import _core

    items = []
    W, H = (int(math.ceil(v)) for v in fig.bbox.size)
    originals = {k: getattr(_core.Scene, k) for k in ("fill_path", "stroke_path", "images", "path_items")}

    def mine(scene):
        return (scene.width, scene.height) == (W, H)

    def fill_path(self, v, codes, rule, color):
        if mine(self):
            items.append(("fill", np.array(v, dtype=np.float64), np.array(codes), color))
        return originals["fill_path"](self, v, codes, rule, color)

    def stroke_path(self, v, codes, color, width, join, cap, miter, dashes, offset):
        if mine(self):
            items.append(("stroke", np.array(v, dtype=np.float64), np.array(codes), color, width, join, cap, list(dashes)))
        return originals["stroke_path"](self, v, codes, color, width, join, cap, miter, dashes, offset)

    def images(self, rgba, origins, encoding="linear"):
        if mine(self):
            h, w = np.asarray(rgba).shape[:2]
            items.extend(("raster", x, y, x + w, y + h) for x, y in np.asarray(origins))
        return originals["images"](self, rgba, origins, encoding)

    def path_items(self, v, codes, offsets, fills, strokes, widths, rule, join, cap, miter, dashes, offset, ox, oy):
        if mine(self):
            for o, f, k, w in zip(np.asarray(offsets), np.asarray(fills), np.asarray(strokes), np.asarray(widths)):
                pv = (np.asarray(v) + o) - (ox, oy)
                if f[3] >= 0:
                    items.append(("fill", pv, np.array(codes), tuple(f)))
                if w > 0 and k[3] >= 0:
                    items.append(("stroke", pv, np.array(codes), tuple(k), w, join, cap, list(dashes)))
        return originals["path_items"](self, v, codes, offsets, fills, strokes, widths, rule, join, cap, miter, dashes,
                                       offset, ox, oy)

    for k, f in (("fill_path", fill_path), ("stroke_path", stroke_path), ("images", images), ("path_items", path_items)):
        setattr(_core.Scene, k, f)
    try:
        ours = render(fig, BACKEND)
    finally:
        for k, f in originals.items():
            setattr(_core.Scene, k, f)
    return ours, items


def contours(v, codes, chords=64):
    """A path's closed contours as polygons, Bezier curves cut into `chords` chords."""
    if codes is None:
        codes = np.full(len(v), Path.LINETO)
        codes[0] = Path.MOVETO
    out, cur, i = [], [], 0
    t = (np.arange(1, chords + 1) / chords)[:, None]
    while i < len(v):
        c = codes[i]
        if c == Path.MOVETO:
            if len(cur) > 2:
                out.append(cur)
            cur, i = [tuple(v[i])], i + 1
        elif c == Path.LINETO:
            cur.append(tuple(v[i]))
            i += 1
        elif c == Path.CURVE3:
            p0, p1, p2 = np.array(cur[-1]), v[i], v[i + 1]
            cur += [tuple(p) for p in (1 - t) ** 2 * p0 + 2 * (1 - t) * t * p1 + t ** 2 * p2]
            i += 2
        elif c == Path.CURVE4:
            p0, p1, p2, p3 = np.array(cur[-1]), v[i], v[i + 1], v[i + 2]
            cur += [tuple(p) for p in (1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * p1 + 3 * (1 - t) * t ** 2 * p2 + t ** 3 * p3]
            i += 3
        elif c == Path.CLOSEPOLY:
            if len(cur) > 2:
                out.append(cur)
            cur, i = [], i + 1
        else:  # STOP
            break
    if len(cur) > 2:
        out.append(cur)
    return out


def signed(poly):
    return 0.5 * sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(poly, poly[1:] + poly[:1]))


def pixel(col, row):
    return [(col, row), (col + 1, row), (col + 1, row + 1), (col, row + 1)]  # counter-clockwise for clip_convex


def fill_coverage(v, codes, col, row):
    """Nonzero coverage of pixel (col, row) by a path whose contours do not overlap (glyphs, bands):
    each contour's area in the pixel with the sign of its orientation."""
    px = pixel(col, row)
    total = 0.0
    for c in contours(v, codes):
        xs, ys = [p[0] for p in c], [p[1] for p in c]
        if max(xs) <= col or min(xs) >= col + 1 or max(ys) <= row or min(ys) >= row + 1:
            continue
        inside = clip_convex(c, px)
        if inside:
            total += math.copysign(area(inside), signed(c))
    return abs(total)


def ccw(poly):
    return poly if signed(poly) > 0 else poly[::-1]


def stroke_pieces(v, width, cap, col, row):
    """The convex pieces of a round-joined polyline's stroke that reach pixel (col, row), clipped
    to it: segment rectangles, join discs and the caps."""
    r = width / 2
    px = pixel(col, row)
    disc = [(r * math.cos(2 * math.pi * k / 256), r * math.sin(2 * math.pi * k / 256)) for k in range(256)]
    pieces = []

    def near(pts):
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return max(xs) > col and min(xs) < col + 1 and max(ys) > row and min(ys) < row + 1

    def add(poly):
        if near(poly):
            got = clip_convex(ccw(poly), px)
            if got and area(got) > 0:
                pieces.append(got)

    n = len(v)
    for i in range(n - 1):
        a, b = v[i], v[i + 1]
        d = b - a
        L = math.hypot(*d)
        if L == 0:
            continue
        u = d / L
        nrm = np.array([-u[1], u[0]]) * r
        a0, b0 = a.copy(), b.copy()
        if cap == "square" and i == 0:
            a0 = a - u * r
        if cap == "square" and i == n - 2:
            b0 = b + u * r
        add([tuple(a0 + nrm), tuple(b0 + nrm), tuple(b0 - nrm), tuple(a0 - nrm)])
    for i in range(n):
        if 0 < i < n - 1 or cap == "round":
            add([(v[i][0] + x, v[i][1] + y) for x, y in disc])
    return pieces


def union_area(pieces, limit=16):
    """The area of the union of convex polygons by inclusion-exclusion (intersections found by
    clipping one by another; an empty one prunes every larger set)."""
    if len(pieces) > limit:
        raise ValueError(f"{len(pieces)} pieces: too many for inclusion-exclusion")
    total = 0.0

    def walk(start, inter, depth):
        nonlocal total
        for j in range(start, len(pieces)):
            nxt = pieces[j] if inter is None else clip_convex(inter, pieces[j])
            if not nxt or area(nxt) <= 0:
                continue
            total += area(nxt) if depth % 2 == 0 else -area(nxt)
            walk(j + 1, nxt, depth + 1)

    walk(0, None, 0)
    return total


def distance(v, col, row):
    """The distance from pixel (col, row)'s centre to the polyline v."""
    p = np.array([col + 0.5, row + 0.5])
    a, b = v[:-1], v[1:]
    ab = b - a
    t = np.clip(((p - a) * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-300), 0, 1)
    return float(np.sqrt(((p - a - t[:, None] * ab) ** 2).sum(1)).min()) if len(a) else float(np.hypot(*(p - v[0])))


def oracle_value(items, col, row):
    """The pixel's 8-bit RGB by the oracle, and the coverage of each item that reaches it. A
    ValueError when an item the oracle does not model reaches it."""
    val = np.ones(3)
    covers = []
    for it in items:
        if it[0] == "raster":
            x0, y0, x1, y1 = it[1:]
            if x0 < col + 1 and x1 > col and y0 < row + 1 and y1 > row:
                raise ValueError("a picture (marker, hatch or image) covers it")
            continue
        v, codes, colour = it[1], it[2], it[3]
        if it[0] == "fill":
            xs, ys = v[:, 0], v[:, 1]
            if xs.max() <= col or xs.min() >= col + 1 or ys.max() <= row or ys.min() >= row + 1:
                continue
            k = fill_coverage(v, codes, col, row)
        else:
            width, join, cap, dashes = it[4:]
            if distance(v, col, row) > width / 2 * (4 if join == "miter" else 1) + 0.75:
                continue  # out of its reach (a miter reaches at most 4 half-widths)
            if join != "round" or dashes or (len(codes) and np.isin(codes, (3, 4, 79)).any()):
                raise ValueError("a stroke other than an undashed, round-joined polyline reaches it")
            k = union_area(stroke_pieces(v, width, cap, col, row))
        if k <= 0:
            continue
        srgb = np.array([c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055 for c in colour[:3]])
        a = k * colour[3]
        val = val * (1 - a) + srgb * a
        covers.append(k)
    return np.floor(val * 255 + 0.5).astype(int), covers


def best_window(d, w, h, region):
    """The top-left corner of the w x h window of largest summed difference within region."""
    r0, r1, c0, c1 = region
    s = np.zeros((d.shape[0] + 1, d.shape[1] + 1))
    s[1:, 1:] = d.cumsum(0).cumsum(1)
    best, at = -1, (r0, c0)
    for y in range(r0, r1 - h + 1):
        for x in range(c0, c1 - w + 1):
            t = s[y + h, x + w] - s[y, x + w] - s[y + h, x] + s[y, x]
            if t > best:
                best, at = t, (y, x)
    return at


def compose(caption, agg, ours, crop, marks, labels):
    """AGG | splinefig at 1:1 with the crop outlined, above the crop of each and their difference
    enlarged ZOOM times (nearest neighbour), the marked pixels outlined; a caption line each."""
    font = ImageFont.load_default()
    (y, x), (h, w) = crop
    H, W = agg.shape[:2]
    gap, head = 8, 14
    d = np.abs(agg - ours).max(axis=2)
    diff = np.repeat((255 - np.minimum(d * 2, 255))[:, :, None], 3, axis=2)  # |difference| x2, dark = large
    zooms = [np.kron(im[y:y + h, x:x + w], np.ones((ZOOM, ZOOM, 1), dtype=np.int32)) for im in (agg, ours, diff)]
    zw, zh = w * ZOOM, h * ZOOM
    top = head + H
    width = max(2 * W + gap, 3 * zw + 2 * gap)
    canvas = Image.new("RGB", (width, top + gap + head + zh + 2 + head * len(caption)), "white")
    canvas.paste(Image.fromarray(agg.astype(np.uint8)), (0, head))
    canvas.paste(Image.fromarray(ours.astype(np.uint8)), (W + gap, head))
    for i, z in enumerate(zooms):
        canvas.paste(Image.fromarray(z.astype(np.uint8)), (i * (zw + gap), top + gap + head))
    dr = ImageDraw.Draw(canvas)
    dr.text((2, 1), "AGG", fill="black", font=font)
    dr.text((W + gap + 2, 1), "splinefig", fill="black", font=font)
    for ox in (0, W + gap):
        dr.rectangle([ox + x - 1, head + y - 1, ox + x + w, head + y + h], outline=(220, 0, 0))
    for i, t in enumerate(labels):
        dr.text((i * (zw + gap) + 2, top + gap + 1), t, fill="black", font=font)
    for i in range(3):
        for k, (r, c) in enumerate(marks):
            px, py = i * (zw + gap) + (c - x) * ZOOM, top + gap + head + (r - y) * ZOOM
            dr.rectangle([px, py, px + ZOOM - 1, py + ZOOM - 1], outline=(220, 0, 0))
            dr.text((px + ZOOM + 1, py - 2), "ab"[k], fill=(220, 0, 0), font=font)
    for i, t in enumerate(caption):
        dr.text((2, top + gap + head + zh + 3 + head * i), t, fill="black", font=font)
    return canvas


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "docs", "images")
    os.makedirs(out, exist_ok=True)
    for make, name, inside in ((lines, "lines", True), (text, "text", False)):
        fig, ax = make()
        agg = render(fig, None)
        ours, items = recorded(fig)
        plt.close(fig)
        H, W = agg.shape[:2]
        d = np.abs(agg - ours).max(axis=2)
        if inside:  # the data area: tick labels are text, which the second figure shows
            x0, y0, x1, y1 = ax.bbox.extents
            region = (int(H - y1) + 3, int(H - y0) - 3, int(x0) + 3, int(x1) - 3)
        else:
            region = (0, H, 0, W)
        ch, cw = 24, 32
        y, x = best_window(d.astype(float), cw, ch, region)
        # The marked pixels: the two largest differences in the crop, 4 px or more apart, on an edge of an
        # item the oracle models (partly covered by it).
        marks, lines_out = [], []
        for r, c in sorted(np.argwhere(d[y:y + ch, x:x + cw] > 0) + (y, x), key=lambda p: -d[p[0], p[1]]):
            if any(abs(r - r0) + abs(c - c0) < 4 for r0, c0 in marks):
                continue  # a second place, not the first one's neighbour
            try:
                want, covers = oracle_value(items, int(c), int(r))
            except ValueError:
                continue
            if not any(0.02 < k < 0.98 for k in covers):
                continue  # an edge of something: a pixel the oracle has something to say about
            marks.append((int(r), int(c)))
            lines_out.append(f"{name} pixel {'ab'[len(marks) - 1]} (x {c}, y {r}): coverage "
                             f"{', '.join(f'{k:.3f}' for k in covers)}; oracle {tuple(want)}, AGG {tuple(agg[r, c])}, "
                             f"splinefig {tuple(ours[r, c])}")
            if len(marks) == 2:
                break
        print(f"{name}: mean |difference| {np.abs(agg - ours).mean():.2f}, max {d.max()}; crop x {x}..{x + cw - 1}, "
              f"y {y}..{y + ch - 1}, max there {d[y:y + ch, x:x + cw].max()}")
        print("\n".join(lines_out))
        labels = [f"AGG x{ZOOM}", f"splinefig x{ZOOM}", "|difference| x2"]
        caption = [f"{'ab'[i]}: " + s.split("; ", 1)[1] for i, s in enumerate(lines_out)]
        im = compose(caption, agg, ours, ((y, x), (ch, cw)), marks, labels)
        path = os.path.join(out, f"matplotlib-{name}.png")
        im.save(path, optimize=True)
        print(f"wrote {os.path.normpath(path)} ({os.path.getsize(path) // 1024} KB)")


if __name__ == "__main__":
    main()
