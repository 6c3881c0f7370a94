//! The parameters of `msdf` and the settings they choose.

use super::field::{FieldKind, FieldSpec};
use crate::methods::Overlay;
use crate::methods::params::{Numbers, ParamSpec, Params};

pub const NAME: &str = "msdf";

/// The most field texels per em a parameter may ask for.
pub const MAX_EM_PX: u32 = 512;
/// The defaults: the first choice of each row (a unit test holds them together).
const DEFAULT_EM_PX: u32 = 32;
const DEFAULT_RANGE: f64 = 4.0;

pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        key: "field",
        choices: &["msdf", "mtsdf", "sdf"],
        numbers: None,
        help: "msdf: Chlumský's multi-channel field (the median of three distances keeps \
               corners sharp); mtsdf: the same with the true distance in a fourth \
               channel; sdf: the single-channel field of Valve's 2007 paper (TextMeshPro).",
    },
    ParamSpec {
        key: "em_px",
        choices: &["32", "16", "24", "48", "64"],
        numbers: Some(Numbers::Whole {
            min: 1,
            max: MAX_EM_PX,
        }),
        help: "Field texels per em, the same at every size the text is drawn: 32 is the \
               low end of what msdf-atlas-gen users pick (32–48); 16 is too coarse for \
               corners (msdfgen issue 9).",
    },
    ParamSpec {
        key: "range",
        choices: &["4", "2", "8"],
        numbers: Some(Numbers::Real {
            min: 0.5,
            max: 64.0,
            unit: "texels",
        }),
        help: "The distances the field holds, texels, from −range/2 to +range/2: \
               msdf-atlas-gen's default is 2, common practice 4–8. Minified text needs a \
               range in proportion to the minification (msdfgen issue 182).",
    },
    ParamSpec {
        key: "correction",
        choices: &["on", "off"],
        numbers: None,
        help: "msdfgen's error correction of texels where interpolating the channels makes \
               artefacts (msdf and mtsdf; the sdf has none to correct).",
    },
    ParamSpec {
        key: "overlaps",
        choices: &["merge", "keep"],
        numbers: None,
        help: "merge: a glyph whose contours overlap is made into a field from their \
               nonzero union, as msdfgen does since 1.8; keep: from the contours as the \
               font has them, which msdfgen calls bad input (issue 110).",
    },
    ParamSpec {
        key: "overlay",
        choices: &["none", "channels", "median"],
        numbers: None,
        help: "channels: the field's channels as colour (red, green, blue); median: the \
               channel the median picks at each pixel, white where two agree.",
    },
];

/// Overlays this method draws.
pub const OVERLAYS: &[Overlay] = &[Overlay::FieldChannels, Overlay::MedianChannel];

/// What the parameters choose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    pub field: FieldSpec,
    /// Make fields from the nonzero union of overlapping contours.
    pub merge_overlaps: bool,
    pub overlay: Option<Overlay>,
}

impl Settings {
    pub fn from_params(params: &Params) -> Settings {
        let kind = match params.word("field") {
            Some("sdf") => FieldKind::Sdf,
            Some("mtsdf") => FieldKind::Mtsdf,
            _ => FieldKind::Msdf,
        };
        Settings {
            field: FieldSpec {
                kind,
                texels_per_em: f64::from(params.whole("em_px").unwrap_or(DEFAULT_EM_PX)),
                range: params.real("range").unwrap_or(DEFAULT_RANGE),
                correction: params.word("correction") != Some("off"),
            },
            merge_overlaps: params.word("overlaps") != Some("keep"),
            overlay: params.word("overlay").and_then(Overlay::named),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fallbacks `from_params` names are the rows' own defaults, and the settings
    /// with nothing given are msdfgen's: a multi-channel field, corrected, overlaps
    /// merged.
    #[test]
    fn the_defaults_are_the_rows_first_choices() {
        let row = |key: &str| PARAMS.iter().find(|r| r.key == key).expect(key);
        assert_eq!(row("em_px").choices[0], DEFAULT_EM_PX.to_string());
        assert_eq!(row("range").choices[0].parse::<f64>(), Ok(DEFAULT_RANGE));
        let settings = Settings::from_params(&Params::parse(NAME, PARAMS, &[]).unwrap());
        assert_eq!(settings.field.kind, FieldKind::Msdf);
        assert_eq!(settings.field.texels_per_em, f64::from(DEFAULT_EM_PX));
        assert_eq!(settings.field.range, DEFAULT_RANGE);
        assert!(settings.field.correction && settings.merge_overlaps);
        assert_eq!(settings.overlay, None);
    }
}
