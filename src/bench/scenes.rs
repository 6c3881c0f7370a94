//! The standard scenes: each one a `render` command line, so that any case of the
//! bench can be rerun alone with `glyphscope render` and gives the same figures.

use std::path::PathBuf;

use glam::{DMat2, DVec2};

use crate::Error;
use crate::camera::Camera;
use crate::geometry::Segment;
use crate::view_args::ViewArgs;

/// The standard page: 2 929 glyphs of DejaVu Sans.
pub const PAGE_TEXT: &str = include_str!("../../data/page.txt");
/// The page's size, px/em.
pub const PAGE_PX_PER_EM: f64 = 16.0;

/// The view after caching: the camera zooms in this much about the image centre…
pub const MOVED_ZOOM: f64 = 2.5;
/// …and turns the text by this much, degrees.
pub const MOVED_ROTATION_DEG: f64 = 30.0;

/// A standard scene: what it shows, and the view that draws it.
#[derive(Clone, Debug)]
pub struct BenchScene {
    pub name: &'static str,
    pub about: &'static str,
    pub args: ViewArgs,
}

/// Every standard scene's name, in the order they run.
pub const SCENE_NAMES: &[&str] = &[
    "page",
    "tiny",
    "headlines",
    "edge",
    "rotated",
    "latin-modern",
    "inter-900",
    "bengali",
    "arabic",
];

/// The scene called `name`.
pub fn scene(name: &str) -> Result<BenchScene, Error> {
    let unknown = || {
        Error::Input(format!(
            "unknown scene '{name}'; choose from: {}",
            SCENE_NAMES.join(", ")
        ))
    };
    // The name the scene keeps, from the list.
    let name = *SCENE_NAMES
        .iter()
        .find(|n| **n == name)
        .ok_or_else(unknown)?;
    let page = |size| text_args(None, PAGE_TEXT, size);
    let (about, args) = match name {
        "page" => (
            "the standard page: 2 929 glyphs of DejaVu Sans at 16 px/em, 1920×1080",
            ViewArgs {
                width: Some(1920),
                height: Some(1080),
                origin: Some(DVec2::new(24.0, 40.0)),
                ..page(PAGE_PX_PER_EM)
            },
        ),
        "tiny" => ("the same page at 7 px/em, framed to its ink", page(7.0)),
        "headlines" => (
            "two headlines at 120 px/em (DejaVu Sans)",
            text_args(None, "Hamburgefonstiv\nGlyph & Scope 2026", 120.0),
        ),
        "edge" => (
            "one glyph ('O') at 20 000 px/em, a 512×512 view centred on the middle of its \
             first curve",
            edge_args()?,
        ),
        "rotated" => (
            "the page's first six lines at 20 px/em, rotated 30° and tilted 35° in \
             perspective",
            ViewArgs {
                matrix: Some(rotation_rows(30.0)),
                tilt: 35.0,
                ..text_args(None, &first_lines(PAGE_TEXT, 6), 20.0)
            },
        ),
        "latin-modern" => (
            "a paragraph (the page's first five lines) in Latin Modern Roman (CFF cubics) \
             at 18 px/em",
            text_args(
                Some("lmroman10-regular.otf"),
                &first_lines(PAGE_TEXT, 5),
                18.0,
            ),
        ),
        "inter-900" => (
            "Inter variable at weight 900, whose glyphs overlap their own contours, 48 px/em",
            ViewArgs {
                variation: vec![("wght".into(), 900.0)],
                ..text_args(
                    Some("Inter-roman.var.ttf"),
                    "Hamburgefonstiv\nQ&@$#4GRe ftkAP",
                    48.0,
                )
            },
        ),
        "bengali" => (
            "a Bengali line with conjuncts (Lohit Bengali) at 32 px/em",
            text_args(
                Some("Lohit-Bengali.ttf"),
                "ক্ষমা বাংলা ভাষা সাহিত্য সংস্কৃতি ও বিজ্ঞান",
                32.0,
            ),
        ),
        "arabic" => (
            "an Arabic paragraph (DejaVu Sans) at 24 px/em: letters joined, their ink \
             overlapping the next's",
            text_args(None, ARABIC_PARAGRAPH, 24.0),
        ),
        _ => return Err(unknown()),
    };
    Ok(BenchScene { name, about, args })
}

/// The `arabic` scene's text: the `arabic-line` hard case's line, then two more.
const ARABIC_PARAGRAPH: &str = "بسم الله الرحمن الرحيم — السلام عليكم ورحمة الله\n\
    العلم نور والجهل ظلام، ومن جد وجد ومن زرع حصد\n\
    تكتب العربية من اليمين إلى اليسار وتتصل حروفها في الكلمة الواحدة";

