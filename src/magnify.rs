//! The pixel microscope: a window of a frame's pixels drawn as N×N blocks, so that the
//! few pixels an error figure talks about can be seen — with a grid from ×8, each
//! pixel's coverage (and its error against the reference) written in its block from
//! ×32, and the exact outline drawn over the blocks. `render --magnify` draws it here;
//! the explorer's panes show the same blocks on the GPU.

use std::str::FromStr;

use glam::DVec2;
use image::{Rgb, RgbImage};
use serde::Serialize;

use crate::Error;
use crate::coverage::CoverageImage;
use crate::geometry::{Rect, distance_to_segment};

use crate::metrics::ErrorStats;
use crate::outline_overlay::OutlineDrawing;

/// The largest magnification: a 64×64 block holds two lines of four characters.
pub const MAX_FACTOR: u32 = 64;
/// The pixel grid is drawn from this magnification.
pub const GRID_FROM: u32 = 8;
/// Each pixel's values are written in its block from this magnification.
pub const VALUES_FROM: u32 = 32;

/// Where the magnified window is centred.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Focus {
    /// The pixel with the largest error against the reference (the one
    /// [`ErrorStats::worst_pixel`] names).
    Worst,
    /// A pixel (x, y).
    Pixel(u32, u32),
}

impl FromStr for Focus {
    type Err = String;

    fn from_str(s: &str) -> Result<Focus, String> {
        if s == "worst" {
            return Ok(Focus::Worst);
        }
        let parsed = s
            .split_once(',')
            .and_then(|(x, y)| Some((x.trim().parse().ok()?, y.trim().parse().ok()?)));
        parsed
            .map(|(x, y)| Focus::Pixel(x, y))
            .ok_or_else(|| format!("'{s}' is not 'worst' or a pixel X,Y (whole numbers ≥ 0)"))
    }
}

impl Focus {
    /// The pixel this focus names in a `width`×`height` frame; `error` must be given
    /// for [`Focus::Worst`].
    pub fn pixel(
        self,
        width: u32,
        height: u32,
        error: Option<&ErrorStats>,
    ) -> Result<(u32, u32), Error> {
        match self {
            Focus::Worst => error.map(|e| e.worst_pixel).ok_or_else(|| {
                Error::Input("--focus worst needs the reference to compare with".into())
            }),
            Focus::Pixel(x, y) if x < width && y < height => Ok((x, y)),
            Focus::Pixel(x, y) => Err(Error::Input(format!(
                "--focus {x},{y} is outside the {width}x{height} frame"
            ))),
        }
    }
}

/// The pixels a magnified picture shows: `cols`×`rows` pixels from (`x0`, `y0`), each
/// drawn as a `factor`×`factor` block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Window {
    pub x0: u32,
    pub y0: u32,
    pub cols: u32,
    pub rows: u32,
    pub factor: u32,
    /// The pixel it is centred on (as far as the frame's edges allow).
    pub focus: (u32, u32),
}

impl Window {
    /// The window of a `width`×`height` frame that a picture of the same size shows at
    /// `factor`, centred on `focus` unless that would reach past the frame's edge.
    pub fn around(width: u32, height: u32, factor: u32, focus: (u32, u32)) -> Window {
        let factor = factor.clamp(1, MAX_FACTOR);
        let cols = width.div_ceil(factor).min(width);
        let rows = height.div_ceil(factor).min(height);
        let start = |centre: u32, span: u32, size: u32| {
            centre
                .saturating_sub(span / 2)
                .min(size.saturating_sub(span))
        };
        Window {
            x0: start(focus.0, cols, width),
            y0: start(focus.1, rows, height),
            cols,
            rows,
            factor,
            focus,
        }
    }

    /// The window's first pixel.
    pub fn origin(&self) -> DVec2 {
        DVec2::new(f64::from(self.x0), f64::from(self.y0))
    }

    /// The window in image pixels.
    pub fn rect(&self) -> Rect {
        let min = DVec2::new(f64::from(self.x0), f64::from(self.y0));
        Rect {
            min,
            max: min + DVec2::new(f64::from(self.cols), f64::from(self.rows)),
        }
    }

    /// The frame pixel drawn at picture pixel (`px`, `py`), if the window has one there.
    pub fn pixel_at(&self, px: u32, py: u32) -> Option<(u32, u32)> {
        let (i, j) = (px / self.factor, py / self.factor);
        (i < self.cols && j < self.rows).then_some((self.x0 + i, self.y0 + j))
    }

