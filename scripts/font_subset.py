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

      "SKF1", u16 units per em, i16 ascender, i16 descender, u16 glyph count,
      count × (u32 code point, u16 advance, u32 offset, u16 length), sorted by code point,
      then the outline commands: u8 op (0 move, 1 line, 2 quadratic, 3 close) followed by
      1, 1, 2 or 0 points of two i16 (font units, y up). All little-endian.
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


class Recorder(BasePen):
    def __init__(self, glyphset):
        super().__init__(glyphset)
        self.out = bytearray()

    def pt(self, p):
        self.out += struct.pack("<hh", round(p[0]), round(p[1]))

    def _moveTo(self, p):
        self.out.append(0)
        self.pt(p)

    def _lineTo(self, p):
        self.out.append(1)
        self.pt(p)

    def _qCurveToOne(self, p1, p2):
        self.out.append(2)
        self.pt(p1)
        self.pt(p2)

    def _curveToOne(self, p1, p2, p3):
        raise SystemExit("cubic outlines are not expected in a TrueType font")

    def _closePath(self):
        self.out.append(3)

    _endPath = _closePath


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
    hmtx = font["hmtx"]
    entries, stream = [], bytearray()
    for cp in sorted(cmap):
        name = cmap[cp]
        pen = Recorder(glyphset)
        glyphset[name].draw(pen)
        entries.append((cp, hmtx[name][0], len(stream), len(pen.out)))
        stream += pen.out
    head = font["head"]
    hhea = font["hhea"]
    blob = bytearray(b"SKF1")
    blob += struct.pack("<HhhH", head.unitsPerEm, hhea.ascent, hhea.descent, len(entries))
    for cp, adv, off, n in entries:
        blob += struct.pack("<IHIH", cp, adv, off, n)
    blob += stream
    (OUT / "glyphs.bin").write_bytes(bytes(blob))
    missing = [c for c in CHARS if ord(c) not in cmap]
    print(f"{len(entries)} glyphs, {len(blob)} bytes; missing: {missing!r}")


if __name__ == "__main__":
    main()
