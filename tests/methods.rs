//! One conformance test over the registry: every method it lists is drawn, checked and
//! measured everywhere a method belongs, so a method added to the registry is tested
//! everywhere and a row left incomplete fails here rather than going missing quietly
//! (from the bench, the plot's legend, the stability sweep or the app's menus).

mod common;

use std::collections::HashSet;

use glyphscope::Error;
use glyphscope::bench::method_settings;
use glyphscope::measure::{self, FrameTiming};
use glyphscope::methods::info::{MethodInfo, Role, Trait};
use glyphscope::methods::params::Numbers;
use glyphscope::methods::{Overlay, registry};
use glyphscope::metrics;
use glyphscope::stability::claims;
use glyphscope::view_args::ViewArgs;

/// A few ordinary scenes, as `render` draws them, with what makes them hard.
fn scenes() -> Vec<(&'static str, ViewArgs, &'static [Trait])> {
    let text = ViewArgs::text;
    vec![
        ("text at 16 px/em", text("Hamburgefonstiv", 16.0), &[]),
        (
            "turned 30° and tilted",
            ViewArgs {
                matrix: Some([0.866_025_4, -0.5, 0.5, 0.866_025_4]),
                tilt: 25.0,
                ..text("Rotated", 28.0)
            },
            &[],
        ),
        (
            "Latin Modern cubics",
            ViewArgs {
                font: Some("fonts/lmroman10-regular.otf".into()),
                ..text("Quixotic", 24.0)
            },
            &[],
        ),
        (
            "Inter at wght 900, contours overlapping",
            ViewArgs {
                font: Some("fonts/Inter-roman.var.ttf".into()),
                variation: vec![("wght".into(), 900.0)],
                ..text("Ökonomie", 32.0)
            },
            &[Trait::Overlapping],
        ),
    ]
}

/// One frame is enough here: the figures checked are the image's, not its time.
const ONE_FRAME: FrameTiming = FrameTiming {
    warmup: 0,
    frames: 1,
};

/// Every method's row is complete for its role, and no two share a name or a colour.
#[test]
fn every_row_is_complete_for_its_role() {
    let mut names = HashSet::new();
    let mut colours = HashSet::new();
    for m in registry::METHODS {
        assert!(names.insert(m.name), "{}: named twice", m.name);
        assert!(
            colours.insert(m.colour),
            "{}: a colour taken already",
            m.name
        );
        assert!(m.summary.len() > 20, "{}: say how it draws", m.name);
        assert_eq!(
            m.constructor.is_some(),
            m.role != Role::Reference,
            "{}: every GPU method can be made; the reference is not one",
            m.name
        );
        assert_eq!(
            m.shader.is_some(),
            m.constructor.is_some(),
            "{}: a shader",
            m.name
        );
        if m.is_benched() {
            assert!(
                m.bench
                    .first()
                    .is_some_and(|s| s.params.is_empty() && s.quick),
                "{}: the bench measures its default first, in --quick too",
                m.name
            );
            let quick = if m.is_peer() { 1 } else { 2 };
            assert!(
                m.bench.iter().filter(|s| s.quick).count() >= quick,
                "{}: --quick shows a trade (a peer: its default)",
                m.name
            );
        } else {
            assert!(
                m.bench.is_empty(),
                "{}: benched, but not in its role",
                m.name
            );
        }
        if m.role == Role::Method {
            assert!(
                m.claims.iter().any(|c| c.params.is_empty()),
                "{}: a drawing method states a claim at its defaults",
                m.name
            );
        }
    }
    assert_eq!(
        registry::METHODS
            .iter()
            .filter(|m| m.role == Role::Baseline)
            .count(),
        1,
        "one baseline divides every bench time"
    );
}

