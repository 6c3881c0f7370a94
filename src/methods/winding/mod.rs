//! `winding`'s row in the registry: its parameters, overlays, claims and bench
//! settings, on the renderer `glyphscope-text` defines ([`Winding`]; the algorithm and
//! its sources are documented there, and in docs/methods/winding.md).

pub use glyphscope_text::winding::{
    Antialiasing, BandCount, GlyphData, Layout, MAX_BANDS, NAME, Rays, Settings, Stage, Winding,
    area, cost, text,
};

use super::info::{Claim, ClaimedSetting, MethodInfo, Role, Trait, bench_at, within};
use super::params::{BETWEEN, Numbers, ParamSpec, Params, Value};
use super::{CurveCost, Method, Overlay};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{CoverageTarget, GpuContext};
use crate::scene::Scene;
use glyphscope_text::winding;

/// `winding`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "winding number of quadratic curves: its exact box-filter integral over \
              each pixel by Green's theorem (aa=area), or from roots along x and y rays \
              anti-aliased per crossing (aa=rays, Slug's family)",
    role: Role::Method,
    shader: Some(winding::SHADER),
    params: PARAMS,
    colour: [31, 119, 180],
    // The exact integral, then the rays: samples and rays are their trade; bands change
    // only the time (the same image), shown on the cheapest setting (without bands a
    // page costs far more: `glyphscope render --case page --method winding --param
    // bands=off --stats S.json` beside the same without it).
    bench: &[
        bench_at(&[], true),
        bench_at(&[("samples", "1")], false),
        bench_at(&[("aa", "rays")], true),
        bench_at(&[("aa", "rays"), ("samples", "1")], true),
        bench_at(&[("aa", "rays"), ("samples", "4")], false),
        bench_at(&[("rays", "slug")], false),
        bench_at(&[("rays", "1")], false),
        bench_at(&[("rays", "1"), ("samples", "1")], true),
        bench_at(&[("rays", "1"), ("samples", "1"), ("bands", "off")], false),
        // What joining overlapping instances costs: the same frame with their coverage
        // added instead (a page without overlaps draws the same instances either way).
        bench_at(&[("between", "add")], false),
    ],
    // Bounds set by the margin rule (info::Claim) from the sweep before them.
    claims: &[
        ClaimedSetting {
            label: NAME,
            params: &[],
            claim: Claim {
                // Exact but for f32 and the half-float target (steps of 4.9e-4 below
                // 1); overlapping contours in scope since they are drawn from their union
                // (`overlaps=merge`, the default), the bound kept. Last measured
                // (`glyphscope stability --methods winding`): max 0.012 (cubic-loop),
                // MAE 0.05/255 (cubic-cusp).
                bound: Some(within(0.02, 0.1)),
                except: &[Trait::BeyondF32],
                // Where an edge is placed to 1/32 px; last measured (the same command):
                // max 0.025 (glyph-max-size-edge). Set when overlaps, kept, were its
                // cases: three winding levels meeting in a sub-pixel, max 0.111, MAE
                // 0.40/255 (winding-256).
                limitation: Some(within(0.25, 0.6)),
                // Set before the first temporal sweep, equal to the still bound: stricter
                // than that bound implies (|e₁ − e₀| ≤ 2·0.02), because an exact method's
                // error is the same small rounding in consecutive frames, not a sign
                // that flips as the text moves.
                temporal: Some(within(0.02, 0.1)),
                statement: "no pixel off by more than 0.02 where f32 font units resolve \
                            the pixel, overlapping contours drawn from their union, and none \
                            changing between frames 1/16 px apart by more than 0.02 beyond \
                            the reference's change",
            },
        },
        ClaimedSetting {
            label: "winding aa=rays",
            params: &[("aa", "rays")],
            claim: Claim {
                // Last measured (`glyphscope stability --methods 'winding aa=rays'`):
                // max 0.475 (thin-stem). The MAE of a frame that is all edges is the
                // error per edge pixel, 1.14/255 on the bench's page (`glyphscope bench
                // --scenes page`, edge MAE; a
                // frame-wide 0.6/255, from cases with blank space around their edges,
                // broke on the first case of 3 px squares, slanted-ulp-segments: 1.19):
                // 1.14 / 0.8 by the margin rule, rounded up.
                bound: Some(within(0.6, 1.5)),
                except: &[Trait::CrowdedPixels],
                // Last measured (the same stability command): max 0.250 (winding-256,
                // merged), MAE 1.40/255 (glyphs-2px); set when winding-256 was kept as
                // drawn: max 0.717, MAE 6.26/255.
                limitation: Some(within(0.9, 8.0)),
                temporal: None,
                statement: "no pixel off by more than 0.6 where at most 8 edges cross a \
                            pixel; a window crossed by more falls back to its averaged \
                            winding",
            },
        },
    ],
    constructor: Some(&|params| Ok(Box::new(Winding::new(settings_from_params(params)?)))),
};

