//! The panes: which methods there are and what each can show (the catalog), each pane's
//! method kept prepared for the scene (prepared again only when the scene or its
//! parameters change), and the controls that choose them.

use std::sync::Arc;
use web_time::Instant;

use eframe::egui;

use super::file_dialog::{FileDialog, FileKind};
use super::gpu_view::{PaneSurface, SharedSurface, lock};
use super::settings::{PaneOverlay, PaneSettings, PaneSource};
use super::trial::{self, Trial};
use crate::camera::Camera;
use crate::coverage::CoverageImage;
use crate::gpu::GpuContext;
use crate::methods::params::{Numbers, ParamSpec, given_text};
use crate::methods::{CurveCost, Overlay};
use crate::methods::{registry, user};
use crate::metrics::ErrorStats;
use crate::scene::Scene;

/// The CPU reference's name among the methods.
pub const REFERENCE: &str = registry::REFERENCE.name;

/// Every method of this build, and what each can do.
pub struct Catalog {
    pub methods: Vec<MethodEntry>,
}

pub struct MethodEntry {
    pub name: &'static str,
    /// Why it cannot be used on this device or scene, in one line.
    pub unavailable: Option<String>,
    pub overlays: &'static [Overlay],
}

impl Catalog {
    /// Asks each method of the registry for itself with default parameters.
    pub fn discover() -> Catalog {
        let methods = registry::METHODS
            .iter()
            .map(|info| {
                let name = info.name;
                if info.constructor.is_none() {
                    return MethodEntry {
                        name,
                        unavailable: None,
                        overlays: &[],
                    };
                }
                match info.create(&[]) {
                    Ok(method) => MethodEntry {
                        name,
                        unavailable: None,
                        overlays: method.overlays(),
                    },
                    Err(e) => MethodEntry {
                        name,
                        unavailable: Some(e.to_string()),
                        overlays: &[],
                    },
                }
            })
            .collect();
        Catalog { methods }
    }

    pub fn get(&self, name: &str) -> Option<&MethodEntry> {
        self.methods.iter().find(|m| m.name == name)
    }

    /// The methods that can be drawn, on the GPU.
    pub fn gpu_methods(&self) -> impl Iterator<Item = &MethodEntry> {
        self.methods
            .iter()
            .filter(|m| m.unavailable.is_none() && m.name != REFERENCE)
    }

    /// Why method `name` cannot draw `overlay`, or None if it can.
    pub fn overlay_unavailable(&self, name: &str, overlay: Overlay) -> Option<String> {
        if self
            .get(name)
            .is_some_and(|m| m.overlays.contains(&overlay))
        {
            return None;
        }
        let able: Vec<&str> = self
            .gpu_methods()
            .filter(|m| m.overlays.contains(&overlay))
            .map(|m| m.name)
            .collect();
        Some(if able.is_empty() {
            format!(
                "'{name}' cannot draw {}; no method in this build draws it yet",
                overlay_description(overlay)
            )
        } else {
            format!(
                "'{name}' cannot draw {}; {} can",
                overlay_description(overlay),
                able.join(", ")
            )
        })
    }
}

/// What an overlay shows, for labels and tooltips.
pub fn overlay_description(overlay: Overlay) -> &'static str {
    match overlay {
        Overlay::EqualDistance => "the purple equal-distance regions",
        Overlay::CellGrid => "the cell grid, cells tinted by how many curves they list",
        Overlay::CurveClasses => "each curve's sign class for the ray through the pixel",
        Overlay::CostHeatMap => "curves evaluated per pixel, on a colour scale",
        Overlay::TriangleWireframe => "the triangles as wireframe",
        Overlay::SubdivisionPoints => "where curves were subdivided",
        Overlay::FieldChannels => "the distance field's channels as colour",
        Overlay::MedianChannel => "the channel the field's median picks",
    }
}

/// A pane at run time: its GPU surface and the numbers shown with it.
pub struct Pane {
    pub surface: SharedSurface,
    /// What the surface's method was made from: the pane's source and method overlay, and the
    /// scene generation it was prepared for.
    built: Option<(PaneSource, Option<String>, u64)>,
    /// Why the pane shows nothing (method unavailable, bad parameters, preparing failed),
    /// or, for a user's file, why its last save does not draw.
    pub problem: Option<String>,
    /// For a user's file (`wgsl:PATH`): a hash of its text when the pane last made its
    /// method; a save that changes it reloads the pane.
    user_stamp: Option<u64>,
    pub gpu_bytes: u64,
    pub prepare_ms: f64,
    pub curves: Option<(Camera, CurveCost)>,
    pub error: Option<(Camera, ErrorStats)>,
    /// This pane's coverage for a resting camera, read back for the error and the
    /// pixel inspector.
    pub capture: Option<(Camera, Arc<CoverageImage>)>,
}

