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

use crate::intervals::paired_ratio;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use glam::{DMat3, DVec3, Mat3};

use super::method_settings::{SHIPPED, baseline_cache_param};
use super::result::Rounds;
use super::side_run::{SideRun, time_round, write_report};
use super::ui;
use crate::Error;
use crate::camera::Camera;
use crate::effort::Effort;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::methods::atlas::{self, auto_cache_size};
use crate::methods::registry;
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
        let font = self
            .font
            .as_ref()
            .ok_or_else(|| Error::Internal("not prepared".into()))?;
        let (text, font) = renderer_made(&mut self.text, gpu, target, font, winding::Stage::Full);
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

/// The renderer in `slot`, made on first use for `target`'s format with `font` added,
/// its coverage shader cut after `stage` (`Stage::Full`: the whole shader, as shipped).
fn renderer_made<'a>(
    slot: &'a mut Option<(TextRenderer, FontId)>,
    gpu: &GpuContext,
    target: &CoverageTarget,
    font: &crate::font::Font,
    stage: winding::Stage,
) -> &'a mut (TextRenderer, FontId) {
    slot.get_or_insert_with(|| {
        let mut text =
            TextRenderer::new(&gpu.device, &gpu.queue, target.channels.format()).cut_after(stage);
        let id = text.add_parsed_font(font.clone());
        (text, id)
    })
}

/// `glyphscope::text` as an app draws a UI with it: a run per label, prepared and
/// rendered every frame, then trimmed (the `ui` scene). Moving, the labels scroll down
/// by 0.37 px a frame.
struct LibraryLabels {
    font: crate::font::Font,
    labels: std::sync::Arc<Vec<ui::Label>>,
    moving: bool,
    /// Where its coverage shader stops (the breakdown of a moving frame), and its name.
    stage: winding::Stage,
    name: &'static str,
    frame: u64,
    text: Option<(TextRenderer, FontId)>,
}

impl Method for LibraryLabels {
    fn name(&self) -> &'static str {
        self.name
    }

    fn prepare(&mut self, _gpu: &GpuContext, _scene: &Scene) -> Result<(), Error> {
        self.text = None;
        Ok(())
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        _camera: &Camera,
    ) -> Result<(), Error> {
        let (text, font) = renderer_made(&mut self.text, gpu, target, &self.font, self.stage);
        self.frame += 1;
        let scroll = if self.moving {
            0.37 * self.frame as f32
        } else {
            0.0
        };
        let runs: Vec<TextRun<'_>> = self
            .labels
            .iter()
            .map(|label| TextRun {
                font: *font,
                content: Content::Text(&label.text),
                size_px: label.size_px,
                transform: Mat3::from_translation(glam::vec2(label.x, label.y + scroll)),
                color: [1.0; 4],
            })
            .collect();
        text.prepare(encoder, [target.width, target.height], &runs)?;
        let mut pass = target.clearing_pass(encoder, "glyphscope::text");
        text.render(&mut pass);
        drop(pass);
        text.trim();
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        self.text
            .as_ref()
            .map_or(0, |(text, _)| text.held().total())
    }
}

const UI_STILL: &str = "glyphscope::text, labels still";
const UI_MOVING: &str = "glyphscope::text, labels moving";

const STILL: &str = "glyphscope::text, text still";
const MOVING: &str = "glyphscope::text, text moving";

/// How a case's method is made, anew in each round.
type MakeMethod = Box<dyn Fn() -> Result<Box<dyn Method>, Error>>;

/// A case: its name, whether its text moves (its error is not measured: a moving
/// frame is not the reference's view), the glyphon case it is compared with, and how
/// it is made.
struct Case {
    name: &'static str,
    moving: bool,
    glyphon: &'static str,
    make: MakeMethod,
}

impl Case {
    fn new(name: &'static str, moving: bool, glyphon: &'static str, make: MakeMethod) -> Case {
        Case {
            name,
            moving,
            glyphon,
            make,
        }
    }
}

/// One case measured.
struct Timed {
    name: &'static str,
    glyphon: &'static str,
    gpu_ms: f64,
    cpu_ms: f64,
    error: Option<metrics::ErrorStats>,
    refused: Option<String>,
    /// What it held on the GPU after its frames, where it can say.
    held_bytes: Option<u64>,
    /// Its GPU + CPU frame in each round (None where it was not timed), so that its
    /// ratio to another case is taken round by round.
    rounds: Vec<Option<f64>>,
}

