#!/usr/bin/env python3
"""Writes the small fonts in tests/fonts/ that pin down where glyphscope places outlines,
then checks each against FreeType (freetype-py) so that the coordinates the Rust tests
expect, worked out by hand from the tables below, are FreeType's too.

    pip install fonttools freetype-py
    python3 tools/make_test_fonts.py

CI does not run this; the fonts it writes are committed. Every number the tests use is
in this file: outlines in font units, hmtx (advance, lsb), gvar deltas, HVAR deltas.
"""

from pathlib import Path

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.t2CharStringPen import T2CharStringPen
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import TTFont, newTable
from fontTools.ttLib.tables import otTables
from fontTools.ttLib.tables._g_l_y_f import GlyphComponent
from fontTools.ttLib.tables.TupleVariation import TupleVariation
from fontTools.varLib.builder import buildVarData, buildVarRegionList, buildVarStore

OUT = Path(__file__).resolve().parent.parent / "tests" / "fonts"
UPEM = 1000
USE_MY_METRICS = 0x0200
ARGS_ARE_XY_VALUES = 0x0002
# 2026-01-01T00:00:00Z in head's clock (seconds since 1904-01-01).
FIXED_TIMESTAMP = 3850070400

# Glyph A of the placement fonts: one contour, a quadratic arch on a box, xMin 100.
# Points in glyf order: on, on, off, on, on.
ARCH = [(100, 0), (100, 500), (250, 700), (400, 500), (400, 0)]
# hmtx for A: advance 600, lsb 40, so lsb != xMin and FreeType shifts A by 40 - 100.
ARCH_METRICS = (600, 40)


def arch_glyph():
    pen = TTGlyphPen(None)
    pen.moveTo(ARCH[0])
    pen.lineTo(ARCH[1])
    pen.qCurveTo(ARCH[2], ARCH[3])
    pen.lineTo(ARCH[4])
    pen.closePath()
    return pen.glyph()


def box_glyph(x0, y0, x1, y1):
    pen = TTGlyphPen(None)
    pen.moveTo((x0, y0))
    pen.lineTo((x0, y1))
    pen.lineTo((x1, y1))
    pen.lineTo((x1, y0))
    pen.closePath()
    return pen.glyph()


def empty_glyph():
    return TTGlyphPen(None).glyph()


def common_tables(fb, family, metrics, axes=None):
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=800, descent=-200)
    fb.setupNameTable({"familyName": family, "styleName": "Regular"})
    fb.setupOS2(sTypoAscender=800, sTypoDescender=-200, usWinAscent=800, usWinDescent=200)
    fb.setupPost()
    if axes:
        fb.setupFvar(axes, [])


def ttf(family, glyphs, metrics, cmap, axes=None):
    fb = FontBuilder(UPEM, isTTF=True)
    fb.setupGlyphOrder(list(glyphs))
    fb.setupCharacterMap(cmap)
    fb.setupGlyf(glyphs)
    common_tables(fb, family, metrics, axes)
    return fb


def save(fb, name):
    OUT.mkdir(parents=True, exist_ok=True)
    path = OUT / name
    # Fixed head timestamps, so the bytes depend only on this script.
    fb.font.recalcTimestamp = False
    fb.font["head"].created = fb.font["head"].modified = FIXED_TIMESTAMP
    fb.font.save(path)
    # Saving recomputes glyf bounding boxes; hmtx must keep the lsb written above.
    return TTFont(path)


def arch_variation(axis):
    """gvar for A at axis peak 1.0: every outline point +20 in x; phantom points
    pp1 +30, pp2 +80 (x), pp3 and pp4 unmoved. So pp1 and the advance vary."""
    deltas = [(20, 0)] * len(ARCH) + [(30, 0), (80, 0), (0, 0), (0, 0)]
    return [TupleVariation({axis: (0.0, 1.0, 1.0)}, deltas)]


