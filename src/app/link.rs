//! A link is a view: the scene, the camera, the layout, each pane's method, parameters
//! and overlays, the magnifier and the motion, written as a URL fragment
//! (`#case=inter-overlaps&a=sdf-cells&b=winding&magnify=32`) that the explorer opens
//! exactly — `glyphscope --view '#…'` on the desktop. Every camera number is written in
//! full (Rust's shortest round-trip form), so the view opened is the view copied, pixel
//! for pixel.
//!
//! The grammar, key by key (values percent-encoded; any key may be left out, and then
//! keeps the default view's value):
//!
//! | key | value |
//! |---|---|
//! | `case` | a named view: a hard case or a bench scene (`glyphscope render --case`) |
//! | `text` | the text (newlines as `%0A`) |
//! | `font` | a shipped font by its number, 0 the first; anything else is a font file's path, which the desktop explorer opens (the web page cannot: it says so) |
//! | `var` | variable-font axes, `TAG:VALUE,TAG:VALUE` |
//! | `glyph` | one glyph (a character, or `#` and an id) instead of the text |
//! | `size` | px/em |
//! | `origin` | the first baseline's origin in pane pixels, `X,Y` |
//! | `rotate`, `skew`, `tilt` | degrees, shear, degrees |
//! | `offset` | the world offset, `DX,DY` |
//! | `frame` | the named view's frame the pane is a window of, `W,H,X,Y` |
//! | `layout` | `1`, `2` or `4` panes |
//! | `a` … `d` | a pane's method, `NAME` or `NAME:KEY=VALUE:…`; or `diff:FIRST[:SECOND]`, panes by letter |
//! | `a.overlay` … | `error` or a method overlay's name |
//! | `a.outline` … | `1`: the outline drawn over the pane |
//! | `a.merged` … | `1`: the merged outline (overlaps removed) drawn under it |
//! | `magnify`, `focus` | the magnifier's N, and its centre in pane pixels `X,Y` |
//! | `motion`, `at` | a motion path (`glyphscope motion --path`) and the frame shown |

use super::panes::pane_letter;
use super::settings::{CaseFrame, FontChoice, Layout, PANES, PaneOverlay, PaneSource, Settings};
use crate::font::SHIPPED_FONTS;
use crate::link_text::{decode, encode};
use crate::methods::params::assignments;
use crate::methods::registry;
use crate::motion::MotionPath;

/// A view opened from a link: its settings, the frame of its motion path shown,
/// whether the link placed the camera (a link that names a case and no camera opens the
/// case as the Cases menu does: framed, magnified on its worst pixel), and whether it
/// named the magnifier's focus (the pixel the explorer then marks).
#[derive(Clone, Debug, PartialEq)]
pub struct LinkedView {
    pub settings: Settings,
    pub frame: i64,
    pub camera_given: bool,
    pub focus_given: bool,
}

/// The farthest frame a link may show, either way: steps from it cannot overflow.
const MAX_FRAME: i64 = 1_000_000_000;

/// The keys that place the camera.
const CAMERA_KEYS: &[&str] = &[
    "size", "origin", "rotate", "skew", "tilt", "offset", "frame", "focus",
];

