//! The named hard cases: the outlines and views that broke the best-known renderers
//! (docs/sources.md names them), each built in code or taken from a shipped font, with the
//! view it is seen through. This is the one place hard cases are defined; the method
//! tests that need one take it from here.
//!
//! Synthetic outlines are drawn in a 1000-unit em seen at 1000 px/em, so one font unit
//! is one pixel and `y = k + 0.5` is a pixel-centre row: the sweep's sub-pixel offsets
//! are multiples of 1/4 px, so offset (0, 0) keeps every such alignment exact.

use glam::{DMat2, DVec2};

use crate::Error;
use crate::camera::{Camera, MAX_SIZE_PX_PER_EM};
use crate::geometry::{Contour, Outline, Segment, project};
use crate::scene::Scene;

/// Units per em of the synthetic outlines.
pub const SYNTHETIC_UNITS_PER_EM: f64 = 1000.0;
/// Their size: one font unit per pixel.
pub const SYNTHETIC_PX_PER_EM: f64 = 1000.0;
/// Whole pixels kept clear around a framed scene's ink.
const MARGIN_PX: f64 = 3.0;

/// How a case's view is placed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Framing {
    /// The whole ink box plus a margin, moved by whole pixels only (so alignments to
    /// pixel centres survive).
    Framed,
    /// A `side`×`side` window whose centre sees `focus` (font units, relative to the
    /// scene's origin): a close-up on part of a glyph too large to view whole.
    Window { side: u32, focus: DVec2 },
}

/// One named hard case.
#[derive(Clone, Debug)]
pub struct HardCase {
    pub name: &'static str,
    /// What it tests, in a phrase.
    pub what: &'static str,
    pub scene: Scene,
    pub size_px_per_em: f64,
    /// Applied before the sweep's rotation (e.g. a skew).
    pub matrix: DMat2,
    pub framing: Framing,
    pub world_offset: DVec2,
    /// What makes it hard in ways some methods document as their limits.
    pub traits: &'static [Trait],
    /// Also seen through the sweep's full turn of rotations, for shapes whose trouble
    /// depends on which of their edges lies along a ray, at every angle.
    pub full_turn: bool,
}

/// A property of a case that a method's claim may leave out of its scope.
pub use crate::methods::info::Trait;

impl HardCase {
    /// The case's camera, turned by `rotation_deg` about the view (after the case's own
    /// matrix) and moved by `subpixel` (pixels).
    pub fn camera(&self, rotation_deg: f64, subpixel: DVec2) -> Result<Camera, Error> {
        let (sin, cos) = rotation_deg.to_radians().sin_cos();
        let mut camera = Camera::new(1, 1, self.size_px_per_em, DVec2::ZERO);
        camera.matrix = Camera::matrix_from_rows(cos, -sin, sin, cos) * self.matrix;
        match self.framing {
            Framing::Framed => {
                let ink = camera.ink_bounds(&self.scene)?;
                camera.origin = (DVec2::splat(MARGIN_PX) - ink.min).floor() + subpixel;
                let extent = (ink.size() + 2.0 * MARGIN_PX + 1.0).ceil();
                camera.width = extent.x as u32;
                camera.height = extent.y as u32;
            }
            Framing::Window { side, focus } => {
                camera.width = side;
                camera.height = side;
                let at = project(
                    &camera.glyph_to_image(self.scene.units_per_em, DVec2::ZERO),
                    focus,
                );
                camera.origin = DVec2::splat(f64::from(side) / 2.0) - at + subpixel;
            }
        }
        camera.world_offset = self.world_offset;
        camera.validate()?;
        Ok(camera)
    }
}

