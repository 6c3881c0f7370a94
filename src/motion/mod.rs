//! Text in motion: a camera path, frame by frame.
//!
//! An outline method exists for text that is constantly transformed (the first line of
//! font-demo, the signed-distance-cells source). A method can be right on average and
//! still shimmer as text moves: an atlas snaps glyphs between its sub-pixel phases, a
//! two-ray heuristic changes its mind as an edge crosses a pixel centre. A
//! [`MotionPath`] moves the camera by a fixed step per frame so that a run is
//! reproducible frame by frame; [`crate::metrics::temporal`] measures what each method
//! does between frames.
//!
//! Frame `n`'s camera is computed from the base camera and `n` in closed form, never by
//! accumulating steps, so stepping back returns exactly the earlier frame's pixels.
//! Motions act on the image plane before the camera's tilt (which turns that plane), so
//! under a tilt a drift is a drift of the untilted picture.
//!
//! The paths the bench, the stability sweep and the explorer share are named here once.

/// 1/16 px a frame along x: between every sub-pixel phase of a 4-phase atlas.
pub const DRIFT_X: &str = "drift:0.0625,0";
/// 1/16 px a frame along 30° (up and right): across rows and columns at once.
pub const DRIFT_30: &str = "drift:0.05412658773652741,-0.03125";
/// A quarter of a degree a frame about the image's centre.
pub const TURN: &str = "rotate:0.25";

pub mod command;
pub mod report;
pub mod run;

use std::f64::consts::TAU;
use std::fmt;

use glam::{DMat2, DVec2};

use crate::Error;
use crate::camera::Camera;

/// One kind of motion, its speed given per frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    /// Moves the text by (dx, dy) image pixels per frame (y down), in the image plane
    /// before any tilt.
    Drift(DVec2),
    /// Turns the text counter-clockwise as seen by this many degrees per frame, about an
    /// image point (None: the centre of the image; for a window, both are the frame's),
    /// in the image plane before any tilt.
    Rotate { deg: f64, about: Option<DVec2> },
    /// Multiplies the size by this factor per frame, about the image's centre.
    Zoom(f64),
    /// Sizes between `low` and `high` times the base size and back, one cycle per
    /// `period` frames (the scale's logarithm follows a cosine, starting at `low`),
    /// about the image's centre.
    Pulse { low: f64, high: f64, period: f64 },
    /// The tilt swings ±`amplitude_deg` about the base tilt, one cycle per `period`
    /// frames (a sine, starting at the base tilt).
    Sway { amplitude_deg: f64, period: f64 },
}

/// Motions applied together, in order, at every frame; no motion at all is the empty
/// path. Written as `drift:DX,DY`, `rotate:DEG` or `rotate:DEG@X,Y`, `zoom:F`,
/// `pulse:LOW,HIGH,PERIOD`, `sway:DEG,PERIOD`, joined by `+` (`still` for none).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MotionPath {
    pub motions: Vec<Motion>,
}

/// The grammar, for help texts and error messages.
pub const PATH_GRAMMAR: &str = "drift:DX,DY (pixels a frame), rotate:DEG or rotate:DEG@X,Y \
     (degrees a frame, counter-clockwise, about the image centre or pixel X,Y), zoom:F (size \
     factor a frame), pulse:LOW,HIGH,PERIOD (size between LOW and HIGH times the base, one \
     cycle per PERIOD frames), sway:DEG,PERIOD (tilt ±DEG, one cycle per PERIOD frames), \
     joined by '+'; 'still' for none";

