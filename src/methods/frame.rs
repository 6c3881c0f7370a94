//! The frame loop every caller shares: a prepared [`Method`] drawn once
//! ([`render_frame`], [`render_image`]) or many times under timestamp queries
//! ([`time_frames`]). The CLI, the bench, the app and the tests all draw through these,
//! so a method is measured exactly as it is checked.

use web_time::Instant;

use super::Method;
use crate::Error;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::timing::Timestamps;
use crate::gpu::{Channels, CoverageTarget, GpuContext};

/// Encodes one frame of `method` into `target`, submits it and waits for the GPU.
pub fn render_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
) -> Result<(), Error> {
    encode_frame(gpu, method, target, camera, true)
}

/// Encodes one frame of `method` into `target` and submits it, without waiting: what
/// the explorer draws offscreen within its frame loop, then reads back asynchronously.
pub fn submit_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
) -> Result<(), Error> {
    encode_frame(gpu, method, target, camera, false)
}

fn encode_frame(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    wait: bool,
) -> Result<(), Error> {
    check_frame(target, camera)?;
    gpu.catching_errors(&format!("rendering with '{}'", method.name()), || {
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        method.encode(gpu, &mut encoder, target, camera)?;
        gpu.queue.submit([encoder.finish()]);
        if wait { gpu.wait_idle() } else { Ok(()) }
    })
}

/// Renders one frame of a prepared `method` into a new coverage-only target the camera's
/// size and reads its coverage back as the method wrote it (nothing clamped).
pub fn render_image(
    gpu: &GpuContext,
    method: &mut dyn Method,
    camera: &Camera,
) -> Result<CoverageImage, Error> {
    let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Coverage)?;
    render_frame(gpu, method, &target, camera)?;
    target.readback(gpu)
}

/// A frame needs a camera that can be drawn with, looking at exactly the target: the
/// camera's image size fixes the projection (the tilt turns about the image centre).
fn check_frame(target: &CoverageTarget, camera: &Camera) -> Result<(), Error> {
    camera.validate()?;
    if (camera.width, camera.height) != (target.width, target.height) {
        return Err(Error::Input(format!(
            "the camera sees {}x{} pixels but the target is {}x{}",
            camera.width, camera.height, target.width, target.height
        )));
    }
    Ok(())
}

/// The time of one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameTime {
    /// The GPU work the method recorded, by timestamps (data it uploads with
    /// `Queue::write_buffer` is copied before the encoder runs and is not in it), and
    /// for a peer, what it submitted on its own less the harness's copy of its picture
    /// ([`Method::peer_gpu_time`]).
    pub gpu_ms: f64,
    /// The CPU work of recording the frame: the method's `encode` — culling, sorting,
    /// building meshes, writing instances — everything it does per frame (for a method
    /// that submits on its own, less the GPU time its submissions waited for).
    pub cpu_ms: f64,
}

/// GPU and CPU time of `frames` frames after `warmup` untimed frames (at least; see
/// [`time_frames_settled`]). `Ok(None)` when the device has no timestamp queries.
pub fn time_frames(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    warmup: usize,
    frames: usize,
) -> Result<Option<Vec<FrameTime>>, Error> {
    Ok(time_frames_settled(gpu, method, target, camera, warmup, frames)?.map(|t| t.times))
}

/// A frame shorter than this is timed several to a submission (and to a pair of
/// timestamps), so that a submission's fixed cost and the idle gap before it, and a
/// clock that ramps between short bursts of work, do not enter its figure.
pub const SHORT_FRAME_MS: f64 = 2.0;
/// At most this many frames to a submission.
pub const MOST_FRAMES_PER_SUBMISSION: u32 = 16;
/// Warm-up goes on past the asked frames while a frame is still faster than every one
/// before it by more than this share (shaders compiling, caches filling, a clock
/// ramping), up to [`MOST_WARMUP_FRAMES`].
const STILL_FALLING: f64 = 0.05;
const MOST_WARMUP_FRAMES: usize = 30;

/// Frames timed, and how.
#[derive(Clone, Debug, PartialEq)]
pub struct TimedFrames {
    pub times: Vec<FrameTime>,
    /// Frames drawn before the timed ones.
    pub warmup_frames: usize,
    /// Frames recorded into each timed submission (1 unless a frame is short).
    pub frames_per_submission: u32,
}

/// GPU and CPU time of `frames` frames. Before them, `warmup` untimed frames and, where
/// `warmup` is not 0, more while the frame time is still falling; where a frame is shorter than
/// [`SHORT_FRAME_MS`], several frames to one submission and one pair of timestamps,
/// each frame's time their share (not for a peer that submits work of its own, which
/// the harness times submission by submission). `Ok(None)` when the device has no
/// timestamp queries.
pub fn time_frames_settled(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    warmup: usize,
    frames: usize,
) -> Result<Option<TimedFrames>, Error> {
    if !gpu.has_timestamps() {
        return Ok(None);
    }
    check_frame(target, camera)?;
    let warmed = warm_up(gpu, method, target, camera, warmup)?;
    let times = time_submissions(
        gpu,
        method,
        target,
        camera,
        frames,
        warmed.frames_per_submission,
    )?;
    Ok(Some(TimedFrames {
        times,
        warmup_frames: warmed.frames,
        frames_per_submission: warmed.frames_per_submission,
    }))
}