    /// An image point (pixels) where the picture draws it.
    fn picture_point(&self, p: DVec2) -> DVec2 {
        (p - self.rect().min) * f64::from(self.factor)
    }
}

/// What a magnified picture shows in each block, beside the pixel's own value.
#[derive(Clone, Copy, Debug, Default)]
pub struct Layers<'a> {
    /// A method's overlay picture (classes, cost, …) of the frame, shown instead of
    /// the coverage.
    pub overlay: Option<&'a RgbImage>,
    /// The reference: the blocks show the signed error (red: too much coverage, blue:
    /// too little, full at 0.5) and, from ×32, the error under the value.
    pub error_against: Option<&'a CoverageImage>,
    /// The exact outline, traced over [`Window::rect`].
    pub outline: Option<&'a OutlineDrawing>,
}

/// A value no coverage can have: shown in yellow whatever the layer.
const INVALID: Rgb<u8> = Rgb([255, 220, 0]);
const GRID: Rgb<u8> = Rgb([110, 110, 110]);
const OUTLINE: Rgb<u8> = Rgb([255, 170, 0]);
const HANDLE: Rgb<u8> = Rgb([120, 170, 255]);

/// Draws `window` of `image` as a `width`×`height` picture (the frame's own size).
pub fn picture(
    image: &CoverageImage,
    window: &Window,
    layers: &Layers,
    width: u32,
    height: u32,
) -> RgbImage {
    let n = window.factor;
    let mut out = RgbImage::new(width, height);
    for j in 0..window.rows {
        for i in 0..window.cols {
            let (x, y) = (window.x0 + i, window.y0 + j);
            let value = image.get(x, y);
            let reference = layers.error_against.map(|r| r.get(x, y));
            let colour = block_colour(value, reference, layers.overlay.map(|o| *o.get_pixel(x, y)));
            fill_block(&mut out, i * n, j * n, n, colour);
            if n >= VALUES_FROM {
                write_values(&mut out, i * n, j * n, n, colour, value, reference);
            }
        }
    }
    if n >= GRID_FROM {
        draw_grid(&mut out, window);
    }
    if let Some(outline) = layers.outline {
        draw_outline(&mut out, window, outline);
    }
    out
}

fn block_colour(value: f32, reference: Option<f32>, overlay: Option<Rgb<u8>>) -> Rgb<u8> {
    let valid = |v: f32| (0.0..=1.0).contains(&v);
    match (reference, overlay) {
        _ if !valid(value) => INVALID,
        (Some(r), _) if !valid(r) => INVALID,
        (Some(r), _) => {
            // The coverage at half brightness, tinted by the error: full red (too much)
            // or blue (too little) at 0.5.
            let e = ((value - r) / 0.5).clamp(-1.0, 1.0);
            let g = (value * 127.0).round() as u8;
            let tint = if e >= 0.0 {
                Rgb([255, 40, 40])
            } else {
                Rgb([40, 90, 255])
            };
            mix(Rgb([g, g, g]), tint, f64::from(e.abs()))
        }
        (None, Some(colour)) => colour,
        (None, None) => {
            let v = (value * 255.0).round() as u8;
            Rgb([v, v, v])
        }
    }
}

fn fill_block(out: &mut RgbImage, x0: u32, y0: u32, n: u32, colour: Rgb<u8>) {
    for y in y0..(y0 + n).min(out.height()) {
        for x in x0..(x0 + n).min(out.width()) {
            out.put_pixel(x, y, colour);
        }
    }
}

/// One pixel-wide lines on each block's top and left edge.
fn draw_grid(out: &mut RgbImage, window: &Window) {
    let n = window.factor;
    let (w, h) = (
        (window.cols * n).min(out.width()),
        (window.rows * n).min(out.height()),
    );
    for y in 0..h {
        for x in 0..w {
            if x % n == 0 || y % n == 0 {
                let p = out.get_pixel_mut(x, y);
                *p = mix(*p, GRID, 0.6);
            }
        }
    }
}

/// The coverage with two decimals, and under it the signed error when there is a
/// reference, in a 3×5 pixel font scaled to the block.
fn write_values(
    out: &mut RgbImage,
    x0: u32,
    y0: u32,
    n: u32,
    background: Rgb<u8>,
    value: f32,
    reference: Option<f32>,
) {
    let scale = n / 16;
    let luminance = 0.2126 * f64::from(background[0])
        + 0.7152 * f64::from(background[1])
        + 0.0722 * f64::from(background[2]);
    let ink = if luminance > 128.0 {
        Rgb([0, 0, 0])
    } else {
        Rgb([255, 255, 255])
    };
    for (k, line) in block_labels(value, reference).iter().enumerate() {
        let top = y0 + scale + k as u32 * 6 * scale + k as u32 * scale;
        let mut left = x0 + 1 + scale / 2;
        for c in line.chars() {
            draw_char(out, left, top, scale, c, ink);
            left += 4 * scale;
        }
    }
}

