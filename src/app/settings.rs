//! Everything the explorer remembers between runs: the scene, the camera, the layout and
//! each pane's method, parameters and overlays. Plain data, saved by eframe's storage and
//! mended on loading where a value no longer fits this build.

use std::path::PathBuf;
use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::display::{Darkening, DisplayMode};
use crate::camera::MAX_SIZE_PX_PER_EM;
use crate::font::SHIPPED_FONTS;
use crate::methods::{registry, sdf_cells, winding};

/// Shown at first start: the classic type-proofing word, pangrams, figures and
/// punctuation — six lines, enough to fill the first start's magnified panes.
pub const DEFAULT_TEXT: &str = "Hamburgefonstiv\n\
    The quick brown fox jumps over the lazy dog.\n\
    Sphinx of black quartz, judge my vow!\n\
    Pack my box with five dozen liquor jugs.\n\
    0123456789 (a+b)/c = 3.5% {x|y} @&$#\n\
    Waltz, nymph, for quick jigs vex Bud.";

/// The path offered first: 1/16 px a frame along x, between any atlas's phases.
pub const DEFAULT_MOTION_PATH: &str = crate::motion::DRIFT_X;

/// Panes there are room for; the layout shows the first 1, 2 or 4.
pub const PANES: usize = 4;

/// The smallest size the explorer zooms out to, px/em; it zooms in as far as the render
/// core accepts ([`MAX_SIZE_PX_PER_EM`]).
pub const MIN_SIZE_PX_PER_EM: f64 = 0.1;
/// Tilt beyond this puts most scenes partly behind the eye.
pub const MAX_TILT_DEG: f64 = 75.0;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    pub scene: SceneSettings,
    pub camera: CameraSettings,
    pub layout: Layout,
    pub panes: [PaneSettings; PANES],
    /// Text and background colours, sRGB, unmultiplied.
    pub text_color: [u8; 3],
    pub background: [u8; 3],
    /// How panes show coverage; display only, the error figures never change with it.
    pub display: DisplayMode,
    /// Stem darkening at display time, by FreeType's or HarfBuzz's GPU rule
    /// (`display::display_color`).
    pub darkening: Darkening,
    /// Full intensity of the signed error and difference pictures, in coverage.
    pub difference_scale: f32,
    /// Draw every frame (for live GPU time) rather than only when something changed.
    pub continuous: bool,
    /// The camera's path when text is set in motion (`crate::motion`'s grammar).
    pub motion_path: String,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            scene: SceneSettings::default(),
            camera: CameraSettings::default(),
            layout: Layout::SideBySide,
            // Pane A is a method with visible artifacts at small sizes (the first start
            // opens on one), beside the reference; then the near-exact winding, and A's
            // signed difference from the reference. No row says "shows artifacts" or
            // "near-exact", so the two are picked by their rows (`INFO.name`, never a
            // string): removing either method stops the build here.
            panes: [
                PaneSettings::method(sdf_cells::INFO.name),
                PaneSettings::method(registry::REFERENCE.name),
                PaneSettings::method(winding::INFO.name),
                PaneSettings {
                    source: PaneSource::Difference {
                        first: 0,
                        second: None,
                    },
                    ..PaneSettings::method(winding::INFO.name)
                },
            ],
            text_color: [255, 255, 255],
            background: [0, 0, 0],
            display: DisplayMode::Linear,
            darkening: Darkening::Off,
            difference_scale: 0.5,
            continuous: false,
            motion_path: DEFAULT_MOTION_PATH.into(),
        }
    }
}

/// What the scene is made of. A change rebuilds the scene and re-prepares the methods;
/// nothing else does.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SceneSettings {
    pub text: String,
    pub font: FontChoice,
    /// Variable-font axis values (tag, value); axes not listed keep their default.
    pub variations: Vec<(String, f32)>,
    /// Glyph mode: one glyph, by character or `#id`, instead of the text.
    pub glyph_mode: bool,
    pub glyph: String,
    /// A named view (a hard case or a bench scene, `crate::named_views`) shown instead
    /// of the font, text and glyph above.
    pub case: Option<String>,
}

