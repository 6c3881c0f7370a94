//! The measurements behind docs/methods/sdf-cells.md: exact mode's error per font,
//! size and transform; the estimate's artifacts glyph by glyph; overlapping contours in
//! Inter; estimate vs exact on the standard page (error, curves per pixel, GPU time).
//!
//!     cargo run --release --example sdf_cells_report [-- page]
//!
//! With `page`, only the page is measured.

use std::collections::BTreeMap;

use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::font::{Font, GlyphId, SHIPPED_FONTS};
use glyphscope::geometry::DEFAULT_QUAD_TOLERANCE_EM;
use glyphscope::gpu::{Channels, CoverageTarget, GpuContext};
use glyphscope::methods::frame::{FrameTime, render_frame, time_frames};
use glyphscope::methods::{Method, registry};

/// Owned `--param` pairs.
type Params = Vec<(String, String)>;
use glyphscope::methods::sdf_cells::{self, SdfCells};
use glyphscope::metrics::{self, ErrorStats, compare};
use glyphscope::reference;
use glyphscope::scene::Scene;

/// The glyphs measured: what each font's text shapes into.
const TEXTS: [&str; 4] = [
    "Hamburgefonstiv&@gQ§8",
    "Hamburgefonstiv&@gQ§8",
    "Hamburgefonstiv&@gQ§8",
    "\u{0995}\u{09CD}\u{09B7} \u{0999}\u{09CD}\u{0995} \u{09AC}\u{09BE}\u{0982}\u{09B2}\u{09BE} \u{09B6}\u{09CD}\u{09B0}\u{09C0}",
];
const SIZES: [f64; 3] = [16.0, 48.0, 400.0];