/// The scene of a UI's labels (`bench::ui`): timed with `--scenes ui`.
pub const UI_SCENE: &str = "ui";

/// Times the library, the `winding` row, the atlas and glyphon on `scene_names` (their
/// own views), and on `ui` the library and glyphon drawing a UI's labels, interleaved
/// in rounds; writes `library.md` into `out` and returns its path.
pub fn run_to(
    scene_names: &[String],
    effort: &Effort,
    frames: Option<usize>,
    adapter: Option<&str>,
    out: &Path,
) -> Result<PathBuf, Error> {
    let ui_named = scene_names.iter().any(|n| n == UI_SCENE);
    let others: Vec<String> = scene_names
        .iter()
        .filter(|n| *n != UI_SCENE)
        .cloned()
        .collect();
    let defaults: &[&str] = if ui_named { &[] } else { DEFAULT_SCENES };
    let SideRun {
        scenes: bench_scenes,
        timing,
        gpu,
        ..
    } = SideRun::open(
        &others,
        defaults,
        effort,
        frames,
        adapter,
        "the library's frames are timed by them",
    )?;
    let scenes_flag = if scene_names.is_empty() {
        String::new()
    } else {
        format!(" --scenes {}", scene_names.join(","))
    };
    let cap_s = effort.bench_settle_cap_s;
    let mut md = format!(
        "# The library's frame\n\n\
         Device: **{}**. `glyphscope bench --library{}{}`: `glyphscope::text` as an app \
         drives it (runs prepared and drawn every frame), the `winding` row (the same \
         shader, glyphscope's own harness), the atlas baseline and glyphon, each prepared \
         anew in each round, at least {} rounds and more until every ratio below is settled \
         (its 95 % interval within ±5 %) or {} s have gone by for the scene, its frames \
         timed after {} warm-up frames; the median of the rounds' medians. *GPU ms*: timestamps around the frame; *CPU ms*: \
         recording it (for the library: `prepare` and `render`). *× atlas*, *× glyphon*: \
         GPU + CPU per frame over theirs, round by round (the median over the rounds of \
         the two frames' ratio in the same round), with its 95 % interval, a bootstrap \
         over the rounds (`*`: wider than ±5 % when the time was up). Error against the \
         reference.\n",
        gpu.adapter_name(),
        effort.flag,
        scenes_flag,
        timing.rounds,
        cap_s,
        timing.per_round.warmup,
    );
    for bench_scene in &bench_scenes {
        let (scene, camera) = bench_scene.args.build()?;
        let cache = [baseline_cache_param(auto_cache_size(camera.size_px_per_em))];
        let cases = [
            Case::new(
                STILL,
                false,
                SHIPPED,
                Box::new(|| Ok(Box::new(Library::new(false)) as Box<dyn Method>)),
            ),
            Case::new(
                MOVING,
                true,
                SHIPPED,
                Box::new(|| Ok(Box::new(Library::new(true)) as Box<dyn Method>)),
            ),
            Case::new(
                "winding",
                false,
                SHIPPED,
                Box::new(|| winding::INFO.create(&[])),
            ),
            Case::new(
                "atlas",
                false,
                SHIPPED,
                Box::new(move || atlas::INFO.create(&cache)),
            ),
            Case::new(
                SHIPPED,
                false,
                SHIPPED,
                Box::new(|| registry::create(SHIPPED, &[])),
            ),
        ];
        let timed = measure(&gpu, &timing, cap_s, &scene, &camera, &cases)?;
        let heading = format!(
            "\n## {}\n\n`glyphscope render --case {}`\n",
            bench_scene.name, bench_scene.name
        );
        write_scene(&mut md, &heading, &timed, false);
    }
    if ui_named {
        let timed = measure_ui(&gpu, &timing, cap_s)?;
        let heading = format!(
            "\n## ui\n\n{} labels of {}–{} px in rows over {}×{} (`bench::ui`, the \
             labels `examples/ui_labels.rs` draws), a run (a glyphon buffer) per label, \
             prepared, rendered and trimmed every frame; *moving*: scrolled by 0.37 px a \
             frame. × glyphon: over glyphon's frame with its labels still or moving alike. \
             *GPU MB held*: `TextRenderer::held` for the library, `gpu_bytes` for the atlas \
             (its texture and buffers); glyphon's atlas is not in its API (see the \
             example's memory figures in docs/library.md).\n",
            ui::LABELS,
            10,
            32,
            ui::SIZE[0],
            ui::SIZE[1],
        );
        write_scene(&mut md, &heading, &timed, true);
        write_stages(&mut md, &timed);
    }
    write_report(out, "library.md", &md)
}

