//! `tessellation` on the standard page (2 929 glyphs, DejaVu Sans at 16 px/em,
//! 1920×1080) under each setting: points, triangles, CPU tessellation time, GPU time
//! and error against the reference.
//!
//! On a shared machine a lone run's timing says little, so the settings take turns:
//! each round times a few frames of every setting, after a warm-up, and the table
//! gives the median over all rounds and the ratio to the default setting.
//!
//!     cargo run --release --example tessellation_page

use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::gpu::{Channels, CoverageTarget, GpuContext};
use glyphscope::methods::frame::{render_frame, time_frames};
use glyphscope::methods::{Method, registry};
use glyphscope::metrics::{self, compare};
use glyphscope::reference;
use glyphscope::scene::Scene;

const SETTINGS: [&[(&str, &str)]; 9] = [
    &[],
    &[("msaa", "1")],
    &[("tolerance_px", "0.05")],
    &[("tolerance_px", "0.25")],
    &[("subdivision", "asa")],
    &[("subdivision", "asa"), ("threshold", "13")],
    &[("subdivision", "fsa")],
    &[("subdivision", "fsa"), ("steps", "4")],
    &[("subdivision", "fsa"), ("msaa", "1")],
];
const ROUNDS: usize = 15;
const FRAMES_PER_ROUND: usize = 3;
/// Builds timed for the CPU figure; the least is quoted.
const BUILDS: usize = 5;

/// One setting's method and what was measured of it.
struct Run {
    label: String,
    method: Box<dyn Method>,
    build_ms: f64,
    times: Vec<f64>,
}

fn main() {
    let text = glyphscope::bench::scenes::PAGE_TEXT;
    let scene = Scene::from_text(&glyphscope::font::default_font(), text).unwrap();
    let camera = Camera::new(1920, 1080, 16.0, DVec2::new(24.0, 40.0));
    let gpu = GpuContext::new().unwrap();
    let target =
        CoverageTarget::new(&gpu, camera.width, camera.height, Channels::Coverage).unwrap();
    let expected = reference::rasterize(&scene, &camera).unwrap();
    println!(
        "{} instances, {} distinct glyphs, {}",
        scene.instances.len(),
        scene.glyphs.len(),
        gpu.adapter_name()
    );

    let mut runs = Vec::new();
    for setting in SETTINGS {
        let params: Vec<(String, String)> = setting
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        // The least CPU time of a few builds: prepare, and the first frame where the
        // meshes depend on the scale.
        let mut build_ms = f64::INFINITY;
        let mut method = registry::create("tessellation", &params).unwrap();
        for _ in 0..BUILDS {
            // A fresh `prepare` drops every mesh.
            method.prepare(&gpu, &scene).unwrap();
            render_frame(&gpu, method.as_mut(), &target, &camera).unwrap();
            build_ms = build_ms.min(method.mesh_stats().unwrap().cpu_build_ms);
        }
        time_frames(&gpu, method.as_mut(), &target, &camera, 5, 1).unwrap();
        let label = if params.is_empty() {
            "default (screen, 0.1 px, msaa 4)".to_string()
        } else {
            setting
                .iter()
                .map(|(k, v)| format!("{k}={v}"))
                .collect::<Vec<_>>()
                .join(" ")
        };
        runs.push(Run {
            label,
            method,
            build_ms,
            times: Vec::new(),
        });
    }
    for _ in 0..ROUNDS {
        for run in &mut runs {
            let frames = time_frames(
                &gpu,
                run.method.as_mut(),
                &target,
                &camera,
                0,
                FRAMES_PER_ROUND,
            )
            .unwrap()
            .expect("timestamps");
            run.times.extend(frames.iter().map(|t| t.gpu_ms));
        }
    }

    println!(
        "\n| setting | points | triangles | CPU tessellation ms | GPU ms (median) | vs default | MAE /255 | max | pixels > 0.5 |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut default_ms = None;
    for run in &mut runs {
        let median = metrics::median(run.times.iter().copied()).expect("frames were timed");
        let default_ms = *default_ms.get_or_insert(median);
        render_frame(&gpu, run.method.as_mut(), &target, &camera).unwrap();
        let error = compare(&target.readback(&gpu).unwrap(), &expected).unwrap();
        let mesh = run.method.mesh_stats().unwrap();
        println!(
            "| {} | {} | {} | {:.2} | {median:.1} | {:.2} | {:.2} | {:.3} | {} |",
            run.label,
            mesh.points,
            mesh.triangles,
            run.build_ms,
            median / default_ms,
            error.mae_255,
            error.max,
            error.pixels_over_05
        );
    }
}
