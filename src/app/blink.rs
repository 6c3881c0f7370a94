//! Blink: pane A shows, in place, the other rendering of the same pixels — pane B's
//! method when pane B is visible and shows one, else the reference — flipped on each
//! press, or a few times a second on its own: the eye catches what changes between two
//! pictures of one place far better than it compares two places.

use std::time::Duration;

use eframe::egui;

use super::explorer::Explorer;
use super::gpu_view::Source;
use super::panes::{REFERENCE, pane_letter};
use super::settings::PaneSource;

/// Flips per second while blinking on its own.
const AUTO_FLIPS_PER_S: f64 = 3.0;

/// The pane that blinks.
pub const BLINKING_PANE: usize = 0;

impl Explorer {
    /// Flips pane A to the other rendering or back (and stops blinking on its own).
    pub(super) fn blink(&mut self) {
        self.blink.auto = false;
        self.blink.flipped ^= true;
    }

    /// Starts or stops blinking on its own; stopped, pane A shows its own method.
    pub(super) fn toggle_auto_blink(&mut self) {
        self.blink.auto ^= true;
        self.blink.flipped = false;
    }

    /// Flips pane A on the clock while blinking on its own; once a frame.
    pub(super) fn tick_blink(&mut self, ctx: &egui::Context) {
        if !self.blink.auto {
            return;
        }
        let time = ctx.input(|i| i.time);
        self.blink.flipped = (time * AUTO_FLIPS_PER_S) as u64 % 2 == 1;
        ctx.request_repaint_after(Duration::from_secs_f64(1.0 / AUTO_FLIPS_PER_S));
    }

    /// What pane A shows instead of its own method while flipped, and its name for the
    /// pane's title; None when it shows its own (or the other is not ready yet).
    pub(super) fn blink_source(&self) -> Option<(Source, String)> {
        if !self.blink.flipped {
            return None;
        }
        let other = BLINKING_PANE + 1;
        if self.settings.layout.panes() > other
            && let PaneSource::Method { name, .. } = &self.settings.panes[other].source
            && name != REFERENCE
            && self.panes[other].has_method()
        {
            let shown = format!("pane {}'s {name}", pane_letter(other));
            return Some((Source::Pane(self.panes[other].surface.clone()), shown));
        }
        self.reference_is_current().then(|| {
            (
                Source::Reference(self.reference.texture.clone()),
                "the reference".into(),
            )
        })
    }
}
