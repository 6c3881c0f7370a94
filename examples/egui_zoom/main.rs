//! An egui `Scene` (drag to pan, scroll or pinch to zoom) whose labels are drawn by egui
//! on the left and by `glyphscope::text` on the right, in one font: zoom to 20× and
//! egui's magnified bitmaps are blurred where the library's edges stay one pixel wide.
//! `cargo run --release --example egui_zoom`.

mod zoom;

fn main() {
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Wgpu,
        viewport: eframe::egui::ViewportBuilder::default()
            .with_inner_size([960.0, 360.0])
            .with_title("egui_zoom"),
        ..Default::default()
    };
    let result = eframe::run_native(
        "egui_zoom",
        options,
        Box::new(|cc| {
            let mut app = zoom::ZoomApp::new(cc)?;
            app.controls = true;
            Ok(Box::new(app) as Box<dyn eframe::App>)
        }),
    );
    if let Err(e) = result {
        eprintln!("egui_zoom: {e}");
        std::process::exit(2);
    }
}