def make_placement():
    """(a) glyf, static: A with lsb 40 != xMin 100; B = A moved by (200, 0) with
    USE_MY_METRICS, its own hmtx (900, 300) matching its own xMin, which FreeType
    ignores for A's phantom points."""
    composite = empty_glyph()
    component = GlyphComponent()
    component.glyphName = "A"
    component.x, component.y = 200, 0
    component.flags = ARGS_ARE_XY_VALUES | USE_MY_METRICS
    composite.numberOfContours = -1
    composite.components = [component]
    glyphs = {".notdef": empty_glyph(), "A": arch_glyph(), "B": composite}
    metrics = {".notdef": (500, 0), "A": ARCH_METRICS, "B": (900, 300)}
    font = save(ttf("Placement Test", glyphs, metrics, {0x41: "A", 0x42: "B"}), "placement.ttf")
    assert font["hmtx"]["A"] == ARCH_METRICS and font["glyf"]["A"].xMin == 100
    assert font["glyf"]["B"].components[0].flags & USE_MY_METRICS
    assert font["hmtx"]["B"] == (900, 300) and font["glyf"]["B"].xMin == 300


def make_placement_var():
    """(b) The variable twin of A, axis SHFT 0..1 (default 0), gvar on the phantom
    points and no HVAR: the shift and the advance follow pp1 and pp2. Beside it a
    combining acute (U+0301, a triangle with xMin 50 = lsb, advance 300) whose pp1 moves
    +40 at SHFT 1: its own advance shrinks, but a shaper zeroes a mark's advance."""
    pen = TTGlyphPen(None)
    pen.moveTo((50, 600))
    pen.lineTo((150, 700))
    pen.lineTo((250, 600))
    pen.closePath()
    glyphs = {".notdef": empty_glyph(), "A": arch_glyph(), "acutecomb": pen.glyph()}
    metrics = {".notdef": (500, 0), "A": ARCH_METRICS, "acutecomb": (300, 50)}
    fb = ttf("Placement Var Test", glyphs, metrics, {0x41: "A", 0x301: "acutecomb"},
             axes=[("SHFT", 0, 0, 1, "Shift")])
    acute = [(0, 0)] * 3 + [(40, 0), (0, 0), (0, 0), (0, 0)]
    fb.setupGvar({"A": arch_variation("SHFT"),
                  "acutecomb": [TupleVariation({"SHFT": (0.0, 1.0, 1.0)}, acute)]})
    save(fb, "placement-var.ttf")


def make_placement_hvar():
    """(b') The same with an HVAR table: A's advance +100 at SHFT 1. With HVAR, FreeType
    leaves the horizontal phantom points unvaried (the advance comes from HVAR)."""
    glyphs = {".notdef": empty_glyph(), "A": arch_glyph()}
    metrics = {".notdef": (500, 0), "A": ARCH_METRICS}
    fb = ttf("Placement HVAR Test", glyphs, metrics, {0x41: "A"},
             axes=[("SHFT", 0, 0, 1, "Shift")])
    fb.setupGvar({"A": arch_variation("SHFT")})
    # One region (SHFT peak 1); VarData rows indexed by glyph id (no AdvWidthMap).
    regions = buildVarRegionList([{"SHFT": (0.0, 1.0, 1.0)}], ["SHFT"])
    store = buildVarStore(regions, [buildVarData([0], [[0], [100]], optimize=False)])
    hvar = otTables.HVAR()
    hvar.Version = 0x00010000
    hvar.VarStore = store
    hvar.AdvWidthMap = hvar.LsbMap = hvar.RsbMap = None
    fb.font["HVAR"] = newTable("HVAR")
    fb.font["HVAR"].table = hvar
    save(fb, "placement-hvar.ttf")


def make_both_outlines():
    """(c) sfntVersion OTTO with a CFF table and a glyf table that disagree: A is a
    triangle in CFF, a box in glyf."""
    fb = FontBuilder(UPEM, isTTF=False)
    order = [".notdef", "A"]
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({0x41: "A"})
    notdef = T2CharStringPen(500, None).getCharString()
    pen = T2CharStringPen(600, None)
    pen.moveTo((100, 0))
    pen.lineTo((300, 600))
    pen.lineTo((500, 0))
    pen.closePath()
    fb.setupCFF("BothOutlinesTest", {"FullName": "Both Outlines Test"},
                {".notdef": notdef, "A": pen.getCharString()}, {})
    common_tables(fb, "Both Outlines Test", {".notdef": (500, 0), "A": (600, 100)})
    glyf = newTable("glyf")
    glyf.glyphOrder = order
    glyf.glyphs = {".notdef": empty_glyph(), "A": box_glyph(150, 0, 450, 400)}
    fb.font["glyf"] = glyf
    fb.font["loca"] = newTable("loca")
    font = save(fb, "both-outlines.otf")
    assert font.sfntVersion == "OTTO" and "glyf" in font and "CFF " in font


