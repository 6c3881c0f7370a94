//! Per-instance data for the methods that draw each glyph instance through its own
//! transform (`GlyphInstance` in `crates/gpu/shaders/common.wgsl`): the homography from the glyph's
//! local font units to image pixels, its inverse, and which distinct glyph it draws.
//!
//! Rewritten every frame, since the camera moves; composed in f64 and rounded to f32
//! only once it is relative to the glyph and the view, so a far-away world position
//! never reaches the GPU.

use std::ops::Range;

use glam::{DMat3, DVec2};

use glyphscope_core::Error;
use glyphscope_core::camera::Camera;
use glyphscope_core::geometry::Rect;
use glyphscope_core::scene::Scene;

use crate::{GpuContext, kit};

/// `GlyphInstance` as WGSL lays it out in a storage buffer (mat3x3 columns are padded
/// to 16 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuInstance {
    to_image: [[f32; 4]; 3],
    to_local: [[f32; 4]; 3],
    glyph: u32,
    _pad: u32,
    /// The text library's premultiplied colour for a glyph drawn straight into a
    /// caller's target, as four 16-bit fractions of 65535; zero for the rows.
    colour: [u32; 2],
}

// WGSL's layout of `GlyphInstance`: two padded mat3x3 (96 bytes), the glyph, a word of
// padding for the vec2's alignment, the colour; 112 bytes in all.
const _: () = assert!(size_of::<GpuInstance>() == 112);
const _: () = assert!(std::mem::offset_of!(GpuInstance, colour) == 104);

impl GpuInstance {
    /// Glyph `glyph` drawn through `to_image` (local font units to image pixels).
    pub fn new(to_image: &DMat3, glyph: u32) -> GpuInstance {
        GpuInstance {
            to_image: columns(to_image),
            to_local: columns(&to_image.inverse()),
            glyph,
            _pad: 0,
            colour: [0; 2],
        }
    }

    /// The same instance drawn in `colour` (premultiplied, each component in 0..=1,
    /// rounded to a multiple of 1/65535: pass one that is, to draw it exactly).
    pub fn coloured(self, colour: [f32; 4]) -> GpuInstance {
        let fraction = |c: f32| (c.clamp(0.0, 1.0) * 65535.0).round() as u32;
        let pair = |a: f32, b: f32| fraction(a) | (fraction(b) << 16);
        GpuInstance {
            colour: [pair(colour[0], colour[1]), pair(colour[2], colour[3])],
            ..self
        }
    }
}

fn columns(m: &DMat3) -> [[f32; 4]; 3] {
    [m.x_axis, m.y_axis, m.z_axis].map(|c| [c.x as f32, c.y as f32, c.z as f32, 0.0])
}

/// The scene's instances on the GPU, culled to the view each frame.
pub struct Instances {
    units_per_em: f64,
    /// (pen position, distinct glyph index, local bounds) per instance.
    placed: Vec<(DVec2, u32, Rect)>,
    staging: Vec<GpuInstance>,
    /// Which instances the last update wrote, in buffer order.
    written: Vec<u32>,
    buffer: wgpu::Buffer,
    /// `Frame` of `common.wgsl`: the target size.
    frame: wgpu::Buffer,
    /// `@group(0)` of every method shader: `frame` and `buffer`.
    bind_group: wgpu::BindGroup,
}

impl Instances {
    pub fn new(gpu: &GpuContext, scene: &Scene) -> Instances {
        let placed: Vec<_> = scene
            .instances
            .iter()
            .map(|i| (i.position, i.glyph, scene.glyphs[i.glyph as usize].bounds))
            .collect();
        Instances::with_room(gpu, scene.units_per_em, placed)
    }

    /// Instances their caller places itself, each through its own transform (text runs:
    /// [`write`](Self::write)), with room for `capacity` to start with.
    pub fn placed_by_caller(gpu: &GpuContext, capacity: usize) -> Instances {
        let mut instances = Instances::with_room(gpu, 1.0, Vec::new());
        instances.grow(gpu, capacity);
        instances
    }

    fn with_room(
        gpu: &GpuContext,
        units_per_em: f64,
        placed: Vec<(DVec2, u32, Rect)>,
    ) -> Instances {
        let frame = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("frame"),
            size: size_of::<[f32; 2]>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let (buffer, bind_group) = Instances::storage(gpu, &frame, placed.len());
        Instances {
            units_per_em,
            staging: Vec::with_capacity(placed.len()),
            written: Vec::with_capacity(placed.len()),
            placed,
            buffer,
            frame,
            bind_group,
        }
    }

    /// A buffer with room for `count` instances (a binding cannot be empty: at least
    /// one) and the bind group of it and `frame`.
    fn storage(
        gpu: &GpuContext,
        frame: &wgpu::Buffer,
        count: usize,
    ) -> (wgpu::Buffer, wgpu::BindGroup) {
        let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("glyph instances"),
            size: (count.max(1) * size_of::<GpuInstance>()) as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = kit::bind_group(
            gpu,
            "frame and instances",
            &kit::frame_layout(gpu),
            &[frame.as_entire_binding(), buffer.as_entire_binding()],
        );
        (buffer, bind_group)
    }