impl Pane {
    pub fn new() -> Pane {
        Pane {
            surface: PaneSurface::new(),
            built: None,
            problem: None,
            user_stamp: None,
            gpu_bytes: 0,
            prepare_ms: 0.0,
            curves: None,
            error: None,
            capture: None,
        }
    }

    /// Makes the pane's method match its settings and the scene: creates and prepares
    /// it when either changed, and does nothing otherwise (so never per frame).
    pub fn sync(
        &mut self,
        gpu: &GpuContext,
        catalog: &Catalog,
        settings: &PaneSettings,
        scene: Option<(&Scene, u64)>,
    ) {
        let generation = scene.map_or(0, |(_, g)| g);
        let wanted = (
            settings.source.clone(),
            method_overlay(settings),
            generation,
        );
        let stamp = user_file(settings).and_then(user::stamp);
        // A user's file that compiles is drawn once it has been drawn in a process of
        // its own (`trial`): a loop that never returns hangs that one, not this one.
        // Asked only where the pane is to make its method: not every frame.
        let trial = || match (user_file(settings), stamp) {
            (Some(name), Some(stamp)) if user::find(name).is_ok() => trial::of(name, stamp),
            _ => Trial::Passed,
        };
        if self.built.as_ref() == Some(&wanted) {
            if stamp != self.user_stamp {
                let drawing = lock(&self.surface).method.is_some();
                let last = if drawing {
                    " (drawing the last version that passed)"
                } else {
                    ""
                };
                match trial() {
                    // Asked again next frame (the pane repaints while it draws a file).
                    Trial::Running => {
                        self.problem = Some(format!("{TRYING}{last}"));
                        return;
                    }
                    Trial::Failed(why) => {
                        self.user_stamp = stamp;
                        self.problem = Some(format!("{why}{last}"));
                    }
                    // The user's file was saved: reloaded where it stands, camera and all.
                    Trial::Passed => {
                        self.user_stamp = stamp;
                        self.reload(gpu, settings, scene);
                    }
                }
            }
            return;
        }
        self.built = Some(wanted);
        self.user_stamp = stamp;
        self.problem = None;
        self.gpu_bytes = 0;
        self.curves = None;
        self.error = None;
        self.capture = None;
        let mut surface = lock(&self.surface);
        surface.method = None;
        surface.generation += 1;
        surface.timer.clear();
        let PaneSource::Method { name, params } = &settings.source else {
            return;
        };
        if name == REFERENCE {
            return;
        }
        if let Some(reason) = catalog.get(name).and_then(|m| m.unavailable.clone()) {
            self.problem = Some(reason);
            return;
        }
        let Some((scene, _)) = scene else {
            return;
        };
        match trial() {
            Trial::Running => {
                // Made once the trial has passed: asked again next frame.
                self.problem = Some(TRYING.into());
                self.built = None;
                return;
            }
            Trial::Failed(why) => {
                self.problem = Some(why);
                return;
            }
            Trial::Passed => {}
        }
        let start = Instant::now();
        let made = prepared_method(gpu, settings, name, params, scene);
        self.prepare_ms = start.elapsed().as_secs_f64() * 1e3;
        if made.is_ok() && !made_what_was_tried(name, stamp) {
            // Saved again between the trial and this read: made once that text passes.
            self.problem = Some(TRYING.into());
            self.built = None;
            return;
        }
        match made {
            Ok(method) => {
                self.gpu_bytes = method.gpu_bytes();
                surface.method = Some(method);
            }
            Err(e) => self.problem = Some(e.to_string()),
        }
    }

    /// A user's file saved since the pane drew it, made again. Where the new text does
    /// not compile or prepare, the last version that did keeps drawing, with the error
    /// beside it.
    fn reload(&mut self, gpu: &GpuContext, settings: &PaneSettings, scene: Option<(&Scene, u64)>) {
        let (Some((scene, _)), PaneSource::Method { name, params }) = (scene, &settings.source)
        else {
            return;
        };
        let start = Instant::now();
        let made = prepared_method(gpu, settings, name, params, scene);
        if made.is_ok() && !made_what_was_tried(name, self.user_stamp) {
            // Saved again between the trial and this read: tried again next frame.
            self.user_stamp = None;
            return;
        }
        let mut surface = lock(&self.surface);
        match made {
            Ok(method) => {
                self.prepare_ms = start.elapsed().as_secs_f64() * 1e3;
                self.problem = None;
                self.curves = None;
                self.error = None;
                self.capture = None;
                self.gpu_bytes = method.gpu_bytes();
                surface.method = Some(method);
                surface.generation += 1;
                surface.timer.clear();
            }
            Err(e) if surface.method.is_some() => {
                self.problem = Some(format!("{e} (drawing the last version that compiled)"));
            }
            Err(e) => self.problem = Some(e.to_string()),
        }
    }

