//! The numerical-stability suite at CI size: every hard case through every method at 4
//! sub-pixel offsets × 2 rotations, and the cameras where the full sweep found each
//! method worst, against the reference, each method held to the bound it claims and
//! the peers observed (`glyphscope stability` runs the full sweep).

mod common;

use glam::DVec2;
use glyphscope::coverage::CoverageImage;
use glyphscope::effort::Effort;
use glyphscope::methods::info::MeanOver;
use glyphscope::methods::registry;
use glyphscope::metrics;
use glyphscope::reference;
use glyphscope::stability::{self, claims, hard_cases, outcome, sweep, worst_cameras};

#[test]
fn every_method_keeps_its_claims_on_every_hard_case() {
    let cases = hard_cases::all();
    let size = sweep::SweepSize::of(&Effort::QUICK);
    let variants = claims::variants();
    let outcomes = sweep::run(common::gpu(), &cases, &variants, &size, |_| {}).unwrap();
    println!("{}", stability::matrix_table(&outcomes));
    assert_eq!(outcomes.len(), cases.len() * variants.len());
    for o in &outcomes {
        let case = cases.iter().find(|c| c.name == o.case).unwrap();
        // Only an observed peer may refuse a view; it draws the others.
        let cameras = size.cameras_for(case).len();
        match &o.refused {
            Some(reason) => {
                assert!(o.observed, "{} × {} refused: {reason}", o.case, o.variant);
                assert!(o.frames < cameras, "{} × {}", o.case, o.variant);
            }
            None => assert_eq!(o.frames, cameras, "{} × {}", o.case, o.variant),
        }
        assert!(o.mae_255.is_finite(), "{} × {}", o.case, o.variant);
    }
    let broken = stability::broken_claims(&outcomes);
    assert!(broken.is_empty(), "claims broken:\n{}", broken.join("\n"));
    // The CI grid runs every listed camera among cameras of the full sweep's: on the
    // device the file was measured on, an error it does not account for means the full
    // sweep must be run again. Another device rounds differently: said, not checked.
    let device = common::gpu().adapter_name();
    if worst_cameras::device() != Some(device.as_str()) {
        println!(
            "data/worst-cameras.csv was measured on {:?}, not {device}: not compared",
            worst_cameras::device()
        );
        return;
    }
    let stale = worst_cameras::stale_entries(worst_cameras::all(), &outcomes);
    assert!(
        stale.is_empty(),
        "data/worst-cameras.csv is out of date (rerun `glyphscope stability --out DIR` \
         and copy DIR/worst-cameras.csv there):\n{}",
        stale.join("\n")
    );
}

/// The documented limitations are measured, not assumed: exact distances on detail under
/// a pixel stay within their looser limitation bound. Touching contours are inside both
/// claims — the estimate's since the winding number gives its side where a rule did (a
/// contour's corner on another's curved edge cracked it before) — and overlapping ones,
/// merged first, too.
#[test]
fn limitations_show_their_numbers() {
    let names = [
        "tip-on-arc",
        "touching-contours",
        "hole-touching-edge",
        "corners-touching-slanted",
        "thin-stem",
        "overlapping-same-direction",
        "figure-8",
    ];
    let cases = stability::select_cases(Some(&names.map(String::from))).unwrap();
    let variants = stability::select_variants(Some(&["sdf-cells".into()])).unwrap();
    assert_eq!(variants.len(), 2, "a method name picks all its variants");
    let outcomes = sweep::run(
        common::gpu(),
        &cases,
        &variants,
        &sweep::SweepSize::of(&Effort::QUICK),
        |_| {},
    )
    .unwrap();
    let find = |case: &str, variant: &str| {
        outcomes
            .iter()
            .find(|o| o.case == case && o.variant == variant)
            .unwrap_or_else(|| panic!("{case} × {variant} did not run"))
    };
    // The bounds each setting claims, as registered.
    let claim = |label: &str| {
        &glyphscope::methods::sdf_cells::INFO
            .claims
            .iter()
            .find(|setting| setting.label == label)
            .unwrap_or_else(|| panic!("{label} is not a claimed setting"))
            .claim
    };
    let claimed_max = |label: &str| claim(label).bound.map(|b| b.max);
    // Where the touching point is an end or a straight edge, the fills' wedges keep the
    // estimate within the bound it claimed elsewhere when they were written (0.65, set
    // before these cases existed; withdrawn when ordinary glyphs broke it); on a curved
    // edge (`tip-on-arc`) the winding number, where a rule gives the side, does. The full
    // sweep counted 455 pixels over 0.5 there over 64 frames with font-demo's rules
    // alone (`ties=merge`; `tests/sdf_cells.rs` draws that camera both ways); the CI
    // grid runs the worst camera of the sweep since.
    const WEDGES_BOUND: f64 = 0.65;
    let estimate = find("tip-on-arc", "sdf-cells");
    assert!(estimate.max <= WEDGES_BOUND, "{estimate:?}");
    assert!(!estimate.breaks_claim(), "{estimate:?}");
    for case in [
        "touching-contours",
        "hole-touching-edge",
        "corners-touching-slanted",
    ] {
        let touching = find(case, "sdf-cells");
        assert!(!touching.limitation && !touching.breaks_claim(), "{case}");
        assert!(touching.max <= WEDGES_BOUND, "{touching:?}");
        let exact = find(case, "sdf-cells exact");
        assert!(!exact.limitation && !exact.breaks_claim(), "{exact:?}");
    }
    let exact = find("thin-stem", "sdf-cells exact");
    assert!(
        exact.limitation,
        "detail under a pixel is exact mode's limitation"
    );
    assert_eq!(
        exact.bound.map(|b| b.max),
        claim("sdf-cells exact").limitation.map(|b| b.max)
    );
    assert!(!exact.breaks_claim(), "{exact:?}");
    for case in ["overlapping-same-direction", "figure-8"] {
        let merged = find(case, "sdf-cells exact");
        assert!(!merged.limitation, "{case} is claimed once merged");
        assert_eq!(merged.bound.map(|b| b.max), claimed_max("sdf-cells exact"));
        assert!(!merged.breaks_claim(), "{merged:?}");
        // Merged, the estimate reads them as it reads any glyph without overlaps.
        assert!(find(case, "sdf-cells").max <= WEDGES_BOUND, "{case}");
    }
}