/// Every case, in the table's order.
pub fn all() -> Vec<HardCase> {
    let synthetic = |name, what, contours: Vec<Contour>| HardCase {
        name,
        what,
        scene: synthetic_scene(Outline { contours }),
        size_px_per_em: SYNTHETIC_PX_PER_EM,
        matrix: DMat2::IDENTITY,
        framing: Framing::Framed,
        world_offset: DVec2::ZERO,
        traits: &[],
        full_turn: false,
    };
    let overlapping = |case: HardCase| HardCase {
        traits: &[Trait::Overlapping],
        ..case
    };
    let touching = |case: HardCase| HardCase {
        traits: &[Trait::TouchingContours],
        ..case
    };
    // Two edges inside one pixel.
    let subpixel_detail = |case: HardCase| HardCase {
        traits: &[Trait::SubpixelDetail],
        ..case
    };
    // Whole contours, or chains of curves, inside a pixel: more than 8 edges cross it.
    let crowded = |case: HardCase| HardCase {
        traits: &[Trait::SubpixelDetail, Trait::CrowdedPixels],
        ..case
    };
    // The ink of neighbouring glyphs overlaps.
    let between_glyphs = |case: HardCase| HardCase {
        traits: &[Trait::OverlappingGlyphs],
        ..case
    };
    let default_font = crate::font::default_font();
    let text = |text: &str| Scene::from_text(&default_font, text).expect("DejaVu shapes it");
    let glyph_o = text("o");
    let bowl = glyph_o.glyphs[0].bounds;
    let inter = crate::font::shipped(2);
    let real = |name, what, scene, size_px_per_em| HardCase {
        name,
        what,
        scene,
        size_px_per_em,
        matrix: DMat2::IDENTITY,
        framing: Framing::Framed,
        world_offset: DVec2::ZERO,
        traits: &[],
        full_turn: false,
    };
    let far = |name, what, offset: f64| HardCase {
        world_offset: DVec2::new(offset, -offset),
        ..real(name, what, text("Rg"), 37.0)
    };
    vec![
        synthetic(
            "vertex-on-centre-row",
            "a diamond whose four vertices sit on pixel centres",
            vec![polygon(&[
                (12.5, 2.5),
                (20.5, 10.5),
                (12.5, 17.5),
                (3.5, 10.5),
            ])],
        ),
        synthetic(
            "horizontal-on-sample-row",
            "a staircase whose horizontal edges run along pixel-centre rows",
            vec![polygon(&[
                (2.0, 2.5),
                (20.0, 2.5),
                (20.0, 8.5),
                (14.0, 8.5),
                (14.0, 12.5),
                (8.0, 12.5),
                (8.0, 16.5),
                (2.0, 16.5),
            ])],
        ),
        synthetic(
            "horizontal-tangent-join",
            "an arch whose halves join with a horizontal tangent on a centre row",
            vec![Contour {
                segments: vec![
                    quad((2.0, 2.5), (2.0, 14.5), (11.0, 14.5)),
                    quad((11.0, 14.5), (20.0, 14.5), (20.0, 2.5)),
                    line((20.0, 2.5), (2.0, 2.5)),
                ],
            }],
        ),
        synthetic(
            "collinear-quadratic",
            "quadratics with the control point on the chord: at its middle (a = 0) and off it",
            vec![Contour {
                segments: vec![
                    quad((2.0, 2.5), (4.0, 9.0), (6.0, 15.5)),
                    quad((6.0, 15.5), (7.0, 15.5), (18.0, 15.5)),
                    line((18.0, 15.5), (18.0, 2.5)),
                    quad((18.0, 2.5), (10.0, 2.5), (2.0, 2.5)),
                ],
            }],
        ),
        synthetic(
            "nearly-collinear-quadratic",
            "quadratics bent by 1e-7 em, across and along the rays",
            vec![Contour {
                segments: vec![
                    quad((2.0, 2.5), (2.0 - 1e-4, 9.0), (2.0, 15.5)),
                    quad((2.0, 15.5), (10.0, 15.5 + 1e-4), (18.0, 15.5)),
                    quad((18.0, 15.5), (18.0 + 1e-4, 10.0), (18.0, 2.5)),
                    quad((18.0, 2.5), (10.0, 2.5 - 1e-4), (2.0, 2.5)),
                ],
            }],
        ),
        synthetic(
            "control-point-past-curve",
            "a bulge whose control point reaches columns the curve never does",
            vec![Contour {
                segments: vec![
                    quad((3.0, 17.5), (16.0, 10.0), (8.0, 3.5)),
                    line((8.0, 3.5), (3.0, 3.5)),
                    line((3.0, 3.5), (3.0, 17.5)),
                ],
            }],
        ),
        synthetic(
            "zero-length-segments",
            "zero-length lines and quadratics, duplicated points",
            zero_length_contours(),
        ),
        synthetic(
            "zero-length-only",
            "a contour whose every segment has zero length: it draws nothing",
            vec![Contour {
                segments: vec![
                    line((9.0, 9.0), (9.0, 9.0)),
                    quad((9.0, 9.0), (9.0, 9.0), (9.0, 9.0)),
                ],
            }],
        ),
        synthetic(
            "f32-collapsed-segment",
            "a segment 1e-7 units long, distinct in f64 but one point in f32, the GPU's precision",
            vec![polygon(&[
                (2.0, 2.0),
                (18.0, 2.0),
                (18.0, 14.0),
                (18.0, 14.0 + 1e-7),
                (2.0, 14.0),
            ])],
        ),
        crowded(synthetic(
            "tiny-curves",
            "quadratics 1e-4 em long along an edge, and a contour 1e-4 em across",
            tiny_curve_contours(),
        )),
        touching(synthetic(
            "touching-contours",
            "squares touching at a corner, a triangle touching a square's edge at its tip",
            vec![
                polygon(&rect(2.0, 2.0, 10.0, 10.0)),
                polygon(&rect(10.0, 10.0, 16.0, 16.0)),
                polygon(&[(18.0, 2.0), (26.0, 2.0), (22.0, 10.0)]),
                polygon(&rect(18.0, 10.0, 26.0, 18.0)),
            ],
        )),
        touching(synthetic(
            "hole-touching-edge",
            "a square with a triangular hole whose tip touches the square's top edge from \
             inside",
            vec![
                polygon(&rect(2.0, 2.0, 18.0, 18.0)),
                polygon(&[(6.0, 8.0), (14.0, 8.0), (10.0, 18.0)]).reversed(),
            ],
        )),
        touching(synthetic(
            "corners-touching-slanted",
            "triangles whose slanted corners touch at a point, the pair drawn twice with \
             its contours in either order",
            corners_touching_slanted(),
        )),
        touching(synthetic(
            "tip-on-arc",
            "a triangle whose tip touches the top of a quadratic arc from outside",
            vec![
                Contour {
                    segments: vec![
                        line((2.0, 2.0), (18.0, 2.0)),
                        line((18.0, 2.0), (18.0, 8.0)),
                        quad((18.0, 8.0), (10.0, 14.0), (2.0, 8.0)),
                        line((2.0, 8.0), (2.0, 2.0)),
                    ],
                },
                polygon(&[(10.0, 11.0), (14.0, 18.0), (6.0, 18.0)]),
            ],
        )),
        touching(synthetic(
            "shared-edge",
            "two squares sharing a whole edge, run once each way, off the pixel grid",
            vec![
                polygon(&rect(2.0, 2.3, 10.6, 14.0)),
                polygon(&rect(10.6, 2.3, 18.0, 14.0)),
            ],
        )),
        overlapping(synthetic(
            "overlapping-same-direction",
            "two squares wound the same way, overlapping",
            vec![
                polygon(&rect(2.0, 2.0, 14.0, 14.0)),
                polygon(&rect(8.0, 8.0, 20.0, 20.0)),
            ],
        )),
        HardCase {
            // Edges 0.05 px apart: some 20 of them cross each pixel of the border.
            traits: &[
                Trait::Overlapping,
                Trait::SubpixelDetail,
                Trait::CrowdedPixels,
                Trait::DeepWinding,
            ],
            ..synthetic(
                "winding-256",
                "256 nested squares wound the same way: the centre winds 256 times",
                (0..256)
                    .map(|k| {
                        let inset = 0.05 * f64::from(k);
                        polygon(&rect(2.0 + inset, 2.0 + inset, 30.0 - inset, 30.0 - inset))
                    })
                    .collect(),
            )
        },
        synthetic(
            "reversed-outer",
            "a ring whose outer contour is clockwise and its hole counter-clockwise",
            vec![
                polygon(&octagon(11.0, 11.0, 9.0)).reversed(),
                polygon(&octagon(11.0, 11.0, 4.5)),
            ],
        ),
        overlapping(synthetic(
            "figure-8",
            "one contour crossing itself: the two lobes wind opposite ways",
            vec![polygon(&[
                (2.0, 2.0),
                (18.0, 18.0),
                (18.0, 2.0),
                (2.0, 18.0),
            ])],
        )),
        overlapping(synthetic(
            "pentagram",
            "a self-intersecting star: its centre winds twice",
            vec![pentagram()],
        )),
        subpixel_detail(synthetic(
            "thin-stem",
            "stems 0.05 px wide, vertical and horizontal",
            vec![
                polygon(&rect(4.0, 2.0, 4.05, 18.0)),
                polygon(&rect(8.3, 2.0, 8.35, 18.0)),
                polygon(&rect(10.0, 6.6, 22.0, 6.65)),
            ],
        )),
        synthetic(
            "cubic-cusp",
            "a cubic with a cusp (zero derivative inside it)",
            vec![cubic_closed(
                (2.0, 2.0),
                (20.0, 18.0),
                (2.0, 18.0),
                (20.0, 2.0),
            )],
        ),
        overlapping(synthetic(
            "cubic-loop",
            "a cubic that loops over itself",
            vec![cubic_closed(
                (2.0, 2.0),
                (26.0, 20.0),
                (-4.0, 20.0),
                (20.0, 2.0),
            )],
        )),
        synthetic(
            "cubic-inflection",
            "an S-shaped cubic (an inflection point) closing a box",
            vec![Contour {
                segments: vec![
                    cubic((2.0, 10.0), (8.0, 22.0), (16.0, -2.0), (22.0, 10.0)),
                    line((22.0, 10.0), (22.0, 2.0)),
                    line((22.0, 2.0), (2.0, 2.0)),
                    line((2.0, 2.0), (2.0, 10.0)),
                ],
            }],
        ),
        // Their layout covers both axes, both sides and both ray directions already:
        // the sweep's own rotations suffice (a full turn would double its time).
        synthetic(
            "near-tangent-vertex-y",
            "bars and slots along x between the ends of curves 1°–8° off the y axis, \
             a pixel-centre column just beside the vertices",
            near_tangent_vertices(false),
        ),
        synthetic(
            "near-tangent-vertex-x",
            "the same transposed: bars along y between curves near the x axis",
            near_tangent_vertices(true),
        ),
        crowded(real(
            "glyphs-2px",
            "DejaVu Sans 'Hamburg@' at 2 px/em",
            text("Hamburg@"),
            2.0,
        )),
        HardCase {
            framing: Framing::Window {
                side: 48,
                focus: DVec2::new(bowl.min.x, (bowl.min.y + bowl.max.y) / 2.0),
            },
            ..real(
                "glyph-100000px-edge",
                "DejaVu 'o' at 100 000 px/em, a 48-pixel view on its bowl's leftmost edge",
                glyph_o.clone(),
                100_000.0,
            )
        },
        HardCase {
            framing: Framing::Window {
                side: 48,
                focus: DVec2::new(bowl.min.x, (bowl.min.y + bowl.max.y) / 2.0),
            },
            traits: &[Trait::BeyondF32],
            ..real(
                "glyph-max-size-edge",
                "the same view at 10⁶ px/em, the largest size accepted",
                glyph_o,
                MAX_SIZE_PX_PER_EM,
            )
        },
        far(
            "world-offset-1e5",
            "DejaVu 'Rg' at 37 px/em, scene and view moved 1e5 px",
            1e5,
        ),
        far(
            "world-offset-1e6",
            "DejaVu 'Rg' at 37 px/em, scene and view moved 1e6 px",
            1e6,
        ),
        HardCase {
            matrix: Camera::matrix_from_rows(1.0, 2.0, 0.0, 1.0),
            ..real(
                "strong-skew",
                "DejaVu 'Rg' at 48 px/em sheared by 2 (x += 2y)",
                text("Rg"),
                48.0,
            )
        },
        // A distance-field atlas's known failures (msdfgen's issues 9, 181 and 182), at
        // sizes where its field, 32 texels per em by default, is drawn magnified,
        // thinner than a texel, and minified: every method runs them.
        real(
            "sharp-corners-magnified",
            "DejaVu Sans 'AVWM' at 128 px/em: sharp vertices, 4–8 px per texel of a \
             32–16 texels-per-em field",
            text("AVWM"),
            128.0,
        ),
        // The 0.6 px bar has both its edges inside one pixel.
        subpixel_detail(HardCase {
            size_px_per_em: 64.0,
            ..synthetic(
                "hairline-stroke",
                "bars 0.02 and 0.01 em wide at 64 px/em (1.3 and 0.6 px): under a texel of \
                 a 32 texels-per-em field",
                vec![
                    polygon(&rect(100.0, 0.0, 120.0, 600.0)),
                    polygon(&rect(300.0, 0.0, 310.0, 600.0)),
                ],
            )
        }),
        // DejaVu's stems are 0.09 em: 0.7 px here, both edges inside one pixel.
        subpixel_detail(real(
            "minified-line",
            "DejaVu Sans 'Hamburgefonstiv' at 8 px/em (stems 0.7 px): a quarter of a 32 \
             texels-per-em field, its range under 2 px",
            text("Hamburgefonstiv"),
            8.0,
        )),
        overlapping(real(
            "inter-overlaps",
            "Inter 'eQ&' (overlapping contours, as variable fonts draw them) at 40 px/em",
            Scene::from_text(&inter, "eQ&").expect("Inter shapes it"),
            40.0,
        )),
        real(
            "latin-modern-cubics",
            "Latin Modern 'g§' (CFF cubics) at 31 px/em",
            Scene::from_text(&crate::font::shipped(1), "g§").expect("Latin Modern shapes it"),
            31.0,
        ),
        HardCase {
            full_turn: true,
            ..real(
                "sun-symbol",
                "a sun symbol (a ring with rays, as U+263C) at 48 px/em: near-vertical \
                 cubics end where a ray's horizontal edge starts",
                Scene::from_outlines(
                    1000.0,
                    vec![(
                        Outline {
                            contours: path(SUN_SYMBOL),
                        },
                        DVec2::ZERO,
                    )],
                ),
                48.0,
            )
        },
        synthetic(
            "slanted-ulp-segments",
            "squares whose corner is cut by a segment 2–4 f32 steps long, slanted 10°–80° \
             off the side before it: its direction rounds to almost anything in f32",
            slanted_ulp_segments(),
        ),
        // Scripts and layouts whose glyphs' ink overlaps, as shaped (docs/methods/
        // winding.md measured them drawn glyph by glyph: 0.11 to 0.34 off).
        between_glyphs(real(
            "arabic-line",
            "an Arabic line in DejaVu Sans at 24 px/em: each letter's ink runs into the \
             next's where they join",
            text(ARABIC_LINE),
            24.0,
        )),
        between_glyphs(real(
            "bengali-line",
            "a Bengali line in Lohit Bengali at 32 px/em: conjuncts, vowel signs over and \
             around their bases, the headline running from letter to letter",
            Scene::from_text(&crate::font::shipped(3), BENGALI_LINE).expect("Lohit shapes it"),
            32.0,
        )),
        between_glyphs(real(
            "box-drawing",
            "DejaVu Sans double-line box-drawing characters meeting at 20 px/em: \
             their lines run past the advance into the next character's",
            text("╔═╦═╗\n╠═╬═╣\n╚═╩═╝"),
            20.0,
        )),
        between_glyphs(real(
            "kerned-overlap",
            "DejaVu Sans 'fT' at 48 px/em: kerned so close that the f's bar runs into \
             the T's",
            text("fT"),
            48.0,
        )),
        // Shapes the survey found (docs/survey.md) that no case here had.
        real(
            "large-circle",
            "DejaVu Sans ◯ (U+25EF) at 48 px/em: a ring a whole em across drawn with few \
             quadratics, each far from its chord (sdf-cells' estimate read 1.0 on it)",
            text("◯"),
            48.0,
        ),
        real(
            "notch",
            "DejaVu Sans 𐌔 (U+10314) at 48 px/em: a zigzag whose concave notch has \
             vertices at equal heights (tessellation's sweep once joined them across the \
             notch, a triangle outside the outline)",
            text("𐌔"),
            48.0,
        ),
        real(
            "bent-strokes",
            "DejaVu Sans 'βζ' at 48 px/em: thin strokes bent tightly, where a chord lies \
             far from its curve (sdf-cells' estimate read pixels a whole pixel off along \
             one side)",
            text("βζ"),
            48.0,
        ),
        real(
            "star-tips",
            "DejaVu Sans ✦✧ (U+2726–7) at 48 px/em: spikes whose two curves arrive at \
             the tip along one line, a cusp (sdf-cells' estimate once read a bar of full \
             coverage across each tip)",
            text("✦✧"),
            48.0,
        ),
        synthetic(
            "opposite-wound-contours",
            "separate contours wound opposite ways, both filled under nonzero: squares side \
             by side, and a counter-clockwise ring with a clockwise hole",
            vec![
                polygon(&rect(2.0, 2.0, 12.0, 12.0)),
                polygon(&rect(15.0, 2.0, 21.0, 12.0)).reversed(),
                polygon(&octagon(31.0, 7.0, 6.0)),
                polygon(&octagon(31.0, 7.0, 3.0)).reversed(),
            ],
        ),
    ]
}

