//! `glyphscope bench --library`: what `glyphscope::text` costs per frame in someone
//! else's app, beside the atlas baseline and glyphon (what people ship) in one run, on
//! the bench's scenes.
//!
//! The library is driven as an app drives it: each frame its runs are prepared and
//! composited in a pass, white text over black, into the bench's coverage target. Two
//! ways: text *still* (the same runs as the last frame's: nothing uploaded or drawn but
//! the composite, as in an app whose text does not move) and text *moving* (the run
//! shifted by 1/64 px every other frame: its coverage drawn anew each frame, what the
//! `winding` row does every frame). Premultiplied white over black is the coverage
//! itself, where premultiplied white over black is the coverage itself
//! (so its error is measured as every method's is). The `winding` row, the same shader
//! drawing coverage, is timed beside it: the difference is the library's own harness.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use glam::{DMat3, DVec3, Mat3};

use super::method_settings::baseline_cache_param;
use super::side_run::{SideRun, write_report};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::methods::atlas::{self, auto_cache_size};
use crate::methods::peers::glyphon;
use crate::methods::winding;
use crate::methods::{Method, frame};
use crate::metrics;
use crate::reference;
use crate::scene::Scene;
use crate::text::{Content, FontId, PositionedGlyph, TextRenderer, TextRun};

/// The scenes measured when none are named: the page, and six of its lines turned and
/// tilted (which glyphon cannot draw: it is `n/a` there).
pub const DEFAULT_SCENES: &[&str] = &["page", "rotated"];

/// `glyphscope::text` as a method: the scene's glyphs as one run, placed by the camera.
struct Library {
    /// Shift the run a little every other frame, so that each frame draws coverage.
    moving: bool,
    frame: u64,
    text: Option<(TextRenderer, FontId)>,
    glyphs: Vec<PositionedGlyph>,
    font: Option<crate::font::Font>,
    units_per_em: f64,
}

impl Library {
    fn new(moving: bool) -> Library {
        Library {
            moving,
            frame: 0,
            text: None,
            glyphs: Vec::new(),
            font: None,
            units_per_em: 1.0,
        }
    }
}

impl Method for Library {
    fn name(&self) -> &'static str {
        if self.moving { MOVING } else { STILL }
    }

    fn prepare(&mut self, _gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        let source = scene.source.as_ref().ok_or_else(|| {
            Error::Refused("the library draws fonts' glyphs, not synthetic outlines".into())
        })?;
        // Text space in font units (a run of size units_per_em), y down.
        self.glyphs = scene
            .instances
            .iter()
            .map(|i| PositionedGlyph {
                id: scene.glyphs[i.glyph as usize].id,
                x: i.position.x as f32,
                y: -i.position.y as f32,
            })
            .collect();
        self.font = Some(source.font.clone());
        self.units_per_em = scene.units_per_em;
        self.text = None;
        Ok(())
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let (text, font) = match &mut self.text {
            Some(text) => text,
            none => {
                let mut text = TextRenderer::new(&gpu.device, &gpu.queue, target.channels.format());
                let font = self
                    .font
                    .clone()
                    .ok_or_else(|| Error::Internal("not prepared".into()))?;
                let id = text.add_parsed_font(font);
                none.insert((text, id))
            }
        };
        // The camera's map of glyph space, from the run's text space (font units, y
        // down): flip y back.
        self.frame += 1;
        let shift = if self.moving && self.frame % 2 == 1 {
            1.0 / 64.0
        } else {
            0.0
        };
        let to_image = DMat3::from_translation(glam::DVec2::new(shift, 0.0))
            * camera.glyph_to_image(self.units_per_em, glam::DVec2::ZERO)
            * DMat3::from_cols(DVec3::X, -DVec3::Y, DVec3::Z);
        let run = TextRun {
            font: *font,
            content: Content::Glyphs(&self.glyphs),
            size_px: self.units_per_em as f32,
            transform: Mat3::from_cols_array(&to_image.to_cols_array().map(|v| v as f32)),
            color: [1.0; 4],
        };
        text.prepare(encoder, [camera.width, camera.height], &[run])?;
        let mut pass = target.clearing_pass(encoder, "glyphscope::text");
        text.render(&mut pass);
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        0
    }
}

const STILL: &str = "glyphscope::text, text still";
const MOVING: &str = "glyphscope::text, text moving";

/// How a case's method is made, anew in each round.
type MakeMethod = Box<dyn Fn() -> Result<Box<dyn Method>, Error>>;

/// One case measured.
struct Timed {
    name: &'static str,
    gpu_ms: f64,
    cpu_ms: f64,
    error: Option<metrics::ErrorStats>,
    refused: Option<String>,
}

