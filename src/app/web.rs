//! The explorer as a web page: the same app on `wasm32-unknown-unknown`, drawn with
//! WebGPU (never WebGL, which has no storage buffers: the methods' shaders need them).
//! `tools/web.sh build` compiles this crate to wasm, binds it with `wasm-bindgen` and
//! writes the page; `tools/web/index.html` starts it with the URL fragment, a link to a
//! view (see `link`).
//!
//! The page's title tells a driver how it went: it ends in `· ready` once the panes
//! have drawn their first frame, and holds `· error:` and the reason when the explorer
//! cannot start (no WebGPU adapter). The URL's fragment follows the view (a reload or a
//! copied address opens it again), and the page's `<body>` carries what a reader of the
//! page that cannot see the canvas needs: `data-status`, the status line, and, once a
//! view has rested, `data-view`, its numbers (see [`ViewNumbers`]).

use std::cell::RefCell;
use std::sync::Arc;

use eframe::egui;
use wasm_bindgen::prelude::*;

use super::explorer::Explorer;
use super::panes::pane_letter;
use super::settings::PaneSource;
use super::state::CanvasKey;
use crate::gpu::GpuContext;

/// The page's handle on the explorer.
#[wasm_bindgen]
pub struct WebHandle {
    runner: eframe::WebRunner,
    /// The explorer's egui context, once started: what the page's calls wake it with.
    context: std::rc::Rc<RefCell<Option<egui::Context>>>,
}

#[wasm_bindgen]
impl WebHandle {
    #[wasm_bindgen(constructor)]
    #[allow(clippy::new_without_default)]
    pub fn new() -> WebHandle {
        eframe::WebLogger::init(log::LevelFilter::Warn).ok();
        WebHandle {
            runner: eframe::WebRunner::new(),
            context: Default::default(),
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
        let context = self.context.clone();
        self.runner
            .start(
                canvas,
                options,
                Box::new(move |cc| {
                    *context.borrow_mut() = Some(cc.egui_ctx.clone());
                    let mut app = Explorer::new(cc);
                    if !fragment.trim_start_matches('#').is_empty() {
                        app.open_link(&fragment);
                    }
                    Ok(Box::new(app))
                }),
            )
            .await
    }

    /// Opens the font file `name` the page read (its file picker, a file dropped on it).
    pub fn open_font(&self, name: String, bytes: Vec<u8>) -> Result<(), JsValue> {
        self.with_explorer(|app| app.open_font_bytes(name, bytes.into()))
    }

    /// Opens the view a fragment describes: the page calls it when the address's
    /// fragment is changed by hand.
    pub fn open_link(&self, fragment: String) -> Result<(), JsValue> {
        self.with_explorer(|app| app.open_link(&fragment))
    }
}

impl WebHandle {
    fn with_explorer(&self, change: impl FnOnce(&mut Explorer)) -> Result<(), JsValue> {
        let mut app = self
            .runner
            .app_mut::<Explorer>()
            .ok_or_else(|| JsValue::from_str("the explorer has not started, or has stopped"))?;
        change(&mut app);
        drop(app);
        if let Some(ctx) = self.context.borrow().as_ref() {
            ctx.request_repaint();
        }
        Ok(())
    }
}

/// "Open font…" on the page: the browser's file picker (`#font-file` in index.html,
/// whose change handler reads the file and calls [`WebHandle::open_font`]).
pub(super) fn pick_font() -> Result<(), String> {
    use wasm_bindgen::JsCast;
    web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("font-file"))
        .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok())
        .map(|input| input.click())
        .ok_or_else(|| "this page has no file picker (#font-file)".to_string())
}

/// What the page cannot do yet, said in the status bar: what waits for the GPU within a
/// frame, and what needs a thread.
pub const LIMITS: &str = "web page: the reference and the errors are worked out within the frame; \
    no curves per pixel or sweep here yet (the desktop explorer has them)";

/// A view at rest, in numbers, as `data-view` on the page's `<body>`: what a test reads
/// to compare the page's pixels with the desktop's.
#[derive(serde::Serialize)]
struct ViewNumbers {
    /// The link of the view.
    link: String,
    /// The pixels of the frame the panes show (the magnifier's window).
    window: Option<crate::magnify::Window>,
    /// Each pane drawing a method: its letter, the method and its coverage of the
    /// window, row by row.
    panes: Vec<(String, String, Vec<f32>)>,
    /// The reference's coverage of the window.
    reference: Option<Vec<f32>>,
}

/// What the page last showed of the explorer, so that the page is written only when it
/// changes.
#[derive(Default)]
struct Shown {
    ready: bool,
    link: Option<String>,
    status: String,
    /// The view at rest and the link `data-view` was written for.
    view: Option<(CanvasKey, Option<String>)>,
}

thread_local! {
    static SHOWN: RefCell<Shown> = RefCell::new(Shown::default());
}

impl Explorer {
    /// After each frame: the title ends in `· ready` once every pane drawing a method has
    /// drawn the view (what a driver waits for); the fragment follows the view; the body's
    /// `data-status` and `data-view` follow the status line and the view at rest.
    pub(super) fn after_frame_on_the_page(&self) {
        let app = self;
        let Some(window) = web_sys::window() else {
            return;
        };
        let (Some(document), Some(body)) =
            (window.document(), window.document().and_then(|d| d.body()))
        else {
            return;
        };
        SHOWN.with_borrow_mut(|shown| {
            if !shown.ready && app.panes_drawn() {
                shown.ready = true;
                document.set_title("glyphscope · ready");
            }
            let status = app.status_text();
            if status != shown.status {
                body.set_attribute("data-status", &status).ok();
                shown.status = status;
            }
            if !app.settled() {
                return;
            }
            // The address follows the view once it rests: during a drag, a zoom or a play
            // the link changes every frame, and browsers throttle history updates that
            // often. A view that cannot travel in a link (a font from this computer) leaves
            // the address without a fragment rather than with a stale one.
            let link = app.link().ok();
            if link != shown.link {
                let address = link
                    .clone()
                    .unwrap_or_else(|| window.location().pathname().unwrap_or_else(|_| "/".into()));
                if let Ok(history) = window.history() {
                    history
                        .replace_state_with_url(&JsValue::NULL, "", Some(&address))
                        .ok();
                }
                shown.link = link;
            }
            // Written again when the view at rest changes, or only its link does (an
            // outline switched on changes no pixel a pane reads back).
            let rested = app
                .canvas
                .analysed
                .clone()
                .map(|key| (key, shown.link.clone()));
            if rested == shown.view {
                return;
            }
            let visible = app.settings.layout.panes();
            let captures: Vec<_> = (0..visible)
                .filter_map(|i| app.pane_capture(i).map(|c| (i, c)))
                .collect();
            let numbers = ViewNumbers {
                link: shown.link.clone().unwrap_or_default(),
                window: app.magnified_window(),
                panes: captures
                    .iter()
                    .filter_map(|(i, image)| match &app.settings.panes[*i].source {
                        PaneSource::Method { name, .. } => Some((
                            pane_letter(*i).to_string(),
                            name.clone(),
                            image.data.clone(),
                        )),
                        _ => None,
                    })
                    .collect(),
                reference: app.reference_image().map(|r| r.data.clone()),
            };
            if let Ok(json) = serde_json::to_string(&numbers) {
                body.set_attribute("data-view", &json).ok();
                shown.view = rested;
            }
        });
    }
}
