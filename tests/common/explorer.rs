//! The explorer in a test harness: built as eframe builds it, on the test GPU, driven
//! through egui_kittest. For the test binaries that have the `app` feature (the other
//! binaries include `common` alone).
#![allow(dead_code)] // each test binary uses its own subset

use std::time::{Duration, Instant};

use egui_kittest::{Harness, wgpu::WgpuTestRenderer};
use glyphscope::app::Explorer;
use glyphscope::app::settings::Settings;

use super::common::gpu;

pub const SIZE: [f32; 2] = [1200.0, 700.0];

/// The real app (as `Explorer::new` makes it for eframe) with `settings`.
pub fn harness(settings: Settings) -> Harness<'static, Explorer> {
    let mut harness = Harness::builder()
        .with_size(SIZE)
        .renderer(WgpuTestRenderer::from_setup(
            glyphscope::app::wgpu_setup_on(gpu()),
        ))
        .build_eframe(|cc| {
            let mut app = Explorer::new(cc);
            app.settings = settings;
            app
        });
    harness.step();
    harness
}

/// Steps and draws frames until the view has rested and its numbers are in, two frames
/// running (a click's events can span frames); returns the screen.
pub fn settle(harness: &mut Harness<'static, Explorer>) -> image::RgbaImage {
    let start = Instant::now();
    let mut was_settled = false;
    loop {
        harness.step();
        let screen = harness.render().expect("the harness draws with wgpu");
        let settled = harness.state().settled();
        if settled && was_settled {
            return screen;
        }
        was_settled = settled;
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "the view never settled"
        );
        std::thread::sleep(Duration::from_millis(10));
    }
}