/// The overlays `winding` draws.
pub const OVERLAYS: &[Overlay] = &[Overlay::CurveClasses, Overlay::CostHeatMap];

/// The parameters `winding` takes.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "aa",
        choices: &["area", "rays"],
        numbers: None,
        help: "area: the exact box-filter integral of the winding number over the pixel, \
               by Green's theorem over each curve, for less than rays with one sample \
               cost; rays: coverage from the crossings of \
               rays through the pixel.",
    },
    ParamSpec {
        key: "rays",
        choices: &["2", "1", "slug"],
        numbers: None,
        help: "Selects aa=rays. 2: rays along x and y, weighted by which sees the edge \
               best; 1: x only (aliases edges near horizontal). 2 costs about twice the \
               curves. slug: x and y rays combined as Slug's published shader does \
               (a one-pixel window per axis, weights from the nearest root), one \
               sample unless samples says otherwise: for comparison.",
    },
    ParamSpec {
        key: "samples",
        choices: &["auto", "1", "4"],
        numbers: None,
        help: "4 sub-pixels tiling the pixel cut small-size error ~4x for ~3.5x the \
               curves; auto uses 4 where a pixel spans over 1/32 em. With aa=area: 4 \
               integrates 4×4 sub-pixels everywhere, 1 never, auto only in the pixels \
               where a curve of overlapping contours meets another.",
    },
    ParamSpec {
        key: "bands",
        choices: &["auto", "off"],
        numbers: Some(Numbers::Whole {
            min: 1,
            max: MAX_BANDS,
        }),
        help: "Bands let a pixel visit only the curves at its height; off visits every \
               curve of the glyph (same image, ~10x the cost).",
    },
    ParamSpec {
        key: "fill",
        choices: &["nonzero", "evenodd"],
        numbers: None,
        help: "Fill rule. Fonts mean nonzero.",
    },
    ParamSpec {
        key: "overlaps",
        choices: &["merge", "keep"],
        numbers: None,
        help: "merge (the default with fill=nonzero): a glyph whose contours overlap is \
               drawn from their nonzero union (geometry::merge_overlaps), so aa=area needs \
               no sub-pixels there; keep (the default with fill=evenodd): from the \
               contours as the font has them.",
    },
    BETWEEN,
    ParamSpec {
        key: "quads",
        choices: &["glyph", "word"],
        numbers: None,
        help: "glyph: a quad per glyph instance over its box; word: each word's letters \
               (instances whose boxes lie less than 0.2 em apart along x) joined into one glyph \
               under one quad (Scene::with_words_joined): fewer, larger quads for a \
               software rasterizer to set up and fill, a glyph's data per distinct word \
               (docs/methods/winding.md, \"A quad per word\").",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "classes", "cost"],
        numbers: None,
        help: "classes: each curve's sign class for the ray through the pixel; cost: \
               curves evaluated per pixel.",
    },
];