def make_short_tags():
    """(d) Axes with two-letter tags, 'M1  ' (0..1) and 'HV  ' (0..100), both default 0.
    A is a box with lsb == xMin (no shift); M1 at 1 moves every point +100 in x, HV at
    100 raises the top edge by 60."""
    glyphs = {".notdef": empty_glyph(), "A": box_glyph(100, 0, 400, 500)}
    metrics = {".notdef": (500, 0), "A": (600, 100)}
    fb = ttf("Short Tags Test", glyphs, metrics, {0x41: "A"},
             axes=[("M1  ", 0, 0, 1, "Move"), ("HV  ", 0, 0, 100, "Height")])
    # Box points in glyf order: (100,0) (100,500) (400,500) (400,0), then 4 phantoms.
    move = [(100, 0)] * 4 + [(0, 0)] * 4
    raise_top = [(0, 0), (0, 60), (0, 60), (0, 0)] + [(0, 0)] * 4
    fb.setupGvar({"A": [TupleVariation({"M1  ": (0.0, 1.0, 1.0)}, move),
                        TupleVariation({"HV  ": (0.0, 1.0, 1.0)}, raise_top)]})
    font = save(fb, "short-tags.ttf")
    assert [a.axisTag for a in font["fvar"].axes] == ["M1  ", "HV  "]


def freetype_view(path, char, coords=None):
    """FreeType's outline (font units, unhinted) and advance for `char`."""
    import freetype

    face = freetype.Face(str(path))
    if coords is not None:
        face.set_var_design_coords(coords)
    face.load_char(char, freetype.FT_LOAD_NO_SCALE | freetype.FT_LOAD_NO_HINTING)
    return [tuple(p) for p in face.glyph.outline.points], face.glyph.advance.x


def check_with_freetype():
    """The values the Rust tests state by hand, as FreeType 2 computes them."""
    def expect(path, char, coords, points, advance):
        got_points, got_advance = freetype_view(OUT / path, char, coords)
        assert got_points == points, f"{path} {char} {coords}: {got_points} != {points}"
        assert got_advance == advance, f"{path} {char} {coords}: {got_advance} != {advance}"
        print(f"FreeType agrees: {path} {char!a} at {coords}: {points}, advance {advance}")

    # (a) shift = lsb - xMin = 40 - 100 = -60.
    expect("placement.ttf", "A", None,
           [(40, 0), (40, 500), (190, 700), (340, 500), (340, 0)], 600)
    # B: A's points + 200, then shifted by A's -pp1.x = -60 (USE_MY_METRICS); advance A's.
    expect("placement.ttf", "B", None,
           [(240, 0), (240, 500), (390, 700), (540, 500), (540, 0)], 600)
    # (b) at SHFT 0.5: points +10; pp1 = 100 - 40 + 15 = 75; advance 600 + 40 - 15 = 625.
    expect("placement-var.ttf", "A", (0.5,),
           [(35, 0), (35, 500), (185, 700), (335, 500), (335, 0)], 625)
    # The acute alone: pp1 = 50 − 50 + 20, advance 300 − 20.
    expect("placement-var.ttf", "\u0301", (0.5,), [(30, 600), (130, 700), (230, 600)], 280)
    expect("placement-var.ttf", "A", (0.0,),
           [(40, 0), (40, 500), (190, 700), (340, 500), (340, 0)], 600)
    # (b') HVAR: phantom deltas dropped, pp1 = 60; points +10 - 60; advance 600 + 50.
    expect("placement-hvar.ttf", "A", (0.5,),
           [(50, 0), (50, 500), (200, 700), (350, 500), (350, 0)], 650)
    # (c) the CFF triangle, not the glyf box.
    expect("both-outlines.otf", "A", None, [(100, 0), (300, 600), (500, 0)], 600)
    # (d) M1 0.5, HV 50: x + 50, top + 30.
    expect("short-tags.ttf", "A", (0.5, 50.0),
           [(150, 0), (150, 530), (450, 530), (450, 0)], 600)


if __name__ == "__main__":
    make_placement()
    make_placement_var()
    make_placement_hvar()
    make_both_outlines()
    make_short_tags()
    check_with_freetype()
