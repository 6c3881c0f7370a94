//! Fonts (`glyphscope_core::font`) and the fonts glyphscope ships in `fonts/`, embedded
//! in the explorer and the command line so that everything works without `--font`. The
//! core and the text library embed none: an app brings its own.

pub use glyphscope_core::font::*;

/// DejaVu Sans, embedded so that everything works without `--font`.
pub const DEFAULT_FONT_BYTES: &[u8] = include_bytes!("../fonts/DejaVuSans.ttf");
pub const DEFAULT_FONT_NAME: &str = "DejaVu Sans";

/// The fonts shipped in `fonts/`, embedded: (name, file name, bytes). Each is there for
/// a reason the methods must face: TrueType quadratics, CFF cubics, a variable font
/// whose glyphs overlap, and a complex script.
pub const SHIPPED_FONTS: &[(&str, &str, &[u8])] = &[
    (DEFAULT_FONT_NAME, "DejaVuSans.ttf", DEFAULT_FONT_BYTES),
    (
        "Latin Modern Roman 10",
        "lmroman10-regular.otf",
        include_bytes!("../fonts/lmroman10-regular.otf"),
    ),
    (
        "Inter (variable)",
        "Inter-roman.var.ttf",
        include_bytes!("../fonts/Inter-roman.var.ttf"),
    ),
    (
        "Lohit Bengali",
        "Lohit-Bengali.ttf",
        include_bytes!("../fonts/Lohit-Bengali.ttf"),
    ),
];

/// The embedded default font.
pub fn default_font() -> Font {
    shipped(0)
}

/// The `index`-th of [`SHIPPED_FONTS`].
pub fn shipped(index: usize) -> Font {
    let (name, _, bytes) = SHIPPED_FONTS[index];
    Font::from_bytes(bytes.to_vec(), name).expect("shipped fonts parse")
}
