//! The overlay pictures of docs/methods/, each panel drawn as `glyphscope render` draws
//! it and written as it writes it (an overlay in premultiplied colour over black, plain
//! coverage in grey), the panels of a picture stacked with a 2 px gap:
//!
//! - `winding-classes.png`: `winding overlay=classes` on "Sg" at 300 px/em;
//! - `winding-cost.png`: `winding overlay=cost` on the standard page's first four lines
//!   at 28 px/em, a 735×132 view, with bands (top) and `bands=off` (bottom);
//! - `sdf-cells-overlays.png`: `sdf-cells overlay=purple bias=0.002` on font-demo's two
//!   curves (one font unit a pixel, as `tests/sdf_cells.rs` draws them), then
//!   `overlay=cells`, `overlay=cost` and `outline=0.02 glow=0.1` on "ag" at 160 px/em;
//! - `tessellation-overlays.png`: `tessellation` on "g" at 300 px/em with
//!   `subdivision=asa overlay=wireframe`, `subdivision=asa overlay=points` and
//!   `overlay=wireframe` (screen subdivision).
//!
//! Written to `screenshots/`, or to the directory given as the first argument.
//! Run: `cargo run --release --example method_overlays`.

use std::path::Path;

use glam::DVec2;
use glyphscope::bench::scenes::PAGE_TEXT;
use glyphscope::camera::Camera;
use glyphscope::coverage::Png as _;
use glyphscope::geometry::{Contour, Outline};
use glyphscope::gpu::GpuContext;
use glyphscope::measure::{self, FrameTiming};
use glyphscope::methods::registry;
use glyphscope::scene::Scene;
use glyphscope::stability::hard_cases::{SYNTHETIC_PX_PER_EM, line, quad, synthetic_scene};
use glyphscope::view_args::ViewArgs;
use image::{DynamicImage, RgbImage};

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;
/// What a panel looks at: the scene and its camera, as `ViewArgs::build` gives them.
type View = (Scene, Camera);
/// `--param KEY=VALUE`s.
type Params<'a> = &'a [(&'a str, &'a str)];

/// Pixels between panels.
const GAP: u32 = 2;
/// The picture is the first frame's; one timed frame is all `measure` needs.
const ONE_FRAME: FrameTiming = FrameTiming {
    warmup: 0,
    frames: 1,
};
/// The 'ag' panels of sdf-cells: the size, and a frame with room for the glow.
const AG_SIZE: f64 = 160.0;
const AG_FRAME: (u32, u32) = (300, 250);

fn main() {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "screenshots".into());
    if let Err(e) = run(Path::new(&dir)) {
        eprintln!("method_overlays: {e}");
        std::process::exit(2);
    }
}

fn run(dir: &Path) -> Result<()> {
    let gpu = GpuContext::new()?;
    std::fs::create_dir_all(dir)?;
    let winding = |view: &View, params: Params| draw(&gpu, view, "winding", params);
    let classes = winding(&text("Sg", 300.0)?, &[("overlay", "classes")])?;
    save(dir, "winding-classes.png", classes)?;

    let page = page_lines()?;
    let cost = [
        winding(&page, &[("overlay", "cost")])?,
        winding(&page, &[("overlay", "cost"), ("bands", "off")])?,
    ];
    save(dir, "winding-cost.png", stack(&cost, Stack::Down))?;

    let sdf_cells = |view: &View, params: Params| draw(&gpu, view, "sdf-cells", params);
    let (w, h) = AG_FRAME;
    let ag = centred("ag", AG_SIZE, w, h)?;
    let sdf = [
        sdf_cells(&font_demo(), &[("overlay", "purple"), ("bias", "0.002")])?,
        sdf_cells(&ag, &[("overlay", "cells")])?,
        sdf_cells(&ag, &[("overlay", "cost")])?,
        sdf_cells(&ag, &[("outline", "0.02"), ("glow", "0.1")])?,
    ];
    save(dir, "sdf-cells-overlays.png", stack(&sdf, Stack::Across))?;

    let tessellation = |view: &View, params: Params| draw(&gpu, view, "tessellation", params);
    let g = text("g", 300.0)?;
    let asa = ("subdivision", "asa");
    let tess = [
        tessellation(&g, &[asa, ("overlay", "wireframe")])?,
        tessellation(&g, &[asa, ("overlay", "points")])?,
        tessellation(&g, &[("overlay", "wireframe")])?,
    ];
    save(
        dir,
        "tessellation-overlays.png",
        stack(&tess, Stack::Across),
    )
}

