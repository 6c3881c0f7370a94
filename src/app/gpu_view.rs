//! The panes' GPU side. Each pane's method renders into its own offscreen
//! [`CoverageTarget`] in egui_wgpu's `prepare()`, on egui's encoder (egui's pass has one
//! sample and no stencil; methods bring their own), and `paint()` draws that texture into
//! the pane at one texel per pixel with the compositor. A pane is drawn again only when
//! its camera, method or parameters changed (or always, in continuous mode).

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

use eframe::egui;
use egui_wgpu::wgpu;

use super::display::{CoverageAdjust, DisplayMode, composite_wgsl};
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::timing::{Timestamps, intervals_ms};
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::magnify::GRID_FROM;
use crate::methods::Method;
use crate::methods::frame::ms_since;

/// How a pane turns its texture(s) into pixels (`mode` in `composite.wgsl`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompositeMode {
    /// Text colour over background by coverage.
    Coverage,
    /// The method's overlay picture (rgb).
    OverlayPicture,
    /// Signed difference of two coverages, coloured like `metrics::error_image`.
    Difference,
    /// The cost heat map's colour scale, for its legend.
    HeatScale,
}

/// `Composite` in composite.wgsl.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct CompositeUniform {
    origin: [f32; 2],
    size: [f32; 2],
    text: [f32; 4],
    background: [f32; 4],
    mode: u32,
    srgb_target: u32,
    difference_scale: f32,
    // Framebuffer pixels per texel side: the magnifier's N.
    block: f32,
    display: u32,
    edge_darkening: f32,
    darkening_exponent: f32,
    grid: u32,
}

/// The pipeline that draws panes, for egui's framebuffer format.
pub struct Compositor {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    /// Bound where a mode reads no second texture.
    blank: wgpu::TextureView,
    srgb_target: bool,
}

impl Compositor {
    pub fn new(gpu: &GpuContext, format: wgpu::TextureFormat) -> Compositor {
        let device = &gpu.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("composite.wgsl"),
            source: wgpu::ShaderSource::Wgsl(composite_wgsl().into()),
        });
        let texture_entry = |binding| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("composite"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                texture_entry(1),
                texture_entry(2),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("composite"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("composite"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        let blank = device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("blank"),
                size: wgpu::Extent3d {
                    width: 1,
                    height: 1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: Channels::Picture.format(),
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            })
            .create_view(&Default::default());
        Compositor {
            pipeline,
            layout,
            blank,
            srgb_target: format.is_srgb(),
        }
    }
}

/// A frame slower than this (ms) is not redrawn while the view moves.
pub const SLOW_FRAME_MS: f64 = 100.0;

/// One pane's GPU state, shared by the UI thread (which creates and prepares the
/// method) and the paint callback (which draws it).
pub struct PaneSurface {
    pub method: Option<Box<dyn Method>>,
    pub target: Option<CoverageTarget>,
    /// Bumped whenever the method is replaced or prepared again.
    pub generation: u64,
    /// The camera and generation the target's contents were drawn for.
    pub drawn: Option<(Camera, u64)>,
    /// Why the last frame could not be drawn.
    pub draw_error: Option<String>,
    /// Wall time of the last frame's recording, ms (a peer that submits its own work
    /// on a software device waits for it there).
    pub last_encode_ms: Option<f64>,
    pub timer: FrameTimer,
    uniform: Option<wgpu::Buffer>,
    bind_group: Option<wgpu::BindGroup>,
}

pub type SharedSurface = Arc<Mutex<PaneSurface>>;

/// Locks a surface; a panic elsewhere while it was held leaves nothing half-written
/// that matters here, so a poisoned lock is used as is.
pub fn lock(surface: &Mutex<PaneSurface>) -> MutexGuard<'_, PaneSurface> {
    surface.lock().unwrap_or_else(|p| p.into_inner())
}

