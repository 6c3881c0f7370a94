//! The numerical-stability suite at CI size: every hard case through every method at 4
//! sub-pixel offsets × 2 rotations against the reference, each method held to the bound
//! it claims (`glyphscope stability` runs the full sweep).

mod common;

use glyphscope::stability::{self, cases, claims, sweep};

#[test]
fn every_method_keeps_its_claims_on_every_hard_case() {
    let cases = cases::all();
    let size = sweep::SweepSize::quick();
    let variants = claims::variants();
    let outcomes = sweep::run(common::gpu(), &cases, &variants, &size, |_| {}).unwrap();
    println!("{}", stability::matrix_table(&outcomes));
    assert_eq!(outcomes.len(), cases.len() * variants.len());
    for o in &outcomes {
        let case = cases.iter().find(|c| c.name == o.case).unwrap();
        assert_eq!(
            o.frames,
            size.cameras_for(case),
            "{} × {}",
            o.case,
            o.variant
        );
        assert!(o.mae_255.is_finite(), "{} × {}", o.case, o.variant);
    }
    let broken = stability::broken_claims(&outcomes);
    assert!(broken.is_empty(), "claims broken:\n{}", broken.join("\n"));
}

/// The documented limitations are measured, not assumed: the estimate cracks along
/// overlaps, where exact distances stay within their looser limitation bound.
#[test]
fn limitations_show_their_numbers() {
    let cases = stability::select_cases(Some(&["overlapping-same-direction".into()])).unwrap();
    let variants = stability::select_variants(Some(&["sdf-cells".into()])).unwrap();
    assert_eq!(variants.len(), 2, "a method name picks all its variants");
    let outcomes = sweep::run(
        common::gpu(),
        &cases,
        &variants,
        &sweep::SweepSize::quick(),
        |_| {},
    )
    .unwrap();
    let estimate = &outcomes[0];
    assert_eq!(estimate.bound, None, "the estimate claims no bound");
    assert!(estimate.limitation);
    assert!(estimate.artifact_pixels > 100, "{estimate:?}");
    assert!(!estimate.breaks_claim());
    let exact = &outcomes[1];
    assert!(exact.limitation, "overlaps are exact mode's limitation");
    assert_eq!(exact.bound, Some(0.8));
    assert!(!exact.breaks_claim(), "{exact:?}");
}

#[test]
fn the_same_cameras_every_run_covering_the_grid() {
    let full = sweep::SweepSize::full();
    assert_eq!(full.offsets.len(), 16);
    assert_eq!(full.rotations_deg, [0.0, 1.0, 45.0, 89.9]);
    let quick = sweep::SweepSize::quick();
    // A case seen through a full turn gets every 30° (90° at CI size) besides.
    let sun = cases::by_name("sun-symbol").unwrap();
    assert_eq!(
        full.rotations_for(&sun),
        [
            0.0, 1.0, 30.0, 45.0, 60.0, 89.9, 90.0, 120.0, 150.0, 180.0, 210.0, 240.0, 270.0,
            300.0, 330.0
        ]
    );
    assert_eq!(quick.rotations_for(&sun), [0.0, 45.0, 90.0, 180.0, 270.0]);
    let square = cases::by_name("vertex-on-centre-row").unwrap();
    assert_eq!(full.rotations_for(&square), full.rotations_deg);
    assert_eq!(full.cameras_for(&sun), 16 * 15);
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
    let case = cases::by_name("vertex-on-centre-row").unwrap();
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
