//! The keyboard and mouse: one table that the key handling, the help window, the
//! controls' hover hints and docs/explorer.md all follow, so a shortcut cannot be listed
//! without working or work without being listed; and what each action does (the
//! screenshot is also the controls' button).

use std::path::PathBuf;

use eframe::egui::{self, Key, KeyboardShortcut, Modifiers};
use glam::DVec2;

use super::explorer::Explorer;
use super::panes::REFERENCE;
use super::settings::{Layout, PaneOverlay, PaneSource};

/// Pixels an arrow key pans by.
const ARROW_PAN_PX: f64 = 40.0;

/// One row of the help: the input, and what it does.
pub struct Shortcut {
    /// The keys or gesture, as the help window and docs/explorer.md write them.
    pub keys: &'static str,
    pub what: &'static str,
    pub input: Input,
}

/// How a row is given: by keys, or by the pointer.
pub enum Input {
    /// Keys handled from this table by [`Explorer::shortcuts`].
    Keys(&'static [Binding]),
    /// A pointer gesture the view handles where it steers the camera (`view.rs`); the
    /// row only describes it.
    Pointer,
}

/// Keys that do one action: pressing any of them does it once.
pub struct Binding {
    pub keys: &'static [KeyboardShortcut],
    pub action: Action,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Moves the view by this many pixels.
    Pan(DVec2),
    /// Zooms by this factor about the pane's centre.
    Zoom(f64),
    /// Rotates by this many degrees (counter-clockwise) about the pane's centre.
    Rotate(f64),
    /// Multiplies the magnifier's N by this (×2 or ÷2), about the pane's centre.
    Magnify(bool),
    /// Centres the magnifier on the hovered pane's (else pane A's) worst pixel.
    WorstPixel,
    /// The next (true) or previous pixel over the threshold, by descending error.
    StepArtifact(bool),
    /// Flips pane A to pane B's method (else the reference) or back.
    Blink,
    /// Pane A flips on its own a few times a second, or stops.
    ToggleAutoBlink,
    ResetCamera,
    FitText,
    SetLayout(Layout),
    ToggleGlyphMode,
    /// The outline on every visible pane, or off where all have it.
    ToggleOutlines,
    /// The error overlay on every visible pane drawing a GPU method, or off where any
    /// has it.
    ToggleErrorOverlays,
    ToggleContinuous,
    /// Text in motion: play or pause the path.
    PlayPause,
    /// One frame of the path on (true) or back.
    StepFrame(bool),
    /// Back to frame 0 of the path.
    Rewind,
    ToggleSweep,
    OpenFont,
    Screenshot,
    ToggleHelp,
}

const fn key(key: Key) -> KeyboardShortcut {
    KeyboardShortcut::new(Modifiers::NONE, key)
}

const fn bind(keys: &'static [KeyboardShortcut], action: Action) -> Binding {
    Binding { keys, action }
}

const fn keyed(keys: &'static str, what: &'static str, bindings: &'static [Binding]) -> Shortcut {
    Shortcut {
        keys,
        what,
        input: Input::Keys(bindings),
    }
}

const fn pointer(keys: &'static str, what: &'static str) -> Shortcut {
    Shortcut {
        keys,
        what,
        input: Input::Pointer,
    }
}

/// The keyboard and mouse, in the order the help and docs/explorer.md list them (and the
/// order keys pressed in one frame take effect).
#[rustfmt::skip]
pub const SHORTCUTS: &[Shortcut] = &[
    pointer("drag", "pan"),
    pointer("wheel / pinch", "zoom about the cursor"),
    keyed("arrows", "pan", &[
        bind(&[key(Key::ArrowLeft)], Action::Pan(DVec2::new(ARROW_PAN_PX, 0.0))),
        bind(&[key(Key::ArrowRight)], Action::Pan(DVec2::new(-ARROW_PAN_PX, 0.0))),
        bind(&[key(Key::ArrowUp)], Action::Pan(DVec2::new(0.0, ARROW_PAN_PX))),
        bind(&[key(Key::ArrowDown)], Action::Pan(DVec2::new(0.0, -ARROW_PAN_PX))),
    ]),
    keyed("+ / −", "zoom in / out ×2 about the centre", &[
        bind(&[key(Key::Plus), key(Key::Equals)], Action::Zoom(2.0)),
        bind(&[key(Key::Minus)], Action::Zoom(0.5)),
    ]),
    keyed("[ / ]", "rotate −15° / +15°", &[
        bind(&[key(Key::OpenBracket)], Action::Rotate(-15.0)),
        bind(&[key(Key::CloseBracket)], Action::Rotate(15.0)),
    ]),
    pointer("Alt + wheel", "magnify the pixels ×2 / ÷2 about the cursor (×1 to ×64)"),
    keyed("M / N", "magnify the pixels ×2 / ÷2", &[
        bind(&[key(Key::M)], Action::Magnify(true)),
        bind(&[key(Key::N)], Action::Magnify(false)),
    ]),
    keyed("W", "magnify on the worst pixel of the hovered pane (else A)", &[
        bind(&[key(Key::W)], Action::WorstPixel),
    ]),
    keyed(". / ,", "next / previous pixel off by > 0.25, worst first", &[
        bind(&[key(Key::Period)], Action::StepArtifact(true)),
        bind(&[key(Key::Comma)], Action::StepArtifact(false)),
    ]),
    // Shift+B first: B alone would match it too (shift is not required to be up).
    keyed("B / Shift+B", "blink pane A with pane B's method (else the reference) / on its own", &[
        bind(&[KeyboardShortcut::new(Modifiers::SHIFT, Key::B)], Action::ToggleAutoBlink),
        bind(&[key(Key::B)], Action::Blink),
    ]),
    keyed("R", "reset the camera", &[bind(&[key(Key::R)], Action::ResetCamera)]),
    keyed("F", "fit the text to the pane", &[bind(&[key(Key::F)], Action::FitText)]),
    keyed("1 / 2 / 4", "one pane / side by side / 2×2", &[
        bind(&[key(Key::Num1)], Action::SetLayout(Layout::Single)),
        bind(&[key(Key::Num2)], Action::SetLayout(Layout::SideBySide)),
        bind(&[key(Key::Num4)], Action::SetLayout(Layout::Grid)),
    ]),
    keyed("G", "glyph mode on / off", &[bind(&[key(Key::G)], Action::ToggleGlyphMode)]),
    keyed("O", "outline overlay on / off", &[bind(&[key(Key::O)], Action::ToggleOutlines)]),
    keyed("E", "error overlay on / off", &[bind(&[key(Key::E)], Action::ToggleErrorOverlays)]),
    keyed("C", "draw continuously (live GPU time)", &[
        bind(&[key(Key::C)], Action::ToggleContinuous),
    ]),
    keyed("Space", "play / pause the motion path", &[bind(&[key(Key::Space)], Action::PlayPause)]),
    keyed("J / L", "one frame of the motion back / on", &[
        bind(&[key(Key::J)], Action::StepFrame(false)),
        bind(&[key(Key::L)], Action::StepFrame(true)),
    ]),
    keyed("Home", "back to frame 0 of the motion", &[bind(&[key(Key::Home)], Action::Rewind)]),
    keyed("P", "speed-vs-error plot", &[bind(&[key(Key::P)], Action::ToggleSweep)]),
    keyed("Ctrl+O", "open a font file", &[
        bind(&[KeyboardShortcut::new(Modifiers::COMMAND, Key::O)], Action::OpenFont),
    ]),
    keyed("S", "screenshot (PNG in the current folder)", &[
        bind(&[key(Key::S)], Action::Screenshot),
    ]),
    keyed("H / F1", "this help", &[bind(&[key(Key::H), key(Key::F1)], Action::ToggleHelp)]),
];

/// Every key binding of the table, in its order.
fn bindings() -> impl Iterator<Item = &'static Binding> {
    SHORTCUTS
        .iter()
        .filter_map(|s| match s.input {
            Input::Keys(bindings) => Some(bindings),
            Input::Pointer => None,
        })
        .flatten()
}