/// The fragment (without its `#`) that opens `settings` at motion frame `frame`, or why
/// the scene cannot travel in a link (a font given as bytes, with no path).
pub fn fragment(settings: &Settings, frame: i64) -> Result<String, String> {
    let mut parts: Vec<(String, String)> = Vec::new();
    let mut put = |key: &str, value: String| parts.push((key.into(), value));
    let scene = &settings.scene;
    match &scene.case {
        Some(case) => put("case", case.clone()),
        None => {
            match &scene.font {
                FontChoice::Shipped(index) => put("font", index.to_string()),
                FontChoice::File(path) => put("font", font_path(path)?),
                FontChoice::Opened { name, .. } => {
                    return Err(format!(
                        "the font {name} was opened from this computer: a link carries a \
                         shipped font or a font file's path, never the font's bytes"
                    ));
                }
            }
            put("text", scene.text.clone());
            if !scene.variations.is_empty() {
                let axes: Vec<String> = scene
                    .variations
                    .iter()
                    .map(|(tag, v)| format!("{tag}:{v}"))
                    .collect();
                put("var", axes.join(","));
            }
            if scene.glyph_mode {
                put("glyph", scene.glyph.clone());
            }
        }
    }
    let c = &settings.camera;
    put("size", c.size_px_per_em.to_string());
    put("origin", pair(c.origin));
    put("rotate", c.rotation_deg.to_string());
    put("skew", c.skew.to_string());
    put("tilt", c.tilt_deg.to_string());
    put("offset", pair(c.world_offset));
    if let Some(f) = c.case_frame {
        put(
            "frame",
            format!("{},{},{},{}", f.width, f.height, f.offset[0], f.offset[1]),
        );
    }
    put("layout", settings.layout.panes().to_string());
    for (index, pane) in settings
        .panes
        .iter()
        .enumerate()
        .take(settings.layout.panes())
    {
        let letter = letter(index);
        put(&letter, pane_source(&pane.source));
        match &pane.overlay {
            PaneOverlay::None => {}
            PaneOverlay::Error => put(&format!("{letter}.overlay"), "error".into()),
            PaneOverlay::Method(name) => put(&format!("{letter}.overlay"), name.clone()),
        }
        if pane.outline {
            put(&format!("{letter}.outline"), "1".into());
        }
        if pane.merged {
            put(&format!("{letter}.merged"), "1".into());
        }
    }
    put("magnify", c.magnify.to_string());
    put("focus", pair(c.focus));
    put("motion", settings.motion_path.clone());
    if MotionPath::parse(&settings.motion_path).is_ok_and(|p| !p.is_still()) {
        put("at", frame.to_string());
    }
    Ok(parts
        .iter()
        .map(|(k, v)| format!("{k}={}", encode(v)))
        .collect::<Vec<_>>()
        .join("&"))
}

/// The view a fragment (with or without its `#`) describes, over the default view; or
/// one line naming what is wrong with it.
pub fn open(fragment: &str) -> Result<LinkedView, String> {
    let mut view = LinkedView {
        settings: Settings::default(),
        frame: 0,
        camera_given: false,
        focus_given: false,
    };
    let text = fragment.trim().trim_start_matches('#');
    if text.is_empty() {
        return Ok(view);
    }
    let mut layout_given = false;
    for part in text.split('&').filter(|p| !p.is_empty()) {
        let (key, raw) = part
            .split_once('=')
            .ok_or_else(|| format!("link: '{part}' is not KEY=VALUE"))?;
        let value = decode(raw).map_err(|e| format!("link: {key}: {e}"))?;
        view.camera_given |= CAMERA_KEYS.contains(&key);
        view.focus_given |= key == "focus";
        apply(&mut view, key, &value, text, &mut layout_given)
            .map_err(|e| format!("link: {key}={}: {e}", value.escape_debug()))?;
    }
    Ok(view)
}

