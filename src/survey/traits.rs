//! Which of the traits a claim may leave out of its scope ([`Trait`]) a glyph has, as
//! one camera sees it: what lets the survey hold each method to its claim on glyphs
//! nobody labelled. Each trait is read from the outline's geometry alone, never from a
//! method's output, by the definitions below; the samples are at most [`SPACING`] px
//! apart, which is the detectors' resolution.
//!
//! - **Overlapping**: the reference's [`crate::reference::overlapping_contours`].
//! - **SubpixelDetail** ("several edges, or a whole contour, inside one pixel"): two
//!   stretches of outline that can cross one pixel together: closer than √2 px (two
//!   edges farther apart than a pixel's diagonal never cross the same pixel) while
//!   being different contours, or parts of one contour more than 4√2 px apart along it:
//!   a stem, hairline or gap thinner than √2 px for a few pixels, or a spike or notch
//!   sharper than 29°, whose two sides stay within √2 px for more than 2√2 px (at a
//!   wider corner the sides part sooner: that is one edge turning, drawn as such by
//!   every method); or a contour less than √2 px across.
//! - **TouchingContours**: two contours within [`SPACING`] of each other.
//! - **CrowdedPixels**: more than 8 of the font's segments pass through one pixel of
//!   this camera's grid.
//! - **DeepWinding**: a winding number over 255 on a scan line (rows [`SPACING`] apart).
//!   A line crosses a polygon of n edges at most n times, so under 512 edges it cannot.
//! - **BeyondF32**: f32 font units resolve less than 1/32 px at the glyph's largest
//!   coordinate.

use glam::{DMat3, DVec2};

use crate::geometry::{Outline, Quad, Segment, line_as_quad, project, winding_number};
use crate::methods::info::Trait;

/// The largest distance between consecutive samples along the outline, pixels.
pub const SPACING: f64 = 0.25;
/// Two edges closer than this can cross one pixel: its diagonal.
const PIXEL_DIAGONAL: f64 = std::f64::consts::SQRT_2;
/// Parts of one contour nearer than this along it are one edge turning (or a corner
/// wider than 29°: sides within √2 px at 2d·sin(θ/2) while 2d > 4√2 needs
/// sin(θ/2) < 1/4), not two edges.
const SAME_EDGE_ARC: f64 = 4.0 * std::f64::consts::SQRT_2;
/// More segments than this through one pixel is a crowded pixel (the rays' window).
const CROWDED: usize = 8;
/// A winding number over this does not fit an 8-bit counter.
const DEEPEST: i32 = 255;
/// The coarsest f32 resolution, in pixels, a method placing edges in font units keeps.
const F32_RESOLUTION_PX: f64 = 1.0 / 32.0;

/// One sample of the outline in image pixels.
struct Sample {
    at: DVec2,
    contour: usize,
    segment: usize,
    /// Distance along its contour from the contour's start, pixels.
    arc: f64,
}

/// The traits of `outline` (font units) seen through the affine map `to_image`, at
/// `px_per_unit` pixels per font unit; `overlapping` as the reference found it. The
/// detectors sample the outline and bin it per pixel: meant for a glyph that fits a
/// survey's frame (thousands of pixels across, not millions).
pub fn of(outline: &Outline, overlapping: bool, to_image: &DMat3, px_per_unit: f64) -> Vec<Trait> {
    let mut traits = Vec::new();
    if overlapping {
        traits.push(Trait::Overlapping);
    }
    let (samples, perimeters) = sample(outline, to_image);
    let (detail, touching) = close_edges(&samples, &perimeters);
    if touching {
        traits.push(Trait::TouchingContours);
    }
    if detail || thin_contour(&samples, &perimeters) {
        traits.push(Trait::SubpixelDetail);
    }
    if crowded(&samples) {
        traits.push(Trait::CrowdedPixels);
    }
    if deep_winding(outline, &samples, &perimeters) {
        traits.push(Trait::DeepWinding);
    }
    let largest = outline
        .segments()
        .flat_map(crate::geometry::segment_points)
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    // f32 has 24 significant bits: its step at `largest` is largest·2⁻²³ at most.
    if largest * f64::powi(2.0, -23) * px_per_unit > F32_RESOLUTION_PX {
        traits.push(Trait::BeyondF32);
    }
    traits
}

