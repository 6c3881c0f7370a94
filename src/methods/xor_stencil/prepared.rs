//! A scene on the GPU — its instances ordered by (layer, glyph), its triangles, their
//! bind group — each frame's runs of visible instances, one draw per run, and the
//! recording of a frame from them: in each jittered pass, every layer's fan and curve
//! triangles counted into the stencil (and under even-odd folded into the covered
//! bit), then the covers that add the pass's coverage where the stencil says inside and
//! clear it; the wireframe overlay's lines last.

use std::ops::Range;

use super::geometry::{Geometry, tolerance_halvings};
use super::layers::disjoint_layers;
use super::params::{FillRule, NAME};
use super::pipelines::{COVERED_BIT, Draws, Jitter, Pipelines};
use crate::Error;
use crate::camera::Camera;
use crate::geometry::{Segment, jacobian_bound};
use crate::gpu::instances::Instances;
use crate::gpu::{GpuContext, kit};
use crate::scene::Scene;

/// What `prepare` made of a scene, and the frame last written.
pub(super) struct Prepared {
    /// The scene with its instances ordered by (layer, glyph).
    scene: Scene,
    pub(super) instances: Instances,
    /// (layer, glyph) of each instance.
    keys: Vec<(u32, u32)>,
    /// Whether any glyph has cubics: only then does the geometry depend on the zoom.
    has_cubics: bool,
    pub(super) geometry: Geometry,
    pub(super) bind_group: wgpu::BindGroup,
    /// This frame's draws: runs of visible instances with one (layer, glyph).
    pub(super) runs: Vec<Run>,
    /// How many instances this frame draws.
    pub(super) visible: u32,
}

/// Consecutive instances of one (layer, glyph), drawn by one call.
#[derive(Clone, Debug)]
pub(super) struct Run {
    pub(super) layer: u32,
    pub(super) glyph: usize,
    pub(super) instances: Range<u32>,
}

/// Binds the method's own buffers (`@group(1)`): glyph bounds, fan and curve points, and
/// one `Jitter` whose offset each pass picks.
fn bind_group(gpu: &GpuContext, pipelines: &Pipelines, geometry: &Geometry) -> wgpu::BindGroup {
    let [bounds, fan, curves] = &geometry.buffers;
    kit::bind_group(
        gpu,
        NAME,
        &pipelines.layout,
        &[
            bounds.as_entire_binding(),
            fan.as_entire_binding(),
            curves.as_entire_binding(),
            wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer: &pipelines.jitter,
                offset: 0,
                size: wgpu::BufferSize::new(size_of::<Jitter>() as u64),
            }),
        ],
    )
}

impl Prepared {
    pub(super) fn new(
        gpu: &GpuContext,
        pipelines: &Pipelines,
        fill: FillRule,
        scene: &Scene,
    ) -> Prepared {
        // Instances ordered by (layer, glyph): each run is one draw.
        let layers = match fill {
            FillRule::NonZero => vec![0; scene.instances.len()],
            FillRule::EvenOdd => disjoint_layers(scene, scene.units_per_em / 1024.0),
        };
        let mut order: Vec<usize> = (0..scene.instances.len()).collect();
        order.sort_by_key(|&i| (layers[i], scene.instances[i].glyph));
        let keys = order
            .iter()
            .map(|&i| (layers[i], scene.instances[i].glyph))
            .collect();
        let scene = Scene {
            units_per_em: scene.units_per_em,
            glyphs: scene.glyphs.clone(),
            instances: order.iter().map(|&i| scene.instances[i]).collect(),
            source: None,
        };
        let instances = Instances::new(gpu, &scene);
        let geometry = Geometry::new(gpu, &scene, 0);
        let bind_group = bind_group(gpu, pipelines, &geometry);
        Prepared {
            has_cubics: scene.glyphs.iter().any(|g| {
                g.outline
                    .segments()
                    .any(|s| matches!(s, Segment::Cubic(..)))
            }),
            scene,
            instances,
            keys,
            geometry,
            bind_group,
            runs: Vec::new(),
            visible: 0,
        }
    }

