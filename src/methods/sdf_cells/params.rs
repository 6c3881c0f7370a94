//! `--param` values of `sdf-cells`, checked.

use super::cells::Mode;
use crate::Error;
use crate::methods::{Overlay, ParamSpec, Params, param, parse_overlay, reject_unknown_params};

pub const NAME: &str = "sdf-cells";

/// Every parameter the method takes.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "mode",
        choices: &["estimate", "exact"],
        range: None,
        help: "estimate: the tangent-line distance of kocsis1david's font-demo (cheap, \
               wrong far from high curvature and where curves tie); exact: true distance \
               to each quadratic (a cubic solve per curve, after Clément Bœsch's \
               \"GPU-computed distances\" article) with the sign from the winding number.",
    },
    ParamSpec {
        key: "bias",
        choices: &["0.001", "0", "0.005"],
        range: None,
        help: "UDIST_BIAS of kocsis1david's font-demo, em: distances closer than this \
               tie and the turn at the join decides.",
    },
    ParamSpec {
        key: "grid",
        choices: &["auto"],
        range: Some((1, MAX_GRID)),
        help: "Cells per side of each glyph's grid. More cells, fewer curves per pixel, \
               more memory.",
    },
    ParamSpec {
        key: "encoding",
        choices: &["auto", "packed", "list"],
        range: None,
        help: "packed: the three loops in one u32 per cell of kocsis1david's font-demo; \
               list: offset + count into an index list; auto: packed where it fits.",
    },
    ParamSpec {
        key: "overlaps",
        choices: &["merge", "keep"],
        range: None,
        help: "merge: a glyph whose contours overlap is drawn from their nonzero union \
               (geometry::merge_overlaps), as kocsis1david's font-demo asks; keep: from \
               the contours as the font has them.",
    },
    ParamSpec {
        key: "outline",
        choices: &["0", "0.02", "0.05"],
        range: None,
        help: "Stroke width outside the edge, em (0 = off). Free once the distance exists.",
    },
    ParamSpec {
        key: "glow",
        choices: &["0", "0.1", "0.3"],
        range: None,
        help: "How far a glow fades beyond the outer edge, em (0 = off); grows the quads.",
    },
    ParamSpec {
        key: "dilate",
        choices: &["0", "0.02", "-0.02"],
        range: None,
        help: "Grow (positive) or erode (negative) the shape, em.",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "purple", "cells", "cost"],
        range: None,
        help: "purple: where the two nearest curves tie; cells: cell borders tinted by \
               curve count; cost: curves evaluated per pixel.",
    },
];

/// Overlays this method draws.
pub const OVERLAYS: &[Overlay] = &[
    Overlay::EqualDistance,
    Overlay::CellGrid,
    Overlay::CostHeatMap,
];

/// The `UDIST_BIAS` of kocsis1david's font-demo, taken as em.
pub const DEFAULT_BIAS_EM: f64 = 0.001;
/// The largest grid a parameter may force, per side.
pub const MAX_GRID: u32 = 64;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GridChoice {
    /// Chosen per glyph from its curve count and shape.
    Auto,
    /// N × N cells for every glyph.
    Fixed(u32),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EncodingChoice {
    /// Packed for every cell font-demo's word holds, the list for the others.
    Auto,
    /// Packed wherever it can be: an automatic grid is refined until every cell fits,
    /// except for glyphs past font-demo's 256 slots, which no grid can fit.
    Packed,
    /// The list for every cell.
    List,
}

/// What the effects do to the distance, in em.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Effects {
    /// Grows (positive) or shrinks (negative) the shape.
    pub dilate: f64,
    /// Width of a stroke drawn outside the (dilated) edge, hollowing the shape: 0 = off.
    pub outline: f64,
    /// How far beyond the shape's outer edge a glow fades out: 0 = off.
    pub glow: f64,
}

/// What preparation does with overlapping contours.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overlaps {
    /// Replaced by their nonzero union, where it differs from them.
    Merge,
    /// Kept as the font draws them.
    Keep,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub mode: Mode,
    pub overlaps: Overlaps,
    pub bias_em: f64,
    pub grid: GridChoice,
    pub encoding: EncodingChoice,
    pub effects: Effects,
    pub overlay: Option<Overlay>,
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            mode: Mode::Estimate,
            overlaps: Overlaps::Merge,
            bias_em: DEFAULT_BIAS_EM,
            grid: GridChoice::Auto,
            encoding: EncodingChoice::Auto,
            effects: Effects::default(),
            overlay: None,
        }
    }
}