/// The Arabic line of the `arabic-line` case: a basmala and a greeting, letters joined
/// as the script writes them.
pub const ARABIC_LINE: &str = "بسم الله الرحمن الرحيم — السلام عليكم ورحمة الله";

/// The Bengali line of the `bengali-line` case: conjuncts (ক্ষ, ত্য, স্কৃ) and vowel signs
/// before, after and over their bases.
pub const BENGALI_LINE: &str = "ক্ষমা বাংলা ভাষা সাহিত্য সংস্কৃতি";

/// A sun symbol (a CFF glyph, 1000 units per em, advance 800), the
/// outline of a real symbol font's U+263C-like glyph: at 48 px/em with the origin at a
/// whole pixel, `winding` read 0.20 for 1.0 beside (594, 284), where the cubic
/// `574,207 588,243 594,284` ends nearly vertical and the line to (739, 284) starts.
const SUN_SYMBOL: &str = "M 384,-39 L 416,-39 L 416,107 C 470,115 491,126 526,152 \
    L 635,43 L 659,64 L 549,176 C 574,207 588,243 594,284 L 739,284 L 739,314 L 594,314 \
    C 592,352 577,389 549,426 L 659,536 L 637,558 L 526,449 C 487,478 459,489 416,493 \
    L 416,639 L 384,639 L 384,493 C 347,489 311,474 275,449 L 163,558 L 143,534 \
    L 251,424 C 225,393 210,357 206,315 L 61,315 L 61,285 L 206,285 C 212,244 227,208 \
    252,175 L 143,65 L 164,43 L 276,151 C 309,127 344,112 384,107 Z \
    M 400,137 C 312,137 238,211 238,299 C 238,387 310,462 400,462 \
    C 488,462 563,387 563,299 C 563,211 490,137 400,137 Z";