#[test]
fn the_same_cameras_every_run_covering_the_grid() {
    let full = sweep::SweepSize::of(&Effort::FULL);
    assert_eq!(full.offsets.len(), 16);
    assert_eq!(full.rotations_deg, [0.0, 1.0, 45.0, 89.9]);
    let quick = sweep::SweepSize::of(&Effort::QUICK);
    // A case seen through a full turn gets every 30° (90° at CI size) besides.
    let sun = hard_cases::by_name("sun-symbol").unwrap();
    assert_eq!(
        full.rotations_for(&sun),
        [
            0.0, 1.0, 30.0, 45.0, 60.0, 89.9, 90.0, 120.0, 150.0, 180.0, 210.0, 240.0, 270.0,
            300.0, 330.0
        ]
    );
    assert_eq!(quick.rotations_for(&sun), [0.0, 45.0, 90.0, 180.0, 270.0]);
    let square = hard_cases::by_name("vertex-on-centre-row").unwrap();
    assert_eq!(full.rotations_for(&square), full.rotations_deg);
    assert_eq!(full.cameras_for(&sun).len(), 16 * 15);
    // One offset in each row and column of the 4×4 grid.
    for axis in [0, 1] {
        let mut seen: Vec<f64> = quick.offsets.iter().map(|o| o[axis]).collect();
        seen.sort_by(f64::total_cmp);
        assert_eq!(seen, [0.0, 0.25, 0.5, 0.75]);
    }
}

/// Synthetic cases keep their pixel-centre alignments at offset 0: a vertex at
/// y = 2.5 font units lands on a pixel-centre row.
#[test]
fn synthetic_cases_are_aligned_to_pixel_centres() {
    let case = hard_cases::by_name("vertex-on-centre-row").unwrap();
    let camera = case.camera(0.0, glam::DVec2::ZERO).unwrap();
    let to_image = camera.glyph_to_image(case.scene.units_per_em, glam::DVec2::ZERO);
    let vertex = glyphscope::geometry::project(&to_image, glam::DVec2::new(12.5, 2.5));
    assert_eq!(vertex.fract(), glam::DVec2::splat(0.5));
}

#[test]
fn unknown_names_are_input_errors() {
    for err in [
        stability::select_cases(Some(&["nope".into()])).unwrap_err(),
        stability::select_variants(Some(&["nope".into()])).unwrap_err(),
    ] {
        assert!(matches!(err, glyphscope::Error::Input(_)), "{err}");
        assert!(err.to_string().contains("'nope'"), "{err}");
    }
}

