//! A motion run: methods drawing the frames of a [`MotionPath`] side by side with the
//! reference, each frame measured as a still (its error) and against the frame before
//! (its temporal error), and timed.

use web_time::Instant;

use serde::Serialize;

use super::MotionPath;
use crate::Error;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::measure::{self, FrameTiming};
use crate::methods::frame::{ms_since, render_frame};
use crate::methods::params::settings_text;
use crate::methods::{Method, registry};
use crate::metrics::{self, ErrorStats, TemporalError, TemporalSummary};
use crate::reference;
use crate::scene::Scene;

/// A method at its settings, as `--method` names it: `NAME` or `NAME:KEY=VALUE:…`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MethodSpec {
    pub name: String,
    pub params: Vec<(String, String)>,
}

impl MethodSpec {
    /// `NAME[:KEY=VALUE…]`, or `wgsl:PATH[:claim=MAX/MAE]` for a user's method (the
    /// path read as `user::split` reads it).
    pub fn parse(text: &str) -> Result<MethodSpec, Error> {
        let text = text.trim();
        let (name, rest) = crate::methods::user::split(text)
            .unwrap_or_else(|| text.split_at(text.find(':').unwrap_or(text.len())));
        let parts = rest
            .strip_prefix(':')
            .into_iter()
            .flat_map(|r| r.split(':'));
        let mut params = parts
            .map(|p| {
                crate::view_args::parse_key_value(p)
                    .map_err(|e| Error::Input(format!("method '{text}': {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        // A user's file takes its claim (`claim=MAX/MAE`) as its row's, not as a
        // parameter of the method drawn: it stays with the name (`registry::find` reads
        // it there).
        if crate::methods::user::split(name).is_some() {
            let claim = params.iter().rposition(|(k, _)| k == "claim");
            let claim = claim.map(|k| params.remove(k).1);
            params.retain(|(k, _)| k != "claim");
            let info = crate::methods::user::find_claimed(name.trim(), claim.as_deref())?;
            let name = match claim {
                Some(claim) => format!("{}:claim={claim}", info.name),
                None => info.name.to_owned(),
            };
            return Ok(MethodSpec { name, params });
        }
        let info = registry::find(name.trim())?;
        Ok(MethodSpec {
            name: info.name.to_owned(),
            params,
        })
    }

    /// `name` or `name key=value, …`.
    pub fn label(&self) -> String {
        match self.params.is_empty() {
            true => self.name.clone(),
            false => format!("{} {}", self.name, self.settings()),
        }
    }

    /// `key=value, …`, or `default`.
    pub fn settings(&self) -> String {
        settings_text(&self.params, &[])
    }

    fn is_reference(&self) -> bool {
        self.name == registry::REFERENCE.name
    }
}

/// One frame of one method.
#[derive(Clone, Debug, Serialize)]
pub struct FrameRecord {
    pub frame: usize,
    /// Against the reference's frame.
    pub error: ErrorStats,
    /// Against the frame before (none for the first).
    pub temporal: Option<TemporalError>,
    /// GPU time (the reference: none) and CPU time of recording the frame (the
    /// reference: its rasterization), ms.
    pub gpu_ms: Option<f64>,
    pub cpu_ms: f64,
}

/// A method's run, or why it could not draw it.
#[derive(Clone, Debug, Serialize)]
pub struct MethodMotion {
    pub method: MethodSpec,
    pub frames: Vec<FrameRecord>,
    pub temporal: TemporalSummary,
    /// A peer's documented limit met by a frame of the path (glyphon: rotation).
    pub refused: Option<String>,
}

impl MethodMotion {
    /// The mean over frames of the still error, in 1/255.
    pub fn still_mae_255(&self) -> f64 {
        let n = self.frames.len().max(1) as f64;
        self.frames.iter().map(|f| f.error.mae_255).sum::<f64>() / n
    }

    /// The largest pixel error of any frame.
    pub fn still_max(&self) -> f64 {
        self.frames.iter().map(|f| f.error.max).fold(0.0, f64::max)
    }

    /// Median GPU + CPU time of a frame, ms.
    pub fn frame_ms(&self) -> Option<f64> {
        metrics::median(
            self.frames
                .iter()
                .map(|f| f.gpu_ms.unwrap_or(0.0) + f.cpu_ms),
        )
    }
}

/// What a run measured.
#[derive(Clone, Debug, Serialize)]
pub struct MotionResult {
    pub path: String,
    pub frames: usize,
    pub width: u32,
    pub height: u32,
    pub adapter: String,
    pub methods: Vec<MethodMotion>,
}

/// Untimed frames each method draws at frame 0 before the run (shaders compile and
/// caches fill on the first frames).
const WARMUP: usize = 3;

/// A GPU method and the target it draws into.
struct Drawer<'g> {
    gpu: &'g GpuContext,
    method: Box<dyn Method>,
    target: CoverageTarget,
}

/// A method drawing the run (no drawer: the reference), with the frame it drew last.
struct Live<'g> {
    drawer: Option<Drawer<'g>>,
    previous: Option<CoverageImage>,
    record: MethodMotion,
}

/// Runs `methods` through `frames` frames of `path` from `base`, frame by frame, each
/// compared with the reference's same frame and with its own previous one. `progress`
/// hears of each frame done. A peer that refuses a frame (its documented limit) is
/// reported as refused; any other failure ends the run.
pub fn run(
    gpu: Option<&GpuContext>,
    scene: &Scene,
    base: &Camera,
    path: &MotionPath,
    frames: usize,
    methods: &[MethodSpec],
    mut progress: impl FnMut(usize),
) -> Result<MotionResult, Error> {
    if frames < 2 {
        return Err(Error::Input(format!(
            "a motion needs at least 2 frames (one change), got {frames}"
        )));
    }
    let cameras: Vec<Camera> = (0..frames)
        .map(|n| {
            let camera = path.camera_at(base, n as i64);
            camera
                .validate()
                .map_err(|e| Error::Input(format!("frame {n} of '{path}': {e}")))?;
            Ok(camera)
        })
        .collect::<Result<_, Error>>()?;
    let mut live = Vec::with_capacity(methods.len());
    for spec in methods {
        live.push(start(gpu, scene, &cameras[0], spec)?);
    }
    let mut previous_reference: Option<CoverageImage> = None;
    for (n, camera) in cameras.iter().enumerate() {
        let start = Instant::now();
        let reference = reference::rasterize(scene, camera)?;
        let reference_ms = ms_since(start);
        for method in &mut live {
            if method.record.refused.is_some() {
                continue;
            }
            let drawn = match draw(method.drawer.as_mut(), camera, &reference, reference_ms) {
                Err(Error::Refused(reason)) => {
                    method.record.refused = Some(format!("frame {n}: {reason}"));
                    continue;
                }
                other => other?,
            };
            let (image, gpu_ms, cpu_ms) = drawn;
            let error = metrics::compare(&image, &reference)?;
            let temporal = match (&method.previous, &previous_reference) {
                (Some(before), Some(reference_before)) => Some(metrics::temporal(
                    [before, &image],
                    [reference_before, &reference],
                )?),
                _ => None,
            };
            method.record.frames.push(FrameRecord {
                frame: n,
                error,
                temporal,
                gpu_ms,
                cpu_ms,
            });
            method.previous = Some(image);
        }
        previous_reference = Some(reference);
        progress(n);
    }
    let methods = live
        .into_iter()
        .map(|mut m| {
            let pairs: Vec<TemporalError> =
                m.record.frames.iter().filter_map(|f| f.temporal).collect();
            m.record.temporal = TemporalSummary::of(&pairs);
            m.record
        })
        .collect();
    Ok(MotionResult {
        path: path.to_string(),
        frames,
        width: base.width,
        height: base.height,
        adapter: gpu.map_or_else(
            || "cpu (exact reference rasterizer)".into(),
            |g| g.adapter_name(),
        ),
        methods,
    })
}

/// Prepares a method and warms it up on the first frame; a peer's refusal is kept as
/// its result.
fn start<'g>(
    gpu: Option<&'g GpuContext>,
    scene: &Scene,
    first: &Camera,
    spec: &MethodSpec,
) -> Result<Live<'g>, Error> {
    let mut live = Live {
        drawer: None,
        previous: None,
        record: MethodMotion {
            method: spec.clone(),
            frames: Vec::new(),
            temporal: TemporalSummary::default(),
            refused: None,
        },
    };
    let info = registry::find(&spec.name)?;
    if spec.is_reference() {
        info.parse_params(&spec.params)?;
        return Ok(live);
    }
    let mut method = info.create(&spec.params)?;
    let gpu = gpu.ok_or_else(|| Error::Gpu("a GPU method needs a GPU context".into()))?;
    let target = CoverageTarget::new(gpu, first.width, first.height, Channels::Coverage)?;
    let warm = method.prepare(gpu, scene).and_then(|()| {
        (0..WARMUP).try_for_each(|_| render_frame(gpu, method.as_mut(), &target, first))
    });
    match warm {
        Err(Error::Refused(reason)) => live.record.refused = Some(format!("frame 0: {reason}")),
        other => other?,
    }
    live.drawer = Some(Drawer {
        gpu,
        method,
        target,
    });
    Ok(live)
}

/// One frame of a method: its coverage (overlapping glyphs' sums taken down to their
/// union, as every figure takes them), GPU and CPU ms.
fn draw(
    drawer: Option<&mut Drawer>,
    camera: &Camera,
    reference: &CoverageImage,
    reference_ms: f64,
) -> Result<(CoverageImage, Option<f64>, f64), Error> {
    let Some(d) = drawer else {
        // The reference itself.
        return Ok((reference.clone(), None, reference_ms));
    };
    let timing = FrameTiming {
        warmup: 0,
        frames: 1,
    };
    let times = measure::time_frames(d.gpu, d.method.as_mut(), &d.target, camera, timing)?.times;
    let image = d.target.readback(d.gpu)?.clamp_to_union();
    let time = times[0];
    Ok((image, Some(time.gpu_ms), time.cpu_ms))
}

/// The frames a method draws of a window of each frame (for the animated picture): the
/// window's own pixels of frames 0 to `frames` − 1, at 8 bits.
pub fn window_frames(
    gpu: Option<&GpuContext>,
    scene: &Scene,
    base: &Camera,
    path: &MotionPath,
    frames: usize,
    spec: &MethodSpec,
    window: (u32, u32, u32, u32),
) -> Result<Vec<CoverageImage>, Error> {
    let (x, y, width, height) = window;
    let cameras: Vec<Camera> = (0..frames)
        .map(|n| path.camera_at(base, n as i64).window(x, y, width, height))
        .collect();
    let mut live = start(gpu, scene, &cameras[0], spec)?;
    if let Some(reason) = live.record.refused {
        return Err(Error::Refused(reason));
    }
    cameras
        .iter()
        .map(|camera| match live.drawer.as_mut() {
            Some(d) => {
                render_frame(d.gpu, d.method.as_mut(), &d.target, camera)?;
                Ok(d.target.readback(d.gpu)?.clamp_to_union())
            }
            None => reference::rasterize(scene, camera),
        })
        .collect()
}