/// The first key that does `action`, named as the controls' hover hints give it
/// ("Ctrl+O"); empty when no key does.
pub fn key_name(action: Action) -> String {
    bindings()
        .find(|b| b.action == action)
        .and_then(|b| b.keys.first())
        .map_or_else(String::new, |k| {
            k.format(&egui::ModifierNames::NAMES, false)
        })
}

impl Explorer {
    /// Does the action of every key of [`SHORTCUTS`] pressed this frame, unless a text
    /// field has the keyboard.
    pub(super) fn shortcuts(&mut self, ctx: &egui::Context) {
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        for binding in bindings() {
            let pressed = binding
                .keys
                .iter()
                .any(|k| ctx.input_mut(|i| i.consume_shortcut(k)));
            if pressed {
                self.perform(binding.action, ctx);
            }
        }
    }

    fn perform(&mut self, action: Action, ctx: &egui::Context) {
        let centre = self.view_centre();
        let pane_size = self.pane_size();
        let upem = self.scene.units_per_em();
        let camera = &mut self.settings.camera;
        let visible = self.settings.layout.panes();
        let panes = &mut self.settings.panes[..visible];
        match action {
            Action::Pan(delta) => camera.pan(delta),
            Action::Zoom(factor) => camera.zoom(factor, centre, upem),
            Action::Rotate(degrees) => camera.rotate(degrees, centre, upem),
            Action::Magnify(up) => {
                let factor = if up {
                    camera.magnify * 2
                } else {
                    camera.magnify / 2
                };
                let (w, h) = (pane_size.x as u32, pane_size.y as u32);
                if w > 0 && h > 0 {
                    let window = camera.pane_camera(w, h).1;
                    let drawn_centre = (centre - window.origin()) * f64::from(window.factor);
                    camera.magnify_about(factor, drawn_centre, w, h);
                }
            }
            Action::WorstPixel => self.go_to_worst_pixel(),
            Action::StepArtifact(forward) => self.step_artifact(forward),
            Action::Blink => self.blink(),
            Action::ToggleAutoBlink => self.toggle_auto_blink(),
            Action::ResetCamera => {
                if let Some(scene) = self.scene.scene() {
                    camera.reset(scene);
                }
            }
            Action::FitText => {
                if let Some(scene) = self.scene.scene() {
                    camera.fit(scene, pane_size);
                }
            }
            Action::SetLayout(layout) => self.settings.layout = layout,
            Action::ToggleGlyphMode => self.settings.scene.glyph_mode ^= true,
            Action::ToggleOutlines => {
                let on = !panes.iter().all(|p| p.outline);
                for pane in panes {
                    pane.outline = on;
                }
            }
            Action::ToggleErrorOverlays => {
                let on = !panes.iter().any(|p| p.overlay == PaneOverlay::Error);
                for pane in panes {
                    let is_gpu_method = matches!(&pane.source,
                        PaneSource::Method { name, .. } if name != REFERENCE);
                    if on && is_gpu_method {
                        pane.overlay = PaneOverlay::Error;
                    } else if pane.overlay == PaneOverlay::Error {
                        pane.overlay = PaneOverlay::None;
                    }
                }
            }
            Action::ToggleContinuous => self.settings.continuous ^= true,
            Action::PlayPause | Action::StepFrame(_) | Action::Rewind => self.transport(action),
            Action::ToggleSweep => self.sweep.open ^= true,
            Action::OpenFont => self.ask_for_font(),
            Action::Screenshot => self.screenshot(ctx),
            Action::ToggleHelp => self.help_open ^= true,
        }
    }

