//! `xor-stencil`: Evan Wallace's "easy scalable text rendering" (as Steffen Haug's
//! "Graphics project" report quotes it, in its section "A more beautiful algorithm"),
//! counted in the stencil buffer.
//!
//! Each contour is drawn as a fan of triangles from its first point over every segment's
//! chord — the polygon through the segment endpoints — plus one Loop–Blinn triangle
//! (p0, p1, p2) per quadratic that keeps only the samples between the chord and the
//! curve (u² − v < 0). Summed with their orientations, these triangles give every
//! sample the outline's exact winding number: the stencil adds +1 for front faces and
//! −1 for back faces (nonzero, 8-bit wrapping counters), or flips a bit (even-odd, Haug's
//! XOR). A cover quad per instance then writes coverage where the stencil says
//! "inside" and clears it. No curve is solved and no epsilon decides anything: what is
//! inside is decided per sample by the rasterizer's own tie rules on shared edges.
//!
//! Anti-aliasing is by point samples, box-filtered: hardware MSAA (`msaa`, 1 or 4)
//! and `passes` jittered repetitions of the whole frame, each adding 1/passes of
//! coverage (Wallace used 6). One frame is one render pass; a pass's covers clear the
//! stencil for the next. See [`jitter_offsets`] for the sample pattern.
//!
//! Cubics are drawn as quadratics within
//! [`DEFAULT_QUAD_TOLERANCE_EM`](crate::geometry::DEFAULT_QUAD_TOLERANCE_EM),
//! tightened as the view zooms in past 4096 px/em so that the conversion stays within
//! 1/16 px. The 8-bit counters are wrong only where the winding number is a nonzero
//! multiple of 256 (Wallace's 4-bit ones, at multiples of 16).
//!
//! Instances: under nonzero, all instances count into one stencil, so where instances
//! overlap their windings add, exactly as the reference sums them. Even-odd is a
//! per-outline rule, so there instances are split into layers whose members cannot
//! touch; each layer's parity is folded into a "covered" stencil bit before the next
//! layer draws, and overlapping glyphs unite instead of cancelling.
//!
//! The code, one concern a file, each importing only the ones above it:
//! - `params.rs`: the name, and the fill rule, samples, passes and overlay its
//!   parameters choose.
//! - `geometry.rs`: each glyph's fan and Loop–Blinn triangles (CPU) and their buffers.
//! - `jitter.rs`: the N-rooks pattern of the jittered passes.
//! - `layers.rs`: even-odd's split of the instances into layers that cannot touch.
//! - `pipelines.rs`: the stencil states and render pipelines (the wireframe's lines
//!   among them), and the uniform buffer of the passes' jitter.
//! - `prepared.rs`: a scene on the GPU, each frame's runs of visible instances, and
//!   recording a frame from them — count into the stencil, fold layers, cover, then
//!   the wireframe.
//! - `count.rs`: `curves_per_pixel`, the Loop–Blinn evaluations per covered pixel.
//!
//! Shader: `shaders/xor_stencil.wgsl`.

mod count;
mod geometry;
mod jitter;
mod layers;
mod params;
mod pipelines;
mod prepared;

pub use geometry::{GeometryData, Triangles, tolerance_halvings};
pub use jitter::jitter_offsets;
pub use params::{FillRule, MAX_PASSES, NAME, PARAMS, Settings};

use super::info::{Claim, ClaimedSetting, MethodInfo, Role, Trait, bench_at, within_on_edges};
use super::params::Params;
use super::sample_pattern::ALIASED_EDGE_MAE_255;
use super::{CurveCost, Method, Overlay};
use crate::Error;
use crate::camera::Camera;
use crate::gpu::msaa::Attachments;
use crate::gpu::{Channels, CoverageTarget, GpuContext};
use crate::scene::Scene;
use params::OVERLAYS;
use pipelines::{Pipelines, SHADER};
use prepared::{Prepared, record_passes, record_wireframe};