/// Traits as a row names them: their names, space-separated.
pub fn names(traits: &[Trait]) -> String {
    traits
        .iter()
        .map(|t| format!("{t:?}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Samples at most [`SPACING`] apart along every contour (flattened to 1/64 px first),
/// and each contour's perimeter.
fn sample(outline: &Outline, to_image: &DMat3) -> (Vec<Sample>, Vec<f64>) {
    let mut samples = Vec::new();
    let mut perimeters = Vec::new();
    let mut segment = 0;
    for (contour, c) in outline.contours.iter().enumerate() {
        let mut arc = 0.0;
        for s in &c.segments {
            let image = s.map(|p| project(to_image, p));
            let mut from = image.start();
            let mut add = |to: DVec2| {
                let steps = ((to - from).length() / SPACING).ceil().max(1.0);
                for k in 0..steps as usize {
                    let t = k as f64 / steps;
                    samples.push(Sample {
                        at: from.lerp(to, t),
                        contour,
                        segment,
                        arc: arc + t * (to - from).length(),
                    });
                }
                arc += (to - from).length();
                from = to;
            };
            image.flatten(1.0 / 64.0, &mut add);
            segment += 1;
        }
        perimeters.push(arc);
    }
    (samples, perimeters)
}

/// Sample indices binned in square cells of `side` pixels over the samples' box: a
/// dense grid (a glyph's box is a few thousand cells at most).
struct Grid {
    origin: DVec2,
    side: f64,
    columns: usize,
    rows: usize,
    cells: Vec<Vec<usize>>,
}

impl Grid {
    fn new(samples: &[Sample], side: f64) -> Grid {
        let (lo, hi) = samples
            .iter()
            .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), s| {
                (lo.min(s.at), hi.max(s.at))
            });
        let origin = (lo / side).floor() * side;
        let extent = ((hi - origin) / side).floor();
        let (columns, rows) = (extent.x as usize + 1, extent.y as usize + 1);
        let mut grid = Grid {
            origin,
            side,
            columns,
            rows,
            cells: vec![Vec::new(); columns * rows],
        };
        for (i, s) in samples.iter().enumerate() {
            let (x, y) = grid.cell(s.at);
            grid.cells[y * columns + x].push(i);
        }
        grid
    }

    fn cell(&self, p: DVec2) -> (usize, usize) {
        let c = ((p - self.origin) / self.side).floor();
        (c.x as usize, c.y as usize)
    }

    /// The samples in the cells around `p`'s (its own included).
    fn around(&self, p: DVec2) -> impl Iterator<Item = usize> + '_ {
        let (x, y) = self.cell(p);
        let columns = x.saturating_sub(1)..(x + 2).min(self.columns);
        (y.saturating_sub(1)..(y + 2).min(self.rows)).flat_map(move |row| {
            columns
                .clone()
                .flat_map(move |column| self.cells[row * self.columns + column].iter().copied())
        })
    }
}

/// Whether two edges can cross one pixel (see the module notes), and whether two
/// contours touch.
fn close_edges(samples: &[Sample], perimeters: &[f64]) -> (bool, bool) {
    if samples.is_empty() {
        return (false, false);
    }
    let grid = Grid::new(samples, PIXEL_DIAGONAL);
    let links = links(samples);
    let (mut detail, mut touching) = (false, false);
    for (i, a) in samples.iter().enumerate() {
        for j in grid.around(a.at).filter(|&j| j > i) {
            let b = &samples[j];
            let d = a.at.distance(b.at);
            if d >= PIXEL_DIAGONAL {
                continue;
            }
            if a.contour != b.contour {
                detail = true;
                touching |= d <= SPACING && !crossing_near(samples, &links, i, j);
            } else {
                let along = (a.arc - b.arc).abs();
                let along = along.min(perimeters[a.contour] - along);
                detail |= along > SAME_EDGE_ARC;
            }
            if detail && touching {
                return (true, true);
            }
        }
    }
    (detail, touching)
}