    /// Saves the window as a PNG in the current folder; the status bar says where.
    pub(super) fn screenshot(&self, ctx: &egui::Context) {
        let status = self.status.clone();
        ctx.request_screenshot(move |image| {
            let stamp = web_time::SystemTime::now()
                .duration_since(web_time::UNIX_EPOCH)
                .map_or(0, |d| d.as_secs());
            let path = PathBuf::from(format!("glyphscope-{stamp}.png"));
            let [w, h] = image.size;
            let bytes: Vec<u8> = image.pixels.iter().flat_map(|p| p.to_array()).collect();
            let message = match image::RgbaImage::from_raw(w as u32, h as u32, bytes)
                .map(|img| img.save(&path))
            {
                Some(Ok(())) => format!("screenshot saved to {}", path.display()),
                Some(Err(e)) => format!("cannot write {}: {e}", path.display()),
                None => "the screenshot had no pixels".into(),
            };
            *status.lock().unwrap_or_else(|p| p.into_inner()) = message;
        });
        ctx.request_repaint();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every kind of action has keys, in one row of the help. The match names each
    /// variant by hand: a new one does not compile until it is numbered here, and a
    /// number past `KINDS` fails the test.
    #[test]
    fn every_action_is_bound_in_exactly_one_row() {
        const KINDS: usize = 22;
        let kind = |action: Action| match action {
            Action::Pan(_) => 0,
            Action::Zoom(_) => 1,
            Action::Rotate(_) => 2,
            Action::ResetCamera => 3,
            Action::FitText => 4,
            Action::SetLayout(_) => 5,
            Action::ToggleGlyphMode => 6,
            Action::ToggleOutlines => 7,
            Action::ToggleErrorOverlays => 8,
            Action::ToggleContinuous => 9,
            Action::ToggleSweep => 10,
            Action::OpenFont => 11,
            Action::Screenshot => 12,
            Action::ToggleHelp => 13,
            Action::Magnify(_) => 14,
            Action::WorstPixel => 15,
            Action::StepArtifact(_) => 16,
            Action::Blink => 17,
            Action::ToggleAutoBlink => 18,
            Action::PlayPause => 19,
            Action::StepFrame(_) => 20,
            Action::Rewind => 21,
        };
        let mut rows: [Vec<&str>; KINDS] = Default::default();
        for shortcut in SHORTCUTS {
            let Input::Keys(bindings) = shortcut.input else {
                continue;
            };
            for binding in bindings {
                assert!(
                    !binding.keys.is_empty(),
                    "{}: a binding with no keys",
                    shortcut.keys
                );
                let seen = &mut rows[kind(binding.action)];
                if !seen.contains(&shortcut.keys) {
                    seen.push(shortcut.keys);
                }
            }
        }
        for (k, seen) in rows.iter().enumerate() {
            assert_eq!(seen.len(), 1, "action kind {k} is in the rows {seen:?}");
        }
    }

    /// Two rows on one key: the first would consume it and the second never fire.
    #[test]
    fn no_key_does_two_things() {
        let keys: Vec<KeyboardShortcut> = bindings().flat_map(|b| b.keys.iter().copied()).collect();
        for (i, k) in keys.iter().enumerate() {
            assert!(!keys[..i].contains(k), "{k:?} is bound twice");
        }
    }

    #[test]
    fn hover_hints_name_the_first_key() {
        assert_eq!(key_name(Action::OpenFont), "Ctrl+O");
        assert_eq!(key_name(Action::ToggleHelp), "H");
        assert_eq!(key_name(Action::SetLayout(Layout::Grid)), "4");
        assert_eq!(key_name(Action::Zoom(3.0)), "");
    }

    /// The explorer page's table of keys is this one, row for row.
    #[test]
    fn the_explorer_page_lists_every_shortcut() {
        let page = include_str!("../../docs/explorer.md");
        let table: Vec<&str> = page
            .lines()
            .skip_while(|l| *l != "| keys | what |")
            .skip(2)
            .take_while(|l| l.starts_with('|'))
            .collect();
        let expected: Vec<String> = SHORTCUTS
            .iter()
            .map(|s| format!("| {} | {} |", s.keys, s.what))
            .collect();
        assert_eq!(table, expected);
    }
}
