//! `glyphscope screenshots`: the pictures of the explorer in README and docs/explorer.md,
//! made headlessly by the real app — what a first start shows, a case under the
//! magnifier, the methods side by side, each debug overlay, the speed-vs-error plot.

use std::path::Path;
use std::time::Duration;

use web_time::Instant;

use eframe::egui;

use super::explorer::Explorer;
use super::headless::Headless;
use super::panes::{Catalog, REFERENCE};
use super::settings::{Layout, PaneOverlay, PaneSettings, PaneSource, Settings};
use crate::Error;
use crate::methods::info::Role;
use crate::methods::registry;
use crate::methods::{Overlay, sdf_cells, winding};

/// Screen size of every screenshot, pixels.
const WIDTH: u32 = 1400;
const HEIGHT: u32 = 860;
/// Longest wait for the background work of one screenshot.
const PATIENCE: Duration = Duration::from_secs(300);

/// Writes every screenshot into `dir`; returns the files written.
pub fn write_all(dir: &Path) -> Result<Vec<String>, Error> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::Output(format!("cannot create '{}': {e}", dir.display())))?;
    let mut screen = Headless::new(WIDTH, HEIGHT)?;
    let catalog = Catalog::discover();
    let mut written = Vec::new();
    let mut save = |name: String, settings: Settings, then: Then| -> Result<(), Error> {
        let path = dir.join(&name);
        let image = photograph(&mut screen, settings, then)?;
        image
            .save(&path)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))?;
        eprintln!("wrote {}", path.display());
        written.push(name);
        Ok(())
    };
    save(
        "app-first-start.png".into(),
        Settings::default(),
        Then::OpenAsOnAFirstStart,
    )?;
    save(
        "app-microscope.png".into(),
        microscope(),
        Then::LoadCase(MICROSCOPE_CASE),
    )?;
    save(
        "app-methods.png".into(),
        methods_side_by_side(&catalog),
        Then::Settle,
    )?;
    for overlay in Overlay::ALL {
        let Some(method) = catalog
            .gpu_methods()
            .find(|m| m.overlays.contains(&overlay))
        else {
            continue;
        };
        let mut pane = PaneSettings::method(method.name);
        pane.overlay = PaneOverlay::Method(overlay.name().into());
        save(
            format!("app-overlay-{}.png", overlay.name()),
            one_glyph(pane),
            Then::Settle,
        )?;
    }
    if let Some(method) = catalog.gpu_methods().find(|m| !is_diagnostic(m.name)) {
        let mut pane = PaneSettings::method(method.name);
        pane.overlay = PaneOverlay::Error;
        let mut settings = one_pane(pane);
        settings.camera.size_px_per_em = 20.0;
        settings.camera.origin = [16.0, 90.0];
        // Good methods err by little: a fine scale shows where.
        settings.difference_scale = 0.02;
        save("app-overlay-error.png".into(), settings, Then::Settle)?;
        let mut pane = PaneSettings::method(method.name);
        pane.outline = true;
        save(
            "app-overlay-outline.png".into(),
            one_glyph(pane),
            Then::Settle,
        )?;
    }
    let mut settings = methods_side_by_side(&catalog);
    settings.layout = Layout::Single;
    settings.camera.size_px_per_em = 24.0;
    save("app-sweep.png".into(), settings, Then::Sweep)?;
    save(
        "app-motion.png".into(),
        atlas_beside_winding_in_motion(),
        Then::Play(24),
    )?;
    Ok(written)
}