/// Each sample's predecessor and successor along its contour (a contour is closed).
fn links(samples: &[Sample]) -> (Vec<usize>, Vec<usize>) {
    let (mut prev, mut next) = (vec![0; samples.len()], vec![0; samples.len()]);
    let mut start = 0;
    for i in 0..samples.len() {
        if i + 1 == samples.len() || samples[i + 1].contour != samples[i].contour {
            for k in start..=i {
                next[k] = if k == i { start } else { k + 1 };
                prev[k] = if k == start { i } else { k - 1 };
            }
            start = i + 1;
        }
    }
    (prev, next)
}

/// Samples within this many steps of a close pair are where two contours that cross
/// there cross: a pixel of outline either way.
const CROSSING_WINDOW: usize = 4;

/// Whether the contour of sample `j` crosses the contour of sample `i` near them: the
/// samples [`CROSSING_WINDOW`] steps before and after `j` lie one inside and one
/// outside `i`'s contour. Overlapping contours come close where they cross, which is
/// not touching; contours that touch stay on one side of each other.
fn crossing_near(
    samples: &[Sample],
    (prev, next): &(Vec<usize>, Vec<usize>),
    i: usize,
    j: usize,
) -> bool {
    let before = (0..CROSSING_WINDOW).fold(j, |k, _| prev[k]);
    let after = (0..CROSSING_WINDOW).fold(j, |k, _| next[k]);
    let contour = samples[i].contour;
    let first = samples
        .iter()
        .position(|s| s.contour == contour)
        .unwrap_or(0);
    // Its polygon, as the project's winding number takes curves.
    let ring: Vec<DVec2> = samples[first..]
        .iter()
        .take_while(|s| s.contour == contour)
        .map(|s| s.at)
        .collect();
    let edges: Vec<Quad> = (0..ring.len())
        .map(|k| line_as_quad(ring[k], ring[(k + 1) % ring.len()]))
        .collect();
    let inside = |p: DVec2| winding_number(p, &edges) != 0;
    inside(samples[before].at) != inside(samples[after].at)
}

/// Whether some contour is less than a pixel's diagonal across: its width, the least
/// extent of its samples along 180 directions a degree apart (within 0.02% of the
/// true width at any turn of the camera). Only a contour shorter than 2·4√2 px needs
/// it: across a longer one that thin, two points half its perimeter apart along it lie
/// within √2 px, which [`close_edges`] finds.
fn thin_contour(samples: &[Sample], perimeters: &[f64]) -> bool {
    let contours = perimeters.len();
    let directions: Vec<DVec2> = (0..180)
        .map(|k| DVec2::from_angle(f64::from(k).to_radians()))
        .collect();
    let mut extents = vec![(f64::INFINITY, f64::NEG_INFINITY); contours * directions.len()];
    for s in samples
        .iter()
        .filter(|s| perimeters[s.contour] <= 2.0 * SAME_EDGE_ARC)
    {
        for (k, d) in directions.iter().enumerate() {
            let along = s.at.dot(*d);
            let (lo, hi) = &mut extents[s.contour * directions.len() + k];
            (*lo, *hi) = (lo.min(along), hi.max(along));
        }
    }
    extents.chunks(directions.len()).any(|contour| {
        let width = contour
            .iter()
            .map(|(lo, hi)| hi - lo)
            .fold(f64::INFINITY, f64::min);
        width.is_finite() && width < PIXEL_DIAGONAL
    })
}

/// Whether more than [`CROWDED`] segments pass through one pixel: each segment's
/// samples, and the midpoints between them, mark the pixels it passes through.
fn crowded(samples: &[Sample]) -> bool {
    if samples.is_empty() {
        return false;
    }
    let (lo, hi) = samples
        .iter()
        .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s.at), hi.max(s.at))
        });
    let (lo, hi) = (lo.floor(), hi.floor());
    let columns = (hi.x - lo.x) as usize + 1;
    let mut segments_in: Vec<Vec<usize>> = vec![Vec::new(); columns * ((hi.y - lo.y) as usize + 1)];
    // Pairs within one contour: the last sample of one and the first of the next are
    // no segment.
    for pair in samples.windows(2).filter(|p| p[0].contour == p[1].contour) {
        for p in [pair[0].at, (pair[0].at + pair[1].at) * 0.5] {
            let q = (p - lo).floor();
            let list = &mut segments_in[q.y as usize * columns + q.x as usize];
            if !list.contains(&pair[0].segment) {
                list.push(pair[0].segment);
                if list.len() > CROWDED {
                    return true;
                }
            }
        }
    }
    false
}