/// The `ui` scene's cases: the library and glyphon drawing the labels still and
/// moving, and the atlas drawing them still.
fn measure_ui(gpu: &GpuContext, timing: &Rounds, cap_s: f64) -> Result<Vec<Timed>, Error> {
    let font = crate::font::default_font();
    let labels = std::sync::Arc::new(ui::labels(&font, ui::LABELS, ui::SIZE)?);
    if ui::any_overlap(&font, &labels)? {
        return Err(Error::Internal(
            "the ui scene's labels overlap: its reference would not be theirs".into(),
        ));
    }
    let scene = ui::scene(&font, &labels)?;
    let camera = ui::camera();
    let cache = [baseline_cache_param(auto_cache_size(camera.size_px_per_em))];
    let library = |moving, stage, name| -> MakeMethod {
        let (font, labels) = (font.clone(), labels.clone());
        Box::new(move || {
            Ok(Box::new(LibraryLabels {
                font: font.clone(),
                labels: labels.clone(),
                moving,
                stage,
                name,
                frame: 0,
                text: None,
            }) as Box<dyn Method>)
        })
    };
    let glyphon = |moving| -> MakeMethod {
        let font = font.clone();
        let labels: Vec<_> = labels
            .iter()
            .map(|l| (l.text.clone(), l.size_px, l.x, l.y))
            .collect();
        Box::new(move || {
            #[cfg(feature = "glyphon")]
            {
                // A peer behind the net, as every row the registry makes.
                Ok(crate::methods::guarded::Guarded::wrap(Box::new(
                    crate::methods::peers::glyphon::GlyphonLabels::new(
                        font.clone(),
                        labels.clone(),
                        moving,
                    ),
                )))
            }
            #[cfg(not(feature = "glyphon"))]
            {
                let _ = (&font, &labels, moving);
                registry::create(SHIPPED, &[])
            }
        })
    };
    const GLYPHON_STILL: &str = "glyphon, labels still";
    const GLYPHON_MOVING: &str = "glyphon, labels moving";
    let full = winding::Stage::Full;
    let mut cases = vec![
        Case::new(
            UI_STILL,
            false,
            GLYPHON_STILL,
            library(false, full, UI_STILL),
        ),
        Case::new(
            UI_MOVING,
            true,
            GLYPHON_MOVING,
            library(true, full, UI_MOVING),
        ),
        Case::new(
            "atlas",
            false,
            GLYPHON_STILL,
            Box::new(move || atlas::INFO.create(&cache)),
        ),
        Case::new(GLYPHON_STILL, false, GLYPHON_STILL, glyphon(false)),
        Case::new(GLYPHON_MOVING, true, GLYPHON_MOVING, glyphon(true)),
    ];
    // The moving frame with the coverage shader cut short after each stage but the
    // last (the full one is UI_MOVING): where its time goes.
    for (stage, name) in winding::Stage::ALL.iter().zip(UI_CUT) {
        cases.push(Case::new(
            name,
            true,
            GLYPHON_MOVING,
            library(true, *stage, name),
        ));
    }
    measure(gpu, timing, cap_s, &scene, &camera, &cases)
}

/// The moving labels with the coverage shader cut after each of `winding::Stage::ALL`
/// but the last.
const UI_CUT: [&str; 4] = [
    "labels moving, shader cut after its quads",
    "labels moving, cut after its setup",
    "labels moving, cut after its walk",
    "labels moving, cut after its right terms",
];

