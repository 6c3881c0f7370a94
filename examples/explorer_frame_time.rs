//! Frame time of the explorer's 2×2 view of the four methods on the standard page of
//! text, drawn exactly as the window draws it (egui_wgpu, paint callbacks, every pane's
//! method) but offscreen:
//!
//!     cargo run --release --example explorer_frame_time [N]
//!
//! With N, the panes are magnified ×N about their centre (each draws a window of a
//! pane's pixels, N×N times fewer of them).
//!
//! Prints the wall time of whole frames (UI, every pane redrawn, GPU finished) in
//! continuous mode, each pane's GPU time from its timestamps, and the time of frames in
//! which only the UI changes (panes are not redrawn then).

use std::time::{Duration, Instant};

use glyphscope::app::headless::Headless;
use glyphscope::app::settings::{Layout, PaneSettings, PaneSource, Settings};
use glyphscope::metrics::median;

const FRAMES: usize = 40;

fn main() -> Result<(), glyphscope::Error> {
    let mut screen = Headless::new(1920, 1080)?;
    let mut settings = Settings {
        layout: Layout::Grid,
        ..Settings::default()
    };
    settings.scene.text = glyphscope::bench::scenes::PAGE_TEXT.into();
    settings.camera.size_px_per_em = 16.0;
    settings.camera.origin = [8.0, 100.0];
    let magnify: u32 = match std::env::args().nth(1) {
        Some(n) => n.parse().map_err(|_| {
            glyphscope::Error::Input(format!("magnification '{n}' is not a whole number"))
        })?,
        None => 1,
    };
    settings.camera.magnify = magnify;
    // The centre of a 2×2 pane of the 1920×1080 screen, roughly: on the text.
    settings.camera.focus = [400.0, 260.0];
    // The four methods, one per pane, at their default parameters.
    for (pane, method) in
        settings
            .panes
            .iter_mut()
            .zip(["winding", "sdf-cells", "xor-stencil", "tessellation"])
    {
        *pane = PaneSettings::method(method);
    }
    let mut app = screen.explorer(settings);
    // Warm up: shaders compile on first use, the reference is worked out once.
    let start = Instant::now();
    while !(app.settled() && start.elapsed() > Duration::from_secs(2)) {
        screen.frame(&mut app)?;
    }
    let camera = app.camera().expect("laid out");
    println!(
        "2×2 on the standard page ({} glyphs), panes drawing {}×{} px (×{magnify}), {}",
        app.scene().map_or(0, |s| s.instances.len()),
        camera.width,
        camera.height,
        screen.gpu().adapter_name()
    );
    for (continuous, what) in [
        (true, "every pane redrawn"),
        (false, "UI only, panes cached"),
    ] {
        app.settings.continuous = continuous;
        let mut times = Vec::new();
        for _ in 0..FRAMES {
            let t = Instant::now();
            screen.frame(&mut app)?;
            times.push(t.elapsed().as_secs_f64() * 1e3);
        }
        println!(
            "frame, {what}: median {:.1} ms",
            median(times).unwrap_or(f64::NAN)
        );
    }
    for pane in 0..4 {
        if let Some(ms) = app.pane_gpu_ms(pane) {
            let method = match &app.settings.panes[pane].source {
                PaneSource::Method { name, .. } => name.as_str(),
                PaneSource::Difference { .. } => "difference",
            };
            println!("pane {pane} ({method}): GPU {ms:.2} ms (median of the recent frames)");
        }
    }
    Ok(())
}
