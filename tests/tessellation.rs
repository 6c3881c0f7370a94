//! Method `tessellation`: the subdivision of Jeff Boody's Glyph reproduced on Glyph's
//! own data and on DejaVu Sans 'g'; the tag state machine against every outline; lyon's
//! nonzero triangles; and the GPU images against the reference from 8 to 20 000 px/em.
//!
//! Run with `--nocapture` for the tables docs/methods/tessellation.md quotes. The GPU tests need an
//! adapter and fail without one (CI installs lavapipe).

mod common;

use common::*;
use glam::DVec2;
use glyphscope::camera::Camera;
use glyphscope::coverage::CoverageImage;
use glyphscope::font::SHIPPED_FONTS;
use glyphscope::geometry::{Contour, Outline, Segment, project};
use glyphscope::gpu::{Channels, CoverageTarget};
use glyphscope::methods::frame::render_frame;
use glyphscope::methods::tessellation::mesh::GlyphMesh;
use glyphscope::methods::tessellation::subdivision::{
    self, PointKind, Subdivision, Tag, TaggedContour,
};
use glyphscope::methods::{MeshStats, Method, registry};
use glyphscope::metrics::{ErrorStats, compare};
use glyphscope::render::{RenderOptions, render};
use glyphscope::scene::Scene;
use glyphscope::view_args::ViewArgs;
use glyphscope::{Error, reference};

fn params(pairs: &[(&str, &str)]) -> Vec<(String, String)> {
    pairs
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

fn tessellation(pairs: &[(&str, &str)]) -> Box<dyn Method> {
    registry::create("tessellation", &params(pairs)).unwrap()
}

fn coverage(pairs: &[(&str, &str)], scene: &Scene, camera: &Camera) -> CoverageImage {
    common::render(tessellation(pairs).as_mut(), scene, camera)
}

/// Glyph's table (resource/adaptive-subdivision.dat): points and summed area error
/// for ASA thresholds 1 to 20 on its Barlow 'g'.
const GLYPH_TABLE_ASA: [(usize, f64); 20] = [
    (229, 1.586691),
    (189, 2.728835),
    (152, 5.162377),
    (133, 6.874214),
    (119, 8.624592),
    (98, 12.094425),
    (98, 12.094425),
    (97, 12.677692),
    (97, 12.677692),
    (91, 14.938252),
    (84, 18.198093),
    (80, 19.882648),
    (80, 19.882648),
    (79, 20.880497),
    (79, 20.880497),
    (71, 25.599403),
    (71, 25.599403),
    (70, 26.946999),
    (64, 32.600826),
    (64, 32.600826),
];

/// Glyph's own 'g', as points and tags (tests/data/barlow-g.txt).
fn barlow_g() -> Vec<TaggedContour> {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/barlow-g.txt"),
    )
    .unwrap();
    let mut contours = vec![TaggedContour::default()];
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields[..] {
            [] => contours.push(TaggedContour::default()),
            [x, y, tag] => contours.last_mut().unwrap().push(
                DVec2::new(x.parse().unwrap(), y.parse().unwrap()),
                if tag == "1" { Tag::On } else { Tag::Conic },
            ),
            _ => panic!("bad line {line:?}"),
        }
    }
    contours.retain(|c| !c.points.is_empty());
    contours
}

#[test]
fn reproduces_glyphs_table_on_its_own_g() {
    let g = barlow_g();
    // "Prior to contour decomposition the 'g' glyph contained 59 points."
    assert_eq!(g.iter().map(|c| c.points.len()).sum::<usize>(), 59);
    // Its data is normalised to a height of 1000 already.
    let cut = |mode| subdivision::subdivide(&g, mode, subdivision::GLYPH_TABLE_HEIGHT);
    assert_eq!(cut(Subdivision::Fixed(16)).points(), 517);
    assert_eq!(cut(Subdivision::Fixed(3)).points(), 101);
    // Threshold 0 is Glyph's FSA-16: no curve is ever under it.
    assert_eq!(cut(Subdivision::Adaptive(0.0)).points(), 517);
    eprintln!("| ASA threshold | points (Glyph) | area error (Glyph) |");
    for (threshold, &(points, error)) in (1..).zip(&GLYPH_TABLE_ASA) {
        let ours = cut(Subdivision::Adaptive(f64::from(threshold)));
        let our_error = ours.area_error.unwrap();
        eprintln!(
            "| {threshold} | {} ({points}) | {our_error:.4} ({error:.4}) |",
            ours.points()
        );
        assert_eq!(ours.points(), points, "threshold {threshold}");
        // Glyph computed in f32.
        assert!(
            (our_error - error).abs() < 5e-4 * error,
            "threshold {threshold}: error {our_error} vs Glyph's {error}"
        );
    }
}

