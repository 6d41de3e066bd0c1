"""Notebook display: the images the module returns show themselves (IPython's _repr_png_), as
the PNG write_image writes. The PNG bytes are decoded here by a reader of their own (zlib and the
PNG filters, from the PNG specification), not by the module."""
import re
import struct
import zlib

import numpy as np
import pytest

import splinefig


def decode_png(data: bytes):
    """(width, height, rows of (r, g, b[, a]) tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, ihdr = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        assert zlib.crc32(kind + body) == struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0]
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    w, h, depth, ctype, _, _, interlace = ihdr
    assert depth == 8 and interlace == 0 and ctype in (2, 6)
    bpp = 3 if ctype == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp:(x + 1) * bpp]) for x in range(w)])
        prev = line
    return w, h, rows


def test_scene_render_shows_as_png_of_its_pixels():
    # A 5x3 white canvas with the pixels x in [1, 3), y in [0, 2) covered by #3366cc: covered
    # pixels are that colour exactly (8-bit sRGB -> linear -> 8-bit is exact), the others white.
    img = splinefig.Scene(5, 3, background="#ffffff").fill([(1, 0), (3, 0), (3, 2), (1, 2)], color="#3366cc").render()
    assert isinstance(img, np.ndarray) and isinstance(img, splinefig.Image)
    w, h, rows = decode_png(img._repr_png_())
    assert (w, h) == (5, 3)
    assert rows[1][2][:3] == (0x33, 0x66, 0xCC)
    assert rows[0][1][:3] == (0x33, 0x66, 0xCC)
    assert rows[0][0][:3] == (255, 255, 255)
    assert rows[2][2][:3] == (255, 255, 255)
    if len(rows[0][0]) == 4:
        assert rows[1][2][3] == 255


def test_srgb_blend_scene_and_read_image_show_their_stored_values(tmp_path):
    img = splinefig.Scene(2, 2, background="#808080", blend="srgb").render()
    assert img.encoding == "srgb"
    _, _, rows = decode_png(img._repr_png_())
    assert rows[0][0][:3] == (0x80, 0x80, 0x80)
    # A file read back (sRGB values as stored) shows as the same pixels.
    path = tmp_path / "g.png"
    splinefig.write_image(path, img, encoding="srgb")
    back = splinefig.read_image(path)
    assert back.encoding == "srgb"
    _, _, rows2 = decode_png(back._repr_png_())
    assert rows2 == rows


def test_rendered_figure_shows_at_its_size():
    img = splinefig.render_spec(None, text="[canvas]\nwidth = 7\nheight = 4\nbackground = \"#ff0000\"\n")
    w, h, rows = decode_png(img._repr_png_())
    assert (w, h) == (7, 4)
    assert rows[3][6][:3] == (255, 0, 0)


def test_what_is_not_an_image_shows_as_an_array():
    img = splinefig.Scene(4, 4).render()
    assert img[0, 0]._repr_png_() is None
    assert img[:, :, :0]._repr_png_() is None
    assert img.sum(axis=(0, 1))._repr_png_() is None


RED = "[canvas]\nwidth = 7\nheight = 4\nbackground = \"#ff0000\"\n"


def test_a_figure_shows_as_the_svg_render_writes(tmp_path, cli, monkeypatch):
    import xml.etree.ElementTree as ET
    monkeypatch.chdir(tmp_path)
    (tmp_path / "red.toml").write_text(RED)
    cli(["render", "red.toml", "-o", "red.svg", "--scale", "2"])
    img = splinefig.render_spec("red.toml", scale=2)
    svg = img._repr_svg_()
    assert svg == (tmp_path / "red.svg").read_text()
    root = ET.fromstring(svg)
    # 7 x 4 CSS px at any scale; the scaled canvas is the view box.
    assert (root.get("width"), root.get("height"), root.get("viewBox")) == ("7", "4", "0 0 14 8")
    assert root.find("{http://www.w3.org/2000/svg}rect").get("fill") == "#ff0000"
    # Moved away from the directory it was rendered in, the figure still shows.
    monkeypatch.chdir("/")
    assert img._repr_svg_() == svg


def test_a_spec_given_as_text_and_a_built_in_figure_show_as_svg():
    svg = splinefig.render_spec("red", text=RED)._repr_svg_()
    assert svg.startswith("<?xml") and "<title>red</title>" in svg
    bias = splinefig.render_figure("bias")._repr_svg_()
    assert re.search(r'<path d="M[^"]*C', bias)  # the curves as cubic Bezier pieces


def test_what_is_no_longer_the_figure_has_no_svg(tmp_path):
    spec = tmp_path / "red.toml"
    spec.write_text(RED)
    img = splinefig.render_spec(spec)
    assert img[1:3]._repr_svg_() is None
    assert (img * 0.5)._repr_svg_() is None
    assert img.copy()._repr_svg_() is None
    assert splinefig.Scene(4, 4).render()._repr_svg_() is None
    # The spec has since become bad: the PNG still shows, the SVG does not.
    spec.write_text("[canvas]\nwidth = -1\n")
    assert img._repr_svg_() is None
    assert img._repr_png_() is not None