/// Where a moving frame of the labels goes: the still frame (the composite and the
/// runs' comparison), then each stage of the coverage pass, each the difference from
/// the one before, from the cut cases `measure_ui` timed.
fn write_stages(md: &mut String, timed: &[Timed]) {
    let frame_of = |name: &str| {
        timed
            .iter()
            .find(|t| t.name == name && t.refused.is_none())
            .map(|t| t.gpu_ms + t.cpu_ms)
    };
    let mut steps = vec![(
        "the still frame: composite and comparison",
        frame_of(UI_STILL),
    )];
    let parts = [
        "quads: rasterizing, the pages cleared and blended, the instances' upload",
        "setup: derivatives, the pixel's frame, its band",
        "walk: each entry of the band (its curve's ends) loaded, mapped, sorted into its zone",
        "right: the terms of curves wholly right of the pixel",
    ];
    for (part, name) in parts.iter().zip(UI_CUT) {
        steps.push((part, frame_of(name)));
    }
    steps.push((
        "across: the curves across the pixel loaded whole and integrated, the fill",
        frame_of(UI_MOVING),
    ));
    let _ = writeln!(
        md,
        "\nWhere a moving frame of the labels goes (GPU + CPU ms, each stage the difference \
         from the row above: the frame with the coverage shader cut short after it, \
         `STAGE` in crates/text/shaders/winding.wgsl):\n\n| part | ms | share |\n|---|---:|---:|"
    );
    let total = frame_of(UI_MOVING).unwrap_or(f64::NAN);
    let mut before = 0.0;
    for (part, ms) in steps {
        let Some(ms) = ms else { continue };
        let step = ms - before;
        let _ = writeln!(md, "| {part} | {step:.2} | {:.0} % |", 100.0 * step / total);
        before = ms;
    }
}

/// Times `cases` on `scene` through `camera`, interleaved in rounds, each prepared anew
/// in each round: `timing.rounds` at least, then more until every ratio to the atlas
/// and to glyphon is settled (`intervals::TARGET`) or `cap_s` seconds have gone by
/// since the first; the error of each still case against the reference.
fn measure(
    gpu: &GpuContext,
    timing: &Rounds,
    cap_s: f64,
    scene: &Scene,
    camera: &Camera,
    cases: &[Case],
) -> Result<Vec<Timed>, Error> {
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)?;
    let expected = reference::rasterize(scene, camera)?;
    let mut timed: Vec<(Timed, Vec<f64>, Vec<f64>)> = cases
        .iter()
        .map(|case| {
            let timed = Timed {
                name: case.name,
                glyphon: case.glyphon,
                gpu_ms: f64::NAN,
                cpu_ms: f64::NAN,
                error: None,
                refused: None,
                held_bytes: None,
                rounds: Vec::new(),
            };
            (timed, Vec::new(), Vec::new())
        })
        .collect();
    let started = std::time::Instant::now();
    let mut round = 0;
    loop {
        let done = round >= timing.rounds
            && (started.elapsed().as_secs_f64() > cap_s
                || all_settled(timed.iter().map(|(t, _, _)| t)));
        if done {
            break;
        }
        round += 1;
        for (case, (timed, gpu_ms, cpu_ms)) in cases.iter().zip(&mut timed) {
            if timed.refused.is_some() {
                timed.rounds.push(None);
                continue;
            }
            let mut method = (case.make)()?;
            match time_round(gpu, timing, method.as_mut(), scene, &target, camera)? {
                Ok((gpu_median, cpu_median)) => {
                    gpu_ms.push(gpu_median);
                    cpu_ms.push(cpu_median);
                    timed.rounds.push(Some(gpu_median + cpu_median));
                    timed.held_bytes = Some(method.gpu_bytes());
                    if timed.error.is_none() && !case.moving {
                        let image = frame::render_image(gpu, method.as_mut(), camera)?;
                        timed.error = Some(metrics::compare(&image.clamp_to_union(), &expected)?);
                    }
                }
                Err(reason) => {
                    timed.refused = Some(reason);
                    timed.rounds.push(None);
                }
            }
        }
    }
    let median = |v: &[f64]| metrics::median(v.iter().copied()).unwrap_or(f64::NAN);
    Ok(timed
        .into_iter()
        .map(|(timed, gpu_ms, cpu_ms)| Timed {
            gpu_ms: median(&gpu_ms),
            cpu_ms: median(&cpu_ms),
            ..timed
        })
        .collect())
}