#[test]
fn dejavu_g_trade_off_is_monotone() {
    let font = glyphscope::font::default_font();
    let outline = font.outline(font.glyph_for_char('g').unwrap());
    let g = TaggedContour::from_outline(&outline);
    let height = font.units_per_em() / subdivision::GLYPH_TABLE_EM_PER_HEIGHT;
    let cut = |mode| {
        let p = subdivision::subdivide(&g, mode, height);
        (p.points(), p.area_error.unwrap())
    };
    let fixed: Vec<(usize, f64)> = (1..=16).map(|n| cut(Subdivision::Fixed(n))).collect();
    let adaptive: Vec<(usize, f64)> = (1..=20)
        .map(|t| cut(Subdivision::Adaptive(f64::from(t))))
        .collect();
    eprintln!(
        "DejaVu Sans 'g': {} points and tags before decomposition",
        g.iter().map(|c| c.points.len()).sum::<usize>()
    );
    eprintln!("| FSA steps | points | area error |");
    for (n, (points, error)) in (1..).zip(&fixed) {
        eprintln!("| {n} | {points} | {error:.3} |");
    }
    eprintln!("| ASA threshold | points | area error |");
    for (t, (points, error)) in (1..).zip(&adaptive) {
        eprintln!("| {t} | {points} | {error:.3} |");
    }
    // More steps: more points, less error, none at Glyph's best.
    assert!(fixed.windows(2).all(|w| w[1].0 > w[0].0 && w[1].1 < w[0].1));
    assert_eq!(fixed[15].1, 0.0);
    // A higher threshold: never more points, never less error — and it does trade.
    assert!(
        adaptive
            .windows(2)
            .all(|w| w[1].0 <= w[0].0 && w[1].1 >= w[0].1)
    );
    assert!(adaptive[19].0 < adaptive[0].0 && adaptive[19].1 > adaptive[0].1);
    // Every ASA polyline lies between FSA-1 and FSA-16 in points, and each error is
    // under threshold/10 per curve.
    let curves: usize = g.iter().map(|c| c.curves().len()).sum();
    for (t, &(points, error)) in (1..).zip(&adaptive) {
        assert!(fixed[0].0 < points && points < fixed[15].0, "threshold {t}");
        assert!(error < f64::from(t) / 10.0 * curves as f64, "threshold {t}");
    }
}

/// Whether two closed sequences of segments are the same up to where they start.
fn same_cycle(a: &[Segment], b: &[Segment]) -> bool {
    a.len() == b.len()
        && (0..a.len().max(1)).any(|k| a.iter().cycle().skip(k).zip(b).all(|(x, y)| x == y))
}

#[test]
fn the_tag_state_machine_rebuilds_every_outline() {
    let (mut virtual_points, mut glyphs) = (0, 0);
    for (index, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        for id in 0..font.glyph_count() {
            for contour in &font.outline(id).contours {
                let tagged = TaggedContour::from_contour(contour);
                let curves = tagged.curves();
                let rebuilt: Vec<Segment> = curves.iter().map(|c| c.segment).collect();
                assert!(
                    same_cycle(&rebuilt, &contour.segments),
                    "{name} glyph {id}: {rebuilt:?} vs {:?}",
                    contour.segments
                );
                virtual_points += curves
                    .iter()
                    .filter(|c| c.end == PointKind::Virtual)
                    .count();
            }
            glyphs += 1;
        }
    }
    eprintln!("{glyphs} glyphs rebuilt, {virtual_points} virtual points among them");
    assert!(
        virtual_points > 10_000,
        "TrueType fonts imply on-curve points"
    );
}

