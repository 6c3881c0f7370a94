//! The numbers too slow for a frame — the CPU reference, each pane's error against it,
//! and curves evaluated per pixel (a counting pass of the method's own) — worked out on
//! a background thread once the view rests. A newer request supersedes any still
//! waiting. The thread keeps its own prepared copy of each pane's method for counting,
//! made again only when the scene or the parameters change. The answers go to the
//! panes and to the explorer's [`ReferenceState`].

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, channel};
use web_time::Instant;

use eframe::egui;

use super::gpu_view::ReferenceTexture;
use super::settings::CameraSettings;
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::methods::{CurveCost, Method, registry};
use crate::metrics::{self, ErrorStats, TemporalError};
use crate::reference;
use crate::scene::Scene;

/// A view to analyse: the scene, the camera, and what each pane showed for it.
pub struct Request {
    /// Numbers requests in the order sent; set by [`Analysis::send`].
    pub id: u64,
    pub scene: Arc<Scene>,
    pub scene_generation: u64,
    pub camera: Camera,
    /// (pane, its coverage for `camera`).
    pub captures: Vec<(usize, Arc<CoverageImage>)>,
    /// The panes to count curves per pixel for.
    pub counts: Vec<Count>,
    /// Each pane's surface generation when the request was made: a result for a pane
    /// whose method has since been remade is not that method's.
    pub pane_generations: Vec<u64>,
    /// The frame of the motion path shown, when text is in motion: a frame that follows
    /// the one analysed before, of the same motion, gets each pane's temporal error.
    pub motion_frame: Option<(i64, MotionKey)>,
}

/// What makes consecutive frames one motion: the path, the camera it starts from and
/// the pane it is drawn in. A frame after any change of these is a new start.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionKey {
    pub path: String,
    pub camera: CameraSettings,
    pub pane: (u32, u32),
}

/// (pane, method, parameters).
pub type Count = (usize, String, Vec<(String, String)>);

pub struct Outcome {
    /// The request answered.
    pub id: u64,
    pub scene_generation: u64,
    pub camera: Camera,
    pub reference: Result<Arc<CoverageImage>, String>,
    /// CPU time of the reference, ms (None when an earlier one was reused).
    pub reference_ms: Option<f64>,
    pub errors: Vec<(usize, Result<ErrorStats, String>)>,
    pub curves: Vec<(usize, Result<Option<CurveCost>, String>)>,
    /// Against the frame before, for the panes that had one (see [`Request::motion_frame`]).
    pub temporal: Vec<(usize, TemporalError)>,
    /// As in the request.
    pub pane_generations: Vec<u64>,
    pub motion_frame: Option<i64>,
}

/// The last frame of motion analysed: what the next frame's temporal error is taken
/// against.
struct PreviousFrame {
    frame: i64,
    motion: MotionKey,
    scene_generation: u64,
    reference: Arc<CoverageImage>,
    /// (pane, its surface generation, its capture).
    captures: Vec<(usize, u64, Arc<CoverageImage>)>,
}

/// The worker's prepared copy of a pane's method: (scene generation, name, parameters).
type Counter = (u64, String, Vec<(String, String)>, Box<dyn Method>);

/// Where the worker works out the numbers, as the panes and the status bar say it.
pub const WHERE: &str = if cfg!(target_arch = "wasm32") {
    "within the frame"
} else {
    "background"
};

/// What the worker keeps between requests: the last reference (reused while only the
/// panes change), each pane's prepared counting method, the last frame of a motion.
#[derive(Default)]
struct Worker {
    last: Option<(u64, Camera, Arc<CoverageImage>)>,
    counters: HashMap<usize, Counter>,
    previous: Option<PreviousFrame>,
}

impl Worker {
    /// The numbers of one view; curves per pixel only with a GPU to count them on.
    fn answer(&mut self, request: &Request, gpu: Option<&GpuContext>) -> Outcome {
        let mut outcome = analyse(request, &mut self.last);
        outcome.temporal = temporal(request, &outcome, &mut self.previous);
        if let Some(gpu) = gpu {
            outcome.curves = count_curves(gpu, request, &mut self.counters);
        }
        outcome
    }
}

/// The background worker and its mailboxes. On the web, which has no threads yet, the
/// worker answers each request as it is sent, within the frame, without counting
/// curves (a counting pass waits for the GPU).
pub struct Analysis {
    #[cfg(not(target_arch = "wasm32"))]
    requests: Sender<Request>,
    #[cfg(target_arch = "wasm32")]
    inline: (Worker, Sender<Outcome>),
    outcomes: Receiver<Outcome>,
    sent: u64,
    answered: u64,
}

impl Analysis {
    #[cfg(not(target_arch = "wasm32"))]
    pub fn start(ctx: egui::Context, gpu: Option<GpuContext>) -> Analysis {
        let (requests, inbox) = channel::<Request>();
        let (outbox, outcomes) = channel();
        std::thread::Builder::new()
            .name("reference and error".into())
            .spawn(move || {
                let mut worker = Worker::default();
                while let Ok(mut request) = inbox.recv() {
                    // Only the newest view matters.
                    while let Ok(newer) = inbox.try_recv() {
                        request = newer;
                    }
                    if outbox.send(worker.answer(&request, gpu.as_ref())).is_err() {
                        return;
                    }
                    ctx.request_repaint();
                }
            })
            .expect("a thread can be started");
        Analysis {
            requests,
            outcomes,
            sent: 0,
            answered: 0,
        }
    }

