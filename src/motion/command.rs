//! `glyphscope motion`: the methods run through the path, the report written, the
//! animated picture of a window drawn again for the methods it shows, and the summary
//! table returned for the command line to print.

use std::path::PathBuf;

use super::MotionPath;
use super::report;
use super::run::{self, MethodSpec};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::GpuContext;
use crate::magnify::Focus;
use crate::methods::registry;
use crate::scene::Scene;

/// What to run, on what view, and where to write it.
pub struct MotionOptions {
    /// The view frame 0 shows.
    pub scene: Scene,
    pub camera: Camera,
    pub path: MotionPath,
    /// Frames drawn (at least 2).
    pub frames: usize,
    pub methods: Vec<MethodSpec>,
    /// The methods the animated picture shows beside the reference: indices into
    /// `methods` (see [`animated_methods`]).
    pub animated: Vec<usize>,
    /// Frames in the animated picture (the first ones; at most `frames`).
    pub animate_frames: usize,
    /// The animated picture's magnification: each pixel a block this many pixels a side.
    pub magnify: u32,
    /// The pixel the animated picture is centred on; where the first animated method's
    /// largest change beyond the reference's is when None or [`Focus::Worst`].
    pub focus: Option<Focus>,
    /// Folder for motion.csv, motion.md, motion.json, temporal.svg and motion.png.
    pub out: PathBuf,
    /// The command line the report names as its source.
    pub command: String,
    /// A part of the name of the adapter to draw with (see [`GpuContext::open`]).
    pub adapter: Option<String>,
}

/// Indices into `methods` of the methods `names` picks by place (1, 2, …), name or
/// label; the first two when `names` is empty.
pub fn animated_methods(names: &[String], methods: &[MethodSpec]) -> Result<Vec<usize>, Error> {
    if names.is_empty() {
        return Ok((0..methods.len().min(2)).collect());
    }
    names
        .iter()
        .map(|name| {
            if let Ok(k) = name.trim().parse::<usize>() {
                return (1..=methods.len())
                    .contains(&k)
                    .then_some(k - 1)
                    .ok_or_else(|| {
                        Error::Input(format!(
                            "--animate {k}: --method lists {} methods",
                            methods.len()
                        ))
                    });
            }
            methods
                .iter()
                .position(|s| s.name == name.trim() || s.label() == name.trim())
                .ok_or_else(|| Error::Input(format!("--animate '{name}' is not one of --method")))
        })
        .collect()
}

/// Runs the methods through the path (progress on stderr), writes the report and the
/// animated picture, and returns the summary table.
pub fn run(options: &MotionOptions) -> Result<String, Error> {
    let (scene, camera, path) = (&options.scene, &options.camera, &options.path);
    // A pixel outside the frame is bad input: said before anything is measured.
    let chosen_focus = match options.focus {
        Some(Focus::Pixel(x, y)) => {
            Some(Focus::Pixel(x, y).pixel(camera.width, camera.height, None)?)
        }
        _ => None,
    };
    let specs = &options.methods;
    let needs_gpu = specs.iter().any(|s| s.name != registry::REFERENCE.name);
    let gpu = needs_gpu
        .then(|| GpuContext::open(options.adapter.as_deref()))
        .transpose()?;
    let frames = options.frames;
    let bar = indicatif::ProgressBar::new(frames as u64);
    let result = run::run(gpu.as_ref(), scene, camera, path, frames, specs, |_| {
        bar.inc(1)
    })?;
    bar.finish_and_clear();
    report::write(&result, &options.out, &options.command)?;
    // The animated picture: a window around the focus, drawn again for the methods
    // shown (the run keeps no frames).
    let shown = options
        .animated
        .iter()
        .filter(|&&k| result.methods[k].refused.is_none())
        .copied()
        .collect::<Vec<_>>();
    if let Some(&first) = shown.first() {
        let animate_frames = options.animate_frames.clamp(2, frames);
        let panel = 288 / options.magnify;
        let (cols, rows) = (
            panel.min(camera.width),
            (192 / options.magnify).min(camera.height),
        );
        // The pixel of the largest change of the run (the worst pair's worst pixel);
        // the frame's centre when the method changed nothing the reference did not.
        let focus = chosen_focus.unwrap_or_else(|| {
            result.methods[first]
                .frames
                .iter()
                .filter_map(|f| f.temporal.map(|t| (t.max, t.worst_pixel)))
                .filter(|(max, _)| *max > 0.0)
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .map_or((camera.width / 2, camera.height / 2), |w| w.1)
        });
        let x0 = focus.0.saturating_sub(cols / 2).min(camera.width - cols);
        let y0 = focus.1.saturating_sub(rows / 2).min(camera.height - rows);
        let draw = |spec: &MethodSpec| {
            run::window_frames(
                gpu.as_ref(),
                scene,
                camera,
                path,
                animate_frames,
                spec,
                (x0, y0, cols, rows),
            )
        };
        let reference_spec = MethodSpec::parse(registry::REFERENCE.name)?;
        let reference = draw(&reference_spec)?;
        let mut panels = vec![report::Panel {
            label: "reference".into(),
            frames: reference.clone(),
            against: None,
        }];
        for &k in &shown {
            panels.push(report::Panel {
                label: specs[k].label(),
                frames: draw(&specs[k])?,
                against: Some(reference.clone()),
            });
        }
        report::animation(&panels, options.magnify, &options.out.join("motion.png"))?;
        eprintln!(
            "animated: pixels ({x0}, {y0}) to ({}, {}), frames 0 to {}",
            x0 + cols - 1,
            y0 + rows - 1,
            animate_frames - 1
        );
    }
    Ok(report::markdown(&result, &options.command))
}
