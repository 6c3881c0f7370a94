//! The same 10 px text in each display mode, stacked top to bottom (linear, sRGB blend,
//! gamma-corrected, linear with FreeType's stem darkening, linear with HarfBuzz GPU's),
//! written to screenshots/display-modes.png.
//! Run: `cargo run --release --example display_modes`.

use glyphscope::app::display::{Darkening, DisplayMode};
use glyphscope::app::headless::Headless;
use glyphscope::app::screenshots::{Then, photograph_panes};
use glyphscope::app::settings::{Layout, PaneSettings, Settings};

const WIDTH: u32 = 900;
const HEIGHT: u32 = 500;
/// Where the text line lies in the pane, and the part of it shown.
const LINE_TOP: u32 = 58;
const STRIP: (u32, u32) = (200, 16);
const ZOOM: u32 = 3;

fn main() {
    if let Err(e) = run() {
        eprintln!("display_modes: {e}");
        std::process::exit(2);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let mut screen = Headless::new(WIDTH, HEIGHT)?;
    let mut strips = Vec::new();
    for (display, darkening) in [
        (DisplayMode::Linear, Darkening::Off),
        (DisplayMode::Srgb, Darkening::Off),
        (DisplayMode::Gamma, Darkening::Off),
        (DisplayMode::Linear, Darkening::FreeType),
        (DisplayMode::Linear, Darkening::HarfBuzzGpu),
    ] {
        let mut settings = Settings {
            layout: Layout::Single,
            display,
            darkening,
            ..Settings::default()
        };
        settings.panes[0] = PaneSettings::method("reference");
        settings.scene.text = "Hamburgefonstiv: the quick brown fox".into();
        settings.camera.size_px_per_em = 10.0;
        // Below the pane's title and notes.
        settings.camera.origin = [12.0, 70.0];
        let (shot, panes) = photograph_panes(&mut screen, settings, Then::Settle)?;
        // The text's line in the pane, each pixel drawn 3×3.
        let pane_left = panes.first().map_or(0, |r| r.min.x as u32);
        let line = image::imageops::crop_imm(&shot, pane_left, LINE_TOP, STRIP.0, STRIP.1);
        let (w, h) = (STRIP.0 * ZOOM, STRIP.1 * ZOOM);
        let filter = image::imageops::FilterType::Nearest;
        strips.push(image::imageops::resize(&line.to_image(), w, h, filter));
    }
    let (w, h) = (STRIP.0 * ZOOM, STRIP.1 * ZOOM);
    let mut picture = image::RgbaImage::new(w, h * strips.len() as u32);
    for (k, strip) in strips.iter().enumerate() {
        image::imageops::replace(&mut picture, strip, 0, (h * k as u32).into());
    }
    std::fs::create_dir_all("screenshots")?;
    picture.save("screenshots/display-modes.png")?;
    eprintln!("wrote screenshots/display-modes.png");
    Ok(())
}
