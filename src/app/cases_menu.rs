//! The Cases menu: every named view of [`crate::named_views`] — the hard cases of
//! `glyphscope stability` and the bench's scenes — loaded into the panes so that each
//! pane pixel is the pixel `glyphscope render --case NAME` draws there, then magnified on
//! the worst pixel of the first pane that shows a GPU method, with each pixel's value
//! and the exact outline drawn. A case added to either source is in the menu.

use eframe::egui;

use super::explorer::Explorer;
use super::settings::CameraSettings;
use crate::named_views::{self, Source};

/// A loaded case's magnification: the first at which each pixel's value is written.
pub const VALUES_MAGNIFY: u32 = crate::magnify::VALUES_FROM;

impl Explorer {
    /// The menu button and its list, hard cases first.
    pub(super) fn cases_menu(&mut self, ui: &mut egui::Ui) {
        let mut chosen = None;
        ui.menu_button("Cases", |ui| {
            let views = self.cases.views.get_or_insert_with(named_views::all);
            egui::ScrollArea::vertical()
                .max_height(480.0)
                .show(ui, |ui| {
                    for (source, heading) in [
                        (Source::HardCase, "hard cases (glyphscope stability)"),
                        (Source::BenchScene, "bench scenes (glyphscope bench)"),
                    ] {
                        ui.weak(heading);
                        for view in views.iter().filter(|v| v.source == source) {
                            if ui.button(view.name).on_hover_text(view.about).clicked() {
                                chosen = Some(view.name);
                                ui.close();
                            }
                        }
                    }
                });
        })
        .response
        .on_hover_text("load a named hard case or bench scene, magnified on its worst pixel");
        if let Some(name) = chosen {
            self.load_case(name);
        }
    }

    /// Shows the named view `name` in the panes (placed once the scene is built).
    pub fn load_case(&mut self, name: &str) {
        self.settings.scene.case = Some(name.to_owned());
        self.remember_the_scene_under_the_case();
        self.auto_fit.pending = true;
    }

    /// Keeps the font, text and glyph settings a case is shown over, so that a change to
    /// them (a font opened, a key) leaves the case.
    pub(super) fn remember_the_scene_under_the_case(&mut self) {
        let mut over = self.settings.scene.clone();
        over.case = None;
        self.cases.loaded_over = Some(over);
    }

    /// The loaded case's name, what it is, and a button back to the text.
    pub(super) fn case_controls(&mut self, ui: &mut egui::Ui) {
        let Some(name) = self.settings.scene.case.clone() else {
            return;
        };
        ui.horizontal_wrapped(|ui| {
            ui.strong(format!("case: {name}"));
            if ui
                .button("back to the text")
                .on_hover_text("leave the case: show the font, text and glyph below")
                .clicked()
            {
                self.settings.scene.case = None;
            }
        });
        let views = self.cases.views.get_or_insert_with(named_views::all);
        if let Some(view) = views.iter().find(|v| v.name == name) {
            ui.weak(view.about);
        }
    }

    /// Leaves the case when the font, text or glyph settings change under it (from the
    /// controls, a key or a dropped file alike); once a frame.
    pub(super) fn leave_case_on_scene_change(&mut self) {
        let scene = &mut self.settings.scene;
        if scene.case.is_some() {
            let mut now = scene.clone();
            now.case = None;
            // A case remembered from the last run is loaded over what is there now.
            let over = self.cases.loaded_over.get_or_insert_with(|| now.clone());
            if *over != now {
                scene.case = None;
            }
        }
        if scene.case.is_none() && self.cases.loaded_over.take().is_some() {
            // Left (by the button or a change): the text framed again, outlines as they were.
            if let Some(outlines) = self.cases.outlines_before.take() {
                for (pane, outline) in self.settings.panes.iter_mut().zip(outlines) {
                    pane.outline = outline;
                }
            }
            self.auto_fit.pending = true;
        }
    }

    /// Places a loaded case in panes of `pane` pixels: true when the scene is a case
    /// (placed, or said why not).
    pub(super) fn place_case(&mut self, pane: (u32, u32)) -> bool {
        let Some(frame) = self.scene.case_camera() else {
            return false;
        };
        match CameraSettings::of_frame(frame, pane.0, pane.1) {
            Some(camera) => {
                // Magnified enough to write each pixel's value, with the exact outline
                // over the pixels: the artifact, its numbers and where the edge runs.
                self.settings.camera = CameraSettings {
                    magnify: VALUES_MAGNIFY,
                    ..camera
                };
                let panes = &mut self.settings.panes;
                self.cases
                    .outlines_before
                    .get_or_insert_with(|| panes.each_ref().map(|p| p.outline));
                let shown = self.settings.layout.panes();
                for pane in &mut panes[..shown] {
                    pane.outline = true;
                }
                self.go_to_worst_pixel_when_ready();
            }
            None => self.set_status(
                "this case's matrix is not a rotation after a skew; the explorer's camera \
                 cannot hold it"
                    .into(),
            ),
        }
        true
    }
}