/// Each listed worst camera was found by the full sweep, so it is one of the full
/// sweep's cameras, on a case and a method variant that exist: a file written by hand,
/// or left behind by a renamed case or a changed grid, fails here. Most of them lie off
/// the CI grid's coarse cameras, which is why they are listed at all (the CI run's
/// stale check, on the device that wrote the file, is what shows it reruns them).
#[test]
fn every_worst_camera_is_one_the_full_sweep_runs() {
    let full = sweep::SweepSize::of(&Effort::FULL);
    let quick = sweep::SweepSize::of(&Effort::QUICK);
    let labels: Vec<&str> = claims::variants().iter().map(|v| v.label).collect();
    let mut off_grid = 0;
    for worst in worst_cameras::all() {
        let case = hard_cases::by_name(worst.case)
            .unwrap_or_else(|| panic!("a worst camera of no case: {worst:?}"));
        assert!(labels.contains(&worst.variant), "{worst:?}");
        let camera = (worst.rotation_deg, DVec2::from(worst.subpixel));
        assert!(full.cameras_for(&case).contains(&camera), "{worst:?}");
        let on_quick_grid =
            quick.rotations_for(&case).contains(&camera.0) && quick.offsets.contains(&camera.1);
        off_grid += usize::from(!on_quick_grid);
    }
    assert!(
        off_grid > 0,
        "every worst camera is on the coarse grid already"
    );
    // Every case where a method is off at all has its worst cameras listed.
    assert!(worst_cameras::all().len() > hard_cases::all().len());
}

/// What each claim is for: coverage rounded to 0 or 1 (a method that finds which side
/// of the edge a pixel centre lies on, and nothing more) is off by at most 0.5, so a
/// bound on the largest error alone lets it through; the bound on the mean error must
/// not. And a NaN anywhere breaks every claim on every case. Seen through the CI
/// grid's cameras, on the CPU: the reference itself, rounded, is the image.
#[test]
fn every_claim_rejects_coverage_rounded_to_0_or_1_and_nan() {
    let size = sweep::SweepSize::of(&Effort::QUICK);
    let variants = claims::variants();
    let mut broken_by_rounding = vec![0; variants.len()];
    for case in hard_cases::all() {
        let mut rounded: Vec<outcome::Outcome> = variants
            .iter()
            .map(|v| outcome::Outcome::new(&case, v))
            .collect();
        let mut with_nan = rounded.clone();
        // Four cameras a case (one per offset at the first rotation) are enough here.
        for &(rotation, offset) in size.cameras_for(&case).iter().take(4) {
            let camera = case.camera(rotation, offset).unwrap();
            let exact = reference::rasterize(&case.scene, &camera).unwrap();
            let round = CoverageImage {
                data: exact.data.iter().map(|v| v.round()).collect(),
                ..exact.clone()
            };
            let mut nan = exact.clone();
            nan.data[0] = f32::NAN;
            for (outcome, image) in [(&mut rounded, round), (&mut with_nan, nan)] {
                let stats = metrics::compare(&image, &exact).unwrap();
                assert!(stats.max <= 0.5 || stats.max.is_infinite(), "{stats:?}");
                for o in outcome.iter_mut() {
                    o.add_frame(&stats, (rotation, offset), image.clone(), &exact);
                }
            }
        }
        for (k, o) in rounded.into_iter().enumerate() {
            broken_by_rounding[k] += usize::from(o.finish().breaks_claim());
        }
        for o in with_nan {
            let o = o.finish();
            assert!(
                o.bound.is_none() || o.breaks_claim(),
                "{} × {}: NaN kept the claim",
                o.case,
                o.variant
            );
        }
    }
    for (variant, broken) in variants.iter().zip(&broken_by_rounding) {
        // A peer is observed, and so is a setting that claims nothing (its statement
        // says so: `every_method_claims_a_bound_where_it_is_meant_to_work`): nothing
        // can break. A claim on the maximum alone (sdf-cells' estimate: one distance per
        // pixel reads a hairline up to 0.5 off, as rounding does) is kept by rounding,
        // and says so.
        let claims_nothing = variant.claim.bound.is_none() && variant.claim.limitation.is_none();
        let max_only = [variant.claim.bound, variant.claim.limitation]
            .into_iter()
            .flatten()
            .all(|b| b.over == MeanOver::Unbounded);
        if max_only && !claims_nothing {
            assert!(
                variant.claim.statement.contains("mean is not"),
                "{}: a claim on the maximum alone does not say so",
                variant.label
            );
            continue;
        }
        if registry::find(variant.method).is_ok_and(|m| m.is_peer()) || claims_nothing {
            assert_eq!(
                *broken, 0,
                "{}: an observed row broke a claim",
                variant.label
            );
            continue;
        }
        println!(
            "{}: rounded coverage breaks it on {broken} cases",
            variant.label
        );
        assert!(
            *broken > 0,
            "{}: rounded coverage keeps the claim",
            variant.label
        );
    }
}