/// `--text TEXT --size SIZE` in the default frame.
fn text(text: &str, size: f64) -> Result<View> {
    Ok(ViewArgs::text(text, size).build()?)
}

/// The standard page's first four lines at 28 px/em, cut to 735×132.
fn page_lines() -> Result<View> {
    let lines: Vec<&str> = PAGE_TEXT.lines().take(4).collect();
    let view = ViewArgs {
        width: Some(735),
        height: Some(132),
        ..ViewArgs::text(&lines.join("\n"), 28.0)
    };
    Ok(view.build()?)
}

/// `text` at `size` in a `width`×`height` frame, its ink box in the middle.
fn centred(text: &str, size: f64, width: u32, height: u32) -> Result<View> {
    let (scene, mut camera) = ViewArgs::text(text, size).build()?;
    let ink = camera.ink_bounds(&scene)?;
    let frame = DVec2::new(f64::from(width), f64::from(height));
    camera.origin += ((frame - ink.size()) / 2.0 - ink.min).round();
    camera.width = width;
    camera.height = height;
    Ok((scene, camera))
}

/// font-demo's figure, as `tests/sdf_cells.rs` draws it: two quadratics turning left at
/// their join, closed by three lines far from it, one font unit a pixel in 200×250.
fn font_demo() -> View {
    let p = [(20.0, 40.0), (60.0, 140.0), (100.0, 80.0)];
    let q = [(140.0, 20.0), (180.0, 120.0)];
    let segments = vec![
        quad(p[0], p[1], p[2]),
        quad(p[2], q[0], q[1]),
        line(q[1], (180.0, 230.0)),
        line((180.0, 230.0), (20.0, 230.0)),
        line((20.0, 230.0), p[0]),
    ];
    let scene = synthetic_scene(Outline {
        contours: vec![Contour { segments }],
    });
    // The baseline at the bottom edge: font (x, y) lands on image (x, 250 − y).
    let camera = Camera::new(200, 250, SYNTHETIC_PX_PER_EM, DVec2::new(0.0, 250.0));
    (scene, camera)
}

/// What `glyphscope render --method METHOD --param …` writes for the view: the overlay
/// where one is asked for, else the coverage in grey.
fn draw(
    gpu: &GpuContext,
    (scene, camera): &View,
    method: &str,
    params: Params,
) -> Result<RgbImage> {
    let params: Vec<(String, String)> = params.iter().map(|&(k, v)| (k.into(), v.into())).collect();
    let info = registry::find(method)?;
    let measured = measure::measure(Some(gpu), scene, camera, info, &params, ONE_FRAME)?;
    Ok(measured
        .overlay
        .unwrap_or_else(|| DynamicImage::from(measured.image.to_gray8()).to_rgb8()))
}

#[derive(Clone, Copy)]
enum Stack {
    Across,
    Down,
}

/// The panels side by side or top to bottom, `GAP` apart, on black.
fn stack(panels: &[RgbImage], how: Stack) -> RgbImage {
    let gaps = GAP * (panels.len() as u32 - 1);
    let widths = panels.iter().map(RgbImage::width);
    let heights = panels.iter().map(RgbImage::height);
    let (w, h) = match how {
        Stack::Across => (widths.sum::<u32>() + gaps, heights.max().unwrap_or(0)),
        Stack::Down => (widths.max().unwrap_or(0), heights.sum::<u32>() + gaps),
    };
    let mut picture = RgbImage::new(w, h);
    let mut at = 0;
    for panel in panels {
        let (x, y) = match how {
            Stack::Across => (at, 0),
            Stack::Down => (0, at),
        };
        image::imageops::replace(&mut picture, panel, x.into(), y.into());
        at += GAP
            + match how {
                Stack::Across => panel.width(),
                Stack::Down => panel.height(),
            };
    }
    picture
}

fn save(dir: &Path, name: &str, picture: RgbImage) -> Result<()> {
    let path = dir.join(name);
    picture.save(&path)?;
    let (w, h) = picture.dimensions();
    eprintln!("wrote {} ({w}×{h})", path.display());
    Ok(())
}