impl MotionPath {
    /// Parses the grammar of [`PATH_GRAMMAR`].
    pub fn parse(text: &str) -> Result<MotionPath, Error> {
        let text = text.trim();
        if text == "still" {
            return Ok(MotionPath::default());
        }
        let motions = text
            .split('+')
            .map(parse_motion)
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| {
                Error::Input(format!(
                    "motion path '{text}': {e}; expected {PATH_GRAMMAR}"
                ))
            })?;
        Ok(MotionPath { motions })
    }

    pub fn is_still(&self) -> bool {
        self.motions.is_empty()
    }

    /// The camera of frame `frame` (0: `base` itself, but for a pulse, which starts at
    /// LOW; negative frames run the path backwards).
    pub fn camera_at(&self, base: &Camera, frame: i64) -> Camera {
        let n = frame as f64;
        let centre = image_centre(base);
        // The motions as one similarity of image points before the tilt: X ↦ L·X + t.
        let mut linear = DMat2::IDENTITY;
        let mut shift = DVec2::ZERO;
        let mut tilt = base.tilt_deg;
        for motion in &self.motions {
            let (l, t) = match *motion {
                Motion::Drift(step) => (DMat2::IDENTITY, n * step),
                Motion::Rotate { deg, about } => {
                    let about = about.map_or(centre, |p| p - frame_offset(base));
                    about_point(turn_in_image(n * deg), about)
                }
                Motion::Zoom(factor) => {
                    about_point(DMat2::from_diagonal(DVec2::splat(factor.powf(n))), centre)
                }
                Motion::Pulse { low, high, period } => {
                    let phase = 0.5 * (1.0 - (TAU * n / period).cos());
                    let scale = low * (high / low).powf(phase);
                    about_point(DMat2::from_diagonal(DVec2::splat(scale)), centre)
                }
                Motion::Sway {
                    amplitude_deg,
                    period,
                } => {
                    tilt += amplitude_deg * (TAU * n / period).sin();
                    (DMat2::IDENTITY, DVec2::ZERO)
                }
            };
            linear = l * linear;
            shift = l * shift + t;
        }
        // X = origin + F·s·M·p with F the y flip, so L·X + t = (L·origin + t) +
        // F·(k·s)·(F·L·F/k)·M·p, k the similarity's scale: F·L·F/k is a rotation in
        // the glyphs' y-up frame.
        let k = linear.determinant().sqrt();
        let flip = DMat2::from_diagonal(DVec2::new(1.0, -1.0));
        Camera {
            size_px_per_em: base.size_px_per_em * k,
            origin: linear * base.origin + shift,
            matrix: flip * linear * flip * base.matrix / k,
            tilt_deg: tilt,
            ..*base
        }
    }
}

/// The centre of the image a camera belongs to, in its own pixels: the frame's for a
/// window, so that every window of one frame turns about the same point.
fn image_centre(camera: &Camera) -> DVec2 {
    match camera.crop {
        Some(c) => DVec2::new(f64::from(c.frame_width), f64::from(c.frame_height)) * 0.5 - c.offset,
        None => DVec2::new(f64::from(camera.width), f64::from(camera.height)) * 0.5,
    }
}

/// Where a window's pixel (0, 0) lies in its frame (none for a whole frame): a point
/// given in the frame's pixels is that much less in the window's.
fn frame_offset(camera: &Camera) -> DVec2 {
    camera.crop.map_or(DVec2::ZERO, |c| c.offset)
}

/// A counter-clockwise turn as seen, in image coordinates (y down).
fn turn_in_image(deg: f64) -> DMat2 {
    let (sin, cos) = deg.to_radians().sin_cos();
    Camera::matrix_from_rows(cos, sin, -sin, cos)
}

/// `linear` about the fixed point `p`: X ↦ L·(X − p) + p.
fn about_point(linear: DMat2, p: DVec2) -> (DMat2, DVec2) {
    (linear, p - linear * p)
}