/// `xor-stencil`'s row in the registry.
pub const INFO: MethodInfo = MethodInfo {
    name: NAME,
    summary: "winding counted per sample in the stencil by a triangle fan and Loop–Blinn \
              curve triangles, MSAA and jittered passes (Evan Wallace's method)",
    role: Role::Method,
    shader: Some(SHADER),
    params: PARAMS,
    colour: [214, 39, 40],
    // Samples × jittered passes: from aliased to 16 coverage levels and beyond.
    bench: &[
        bench_at(&[], true),
        bench_at(&[("msaa", "1"), ("passes", "1")], true),
        bench_at(&[("msaa", "4"), ("passes", "1")], false),
        bench_at(&[("msaa", "1"), ("passes", "4")], false),
        bench_at(&[("msaa", "1"), ("passes", "16")], false),
    ],
    claims: &[ClaimedSetting {
        label: NAME,
        params: &[],
        claim: Claim {
            // The mean is over edge pixels, where a sampled method's error lives: over a
            // glyph's slot it grows with the share of edge pixels, and a bound of
            // 3.3/255 there broke on 497 glyphs dense in edges (`glyphscope survey
            // --fonts fonts`) that no pixel found wrong by more than 0.5. Over edge
            // pixels the claim is that the samples beat aliasing: under one centre
            // sample's mean error on a straight edge (49/255, `ALIASED_EDGE_MAE_255`),
            // which coverage rounded to 0 or 1 breaks. The default's 16 samples are off
            // by 0.040 on average there (10/255) and 0.234 at worst
            // (`the_patterns_straight_edge_errors`); corners, curves and several edges
            // in a pixel raise the mean over a glyph. Set after the survey had shown
            // edge means up to 37.2/255 (⌨, ▒ at 9 px/em), from the rule, not from it.
            bound: Some(within_on_edges(0.5, ALIASED_EDGE_MAE_255)),
            except: &[Trait::DeepWinding],
            // A wrapped counter reads a covered pixel as empty: no bound.
            limitation: None,
            temporal: None,
            statement: "16 samples (4x MSAA, 4 jittered passes): no pixel off by more than \
                        0.5, and edge pixels off by less on average than one sample at the \
                        centre is on a straight edge (49/255); 8-bit counters read a \
                        winding of 256 as 0",
        },
    }],
    constructor: Some(&|params| Ok(Box::new(XorStencil::new(params)))),
};

pub struct XorStencil {
    settings: Settings,
    /// Built on the first `prepare`; they depend on the device and the settings only.
    pipelines: Option<Pipelines>,
    prepared: Option<Prepared>,
    attachments: Option<Attachments>,
}

impl XorStencil {
    pub fn new(params: &Params) -> XorStencil {
        XorStencil::with_settings(Settings::from_params(params))
    }

    pub fn with_settings(settings: Settings) -> XorStencil {
        XorStencil {
            settings,
            pipelines: None,
            prepared: None,
            attachments: None,
        }
    }
}

impl Method for XorStencil {
    fn name(&self) -> &'static str {
        NAME
    }

    fn prepare(&mut self, gpu: &GpuContext, scene: &Scene) -> Result<(), Error> {
        gpu.catching_errors("preparing 'xor-stencil'", || {
            let pipelines = self
                .pipelines
                .get_or_insert_with(|| Pipelines::new(gpu, &self.settings));
            self.prepared = Some(Prepared::new(gpu, pipelines, self.settings.fill, scene));
            Ok(())
        })
    }

    fn encode(
        &mut self,
        gpu: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        target: &CoverageTarget,
        camera: &Camera,
    ) -> Result<(), Error> {
        let (Some(pipelines), Some(prepared)) = (&mut self.pipelines, &mut self.prepared) else {
            return Err(super::not_prepared(NAME));
        };
        let draws = pipelines.draws(gpu, target.channels);
        prepared.update(gpu, pipelines, camera)?;
        let attachments = Attachments::fit(
            self.attachments.take(),
            gpu,
            target,
            self.settings.samples,
            true,
        );
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some(NAME),
                color_attachments: &[Some(
                    attachments.color(target, wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT)),
                )],
                depth_stencil_attachment: attachments.stencil(true),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            if prepared.visible > 0 {
                record_passes(&mut pass, pipelines, &draws, prepared, self.settings.passes);
                if let Some(lines) = &draws.wireframe {
                    record_wireframe(&mut pass, lines, pipelines, prepared, self.settings.passes);
                }
            }
        }
        self.attachments = Some(attachments);
        Ok(())
    }

    fn gpu_bytes(&self) -> u64 {
        let jitter = self.pipelines.as_ref().map_or(0, |p| p.jitter.size());
        let prepared = self.prepared.as_ref().map_or(0, Prepared::bytes);
        let attachments = self.attachments.as_ref().map_or(0, Attachments::bytes);
        jitter + prepared + attachments
    }

    fn overlays(&self) -> &'static [Overlay] {
        OVERLAYS
    }

    /// Loop–Blinn evaluations (u² − v, one per covered sample of a curve triangle, in
    /// every pass) per covered pixel, counted by drawing the frame's curve triangles
    /// into an additive target with the frame's samples and jitter.
    fn curves_per_pixel(
        &mut self,
        gpu: &GpuContext,
        camera: &Camera,
    ) -> Result<Option<CurveCost>, Error> {
        let target = CoverageTarget::new(gpu, camera.width, camera.height, Channels::Picture)?;
        super::frame::render_frame(gpu, self, &target, camera)?;
        let coverage = target.readback(gpu)?;
        let (Some(pipelines), Some(prepared)) = (&mut self.pipelines, &self.prepared) else {
            unreachable!("render_frame succeeded, so the method is prepared");
        };
        count::curve_cost(
            gpu,
            pipelines,
            prepared,
            &self.settings,
            &target,
            &coverage.data,
        )
    }
}
