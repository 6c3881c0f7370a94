//! The compositor's `display_color` (composite.wgsl) against its CPU mirror
//! (`glyphscope::app::display::display_color`) on a ramp of coverage, for every mode.

mod common;

use common::run_probe;
use glyphscope::app::display::{
    CoverageAdjust, Darkening, DisplayMode, composite_wgsl, display_color, srgb_encode,
};
use glyphscope::gpu::GpuContext;

/// Inputs: coverage, then text rgb, background rgb, mode, edge darkening, exponent;
/// output rgb.
fn shader_display_color(gpu: &GpuContext, inputs: &[[f32; 12]]) -> Vec<[f32; 4]> {
    let probe = "
struct ProbeInput { a: vec4<f32>, b: vec4<f32>, c: vec4<f32> }
@group(1) @binding(0) var<storage, read> probe_inputs: array<ProbeInput>;
@group(1) @binding(1) var<storage, read_write> probe_outputs: array<vec4<f32>>;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x < arrayLength(&probe_inputs) {
        let v = probe_inputs[id.x];
        let rgb = display_color(v.a.x, v.a.yzw, v.b.xyz, u32(v.b.w), v.c.x, v.c.y);
        probe_outputs[id.x] = vec4<f32>(rgb, 0.0);
    }
}
";
    run_probe(
        gpu,
        format!("{}\n{probe}", composite_wgsl()),
        (1, 0),
        bytemuck::cast_slice(inputs),
        inputs.len(),
        16,
    )
    .chunks_exact(4)
    .map(|c| [c[0], c[1], c[2], c[3]])
    .collect()
}

/// Every mode, under each darkening (at 10 ppem, where both act), light on dark, dark on
/// light and coloured,
/// over coverage 0..=1 in 1/64 steps: the shader within 1e-4 of the mirror (f32 `pow`
/// on the GPU may differ by a few ulps; a wrong formula moves values by 1e-2 or more).
#[test]
fn the_shader_shows_coverage_as_its_cpu_mirror_does() {
    let gpu = common::gpu();
    let colours = [
        ([1.0, 1.0, 1.0], [0.0, 0.0, 0.0]),
        ([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]),
        ([0.8, 0.1, 0.05], [0.02, 0.05, 0.3]),
    ];
    let mut cases = Vec::new();
    for mode in DisplayMode::ALL {
        for darkening in Darkening::ALL {
            for (text, background) in colours {
                // The darkenings read the text colour as sRGB, as the app passes it.
                let adjust = darkening.adjust(10.0, text.map(srgb_encode));
                for k in 0..=64 {
                    cases.push((k as f32 / 64.0, text, background, mode, adjust));
                }
            }
        }
    }
    let inputs: Vec<[f32; 12]> = cases
        .iter()
        .map(
            |&(c, t, b, mode, d): &(f32, _, _, DisplayMode, CoverageAdjust)| {
                let index = mode.shader_index() as f32;
                [
                    c, t[0], t[1], t[2], b[0], b[1], b[2], index, d.edge_px, d.exponent, 0.0, 0.0,
                ]
            },
        )
        .collect();
    let shown = shader_display_color(gpu, &inputs);
    for (case, got) in cases.iter().zip(&shown) {
        let &(c, t, b, mode, d) = case;
        let want = display_color(c, t, b, mode, d);
        for i in 0..3 {
            assert!(
                got[i].is_finite() && (got[i] - want[i]).abs() <= 1e-4,
                "{case:?}: shader {got:?}, mirror {want:?}"
            );
        }
    }
}