fn parse_motion(part: &str) -> Result<Motion, String> {
    let (kind, args) = part
        .trim()
        .split_once(':')
        .ok_or_else(|| format!("'{part}' has no ':'"))?;
    let numbers = |text: &str, count: usize| -> Result<Vec<f64>, String> {
        let values = text
            .split(',')
            .map(|v| {
                v.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| format!("'{v}' in '{part}' is not a finite number"))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if values.len() != count {
            return Err(format!(
                "'{part}' needs {count} number(s), got {}",
                values.len()
            ));
        }
        Ok(values)
    };
    let positive = |v: f64, what: &str| {
        if v > 0.0 {
            Ok(v)
        } else {
            Err(format!("{what} in '{part}' must be positive, got {v}"))
        }
    };
    match kind.trim() {
        "drift" => {
            let v = numbers(args, 2)?;
            Ok(Motion::Drift(DVec2::new(v[0], v[1])))
        }
        "rotate" => {
            let (deg, about) = match args.split_once('@') {
                Some((deg, about)) => {
                    let p = numbers(about, 2)?;
                    (deg, Some(DVec2::new(p[0], p[1])))
                }
                None => (args, None),
            };
            Ok(Motion::Rotate {
                deg: numbers(deg, 1)?[0],
                about,
            })
        }
        "zoom" => Ok(Motion::Zoom(positive(numbers(args, 1)?[0], "the factor")?)),
        "pulse" => {
            let v = numbers(args, 3)?;
            Ok(Motion::Pulse {
                low: positive(v[0], "LOW")?,
                high: positive(v[1], "HIGH")?,
                period: positive(v[2], "the period")?,
            })
        }
        "sway" => {
            let v = numbers(args, 2)?;
            if v[0].abs() >= 90.0 {
                return Err(format!(
                    "a sway of {}° in '{part}' would turn the text edge-on",
                    v[0]
                ));
            }
            Ok(Motion::Sway {
                amplitude_deg: v[0],
                period: positive(v[1], "the period")?,
            })
        }
        other => Err(format!("unknown motion '{other}'")),
    }
}

impl fmt::Display for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Motion::Drift(d) => write!(f, "drift:{},{}", d.x, d.y),
            Motion::Rotate { deg, about: None } => write!(f, "rotate:{deg}"),
            Motion::Rotate {
                deg,
                about: Some(p),
            } => write!(f, "rotate:{deg}@{},{}", p.x, p.y),
            Motion::Zoom(k) => write!(f, "zoom:{k}"),
            Motion::Pulse { low, high, period } => write!(f, "pulse:{low},{high},{period}"),
            Motion::Sway {
                amplitude_deg,
                period,
            } => write!(f, "sway:{amplitude_deg},{period}"),
        }
    }
}