    /// Writes this frame's instances, finds its runs, and converts the cubics again if
    /// the zoom asks for another tolerance.
    pub(super) fn update(
        &mut self,
        gpu: &GpuContext,
        pipelines: &Pipelines,
        camera: &Camera,
    ) -> Result<(), Error> {
        // The jitter moves the image by under half a pixel.
        self.visible = self.instances.update(gpu, camera, 0.5)?;
        self.runs.clear();
        let mut px_per_em = 0.0f64;
        for (slot, &index) in self.instances.written().iter().enumerate() {
            let (layer, glyph) = self.keys[index as usize];
            let (glyph, slot) = (glyph as usize, slot as u32);
            match self.runs.last_mut() {
                Some(run) if run.layer == layer && run.glyph == glyph => {
                    run.instances.end = slot + 1
                }
                _ => self.runs.push(Run {
                    layer,
                    glyph,
                    instances: slot..slot + 1,
                }),
            }
            if self.has_cubics {
                let pen = self.scene.instances[index as usize].position;
                let to_image = camera.glyph_to_image(self.scene.units_per_em, pen);
                let bounds = self.scene.glyphs[glyph].bounds;
                px_per_em =
                    px_per_em.max(jacobian_bound(&to_image, &bounds) * self.scene.units_per_em);
            }
        }
        let halvings = tolerance_halvings(px_per_em);
        if halvings != self.geometry.halvings {
            self.geometry = Geometry::new(gpu, &self.scene, halvings);
            self.bind_group = bind_group(gpu, pipelines, &self.geometry);
        }
        Ok(())
    }

    pub(super) fn bytes(&self) -> u64 {
        self.instances.bytes()
            + self
                .geometry
                .buffers
                .iter()
                .map(wgpu::Buffer::size)
                .sum::<u64>()
    }
}

/// Records every pass of a frame: per layer the fan and curve triangles into the stencil
/// (and, under even-odd, the layer folded into the covered bit), then the covers.
pub(super) fn record_passes(
    pass: &mut wgpu::RenderPass<'_>,
    pipelines: &Pipelines,
    draws: &Draws,
    prepared: &Prepared,
    passes: u32,
) {
    for k in 0..passes {
        pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
        pass.set_bind_group(1, &prepared.bind_group, &[pipelines.jitter_offset(k)]);
        for layer in prepared.runs.chunk_by(|a, b| a.layer == b.layer) {
            for (pipeline, ranges) in [
                (&draws.fan, &prepared.geometry.fan_ranges),
                (&draws.curve, &prepared.geometry.curve_ranges),
            ] {
                pass.set_pipeline(pipeline);
                draw_runs(pass, layer, ranges, 1);
            }
            if let Some(fold) = &draws.fold_layer {
                pass.set_pipeline(fold);
                pass.set_stencil_reference(COVERED_BIT);
                let first = layer[0].instances.start;
                let last = layer[layer.len() - 1].instances.end;
                pass.draw(0..4, first..last);
            }
        }
        pass.set_pipeline(&draws.cover);
        pass.set_stencil_reference(0);
        pass.draw(0..4, 0..prepared.visible);
    }
}

/// Draws each of `runs` with its glyph's points in `ranges` (per distinct glyph), as
/// `vertices_per_point` vertices each, skipping glyphs without any.
pub(super) fn draw_runs(
    pass: &mut wgpu::RenderPass<'_>,
    runs: &[Run],
    ranges: &[Range<u32>],
    vertices_per_point: u32,
) {
    for run in runs {
        let points = &ranges[run.glyph];
        if !points.is_empty() {
            let vertices = vertices_per_point * points.start..vertices_per_point * points.end;
            pass.draw(vertices, run.instances.clone());
        }
    }
}

/// Draws the edges of every visible instance's triangles with `lines`, after the
/// `passes` jittered passes, at the unshifted `Jitter` that follows theirs.
pub(super) fn record_wireframe(
    pass: &mut wgpu::RenderPass<'_>,
    lines: &[wgpu::RenderPipeline; 2],
    pipelines: &Pipelines,
    prepared: &Prepared,
    passes: u32,
) {
    let unshifted = pipelines.jitter_offset(passes);
    pass.set_bind_group(0, prepared.instances.bind_group(), &[]);
    pass.set_bind_group(1, &prepared.bind_group, &[unshifted]);
    for (pipeline, ranges) in lines.iter().zip([
        &prepared.geometry.fan_ranges,
        &prepared.geometry.curve_ranges,
    ]) {
        pass.set_pipeline(pipeline);
        // Six line vertices per triangle's three points.
        draw_runs(pass, &prepared.runs, ranges, 2);
    }
}
