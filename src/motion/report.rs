//! What `glyphscope motion` writes: the per-frame CSV, the summary (Markdown and
//! JSON), the SVG plot of temporal error against frame, and the animated picture of a
//! magnified window, methods beside the reference.

use std::fmt::Write as _;
use std::path::Path;

use glam::DVec2;
use image::{Rgb, RgbImage};
use plotters::prelude::*;

use super::run::{MethodMotion, MotionResult};
use crate::Error;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::magnify::{self, Layers, Window};
use crate::methods::registry;
use crate::reference;
use crate::scene::Scene;

fn write_file(path: &Path, text: &str) -> Result<(), Error> {
    std::fs::write(path, text)
        .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))
}

/// One row per method and frame.
pub fn csv(result: &MotionResult) -> String {
    let mut out = String::from(
        "frame,method,settings,mae_255,edge_mae_255,max,pixels_over_025,pixels_over_05,\
         temporal_mae_255,temporal_edge_mae_255,temporal_max,temporal_pixels_over_01,gpu_ms,cpu_ms\n",
    );
    for m in &result.methods {
        let settings = m.method.settings();
        for f in &m.frames {
            let e = &f.error;
            let t = f.temporal.as_ref();
            let opt = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:.6}"));
            let _ = writeln!(
                out,
                "{},{},\"{}\",{:.6},{:.6},{:.6},{},{},{},{},{},{},{},{:.6}",
                f.frame,
                m.method.name,
                settings,
                e.mae_255,
                e.edge.mae_255,
                e.max,
                e.pixels_over_025,
                e.pixels_over_05,
                opt(t.map(|t| t.mae_255)),
                opt(t.map(|t| t.edge.mae_255)),
                opt(t.map(|t| t.max)),
                t.map_or(String::new(), |t| t.pixels_over.to_string()),
                opt(f.gpu_ms),
                f.cpu_ms,
            );
        }
    }
    out
}

/// The summary table: per method the still error beside the temporal one, and time.
pub fn markdown(result: &MotionResult, command: &str) -> String {
    let mut out = format!(
        "# glyphscope motion\n\n`{command}`\n\n{} frames of `{}`, {}×{} px, on {}. *Still*: the \
         error of each frame against the reference's, mean over frames (and the largest \
         pixel error of any frame). *Temporal*: per pixel, the method's change from one frame \
         to the next less the reference's, |Δm − Δr|, mean over frame pairs over the whole \
         frame and over edge pixels, the largest, pixels over 0.1 per pair, and the worst \
         pair. *ms*: median GPU + CPU time of a frame.\n\n",
        result.frames, result.path, result.width, result.height, result.adapter
    );
    out.push_str(
        "| method | still MAE /255 (max) | temporal MAE /255 | temporal edge MAE /255 | temporal max | > 0.1 per pair | worst pair (MAE /255) | ms |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for m in &result.methods {
        let _ = writeln!(out, "{}", table_row(m));
    }
    out
}

fn table_row(m: &MethodMotion) -> String {
    if let Some(reason) = &m.refused {
        return format!("| {} | n/a — {reason} | | | | | | |", m.method.label());
    }
    let t = &m.temporal;
    format!(
        "| {} | {:.2} ({:.3}) | {:.3} | {:.2} | {:.3} | {:.1} | {}→{} ({:.3}) | {} |",
        m.method.label(),
        m.still_mae_255(),
        m.still_max(),
        t.mae_255,
        t.edge_mae_255,
        t.max,
        t.pixels_over_per_pair,
        t.worst_pair,
        t.worst_pair + 1,
        t.worst_pair_mae_255,
        m.frame_ms().map_or("—".into(), |ms| format!("{ms:.2}")),
    )
}

/// Writes motion.csv, motion.md, motion.json and temporal.svg into `dir`.
pub fn write(result: &MotionResult, dir: &Path, command: &str) -> Result<(), Error> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::Output(format!("cannot create '{}': {e}", dir.display())))?;
    write_file(&dir.join("motion.csv"), &csv(result))?;
    write_file(&dir.join("motion.md"), &markdown(result, command))?;
    let json = serde_json::to_string_pretty(result).expect("the result serializes");
    write_file(&dir.join("motion.json"), &(json + "\n"))?;
    plot(result, &dir.join("temporal.svg"))
}

fn plot_error(e: impl std::fmt::Debug) -> Error {
    Error::Output(format!("cannot draw the plot: {e:?}"))
}

