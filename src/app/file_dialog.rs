//! "Open font…" and a pane's "Open…" for your shader: a path field and a folder listing
//! of the files of the kind asked for, inside the app, so it works the same on any
//! desktop and under Xvfb or a test harness (a native dialog needs a desktop portal).
//! Dropping a font file on the window opens it too. The web page has no file system:
//! there "Open font…" is the browser's file picker (`web`), and a dropped file arrives
//! as bytes.

use std::path::{Path, PathBuf};

use eframe::egui;

#[derive(Clone, Debug)]
pub struct FileDialog {
    pub open: bool,
    /// The path typed or picked: a file, or a folder to list.
    pub path: String,
    pub kind: FileKind,
}

/// What a dialog opens.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileKind {
    Font,
    /// A WGSL file: your own method (docs/your-method.md).
    Shader,
}

impl FileKind {
    fn title(self) -> &'static str {
        match self {
            FileKind::Font => "Open font",
            FileKind::Shader => "Open your shader",
        }
    }

    fn lists(self, path: &Path) -> bool {
        match self {
            FileKind::Font => is_font_file(path),
            FileKind::Shader => path.extension().is_some_and(|e| e == "wgsl"),
        }
    }

    fn hint(self) -> &'static str {
        match self {
            FileKind::Font => "Or drop a .ttf/.otf file on the window.",
            FileKind::Shader => {
                "A .wgsl file defining user_coverage (docs/your-method.md); the pane \
                 draws it again whenever it is saved."
            }
        }
    }
}

impl FileDialog {
    /// A closed dialog for `kind`, listing the working folder.
    pub fn new(kind: FileKind) -> Self {
        let start = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("/"));
        FileDialog {
            open: false,
            path: start.display().to_string(),
            kind,
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

/// Folders, then the files of `kind`, in `dir`, each sorted by name.
fn listing(dir: &Path, kind: FileKind) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir() || kind.lists(p))
        .filter(|p| {
            !p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with('.'))
        })
        .collect();
    paths.sort_by_key(|p| (!p.is_dir(), p.file_name().map(|n| n.to_os_string())));
    paths
}

impl FileDialog {
    /// Shows the window (`id` tells two dialogs of one kind apart); returns a file the
    /// user chose to open.
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        id: impl std::hash::Hash + std::fmt::Debug,
    ) -> Option<PathBuf> {
        let mut chosen = None;
        let mut open = self.open;
        let kind = self.kind;
        egui::Window::new(kind.title())
            .id(egui::Id::unique(("file dialog", kind.title(), id)))
            .open(&mut open)
            .default_width(420.0)
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    let label = ui.label("path");
                    let field = ui
                        .add(
                            egui::TextEdit::singleline(&mut self.path)
                                .desired_width(300.0)
                                .id_salt((kind.title(), "path")),
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
                    // A bare file name's folder is the working one.
                    here.parent()
                        .filter(|p| !p.as_os_str().is_empty())
                        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
                };
                if let Some(parent) = dir.parent()
                    && ui.button("Up one folder").clicked()
                {
                    self.path = parent.display().to_string();
                }
                egui::ScrollArea::vertical()
                    .max_height(300.0)
                    .show(ui, |ui| {
                        for path in listing(&dir, kind) {
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
                ui.weak(kind.hint());
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
