//! "Open font…": a path field and a folder listing of the font files in it, inside the
//! app, so it works the same on any desktop and under Xvfb or a test harness (a native
//! dialog needs a desktop portal). Dropping a file on the window opens it too. The web
//! page has no file system: there "Open font…" is the browser's file picker (`web`),
//! and a dropped file arrives as bytes.

use std::path::{Path, PathBuf};

use eframe::egui;

pub struct FontDialog {
    pub open: bool,
    /// The path typed or picked: a font file, or a folder to list.
    pub path: String,
}

impl Default for FontDialog {
    fn default() -> Self {
        let start = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("/"));
        FontDialog {
            open: false,
            path: start.display().to_string(),
        }
    }
}

/// Whether a file name looks like a font the core can read.
pub fn is_font_file(path: &Path) -> bool {
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
        matches!(
            e.to_ascii_lowercase().as_str(),
            "ttf" | "otf" | "ttc" | "otc"
        )
    })
}

/// Folders, then font files, in `dir`, each sorted by name.
fn listing(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir() || is_font_file(p))
        .filter(|p| {
            !p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    paths.sort_by_key(|p| (!p.is_dir(), p.file_name().map(|n| n.to_os_string())));
    paths
}

impl FontDialog {
    /// Shows the window; returns a font file the user chose to open.
    pub fn show(&mut self, ctx: &egui::Context) -> Option<PathBuf> {
        let mut chosen = None;
        let mut open = self.open;
        egui::Window::new("Open font")
            .open(&mut open)
            .default_width(420.0)
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    let label = ui.label("path");
                    let field = ui
                        .add(
                            egui::TextEdit::singleline(&mut self.path)
                                .desired_width(300.0)
                                .id_salt("font path"),
                        )
                        .labelled_by(label.id);
                    let entered =
                        field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                    if ui.button("Open").clicked() || entered {
                        chosen = Some(PathBuf::from(self.path.trim()));
                    }
                });
                let here = PathBuf::from(self.path.trim());
                let dir = if here.is_dir() {
                    here
                } else {
                    here.parent().map(Path::to_path_buf).unwrap_or_default()
                };
                if let Some(parent) = dir.parent()
                    && ui.button("Up one folder").clicked()
                {
                    self.path = parent.display().to_string();
                }
                egui::ScrollArea::vertical()
                    .max_height(300.0)
                    .show(ui, |ui| {
                        for path in listing(&dir) {
                            let name = path
                                .file_name()
                                .map(|n| n.to_string_lossy().into_owned())
                                .unwrap_or_default();
                            let label = if path.is_dir() {
                                format!("{name}/")
                            } else {
                                name
                            };
                            let response =
                                ui.selectable_label(path.display().to_string() == self.path, label);
                            if response.double_clicked() && !path.is_dir() {
                                chosen = Some(path.clone());
                            }
                            if response.clicked() {
                                self.path = path.display().to_string();
                            }
                        }
                    });
                ui.weak("Or drop a .ttf/.otf file on the window.");
            });
        self.open = open;
        if let Some(path) = &chosen
            && path.is_dir()
        {
            self.path = path.display().to_string();
            return None;
        }
        if chosen.is_some() {
            self.open = false;
        }
        chosen
    }
}