/// The committed full bench run (`docs/bench/bench.json`, which the docs quote) measured
/// exactly what the registry's rows list: every benched method at each of its settings
/// and nothing else. A setting added, dropped or changed in a row without the bench
/// rerun fails here, naming it.
#[test]
fn the_committed_bench_run_measured_every_setting_the_rows_list() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/bench/bench.json");
    let run: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    // A quick run measures only the settings the rows mark for it.
    let quick = run["quick"].as_bool().unwrap();
    // (method, its parameters as the run names them), the scene's own atlas cache size
    // left out: the bench adds it per scene.
    let mut measured: Vec<(String, Vec<(String, String)>)> = run["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|case| {
            let params = case["params"]
                .as_array()
                .unwrap()
                .iter()
                .map(|kv| {
                    (
                        kv[0].as_str().unwrap().into(),
                        kv[1].as_str().unwrap().into(),
                    )
                })
                .filter(|(k, _): &(String, String)| k != "cache_px_per_em")
                .collect();
            (case["method"].as_str().unwrap().to_owned(), params)
        })
        .collect();
    measured.sort();
    measured.dedup();
    let mut listed: Vec<(String, Vec<(String, String)>)> = std::iter::once(&registry::REFERENCE)
        .chain(registry::benched())
        .flat_map(|m| {
            let settings = if m.is_reference() {
                vec![Vec::new()]
            } else {
                method_settings::settings(m, !quick)
            };
            settings.into_iter().map(|p| (m.name.to_owned(), p))
        })
        .collect();
    listed.sort();
    for setting in &listed {
        assert!(
            measured.contains(setting),
            "{setting:?}: listed, but not in the committed run (rerun the bench)"
        );
    }
    for setting in &measured {
        assert!(
            listed.contains(setting),
            "{setting:?}: in the committed run, but no row lists it"
        );
    }
}

/// The stability sweep runs every drawing method and peer, each at settings it accepts.
#[test]
fn the_stability_sweep_runs_every_method_and_peer() {
    let swept: HashSet<&str> = claims::variants().iter().map(|v| v.method).collect();
    for m in registry::METHODS
        .iter()
        .filter(|m| matches!(m.role, Role::Method | Role::Peer))
    {
        assert!(
            swept.contains(m.name),
            "{}: not in the stability sweep",
            m.name
        );
    }
    for v in claims::variants() {
        let m = registry::find(v.method).unwrap();
        m.create(&v.params())
            .unwrap_or_else(|e| panic!("{}: {e}", v.label));
    }
}

/// The parameter table of a method's page, `docs/methods/NAME.md` (the section whose
/// heading starts `## Parameters`): each parameter's key, and the value the page marks
/// `` `X` (default``, if it marks one.
fn documented_parameters(method: &str) -> Vec<(String, Option<String>)> {
    let path = format!("{}/docs/methods/{method}.md", env!("CARGO_MANIFEST_DIR"));
    let page = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let Some((_, section)) = page.split_once("\n## Parameters") else {
        return Vec::new();
    };
    let section = section.split("\n## ").next().unwrap_or_default();
    section
        .lines()
        .filter_map(|line| {
            let mut cells = line.split('|').map(str::trim).skip(1);
            let key = cells.next()?.strip_prefix('`')?.strip_suffix('`')?;
            let default = cells.next().and_then(|values| {
                let (before, _) = values.split_once("` (default")?;
                Some(before.rsplit('`').next()?.to_owned())
            });
            Some((key.to_owned(), default))
        })
        .collect()
}

/// Each method takes exactly the parameters its page documents, and where the page
/// names a default, it is the row's (the first choice, which the app and the Pareto
/// sweep take as the default).
#[test]
fn every_method_takes_the_parameters_its_page_documents() {
    for m in registry::METHODS {
        let documented = documented_parameters(m.name);
        let mut keys: Vec<&str> = m.params.iter().map(|p| p.key).collect();
        let mut on_page: Vec<&str> = documented.iter().map(|(k, _)| k.as_str()).collect();
        keys.sort();
        on_page.sort();
        assert_eq!(keys, on_page, "{}: its rows and its page's table", m.name);
        for (key, default) in &documented {
            let row = m.params.iter().find(|p| p.key == key).unwrap();
            if let Some(default) = default {
                assert_eq!(row.choices[0], default, "{} {key}: the default", m.name);
            }
        }
    }
    // The table is read: a page with parameters gives keys and defaults.
    let winding = documented_parameters("winding");
    assert!(
        winding.contains(&("bands".into(), Some("auto".into()))),
        "{winding:?}"
    );
}