#[test]
fn lyon_triangles_cover_the_nonzero_area_of_every_glyph() {
    // Each glyph's polylines as an outline of lines: the reference fills that polygon
    // exactly, so its covered area is the nonzero area the triangles must have.
    let mut checked = 0;
    for (index, (name, _, _)) in SHIPPED_FONTS.iter().enumerate() {
        let font = glyphscope::font::shipped(index);
        let height = font.units_per_em() / subdivision::GLYPH_TABLE_EM_PER_HEIGHT;
        let snap = (font.units_per_em() / f64::from(1 << 21)) as f32;
        for id in 0..font.glyph_count() {
            let outline = font.outline(id);
            let tagged = TaggedContour::from_outline(&outline);
            let polylines = subdivision::subdivide(&tagged, Subdivision::Fixed(4), height);
            let mesh = GlyphMesh::tessellate(&polylines, snap)
                .unwrap_or_else(|e| panic!("{name} glyph {id}: {e:?}"));
            // The exact comparison costs a reference rasterization: every 25th glyph.
            if id % 25 != 0 || outline.is_empty() {
                continue;
            }
            let polygon = Outline {
                contours: polylines
                    .contours
                    .iter()
                    .map(|c| polygon(&c.iter().map(|(p, _)| (p.x, p.y)).collect::<Vec<_>>()))
                    .collect(),
            };
            // One pixel per 8 font units: small images, and the reference is exact at any
            // resolution.
            let scene = Scene::from_outlines(font.units_per_em(), vec![(polygon, DVec2::ZERO)]);
            let bounds = scene.glyphs[0].bounds;
            let camera = Camera::new(
                (bounds.size().x / 8.0).ceil() as u32 + 2,
                (bounds.size().y / 8.0).ceil() as u32 + 2,
                font.units_per_em() / 8.0,
                DVec2::new(1.0 - bounds.min.x / 8.0, 1.0 + bounds.max.y / 8.0),
            );
            let area = reference::rasterize(&scene, &camera).unwrap().sum() * 64.0;
            assert!(
                (mesh.area() - area).abs() <= 1e-5 * area + 1e-3,
                "{name} glyph {id}: triangles {} vs nonzero area {area}",
                mesh.area()
            );
            checked += 1;
        }
    }
    assert!(checked > 350, "{checked}");
}

/// Texts that bring out each shipped font's hard cases (quadratics, cubics, overlapping
/// contours, conjuncts).
const TEXTS: [(usize, &str); 4] = [
    (0, "g&@"),
    (1, "Qa§"),
    (2, "Bé4"),
    (3, "\u{0995}\u{09CD}\u{09B7}"),
];
const SIZES: [f64; 5] = [8.0, 16.0, 48.0, 400.0, 20_000.0];
/// Window side for the sizes whose text would not fit an image, pixels.
const WINDOW: u32 = 160;

