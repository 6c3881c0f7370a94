//! What a survey measures: sizes, transforms, methods (each with the claim it makes at
//! its settings), variable instances and the glyph range. Checked once from the
//! command line; written beside the results, so a resumed run or a merge of shards
//! refuses results measured by another plan.

use glam::DMat2;
use serde::Serialize;

use crate::Error;
use crate::camera::{Camera, MAX_SIZE_PX_PER_EM};
use crate::methods::info::{Bound, Claim, MethodInfo, Role, Trait};
use crate::methods::registry;
use crate::motion::run::MethodSpec;

/// The default sizes: from small text to a headline.
pub const DEFAULT_SIZES: [f64; 4] = [9.0, 12.0, 24.0, 48.0];
/// The default transforms: the glyph as set, and turned by an angle that lines up
/// with nothing.
pub const DEFAULT_TRANSFORMS: [&str; 2] = ["still", "rotate:30"];

/// A camera transform of the glyphs: a rotation after a skew, as the explorer's
/// `rotate` and `skew` set them (so a survey row opens as a link).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Transform {
    /// As `--transforms` names it.
    pub name: String,
    pub rotation_deg: f64,
    pub skew: f64,
}

impl Transform {
    /// `still`, `rotate:DEG`, `skew:K`, or `rotate:DEG+skew:K`.
    pub fn parse(text: &str) -> Result<Transform, Error> {
        let bad = |why: &str| {
            Error::Input(format!(
                "--transforms: '{text}' {why}; a transform is still, rotate:DEG, skew:K or \
                 rotate:DEG+skew:K (a tilt's perspective depends on the whole frame, so a \
                 survey has none)"
            ))
        };
        let mut transform = Transform {
            name: text.to_owned(),
            rotation_deg: 0.0,
            skew: 0.0,
        };
        if text == "still" {
            return Ok(transform);
        }
        for part in text.split('+') {
            let (key, value) = part
                .split_once(':')
                .ok_or_else(|| bad("is not KEY:VALUE"))?;
            let value: f64 = value
                .parse()
                .ok()
                .filter(|v: &f64| v.is_finite())
                .ok_or_else(|| bad("has a value that is not a number"))?;
            match key {
                "rotate" => transform.rotation_deg = value,
                "skew" if value.abs() <= 4.0 => transform.skew = value,
                "skew" => return Err(bad("skews by more than 4")),
                _ => return Err(bad("names no transform")),
            }
        }
        Ok(transform)
    }

    /// The camera's matrix: the skew, then the rotation.
    pub fn matrix(&self) -> DMat2 {
        let (sin, cos) = self.rotation_deg.to_radians().sin_cos();
        Camera::matrix_from_rows(cos, -sin, sin, cos)
            * Camera::matrix_from_rows(1.0, self.skew, 0.0, 1.0)
    }
}

/// A method at its settings, with the claim it makes there.
#[derive(Clone, Debug)]
pub struct MethodRun {
    /// As `--methods` names it (`NAME` or `NAME:KEY=VALUE:…`).
    pub label: String,
    pub info: &'static MethodInfo,
    pub params: Vec<(String, String)>,
    /// The registry's claim for exactly these settings; None: observed only.
    pub claim: Option<Claim>,
}

impl MethodRun {
    /// The method `text` names (`NAME` or `NAME:KEY=VALUE:…`), with the claim its row
    /// makes at the same settings (defaults filled in on both sides).
    pub fn parse(text: &str) -> Result<MethodRun, Error> {
        let spec = MethodSpec::parse(text)?;
        let info = registry::find(&spec.name)?;
        if !draws_glyphs(info) {
            return Err(Error::Input(format!(
                "--methods: '{}' does not draw glyphs to measure (the survey compares \
                 every method with the reference)",
                info.name
            )));
        }
        let given = info.parse_params(&spec.params)?;
        let claim = info
            .claims
            .iter()
            .find(|c| {
                let claimed = info
                    .parse_params(&crate::methods::params::owned(c.params))
                    .expect("a claimed setting parses");
                info.params
                    .iter()
                    .all(|p| claimed.get(p.key) == given.get(p.key))
            })
            .map(|c| c.claim)
            // A peer's rows state no claim of glyphscope's: it is measured as it is.
            .filter(|_| !info.is_peer());
        Ok(MethodRun {
            label: text.trim().to_owned(),
            info,
            params: spec.params,
            claim,
        })
    }
}

