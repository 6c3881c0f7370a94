//! Every view with a name: the hard cases of [`crate::stability::hard_cases`] (seen unturned,
//! at sub-pixel offset 0) and the bench's standard scenes. `glyphscope render --case
//! NAME` draws one and the explorer's Cases menu loads one, from this one list, so a
//! case added to either source is on both at once.

use crate::Error;
use crate::bench::scenes::{self, SCENE_NAMES};
use crate::camera::Camera;
use crate::font::SHIPPED_FONTS;
use crate::scene::Scene;
use crate::stability::hard_cases;

/// Where a named view comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// A hard case of `glyphscope stability`.
    HardCase,
    /// A standard scene of `glyphscope bench`.
    BenchScene,
}

/// A named view, without its scene: what a menu lists.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedView {
    pub name: &'static str,
    /// What it shows or tests, in a phrase.
    pub about: &'static str,
    pub source: Source,
}

/// Every named view: the hard cases in their table's order, then the bench scenes.
pub fn all() -> Vec<NamedView> {
    let hard = hard_cases::all().into_iter().map(|c| NamedView {
        name: c.name,
        about: c.what,
        source: Source::HardCase,
    });
    let bench = SCENE_NAMES.iter().filter_map(|name| {
        let scene = scenes::scene(name).ok()?;
        Some(NamedView {
            name: scene.name,
            about: scene.about,
            source: Source::BenchScene,
        })
    });
    hard.chain(bench).collect()
}

/// The scene and camera of the view called `name`: a hard case's own frame (as the
/// stability sweep sees it at rotation 0 and offset (0, 0)), or a bench scene's.
pub fn build(name: &str) -> Result<(Scene, Camera), Error> {
    if let Some(case) = hard_cases::all().into_iter().find(|c| c.name == name) {
        let camera = case.camera(0.0, glam::DVec2::ZERO)?;
        return Ok((case.scene, camera));
    }
    if SCENE_NAMES.contains(&name) {
        let args = scenes::scene(name)?.args;
        // The bench names its fonts by path under fonts/; the embedded copy of a shipped
        // font is the same file, and needs no working directory.
        let shipped = args.font.as_ref().and_then(|path| {
            let file = path.file_name()?;
            SHIPPED_FONTS.iter().position(|(_, f, _)| file == *f)
        });
        let font = match shipped {
            Some(index) if args.variation.is_empty() => crate::font::shipped(index),
            Some(index) => crate::font::shipped(index).with_variations(&args.variation)?,
            None => args.font()?,
        };
        return args.build_with(font);
    }
    Err(Error::Input(format!(
        "unknown case '{name}'; choose from: {}",
        all().iter().map(|v| v.name).collect::<Vec<_>>().join(", ")
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every listed view builds; hard cases come first, names are unique, and a bench
    /// scene's view is the one its own `render` command line draws.
    #[test]
    fn every_named_view_builds_and_names_are_unique() {
        let views = all();
        assert_eq!(
            views
                .iter()
                .filter(|v| v.source == Source::HardCase)
                .count(),
            hard_cases::all().len()
        );
        assert_eq!(
            views
                .iter()
                .filter(|v| v.source == Source::BenchScene)
                .count(),
            SCENE_NAMES.len()
        );
        let mut names: Vec<_> = views.iter().map(|v| v.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), views.len(), "a name is used twice");
        for view in &views {
            let (scene, camera) = build(view.name).unwrap();
            assert!(!scene.instances.is_empty(), "{}", view.name);
            camera.validate().unwrap();
        }
        let (_, by_name) = build("rotated").unwrap();
        let (_, by_args) = scenes::scene("rotated").unwrap().args.build().unwrap();
        assert_eq!(by_name, by_args);
        assert!(
            build("no-such-case")
                .unwrap_err()
                .to_string()
                .contains("choose from")
        );
    }
}
