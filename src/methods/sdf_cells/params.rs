//! The parameters of `sdf-cells` and the settings they choose.

use super::cells::Mode;
use crate::methods::Overlay;
use crate::methods::params::{BETWEEN, Numbers, ParamSpec, Params, Value};

pub const NAME: &str = "sdf-cells";

/// Every parameter the method takes.
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "mode",
        choices: &["estimate", "exact"],
        numbers: None,
        help: "estimate: the tangent-line distance of kocsis1david's font-demo (cheap; \
               curves halved until flat, and the side from the winding number where \
               curves tie, by default); exact: true distance \
               to each quadratic (a cubic solve per curve, after Clément Bœsch's \
               \"GPU-computed distances\" article) with the sign from the winding number.",
    },
    ParamSpec {
        key: "flatness",
        choices: &["0.004", "off", "0.001"],
        numbers: Some(Numbers::Real {
            min: 0.0001,
            max: 1.0,
            unit: "em",
        }),
        help: "estimate: each curve halved until it keeps within this many em of its \
               chord, the remedy font-demo names (\"beziers can be subdivided\"): the \
               tangent-line distance is off by about the curve's bend, and so is the \
               chord that picks the nearest curve; off: the curves as the font has them, \
               font-demo as published. More curves per cell as it shrinks.",
    },
    ParamSpec {
        key: "ties",
        choices: &["winding", "merge"],
        numbers: None,
        help: "estimate: where the side of the nearest curve comes from a rule rather \
               than its tangent line (curves tied within `bias` disagree, or the pixel \
               lies past the ends of the nearest chord), winding: the winding number \
               along the pixel's row decides, as exact mode's does everywhere; merge: \
               font-demo's rules for joins and ties decide alone, as published (a wrong \
               choice reads a pixel a whole pixel off).",
    },
    ParamSpec {
        key: "bias",
        choices: &["0.001", "0", "0.005"],
        numbers: Some(Numbers::Real {
            min: 0.0,
            max: 0.1,
            unit: "em",
        }),
        help: "UDIST_BIAS of kocsis1david's font-demo, em: distances closer than this \
               tie and the turn at the join decides.",
    },
    ParamSpec {
        key: "grid",
        choices: &["auto"],
        numbers: Some(Numbers::Whole {
            min: 1,
            max: MAX_GRID,
        }),
        help: "Cells per side of each glyph's grid. More cells, fewer curves per pixel, \
               more memory.",
    },
    ParamSpec {
        key: "encoding",
        choices: &["auto", "packed", "list"],
        numbers: None,
        help: "packed: the three loops in one u32 per cell of kocsis1david's font-demo; \
               list: offset + count into an index list; auto: packed where it fits.",
    },
    ParamSpec {
        key: "overlaps",
        choices: &["merge", "keep"],
        numbers: None,
        help: "merge: a glyph whose contours overlap is drawn from their nonzero union \
               (geometry::merge_overlaps), as kocsis1david's font-demo asks; keep: from \
               the contours as the font has them.",
    },
    BETWEEN,
    ParamSpec {
        key: "outline",
        choices: &["0", "0.02", "0.05"],
        numbers: Some(Numbers::Real {
            min: 0.0,
            max: 0.5,
            unit: "em",
        }),
        help: "Stroke width outside the edge, em (0 = off). Free once the distance exists.",
    },
    ParamSpec {
        key: "glow",
        choices: &["0", "0.1", "0.3"],
        numbers: Some(Numbers::Real {
            min: 0.0,
            max: 1.0,
            unit: "em",
        }),
        help: "How far a glow fades beyond the outer edge, em (0 = off); grows the quads.",
    },
    ParamSpec {
        key: "dilate",
        choices: &["0", "0.02", "-0.02"],
        numbers: Some(Numbers::Real {
            min: -0.5,
            max: 0.5,
            unit: "em",
        }),
        help: "Grow (positive) or erode (negative) the shape, em.",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "purple", "cells", "cost"],
        numbers: None,
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
/// How far a curve may stray from its chord in the estimate, em, by default.
pub const DEFAULT_FLATNESS_EM: f64 = 0.004;
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
    /// Draw each group of instances whose ink overlaps as one glyph (`between=union`).
    pub join_instances: bool,
    pub bias_em: f64,
    /// Estimate: curves halved until within this many em of their chord; None: off.
    pub flatness_em: Option<f64>,
    /// Estimate: where tied curves' sides disagree, the winding number decides.
    pub ties_by_winding: bool,
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
            join_instances: true,
            bias_em: DEFAULT_BIAS_EM,
            flatness_em: Some(DEFAULT_FLATNESS_EM),
            ties_by_winding: true,
            grid: GridChoice::Auto,
            encoding: EncodingChoice::Auto,
            effects: Effects::default(),
            overlay: None,
        }
    }
}

impl Settings {
    pub fn from_params(params: &Params) -> Settings {
        let defaults = Settings::default();
        let em = |key: &str, default: f64| params.real(key).unwrap_or(default);
        Settings {
            mode: match params.word("mode") {
                Some("exact") => Mode::Exact,
                _ => Mode::Estimate,
            },
            overlaps: match params.word("overlaps") {
                Some("keep") => Overlaps::Keep,
                _ => Overlaps::Merge,
            },
            join_instances: params.word("between") != Some("add"),
            bias_em: em("bias", defaults.bias_em),
            flatness_em: match params.get("flatness") {
                Some(Value::Word("off")) => None,
                Some(Value::Real(x)) => Some(x),
                _ => defaults.flatness_em,
            },
            ties_by_winding: params.word("ties") != Some("merge"),
            grid: match params.get("grid") {
                Some(Value::Whole(n)) => GridChoice::Fixed(n),
                _ => GridChoice::Auto,
            },
            encoding: match params.word("encoding") {
                Some("packed") => EncodingChoice::Packed,
                Some("list") => EncodingChoice::List,
                _ => EncodingChoice::Auto,
            },
            effects: Effects {
                dilate: em("dilate", defaults.effects.dilate),
                outline: em("outline", defaults.effects.outline),
                glow: em("glow", defaults.effects.glow),
            },
            overlay: params.word("overlay").and_then(Overlay::named),
        }
    }

    /// How far outside the outline the effects draw, em.
    pub fn reach_em(&self) -> f64 {
        let e = &self.effects;
        e.dilate.max(0.0) + e.outline + e.glow
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;
    use crate::methods::params::owned;

    fn parse(pairs: &[(&str, &str)]) -> Result<Settings, Error> {
        Params::parse(NAME, PARAMS, &owned(pairs)).map(|params| Settings::from_params(&params))
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
            ("between", "add"),
        ])
        .unwrap();
        assert_eq!(s.mode, Mode::Exact);
        assert_eq!(s.grid, GridChoice::Fixed(12));
        assert_eq!(s.encoding, EncodingChoice::List);
        assert_eq!(s.overlay, Some(Overlay::EqualDistance));
        assert!(!s.join_instances);
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
            ("between", "merge", "union or add"),
            ("bias", "-1", "number of em"),
            ("bias", "nan", "number of em"),
            ("glow", "1e400", "number of em"),
            ("outline", "wide", "number of em"),
            ("overlay", "wireframe", "overlay=wireframe is not valid"),
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