/// What a magnified block writes about its pixel: its coverage, then its signed error
/// against `reference` when there is one (the explorer writes the same).
pub fn block_labels(value: f32, reference: Option<f32>) -> Vec<String> {
    let mut lines = vec![short_number(f64::from(value), false)];
    if let Some(r) = reference {
        lines.push(short_number(f64::from(value) - f64::from(r), true));
    }
    lines
}

/// At most four characters: ".53", "1.00", "-.05", "+.12", "nan", "inf"; a leading
/// zero is dropped so two decimals fit, and an error that rounds to none is "0".
fn short_number(v: f64, signed: bool) -> String {
    if v.is_nan() {
        return "nan".into();
    }
    if v.is_infinite() {
        return if v > 0.0 { "inf".into() } else { "-inf".into() };
    }
    let text = format!("{:.2}", v.abs());
    if signed && text == "0.00" {
        return "0".into();
    }
    let text = text.strip_prefix('0').unwrap_or(&text).to_owned();
    let sign = if v < 0.0 {
        "-"
    } else if signed {
        "+"
    } else {
        ""
    };
    format!("{sign}{text}")
}

/// The 3×5 pixel font: rows top to bottom, 3 bits each (most significant = left).
fn glyph_rows(c: char) -> [u8; 5] {
    match c {
        '0' => [7, 5, 5, 5, 7],
        '1' => [2, 6, 2, 2, 7],
        '2' => [7, 1, 7, 4, 7],
        '3' => [7, 1, 3, 1, 7],
        '4' => [5, 5, 7, 1, 1],
        '5' => [7, 4, 7, 1, 7],
        '6' => [7, 4, 7, 5, 7],
        '7' => [7, 1, 1, 2, 2],
        '8' => [7, 5, 7, 5, 7],
        '9' => [7, 5, 7, 1, 7],
        '.' => [0, 0, 0, 0, 2],
        '-' => [0, 0, 7, 0, 0],
        '+' => [0, 2, 7, 2, 0],
        'n' => [0, 6, 5, 5, 5],
        'a' => [0, 3, 5, 5, 3],
        'i' => [2, 0, 2, 2, 2],
        'f' => [3, 2, 7, 2, 2],
        _ => [7, 7, 7, 7, 7],
    }
}

fn draw_char(out: &mut RgbImage, left: u32, top: u32, scale: u32, c: char, ink: Rgb<u8>) {
    for (row, bits) in glyph_rows(c).into_iter().enumerate() {
        for col in 0..3u32 {
            if bits & (4 >> col) != 0 {
                let (x, y) = (left + col * scale, top + row as u32 * scale);
                for dy in 0..scale {
                    for dx in 0..scale {
                        if x + dx < out.width() && y + dy < out.height() {
                            out.put_pixel(x + dx, y + dy, ink);
                        }
                    }
                }
            }
        }
    }
}

/// The outline over the blocks: curves 1.5 px wide, handles 1 px, on-curve points as
/// discs and control points as rings, all anti-aliased by distance.
fn draw_outline(out: &mut RgbImage, window: &Window, outline: &OutlineDrawing) {
    for (pieces, width, colour) in [
        (&outline.handles, 1.0, HANDLE),
        (&outline.lines, 1.5, OUTLINE),
    ] {
        for [a, b] in pieces {
            let (a, b) = (window.picture_point(*a), window.picture_point(*b));
            stroke(out, a, b, width, colour);
        }
    }
    for p in &outline.on_curve {
        let p = window.picture_point(*p);
        paint_by_distance(out, p, p, 3.5, OUTLINE, |d| 3.0 - d);
    }
    for p in &outline.off_curve {
        let p = window.picture_point(*p);
        paint_by_distance(out, p, p, 3.5, HANDLE, |d| 0.75 - (d - 2.5).abs());
    }
}

fn stroke(out: &mut RgbImage, a: DVec2, b: DVec2, width: f64, colour: Rgb<u8>) {
    paint_by_distance(out, a, b, width, colour, |d| width / 2.0 - d);
}