/// The views a size is checked in: rotated, skewed or upright by size, each at two
/// sub-pixel offsets. Up to 48 px/em the whole text; above, a window onto the first
/// glyph's outline.
fn views(scene: &Scene, size: f64, k: usize) -> Vec<Camera> {
    let (s30, c30) = 30f64.to_radians().sin_cos();
    let matrices = [
        [c30, -s30, s30, c30],
        [1.0, 0.35, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
    ];
    let [a, b, c, d] = matrices[k % matrices.len()];
    [DVec2::new(0.37, 0.61), DVec2::new(0.81, 0.13)]
        .into_iter()
        .map(|subpixel| {
            let mut camera = Camera::new(WINDOW, WINDOW, size, DVec2::ZERO);
            camera.matrix = Camera::matrix_from_rows(a, b, c, d);
            let first = scene.instances[0];
            let to_image = camera.glyph_to_image(scene.units_per_em, first.position);
            if size <= 48.0 {
                let ink = scene
                    .instances
                    .iter()
                    .map(|i| {
                        let m = camera.glyph_to_image(scene.units_per_em, i.position);
                        Camera::project_bounds(&m, &scene.glyphs[i.glyph as usize].bounds).unwrap()
                    })
                    .reduce(|a, b| a.union(b))
                    .unwrap();
                camera.origin = DVec2::splat(2.0) - ink.min + subpixel;
                camera.width = (ink.size().x + 5.0).ceil() as u32;
                camera.height = (ink.size().y + 5.0).ceil() as u32;
            } else {
                // Centred on an outline point a third of the way round the first contour.
                let contour = &scene.glyphs[first.glyph as usize].outline.contours[0];
                let focus = contour.segments[contour.segments.len() / 3].end();
                let centre = DVec2::splat(f64::from(WINDOW) / 2.0);
                camera.origin = centre - project(&to_image, focus) + subpixel;
            }
            camera
        })
        .collect()
}

/// Worst error over `views`, MAE averaged.
fn error_over(
    pairs: &[(&str, &str)],
    scene: &Scene,
    views: &[(Camera, CoverageImage)],
) -> ErrorStats {
    let mut worst = ErrorStats::default();
    for (camera, expected) in views {
        let e = compare(&coverage(pairs, scene, camera), expected).unwrap();
        worst.mae_255 += e.mae_255 / views.len() as f64;
        worst.pixels_over_05 += e.pixels_over_05;
        if e.max > worst.max {
            worst.max = e.max;
        }
    }
    worst
}

#[test]
fn screen_space_mode_is_within_half_a_pixel_from_8_to_20000_px_per_em() {
    const MODES: [&[(&str, &str)]; 3] = [
        &[("subdivision", "screen")],
        &[("subdivision", "asa"), ("threshold", "3")],
        &[("subdivision", "fsa"), ("steps", "16")],
    ];
    eprintln!("| font | px/em | mode | msaa | MAE /255 | max | pixels > 0.5 |");
    let mut facets_at_20000 = 0;
    for (font_index, text) in TEXTS {
        let font = glyphscope::font::shipped(font_index);
        let scene = Scene::from_text(&font, text).unwrap();
        for (k, size) in SIZES.into_iter().enumerate() {
            let views: Vec<(Camera, CoverageImage)> = views(&scene, size, k)
                .into_iter()
                .map(|c| (c, reference::rasterize(&scene, &c).unwrap()))
                .collect();
            for mode in MODES {
                let mut by_samples = Vec::new();
                for msaa in ["4", "1"] {
                    let mut pairs = mode.to_vec();
                    pairs.push(("msaa", msaa));
                    let e = error_over(&pairs, &scene, &views);
                    let label: Vec<String> = mode.iter().map(|(k, v)| format!("{k}={v}")).collect();
                    eprintln!(
                        "| {} | {size} | {} | {msaa} | {:.2} | {:.3} | {} |",
                        SHIPPED_FONTS[font_index].0,
                        label.join(" "),
                        e.mae_255,
                        e.max,
                        e.pixels_over_05
                    );
                    by_samples.push(e);
                }
                let what = format!(
                    "{} {text:?} at {size} px/em, {mode:?}",
                    SHIPPED_FONTS[font_index].0
                );
                if mode[0].1 == "screen" {
                    assert!(
                        by_samples[0].max <= 0.5,
                        "{what}: max error {}",
                        by_samples[0].max
                    );
                    // Four samples a pixel are a real anti-aliasing, not one sample four
                    // times (where facets do not dominate the error).
                    assert!(
                        by_samples[0].mae_255 < 0.6 * by_samples[1].mae_255,
                        "{what}: msaa=4 hardly better than 1"
                    );
                }
                if size == 20_000.0 && mode[0].1 == "fsa" {
                    facets_at_20000 += by_samples[0].pixels_over_05;
                }
            }
        }
    }
    // Glyph's fixed subdivision shows its facets under zoom: the reason for the
    // screen-space mode.
    assert!(
        facets_at_20000 > 100,
        "{facets_at_20000} pixels over 0.5 for FSA-16"
    );
}

#[test]
fn a_page_of_repeated_glyphs_matches_the_reference() {
    // Many instances of few glyphs: one draw per distinct glyph, instances culled to the
    // view, and tilted so that instances fall into different scale buckets.
    let text: String = glyphscope::bench::scenes::PAGE_TEXT
        .lines()
        .take(4)
        .collect::<Vec<_>>()
        .join("\n");
    let scene = Scene::from_text(&glyphscope::font::default_font(), &text).unwrap();
    let mut camera = Camera::new(700, 90, 16.0, DVec2::new(-3.3, 20.6));
    camera.tilt_deg = 35.0;
    let expected = reference::rasterize(&scene, &camera).unwrap();
    let mut method = tessellation(&[]);
    let actual = common::render(method.as_mut(), &scene, &camera);
    let e = compare(&actual, &expected).unwrap();
    eprintln!("page, tilted 35°: {e:?}");
    assert!(e.max <= 0.5 && e.mae_255 < 8.0, "{e:?}");
    let stats = method.mesh_stats().unwrap();
    let buckets: std::collections::BTreeSet<_> =
        stats.glyphs.iter().map(|g| g.scale_bucket).collect();
    assert!(
        buckets.len() >= 2,
        "the tilt spans one scale bucket only: {buckets:?}"
    );
}

#[test]
fn far_world_offset_changes_nothing() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "Sg").unwrap();
    let mut camera = Camera::new(64, 48, 30.0, DVec2::new(3.4, 36.2));
    camera.matrix = Camera::matrix_from_rows(0.9, -0.3, 0.4, 1.1);
    let near = coverage(&[], &scene, &camera);
    camera.world_offset = DVec2::new(1e5, -1e5);
    let far = coverage(&[], &scene, &camera);
    assert_eq!(near.data, far.data);
}