    /// Whether the pane's method was made from `settings` for scene `generation` (and,
    /// for a user's file, from its text as it is now).
    pub fn is_built_for(&self, settings: &PaneSettings, generation: u64) -> bool {
        self.built.as_ref().is_some_and(|(source, overlay, g)| {
            (source, overlay, *g) == (&settings.source, &method_overlay(settings), generation)
        }) && user_file(settings).is_none_or(|name| user::stamp(name) == self.user_stamp)
    }

    /// Whether the pane's picture is this method's own (not the reference or a difference).
    pub fn has_method(&self) -> bool {
        lock(&self.surface).method.is_some()
    }
}

/// Method `name` made with the pane's `params` and overlay, and prepared for `scene`.
fn prepared_method(
    gpu: &GpuContext,
    settings: &PaneSettings,
    name: &str,
    params: &[(String, String)],
    scene: &Scene,
) -> Result<Box<dyn crate::methods::Method>, crate::Error> {
    let mut params = params.to_vec();
    if let Some(overlay) = method_overlay(settings) {
        params.push(("overlay".into(), overlay));
    }
    let mut method = registry::create(name, &params)?;
    method.prepare(gpu, scene)?;
    Ok(method)
}

/// Whether a method made for `name` was made from the text stamped `tried` (the one
/// its trial drew): always, for a name that is not a user's file.
fn made_what_was_tried(name: &str, tried: Option<u64>) -> bool {
    !name.starts_with(user::PREFIX) || user::made_from(name) == tried
}

/// The user's file a pane draws (`wgsl:PATH`), if it draws one.
pub fn user_file(settings: &PaneSettings) -> Option<&str> {
    match &settings.source {
        PaneSource::Method { name, .. } if name.starts_with(user::PREFIX) => Some(name),
        _ => None,
    }
}

/// What a pane says while a user's file is tried in a process of its own (`trial`).
const TRYING: &str = "drawing your shader in a separate process first (a loop that never \
                      returns would hang the explorer)…";

/// The file the "your shader…" entry opens first: the example of docs/your-method.md.
const FIRST_USER_FILE: &str = "examples/methods/supersampled.wgsl";

/// The current value of a parameter (its default when not given).
fn param_value(params: &[(String, String)], spec: &ParamSpec) -> String {
    given_text(params, spec.key)
        .unwrap_or(spec.choices[0])
        .to_string()
}

fn set_param(params: &mut Vec<(String, String)>, spec: &ParamSpec, value: String) {
    params.retain(|(k, _)| k != spec.key);
    if value != spec.choices[0] {
        params.push((spec.key.to_string(), value));
    }
}

