//! The explorer as a web page: the same app on `wasm32-unknown-unknown`, drawn with
//! WebGPU (never WebGL, which has no storage buffers: the methods' shaders need them).
//! `tools/web.sh build` compiles this crate to wasm, binds it with `wasm-bindgen` and
//! writes the page; `tools/web/index.html` starts it with the URL fragment, a link to a
//! view (see `link`).
//!
//! The page's title tells a driver how it went: it ends in `· ready` once the panes
//! have drawn their first frame, and holds `· error:` and the reason when the explorer
//! cannot start (no WebGPU adapter).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use eframe::web_sys;
use wasm_bindgen::prelude::*;

use super::Explorer;
use crate::gpu::GpuContext;

/// The page's handle on the explorer.
#[wasm_bindgen]
pub struct WebHandle {
    runner: eframe::WebRunner,
}

#[wasm_bindgen]
impl WebHandle {
    #[wasm_bindgen(constructor)]
    #[allow(clippy::new_without_default)]
    pub fn new() -> WebHandle {
        eframe::WebLogger::init(log::LevelFilter::Warn).ok();
        WebHandle {
            runner: eframe::WebRunner::new(),
        }
    }

    /// Starts the explorer in `canvas` on the view `fragment` describes (empty: the
    /// default view).
    pub async fn start(
        &self,
        canvas: web_sys::HtmlCanvasElement,
        fragment: String,
    ) -> Result<(), JsValue> {
        let mut setup = egui_wgpu::WgpuSetupCreateNew::without_display_handle();
        setup.instance_descriptor.backends = wgpu::Backends::BROWSER_WEBGPU;
        setup.device_descriptor = Arc::new(GpuContext::device_descriptor);
        let options = eframe::WebOptions {
            wgpu_options: egui_wgpu::WgpuConfiguration {
                wgpu_setup: egui_wgpu::WgpuSetup::CreateNew(setup),
                ..Default::default()
            },
            ..Default::default()
        };
        self.runner
            .start(
                canvas,
                options,
                Box::new(move |cc| {
                    let mut app = Explorer::new(cc);
                    if !fragment.trim_start_matches('#').is_empty() {
                        app.open_link(&fragment);
                    }
                    Ok(Box::new(app))
                }),
            )
            .await
    }
}

/// What the page cannot do yet, said in the status bar: what waits for the GPU within a
/// frame, and what needs a thread.
pub const LIMITS: &str = "web page: the reference and the errors are worked out within the frame; \
    no curves per pixel or sweep here yet (the desktop explorer has them)";

/// After each frame: once every pane drawing a method has drawn the view, the page's
/// title ends in `· ready` (what a driver waits for).
pub(super) fn after_frame(app: &Explorer) {
    static READY: AtomicBool = AtomicBool::new(false);
    if READY.load(Ordering::Relaxed) || !app.panes_drawn() {
        return;
    }
    READY.store(true, Ordering::Relaxed);
    if let Some(document) = web_sys::window().and_then(|w| w.document()) {
        document.set_title("glyphscope · ready");
    }
}