#[test]
fn overlaps_and_self_intersections_fill_by_the_nonzero_rule() {
    // Pixel-aligned squares: 4x MSAA is exact on them, so any error is a fill-rule error.
    // Two overlapping the same way (even-odd would empty the overlap), a third with a
    // hole wound the other way, and a pentagram whose centre has winding 2.
    let star: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let angle =
                std::f64::consts::FRAC_PI_2 + f64::from(k * 2) * std::f64::consts::TAU / 5.0;
            (80.0 + 14.0 * angle.cos(), 16.0 + 14.0 * angle.sin())
        })
        .collect();
    let contours: [&[(f64, f64)]; 5] = [
        &rect(2.0, 2.0, 22.0, 22.0),
        &rect(12.0, 12.0, 32.0, 30.0),
        &rect(40.0, 2.0, 60.0, 30.0),
        &[(45.0, 7.0), (45.0, 25.0), (55.0, 25.0), (55.0, 7.0)],
        &star,
    ];
    let scene = single(polygons(&contours));
    let camera = unit_camera(100, 32);
    let expected = reference::rasterize(&scene, &camera).unwrap();
    let actual = coverage(&[], &scene, &camera);
    let squares = |image: &CoverageImage| -> Vec<f32> {
        (0..32)
            .flat_map(|y| (0..62).map(move |x| (x, y)))
            .map(|(x, y)| image.get(x, y))
            .collect()
    };
    assert_eq!(squares(&actual), squares(&expected), "squares differ");
    // The star's centre pixel is inside its inner pentagon.
    assert_eq!(actual.get(80, 16), 1.0);
    let e = compare(&actual, &expected).unwrap();
    assert!(e.max <= 0.5, "{e:?}");
}

#[test]
fn screen_space_meshes_are_rebuilt_only_across_scale_buckets() {
    let gpu = gpu();
    let scene = Scene::from_text(&glyphscope::font::default_font(), "agag").unwrap();
    let mut method = tessellation(&[]);
    method.prepare(gpu, &scene).unwrap();
    assert_eq!(
        method.mesh_stats().unwrap().glyphs.len(),
        0,
        "nothing is known of the scale yet"
    );
    let target = CoverageTarget::new(gpu, 200, 60, Channels::Coverage).unwrap();
    let mut frame = |size: f64| -> MeshStats {
        let camera = Camera::new(200, 60, size, DVec2::new(2.0, 45.0));
        render_frame(gpu, method.as_mut(), &target, &camera).unwrap();
        method.mesh_stats().unwrap()
    };
    // DejaVu has 2048 units per em: 17 to 32 px/em all lie in the bucket 2⁻⁶ px/unit.
    let first = frame(17.0);
    assert_eq!(first.glyphs.len(), 2);
    assert!(first.glyphs.iter().all(|g| g.scale_bucket == Some(-6)));
    for size in [20.0, 25.5, 32.0] {
        assert_eq!(frame(size), first, "{size} px/em rebuilt a mesh");
    }
    let finer = frame(33.0);
    assert_eq!(finer.glyphs.len(), 4, "both buckets kept a while");
    assert!(
        finer.points > 2 * first.points,
        "{} vs {}",
        finer.points,
        first.points
    );
    for _ in 0..130 {
        frame(40.0);
    }
    // Zooming on past another bucket drops what no frame has used for a while.
    let later = frame(70.0);
    let buckets: Vec<_> = later
        .glyphs
        .iter()
        .map(|g| g.scale_bucket.unwrap())
        .collect();
    assert_eq!(buckets, [-5, -4, -5, -4], "{later:?}");
}