impl Default for SceneSettings {
    fn default() -> Self {
        SceneSettings {
            text: DEFAULT_TEXT.into(),
            font: FontChoice::Shipped(0),
            variations: Vec::new(),
            glyph_mode: false,
            glyph: "g".into(),
            case: None,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum FontChoice {
    /// An index into [`SHIPPED_FONTS`].
    Shipped(usize),
    /// A .ttf/.otf opened from disk.
    File(PathBuf),
    /// A font given as bytes, with no path: the web page's file picker or a file dropped
    /// on the page. The bytes are not remembered between runs (see `sanitize`).
    Opened {
        name: String,
        #[serde(skip)]
        bytes: FontBytes,
    },
}

/// A font file's bytes, shared; two are the same font when they are the same bytes in
/// memory (the settings are compared every frame: comparing megabytes would be slow).
#[derive(Clone, Default)]
pub struct FontBytes(pub Arc<[u8]>);

impl PartialEq for FontBytes {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for FontBytes {}

impl std::fmt::Debug for FontBytes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} bytes", self.0.len())
    }
}

impl FontChoice {
    pub fn label(&self) -> String {
        match self {
            FontChoice::Shipped(i) => SHIPPED_FONTS
                .get(*i)
                .map_or_else(|| "?".into(), |f| f.0.to_string()),
            FontChoice::File(path) => path.file_name().map_or_else(
                || path.display().to_string(),
                |n| n.to_string_lossy().into(),
            ),
            FontChoice::Opened { name, .. } => name.clone(),
        }
    }
}

/// The one camera every pane shares, in the terms a person steers it by; the render
/// core's [`crate::camera::Camera`] is built from it for each frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct CameraSettings {
    pub size_px_per_em: f64,
    /// The first baseline's origin, in pixels from a pane's top-left corner.
    pub origin: [f64; 2],
    /// Counter-clockwise, degrees.
    pub rotation_deg: f64,
    /// Horizontal shear: x += skew·y before the rotation.
    pub skew: f64,
    pub tilt_deg: f64,
    /// The pixel magnifier: each pixel drawn as an N×N block (1: off), N ≤ 64.
    pub magnify: u32,
    /// The pane pixel (at ×1) the magnified window is centred on.
    pub focus: [f64; 2],
    /// Added to both the scene's and the view's world position, pixels: a named view's
    /// far-from-the-origin placement.
    pub world_offset: [f64; 2],
    /// The frame of a named view the pane is a window of, if one is loaded.
    pub case_frame: Option<CaseFrame>,
}

/// A named view's frame, which the pane shows a window of: its size (the tilt turns
/// about the frame's centre, at a focal length set by its larger side) and the frame
/// pixel at the pane's (0, 0). With it, each pane pixel is the pixel `glyphscope render
/// --case` draws there.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaseFrame {
    pub width: u32,
    pub height: u32,
    pub offset: [f64; 2],
}