impl PaneSurface {
    pub fn new() -> SharedSurface {
        Arc::new(Mutex::new(PaneSurface {
            method: None,
            target: None,
            generation: 0,
            drawn: None,
            draw_error: None,
            last_encode_ms: None,
            timer: FrameTimer::default(),
            uniform: None,
            bind_group: None,
        }))
    }

    /// Whether the target holds a frame drawn for `camera` with the current method.
    pub fn shows(&self, camera: &Camera) -> bool {
        self.drawn == Some((*camera, self.generation))
    }

    /// Whether the pane waits for the view to rest before drawing again: its last frame
    /// took longer than [`SLOW_FRAME_MS`] (vello on a software device), so drawing it
    /// while the view moves would stall every pane.
    pub fn waits_for_rest(&self) -> bool {
        self.drawn.is_some() && self.last_encode_ms.is_some_and(|ms| ms > SLOW_FRAME_MS)
    }

    /// Draws the method for `camera` into a target of the camera's size, unless the
    /// target already shows exactly that.
    fn draw(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        always: bool,
        moving: bool,
    ) {
        if (self.shows(camera) || (moving && self.waits_for_rest())) && !always {
            return;
        }
        let Some(method) = self.method.as_mut() else {
            return;
        };
        let fits = self
            .target
            .as_ref()
            .is_some_and(|t| (t.width, t.height) == (camera.width, camera.height));
        if !fits {
            self.target = None;
            match CoverageTarget::new(gpu, camera.width, camera.height, Channels::Picture) {
                Ok(t) => self.target = Some(t),
                Err(e) => {
                    self.draw_error = Some(e.to_string());
                    return;
                }
            }
        }
        let target = self.target.as_ref().expect("made above");
        let slot = self.timer.begin(gpu, encoder);
        let start = web_time::Instant::now();
        let result = method.encode(gpu, encoder, target, camera);
        let encode_ms = ms_since(start);
        self.timer.record_cpu(encode_ms);
        self.last_encode_ms = Some(encode_ms);
        if let Some(slot) = slot {
            self.timer.end(encoder, slot);
        }
        match result {
            Ok(()) => {
                self.draw_error = None;
                self.drawn = Some((*camera, self.generation));
            }
            Err(e) => {
                self.draw_error = Some(e.to_string());
                self.drawn = None;
            }
        }
    }
}

/// The reference's coverage on the GPU, in alpha like a target's.
pub type ReferenceTexture = Arc<Mutex<Option<wgpu::Texture>>>;

/// A texture a pane shows: a pane's target, or the reference.
#[derive(Clone)]
pub enum Source {
    Pane(SharedSurface),
    Reference(ReferenceTexture),
}

impl Source {
    fn view(&self) -> Option<wgpu::TextureView> {
        match self {
            Source::Pane(surface) => lock(surface).target.as_ref().map(|t| t.view.clone()),
            Source::Reference(texture) => texture
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .as_ref()
                .map(|t| t.create_view(&Default::default())),
        }
    }
}

/// What one pane's callback does this frame.
pub struct PanePaint {
    pub gpu: GpuContext,
    pub compositor: Arc<Compositor>,
    /// The pane's own surface: its method and target, its uniform and bind group.
    pub surface: SharedSurface,
    /// Draw the pane's method for this camera first (None: show sources only).
    pub camera: Option<Camera>,
    /// Redraw even if nothing changed (continuous mode, for live timing).
    pub always: bool,
    /// The textures shown; the pane's own target when `first` is None.
    pub first: Option<Source>,
    pub second: Option<Source>,
    pub mode: CompositeMode,
    pub text: egui::Rgba,
    pub background: egui::Rgba,
    pub difference_scale: f32,
    /// How coverage is shown (`CompositeMode::Coverage` only).
    pub display: DisplayMode,
    /// Stem darkening (`CompositeMode::Coverage` only).
    pub darkening: CoverageAdjust,
    /// Each texel drawn as a block of this many pixels a side (the magnifier).
    pub block: u32,
    /// The view is moving: a slow pane keeps its last picture until it rests.
    pub moving: bool,
    /// The pane, in points.
    pub rect: egui::Rect,
}