    /// Makes room for `count` instances, doubling the buffer when it is too small.
    fn grow(&mut self, gpu: &GpuContext, count: usize) {
        let room = self.buffer.size() as usize / size_of::<GpuInstance>();
        if count > room {
            let (buffer, bind_group) = Instances::storage(gpu, &self.frame, count.max(2 * room));
            self.buffer = buffer;
            self.bind_group = bind_group;
        }
    }

    /// Gives back room past four times `count` instances (a buffer that grew for frames
    /// long gone), keeping twice `count`.
    pub fn shrink_to(&mut self, gpu: &GpuContext, count: usize) {
        let room = self.buffer.size() as usize / size_of::<GpuInstance>();
        if room > 4 * count.max(1) {
            let (buffer, bind_group) = Instances::storage(gpu, &self.frame, 2 * count.max(1));
            self.buffer = buffer;
            self.bind_group = bind_group;
        }
    }

    /// Writes `items` as the instances to draw and `size` as the target's, for
    /// instances placed by their caller; returns the bytes uploaded.
    pub fn write(&mut self, gpu: &GpuContext, size: [u32; 2], items: &[GpuInstance]) -> u64 {
        self.grow(gpu, items.len());
        let size = size.map(|v| v as f32);
        gpu.queue
            .write_buffer(&self.frame, 0, bytemuck::cast_slice(&size));
        if !items.is_empty() {
            gpu.queue
                .write_buffer(&self.buffer, 0, bytemuck::cast_slice(items));
        }
        (size_of_val(&size) + size_of_val(items)) as u64
    }

    /// Writes this frame's transforms for the instances whose bounds, grown by `margin`
    /// pixels plus a pixel, reach the view; returns how many were written (draw that
    /// many instances). Fails if the tilt puts an instance behind the eye.
    pub fn update(&mut self, gpu: &GpuContext, camera: &Camera, margin: f64) -> Result<u32, Error> {
        // One key: one group, in the scene's order.
        let groups = self.update_grouped(gpu, camera, margin, |_, _| 0u8)?;
        Ok(groups.last().map_or(0, |(_, range)| range.end))
    }

    /// Like [`update`](Self::update), but writes the instances sorted by `key` — a
    /// function of each instance's distinct glyph and transform — and returns each
    /// key's range of written instances, in key order. Methods whose geometry differs
    /// per glyph (or per scale) draw one instanced draw per group.
    pub fn update_grouped<K: Ord + Copy>(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
        margin: f64,
        mut key: impl FnMut(u32, &DMat3) -> K,
    ) -> Result<Vec<(K, Range<u32>)>, Error> {
        let view = camera.grown_view(1.0 + margin);
        let mut keyed = Vec::with_capacity(self.placed.len());
        for (index, &(pen, glyph, bounds)) in (0u32..).zip(&self.placed) {
            let to_image = camera.glyph_to_image(self.units_per_em, pen);
            if !Camera::project_bounds(&to_image, &bounds)?.overlaps(&view) {
                continue;
            }
            let instance = GpuInstance::new(&to_image, glyph);
            keyed.push((key(glyph, &to_image), index, instance));
        }
        // Stable: within a group, instances keep the scene's order.
        keyed.sort_by_key(|&(k, _, _)| k);
        let mut groups: Vec<(K, Range<u32>)> = Vec::new();
        self.staging.clear();
        self.written.clear();
        for (index, &(k, scene_index, instance)) in (0u32..).zip(&keyed) {
            self.staging.push(instance);
            self.written.push(scene_index);
            match groups.last_mut() {
                Some((last, range)) if *last == k => range.end = index + 1,
                _ => groups.push((k, index..index + 1)),
            }
        }
        let size = [camera.width as f32, camera.height as f32];
        gpu.queue
            .write_buffer(&self.frame, 0, bytemuck::cast_slice(&size));
        if !self.staging.is_empty() {
            gpu.queue
                .write_buffer(&self.buffer, 0, bytemuck::cast_slice(&self.staging));
        }
        Ok(groups)
    }

    /// The instances the last update wrote, in buffer order, as indices into the
    /// scene's instances: methods that draw instances in runs (per glyph, per layer)
    /// find their runs here.
    pub fn written(&self) -> &[u32] {
        &self.written
    }

    /// `@group(0)` of every method shader: the `Frame` uniform and the
    /// `array<GlyphInstance>` (see [`kit::frame_layout`]).
    pub fn bind_group(&self) -> &wgpu::BindGroup {
        &self.bind_group
    }

    pub fn bytes(&self) -> u64 {
        self.buffer.size() + self.frame.size()
    }
}