/// Whether every case's ratio to the atlas and to its glyphon case, where both were
/// timed, is settled: a ratio with a figure that is not a number has no interval and
/// is not.
fn all_settled<'a>(timed: impl Iterator<Item = &'a Timed> + Clone) -> bool {
    let find = |name: &str| {
        timed
            .clone()
            .find(|t| t.name == name && t.refused.is_none())
    };
    timed.clone().filter(|t| t.refused.is_none()).all(|t| {
        ["atlas", t.glyphon]
            .into_iter()
            .filter(|&over| over != t.name)
            .filter_map(find)
            .all(|over| paired_ratio(&t.rounds, &over.rounds).is_some_and(|r| r.settled))
    })
}

/// One scene's table, under `heading`; with `memory`, what each case held.
fn write_scene(md: &mut String, heading: &str, timed: &[Timed], memory: bool) {
    let case_named = |name: &str| timed.iter().find(|t| t.name == name && t.refused.is_none());
    let atlas = case_named("atlas");
    let (memory_head, memory_rule) = if memory {
        (" GPU MB held |", "---:|")
    } else {
        ("", "")
    };
    let _ = writeln!(
        md,
        "{heading}\n\
         | method | GPU ms | CPU ms | × atlas | × glyphon | MAE /255 | edge MAE /255 | max |{memory_head}\n\
         |---|---:|---:|---:|---:|---:|---:|---:|{memory_rule}"
    );
    for t in timed {
        if let Some(reason) = &t.refused {
            let _ = writeln!(md, "| {} | n/a — {reason} | | | | | | |", t.name);
            continue;
        }
        // Paired round by round, with its 95 % interval (`*`: wider than ±5 %).
        let ratio = |of: Option<&Timed>| {
            of.and_then(|o| paired_ratio(&t.rounds, &o.rounds))
                .map_or("n/a".into(), |r| r.cell(2))
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
        let held = match (memory, t.held_bytes) {
            (false, _) => String::new(),
            (true, Some(bytes)) if !t.name.starts_with("glyphon") => {
                format!(" {:.1} |", bytes as f64 / 1e6)
            }
            (true, _) => " — |".into(),
        };
        let _ = writeln!(
            md,
            "| {} | {:.2} | {:.3} | {} | {} | {mae} | {edge} | {max} |{held}",
            t.name,
            t.gpu_ms,
            t.cpu_ms,
            ratio(atlas),
            ratio(case_named(t.glyphon)),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::{Timed, all_settled};

    fn timed(name: &'static str, rounds: &[f64]) -> Timed {
        Timed {
            name,
            glyphon: "glyphon",
            gpu_ms: f64::NAN,
            cpu_ms: f64::NAN,
            error: None,
            refused: None,
            held_bytes: None,
            rounds: rounds.iter().map(|&ms| Some(ms)).collect(),
        }
    }

    /// Ratios steady round by round are settled even where the frames drift (the
    /// machine slowing every case of a round alike); one that jumps between rounds is
    /// not; a refused case holds nothing up.
    #[test]
    fn settled_means_every_paired_ratio_within_the_target() {
        let drift = [10.0, 12.0, 9.0, 11.0, 10.5];
        let atlas = timed("atlas", &drift);
        let glyphon = timed("glyphon", &drift.map(|ms| 0.5 * ms));
        let steady = timed("steady", &drift.map(|ms| 2.0 * ms));
        assert!(all_settled([&atlas, &glyphon, &steady].into_iter()));
        let jumpy = timed("jumpy", &[20.0, 36.0, 14.0, 30.0, 17.0]);
        assert!(!all_settled([&atlas, &glyphon, &jumpy].into_iter()));
        let mut refused = timed("refused", &[1.0, 90.0, 3.0, 50.0, 7.0]);
        refused.refused = Some("n/a".into());
        assert!(all_settled(
            [&atlas, &glyphon, &steady, &refused].into_iter()
        ));
        // A figure that is not a number never counts as settled.
        let broken = timed("broken", &[20.0, f64::NAN, 18.0, 22.0, 21.0]);
        assert!(!all_settled([&atlas, &glyphon, &broken].into_iter()));
    }
}