/// The case called `name`.
pub fn by_name(name: &str) -> Option<HardCase> {
    all().into_iter().find(|c| c.name == name)
}

/// Every case's name.
pub fn names() -> Vec<&'static str> {
    all().iter().map(|c| c.name).collect()
}

/// A scene of one synthetic outline at the origin.
pub fn synthetic_scene(outline: Outline) -> Scene {
    Scene::from_outlines(SYNTHETIC_UNITS_PER_EM, vec![(outline, DVec2::ZERO)])
}

/// A closed polygon through `points` (font units, y up).
pub fn polygon(points: &[(f64, f64)]) -> Contour {
    let p: Vec<DVec2> = points.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    Contour {
        segments: (0..p.len())
            .map(|i| Segment::Line(p[i], p[(i + 1) % p.len()]))
            .collect(),
    }
}

/// An axis-aligned rectangle, counter-clockwise (y up).
pub fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<(f64, f64)> {
    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
}

/// A pentagram centred at (11, 11), radius 9, drawn as one self-crossing contour.
pub fn pentagram() -> Contour {
    let star: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + f64::from(k * 2) * std::f64::consts::TAU / 5.0;
            (11.0 + 9.0 * a.cos(), 11.0 + 9.0 * a.sin())
        })
        .collect();
    polygon(&star)
}