/// Sets what `key`=`value` of the fragment `link` (without its `#`) says.
fn apply(
    view: &mut LinkedView,
    key: &str,
    value: &str,
    link: &str,
    layout_given: &mut bool,
) -> Result<(), String> {
    let s = &mut view.settings;
    let c = &mut s.camera;
    match key {
        "case" => {
            if !crate::named_views::all().iter().any(|v| v.name == value) {
                return Err("no named view has this name".into());
            }
            s.scene.case = Some(value.into());
        }
        "text" => s.scene.text = value.into(),
        "font" => s.scene.font = font(value, link)?,
        "var" => {
            s.scene.variations = value
                .split(',')
                .map(|axis| {
                    let (tag, v) = axis.split_once(':').ok_or("not TAG:VALUE")?;
                    let v: f32 = v.parse().map_err(|_| "not a number")?;
                    Ok((tag.to_string(), v))
                })
                .collect::<Result<_, &str>>()?;
        }
        "glyph" => {
            s.scene.glyph_mode = true;
            s.scene.glyph = value.into();
        }
        "size" => c.size_px_per_em = positive(value)?,
        "origin" => c.origin = numbers(value)?,
        "rotate" => c.rotation_deg = number(value)?,
        "skew" => c.skew = number(value)?,
        "tilt" => {
            let tilt = number(value)?;
            if tilt.abs() >= 90.0 {
                return Err("a tilt must lie strictly between -90 and 90".into());
            }
            c.tilt_deg = tilt;
        }
        "offset" => c.world_offset = numbers(value)?,
        "frame" => {
            let v: Vec<&str> = value.split(',').collect();
            let [w, h, x, y] = v[..] else {
                return Err("not W,H,X,Y".into());
            };
            let side = |t: &str| -> Result<u32, String> {
                t.parse::<u32>()
                    .ok()
                    .filter(|n| (1..=crate::camera::MAX_IMAGE_SIDE).contains(n))
                    .ok_or_else(|| format!("'{t}' is not a frame side"))
            };
            c.case_frame = Some(CaseFrame {
                width: side(w)?,
                height: side(h)?,
                offset: [number(x)?, number(y)?],
            });
        }
        "layout" => {
            s.layout = match value {
                "1" => Layout::Single,
                "2" => Layout::SideBySide,
                "4" => Layout::Grid,
                _ => return Err("not 1, 2 or 4".into()),
            };
            *layout_given = true;
        }
        "magnify" => {
            c.magnify = value
                .parse::<u32>()
                .ok()
                .filter(|n| (1..=crate::magnify::MAX_FACTOR).contains(n))
                .ok_or_else(|| format!("not a factor from 1 to {}", crate::magnify::MAX_FACTOR))?;
        }
        "focus" => c.focus = numbers(value)?,
        "motion" => {
            MotionPath::parse(value).map_err(|e| e.to_string())?;
            s.motion_path = value.into();
        }
        "at" => {
            view.frame = value
                .parse::<i64>()
                .ok()
                .filter(|n| n.abs() <= MAX_FRAME)
                .ok_or_else(|| format!("not a frame number from -{MAX_FRAME} to {MAX_FRAME}"))?;
        }
        _ => return pane_key(s, key, value, *layout_given),
    }
    Ok(())
}

/// A `font` value: a shipped font's number, else a font file's path (on the desktop;
/// the web page has no files to open). `link` is the whole fragment, for the web page's
/// message.
fn font(value: &str, link: &str) -> Result<FontChoice, String> {
    if let Ok(index) = value.parse::<usize>() {
        if index >= SHIPPED_FONTS.len() {
            return Err(format!(
                "there are {} shipped fonts, from 0",
                SHIPPED_FONTS.len()
            ));
        }
        return Ok(FontChoice::Shipped(index));
    }
    if value.is_empty() {
        return Err("neither a shipped font's number nor a font file's path".into());
    }
    if cfg!(target_arch = "wasm32") {
        return Err(local_path_on_the_web(value, link));
    }
    Ok(FontChoice::File(value.into()))
}

/// What the web page says of a link whose font is a path on some computer.
fn local_path_on_the_web(path: &str, link: &str) -> String {
    format!(
        "the web page cannot open a font from a local path ('{path}'); open this link in \
         the desktop explorer: glyphscope --view '#{link}'"
    )
}

/// A font file's path as a `font` value: as it is, but for a path of digits alone, which
/// would read as a shipped font's number and is written `./N`; or why it cannot be
/// written (not UTF-8, empty).
fn font_path(path: &std::path::Path) -> Result<String, String> {
    let text = path.to_str().ok_or_else(|| {
        format!(
            "the font's path {} is not UTF-8: a link cannot carry it",
            path.display()
        )
    })?;
    if text.is_empty() {
        return Err("the font has an empty path: a link cannot carry it".into());
    }
    Ok(if text.parse::<usize>().is_ok() {
        format!("./{text}")
    } else {
        text.to_string()
    })
}

/// `a` … `d`, `a.overlay`, `a.outline`, `a.merged`.
fn pane_key(s: &mut Settings, key: &str, value: &str, layout_given: bool) -> Result<(), String> {
    let (letter, field) = key.split_once('.').unwrap_or((key, ""));
    let index = pane_index(letter).ok_or_else(|| "unknown key".to_string())?;
    // A pane named beyond the default layout shows it, unless the link sets one.
    if !layout_given && index >= s.layout.panes() {
        s.layout = if index >= 2 {
            Layout::Grid
        } else {
            Layout::SideBySide
        };
    }
    let pane = &mut s.panes[index];
    match field {
        "" => pane.source = parse_source(value, index)?,
        "overlay" => {
            pane.overlay = match value {
                "error" => PaneOverlay::Error,
                "none" => PaneOverlay::None,
                name => PaneOverlay::Method(name.into()),
            }
        }
        "outline" => pane.outline = flag(value)?,
        "merged" => pane.merged = flag(value)?,
        _ => return Err("unknown key".into()),
    }
    Ok(())
}