#[test]
fn overlays_draw_over_unchanged_coverage() {
    let scene = Scene::from_text(&glyphscope::font::default_font(), "g").unwrap();
    let camera = Camera::new(90, 110, 100.0, DVec2::new(8.0, 78.0));
    let plain = coverage(&[("subdivision", "asa")], &scene, &camera);
    type Colour = fn(&[u8; 3]) -> bool;
    let orange: Colour = |&[r, g, b]| r > 200 && (100..180).contains(&g) && b < 60;
    let yellow: Colour = |&[r, g, b]| r > 200 && g > 180 && b < 100;
    let magenta: Colour = |&[r, g, b]| r > 200 && g < 120 && b > 180;
    let blue: Colour = |&[r, g, b]| r < 100 && g > 150 && b > 200;
    // Edges orange; outline points yellow, virtual midpoints magenta, steps blue.
    for (overlay, colours) in [
        ("wireframe", vec![orange]),
        ("points", vec![yellow, magenta, blue]),
    ] {
        let mut method = tessellation(&[("subdivision", "asa"), ("overlay", overlay)]);
        let (coverage, picture) = render_with_picture(method.as_mut(), &scene, &camera);
        assert_eq!(coverage.data, plain.data, "{overlay} changed coverage");
        for (k, colour) in colours.into_iter().enumerate() {
            let count = picture.pixels().filter(|p| colour(&p.0)).count();
            assert!(count > 10, "{overlay}: {count} pixels of colour {k}");
        }
    }
}

#[test]
fn the_command_line_reports_points_triangles_and_area_error() {
    let args = |pairs: &[&str]| RenderOptions {
        method: "tessellation".into(),
        params: pairs
            .chunks(2)
            .map(|kv| (kv[0].to_string(), kv[1].to_string()))
            .collect(),
        ..RenderOptions::of(ViewArgs::text("gg", 24.0))
    };
    // A mode's own parameter picks the mode.
    let asa = render(&args(&["threshold", "13"])).unwrap();
    let mesh = asa.stats.mesh.as_ref().unwrap();
    assert_eq!(mesh.glyphs.len(), 1, "two instances, one distinct glyph");
    let g = &mesh.glyphs[0];
    assert_eq!((g.points, g.scale_bucket), (83, None));
    assert!(g.triangles > 0 && g.area_error.unwrap() > 0.0);
    let json = serde_json::to_value(&asa.stats).unwrap();
    assert!(json["mesh"]["cpu_build_ms"].as_f64().unwrap() > 0.0);
    let screen = render(&args(&[])).unwrap().stats.mesh.unwrap();
    assert_eq!(screen.glyphs[0].area_error, None);
    assert_eq!(screen.glyphs[0].scale_bucket, Some(-6));
}