/// Every one of glyphscope's methods bounds its error on ordinary text in some claimed
/// setting, and a bound on the maximum comes with one on the mean or says that it does
/// not (`sdf-cells`' estimate); a setting that claims nothing says so in its statement.
/// A peer claims nothing anywhere.
#[test]
fn every_method_claims_a_bound_where_it_is_meant_to_work() {
    let ordinary = hard_cases::by_name("latin-modern-cubics").unwrap();
    let mut bounded: Vec<&str> = Vec::new();
    let mut methods: Vec<&str> = Vec::new();
    for variant in claims::variants() {
        if registry::find(variant.method).is_ok_and(|m| m.is_peer()) {
            assert_eq!(variant.claim.bound, None, "{}", variant.label);
            assert_eq!(variant.claim.limitation, None, "{}", variant.label);
            continue;
        }
        methods.push(variant.method);
        match variant.claim.bound(ordinary.traits) {
            Some(bound) => {
                let mean_bounded = bound.mae_255 > 0.0
                    || (bound.over == MeanOver::Unbounded
                        && variant.claim.statement.contains("mean is not"));
                assert!(bound.max < 1.0 && mean_bounded, "{}", variant.label);
                bounded.push(variant.method);
            }
            None => assert!(
                variant.claim.statement.contains("no bound"),
                "{} claims nothing and does not say so",
                variant.label
            ),
        }
    }
    for method in methods {
        assert!(
            bounded.contains(&method),
            "{method} claims nothing in any setting"
        );
    }
}

/// The hard cases in motion, every method through the drift, each held to its temporal
/// claim where it makes one (winding's default), the others shown.
#[test]
fn every_temporal_claim_holds_on_every_hard_case() {
    let cases = hard_cases::all();
    let variants = claims::variants();
    let frames = Effort::QUICK.stability_motion_frames;
    let outcomes =
        stability::temporal::run(common::gpu(), &cases, &variants, frames, |_| {}).unwrap();
    println!("{}", stability::temporal::table(&outcomes, frames));
    assert_eq!(outcomes.len(), cases.len() * variants.len());
    for o in &outcomes {
        assert!(
            o.failure.is_none(),
            "{} × {}: {:?}",
            o.case,
            o.variant,
            o.failure
        );
        if o.refused.is_none() {
            assert_eq!(o.pairs, frames - 1, "{} × {}", o.case, o.variant);
            assert!(
                o.mae_255.is_finite() && o.max.is_finite(),
                "{} × {}",
                o.case,
                o.variant
            );
        }
    }
    assert!(
        outcomes.iter().any(|o| o.bound.is_some()),
        "no temporal claim was checked"
    );
    let broken = stability::temporal::broken_claims(&outcomes);
    assert!(
        broken.is_empty(),
        "temporal claims broken:\n{}",
        broken.join("\n")
    );
}

/// A temporal claim can fail: the reference rounded to 0 or 1 frame by frame (a method
/// that snaps each pixel) breaks winding's on a drifting case, as NaN does.
#[test]
fn a_temporal_claim_rejects_snapping_and_nan() {
    let case = hard_cases::by_name("latin-modern-cubics").unwrap();
    let variant = claims::variants()
        .into_iter()
        .find(|v| v.claim.temporal.is_some())
        .expect("a method claims a temporal bound");
    let bound = variant.claim.temporal.unwrap();
    let path = glyphscope::motion::MotionPath::parse(stability::temporal::PATH).unwrap();
    let base = case.camera(0.0, DVec2::ZERO).unwrap();
    let frames: Vec<CoverageImage> = (0..4)
        .map(|n| reference::rasterize(&case.scene, &path.camera_at(&base, n)).unwrap())
        .collect();
    let snap = |image: &CoverageImage| CoverageImage {
        data: image.data.iter().map(|v| v.round()).collect(),
        ..image.clone()
    };
    let mut snapped_breaks = false;
    for pair in frames.windows(2) {
        let t =
            metrics::temporal([&snap(&pair[0]), &snap(&pair[1])], [&pair[0], &pair[1]]).unwrap();
        snapped_breaks |= !bound.holds(t.max, t.mae_255, t.edge.mae_255);
        let mut nan = pair[1].clone();
        nan.data[0] = f32::NAN;
        let t = metrics::temporal([&pair[0], &nan], [&pair[0], &pair[1]]).unwrap();
        assert!(
            !bound.holds(t.max, t.mae_255, t.edge.mae_255),
            "NaN kept the temporal claim"
        );
    }
    assert!(snapped_breaks, "snapped coverage kept the temporal claim");
}