/// The path in its own grammar: `parse` reads back what this writes.
impl fmt::Display for MotionPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.motions.is_empty() {
            return f.write_str("still");
        }
        for (k, motion) in self.motions.iter().enumerate() {
            if k > 0 {
                f.write_str("+")?;
            }
            write!(f, "{motion}")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::project;

    fn base() -> Camera {
        let mut camera = Camera::new(200, 100, 20.0, DVec2::new(30.0, 70.0));
        camera.matrix = Camera::matrix_from_rows(1.0, 0.25, 0.0, 1.0);
        camera
    }

    /// Where the glyph point `p` (font units, pen at the origin) lands in frame `n`.
    fn image_of(path: &MotionPath, n: i64, p: DVec2) -> DVec2 {
        project(
            &path
                .camera_at(&base(), n)
                .glyph_to_image(1000.0, DVec2::ZERO),
            p,
        )
    }

    #[test]
    fn the_grammar_reads_back_what_it_writes() {
        for text in [
            "still",
            "drift:0.0625,0",
            "rotate:0.25",
            "rotate:-1.5@10,20.5",
            "zoom:1.01",
            "pulse:1,2,32",
            "sway:10,16",
            "drift:0.1,-0.2+rotate:0.25+zoom:0.99",
        ] {
            let path = MotionPath::parse(text).unwrap();
            assert_eq!(path.to_string(), text);
        }
        for bad in [
            "",
            "drift",
            "drift:1",
            "drift:1,x",
            "spin:1",
            "zoom:0",
            "zoom:-2",
            "pulse:1,2,0",
            "sway:95,10",
            "drift:nan,0",
            "rotate:1@2",
            "drift:1,0+",
        ] {
            let e = MotionPath::parse(bad).unwrap_err().to_string();
            assert!(
                e.starts_with("motion path") && !e.contains('\n'),
                "{bad}: {e}"
            );
        }
    }

    #[test]
    fn drift_moves_every_point_by_the_step_per_frame() {
        let path = MotionPath::parse("drift:0.125,-0.5").unwrap();
        let p = DVec2::new(123.0, 456.0);
        for n in [-3, 0, 1, 7] {
            let moved = image_of(&path, n, p) - image_of(&path, 0, p);
            let expected = n as f64 * DVec2::new(0.125, -0.5);
            assert!((moved - expected).length() < 1e-9, "frame {n}: {moved}");
        }
    }

    /// A point right of the centre turns upwards (y down) for a positive angle, by the
    /// hand-worked rotation about the centre (100, 50).
    #[test]
    fn rotate_turns_counter_clockwise_about_the_centre() {
        let path = MotionPath::parse("rotate:30").unwrap();
        let p = DVec2::new(500.0, 300.0);
        let before = image_of(&path, 0, p);
        let after = image_of(&path, 3, p);
        let centre = DVec2::new(100.0, 50.0);
        let r = before - centre;
        // 90° counter-clockwise as seen: (x, y) ↦ (y, −x) in image coordinates.
        let expected = centre + DVec2::new(r.y, -r.x);
        assert!((after - expected).length() < 1e-9, "{after} vs {expected}");
        let about = MotionPath::parse("rotate:90@0,0").unwrap();
        let turned = image_of(&about, 1, p);
        let b = image_of(&about, 0, p);
        assert!((turned - DVec2::new(b.y, -b.x)).length() < 1e-9);
    }

    #[test]
    fn zoom_and_pulse_scale_about_the_centre() {
        let centre = DVec2::new(100.0, 50.0);
        let p = DVec2::new(500.0, 300.0);
        let zoom = MotionPath::parse("zoom:1.5").unwrap();
        let expected = centre + 2.25 * (image_of(&zoom, 0, p) - centre);
        assert!((image_of(&zoom, 2, p) - expected).length() < 1e-9);
        assert!((zoom.camera_at(&base(), 2).size_px_per_em - 45.0).abs() < 1e-12);
        // Pulse: LOW at frame 0, HIGH half a period later, LOW again after one.
        let pulse = MotionPath::parse("pulse:0.5,2,8").unwrap();
        for (n, scale) in [(0, 0.5), (4, 2.0), (8, 0.5), (2, 1.0)] {
            let size = pulse.camera_at(&base(), n).size_px_per_em;
            assert!((size - 20.0 * scale).abs() < 1e-9, "frame {n}: {size}");
        }
    }

    #[test]
    fn sway_swings_the_tilt_and_motions_compose_in_order() {
        let sway = MotionPath::parse("sway:10,8").unwrap();
        let tilts: Vec<f64> = (0..5)
            .map(|n| sway.camera_at(&base(), n).tilt_deg)
            .collect();
        for (t, expected) in
            tilts
                .iter()
                .zip([0.0, 10.0 / 2f64.sqrt(), 10.0, 10.0 / 2f64.sqrt(), 0.0])
        {
            assert!((t - expected).abs() < 1e-9, "{tilts:?}");
        }
        // Drift then a half turn about (0, 0): the drift is turned too.
        let both = MotionPath::parse("drift:1,0+rotate:180@0,0").unwrap();
        let p = DVec2::new(10.0, 20.0);
        let expected = -(image_of(&both, 0, p) + DVec2::new(1.0, 0.0));
        assert!((image_of(&both, 1, p) - expected).length() < 1e-9);
    }

    /// A window of a frame moves as the frame does: every motion acts on the frame's
    /// pixels, about the frame's centre or point.
    #[test]
    fn a_window_moves_with_its_frame() {
        let mut frame = base();
        frame.tilt_deg = 20.0;
        let path = MotionPath::parse("drift:0.3,0.1+rotate:2@40,30+zoom:1.02+sway:5,8").unwrap();
        let p = DVec2::new(321.0, 123.0);
        for n in [1, 4] {
            let whole = path.camera_at(&frame, n);
            let window = path.camera_at(&frame.window(50, 20, 30, 40), n);
            let in_frame = project(&whole.glyph_to_image(1000.0, DVec2::ZERO), p);
            let in_window = project(&window.glyph_to_image(1000.0, DVec2::ZERO), p);
            assert!(
                (in_frame - DVec2::new(50.0, 20.0) - in_window).length() < 1e-9,
                "frame {n}"
            );
        }
    }

    #[test]
    fn the_matrix_stays_a_rotation_of_the_base_one() {
        let path = MotionPath::parse("rotate:7+zoom:1.1").unwrap();
        let camera = path.camera_at(&base(), 5);
        let turn = camera.matrix * base().matrix.inverse();
        assert!((turn.determinant() - 1.0).abs() < 1e-12);
        let angle = turn.x_axis.y.atan2(turn.x_axis.x).to_degrees();
        assert!((angle - 35.0).abs() < 1e-9, "{angle}");
    }
}