impl Default for CameraSettings {
    fn default() -> Self {
        CameraSettings {
            size_px_per_em: 48.0,
            origin: [16.0, 120.0],
            rotation_deg: 0.0,
            skew: 0.0,
            tilt_deg: 0.0,
            magnify: 1,
            focus: [0.0, 0.0],
            world_offset: [0.0, 0.0],
            case_frame: None,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Layout {
    Single,
    SideBySide,
    Grid,
}

impl Layout {
    pub const ALL: [Layout; 3] = [Layout::Single, Layout::SideBySide, Layout::Grid];

    pub fn panes(self) -> usize {
        match self {
            Layout::Single => 1,
            Layout::SideBySide => 2,
            Layout::Grid => 4,
        }
    }

    /// (columns, rows).
    pub fn grid(self) -> (usize, usize) {
        match self {
            Layout::Single => (1, 1),
            Layout::SideBySide => (2, 1),
            Layout::Grid => (2, 2),
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Layout::Single => "one pane",
            Layout::SideBySide => "side by side",
            Layout::Grid => "2×2",
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PaneSettings {
    pub source: PaneSource,
    /// The picture drawn instead of plain coverage.
    pub overlay: PaneOverlay,
    /// The font's outline with its on- and off-curve points, drawn on top.
    pub outline: bool,
    /// The outline with overlapping contours merged (what `overlaps=merge` draws from),
    /// drawn under the font's.
    pub merged: bool,
}

impl Default for PaneSettings {
    fn default() -> Self {
        PaneSettings::method(winding::INFO.name)
    }
}

impl PaneSettings {
    pub fn method(name: &str) -> PaneSettings {
        PaneSettings {
            source: PaneSource::Method {
                name: name.into(),
                params: Vec::new(),
            },
            overlay: PaneOverlay::None,
            outline: false,
            merged: false,
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum PaneSource {
    /// A method of the registry (the reference included) with its
    /// parameters other than `overlay`, as `--param` would give them.
    Method {
        name: String,
        params: Vec<(String, String)>,
    },
    /// Signed difference of pane `first` and pane `second` (the reference when None).
    Difference { first: usize, second: Option<usize> },
}

/// What a pane draws instead of plain coverage.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PaneOverlay {
    None,
    /// A method overlay, by its `overlay=` name.
    Method(String),
    /// Signed error against the reference (red: too much coverage, blue: too little).
    Error,
}

/// Keeps remembered settings usable with this build (fonts, pane references).
pub(super) fn sanitize(settings: &mut Settings) {
    let usable = match &settings.scene.font {
        FontChoice::Shipped(i) => *i < SHIPPED_FONTS.len(),
        FontChoice::File(_) => true,
        // Remembered from an earlier run without its bytes.
        FontChoice::Opened { bytes, .. } => !bytes.0.is_empty(),
    };
    if !usable {
        settings.scene.font = FontChoice::Shipped(0);
    }
    for (index, pane) in settings.panes.iter_mut().enumerate() {
        if let PaneSource::Difference { first, second } = &mut pane.source {
            if *first >= PANES || *first == index {
                *first = usize::from(index == 0);
            }
            if second.is_some_and(|s| s >= PANES || s == index) {
                *second = None;
            }
        }
    }
    let c = &mut settings.camera;
    if !(c.size_px_per_em.is_finite() && c.size_px_per_em > 0.0) {
        *c = Default::default();
    }
    c.size_px_per_em = c
        .size_px_per_em
        .clamp(MIN_SIZE_PX_PER_EM, MAX_SIZE_PX_PER_EM);
    c.tilt_deg = c.tilt_deg.clamp(-MAX_TILT_DEG, MAX_TILT_DEG);
    c.magnify = c.magnify.clamp(1, crate::magnify::MAX_FACTOR);
    if !c.focus.iter().all(|v| v.is_finite()) {
        c.focus = [0.0, 0.0];
    }
    if !c.world_offset.iter().all(|v| v.is_finite()) {
        c.world_offset = [0.0, 0.0];
    }
    let side = 1..=crate::camera::MAX_IMAGE_SIDE;
    if c.case_frame.is_some_and(|f| {
        let usable = side.contains(&f.width)
            && side.contains(&f.height)
            && f.offset.iter().all(|v| v.is_finite());
        !usable
    }) {
        c.case_frame = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remembered_settings_survive_a_round_trip_and_bad_values_are_mended() {
        let mut s = Settings::default();
        s.panes[2].source = PaneSource::Difference {
            first: 9,
            second: Some(2),
        };
        s.scene.font = FontChoice::Shipped(42);
        let mut back: Settings = serde_json::from_str(&serde_json::to_string(&s).unwrap()).unwrap();
        assert_eq!(back, s);
        sanitize(&mut back);
        assert_eq!(back.scene.font, FontChoice::Shipped(0));
        assert_eq!(
            back.panes[2].source,
            PaneSource::Difference {
                first: 0,
                second: None
            }
        );
    }

    /// A font opened from bytes is remembered by name only; the next run, without its
    /// bytes, opens the default font rather than an empty one.
    #[test]
    fn a_font_opened_from_bytes_is_not_remembered_without_them() {
        let bytes = FontBytes(Arc::from(crate::font::SHIPPED_FONTS[0].2));
        let mut s = Settings::default();
        s.scene.font = FontChoice::Opened {
            name: "mine.ttf".into(),
            bytes: bytes.clone(),
        };
        let mut kept = s.clone();
        sanitize(&mut kept);
        assert_eq!(kept.scene.font, s.scene.font, "bytes in hand: kept");
        let json = serde_json::to_string(&s).unwrap();
        assert!(
            json.len() < 4096,
            "the bytes are not written: {} bytes",
            json.len()
        );
        let mut back: Settings = serde_json::from_str(&json).unwrap();
        sanitize(&mut back);
        assert_eq!(back.scene.font, FontChoice::Shipped(0));
        // The same bytes copied are another font: compared by identity, not content.
        let copy = FontBytes(Arc::from(&*bytes.0));
        assert_ne!(copy, bytes);
    }
}