/// The curve classes' colours as the class overlay draws them (index: y0 > 0, y1 > 0,
/// y2 > 0 relative to the ray, as bits 0, 1, 2) and which roots each class counts: the
/// legend of the overlay.
pub const CLASS_LEGEND: [([f32; 3], &str); 8] = [
    ([0.35, 0.35, 0.35], "000 below: no root"),
    ([1.0, 0.35, 0.2], "001 t1 (descending)"),
    ([0.75, 0.3, 1.0], "010 both roots"),
    ([1.0, 0.75, 0.1], "011 t1 (descending)"),
    ([0.2, 0.6, 1.0], "100 t2 (ascending)"),
    ([1.0, 0.4, 0.85], "101 both roots"),
    ([0.2, 0.9, 0.7], "110 t2 (ascending)"),
    ([0.7, 0.7, 0.7], "111 above: no root"),
];

/// The settings `params` choose; refused where two parameters contradict each other.
pub fn settings_from_params(params: &Params) -> Result<Settings, Error> {
    let mut s = Settings::default();
    let aa = params.given("aa").and_then(Value::word);
    if aa == Some("rays") {
        s.aa = Antialiasing::Rays;
    }
    if let Some(rays) = params.given("rays").and_then(Value::word) {
        // A ray count asks for rays.
        if aa == Some("area") {
            return Err(Error::Input(format!(
                "winding: rays={rays} does not apply to aa=area, which casts no rays"
            )));
        }
        s.aa = Antialiasing::Rays;
        s.rays = match rays {
            "1" => Rays::X,
            "slug" => {
                // Slug's shader takes one sample per pixel.
                s.samples = 1;
                Rays::Slug
            }
            _ => Rays::XY,
        };
    }
    if let Some(samples) = params.given("samples").and_then(Value::word) {
        s.samples = match samples {
            "1" => 1,
            "4" => 4,
            _ => 0,
        };
    }
    s.even_odd = params.word("fill") == Some("evenodd");
    // Merged unless the fill is even-odd, whose image the nonzero union is not.
    s.merge_overlaps = match params.given("overlaps").and_then(Value::word) {
        Some("merge") if s.even_odd => {
            return Err(Error::Input(
                "winding: overlaps=merge takes the nonzero union, which fill=evenodd \
                 would not draw the same"
                    .into(),
            ));
        }
        Some(overlaps) => overlaps == "merge",
        None => !s.even_odd,
    };
    // Joined unless the fill is even-odd, under which a group's outlines drawn
    // together would cancel where they overlap.
    s.join_instances = match params.given("between").and_then(Value::word) {
        Some("union") if s.even_odd => {
            return Err(Error::Input(
                "winding: between=union draws overlapping instances as one glyph, \
                 which fill=evenodd would empty where they overlap"
                    .into(),
            ));
        }
        Some(between) => between == "union",
        None => !s.even_odd,
    };
    s.join_words = params.word("quads") == Some("word");
    if s.join_words && (s.even_odd || !s.join_instances) {
        return Err(Error::Input(
            "winding: quads=word draws each word as one glyph, whose overlapping ink counts \
             once under the nonzero rule: it takes neither fill=evenodd nor between=add"
                .into(),
        ));
    }
    s.bands = match params.get("bands") {
        Some(Value::Whole(n)) => Some(BandCount::Fixed(n)),
        Some(Value::Word("off")) => None,
        _ => Some(BandCount::Auto),
    };
    s.overlay = params.word("overlay").and_then(Overlay::named);
    Ok(s)
}

impl Method for Winding {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        Winding::prepare(self, gpu, scene)
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        Winding::encode(self, gpu, encoder, target, camera)
    }

    fn gpu_bytes(&self) -> u64 {
        Winding::gpu_bytes(self)
    }

    fn overlays(&self) -> &'static [Overlay] {
        OVERLAYS
    }

    fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        Winding::curves_per_pixel(self, gpu, camera).map(Some)
    }
}