/// What a screenshot waits for once the explorer has its settings.
#[derive(Clone, Copy, Debug)]
pub enum Then {
    /// The view at rest, its numbers in.
    Settle,
    /// Then a speed-vs-error sweep run to its end.
    Sweep,
    /// What a first start shows (at rest, on the worst pixel).
    OpenAsOnAFirstStart,
    /// A case loaded from the Cases menu (at rest, on its worst pixel).
    LoadCase(&'static str),
    /// The motion path played this many frames, its charts open (at rest).
    Play(i64),
}

/// The case README's first picture shows.
const MICROSCOPE_CASE: &str = "tip-on-arc";

/// sdf-cells beside its own error against the reference, for a loaded case: coverage
/// and error written in each magnified pixel, the exact outline over both. Its caption
/// in README and docs/explorer.md says what sdf-cells gets wrong on this case, so
/// sdf-cells is picked by its row, not by a role.
fn microscope() -> Settings {
    // The estimate as font-demo publishes it (its rules for ties and corners alone): the
    // default reads this view right since the winding number gives the side there.
    let published = || PaneSettings {
        source: PaneSource::Method {
            name: sdf_cells::INFO.name.into(),
            params: vec![("ties".into(), "merge".into())],
        },
        ..PaneSettings::method(sdf_cells::INFO.name)
    };
    let mut settings = Settings::default();
    settings.panes[0] = published();
    settings.panes[1] = PaneSettings {
        overlay: PaneOverlay::Error,
        ..published()
    };
    settings
}

/// Whether `name` is a diagnostic (a check of the GPU path, not a way to draw text).
fn is_diagnostic(name: &str) -> bool {
    registry::find(name).is_ok_and(|m| m.role == Role::Diagnostic)
}

/// The GPU methods in a 2×2 grid (the diagnostics last), the reference and a
/// difference filling any panes left.
fn methods_side_by_side(catalog: &Catalog) -> Settings {
    let drawn: Vec<&str> = catalog.gpu_methods().map(|m| m.name).collect();
    let (diagnostics, mut names): (Vec<&str>, Vec<&str>) =
        drawn.into_iter().partition(|n| is_diagnostic(n));
    names.push(REFERENCE);
    names.extend(diagnostics);
    let mut settings = Settings {
        layout: Layout::Grid,
        ..Settings::default()
    };
    for (pane, name) in settings.panes.iter_mut().zip(names.iter().take(3)) {
        *pane = PaneSettings::method(name);
    }
    settings.panes[3] = if names.len() > 4 {
        PaneSettings::method(names[3])
    } else {
        PaneSettings {
            source: PaneSource::Difference {
                first: 0,
                second: None,
            },
            ..PaneSettings::default()
        }
    };
    settings.camera.size_px_per_em = 40.0;
    settings.camera.origin = [12.0, 110.0];
    settings
}

/// The baseline (the atlas) beside winding, magnified ×16 on small text drifting 1/16
/// px a frame: the atlas's phases against an exact method, with the charts of both. Its
/// captions in docs/motion.md and docs/explorer.md name winding, so winding is picked
/// by its row, not by a role.
fn atlas_beside_winding_in_motion() -> Settings {
    let mut settings = Settings {
        layout: Layout::SideBySide,
        motion_path: super::settings::DEFAULT_MOTION_PATH.into(),
        ..Settings::default()
    };
    settings.scene.text = "Hamburgefonstiv".into();
    settings.panes[0] = PaneSettings::method(registry::baseline().name);
    settings.panes[1] = PaneSettings::method(winding::INFO.name);
    settings.camera.size_px_per_em = 12.0;
    // Near the pane's top edge, so that the magnified window starts there and the text
    // stays clear of the Motion window below it.
    settings.camera.origin = [16.0, 14.0];
    settings.camera.magnify = 16;
    settings.camera.focus = [40.0, 9.0];
    settings
}

fn one_pane(pane: PaneSettings) -> Settings {
    let mut settings = Settings {
        layout: Layout::Single,
        ..Settings::default()
    };
    settings.panes[0] = pane;
    settings
}

/// One big glyph in one pane.
fn one_glyph(pane: PaneSettings) -> Settings {
    let mut settings = one_pane(pane);
    settings.scene.glyph_mode = true;
    settings.scene.glyph = "g".into();
    settings.camera.size_px_per_em = 700.0;
    settings.camera.origin = [420.0, 560.0];
    settings
}

/// Runs the explorer with `settings`, does what `then` says, waits until its numbers are
/// in, and returns the last frame.
pub fn photograph(
    screen: &mut Headless,
    settings: Settings,
    then: Then,
) -> Result<image::RgbaImage, Error> {
    photograph_panes(screen, settings, then).map(|(image, _)| image)
}

/// [`photograph`], and where the panes are in the picture (pixels: the headless
/// screen draws one pixel a point).
pub fn photograph_panes(
    screen: &mut Headless,
    settings: Settings,
    then: Then,
) -> Result<(image::RgbaImage, Vec<egui::Rect>), Error> {
    let mut app: Explorer = screen.explorer(settings);
    match then {
        Then::OpenAsOnAFirstStart => app.open_as_on_a_first_start(),
        Then::LoadCase(name) => app.load_case(name),
        Then::Settle | Then::Sweep | Then::Play(_) => {}
    }
    let sweep = matches!(then, Then::Sweep);
    let start = Instant::now();
    let mut frames = 0;
    let mut sweep_started = false;
    loop {
        screen.frame(&mut app)?;
        frames += 1;
        let settled = frames > 3 && app.settled();
        if sweep && settled && !sweep_started {
            app.start_sweep(&screen.context().clone());
            sweep_started = true;
        }
        if let Then::Play(last) = then {
            if settled && !app.is_playing() && app.motion_frame() == 0 {
                app.play_motion(true);
            } else if app.is_playing() && app.motion_frame() >= last {
                app.play_motion(false);
            }
        }
        let played = match then {
            Then::Play(last) => !app.is_playing() && app.motion_frame() >= last,
            _ => true,
        };
        let done = settled && played && (!sweep || (sweep_started && !app.sweep_running()));
        if done {
            break;
        }
        if start.elapsed() > PATIENCE {
            return Err(Error::Gpu("the explorer did not settle in time".into()));
        }
        std::thread::sleep(Duration::from_millis(30));
    }
    // One more frame shows what arrived last.
    screen.frame(&mut app)?;
    let image = screen.screenshot(&mut app)?;
    Ok((image, app.pane_rects().to_vec()))
}