/// (name, matrix rows, sub-pixel offset of the origin).
fn transforms() -> [(&'static str, [f64; 4], DVec2); 3] {
    let (s30, c30) = 30f64.to_radians().sin_cos();
    let (s75, c75) = (-75f64).to_radians().sin_cos();
    [
        ("upright", [1.0, 0.0, 0.0, 1.0], DVec2::new(0.37, 0.61)),
        ("rotated 30°", [c30, -s30, s30, c30], DVec2::new(0.11, 0.83)),
        (
            "rotated −75°, skewed",
            [c75, c75 * 0.25 - s75, s75, s75 * 0.25 + c75],
            DVec2::new(0.5, 0.25),
        ),
    ]
}

fn params(pairs: &[(&str, &str)]) -> Params {
    pairs
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

/// A camera framing one glyph at `size` under `matrix`, the origin shifted by `shift`.
fn frame(scene: &Scene, size: f64, matrix: [f64; 4], shift: DVec2) -> Camera {
    let mut camera = Camera::new(1, 1, size, DVec2::ZERO);
    camera.matrix = Camera::matrix_from_rows(matrix[0], matrix[1], matrix[2], matrix[3]);
    let to_image = camera.glyph_to_image(scene.units_per_em, DVec2::ZERO);
    let ink = Camera::project_bounds(&to_image, &scene.glyphs[0].bounds).expect("no tilt");
    camera.origin = DVec2::splat(3.0) - ink.min.floor() + shift;
    camera.width = (ink.size().x.ceil() + 7.0) as u32;
    camera.height = (ink.size().y.ceil() + 7.0) as u32;
    camera
}

fn error_of(gpu: &GpuContext, method: &mut SdfCells, scene: &Scene, camera: &Camera) -> ErrorStats {
    method.prepare(gpu, scene).expect("prepares");
    let target =
        CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage).expect("target");
    render_frame(gpu, method, &target, camera).expect("renders");
    let image = target.readback(gpu).expect("reads back");
    compare(
        &image,
        &reference::rasterize(scene, camera).expect("reference"),
    )
    .expect("same size")
}

/// Worst figures over several renders.
#[derive(Default)]
struct Worst {
    max: f64,
    mae_255: f64,
    over_025: usize,
    over_05: usize,
    renders: usize,
}

impl Worst {
    fn add(&mut self, e: &ErrorStats) {
        self.max = self.max.max(e.max);
        self.mae_255 = self.mae_255.max(e.mae_255);
        self.over_025 += e.pixels_over_025;
        self.over_05 += e.pixels_over_05;
        self.renders += 1;
    }
}

fn glyphs(font: &Font, text: &str) -> Vec<GlyphId> {
    Scene::from_text(font, text)
        .expect("shapes")
        .glyphs
        .iter()
        .map(|g| g.id)
        .collect()
}

fn glyphs_report(gpu: &GpuContext) {
    let sdf_cells = |pairs| SdfCells::new(&sdf_cells::INFO.parse_params(&params(pairs)).unwrap());
    let mut estimate = sdf_cells(&[("mode", "estimate")]);
    let mut exact = sdf_cells(&[("mode", "exact")]);
    println!("## Exact mode: worst pixel per font, size and transform\n");
    println!("Glyphs without overlapping contours; overlapping ones in their own rows.\n");
    println!(
        "| font | glyphs | size | transform | max error | worst MAE (/255) | px > 0.25 | px > 0.5 |"
    );
    println!("|---|---:|---:|---|---:|---:|---:|---:|");
    // (font, glyph) → pixels over 0.5 and 0.25 in estimate mode, per size.
    let mut artifacts: BTreeMap<(usize, GlyphId), [(usize, usize); 3]> = BTreeMap::new();
    let mut overlap_rows = Vec::new();
    for (index, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        let ids = glyphs(&font, TEXTS[index]);
        let tolerance = DEFAULT_QUAD_TOLERANCE_EM * font.units_per_em();
        let overlapping: Vec<bool> = ids
            .iter()
            .map(|&id| reference::overlapping_contours(&font.outline(id).to_quadratics(tolerance)))
            .collect();
        for (s, &size) in SIZES.iter().enumerate() {
            for (what, matrix, shift) in transforms() {
                let (mut clean, mut overlaps) = (Worst::default(), Worst::default());
                for (&id, &overlap) in ids.iter().zip(&overlapping) {
                    let scene = Scene::from_glyph_id(&font, u32::from(id)).unwrap();
                    let camera = frame(&scene, size, matrix, shift);
                    let e = error_of(gpu, &mut exact, &scene, &camera);
                    if overlap { &mut overlaps } else { &mut clean }.add(&e);
                    let a = error_of(gpu, &mut estimate, &scene, &camera);
                    let entry = artifacts.entry((index, id)).or_default();
                    entry[s].0 += a.pixels_over_05;
                    entry[s].1 += a.pixels_over_025;
                }
                let row = |w: &Worst, label: &str| {
                    format!(
                        "| {name}{label} | {} | {size} | {what} | {:.3} | {:.2} | {} | {} |",
                        w.renders, w.max, w.mae_255, w.over_025, w.over_05
                    )
                };
                println!("{}", row(&clean, ""));
                if overlaps.renders > 0 {
                    overlap_rows.push(row(&overlaps, " (overlapping)"));
                }
            }
        }
    }
    for row in overlap_rows {
        println!("{row}");
    }
    println!("\n## Estimate mode: glyphs with pixels off by more than 0.5\n");
    println!("Summed over the three transforms; (> 0.25 in brackets).\n");
    println!("| font | glyph | 16 px | 48 px | 400 px |");
    println!("|---|---|---:|---:|---:|");
    let mut clean_glyphs = Vec::new();
    for ((index, id), counts) in &artifacts {
        let font = glyphscope::font::shipped(*index);
        let label = glyph_label(&font, *id, TEXTS[*index]);
        if counts.iter().all(|c| c.0 == 0) {
            clean_glyphs.push(format!("{} {label}", SHIPPED_FONTS[*index].0));
            continue;
        }
        let cells: Vec<String> = counts
            .iter()
            .map(|c| format!("{} ({})", c.0, c.1))
            .collect();
        println!(
            "| {} | {label} | {} |",
            SHIPPED_FONTS[*index].0,
            cells.join(" | ")
        );
    }
    println!("\nNo pixel over 0.5: {}.", clean_glyphs.join(", "));
}

/// The character a glyph comes from, if one maps to it alone, else its id.
fn glyph_label(font: &Font, id: GlyphId, text: &str) -> String {
    text.chars()
        .find(|&c| font.glyph_for_char(c).ok() == Some(id))
        .map_or(format!("#{id}"), |c| format!("'{c}'"))
}

fn page_report(gpu: &GpuContext) {
    let font = glyphscope::font::default_font();
    let scene = Scene::from_text(&font, glyphscope::bench::scenes::PAGE_TEXT).unwrap();
    let camera = Camera::new(1920, 1080, 16.0, DVec2::new(24.0, 40.0));
    let expected = reference::rasterize(&scene, &camera).unwrap();
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage).unwrap();
    println!("\n## The standard page (DejaVu Sans, 16 px/em, 1920×1080)\n");
    // `bounds` (one quad per glyph, exact box coverage) runs beside the modes as a
    // yardstick: its time moves with the machine's load, not with sdf-cells.
    let rows: [(&str, &str, Params); 4] = [
        ("estimate", "sdf-cells", params(&[("mode", "estimate")])),
        ("exact", "sdf-cells", params(&[("mode", "exact")])),
        (
            "exact, list encoding",
            "sdf-cells",
            params(&[("mode", "exact"), ("encoding", "list")]),
        ),
        ("bounds (yardstick)", "bounds", Vec::new()),
    ];
    let mut methods: Vec<(&str, Box<dyn Method>)> = rows
        .iter()
        .map(|(name, method, p)| (*name, registry::create(method, p).unwrap()))
        .collect();
    for (_, method) in &mut methods {
        method.prepare(gpu, &scene).unwrap();
        // Warm-up: shaders compile on first use.
        time_frames(gpu, method.as_mut(), &target, &camera, 5, 1).unwrap();
    }
    // Interleaved rounds, so that load from elsewhere falls on every mode alike; each
    // round's median per mode, and each round's ratio to the estimate.
    let median = |t: Vec<f64>| metrics::median(t).expect("frames were timed");
    let gpu_ms = |t: Vec<FrameTime>| t.iter().map(|t| t.gpu_ms).collect::<Vec<_>>();
    let rounds: Vec<Vec<f64>> = (0..9)
        .map(|_| {
            methods
                .iter_mut()
                .map(|(_, method)| {
                    median(gpu_ms(
                        time_frames(gpu, method.as_mut(), &target, &camera, 1, 7)
                            .unwrap()
                            .unwrap(),
                    ))
                })
                .collect()
        })
        .collect();
    println!(
        "| mode | MAE (/255) | max | px > 0.25 | px > 0.5 | curves/px (mean, max) | GPU ms (median, fastest round) | vs estimate (median of rounds) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let mut culprits = String::new();
    for (k, (name, method)) in methods.iter_mut().enumerate() {
        render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
        let image = target.readback(gpu).unwrap();
        let e = compare(&image, &expected).unwrap();
        if k == 0 {
            culprits = page_culprits(
                &scene,
                &camera,
                &image,
                &expected,
                glyphscope::bench::scenes::PAGE_TEXT,
            );
        }
        let cost = match method.curves_per_pixel(gpu, &camera).unwrap() {
            Some(c) => format!("{:.2}, {}", c.mean, c.max),
            None => "—".into(),
        };
        let mine: Vec<f64> = rounds.iter().map(|r| r[k]).collect();
        let ratio = median(rounds.iter().map(|r| r[k] / r[0]).collect());
        println!(
            "| {name} | {:.3} | {:.3} | {} | {} | {cost} | {:.1}, {:.1} | {ratio:.2}× |",
            e.mae_255,
            e.max,
            e.pixels_over_025,
            e.pixels_over_05,
            median(mine.clone()),
            mine.iter().copied().fold(f64::INFINITY, f64::min),
        );
        eprintln!("{name}: {} GPU bytes", method.gpu_bytes());
    }
    println!("\nEstimate pixels over 0.5 by glyph: {culprits}.");
    println!("\nAdapter: {}.", gpu.adapter_name());
}

/// The glyphs whose quads hold the pixels off by more than 0.5, with their counts.
fn page_culprits(
    scene: &Scene,
    camera: &Camera,
    image: &glyphscope::coverage::CoverageImage,
    expected: &glyphscope::coverage::CoverageImage,
    text: &str,
) -> String {
    let font = glyphscope::font::default_font();
    let boxes: Vec<_> = scene
        .instances
        .iter()
        .map(|i| {
            let to_image = camera.glyph_to_image(scene.units_per_em, i.position);
            let bounds = &scene.glyphs[i.glyph as usize].bounds;
            (i.glyph, Camera::project_bounds(&to_image, bounds).unwrap())
        })
        .collect();
    let mut counts: BTreeMap<String, usize> = BTreeMap::new();
    for y in 0..camera.height {
        for x in 0..camera.width {
            if (image.get(x, y) - expected.get(x, y)).abs() <= 0.5 {
                continue;
            }
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let owner = boxes
                .iter()
                .filter(|(_, b)| b.min.cmple(centre + 1.0).all() && b.max.cmpge(centre - 1.0).all())
                .map(|(g, _)| glyph_label(&font, scene.glyphs[*g as usize].id, text))
                .next()
                .unwrap_or_else(|| "?".into());
            *counts.entry(owner).or_default() += 1;
        }
    }
    let mut sorted: Vec<_> = counts.into_iter().collect();
    sorted.sort_by_key(|(_, n)| std::cmp::Reverse(*n));
    sorted
        .iter()
        .map(|(g, n)| format!("{g} {n}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn main() {
    let gpu = GpuContext::new().unwrap_or_else(|e| panic!("{e}"));
    if std::env::args().nth(1).as_deref() != Some("page") {
        glyphs_report(&gpu);
    }
    page_report(&gpu);
}