impl egui_wgpu::CallbackTrait for PanePaint {
    fn prepare(
        &self,
        _device: &wgpu::Device,
        queue: &wgpu::Queue,
        screen: &egui_wgpu::ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        _resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let gpu = &self.gpu;
        let first = self.first.as_ref().and_then(Source::view);
        let second = self.second.as_ref().and_then(Source::view);
        let mut surface = lock(&self.surface);
        if let Some(camera) = &self.camera {
            surface.draw(gpu, encoder, camera, self.always, self.moving);
        }
        let first = first.or_else(|| surface.target.as_ref().map(|t| t.view.clone()));
        let first = match (self.mode, first) {
            (CompositeMode::HeatScale, _) => self.compositor.blank.clone(),
            (_, Some(view)) => view,
            (_, None) => {
                surface.bind_group = None;
                return Vec::new();
            }
        };
        let ppp = screen.pixels_per_point;
        // egui rounds the callback's viewport the same way.
        let origin = (self.rect.min.to_vec2() * ppp).round();
        let size = (self.rect.size() * ppp).round();
        let uniform = CompositeUniform {
            origin: [origin.x, origin.y],
            size: [size.x.max(1.0), size.y.max(1.0)],
            text: self.text.to_array(),
            background: self.background.to_array(),
            mode: match self.mode {
                CompositeMode::Coverage => 0,
                CompositeMode::OverlayPicture => 1,
                CompositeMode::Difference => 2,
                CompositeMode::HeatScale => 3,
            },
            srgb_target: u32::from(self.compositor.srgb_target),
            difference_scale: self.difference_scale,
            block: self.block as f32,
            display: self.display.shader_index(),
            edge_darkening: self.darkening.edge_px,
            darkening_exponent: self.darkening.exponent,
            grid: u32::from(self.block >= GRID_FROM),
        };
        let buffer = surface.uniform.get_or_insert_with(|| {
            gpu.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("composite"),
                size: size_of::<CompositeUniform>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        });
        queue.write_buffer(buffer, 0, bytemuck::bytes_of(&uniform));
        let second = second.unwrap_or_else(|| self.compositor.blank.clone());
        let bind_group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("composite"),
            layout: &self.compositor.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&first),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(&second),
                },
            ],
        });
        surface.bind_group = Some(bind_group);
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        _resources: &egui_wgpu::CallbackResources,
    ) {
        let surface = lock(&self.surface);
        if let Some(bind_group) = &surface.bind_group {
            pass.set_pipeline(&self.compositor.pipeline);
            pass.set_bind_group(0, bind_group, &[]);
            pass.draw(0..3, 0..1);
        }
    }
}

/// Live GPU time of a pane's frames: timestamps around the method's passes on egui's
/// own encoder, read back a frame or two later without waiting, kept as a rolling window.
#[derive(Default)]
pub struct FrameTimer {
    slots: Vec<TimerSlot>,
    recent: VecDeque<f64>,
    /// The CPU's time recording each of the recent frames (the method's `encode`).
    recent_cpu: VecDeque<f64>,
}

/// Frames the rolling median is taken over.
const TIMED_WINDOW: usize = 15;
/// Readbacks in flight at most; a frame finding none free goes untimed.
const TIMER_SLOTS: usize = 4;

const FREE: u8 = 0;
const RECORDED: u8 = 1;
const MAPPING: u8 = 2;
const MAPPED: u8 = 3;

struct TimerSlot {
    timestamps: Timestamps,
    state: Arc<AtomicU8>,
}

impl FrameTimer {
    fn begin(&mut self, gpu: &GpuContext, encoder: &mut wgpu::CommandEncoder) -> Option<usize> {
        if !gpu.has_timestamps() {
            return None;
        }
        let free = self
            .slots
            .iter()
            .position(|s| s.state.load(Ordering::Acquire) == FREE);
        let index = match free {
            Some(i) => i,
            None if self.slots.len() < TIMER_SLOTS => {
                self.slots.push(TimerSlot {
                    timestamps: Timestamps::new(gpu, "pane timestamps", 2),
                    state: Arc::new(AtomicU8::new(FREE)),
                });
                self.slots.len() - 1
            }
            None => return None,
        };
        self.slots[index].timestamps.write(encoder, 0);
        Some(index)
    }