#[test]
fn bad_parameters_are_input_errors() {
    for (pairs, expect) in [
        (&[("rays", "2")][..], "has no parameter 'rays'"),
        (&[("subdivision", "magic")], "must be screen, asa or fsa"),
        (&[("subdivision", "fsa"), ("steps", "0")], "steps must be"),
        (&[("subdivision", "fsa"), ("steps", "2.5")], "steps must be"),
        (
            &[("subdivision", "fsa"), ("steps", "100000")],
            "steps must be",
        ),
        (
            &[("subdivision", "asa"), ("threshold", "-1")],
            "threshold must be",
        ),
        (
            &[("subdivision", "asa"), ("threshold", "nan")],
            "threshold must be",
        ),
        (&[("tolerance_px", "0")], "tolerance_px must be"),
        (&[("tolerance_px", "abc")], "tolerance_px must be"),
        (&[("msaa", "8")], "msaa must be 1 or 4"),
        (
            &[("subdivision", "asa"), ("steps", "4")],
            "steps applies to subdivision=fsa, not to subdivision=asa",
        ),
        (
            &[("steps", "4"), ("threshold", "4")],
            "threshold applies to subdivision=asa, not to subdivision=fsa (implied by steps)",
        ),
        (
            &[("overlay", "cells")],
            "overlay must be none, wireframe or points",
        ),
    ] {
        match registry::create("tessellation", &params(pairs)) {
            Err(Error::Input(message)) => {
                assert!(message.contains(expect), "{pairs:?}: {message}");
                assert!(!message.contains('\n'));
            }
            Err(e) => panic!("{pairs:?}: not an input error: {e}"),
            Ok(_) => panic!("{pairs:?} accepted"),
        }
    }
}

#[test]
fn degenerate_contours_draw_nothing_and_do_not_fail() {
    // A contour of one point, a line there and back, and an empty outline next to a
    // real square.
    let p = DVec2::new(5.0, 5.0);
    let q = DVec2::new(15.0, 5.0);
    let mut outline = polygons(&[&rect(20.0, 2.0, 30.0, 12.0)]);
    outline.contours.push(Contour {
        segments: vec![Segment::Line(p, p)],
    });
    outline.contours.push(Contour {
        segments: vec![Segment::Line(p, q), Segment::Line(q, p)],
    });
    let scene = single(outline);
    let camera = unit_camera(40, 16);
    let image = coverage(&[("subdivision", "fsa"), ("steps", "3")], &scene, &camera);
    assert_eq!(image.sum(), 100.0);
}

/// DejaVu Sans's 𐌔 (U+10314), its ten points as the font has them: a zigzag whose
/// concave notch on the left (tip at (500, 750)) lies between vertices that pair up at
/// y = 400, 750 and 1100. lyon's sweep along y filled the triangle (404, 400),
/// (500, 750), (404, 1100) across the notch (max error 1.0 at 24 and 48 px). Worked by
/// hand from the points: every triangle's centre inside the zigzag, and the triangles'
/// areas adding up to the polygon's, 356 300 units² by the shoelace formula.
#[test]
fn a_notch_between_vertices_at_equal_heights_is_not_filled() {
    let points = [
        (404.0, 1100.0),
        (754.0, 750.0),
        (404.0, 400.0),
        (691.0, 114.0),
        (563.0, -14.0),
        (150.0, 400.0),
        (500.0, 750.0),
        (150.0, 1100.0),
        (563.0, 1514.0),
        (691.0, 1386.0),
    ];
    let mut contour = TaggedContour::default();
    for (x, y) in points {
        contour.push(DVec2::new(x, y), Tag::On);
    }
    let (_, mesh) =
        glyphscope::methods::tessellation::glyph_mesh(&[contour], 2048.0, Subdivision::Fixed(4))
            .unwrap();
    let vertex = |i: u32| {
        let [x, y] = mesh.vertices[i as usize];
        DVec2::new(f64::from(x), f64::from(y))
    };
    // Inside the zigzag by the even-odd crossing count along +x, written here apart
    // from the crate's own check.
    let inside = |p: DVec2| {
        let mut crossings = 0;
        for k in 0..points.len() {
            let (a, b) = (points[k], points[(k + 1) % points.len()]);
            if (a.1 > p.y) != (b.1 > p.y) {
                let x = a.0 + (p.y - a.1) / (b.1 - a.1) * (b.0 - a.0);
                if x > p.x {
                    crossings += 1;
                }
            }
        }
        crossings % 2 == 1
    };
    let mut area = 0.0;
    for t in mesh.triangles.chunks_exact(3) {
        let (a, b, c) = (vertex(t[0]), vertex(t[1]), vertex(t[2]));
        let centre = (a + b + c) / 3.0;
        assert!(
            inside(centre),
            "a triangle outside the outline: {a} {b} {c}"
        );
        area += 0.5 * (b - a).perp_dot(c - a).abs();
    }
    assert!(
        (area - 356_300.0).abs() < 1.0,
        "the triangles cover {area} units²"
    );
}