/// Times the library, the `winding` row, the atlas and glyphon on `scene_names` (their
/// own views), interleaved in rounds; writes `library.md` into `out` and returns its
/// path.
pub fn run_to(
    scene_names: &[String],
    quick: bool,
    frames: Option<usize>,
    adapter: Option<&str>,
    out: &Path,
) -> Result<PathBuf, Error> {
    let SideRun {
        scenes: bench_scenes,
        timing,
        gpu,
        scenes_flag,
    } = SideRun::open(
        scene_names,
        DEFAULT_SCENES,
        quick,
        frames,
        adapter,
        "the library's frames are timed by them",
    )?;
    let mut md = format!(
        "# The library's frame\n\n\
         Device: **{}**. `glyphscope bench --library{}{}`: `glyphscope::text` as an app \
         drives it (runs prepared and drawn every frame), the `winding` row (the same \
         shader, glyphscope's own harness), the atlas baseline and glyphon, each prepared \
         anew in each of {} rounds, its frames timed after {} warm-up frames; the median \
         of the rounds' medians. *GPU ms*: timestamps around the frame; *CPU ms*: \
         recording it (for the library: `prepare` and `render`). *× atlas*, *× glyphon*: \
         GPU + CPU per frame over theirs in the same run. Error against the reference.\n",
        gpu.adapter_name(),
        if quick { " --quick" } else { "" },
        scenes_flag,
        timing.rounds,
        timing.per_round.warmup,
    );
    for bench_scene in &bench_scenes {
        let (scene, camera) = bench_scene.args.build()?;
        let cache = [baseline_cache_param(auto_cache_size(camera.size_px_per_em))];
        let make: [(&'static str, MakeMethod); 5] = [
            (
                STILL,
                Box::new(|| Ok(Box::new(Library::new(false)) as Box<dyn Method>)),
            ),
            (
                MOVING,
                Box::new(|| Ok(Box::new(Library::new(true)) as Box<dyn Method>)),
            ),
            ("winding", Box::new(|| winding::INFO.create(&[]))),
            ("atlas", Box::new(move || atlas::INFO.create(&cache))),
            ("glyphon", Box::new(|| glyphon::INFO.create(&[]))),
        ];
        let target = CoverageTarget::new(&gpu, camera.width, camera.height, Channels::Coverage)?;
        let expected = reference::rasterize(&scene, &camera)?;
        let mut cases: Vec<(Timed, Vec<f64>, Vec<f64>)> = make
            .iter()
            .map(|(name, _)| {
                let timed = Timed {
                    name,
                    gpu_ms: f64::NAN,
                    cpu_ms: f64::NAN,
                    error: None,
                    refused: None,
                };
                (timed, Vec::new(), Vec::new())
            })
            .collect();
        for _ in 0..timing.rounds {
            for ((_, create), (timed, gpu_ms, cpu_ms)) in make.iter().zip(&mut cases) {
                if timed.refused.is_some() {
                    continue;
                }
                let mut method = create()?;
                let drawn = method.prepare(&gpu, &scene).and_then(|()| {
                    let per_round = timing.per_round;
                    frame::time_frames(
                        &gpu,
                        method.as_mut(),
                        &target,
                        &camera,
                        per_round.warmup,
                        per_round.frames,
                    )
                });
                match drawn {
                    Ok(times) => {
                        let times = times.expect("the device has timestamps: checked above");
                        gpu_ms.extend(metrics::median(times.iter().map(|t| t.gpu_ms)));
                        cpu_ms.extend(metrics::median(times.iter().map(|t| t.cpu_ms)));
                        // The moving run is 1/64 px off the view on every other frame.
                        if timed.error.is_none() && timed.name != MOVING {
                            let image = frame::render_image(&gpu, method.as_mut(), &camera)?;
                            timed.error =
                                Some(metrics::compare(&image.clamp_to_union(), &expected)?);
                        }
                    }
                    Err(Error::Refused(reason)) => timed.refused = Some(reason),
                    Err(e) => return Err(e),
                }
            }
        }
        let median = |v: &[f64]| metrics::median(v.iter().copied()).unwrap_or(f64::NAN);
        let timed: Vec<Timed> = cases
            .into_iter()
            .map(|(timed, gpu_ms, cpu_ms)| Timed {
                gpu_ms: median(&gpu_ms),
                cpu_ms: median(&cpu_ms),
                ..timed
            })
            .collect();
        write_scene(&mut md, bench_scene.name, &timed);
    }
    write_report(out, "library.md", &md)
}

/// One scene's table.
fn write_scene(md: &mut String, name: &str, timed: &[Timed]) {
    let frame_of = |case: &str| {
        timed
            .iter()
            .find(|t| t.name == case && t.refused.is_none())
            .map(|t| t.gpu_ms + t.cpu_ms)
    };
    let (atlas, glyphon) = (frame_of("atlas"), frame_of("glyphon"));
    let _ = writeln!(
        md,
        "\n## {name}\n\n`glyphscope render --case {name}`\n\n\
         | method | GPU ms | CPU ms | × atlas | × glyphon | MAE /255 | edge MAE /255 | max |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|"
    );
    for t in timed {
        if let Some(reason) = &t.refused {
            let _ = writeln!(md, "| {} | n/a — {reason} | | | | | | |", t.name);
            continue;
        }
        let ratio = |of: Option<f64>| {
            of.map_or("n/a".into(), |o| {
                format!("{:.2}", (t.gpu_ms + t.cpu_ms) / o)
            })
        };
        let (mae, edge, max) =
            t.error
                .as_ref()
                .map_or(("—".into(), "—".into(), "—".into()), |e| {
                    (
                        format!("{:.2}", e.mae_255),
                        format!("{:.2}", e.edge.mae_255),
                        format!("{:.3}", e.max),
                    )
                });
        let _ = writeln!(
            md,
            "| {} | {:.2} | {:.3} | {} | {} | {mae} | {edge} | {max} |",
            t.name,
            t.gpu_ms,
            t.cpu_ms,
            ratio(atlas),
            ratio(glyphon),
        );
    }
}