/// Temporal MAE of each frame pair against the pair's second frame, one line per method.
pub fn plot(result: &MotionResult, path: &Path) -> Result<(), Error> {
    let series: Vec<(&MethodMotion, Vec<(f64, f64)>)> = result
        .methods
        .iter()
        .filter(|m| m.refused.is_none())
        .map(|m| {
            let points = m
                .frames
                .iter()
                .filter_map(|f| f.temporal.map(|t| (f.frame as f64, t.mae_255)))
                .collect();
            (m, points)
        })
        .collect();
    let top = series
        .iter()
        .flat_map(|(_, p)| p.iter().map(|p| p.1))
        .filter(|v| v.is_finite())
        .fold(0.0f64, f64::max)
        .max(0.01)
        * 1.1;
    let root = SVGBackend::new(path, (800, 420)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("temporal error per frame: {}", result.path),
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            0.0..(result.frames.saturating_sub(1)).max(1) as f64,
            0.0..top,
        )
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc("frame (change from the frame before)")
        .y_desc("temporal MAE, 1/255")
        .light_line_style(WHITE)
        .draw()
        .map_err(plot_error)?;
    for (m, points) in series {
        let [r, g, b] = registry::find(&m.method.name).map_or([0, 0, 0], |i| i.colour);
        let colour = RGBColor(r, g, b);
        chart
            .draw_series(LineSeries::new(points, colour.stroke_width(2)))
            .map_err(plot_error)?
            .label(m.method.label())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 18, y)], colour.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(plot_error)?;
    root.present().map_err(plot_error)
}

/// A picture's panel: a label above a magnified window's frames.
pub struct Panel {
    pub label: String,
    pub frames: Vec<CoverageImage>,
    /// The reference's frames, for a second row of the signed error; none for the
    /// reference's own panel.
    pub against: Option<Vec<CoverageImage>>,
}

const GAP: u32 = 8;
const LABEL_HEIGHT: u32 = 24;
const BACKGROUND: Rgb<u8> = Rgb([32, 32, 32]);
/// Each frame shows this long, ms.
pub const FRAME_DELAY_MS: u16 = 100;

/// The animated picture (APNG): panels side by side, each the window's pixels as
/// `factor`×`factor` blocks, coverage above and signed error against the reference below
/// (red: too much, blue: too little, full at 0.5), a label over each.
pub fn animation(panels: &[Panel], factor: u32, path: &Path) -> Result<(), Error> {
    let first = panels
        .first()
        .and_then(|p| p.frames.first())
        .ok_or_else(|| Error::Internal("an animation needs frames".into()))?;
    let (cols, rows) = (first.width, first.height);
    let (panel_w, panel_h) = (cols * factor, rows * factor);
    let width = panels.len() as u32 * (panel_w + GAP) + GAP;
    let height = LABEL_HEIGHT + 2 * panel_h + 3 * GAP;
    let frames = panels.iter().map(|p| p.frames.len()).min().unwrap_or(0);
    let labels: Vec<CoverageImage> = panels
        .iter()
        .map(|p| label_image(&p.label, panel_w, LABEL_HEIGHT))
        .collect::<Result<_, _>>()?;
    let window = Window {
        x0: 0,
        y0: 0,
        cols,
        rows,
        factor,
        focus: (cols / 2, rows / 2),
    };
    let file = std::fs::File::create(path)
        .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
    let png_error =
        |e: png::EncodingError| Error::Output(format!("cannot write '{}': {e}", path.display()));
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_animated(frames as u32, 0).map_err(png_error)?;
    encoder
        .set_frame_delay(FRAME_DELAY_MS, 1000)
        .map_err(png_error)?;
    let mut writer = encoder.write_header().map_err(png_error)?;
    for n in 0..frames {
        let mut canvas = RgbImage::from_pixel(width, height, BACKGROUND);
        for (k, panel) in panels.iter().enumerate() {
            let left = GAP + k as u32 * (panel_w + GAP);
            blend_label(&mut canvas, &labels[k], left, 0);
            let top = LABEL_HEIGHT + GAP;
            let image = &panel.frames[n];
            let coverage = magnify::picture(image, &window, &Layers::default(), panel_w, panel_h);
            image::imageops::replace(&mut canvas, &coverage, i64::from(left), i64::from(top));
            if let Some(reference) = &panel.against {
                let layers = Layers {
                    error_against: Some(&reference[n]),
                    ..Layers::default()
                };
                let error = magnify::picture(image, &window, &layers, panel_w, panel_h);
                let below = top + panel_h + GAP;
                image::imageops::replace(&mut canvas, &error, i64::from(left), i64::from(below));
            }
        }
        writer
            .write_image_data(canvas.as_raw())
            .map_err(png_error)?;
    }
    writer.finish().map_err(png_error)
}

/// A label drawn by the reference from the embedded font: white on the background.
fn label_image(text: &str, width: u32, height: u32) -> Result<CoverageImage, Error> {
    let font = crate::font::default_font();
    let scene = Scene::from_text(&font, text)?;
    let camera = Camera::new(
        width,
        height,
        14.0,
        DVec2::new(2.0, f64::from(height) - 7.0),
    );
    reference::rasterize(&scene, &camera)
}

fn blend_label(canvas: &mut RgbImage, label: &CoverageImage, left: u32, top: u32) {
    for y in 0..label.height {
        for x in 0..label.width {
            let a = label.get(x, y).clamp(0.0, 1.0);
            let (cx, cy) = (left + x, top + y);
            if a > 0.0 && cx < canvas.width() && cy < canvas.height() {
                let p = canvas.get_pixel_mut(cx, cy);
                for c in 0..3 {
                    p[c] = (f32::from(p[c]) * (1.0 - a) + 255.0 * a).round() as u8;
                }
            }
        }
    }
}