/// Whether a row of the registry draws glyphs the survey can measure: the methods, the
/// baseline and the peers.
fn draws_glyphs(info: &MethodInfo) -> bool {
    matches!(info.role, Role::Method | Role::Baseline | Role::Peer)
}

/// Everything a survey measures, checked.
#[derive(Clone, Debug)]
pub struct Plan {
    pub sizes: Vec<f64>,
    pub transforms: Vec<Transform>,
    pub methods: Vec<MethodRun>,
    /// Variable-font instances besides the default, each `(tag, value)`s.
    pub instances: Vec<Vec<(String, f32)>>,
    /// Only glyph ids in this range (inclusive), where given.
    pub glyphs: Option<(u16, u16)>,
}

impl Plan {
    /// The plan the options describe: sizes (default [`DEFAULT_SIZES`]), transforms
    /// (default [`DEFAULT_TRANSFORMS`]), methods (default every row that draws glyphs,
    /// at its default settings).
    pub fn new(
        sizes: &[f64],
        transforms: &[String],
        methods: &[String],
        instances: Vec<Vec<(String, f32)>>,
        glyphs: Option<(u16, u16)>,
    ) -> Result<Plan, Error> {
        let sizes = if sizes.is_empty() {
            DEFAULT_SIZES.to_vec()
        } else {
            sizes.to_vec()
        };
        for &size in &sizes {
            if !size.is_finite() || size <= 0.0 || size > MAX_SIZE_PX_PER_EM {
                return Err(Error::Input(format!(
                    "--sizes: {size} is not a size from 0 to {MAX_SIZE_PX_PER_EM} px/em"
                )));
            }
        }
        let transforms = if transforms.is_empty() {
            DEFAULT_TRANSFORMS
                .iter()
                .map(|t| Transform::parse(t))
                .collect()
        } else {
            transforms
                .iter()
                .map(|t| Transform::parse(t))
                .collect::<Result<Vec<_>, _>>()
        }?;
        let methods = if methods.is_empty() {
            registry::METHODS
                .iter()
                .filter(|m| draws_glyphs(m))
                .map(|m| MethodRun::parse(m.name))
                .collect::<Result<Vec<_>, _>>()?
        } else {
            methods
                .iter()
                .map(|m| MethodRun::parse(m))
                .collect::<Result<Vec<_>, _>>()?
        };
        let mut labels: Vec<&str> = methods.iter().map(|m| m.label.as_str()).collect();
        labels.sort();
        if labels.windows(2).any(|w| w[0] == w[1]) {
            return Err(Error::Input("--methods: a method is named twice".into()));
        }
        if let Some((first, last)) = glyphs
            && first > last
        {
            return Err(Error::Input(format!("--glyphs: {first}-{last} is empty")));
        }
        Ok(Plan {
            sizes,
            transforms,
            methods,
            instances,
            glyphs,
        })
    }

    /// The glyph ids of a face with `count` glyphs that the plan surveys.
    pub fn glyph_ids(&self, count: u16) -> impl Iterator<Item = u16> + use<> {
        let (first, last) = self.glyphs.unwrap_or((0, u16::MAX));
        (first..=last.min(count.saturating_sub(1))).filter(move |_| count > 0)
    }

    /// The plan as written beside the results: what must match for results to merge
    /// (the claims each method is held to and the version among them).
    pub fn describe(&self) -> PlanFile {
        PlanFile {
            glyphscope: env!("CARGO_PKG_VERSION").to_owned(),
            claims: self
                .methods
                .iter()
                .map(|m| m.claim.as_ref().map(ClaimTerms::of))
                .collect(),
            sizes: self.sizes.clone(),
            transforms: self.transforms.iter().map(|t| t.name.clone()).collect(),
            methods: self.methods.iter().map(|m| m.label.clone()).collect(),
            instances: self.instances.clone(),
            glyphs: self.glyphs,
            user_files: self
                .methods
                .iter()
                .filter_map(|m| {
                    let stamp = crate::methods::user::stamp(m.info.name)?;
                    Some((m.info.name.to_owned(), format!("{stamp:016x}")))
                })
                .collect(),
        }
    }