/// The controls of pane `index`: method (or difference), parameters, overlays.
pub fn pane_controls(
    ui: &mut egui::Ui,
    index: usize,
    pane: &mut PaneSettings,
    catalog: &Catalog,
    visible_panes: usize,
) {
    let current = match &pane.source {
        PaneSource::Method { name, .. } => name.clone(),
        PaneSource::Difference { .. } => "difference".into(),
    };
    egui::ComboBox::new((index, "method"), "method")
        .selected_text(&current)
        .width(150.0)
        .show_ui(ui, |ui| {
            for entry in &catalog.methods {
                let response = ui
                    .add_enabled(
                        entry.unavailable.is_none(),
                        egui::Button::selectable(current == entry.name, entry.name),
                    )
                    .on_disabled_hover_text(entry.unavailable.clone().unwrap_or_default());
                if response.clicked() && current != entry.name {
                    pane.source = PaneSource::Method {
                        name: entry.name.into(),
                        params: Vec::new(),
                    };
                    pane.overlay = PaneOverlay::None;
                }
            }
            let response = ui
                .add_enabled(
                    index > 0,
                    egui::Button::selectable(current == "difference", "difference"),
                )
                .on_hover_text("signed difference of two panes, or of a pane and the reference")
                .on_disabled_hover_text("the first pane always shows a method");
            if response.clicked() && current != "difference" {
                pane.source = PaneSource::Difference {
                    first: 0,
                    second: None,
                };
                pane.overlay = PaneOverlay::None;
            }
            let yours = current.starts_with(user::PREFIX);
            let response = ui
                .add(egui::Button::selectable(yours, "your shader…"))
                .on_hover_text(
                    "a WGSL file defining user_coverage, drawn on winding's quads and data \
                     and reloaded when it is saved (docs/your-method.md)",
                );
            if response.clicked() && !yours {
                pane.source = PaneSource::Method {
                    name: format!("{}{FIRST_USER_FILE}", user::PREFIX),
                    params: Vec::new(),
                };
                pane.overlay = PaneOverlay::None;
            }
        });
    // A user's file: its path, edited in place (applied on Enter or leaving the field).
    if let PaneSource::Method { name, .. } = &mut pane.source
        && let Some((path_name, given)) = user::split(name)
        && let Some(path) = path_name.strip_prefix(user::PREFIX)
    {
        // What follows the path (a claim given with it) stays with the file chosen.
        let given = given.to_owned();
        // What is being typed, until applied: kept with the path it started from, so a
        // path changed elsewhere (a link, the settings) starts the field anew.
        let id = ui.scope_id().with(("user file", index));
        let mut text = ui
            .data(|d| d.get_temp::<(String, String)>(id))
            .filter(|(from, _)| from == path)
            .map_or_else(|| path.to_owned(), |(_, text)| text);
        // Or picked from a folder listing of .wgsl files (`file_dialog`), starting at
        // the file drawn now.
        let dialog_id = ui.scope_id().with(("user file dialog", index));
        let mut dialog = ui
            .data(|d| d.get_temp::<FileDialog>(dialog_id))
            .unwrap_or_else(|| FileDialog::new(FileKind::Shader));
        let mut chosen = None;
        ui.horizontal(|ui| {
            let response = ui.add(
                egui::TextEdit::singleline(&mut text)
                    .hint_text("path/to/your.wgsl")
                    .desired_width(220.0),
            );
            if response.lost_focus() && text != path {
                chosen = Some(text.clone());
            }
            if ui
                .button("Open…")
                .on_hover_text("pick a .wgsl file from a folder")
                .clicked()
            {
                dialog.open = true;
                dialog.path = path.to_owned();
            }
        });
        if dialog.open
            && let Some(file) = dialog.show(ui.ctx(), index)
        {
            chosen = Some(file.display().to_string());
        }
        let from = path.to_owned();
        ui.data_mut(|d| {
            d.insert_temp(id, (from, text));
            d.insert_temp(dialog_id, dialog);
        });
        if let Some(chosen) = chosen {
            *name = format!("{}{chosen}{given}", user::PREFIX);
        }
    }
    if let Some(reason) = catalog.get(&current).and_then(|m| m.unavailable.as_ref()) {
        ui.colored_label(ui.visuals().weak_text_color(), reason);
    }
    match &mut pane.source {
        PaneSource::Method { name, params } => {
            for spec in registry::param_specs(name) {
                // Overlays have their own row.
                if spec.key == "overlay" {
                    continue;
                }
                param_control(ui, index, spec, params);
            }
        }
        PaneSource::Difference { first, second } => {
            difference_controls(ui, index, first, second, visible_panes);
        }
    }
    overlay_controls(ui, pane, catalog);
}

fn param_control(
    ui: &mut egui::Ui,
    index: usize,
    spec: &ParamSpec,
    params: &mut Vec<(String, String)>,
) {
    let mut value = param_value(params, spec);
    let before = value.clone();
    ui.horizontal(|ui| {
        ui.label(spec.key).on_hover_text(spec.help);
        egui::ComboBox::from_id_salt((index, spec.key))
            .selected_text(&value)
            .show_ui(ui, |ui| {
                for choice in spec.choices {
                    ui.selectable_value(&mut value, choice.to_string(), *choice);
                }
            })
            .response
            .on_hover_text(spec.help);
        let allowed = format!("{}: {}", spec.key, spec.allowed());
        match spec.numbers {
            Some(Numbers::Whole { min, max }) => {
                let mut n = value.parse::<u32>().unwrap_or(min);
                let response = ui
                    .add(egui::DragValue::new(&mut n).range(min..=max))
                    .on_hover_text(allowed);
                if response.changed() {
                    value = n.to_string();
                }
            }
            Some(Numbers::Real { min, max, .. }) => {
                let mut x = value.parse::<f64>().unwrap_or(min);
                // A few hundred pixels of drag across the range, or steps of 0.1
                // where it has no end.
                let speed = if max.is_finite() {
                    (max - min) / 500.0
                } else {
                    0.1
                };
                let response = ui
                    .add(egui::DragValue::new(&mut x).range(min..=max).speed(speed))
                    .on_hover_text(allowed);
                if response.changed() {
                    value = x.to_string();
                }
            }
            None => {}
        }
    });
    if value != before {
        set_param(params, spec, value);
    }
}