    fn end(&mut self, encoder: &mut wgpu::CommandEncoder, index: usize) {
        let slot = &self.slots[index];
        slot.timestamps.write(encoder, 1);
        slot.timestamps.resolve(encoder);
        slot.state.store(RECORDED, Ordering::Release);
    }

    /// Called from the UI each frame, after the frames recorded so far were submitted:
    /// starts reading the recorded slots and takes the times that have arrived.
    pub fn collect(&mut self, gpu: &GpuContext) {
        for slot in &self.slots {
            let readable = &slot.timestamps.readable;
            match slot.state.load(Ordering::Acquire) {
                RECORDED => {
                    slot.state.store(MAPPING, Ordering::Release);
                    let state = slot.state.clone();
                    readable.map_async(wgpu::MapMode::Read, .., move |result| {
                        state.store(
                            if result.is_ok() { MAPPED } else { FREE },
                            Ordering::Release,
                        );
                    });
                }
                MAPPED => {
                    if let Ok(bytes) = readable.get_mapped_range(..) {
                        let intervals = intervals_ms(gpu, &bytes);
                        drop(bytes);
                        for ms in intervals {
                            if self.recent.len() == TIMED_WINDOW {
                                self.recent.pop_front();
                            }
                            self.recent.push_back(ms);
                        }
                    }
                    readable.unmap();
                    slot.state.store(FREE, Ordering::Release);
                }
                _ => {}
            }
        }
        // Fires the map callbacks of readbacks that have finished; never waits.
        let _ = gpu.device.poll(wgpu::PollType::Poll);
    }

    /// Median GPU time of the recent frames, and how many there are.
    pub fn median_ms(&self) -> Option<(f64, usize)> {
        crate::metrics::median(self.recent.iter().copied()).map(|m| (m, self.recent.len()))
    }

    fn record_cpu(&mut self, ms: f64) {
        if self.recent_cpu.len() == TIMED_WINDOW {
            self.recent_cpu.pop_front();
        }
        self.recent_cpu.push_back(ms);
    }

    /// Median CPU time of recording the recent frames.
    pub fn median_cpu_ms(&self) -> Option<f64> {
        crate::metrics::median(self.recent_cpu.iter().copied())
    }

    pub fn clear(&mut self) {
        self.recent.clear();
        self.recent_cpu.clear();
    }
}

/// Writes reference coverage into `texture` (coverage in alpha, as the compositor reads
/// a target), making the texture anew when the size changed.
pub fn upload_reference(gpu: &GpuContext, texture: &ReferenceTexture, image: &CoverageImage) {
    let mut slot = texture.lock().unwrap_or_else(|p| p.into_inner());
    let size = wgpu::Extent3d {
        width: image.width,
        height: image.height,
        depth_or_array_layers: 1,
    };
    if slot.as_ref().is_none_or(|t| t.size() != size) {
        *slot = Some(gpu.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("reference coverage"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: Channels::Picture.format(),
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        }));
    }
    let texture = slot.as_ref().expect("made above");
    let texels: Vec<half::f16> = image
        .data
        .iter()
        .flat_map(|&c| [0.0, 0.0, 0.0, c].map(half::f16::from_f32))
        .collect();
    gpu.queue.write_texture(
        texture.as_image_copy(),
        bytemuck::cast_slice(&texels),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(image.width * 8),
            rows_per_image: None,
        },
        size,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_compositor_shader_is_valid_wgsl() {
        let module = naga::front::wgsl::parse_str(&composite_wgsl()).unwrap();
        naga::valid::Validator::new(Default::default(), naga::valid::Capabilities::all())
            .validate(&module)
            .unwrap();
    }
}