fn parse_source(value: &str, index: usize) -> Result<PaneSource, String> {
    // A user's file: its path may hold colons, and ends at `.wgsl` (`MethodSpec`).
    if value.starts_with(crate::methods::user::PREFIX) {
        let spec = crate::motion::run::MethodSpec::parse(value).map_err(|e| e.to_string())?;
        return Ok(PaneSource::Method {
            name: spec.name,
            params: spec.params,
        });
    }
    let mut parts = value.split(':');
    let name = parts.next().unwrap_or_default();
    if name == "diff" {
        let pane = |t: &str| {
            pane_index(t)
                .filter(|&p| p != index)
                .ok_or_else(|| format!("'{t}' is not another pane"))
        };
        let first = pane(parts.next().ok_or("diff needs the pane it shows")?)?;
        let second = parts.next().map(pane).transpose()?;
        return Ok(PaneSource::Difference { first, second });
    }
    let info = registry::find(name).map_err(|e| e.to_string())?;
    let params = parts
        .map(crate::view_args::parse_key_value)
        .collect::<Result<Vec<_>, _>>()?;
    Ok(PaneSource::Method {
        name: info.name.into(),
        params,
    })
}

fn pane_source(source: &PaneSource) -> String {
    match source {
        PaneSource::Method { name, params } => std::iter::once(name.clone())
            .chain(assignments(params))
            .collect::<Vec<_>>()
            .join(":"),
        PaneSource::Difference { first, second } => {
            let mut text = format!("diff:{}", letter(*first));
            if let Some(second) = second {
                text.push(':');
                text.push_str(&letter(*second));
            }
            text
        }
    }
}

/// A `1` or `0` flag.
fn flag(value: &str) -> Result<bool, String> {
    match value {
        "1" => Ok(true),
        "0" => Ok(false),
        _ => Err("not 0 or 1".into()),
    }
}

/// A pane's key: its letter (`pane_letter`) in lower case.
fn letter(index: usize) -> String {
    pane_letter(index).to_ascii_lowercase().to_string()
}

fn pane_index(letter: &str) -> Option<usize> {
    match letter.as_bytes() {
        [c @ b'a'..=b'z'] => Some(usize::from(c - b'a')).filter(|&i| i < PANES),
        _ => None,
    }
}

fn pair(v: [f64; 2]) -> String {
    format!("{},{}", v[0], v[1])
}

fn number(text: &str) -> Result<f64, String> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("'{text}' is not a finite number"))
}

fn positive(text: &str) -> Result<f64, String> {
    let v = number(text)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("'{text}' is not positive"))
    }
}