/// How the explorer names pane `index`: A, B, C, D.
pub fn pane_letter(index: usize) -> char {
    (b'A' + index as u8) as char
}

/// What a difference pane subtracts, named: pane `second`, or the reference when None.
pub fn subtrahend_label(second: Option<usize>) -> String {
    second.map_or_else(|| REFERENCE.to_string(), |i| pane_letter(i).to_string())
}

fn difference_controls(
    ui: &mut egui::Ui,
    index: usize,
    first: &mut usize,
    second: &mut Option<usize>,
    visible_panes: usize,
) {
    let others: Vec<usize> = (0..visible_panes).filter(|&i| i != index).collect();
    ui.horizontal(|ui| {
        egui::ComboBox::from_id_salt((index, "first"))
            .selected_text(pane_letter(*first).to_string())
            .width(40.0)
            .show_ui(ui, |ui| {
                for &i in &others {
                    ui.selectable_value(first, i, pane_letter(i).to_string());
                }
            });
        ui.label("−");
        egui::ComboBox::from_id_salt((index, "second"))
            .selected_text(subtrahend_label(*second))
            .width(80.0)
            .show_ui(ui, |ui| {
                ui.selectable_value(second, None, REFERENCE);
                for &i in &others {
                    ui.selectable_value(second, Some(i), pane_letter(i).to_string());
                }
            });
    });
}

/// One toggle per overlay: the method's own (greyed with the reason where it has none),
/// the error against the reference, and the outline on top.
fn overlay_controls(ui: &mut egui::Ui, pane: &mut PaneSettings, catalog: &Catalog) {
    let method = match &pane.source {
        PaneSource::Method { name, .. } => Some(name.clone()),
        PaneSource::Difference { .. } => None,
    };
    let is_reference = method.as_deref() == Some(REFERENCE);
    ui.horizontal_wrapped(|ui| {
        ui.label("overlay");
        let mut choose = |ui: &mut egui::Ui,
                          overlay: PaneOverlay,
                          label: &str,
                          unavailable: Option<String>,
                          help: &str| {
            let selected = pane.overlay == overlay;
            let response = ui
                .add_enabled(
                    unavailable.is_none(),
                    egui::Button::selectable(selected, label),
                )
                .on_hover_text(help)
                .on_disabled_hover_text(unavailable.unwrap_or_default());
            if response.clicked() {
                pane.overlay = if selected { PaneOverlay::None } else { overlay };
            }
        };
        for overlay in Overlay::ALL {
            let unavailable = match &method {
                Some(name) => catalog.overlay_unavailable(name, overlay),
                None => Some("a difference pane draws no method overlay".into()),
            };
            choose(
                ui,
                PaneOverlay::Method(overlay.name().into()),
                overlay.name(),
                unavailable,
                overlay_description(overlay),
            );
        }
        let error_unavailable = if is_reference {
            Some("the reference is what the error is measured against".into())
        } else if method.is_none() {
            Some("a difference pane already shows a difference".into())
        } else {
            None
        };
        choose(
            ui,
            PaneOverlay::Error,
            "error",
            error_unavailable,
            "signed error against the reference, once the view rests (red: too much \
             coverage, blue: too little)",
        );
        ui.checkbox(&mut pane.outline, "outline points")
            .on_hover_text("the font's outline: on-curve points filled, off-curve hollow");
        ui.checkbox(&mut pane.merged, "merged outline")
            .on_hover_text(
                "green, under the font's outline: each glyph's contours merged into their nonzero \
             union (what sdf-cells and winding draw from with overlaps=merge, their default); a \
             curve inside the fill shows orange alone",
            );
    });
}

/// The `overlay` parameter a pane's method is made with. Only method overlays change the
/// method; the error overlay is the compositor's, so toggling it prepares nothing.
fn method_overlay(settings: &PaneSettings) -> Option<String> {
    match &settings.overlay {
        PaneOverlay::Method(name) => Some(name.clone()),
        PaneOverlay::None | PaneOverlay::Error => None,
    }
}
