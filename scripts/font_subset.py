#!/usr/bin/env python3
# Copyright 2026 the Spherekit Authors
# SPDX-License-Identifier: Apache-2.0 OR MIT
"""Subsets DejaVu Sans to the characters the renderer draws and writes its outlines.

    python3 scripts/font_subset.py [/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf]

Needs fontTools (`pip install fonttools` into a venv) and Debian's fonts-dejavu-core. Writes

- crates/spherekit-render/fonts/DejaVuSans-subset.ttf: the subset font (Bitstream Vera
  licence with DejaVu's public-domain changes, see LICENSE-DejaVu next to it);
- crates/spherekit-render/fonts/glyphs.bin: the same outlines in the renderer's format, which
  the renderer embeds (so that it needs no font parser):

      "SKF3", u16 units per em, i16 ascender, i16 descender, u16 glyph count,
      count × (u24 code point, u16 advance, u16 offset), sorted by code point (little-endian;
      a glyph's data runs to the next glyph's offset, the last one's to the end), then each
      glyph's data. It starts with a varint `h`. A simple glyph (`h` even) has `h / 2`
      contours, each a varint piece count, its start point and its pieces (a line: its end
      point; a quadratic: its control point, then its end point). Points are in units of
      QUANTUM font units (y up), each coordinate the zigzag varint (LEB128) of its difference
      from the previous coordinate of the same axis, carried across contours; the x of a
      piece's first point is shifted left by one with the low bit set for a quadratic. A
      composite glyph (`h` odd, the accented letters) is `h / 2` components, each the varint
      index of a glyph in the table and its offset (zigzag varints, font units). Glyphs that
      only serve as components (the accents) come last, with code points above U+10FFFF.
"""
import struct
import sys
from pathlib import Path

from fontTools import subset
from fontTools.pens.basePen import BasePen
from fontTools.ttLib import TTFont

CHARS = (
    "".join(chr(c) for c in range(0x20, 0x7F))  # ASCII
    + "".join(chr(c) for c in range(0xC0, 0x100) if c not in (0xD7, 0xF7))  # Latin-1 letters
    + "".join(chr(c) for c in range(0x3B1, 0x3CA))  # Greek small letters
    + "·−×÷°±ΓΔΘΛΠΣΦΨΩ′″–—…²³¹⁰⁴⁵⁶⁷⁸⁹₀₁₂₃ⁿ|≤≥≈→←∞√∂"
)
OUT = Path(__file__).resolve().parent.parent / "crates/spherekit-render/fonts"


# Coordinates are stored in units of 2 font units (1/1024 em): at most a quarter of a unit
# off, 0.01 px at 40 px per em.
QUANTUM = 2


class Recorder(BasePen):
    """Collects contours as (start, [(control or None, end)])."""

    def __init__(self, glyphset):
        super().__init__(glyphset)
        self.contours = []

    def _moveTo(self, p):
        self.contours.append((p, []))

    def _lineTo(self, p):
        self.contours[-1][1].append((None, p))

    def _qCurveToOne(self, p1, p2):
        self.contours[-1][1].append((p1, p2))

    def _curveToOne(self, p1, p2, p3):
        raise SystemExit("cubic outlines are not expected in a TrueType font")

    def _closePath(self):
        pass

    _endPath = _closePath


def varint(out, z):
    while True:
        byte = z & 0x7F
        z >>= 7
        out.append(byte | (0x80 if z else 0))
        if not z:
            return


def zigzag(d):
    return (d << 1) if d >= 0 else ((-d << 1) - 1)


def encode_composite(components):
    """A composite glyph: [(glyph index, dx, dy)] in font units."""
    out = bytearray()
    varint(out, (len(components) << 1) | 1)
    for index, dx, dy in components:
        varint(out, index)
        varint(out, zigzag(dx))
        varint(out, zigzag(dy))
    return out


def encode(contours):
    out = bytearray()
    last = [0, 0]

    def point(p, flag=None):
        q = [round(p[0] / QUANTUM), round(p[1] / QUANTUM)]
        zx, zy = zigzag(q[0] - last[0]), zigzag(q[1] - last[1])
        if flag is not None:
            zx = (zx << 1) | flag
        varint(out, zx)
        varint(out, zy)
        last[:] = q

    varint(out, len(contours) << 1)
    for start, pieces in contours:
        varint(out, len(pieces))
        point(start)
        for ctrl, end in pieces:
            if ctrl is None:
                point(end, 0)
            else:
                point(ctrl, 1)
                point(end)
    return out


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
    options = subset.Options()
    options.layout_features = []
    options.hinting = False
    options.name_IDs = ["*"]
    options.notdef_outline = True
    font = subset.load_font(src, options)
    sub = subset.Subsetter(options)
    sub.populate(text=CHARS)
    sub.subset(font)
    OUT.mkdir(parents=True, exist_ok=True)
    subset.save_font(font, str(OUT / "DejaVuSans-subset.ttf"), options)

    font = TTFont(str(OUT / "DejaVuSans-subset.ttf"))
    cmap = font.getBestCmap()
    glyphset = font.getGlyphSet()
    glyf = font["glyf"]
    hmtx = font["hmtx"]
    # The glyphs by code point, then the components that have none (code points 0x110000 + i).
    names = [(cp, cmap[cp]) for cp in sorted(cmap)]
    extra = []

    def components_of(name):
        for comp in glyf[name].components:
            if comp.transform if hasattr(comp, "transform") else False:
                raise SystemExit(f"{name}: a scaled component is not supported")
            yield comp.glyphName
            if glyf[comp.glyphName].isComposite():
                yield from components_of(comp.glyphName)

    for _, name in names:
        if glyf[name].isComposite():
            for comp in components_of(name):
                if comp not in cmap.values() and comp not in extra:
                    extra.append(comp)
    names += [(0x110000 + i, name) for i, name in enumerate(extra)]
    index = {}
    for i, (_, name) in enumerate(names):
        index.setdefault(name, i)
    entries, stream = [], bytearray()
    for cp, name in names:
        g = glyf[name]
        if g.isComposite():
            data = encode_composite([(index[c.glyphName], c.x, c.y) for c in g.components])
        else:
            pen = Recorder(glyphset)
            glyphset[name].draw(pen)
            data = encode(pen.contours)
        entries.append((cp, hmtx[name][0], len(stream)))
        stream += data
    if len(stream) > 0xFFFF:
        raise SystemExit("the outlines no longer fit 16-bit offsets")
    head = font["head"]
    hhea = font["hhea"]
    blob = bytearray(b"SKF3")
    blob += struct.pack("<HhhH", head.unitsPerEm, hhea.ascent, hhea.descent, len(entries))
    for cp, adv, off in entries:
        blob += struct.pack("<I", cp)[:3] + struct.pack("<HH", adv, off)
    blob += stream
    (OUT / "glyphs.bin").write_bytes(bytes(blob))
    missing = [c for c in CHARS if ord(c) not in cmap]
    print(f"{len(entries)} glyphs, {len(blob)} bytes; missing: {missing!r}")


if __name__ == "__main__":
    main()