/// The scene's view after caching: zoomed by [`MOVED_ZOOM`] about the image centre and
/// turned by [`MOVED_ROTATION_DEG`], same image size and tilt. `camera` is the scene's
/// own, as [`ViewArgs::build`] framed it.
pub fn moved_args(args: &ViewArgs, camera: &Camera) -> ViewArgs {
    let rotation = rotation(MOVED_ROTATION_DEG);
    // Image space is font space flipped in y: the same turn seen there is F·R·F.
    let flip = DMat2::from_diagonal(DVec2::new(1.0, -1.0));
    let centre = DVec2::new(f64::from(camera.width), f64::from(camera.height)) / 2.0;
    let origin = centre + MOVED_ZOOM * (flip * rotation * flip) * (camera.origin - centre);
    let m = rotation * camera.matrix;
    ViewArgs {
        size: Some(camera.size_px_per_em * MOVED_ZOOM),
        width: Some(camera.width),
        height: Some(camera.height),
        origin: Some(origin),
        matrix: Some([m.x_axis.x, m.y_axis.x, m.x_axis.y, m.y_axis.y]),
        ..args.clone()
    }
}

/// A shipped font's path, relative to the repository root the bench runs in: the
/// command lines it reports then work on any checkout.
fn font_path(file: &str) -> PathBuf {
    PathBuf::from("fonts").join(file)
}

fn text_args(font: Option<&str>, text: &str, size: f64) -> ViewArgs {
    ViewArgs {
        font: font.map(font_path),
        ..ViewArgs::text(text, size)
    }
}

fn first_lines(text: &str, count: usize) -> String {
    text.lines().take(count).collect::<Vec<_>>().join("\n")
}

fn rotation(degrees: f64) -> DMat2 {
    DMat2::from_angle(degrees.to_radians())
}

/// [a b c d] of a rotation, in reading order as `--matrix` takes it.
fn rotation_rows(degrees: f64) -> [f64; 4] {
    let m = rotation(degrees);
    [m.x_axis.x, m.y_axis.x, m.x_axis.y, m.y_axis.y]
}

/// 'O' at 20 000 px/em seen through a 512×512 window whose centre is the point halfway
/// along the glyph's first curve: the edge, as the camera sees it zoomed right in.
fn edge_args() -> Result<ViewArgs, Error> {
    const SIZE: f64 = 20_000.0;
    const SIDE: u32 = 512;
    let font = crate::font::default_font();
    let outline = font.outline(font.glyph_for_char('O')?);
    let on_edge = outline
        .segments()
        .find_map(|s| match *s {
            Segment::Quad(p0, p1, p2) => Some((p0 + 2.0 * p1 + p2) / 4.0),
            Segment::Cubic(p0, p1, p2, p3) => Some((p0 + 3.0 * (p1 + p2) + p3) / 8.0),
            Segment::Line(..) => None,
        })
        .ok_or_else(|| Error::Font("'O' has no curve".into()))?;
    let s = SIZE / font.units_per_em();
    let centre = f64::from(SIDE) / 2.0;
    Ok(ViewArgs {
        width: Some(SIDE),
        height: Some(SIDE),
        origin: Some(DVec2::new(centre - on_edge.x * s, centre + on_edge.y * s)),
        ..text_args(None, "O", SIZE)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::project;

    #[test]
    fn every_scene_builds() {
        for name in SCENE_NAMES {
            let scene = scene(name).unwrap();
            let (s, camera) = scene.args.build().unwrap();
            assert!(!s.instances.is_empty(), "{name}");
            moved_args(&scene.args, &camera).build().unwrap();
        }
        assert!(scene("nope").is_err());
    }

    /// The moved view is the scene's own image zoomed and turned about its centre.
    #[test]
    fn moved_view_zooms_and_turns_about_the_centre() {
        let page = scene("page").unwrap();
        let (s, camera) = page.args.build().unwrap();
        let (_, moved) = moved_args(&page.args, &camera).build().unwrap();
        let pen = s.instances[100].position;
        let centre = DVec2::new(960.0, 540.0);
        let before = project(&camera.glyph_to_image(s.units_per_em, pen), DVec2::ZERO) - centre;
        let after = project(&moved.glyph_to_image(s.units_per_em, pen), DVec2::ZERO) - centre;
        assert!((after.length() - MOVED_ZOOM * before.length()).abs() < 1e-9);
        // Counter-clockwise on screen (y down): the angle decreases by 30°.
        let turn = after.y.atan2(after.x) - before.y.atan2(before.x);
        let turn = (turn.to_degrees() + 540.0) % 360.0 - 180.0;
        assert!((turn + MOVED_ROTATION_DEG).abs() < 1e-9, "{turn}");
    }
}