pub fn line(a: (f64, f64), b: (f64, f64)) -> Segment {
    Segment::Line(DVec2::from(a), DVec2::from(b))
}

pub fn quad(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> Segment {
    Segment::Quad(DVec2::from(a), DVec2::from(b), DVec2::from(c))
}

fn cubic(a: (f64, f64), b: (f64, f64), c: (f64, f64), d: (f64, f64)) -> Segment {
    Segment::Cubic(
        DVec2::from(a),
        DVec2::from(b),
        DVec2::from(c),
        DVec2::from(d),
    )
}

/// A cubic closed by its chord.
fn cubic_closed(a: (f64, f64), b: (f64, f64), c: (f64, f64), d: (f64, f64)) -> Contour {
    Contour {
        segments: vec![cubic(a, b, c, d), line(d, a)],
    }
}

/// A regular octagon (counter-clockwise), vertices off the pixel grid's symmetries.
fn octagon(cx: f64, cy: f64, r: f64) -> Vec<(f64, f64)> {
    (0..8)
        .map(|k| {
            let a = 0.3 + f64::from(k) * std::f64::consts::TAU / 8.0;
            (cx + r * a.cos(), cy + r * a.sin())
        })
        .collect()
}

/// Zero-length lines and quadratics and repeated points inside one contour.
fn zero_length_contours() -> Vec<Contour> {
    let p = (12.0, 15.5);
    vec![Contour {
        segments: vec![
            line((3.0, 3.0), p),
            line(p, p),
            quad(p, p, p),
            line(p, (21.0, 4.0)),
            line((21.0, 4.0), (21.0, 4.0)),
            line((21.0, 4.0), (3.0, 3.0)),
        ],
    }]
}

/// A square whose top edge is a chain of 1e-4 em quadratics (0.1 font unit each, bent
/// up by a tenth of that), and a separate contour 1e-4 em across.
fn tiny_curve_contours() -> Vec<Contour> {
    let step = 0.1;
    let mut segments = vec![
        line((2.0, 2.0), (18.0, 2.0)),
        line((18.0, 2.0), (18.0, 14.0)),
    ];
    let steps = 160;
    for k in (0..steps).rev() {
        let x1 = 2.0 + f64::from(k + 1) * step;
        let x0 = 2.0 + f64::from(k) * step;
        segments.push(quad((x1, 14.0), ((x0 + x1) / 2.0, 14.01), (x0, 14.0)));
    }
    segments.push(line((2.0, 14.0), (2.0, 2.0)));
    vec![Contour { segments }, polygon(&rect(10.0, 17.0, 10.1, 17.1))]
}

/// Two triangles touching at a corner with slanted, unequal wedges, and the same pair
/// 20 units to the right with its contours in the other order.
fn corners_touching_slanted() -> Vec<Contour> {
    let left = [(2.0, 2.0), (10.0, 10.0), (3.0, 12.0)];
    let right = [(10.0, 10.0), (16.0, 4.0), (18.0, 14.0)];
    let shifted = |points: &[(f64, f64)]| -> Vec<(f64, f64)> {
        points.iter().map(|&(x, y)| (x + 20.0, y)).collect()
    };
    vec![
        polygon(&left),
        polygon(&right),
        polygon(&shifted(&right)),
        polygon(&shifted(&left)),
    ]
}

/// Squares 3 units across and 3 apart (beyond the estimate's ties of 1 unit, 0.001 em),
/// counter-clockwise, each with one corner cut by a straight segment `steps` f32 steps
/// long (2⁻¹⁹ units between 16 and 32, where the corners lie) leaving the side before it
/// at `slant` degrees: 2, 3 and 4 steps at 10°, 45° and 80°, each at a different corner
/// of the square so that the cut runs every way. The cut's ends are not on the f32 grid.
fn slanted_ulp_segments() -> Vec<Contour> {
    let step = 2f64.powi(-19);
    let mut contours = Vec::new();
    for (row, steps) in [2.0, 3.0, 4.0].into_iter().enumerate() {
        for (column, slant) in [10.0f64, 45.0, 80.0].into_iter().enumerate() {
            let corner_index = (row + column) % 4;
            let origin = DVec2::new(16.3 + 6.0 * column as f64, 16.7 + 6.0 * row as f64);
            let corners: Vec<DVec2> = rect(0.0, 0.0, 3.0, 3.0)
                .into_iter()
                .map(|(x, y)| origin + DVec2::new(x, y))
                .collect();
            let at = corners[corner_index];
            let before = corners[(corner_index + 3) % 4];
            let after = corners[(corner_index + 1) % 4];
            // Back along the side before the corner, then across to the side after it.
            let incoming = (at - before).normalize();
            let outgoing = (after - at).normalize();
            let (sin, cos) = slant.to_radians().sin_cos();
            let cut = (incoming * cos + outgoing * sin) * steps * step;
            // The cut leaves the side before at `from` and meets the side after at `to`:
            // `cut` splits into its components along the two sides.
            let from = at - incoming * cut.dot(incoming);
            let to = from + cut;
            let mut points = Vec::new();
            for k in 1..=4 {
                let corner = (corner_index + k) % 4;
                if corner == corner_index {
                    points.extend([from, to]);
                } else {
                    points.push(corners[corner]);
                }
            }
            contours.push(polygon(
                &points.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>(),
            ));
        }
    }
    contours
}

/// Contours written as an SVG path of absolute `M`, `L`, `C` and `Z` commands, with
/// `x,y` pairs (font units, y up), each command and point a word. For this file's own
/// constants: a malformed path is a bug here, hence the panics.
fn path(d: &str) -> Vec<Contour> {
    let mut words = d.split_whitespace();
    let point = |words: &mut std::str::SplitWhitespace| {
        let (x, y) = words
            .next()
            .and_then(|w| w.split_once(','))
            .expect("a command's points are x,y pairs");
        DVec2::new(
            x.parse().expect("x is a number"),
            y.parse().expect("y is a number"),
        )
    };
    let mut contours = Vec::new();
    let mut segments = Vec::new();
    let (mut start, mut pen) = (DVec2::ZERO, DVec2::ZERO);
    while let Some(command) = words.next() {
        match command {
            "M" => {
                start = point(&mut words);
                pen = start;
            }
            "L" => {
                let to = point(&mut words);
                segments.push(Segment::Line(pen, to));
                pen = to;
            }
            "C" => {
                let (c1, c2, to) = (point(&mut words), point(&mut words), point(&mut words));
                segments.push(Segment::Cubic(pen, c1, c2, to));
                pen = to;
            }
            "Z" => {
                if pen != start {
                    segments.push(Segment::Line(pen, start));
                }
                contours.push(Contour {
                    segments: std::mem::take(&mut segments),
                });
            }
            _ => panic!("path command '{command}' is not M, L, C or Z"),
        }
    }
    contours
}

/// Angles (degrees) off the axis at which the curves of `near_tangent_vertices` meet
/// their vertices.
const NEAR_TANGENT_ANGLES_DEG: [f64; 3] = [1.0, 3.0, 8.0];

/// A grid of contours, each a body whose side is two near-vertical quadratics, `angle`
/// off the y axis at their ends, with a bar along x between those ends: the curve
/// arrives at one vertex and a line leaves it along x, as a sun's ray leaves its ring.
/// Bars sticking out (inner corners) and slots cut in (outer corners), each mirrored
/// too, at every angle, 1 unit thick with curves 3 long and 1.5 thick with curves 10
/// long. The vertices sit a small step beside a pixel-centre column (tan(angle) × 0.2,
/// so the column meets the curves 0.2 units past them) and 0.1 off a pixel-centre row,
/// so at offset 0 a y-ray passes both on the curves' side. `transpose` swaps x and y.
fn near_tangent_vertices(transpose: bool) -> Vec<Contour> {
    let mut contours = Vec::new();
    let mut cell = 0;
    for slot in [false, true] {
        for mirror in [false, true] {
            for angle_deg in NEAR_TANGENT_ANGLES_DEG {
                for (thickness, length) in [(1.0, 3.0), (1.5, 10.0)] {
                    let (sin, cos) = f64::to_radians(angle_deg).sin_cos();
                    let lower = DVec2::new(sin / cos * 0.2, 0.1);
                    let upper = lower + DVec2::new(0.0, thickness);
                    let bar = DVec2::new(if slot { -2.0 } else { 3.0 }, 0.0);
                    let arrive = DVec2::new(sin, cos);
                    let start = lower + DVec2::new(-0.6 * length, -length);
                    let end = upper + DVec2::new(-0.6 * length, length);
                    let back = start.x - 3.0;
                    // Cells 14 × 24 units, six a row; the anchor is a pixel centre.
                    let anchor = DVec2::new(
                        f64::from(cell % 6) * 14.0 + if mirror { 4.5 } else { 9.5 },
                        f64::from(cell / 6) * 24.0 + 11.5,
                    );
                    let place = |p: DVec2| {
                        let p = anchor + if mirror { DVec2::new(-p.x, p.y) } else { p };
                        if transpose { DVec2::new(p.y, p.x) } else { p }
                    };
                    let mut segments = vec![
                        Segment::Quad(start, lower - 0.5 * length * arrive, lower),
                        Segment::Line(lower, lower + bar),
                        Segment::Line(lower + bar, upper + bar),
                        Segment::Line(upper + bar, upper),
                        Segment::Quad(upper, upper + 0.5 * length * DVec2::new(-sin, cos), end),
                    ];
                    let corners = [
                        end,
                        DVec2::new(back, end.y),
                        DVec2::new(back, start.y),
                        start,
                    ];
                    for k in 1..corners.len() {
                        segments.push(Segment::Line(corners[k - 1], corners[k]));
                    }
                    let contour = Contour {
                        segments: segments.iter().map(|s| s.map(place)).collect(),
                    };
                    // Mirroring or transposing alone turns the contour clockwise: turn
                    // it back, as a font winds every contour of a glyph alike.
                    contours.push(if mirror != transpose {
                        contour.reversed()
                    } else {
                        contour
                    });
                    cell += 1;
                }
            }
        }
    }
    contours
}