    /// The plan a folder's file names, rebuilt (its methods' claims from today's
    /// registry: [`PlanFile`]s compare the claims they were judged by).
    pub fn from_file(file: &PlanFile) -> Result<Plan, Error> {
        Plan::new(
            &file.sizes,
            &file.transforms,
            &file.methods,
            file.instances.clone(),
            file.glyphs,
        )
    }
}

/// What a survey's folder was measured under, as its plan file holds it: the plan, and
/// what judged its results (the build and each method's claim). A run resumes, and
/// shards merge, only under an equal one.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PlanFile {
    /// The glyphscope version that measured: results judged by another build's claims
    /// do not mix with these.
    pub glyphscope: String,
    /// Each method's claim, in the order of `methods`; None where it claims nothing.
    pub claims: Vec<Option<ClaimTerms>>,
    pub sizes: Vec<f64>,
    /// As `--transforms` names them.
    pub transforms: Vec<String>,
    /// As `--methods` names them.
    pub methods: Vec<String>,
    /// Variable-font instances surveyed besides the default.
    pub instances: Vec<Vec<(String, f32)>>,
    /// The glyph ids surveyed, first and last; None for all.
    pub glyphs: Option<(u16, u16)>,
    /// Each user's file (`wgsl:PATH`) with a hash of its text: the results of a file
    /// edited since do not mix with these.
    #[serde(default)]
    pub user_files: Vec<(String, String)>,
}

/// The terms a claim judges rows by (its statement, words for people, aside).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ClaimTerms {
    pub bound: Option<Bound>,
    pub except: Vec<Trait>,
    pub limitation: Option<Bound>,
    pub temporal: Option<Bound>,
}

impl ClaimTerms {
    fn of(claim: &Claim) -> ClaimTerms {
        ClaimTerms {
            bound: claim.bound,
            except: claim.except.to_vec(),
            limitation: claim.limitation,
            temporal: claim.temporal,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transforms_parse_and_bad_ones_are_input_errors() {
        let t = Transform::parse("rotate:30+skew:0.25").unwrap();
        assert_eq!((t.rotation_deg, t.skew), (30.0, 0.25));
        let m = Transform::parse("rotate:90").unwrap().matrix();
        // A quarter turn counter-clockwise takes x to y.
        assert!((m * glam::DVec2::X - glam::DVec2::Y).length() < 1e-12);
        for bad in ["tilt:10", "rotate:x", "rotate", "skew:9", "rotate:inf"] {
            assert!(
                matches!(Transform::parse(bad), Err(Error::Input(_))),
                "{bad}"
            );
        }
    }

    /// A method named at its claimed settings carries that claim, spelled either way
    /// (defaults written out or left out); other settings carry none.
    #[test]
    fn a_method_carries_the_claim_of_its_settings() {
        let winding = MethodRun::parse("winding").unwrap();
        let explicit = MethodRun::parse("winding:aa=area").unwrap();
        let rays = MethodRun::parse("winding:aa=rays").unwrap();
        let claims = crate::methods::winding::INFO.claims;
        assert_eq!(winding.claim, Some(claims[0].claim));
        assert_eq!(explicit.claim, Some(claims[0].claim));
        assert_eq!(rays.claim, Some(claims[1].claim));
        assert_eq!(MethodRun::parse("winding:samples=1").unwrap().claim, None);
        assert_eq!(MethodRun::parse("atlas").unwrap().claim, None);
        assert_eq!(MethodRun::parse("msdf").unwrap().claim, None, "a peer");
        assert!(MethodRun::parse("reference").is_err());
        assert!(MethodRun::parse("bounds").is_err());
    }

    #[test]
    fn the_glyph_range_is_clipped_to_the_font() {
        let plan = Plan::new(&[], &[], &["winding".into()], Vec::new(), Some((5, 9))).unwrap();
        assert_eq!(plan.glyph_ids(7).collect::<Vec<_>>(), [5, 6]);
        assert_eq!(plan.glyph_ids(3).count(), 0);
        assert!(Plan::new(&[0.0], &[], &[], Vec::new(), None).is_err());
        assert!(
            Plan::new(
                &[],
                &[],
                &["winding".into(), "winding".into()],
                Vec::new(),
                None
            )
            .is_err()
        );
    }
}