impl Settings {
    pub fn from_params(params: &Params) -> Result<Settings, Error> {
        let keys: Vec<&str> = PARAMS.iter().map(|p| p.key).collect();
        reject_unknown_params(NAME, params, &keys)?;
        let defaults = Settings::default();
        let mode = match param(params, "mode") {
            None | Some("estimate") => Mode::Estimate,
            Some("exact") => Mode::Exact,
            Some(other) => return Err(bad("mode", other, "estimate or exact")),
        };
        let grid = match param(params, "grid") {
            None | Some("auto") => GridChoice::Auto,
            Some(v) => match v.parse::<u32>() {
                Ok(n) if (1..=MAX_GRID).contains(&n) => GridChoice::Fixed(n),
                _ => {
                    return Err(bad(
                        "grid",
                        v,
                        &format!("auto or a whole number 1 to {MAX_GRID}"),
                    ));
                }
            },
        };
        let encoding = match param(params, "encoding") {
            None | Some("auto") => EncodingChoice::Auto,
            Some("packed") => EncodingChoice::Packed,
            Some("list") => EncodingChoice::List,
            Some(other) => return Err(bad("encoding", other, "auto, packed or list")),
        };
        let overlaps = match param(params, "overlaps") {
            None | Some("merge") => Overlaps::Merge,
            Some("keep") => Overlaps::Keep,
            Some(other) => return Err(bad("overlaps", other, "merge or keep")),
        };
        Ok(Settings {
            mode,
            overlaps,
            bias_em: number(params, "bias", defaults.bias_em, 0.0, 0.1)?,
            grid,
            encoding,
            effects: Effects {
                dilate: number(params, "dilate", 0.0, -0.5, 0.5)?,
                outline: number(params, "outline", 0.0, 0.0, 0.5)?,
                glow: number(params, "glow", 0.0, 0.0, 1.0)?,
            },
            overlay: parse_overlay(NAME, param(params, "overlay"), OVERLAYS)?,
        })
    }

    /// How far outside the outline the effects draw, em.
    pub fn reach_em(&self) -> f64 {
        let e = &self.effects;
        e.dilate.max(0.0) + e.outline + e.glow
    }
}

fn bad(key: &str, value: &str, expected: &str) -> Error {
    Error::Input(format!(
        "method '{NAME}': {key}={value} is not valid; expected {expected}"
    ))
}

/// The number of em a parameter gives, within [low, high].
fn number(params: &Params, key: &str, default: f64, low: f64, high: f64) -> Result<f64, Error> {
    let Some(text) = param(params, key) else {
        return Ok(default);
    };
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && (low..=high).contains(&v) => Ok(v),
        _ => Err(bad(
            key,
            text,
            &format!("a number of em from {low} to {high}"),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(pairs: &[(&str, &str)]) -> Result<Settings, Error> {
        let params: Vec<(String, String)> = pairs
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect();
        Settings::from_params(&params)
    }

    #[test]
    fn good_values_parse() {
        let s = parse(&[
            ("mode", "exact"),
            ("bias", "0.002"),
            ("grid", "12"),
            ("encoding", "list"),
            ("dilate", "-0.02"),
            ("outline", "0.03"),
            ("glow", "0.1"),
            ("overlay", "purple"),
        ])
        .unwrap();
        assert_eq!(s.mode, Mode::Exact);
        assert_eq!(s.grid, GridChoice::Fixed(12));
        assert_eq!(s.encoding, EncodingChoice::List);
        assert_eq!(s.overlay, Some(Overlay::EqualDistance));
        assert!(
            (s.reach_em() - 0.13).abs() < 1e-12,
            "erosion reaches nowhere"
        );
        assert_eq!(parse(&[]).unwrap(), Settings::default());
    }

    #[test]
    fn bad_values_are_one_line_input_errors() {
        for (key, value, expect) in [
            ("mode", "fast", "estimate or exact"),
            ("grid", "0", "1 to 64"),
            ("grid", "65", "1 to 64"),
            ("grid", "2.5", "whole number"),
            ("encoding", "zip", "auto, packed or list"),
            ("bias", "-1", "number of em"),
            ("bias", "nan", "number of em"),
            ("glow", "1e400", "number of em"),
            ("outline", "wide", "number of em"),
            ("overlay", "wireframe", "no overlay 'wireframe'"),
            ("colour", "red", "no parameter 'colour'"),
        ] {
            let err = parse(&[(key, value)]).unwrap_err();
            let message = err.to_string();
            assert!(matches!(err, Error::Input(_)), "{key}={value}");
            assert!(message.contains(expect), "{key}={value}: {message}");
            assert!(!message.contains('\n'));
        }
    }
}