/// Paints the pixels near segment a–b with `colour`, each with the alpha
/// `inside(distance from its centre to the segment) + ½` (so a pixel whose centre is
/// on the shape's edge is half covered).
fn paint_by_distance(
    out: &mut RgbImage,
    a: DVec2,
    b: DVec2,
    reach: f64,
    colour: Rgb<u8>,
    inside: impl Fn(f64) -> f64,
) {
    let lo = (a.min(b) - reach - 1.0).max(DVec2::ZERO);
    let hi =
        (a.max(b) + reach + 1.0).min(DVec2::new(f64::from(out.width()), f64::from(out.height())));
    if !(lo.x < hi.x && lo.y < hi.y) {
        return;
    }
    for y in lo.y as u32..hi.y.ceil() as u32 {
        for x in lo.x as u32..hi.x.ceil() as u32 {
            if x >= out.width() || y >= out.height() {
                continue;
            }
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let alpha = (inside(distance_to_segment(centre, a, b)) + 0.5).clamp(0.0, 1.0);
            if alpha > 0.0 {
                let p = out.get_pixel_mut(x, y);
                *p = mix(*p, colour, alpha);
            }
        }
    }
}

fn mix(under: Rgb<u8>, over: Rgb<u8>, alpha: f64) -> Rgb<u8> {
    Rgb(std::array::from_fn(|k| {
        (f64::from(under[k]) * (1.0 - alpha) + f64::from(over[k]) * alpha).round() as u8
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_window_centres_on_its_focus_and_stays_in_the_frame() {
        let w = Window::around(100, 60, 10, (50, 30));
        assert_eq!((w.x0, w.y0, w.cols, w.rows), (45, 27, 10, 6));
        let corner = Window::around(100, 60, 10, (99, 0));
        assert_eq!((corner.x0, corner.y0), (90, 0));
        // A factor that does not divide the frame shows the partial pixel too.
        let w = Window::around(100, 60, 16, (0, 59));
        assert_eq!((w.cols, w.rows, w.x0, w.y0), (7, 4, 0, 56));
        assert_eq!(w.pixel_at(16 * 6 + 3, 16 * 3), Some((6, 59)));
        assert_eq!(w.pixel_at(16 * 7, 0), None);
        let whole = Window::around(100, 60, 1, (3, 3));
        assert_eq!(
            (whole.x0, whole.y0, whole.cols, whole.rows),
            (0, 0, 100, 60)
        );
    }

    #[test]
    fn focus_parses_and_refuses_what_is_not_a_pixel() {
        assert_eq!("worst".parse(), Ok(Focus::Worst));
        assert_eq!("12, 7".parse(), Ok(Focus::Pixel(12, 7)));
        for bad in ["", "12", "-1,3", "1.5,2", "worst,1", "a,b"] {
            assert!(bad.parse::<Focus>().is_err(), "{bad}");
        }
        assert!(Focus::Pixel(10, 0).pixel(10, 10, None).is_err());
        assert!(Focus::Worst.pixel(10, 10, None).is_err());
    }

    #[test]
    fn each_block_shows_its_pixel() {
        let mut image = CoverageImage::new(8, 4);
        for (k, v) in image.data.iter_mut().enumerate() {
            *v = k as f32 / 31.0;
        }
        image.data[19] = f32::NAN;
        let window = Window::around(8, 4, 4, (4, 2));
        let out = picture(&image, &window, &Layers::default(), 8, 4);
        for py in 0..4 {
            for px in 0..8 {
                let (x, y) = window.pixel_at(px, py).unwrap();
                let v = image.get(x, y);
                let expected = if v.is_nan() {
                    INVALID
                } else {
                    let g = (v * 255.0).round() as u8;
                    Rgb([g, g, g])
                };
                assert_eq!(
                    *out.get_pixel(px, py),
                    expected,
                    "({px}, {py}) shows ({x}, {y})"
                );
            }
        }
    }

    #[test]
    fn numbers_fit_four_characters() {
        assert_eq!(short_number(0.53, false), ".53");
        assert_eq!(short_number(1.0, false), "1.00");
        assert_eq!(short_number(0.0, false), ".00");
        assert_eq!(short_number(-0.054, true), "-.05");
        assert_eq!(short_number(0.12, true), "+.12");
        assert_eq!(short_number(-0.001, true), "0");
        assert_eq!(short_number(f64::NAN, false), "nan");
        assert_eq!(short_number(f64::NEG_INFINITY, true), "-inf");
        for c in "0123456789.-+naif".chars() {
            assert_ne!(glyph_rows(c), [7; 5], "{c} has a glyph");
        }
    }
}