/// Every GPU method draws every scene as `render` does: finite coverage, ink where the
/// reference has ink, and — for each setting it claims a bound at — no pixel off by
/// more than the bound where the scene is inside the claim's scope.
#[test]
fn every_method_draws_every_scene_within_its_claims() {
    let gpu = common::gpu();
    for (what, view, traits) in scenes() {
        let (scene, camera) = view.build().unwrap();
        let reference =
            measure::measure(None, &scene, &camera, &registry::REFERENCE, &[], ONE_FRAME)
                .unwrap()
                .image;
        for m in registry::METHODS.iter().filter(|m| !m.is_reference()) {
            // (params, the bound claimed on this scene, label)
            type Setting<'a> = (Vec<(String, String)>, Option<f64>, &'a str);
            let mut settings: Vec<Setting> = m
                .claims
                .iter()
                .map(|c| {
                    let params = c
                        .params
                        .iter()
                        .map(|&(k, v)| (k.into(), v.into()))
                        .collect();
                    (params, c.claim.bound(traits).map(|b| b.max), c.label)
                })
                .collect();
            if !m.claims.iter().any(|c| c.params.is_empty()) {
                settings.push((Vec::new(), None, m.name));
            }
            for (params, bound, label) in settings {
                let drawn =
                    match measure::measure(Some(gpu), &scene, &camera, m, &params, ONE_FRAME) {
                        Ok(drawn) => drawn,
                        // A peer's documented limit, said in one line that names it.
                        Err(Error::Refused(reason)) if m.is_peer() => {
                            assert!(
                                reason.contains(m.name) && !reason.contains('\n'),
                                "{reason}"
                            );
                            continue;
                        }
                        Err(e) => panic!("{label} on {what}: {e}"),
                    };
                let image = &drawn.image;
                assert!(
                    image.data.iter().all(|v| v.is_finite()),
                    "{label} on {what}: non-finite coverage"
                );
                assert!(
                    image.sum() > 0.25 * reference.sum(),
                    "{label} on {what}: {} px of ink where the reference has {}",
                    image.sum(),
                    reference.sum()
                );
                let error = metrics::compare(image, &reference).unwrap();
                if let Some(bound) = bound {
                    assert!(
                        error.max <= bound,
                        "{label} on {what}: off by {} at {:?}, over its claim of {bound}",
                        error.max,
                        error.worst_pixel
                    );
                }
            }
        }
    }
}

/// Every overlay a method offers draws a picture, and every value its parameters offer
/// (the app builds its controls from them) is accepted.
#[test]
fn every_overlay_and_parameter_of_every_method_works() {
    let gpu = common::gpu();
    let (scene, camera) = ViewArgs::text("go", 48.0).build().unwrap();
    for m in registry::METHODS.iter().filter(|m| !m.is_reference()) {
        let offered = m.create(&[]).unwrap().overlays();
        for overlay in Overlay::ALL {
            let params = vec![("overlay".to_string(), overlay.name().to_string())];
            if !offered.contains(&overlay) {
                assert!(
                    m.create(&params).is_err(),
                    "{}: {} not offered",
                    m.name,
                    overlay.name()
                );
                continue;
            }
            let drawn = measure::measure(Some(gpu), &scene, &camera, m, &params, ONE_FRAME)
                .unwrap_or_else(|e| panic!("{} {}: {e}", m.name, overlay.name()));
            let picture = drawn.overlay.expect("an overlay is a picture");
            let lit = picture.pixels().filter(|p| p.0 != [0, 0, 0]).count();
            assert!(
                lit > 50,
                "{} {}: {lit} pixels drawn",
                m.name,
                overlay.name()
            );
        }
        for spec in m.params {
            let mut values: Vec<String> = spec.choices.iter().map(|v| v.to_string()).collect();
            match spec.numbers {
                Some(Numbers::Whole { min, max }) => {
                    values.extend([min, max].map(|n| n.to_string()))
                }
                Some(Numbers::Real { min, max, .. }) => values.extend(
                    [min, max]
                        .iter()
                        .filter(|x| x.is_finite())
                        .map(|x| x.to_string()),
                ),
                None => {}
            }
            for value in values {
                m.create(&[(spec.key.to_string(), value.clone())])
                    .unwrap_or_else(|e| panic!("{} {}={value}: {e}", m.name, spec.key));
            }
        }
    }
}

/// A name the registry does not hold is refused with the names it does, in one line.
#[test]
fn an_unknown_method_names_the_known_ones() {
    let error = registry::find("no-such-method").unwrap_err().to_string();
    assert!(!error.contains('\n'));
    for m in registry::METHODS {
        assert!(error.contains(m.name), "{error}");
    }
    let _: &MethodInfo = registry::find(registry::REFERENCE.name).unwrap();
}