    #[cfg(target_arch = "wasm32")]
    pub fn start(_: egui::Context, _: Option<GpuContext>) -> Analysis {
        let (outbox, outcomes) = channel();
        Analysis {
            inline: (Worker::default(), outbox),
            outcomes,
            sent: 0,
            answered: 0,
        }
    }

    pub fn send(&mut self, mut request: Request) {
        self.sent += 1;
        request.id = self.sent;
        // The worker lives as long as the app; if it died, the numbers just stay unknown.
        #[cfg(not(target_arch = "wasm32"))]
        let _ = self.requests.send(request);
        #[cfg(target_arch = "wasm32")]
        {
            let (worker, outbox) = &mut self.inline;
            let _ = outbox.send(worker.answer(&request, None));
        }
    }

    /// Whether the newest request is still being worked on.
    pub fn busy(&self) -> bool {
        self.answered < self.sent
    }

    /// The newest answer that has arrived, if any.
    pub fn receive(&mut self) -> Option<Outcome> {
        let newest = self.outcomes.try_iter().last()?;
        self.answered = newest.id;
        Some(newest)
    }
}

/// The reference for the resting view, on the GPU for the panes that show it.
#[derive(Default)]
pub struct ReferenceState {
    pub texture: ReferenceTexture,
    pub image: Option<Arc<CoverageImage>>,
    /// (scene generation, camera) the image is for.
    pub made_for: Option<(u64, Camera)>,
    pub cpu_ms: Option<f64>,
    pub problem: Option<String>,
}

fn analyse(request: &Request, last: &mut Option<(u64, Camera, Arc<CoverageImage>)>) -> Outcome {
    let reused = last
        .as_ref()
        .filter(|(generation, camera, _)| {
            (*generation, *camera) == (request.scene_generation, request.camera)
        })
        .map(|(_, _, image)| image.clone());
    let mut reference_ms = None;
    let reference = match reused {
        Some(image) => Ok(image),
        None => {
            let start = Instant::now();
            let result = reference::rasterize(&request.scene, &request.camera)
                .map(Arc::new)
                .map_err(|e| e.to_string());
            reference_ms = Some(start.elapsed().as_secs_f64() * 1e3);
            if let Ok(image) = &result {
                *last = Some((request.scene_generation, request.camera, image.clone()));
            }
            result
        }
    };
    let errors = match &reference {
        Ok(reference) => request
            .captures
            .iter()
            .map(|(pane, image)| {
                (
                    *pane,
                    metrics::compare(image, reference).map_err(|e| e.to_string()),
                )
            })
            .collect(),
        Err(_) => Vec::new(),
    };
    Outcome {
        id: request.id,
        scene_generation: request.scene_generation,
        camera: request.camera,
        reference,
        reference_ms,
        errors,
        curves: Vec::new(),
        temporal: Vec::new(),
        pane_generations: request.pane_generations.clone(),
        motion_frame: request.motion_frame.as_ref().map(|(n, _)| *n),
    }
}

/// Each pane's temporal error from the frame before, when this request is the next
/// frame of the same motion (same path, starting camera, pane size and scene, and the
/// same method in the pane); keeps this frame for the next.
fn temporal(
    request: &Request,
    outcome: &Outcome,
    previous: &mut Option<PreviousFrame>,
) -> Vec<(usize, TemporalError)> {
    let (Some((frame, motion)), Ok(reference)) = (&request.motion_frame, &outcome.reference) else {
        *previous = None;
        return Vec::new();
    };
    let mut changes = Vec::new();
    if let Some(before) = previous.as_ref().filter(|p| {
        p.frame + 1 == *frame
            && p.motion == *motion
            && p.scene_generation == request.scene_generation
            && (p.reference.width, p.reference.height) == (reference.width, reference.height)
    }) {
        for (pane, image) in &request.captures {
            let earlier = before.captures.iter().find(|(p, generation, _)| {
                p == pane && *generation == request.pane_generations[*pane]
            });
            if let Some((_, _, earlier)) = earlier
                && let Ok(change) =
                    metrics::temporal([earlier, image], [&before.reference, reference])
            {
                changes.push((*pane, change));
            }
        }
    }
    *previous = Some(PreviousFrame {
        frame: *frame,
        motion: motion.clone(),
        scene_generation: request.scene_generation,
        reference: reference.clone(),
        captures: request
            .captures
            .iter()
            .map(|(pane, image)| (*pane, request.pane_generations[*pane], image.clone()))
            .collect(),
    });
    changes
}

fn count_curves(
    gpu: &GpuContext,
    request: &Request,
    counters: &mut HashMap<usize, Counter>,
) -> Vec<(usize, Result<Option<CurveCost>, String>)> {
    counters.retain(|pane, _| request.counts.iter().any(|(p, _, _)| p == pane));
    request
        .counts
        .iter()
        .map(|(pane, name, params)| {
            let fresh = counters.get(pane).is_some_and(|(generation, n, p, _)| {
                (*generation, n, p) == (request.scene_generation, name, params)
            });
            if !fresh {
                let made = registry::create(name, params).and_then(|mut m| {
                    m.prepare(gpu, &request.scene)?;
                    Ok(m)
                });
                match made {
                    Ok(m) => {
                        counters.insert(
                            *pane,
                            (request.scene_generation, name.clone(), params.clone(), m),
                        );
                    }
                    Err(e) => return (*pane, Err(e.to_string())),
                }
            }
            let method = &mut counters.get_mut(pane).expect("made above").3;
            let counted = method
                .curves_per_pixel(gpu, &request.camera)
                .map_err(|e| e.to_string());
            (*pane, counted)
        })
        .collect()
}