fn numbers(text: &str) -> Result<[f64; 2], String> {
    let (a, b) = text
        .split_once(',')
        .ok_or_else(|| format!("'{text}' is not X,Y"))?;
    Ok([number(a)?, number(b)?])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::settings::{CameraSettings, PaneSettings};

    fn varied() -> Settings {
        let mut s = Settings {
            layout: Layout::Grid,
            motion_path: "drift:0.1,-0.2+rotate:0.5@3,4".into(),
            ..Settings::default()
        };
        s.scene.text = "Wave & co = 50% #1\nline two".into();
        s.scene.font = FontChoice::Shipped(1);
        s.scene.variations = vec![("wght".into(), 700.0)];
        s.camera = CameraSettings {
            size_px_per_em: 12.345678901234567,
            origin: [0.1 + 0.2, -7.5],
            rotation_deg: 33.3,
            skew: -0.25,
            tilt_deg: 35.0,
            magnify: 16,
            focus: [40.5, 9.25],
            world_offset: [1e6, -3.0],
            case_frame: Some(CaseFrame {
                width: 640,
                height: 480,
                offset: [3.0, 7.0],
            }),
        };
        s.panes[0] = PaneSettings::method("sdf-cells");
        if let PaneSource::Method { params, .. } = &mut s.panes[0].source {
            params.push(("mode".into(), "exact".into()));
        }
        s.panes[0].overlay = PaneOverlay::Method("cells".into());
        s.panes[1].overlay = PaneOverlay::Error;
        s.panes[1].outline = true;
        s.panes[1].merged = true;
        s.panes[3].source = PaneSource::Difference {
            first: 0,
            second: Some(1),
        };
        s
    }

    /// Every field the link carries comes back exactly, numbers to the last bit, text
    /// with the characters the grammar uses.
    #[test]
    fn a_view_survives_its_link() {
        let s = varied();
        let link = fragment(&s, 17).unwrap();
        assert!(
            !link.contains(' ') && !link.contains('\n') && !link.contains('#'),
            "{link}"
        );
        let back = open(&format!("#{link}")).unwrap();
        assert_eq!(back.frame, 17);
        assert_eq!(back.settings.scene, s.scene);
        assert_eq!(back.settings.camera, s.camera);
        assert_eq!(back.settings.layout, s.layout);
        assert_eq!(back.settings.panes, s.panes);
        assert_eq!(back.settings.motion_path, s.motion_path);
        let mut case = Settings::default();
        case.scene.case = Some("inter-overlaps".into());
        let back = open(&fragment(&case, 0).unwrap()).unwrap();
        assert_eq!(back.settings.scene.case.as_deref(), Some("inter-overlaps"));
    }

    /// A pane drawing a user's file (its path with a folder, and a colon where a
    /// Windows path has one) travels in a link, as the survey writes them.
    #[test]
    fn a_users_file_survives_its_link() {
        let mut s = Settings {
            layout: Layout::SideBySide,
            ..Settings::default()
        };
        s.panes[1] = PaneSettings::method("wgsl:examples/methods/supersampled.wgsl");
        let back = open(&format!("#{}", fragment(&s, 0).unwrap())).unwrap();
        assert_eq!(back.settings.panes[1], s.panes[1]);
        let e = open("#b=wgsl:no/such/file.wgsl").err().unwrap();
        assert!(e.contains("no/such/file.wgsl"), "{e}");
    }

    /// The issue's own example, written by hand: only what it names changes.
    #[test]
    fn a_short_link_changes_only_what_it_names() {
        let view = open("#case=inter-overlaps&a=sdf-cells&b=winding&magnify=32").unwrap();
        let s = view.settings.clone();
        let default = Settings::default();
        assert_eq!(s.scene.case.as_deref(), Some("inter-overlaps"));
        assert_eq!(s.panes[0], PaneSettings::method("sdf-cells"));
        assert_eq!(s.panes[1], PaneSettings::method("winding"));
        assert_eq!(s.camera.magnify, 32);
        assert_eq!(s.camera.size_px_per_em, default.camera.size_px_per_em);
        assert_eq!(s.layout, Layout::SideBySide);
        assert!(
            !view.camera_given,
            "the case is placed as the Cases menu places it"
        );
        assert!(open("#case=inter-overlaps&size=12").unwrap().camera_given);
        assert_eq!(open("#c=atlas").unwrap().settings.layout, Layout::Grid);
        assert_eq!(open("").unwrap().settings, default);
    }

    /// A malformed link is one line naming the key and what is wrong.
    #[test]
    fn a_malformed_link_says_what_is_wrong() {
        for (link, expected) in [
            ("#case=nonesuch", "case=nonesuch"),
            ("#size=-3", "size=-3"),
            ("#size=abc", "size=abc"),
            ("#tilt=95", "tilt=95"),
            ("#magnify=65", "magnify=65"),
            ("#a=nonesuch", "a=nonesuch"),
            ("#a=diff:a", "a=diff:a"),
            ("#e=winding", "e=winding"),
            ("#zoom=2", "zoom=2"),
            ("#text=%zz", "text"),
            ("#layout", "'layout' is not KEY=VALUE"),
            ("#motion=spin:1", "motion=spin:1"),
            ("#frame=1,2,3", "frame=1,2,3"),
            ("#font=99", "font=99"),
            ("#a.outline=yes", "a.outline=yes"),
            ("#text=%€", "'%€' is not"),
            ("#case=a%0Ab", "case=a\\nb"),
            ("#at=9223372036854775807", "at=9223372036854775807"),
        ] {
            let e = open(link).unwrap_err();
            assert!(e.starts_with("link: ") && !e.contains('\n'), "{link}: {e}");
            assert!(e.contains(expected), "{link}: {e} lacks {expected:?}");
        }
    }

    /// A font opened from disk travels as its path, characters the grammar uses and all,
    /// with a glyph by id; a path of digits alone is written so that it is not read as a
    /// shipped font's number.
    #[test]
    fn a_font_from_disk_travels_as_its_path() {
        let mut s = Settings::default();
        s.scene.font = FontChoice::File("/tmp/my fonts/A&B=50% #1, Ä.ttf".into());
        s.scene.glyph_mode = true;
        s.scene.glyph = "#36".into();
        let link = fragment(&s, 0).unwrap();
        assert!(
            link.starts_with("font=%2Ftmp%2Fmy%20fonts%2FA%26B%3D50%25%20%231,%20%C3%84.ttf&"),
            "{link}"
        );
        let back = open(&link).unwrap();
        assert_eq!(back.settings.scene, s.scene);
        assert_eq!(back.settings.camera, s.camera);

        s.scene.font = FontChoice::File("7".into());
        let link = fragment(&s, 0).unwrap();
        assert!(link.starts_with("font=.%2F7&"), "{link}");
        assert_eq!(
            open(&link).unwrap().settings.scene.font,
            FontChoice::File("./7".into())
        );
        s.scene.font = FontChoice::File("".into());
        assert!(fragment(&s, 0).unwrap_err().contains("empty path"));
    }

    /// A number is a shipped font, whichever way it is written; one past the last is an
    /// error, not a path.
    #[test]
    fn a_number_stays_a_shipped_font() {
        for (link, index) in [("#font=0", 0), ("#font=2", 2), ("#font=%32", 2)] {
            assert_eq!(
                open(link).unwrap().settings.scene.font,
                FontChoice::Shipped(index),
                "{link}"
            );
        }
        let e = open(&format!("#font={}", SHIPPED_FONTS.len())).unwrap_err();
        assert!(e.contains("shipped fonts"), "{e}");
        assert!(open("#font=").unwrap_err().contains("font="));
    }

    /// A path to no file is a well-formed link: it opens, and the scene then says what
    /// the explorer shows for a font file it cannot read, naming the file.
    #[test]
    fn a_missing_font_file_opens_and_the_scene_names_it() {
        let view = open("#font=%2Fno%2Fsuch%2Fdir%2FMissing.ttf&glyph=%2336").unwrap();
        let path = "/no/such/dir/Missing.ttf";
        assert_eq!(view.settings.scene.font, FontChoice::File(path.into()));
        let mut scene = super::super::scene_state::SceneState::default();
        scene.sync(&view.settings.scene);
        assert!(scene.scene().is_none());
        let problem = scene.problem().expect("the font cannot be read");
        assert!(
            problem.contains(&format!("cannot read font file '{path}'")),
            "{problem}"
        );
    }

    /// The web page cannot open a path: it says so, and gives the command that opens the
    /// link on the desktop. (Written here as the page writes it; the page reaches it
    /// through `font` under wasm32.)
    #[test]
    fn the_web_page_says_a_local_path_opens_on_the_desktop() {
        let link = "font=%2Ftmp%2FA.ttf&glyph=%2336";
        let message = local_path_on_the_web("/tmp/A.ttf", link);
        assert_eq!(
            message,
            "the web page cannot open a font from a local path ('/tmp/A.ttf'); open this \
             link in the desktop explorer: glyphscope --view '#font=%2Ftmp%2FA.ttf&glyph=%2336'"
        );
        assert!(!message.contains('\n'));
    }

    /// A font given as bytes (the web page's file picker) has no path to write: the
    /// link refuses it and says why.
    #[test]
    fn a_font_given_as_bytes_cannot_travel() {
        let mut s = Settings::default();
        s.scene.font = FontChoice::Opened {
            name: "Mine.ttf".into(),
            bytes: crate::app::settings::FontBytes(std::sync::Arc::from(vec![0u8; 4])),
        };
        let why = fragment(&s, 0).unwrap_err();
        assert!(
            why.contains("Mine.ttf") && why.contains("opened from this computer"),
            "{why}"
        );
    }
}