/// Whether a winding number over [`DEEPEST`] occurs on a scan line [`SPACING`] apart.
/// A horizontal line meets a segment of degree d at most d times, and a point's winding
/// number is at most half the line's crossings (the fewer on one side of it): under
/// 512 crossings in all, it cannot.
fn deep_winding(outline: &Outline, samples: &[Sample], perimeters: &[f64]) -> bool {
    let degrees: usize = outline
        .segments()
        .map(|s| match s {
            Segment::Line(..) => 1,
            Segment::Quad(..) => 2,
            Segment::Cubic(..) => 3,
        })
        .sum();
    if degrees < 2 * (DEEPEST as usize + 1) {
        return false;
    }
    let (lo, hi) = samples
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s.at.y), hi.max(s.at.y))
        });
    let first = (lo / SPACING).floor();
    let lines = ((hi / SPACING).ceil() - first) as usize + 1;
    let row_y = |k: usize| (first + k as f64) * SPACING + SPACING / 2.0;
    // Each edge (consecutive samples of a contour, closed) put on the lines it crosses.
    let mut crossings: Vec<Vec<(f64, i32)>> = vec![Vec::new(); lines];
    let mut start = 0;
    for c in 0..perimeters.len() {
        let end = start
            + samples[start..]
                .iter()
                .take_while(|s| s.contour == c)
                .count();
        for k in start..end {
            let (a, b) = (
                samples[k].at,
                samples[if k + 1 < end { k + 1 } else { start }].at,
            );
            let (top, bottom) = (a.y.min(b.y), a.y.max(b.y));
            let from = (((top - SPACING / 2.0) / SPACING).ceil() - first).max(0.0) as usize;
            for (line, bucket) in crossings.iter_mut().enumerate().skip(from) {
                let y = row_y(line);
                if y >= bottom {
                    break;
                }
                if y >= top && (a.y <= y) != (b.y <= y) {
                    let x = a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
                    bucket.push((x, if b.y > a.y { 1 } else { -1 }));
                }
            }
        }
        start = end;
    }
    crossings.iter_mut().any(|line| {
        line.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut winding = 0;
        line.iter().any(|&(_, direction)| {
            winding += direction;
            winding.abs() > DEEPEST
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Contour;

    /// An axis-aligned rectangle as one contour, counter-clockwise.
    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Contour {
        let p = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(|(x, y)| DVec2::new(x, y));
        Contour {
            segments: (0..4)
                .map(|i| Segment::Line(p[i], p[(i + 1) % 4]))
                .collect(),
        }
    }

    fn traits(contours: Vec<Contour>) -> Vec<Trait> {
        // One unit is one pixel; y is not flipped (the detectors do not care).
        of(&Outline { contours }, false, &DMat3::IDENTITY, 1.0)
    }

    /// Hand-worked against the definitions: a 1.3 px stem has edges closer than √2; a
    /// 1.5 px one does not; a 10 px square has none; a 1 px dot is a contour under a
    /// pixel's diagonal; two squares 3 px apart are neither close nor touching, sharing
    /// an edge they touch.
    #[test]
    fn subpixel_detail_and_touching_follow_their_definitions() {
        assert_eq!(
            traits(vec![rect(0.0, 0.0, 1.3, 20.0)]),
            [Trait::SubpixelDetail]
        );
        assert!(traits(vec![rect(0.0, 0.0, 1.5, 20.0)]).is_empty());
        assert!(traits(vec![rect(0.0, 0.0, 10.0, 10.0)]).is_empty());
        assert_eq!(
            traits(vec![rect(0.0, 0.0, 20.0, 1.0)]),
            [Trait::SubpixelDetail]
        );
        let apart = traits(vec![
            rect(0.0, 0.0, 10.0, 10.0),
            rect(13.0, 0.0, 23.0, 10.0),
        ]);
        assert!(apart.is_empty(), "{apart:?}");
        let near = traits(vec![
            rect(0.0, 0.0, 10.0, 10.0),
            rect(11.0, 0.0, 21.0, 10.0),
        ]);
        assert_eq!(near, [Trait::SubpixelDetail]);
        let touching = traits(vec![
            rect(0.0, 0.0, 10.0, 10.0),
            rect(10.0, 0.0, 20.0, 10.0),
        ]);
        assert_eq!(touching, [Trait::TouchingContours, Trait::SubpixelDetail]);
    }

    /// Contours that cross (overlap) come close where they cross without touching; a
    /// 1.2 px dot is under √2 px across at any turn (its axis-aligned box is not).
    #[test]
    fn crossing_is_not_touching_and_a_turned_dot_is_still_thin() {
        let crossed = traits(vec![rect(0.0, 0.0, 10.0, 10.0), rect(5.0, 5.0, 15.0, 15.0)]);
        assert!(!crossed.contains(&Trait::TouchingContours), "{crossed:?}");
        let turn = DMat3::from_angle(30f64.to_radians());
        let dot = Outline {
            contours: vec![rect(0.0, 0.0, 1.2, 1.2)],
        };
        assert_eq!(of(&dot, false, &turn, 1.0), [Trait::SubpixelDetail]);
        let square = Outline {
            contours: vec![rect(0.0, 0.0, 3.0, 3.0)],
        };
        assert!(of(&square, false, &turn, 1.0).is_empty());
    }

    /// A corner of 20° is a spike (its sides within √2 px more than 4√2 px along the
    /// contour: at 2.83 < d < 4.07 px from the apex, 2d·sin 10° < √2); one of 40° is
    /// not (2d·sin 20° < √2 only for d < 2.07), nor a square's right angles (above).
    #[test]
    fn a_sharp_spike_is_detail_and_a_wider_corner_is_not() {
        let triangle = |apex_deg: f64| {
            let half = (apex_deg / 2.0).to_radians();
            let (a, b) = (
                DVec2::ZERO,
                DVec2::new(20.0 * half.cos(), 20.0 * half.sin()),
            );
            let c = DVec2::new(b.x, -b.y);
            Contour {
                segments: vec![
                    Segment::Line(a, c),
                    Segment::Line(c, b),
                    Segment::Line(b, a),
                ],
            }
        };
        assert_eq!(traits(vec![triangle(20.0)]), [Trait::SubpixelDetail]);
        assert!(traits(vec![triangle(40.0)]).is_empty());
    }

    /// Five slivers (two segments each) crossing one pixel crowd it with ten segments;
    /// four, with eight, do not. 256 nested squares wind 256 deep; one square of 600
    /// edges winds 1.
    #[test]
    fn crowding_and_deep_winding_count_what_they_say() {
        let fan = |n: usize| {
            (0..n)
                .map(|k| {
                    let a = (k as f64 * 20.0).to_radians();
                    let d = DVec2::new(a.cos(), a.sin()) * 30.0;
                    let (p, q) = (DVec2::splat(0.5) - d, DVec2::splat(0.5) + d);
                    Contour {
                        segments: vec![Segment::Line(p, q), Segment::Line(q, p)],
                    }
                })
                .collect::<Vec<_>>()
        };
        assert!(traits(fan(5)).contains(&Trait::CrowdedPixels));
        assert!(!traits(fan(4)).contains(&Trait::CrowdedPixels));
        let nested: Vec<Contour> = (0..256)
            .map(|k| {
                let k = k as f64;
                rect(-k, -k, 1.0 + k, 1.0 + k)
            })
            .collect();
        assert!(traits(nested).contains(&Trait::DeepWinding));
        assert!(!traits(vec![rect(0.0, 0.0, 150.0, 10.0)]).contains(&Trait::DeepWinding));
    }

    #[test]
    fn f32_runs_out_only_past_half_a_million_px_per_em() {
        // A unit square at the far corner of a 2048-unit em: its coordinates are large,
        // its pixels few.
        let glyph = Outline {
            contours: vec![rect(2047.0, 2047.0, 2048.0, 2048.0)],
        };
        let at = |px_per_em: f64| {
            let scale = px_per_em / 2048.0;
            of(
                &glyph,
                false,
                &DMat3::from_scale(DVec2::splat(scale)),
                scale,
            )
        };
        assert!(!at(48.0).contains(&Trait::BeyondF32));
        assert!(at(1e6).contains(&Trait::BeyondF32));
    }
}
