//! A view: the scene and the camera that looks at it, as `glyphscope render`'s
//! arguments describe them. The CLI, the bench's standard scenes and the tests build
//! their frames from these, so every bench case reruns alone as a `render` command.

use std::path::{Path, PathBuf};

use clap::Args;
use glam::DVec2;

use crate::Error;
use crate::camera::{Camera, MAX_IMAGE_SIDE, MAX_SIZE_PX_PER_EM};
use crate::font::{Font, axis_tag};
use crate::scene::Scene;

/// What to draw and from where.
#[derive(Args, Clone, Debug)]
pub struct ViewArgs {
    /// Font file (.ttf/.otf); the embedded DejaVu Sans when absent.
    #[arg(long)]
    pub font: Option<PathBuf>,
    /// Text to shape; '\n' (or a literal backslash-n) starts a new line.
    // Not required here: `render --case` names a view instead, and `build` says what is
    // missing.
    #[arg(long, conflicts_with = "glyph_id")]
    pub text: Option<String>,
    /// One glyph by its id in the font.
    #[arg(long)]
    pub glyph_id: Option<u32>,
    /// Size in pixels per em (required).
    #[arg(long, allow_negative_numbers = true)]
    pub size: Option<f64>,
    /// Image width; by default the ink box plus a margin.
    #[arg(long)]
    pub width: Option<u32>,
    /// Image height; by default the ink box plus a margin.
    #[arg(long)]
    pub height: Option<u32>,
    /// Baseline origin X,Y in pixels; by default the ink box starts at the margin.
    #[arg(long, value_parser = parse_pair, allow_hyphen_values = true)]
    pub origin: Option<DVec2>,
    /// Matrix A,B,C,D: X = ox + (A·x + B·y)·s, Y = oy − (C·x + D·y)·s.
    #[arg(long, value_parser = parse_matrix, allow_hyphen_values = true)]
    pub matrix: Option<[f64; 4]>,
    /// Moves scene and view together by DX,DY pixels (the image must not change).
    #[arg(long, value_parser = parse_pair, allow_hyphen_values = true)]
    pub world_offset: Option<DVec2>,
    /// Perspective tilt in degrees about the image's horizontal centre line.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub tilt: f64,
    /// Variable-font axis values, TAG=VALUE[,TAG=VALUE...] (e.g. wght=700); a tag
    /// shorter than four characters is space-padded (M1=0.4 sets axis 'M1  ').
    #[arg(long, value_delimiter = ',', value_parser = parse_variation)]
    pub variation: Vec<(String, f32)>,
}

/// Margin around the ink box of a default frame, pixels.
pub const FRAME_MARGIN_PX: f64 = 4.0;

impl ViewArgs {
    /// `--text TEXT --size SIZE` in the default font and frame: the start of a view
    /// built in code.
    pub fn text(text: &str, size: f64) -> ViewArgs {
        ViewArgs {
            font: None,
            text: Some(text.to_owned()),
            glyph_id: None,
            size: Some(size),
            width: None,
            height: None,
            origin: None,
            matrix: None,
            world_offset: None,
            tilt: 0.0,
            variation: Vec::new(),
        }
    }

    /// Loads the font, applying `--variation` values.
    pub fn font(&self) -> Result<Font, Error> {
        load_font(self.font.as_deref(), &self.variation)
    }

    /// Builds the scene and the camera that look at it, checking every input.
    pub fn build(&self) -> Result<(Scene, Camera), Error> {
        self.build_with(self.font()?)
    }

