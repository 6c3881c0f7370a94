//! The interactive explorer. It is UI only: every pixel it shows comes from the render
//! core — the methods through [`crate::methods::Method`], the reference, the metrics —
//! and it prepares data only when the scene or a method's parameters change.
//!
//! - `explorer`: the [`Explorer`] itself, what it holds and its frame; each file below
//!   adds the methods of its own part.
//! - `state`: what the canvas, blink, Cases menu, artifacts and playback keep between
//!   frames, held by the explorer.
//! - `settings`: what is remembered between runs.
//! - `scene_state`: the font and scene built from the settings.
//! - `camera_control`: the shared camera and how input steers it.
//! - `shortcuts`: the keyboard and mouse, one table for the keys, the help and the docs.
//! - `panes`: the method catalog, each pane's prepared method, the pane controls.
//! - `canvas`: the panes laid out, steered by the pointer, and settling when at rest.
//! - `gpu_view`: egui_wgpu paint callbacks drawing each pane's offscreen target.
//! - `display`: what a pane shows of a coverage value (blending, stem darkening).
//! - `analysis`: the reference and the error figures, on a background thread.
//! - `cases_menu`: the Cases menu, loading each named hard case and bench scene.
//! - `artifacts`: a pane's pixels off from the reference, worst first, to step through.
//! - `mark`: the frame around the pixel the view opened on (a worst pixel, a link's
//!   focus), in every pane until the view moves.
//! - `blink`: pane A flipped in place to pane B's method or the reference.
//! - `playback`: text in motion: the camera along a path frame by frame, with strip
//!   charts of each pane's error and temporal error.
//! - `pareto`: speed against error over every parameter combination, plotted with its
//!   Pareto front.
//! - `controls`: the side panel, the status bar and the windows.
//! - `web`: the explorer as a web page (wasm32 and WebGPU only).
//! - `link`: a view as a URL fragment, copied from the explorer and opened by
//!   `glyphscope --view`.
//! - `outline_painter`, `file_dialog`, `headless` (offscreen frames for `glyphscope screenshots`).

mod analysis;
mod artifacts;
mod blink;
mod camera_control;
mod canvas;
mod cases_menu;
mod controls;
pub mod display;
mod explorer;
mod file_dialog;
mod gpu_view;
pub mod headless;
mod link;
mod mark;
mod outline_painter;
mod panes;
mod pareto;
mod playback;
mod scene_state;
pub mod screenshots;
pub mod settings;
mod shortcuts;
mod state;
mod trial;
pub use trial::try_with as try_user_files_with;
#[cfg(target_arch = "wasm32")]
pub mod web;

use std::sync::Arc;

pub use self::explorer::Explorer;
pub use self::mark::MARK_COLOR;
use crate::gpu::GpuContext;

/// Opens the explorer window, on the view a link describes when `view` is given (a
/// malformed one opens the default view and says what was wrong). The web page starts
/// the explorer its own way (`web`).
#[cfg(not(target_arch = "wasm32"))]
pub fn run(view: Option<&str>) -> Result<(), crate::Error> {
    #[cfg(all(
        unix,
        not(any(target_os = "macos", target_os = "ios", target_os = "android"))
    ))]
    check_keyboard_library()?;
    let view = view.map(str::to_owned);
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Wgpu,
        viewport: eframe::egui::ViewportBuilder::default()
            .with_inner_size([1400.0, 860.0])
            .with_title("glyphscope")
            .with_drag_and_drop(true),
        wgpu_options: egui_wgpu::WgpuConfiguration {
            wgpu_setup: wgpu_setup(),
            ..Default::default()
        },
        ..Default::default()
    };
    eframe::run_native(
        "glyphscope",
        options,
        Box::new(move |cc| {
            let mut app = Explorer::new(cc);
            if let Some(link) = &view {
                app.open_link(link);
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| {
        // Debian's packages, where they are the answer.
        let hint = match e {
            _ if !cfg!(target_os = "linux") => String::new(),
            eframe::Error::WinitEventLoop(_) => format!(
                " (it needs a display and, on X11, apt-get install {X11_LIBRARIES}; on \
                 Wayland, {WAYLAND_LIBRARIES})"
            ),
            eframe::Error::Wgpu(_) => format!(" (no Vulkan or GL driver: {DRIVERS})"),
            _ => String::new(),
        };
        crate::Error::Gpu(format!("cannot open the window: {e}{hint}"))
    })
}

/// What the window loads when it opens and a minimal Debian 12 lacks (checked there by
/// `tools/fresh-machine.sh window`; README's set-up lists them too). Wayland's are winit's
/// list, not checked.
#[cfg(not(target_arch = "wasm32"))]
const X11_LIBRARIES: &str = "libx11-6 libx11-xcb1 libxcursor1 libxrandr2 libxi6 libxkbcommon-x11-0";
#[cfg(not(target_arch = "wasm32"))]
const WAYLAND_LIBRARIES: &str = "libwayland-client0 libwayland-cursor0 libxkbcommon0";
#[cfg(not(target_arch = "wasm32"))]
const DRIVERS: &str =
    "apt-get install mesa-vulkan-drivers, or for GL libegl1 libegl-mesa0 libgl1-mesa-dri";

/// winit reads the keyboard through libxkbcommon and panics where it cannot load it
/// (xkbcommon-dl's loaders `expect` the library), so the explorer loads it first, through
/// the same loader, and names the libraries to install. With no display at all, winit's
/// own error says so.
#[cfg(all(
    unix,
    not(any(target_os = "macos", target_os = "ios", target_os = "android"))
))]
fn check_keyboard_library() -> Result<(), crate::Error> {
    let set = |name| std::env::var_os(name).is_some_and(|v| !v.is_empty());
    let wayland = set("WAYLAND_DISPLAY") || set("WAYLAND_SOCKET");
    let (loaded, packages) = if wayland {
        (
            xkbcommon_dl::xkbcommon_option().is_some(),
            WAYLAND_LIBRARIES,
        )
    } else if set("DISPLAY") {
        let both = xkbcommon_dl::xkbcommon_option().is_some()
            && xkbcommon_dl::x11::xkbcommon_x11_option().is_some();
        (both, X11_LIBRARIES)
    } else {
        (true, "")
    };
    if loaded {
        return Ok(());
    }
    Err(crate::Error::Gpu(format!(
        "cannot open the window: no libxkbcommon, which winit reads the keyboard with \
         (Debian: apt-get install {packages})"
    )))
}

/// The device the explorer asks for (in eframe, headless and in tests): what the methods
/// get from [`GpuContext::new`], timestamp queries included.
pub fn wgpu_setup() -> egui_wgpu::WgpuSetup {
    let mut setup = egui_wgpu::WgpuSetupCreateNew::without_display_handle();
    setup.device_descriptor = Arc::new(GpuContext::device_descriptor);
    egui_wgpu::WgpuSetup::CreateNew(setup)
}

/// eframe's setup on a device already open: the app draws on `gpu`'s device (the
/// tests' one device per test binary), which glyphscope opened (so it has its adapter).
pub fn wgpu_setup_on(gpu: &GpuContext) -> egui_wgpu::WgpuSetup {
    let (instance, adapter) = gpu
        .instance_and_adapter()
        .expect("a device glyphscope opened keeps its adapter");
    egui_wgpu::WgpuSetup::Existing(egui_wgpu::WgpuSetupExisting {
        instance: instance.clone(),
        adapter: adapter.clone(),
        device: gpu.device.clone(),
        queue: gpu.queue.clone(),
    })
}