/// What a warm-up found: the frames it drew, and how many frames a timed submission
/// should hold.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WarmedUp {
    pub frames: usize,
    pub frames_per_submission: u32,
    /// The wall time of its last frames (their median), ms: what a frame costs now.
    pub frame_ms: f64,
}

/// Draws `warmup` untimed frames and, where `warmup` is not 0, more while the frame
/// time is still falling; says how many frames a timed submission should hold (see
/// [`time_frames_settled`]).
pub fn warm_up(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    warmup: usize,
) -> Result<WarmedUp, Error> {
    check_frame(target, camera)?;
    // First frames pay for lazy shader compilation and first-use allocations.
    let mut walls: Vec<f64> = Vec::new();
    // No warm-up asked (a frame of a path timed as it comes): none, and no batching.
    while walls.len() < warmup
        || (warmup > 0 && walls.len() < MOST_WARMUP_FRAMES && still_falling(&walls))
    {
        let start = Instant::now();
        render_frame(gpu, method, target, camera)?;
        walls.push(ms_since(start));
    }
    // A peer that submits work of its own is timed submission by submission; one that
    // draws into the frame's encoder (its copy into the target timed apart) is batched
    // like the project's methods, its copy taken off once per frame.
    let submits_itself = method
        .peer_gpu_time(gpu)?
        .is_some_and(|t| t.submitted_ms > 0.0);
    let recent = crate::metrics::median(walls.iter().rev().take(3).copied()).unwrap_or(0.0);
    let frames_per_submission = if walls.is_empty() || submits_itself || recent >= SHORT_FRAME_MS {
        1
    } else {
        ((SHORT_FRAME_MS / recent.max(1e-3)).ceil() as u32).clamp(1, MOST_FRAMES_PER_SUBMISSION)
    };
    Ok(WarmedUp {
        frames: walls.len(),
        frames_per_submission,
        frame_ms: recent,
    })
}

/// `samples` timed submissions of `per_submission` frames each, after a warm-up: each
/// frame's time its share of its submission's.
pub fn time_submissions(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    samples: usize,
    per_submission: u32,
) -> Result<Vec<FrameTime>, Error> {
    check_frame(target, camera)?;
    // A query set holds at most QUERY_SET_MAX_QUERIES timestamps: two a submission.
    let batch_limit = wgpu::QUERY_SET_MAX_QUERIES / 2;
    let mut times = Vec::with_capacity(samples);
    while times.len() < samples {
        let batch = u32::try_from(samples - times.len())
            .unwrap_or(u32::MAX)
            .min(batch_limit);
        times.extend(time_batch(
            gpu,
            method,
            target,
            camera,
            batch,
            per_submission,
        )?);
    }
    Ok(times)
}

/// Whether the last of `walls` is faster than every one before it by more than
/// [`STILL_FALLING`].
fn still_falling(walls: &[f64]) -> bool {
    let Some((last, before)) = walls.split_last() else {
        return true;
    };
    let fastest = before.iter().copied().fold(f64::INFINITY, f64::min);
    *last < fastest * (1.0 - STILL_FALLING)
}

fn time_batch(
    gpu: &GpuContext,
    method: &mut dyn Method,
    target: &CoverageTarget,
    camera: &Camera,
    samples: u32,
    per_submission: u32,
) -> Result<Vec<FrameTime>, Error> {
    gpu.catching_errors(&format!("timing '{}'", method.name()), || {
        let timestamps = Timestamps::new(gpu, "frame timestamps", 2 * samples);
        let mut frame_ms = Vec::with_capacity(samples as usize);
        let share = f64::from(per_submission);
        for sample in 0..samples {
            let mut encoder = gpu
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("timed frame"),
                });
            timestamps.write(&mut encoder, 2 * sample);
            let start = Instant::now();
            for _ in 0..per_submission {
                method.encode(gpu, &mut encoder, target, camera)?;
            }
            let encode_ms = ms_since(start) / share;
            timestamps.write(&mut encoder, 2 * sample + 1);
            gpu.queue.submit([encoder.finish()]);
            // One submission at a time, as `render_frame` draws them: no frame's work
            // overlaps the next one's timestamps.
            gpu.wait_idle()?;
            let wall_ms = ms_since(start);
            let own = method.peer_gpu_time(gpu)?;
            frame_ms.push((encode_ms, own.map(|own| (own, wall_ms))));
        }
        let gpu_ms = timestamps.read_intervals(gpu)?;
        Ok(gpu_ms
            .into_iter()
            .zip(frame_ms)
            .map(|(recorded_ms, (encode_ms, peer))| match peer {
                None => FrameTime {
                    gpu_ms: recorded_ms / share,
                    cpu_ms: encode_ms,
                },
                // A peer: its own submissions count (one frame a submission then), the
                // harness's copy does not (the same copy in each frame of a batch).
                // Where the driver executes a submission inside it (a software
                // device), `encode` waited for that work, so the CPU time is the
                // frame's wall time less all GPU time, if that is less.
                Some((t, wall_ms)) => FrameTime {
                    gpu_ms: ((recorded_ms - share * t.copy_ms) / share + t.submitted_ms).max(0.0),
                    cpu_ms: if t.submitted_ms > 0.0 {
                        encode_ms
                            .min(wall_ms - recorded_ms - t.submitted_ms)
                            .max(0.0)
                    } else {
                        encode_ms
                    },
                },
            })
            .collect())
    })
}

/// Milliseconds since `start`.
pub fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}