    /// [`ViewArgs::build`] with `font` already loaded (at the `--variation` instance).
    pub fn build_with(&self, font: Font) -> Result<(Scene, Camera), Error> {
        let size = self
            .size
            .ok_or_else(|| Error::Input("give --size".into()))?;
        if !size.is_finite() || size <= 0.0 {
            return Err(Error::Input(format!(
                "--size must be a positive number of px/em, got {size}"
            )));
        }
        if size > MAX_SIZE_PX_PER_EM {
            return Err(Error::Input(format!(
                "--size {size} is over the limit of {MAX_SIZE_PX_PER_EM}"
            )));
        }
        let scene = match (&self.text, self.glyph_id) {
            (Some(text), _) => Scene::from_text(&font, text)?,
            (None, Some(id)) => Scene::from_glyph_id(&font, id)?,
            (None, None) => return Err(Error::Input("give --text or --glyph-id".into())),
        };
        let mut camera = Camera::new(1, 1, size, DVec2::ZERO);
        if let Some([a, b, c, d]) = self.matrix {
            camera.matrix = Camera::matrix_from_rows(a, b, c, d);
        }
        camera.validate()?;
        // The frame: ink bounds under the matrix, before any tilt (which turns about the
        // frame's centre and so needs the frame first).
        let ink = camera.ink_bounds(&scene)?;
        camera.origin = self
            .origin
            .unwrap_or(DVec2::splat(FRAME_MARGIN_PX) - ink.min);
        let ink_max = ink.max + camera.origin;
        let side = |given: Option<u32>, extent: f64, flag: &str| -> Result<u32, Error> {
            if let Some(v) = given {
                return Ok(v);
            }
            let v = (extent.max(0.0) + FRAME_MARGIN_PX).ceil();
            if v > f64::from(MAX_IMAGE_SIDE) {
                return Err(Error::Input(format!(
                    "the text is {v} px {flag} at this size, over the limit of {MAX_IMAGE_SIDE}; \
                     pass --width and --height to view part of it"
                )));
            }
            Ok(v.max(1.0) as u32)
        };
        camera.width = side(self.width, ink_max.x, "wide")?;
        camera.height = side(self.height, ink_max.y, "tall")?;
        camera.world_offset = self.world_offset.unwrap_or(DVec2::ZERO);
        camera.tilt_deg = self.tilt;
        camera.validate()?;
        // Fails early, with a clear message, if the tilt puts ink behind the eye.
        camera.ink_bounds(&scene)?;
        Ok((scene, camera))
    }

    /// The `render` arguments that draw this view (add `--method` and `--param`s).
    pub fn command_line(&self) -> Vec<String> {
        let mut out = Vec::new();
        if let Some(font) = &self.font {
            out.extend(["--font".into(), font.display().to_string()]);
        }
        if let Some(text) = &self.text {
            out.extend(["--text".into(), text.clone()]);
        }
        if let Some(size) = self.size {
            out.extend(["--size".into(), size.to_string()]);
        }
        let pair = |v: DVec2| format!("{},{}", v.x, v.y);
        if let (Some(w), Some(h)) = (self.width, self.height) {
            out.extend([
                "--width".into(),
                w.to_string(),
                "--height".into(),
                h.to_string(),
            ]);
        }
        if let Some(origin) = self.origin {
            out.extend(["--origin".into(), pair(origin)]);
        }
        if let Some(m) = self.matrix {
            out.extend(["--matrix".into(), m.map(|v| v.to_string()).join(",")]);
        }
        if self.tilt != 0.0 {
            out.extend(["--tilt".into(), self.tilt.to_string()]);
        }
        for (tag, value) in &self.variation {
            // Unpadded, so the line pastes into a shell; parsing pads it again.
            out.extend(["--variation".into(), format!("{}={value}", tag.trim_end())]);
        }
        out
    }
}

/// `--font` (the embedded default when absent) at the `--variation` instance.
pub fn load_font(path: Option<&Path>, variation: &[(String, f32)]) -> Result<Font, Error> {
    let font = match path {
        Some(path) => Font::from_path(path)?,
        None => crate::font::default_font(),
    };
    if variation.is_empty() {
        Ok(font)
    } else {
        font.with_variations(variation)
    }
}

fn parse_number(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("'{s}' is not a finite number"))
    }
}

fn parse_numbers<const N: usize>(s: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != N {
        return Err(format!("expected {N} comma-separated numbers, got '{s}'"));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = parse_number(p)?;
    }
    Ok(out)
}

fn parse_pair(s: &str) -> Result<DVec2, String> {
    parse_numbers::<2>(s).map(DVec2::from_array)
}

fn parse_matrix(s: &str) -> Result<[f64; 4], String> {
    parse_numbers::<4>(s)
}

pub fn parse_key_value(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((k, v)) if !k.trim().is_empty() => Ok((k.trim().to_owned(), v.trim().to_owned())),
        _ => Err(format!("expected KEY=VALUE, got '{s}'")),
    }
}

/// TAG=VALUE, the tag space-padded to four characters.
pub fn parse_variation(s: &str) -> Result<(String, f32), String> {
    let (tag, value) = parse_key_value(s)?;
    let tag = axis_tag(&tag).map_err(|e| e.to_string())?;
    let value = parse_number(&value)?;
    Ok((tag, value as f32))
}
