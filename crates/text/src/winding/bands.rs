//! CPU preparation for `winding`: each distinct glyph's quadratic curves, and its bands,
//! laid out as the shader reads them.
//!
//! A band lists every curve whose control-point bounds overlap it across the ray, so a
//! ray cast inside the band meets no other curve. Each band keeps its curves twice:
//! by descending max (rays cast towards +) and by ascending min (rays cast towards −);
//! a ray then stops at the first curve lying wholly behind it. (A segment's list, below,
//! is walked towards + alone and kept once.)
//!
//! `aa=area` needs every curve at the height of a whole pixel, not of one ray, so its
//! bands ([`Layout::Area`]) overlap: each reaches one and a half bands beyond its
//! boundaries, and a pixel up to three bands tall lies wholly inside the band holding
//! its centre. Pixels taller than that take a coarser level: the same at twice the
//! height, four times, … up to one band for the glyph.
//!
//! A glyph much wider than tall (a joined word: `between=union`) also splits each of
//! its `aa=area` bands along x into segments ([`segment_curves`]), so that a pixel in
//! the middle of a word walks the curves of its own stretch, not half the word's. A
//! segment's list holds the curves left of its right boundary, those across it cut
//! there, and, for everything right of it, a few vertical lines on the boundary: what
//! the curves right of a pixel add to its integral is the pixel's area between their
//! end heights, so theirs telescopes to the heights where the outline crosses the
//! boundary, which the lines carry.

use glam::DVec2;

use super::overlaps::overlap_flags;
use crate::geometry::{
    DEFAULT_QUAD_TOLERANCE_EM, Outline, Quad, Segment, cubic_to_quadratics, monotone_pieces,
    point_at, subcurve, t_at,
};
use crate::scene::Scene;

/// `Curve` in `winding.wgsl`, three texels of the curve texture (`curve_at` there):
/// the points and marks in the first two, the bounds only `aa=rays` needs in the third.
/// (`aa=area` reads its curves inline in the band lists: [`GlyphData::band_entries_inline`].)
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuCurve {
    pub p0p1: [f32; 4],
    pub p2: [f32; 2],
    /// 1 where the curve may separate other winding levels than 0 and the fill
    /// ([`overlap_flags`]), else 0.
    pub overlaps: f32,
    /// The index, within its glyph, of the font's curve this one is a piece of
    /// (`aa=area`'s prep splits curves where x or y turns).
    pub parent: u32,
    /// The control points' bounds: max x, max y, min x, min y.
    pub max_min: [f32; 4],
}

/// `Glyph` in `winding.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuGlyph {
    pub bounds: [f32; 4],
    pub band_count_h: u32,
    /// [`Layout::Rays`]: the vertical bands; [`Layout::Area`]: the segments each band is
    /// split into along x (0: none) in its low 16 bits, and in its high 16 how many
    /// levels of bands, from the finest, are split.
    pub band_count_v: u32,
    pub first_band: u32,
    pub units_per_em: f32,
}

/// `Band` in `winding.wgsl`: offsets of its two orderings in the band-curve list.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuBand {
    pub by_max: u32,
    pub by_min: u32,
    pub count: u32,
}

/// How many bands each glyph gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BandCount {
    /// Chosen per glyph: doubled while doubling still saves half a curve per band.
    Auto,
    /// The same count for every glyph, in each direction.
    Fixed(u32),
}

/// Most bands in one direction: past this, bands cost memory and save nothing.
pub const MAX_BANDS: u32 = 64;

/// Which bands each glyph gets, in the order `band_for` (winding_rays.wgsl) finds them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// For rays: its horizontal bands, its vertical bands, then one band listing all its
    /// curves (brute force, and the class overlay).
    Rays,
    /// For `aa=area`: its horizontal bands, each reaching `AREA_REACH` bands beyond its
    /// boundaries; the band of all its curves; then the coarser levels, each with bands
    /// twice as tall (and as far apart) as the last, down to a single band. In a glyph
    /// split into segments along x, each band of the levels split is followed by its
    /// segments' records (`segment_curves` in bands.rs).
    Area,
}

/// Everything the shader reads about the distinct glyphs, built once per scene.
#[derive(Default, Debug)]
pub struct GlyphData {
    pub curves: Vec<GpuCurve>,
    pub glyphs: Vec<GpuGlyph>,
    /// Per glyph, as its [`Layout`] orders them.
    pub bands: Vec<GpuBand>,
    pub band_curves: Vec<u32>,
    /// Per glyph, whether any of its curves is marked as overlapping (only with
    /// [`Layout::Area`]): its pixels may need the sub-pixel grid.
    pub marked: Vec<bool>,
    /// Whether its glyphs are laid out for `aa=area` ([`Layout::Area`]), whose walk
    /// reads each list entry's curve inline ([`GlyphData::band_entries_inline`]).
    pub area: bool,
}

/// A quadratic curve as the bands are built from it: in local font units, rounded to
/// f32 the way the GPU holds it, with its bounds and marks ([`GpuCurve`] is the record
/// the GPU reads).
#[derive(Clone, Copy, Debug)]
struct PreparedCurve {
    p: Quad,
    min: DVec2,
    max: DVec2,
    /// Marked by [`overlap_flags`] (only for [`Layout::Area`]).
    overlaps: bool,
    /// Kept in the bands even when it runs along them: in a glyph with marked curves,
    /// `aa=area` counts every curve crossing a pixel.
    counted: bool,
    /// Its index among the glyph's curves before any split.
    parent: u32,
}

impl PreparedCurve {
    /// The record the GPU reads.
    fn gpu(&self) -> GpuCurve {
        let [p0, p1, p2] = self.p.map(|p| p.as_vec2());
        GpuCurve {
            p0p1: [p0.x, p0.y, p1.x, p1.y],
            p2: p2.to_array(),
            overlaps: f32::from(u8::from(self.overlaps)),
            parent: self.parent,
            max_min: [
                self.max.x as f32,
                self.max.y as f32,
                self.min.x as f32,
                self.min.y as f32,
            ],
        }
    }

    fn along(&self, axis: usize) -> (f64, f64) {
        (self.min[axis], self.max[axis])
    }

    /// A line along the ray never crosses it (its sign class is uniform), nor adds to
    /// a pixel's integral: it is left out of that direction's bands, as Slug does —
    /// unless `aa=area` must count it to know where three winding levels may meet.
    fn is_left_out(&self, across: usize) -> bool {
        !self.counted
            && self.p[0][across] == self.p[1][across]
            && self.p[1][across] == self.p[2][across]
    }
}

/// The quadratics of an outline, contour by contour: cubics become quadratics within
/// `tolerance` (font units); lines become quadratics with their midpoint as control
/// point, exactly representable; zero-length pieces, which cannot change any winding
/// number, are dropped.
fn contours(outline: &Outline, tolerance: f64) -> Vec<Vec<PreparedCurve>> {
    outline
        .contours
        .iter()
        .map(|contour| {
            let mut quads = Vec::with_capacity(contour.segments.len());
            for segment in &contour.segments {
                push_quads(segment, tolerance, &mut quads);
            }
            quads
        })
        .collect()
}

/// Appends `segment` as quadratics; a cubic is converted here, so that no outline a
/// caller passes can reach the shader with a curve it cannot read.
fn push_quads(segment: &Segment, tolerance: f64, quads: &mut Vec<PreparedCurve>) {
    let Some(p) = segment.as_quad() else {
        // A cubic: the conversion yields only lines and quadratics.
        cubic_to_quadratics(segment, tolerance, &mut |piece| {
            push_quads(&piece, tolerance, quads)
        });
        return;
    };
    // Round once, here, so that bounds and bands agree with what the GPU sees.
    let p = p.map(|v| v.as_vec2().as_dvec2());
    if p[0] != p[1] || p[1] != p[2] {
        quads.push(PreparedCurve {
            p,
            min: p[0].min(p[1]).min(p[2]),
            max: p[0].max(p[1]).max(p[2]),
            overlaps: false,
            counted: false,
            parent: 0,
        });
    }
}

/// `q` split where x or y turns, for `aa=area`, whose shader takes every curve to be
/// monotone in both: each piece rounded to f32 as the GPU holds it (pieces share their
/// ends exactly: both are the same blossom), its middle control point then kept within
/// its ends' box, which a monotone piece's is (rounding may have nudged it out by an
/// ulp). Pieces that rounding leaves as a point are dropped.
fn monotone_quads(q: &PreparedCurve) -> Vec<PreparedCurve> {
    monotone_pieces(q.p)
        .into_iter()
        .flatten()
        .filter_map(|piece| {
            let [a, b, c] = piece.map(|v| v.as_vec2().as_dvec2());
            let b = b.clamp(a.min(c), a.max(c));
            (a != b || b != c).then(|| PreparedCurve {
                p: [a, b, c],
                min: a.min(c),
                max: a.max(c),
                ..*q
            })
        })
        .collect()
}

impl GlyphData {
    /// What `winding` uploads for `scene`: every distinct glyph, with bands in `layout`.
    pub fn of_scene(scene: &Scene, band_count: BandCount, layout: Layout) -> GlyphData {
        let mut data = GlyphData::default();
        for glyph in &scene.glyphs {
            if glyph.merged {
                data.push_union(&glyph.outline, scene.units_per_em, band_count, layout);
            } else {
                data.push(&glyph.outline, scene.units_per_em, band_count, layout);
            }
        }
        data
    }

    /// Appends one glyph (an outline in a font of `units_per_em`, its cubics converted to
    /// quadratics within the project's tolerance) and returns its index.
    pub fn push(
        &mut self,
        outline: &Outline,
        units_per_em: f64,
        band_count: BandCount,
        layout: Layout,
    ) -> u32 {
        self.push_contours(outline, units_per_em, band_count, layout, false)
    }

    /// [`GlyphData::push`] for an outline that is a nonzero union of contours
    /// ([`merge_overlaps`](crate::geometry::merge_overlaps)'s): no curve is marked as
    /// overlapping. Its winding number is 0 or its fill sign everywhere, so no pixel
    /// holds three winding levels, where its contours touch (which marks the curves of
    /// an outline as a font gives it: touching contours wound against each other put
    /// three levels in a pixel) as anywhere else.
    pub fn push_union(
        &mut self,
        outline: &Outline,
        units_per_em: f64,
        band_count: BandCount,
        layout: Layout,
    ) -> u32 {
        self.push_contours(outline, units_per_em, band_count, layout, true)
    }

    fn push_contours(
        &mut self,
        outline: &Outline,
        units_per_em: f64,
        band_count: BandCount,
        layout: Layout,
        union: bool,
    ) -> u32 {
        let contours = contours(outline, DEFAULT_QUAD_TOLERANCE_EM * units_per_em);
        // Only `aa=area` reads the marks (rays never integrate a pixel as a whole).
        let overlaps: Vec<bool> = match layout {
            Layout::Rays => vec![false; contours.iter().map(Vec::len).sum()],
            Layout::Area if union => vec![false; contours.iter().map(Vec::len).sum()],
            Layout::Area => {
                let curves: Vec<Vec<Quad>> = contours
                    .iter()
                    .map(|c| c.iter().map(|q| q.p).collect())
                    .collect();
                overlap_flags(&curves, units_per_em).concat()
            }
        };
        let any_marked = overlaps.contains(&true);
        let quads: Vec<PreparedCurve> = (contours.concat().into_iter().zip(overlaps))
            .zip(0..)
            .flat_map(|((q, overlaps), parent)| {
                let marked = PreparedCurve {
                    overlaps,
                    counted: any_marked,
                    parent,
                    ..q
                };
                match layout {
                    Layout::Rays => vec![marked],
                    Layout::Area => monotone_quads(&marked),
                }
            })
            .collect();
        let first_curve = self.curves.len() as u32;
        self.curves.extend(quads.iter().map(PreparedCurve::gpu));
        let min = quads
            .iter()
            .fold(DVec2::splat(f64::INFINITY), |m, q| m.min(q.min));
        let max = quads
            .iter()
            .fold(DVec2::splat(f64::NEG_INFINITY), |m, q| m.max(q.max));
        let (min, max) = if quads.is_empty() {
            (DVec2::ZERO, DVec2::ZERO)
        } else {
            (min, max)
        };

        let first_band = self.bands.len() as u32;
        let all: Vec<usize> = (0..quads.len()).collect();
        // Horizontal bands split y (rays along x, axis 0); vertical ones split x.
        let count_h = resolve(band_count, &quads, 1, (min.y, max.y));
        let count_v = match layout {
            Layout::Rays => {
                let count_v = resolve(band_count, &quads, 0, (min.x, max.x));
                self.push_bands(&quads, first_curve, 1, (min.y, max.y), count_h, 0.0);
                self.push_bands(&quads, first_curve, 0, (min.x, max.x), count_v, 0.0);
                self.push_band(&quads, first_curve, &all, 0);
                count_v
            }
            Layout::Area => {
                let segments = auto_segment_count(&quads, (min, max));
                // Each segment's curves once in the curve list; the bands list them.
                let lists: Vec<(u32, Vec<PreparedCurve>)> = (1..=segments)
                    .map(|j| {
                        let curves = segment_curves(&quads, (min.x, max.x), segments, j);
                        let first = self.curves.len() as u32;
                        self.curves.extend(curves.iter().map(PreparedCurve::gpu));
                        (first, curves)
                    })
                    .collect();
                // A level's bands serve pixels taller than 2·AREA_REACH of the finer
                // level's bands (the finest, any): where those are wider than a segment
                // (a pixel about square), none fits one, and the level keeps its bands
                // whole. The levels from the finest that are split, as the shader
                // counts them (`area_band`).
                let segment_width = (max.x - min.x) / f64::from(segments.max(1));
                let band_height =
                    |level: u32| (max.y - min.y) / f64::from(count_h) * f64::from(1 << level);
                let split_levels = if segments == 0 {
                    0
                } else {
                    1 + (1..8)
                        .take_while(|&l| 2.0 * AREA_REACH * band_height(l - 1) < segment_width)
                        .count() as u32
                };
                let level = |this: &mut GlyphData, range: (f64, f64), count: u32, split: bool| {
                    let lists = if split { &lists[..] } else { &[] };
                    let split: Vec<Vec<Vec<usize>>> = (lists.iter())
                        .map(|(_, curves)| band_members(curves, 1, range, count, AREA_REACH))
                        .collect();
                    let bands = band_members(&quads, 1, range, count, AREA_REACH);
                    for (b, members) in bands.iter().enumerate() {
                        this.push_band(&quads, first_curve, members, 0);
                        for ((first, curves), members) in lists.iter().zip(&split) {
                            this.push_segment(curves, *first, &members[b]);
                        }
                    }
                };
                level(self, (min.y, max.y), count_h, split_levels > 0);
                self.push_band(&quads, first_curve, &all, 0);
                let (mut height, mut count, mut l) =
                    ((max.y - min.y) / f64::from(count_h), count_h, 0);
                while count > 1 {
                    height *= 2.0;
                    count = count.div_ceil(2);
                    l += 1;
                    level(
                        self,
                        (min.y, min.y + height * f64::from(count)),
                        count,
                        l < split_levels,
                    );
                }
                segments | (split_levels << 16)
            }
        };
        self.marked.push(any_marked);
        self.area |= layout == Layout::Area;
        self.glyphs.push(GpuGlyph {
            bounds: [min.x as f32, min.y as f32, max.x as f32, max.y as f32],
            band_count_h: count_h,
            band_count_v: count_v,
            first_band,
            units_per_em: units_per_em as f32,
        });
        self.glyphs.len() as u32 - 1
    }

    /// Pushes `count` bands splitting `range` of coordinate `across`, each reaching
    /// `reach` of a band beyond its boundaries.
    fn push_bands(
        &mut self,
        quads: &[PreparedCurve],
        first_curve: u32,
        across: usize,
        range: (f64, f64),
        count: u32,
        reach: f64,
    ) {
        let along = 1 - across;
        for members in band_members(quads, across, range, count, reach) {
            self.push_band(quads, first_curve, &members, along);
        }
    }

    fn push_band(
        &mut self,
        quads: &[PreparedCurve],
        first_curve: u32,
        members: &[usize],
        along: usize,
    ) {
        let mut by_max = members.to_vec();
        by_max.sort_by(|&a, &b| quads[b].along(along).1.total_cmp(&quads[a].along(along).1));
        let mut by_min = members.to_vec();
        by_min.sort_by(|&a, &b| quads[a].along(along).0.total_cmp(&quads[b].along(along).0));
        let start = self.band_curves.len() as u32;
        self.band_curves.extend(
            by_max
                .iter()
                .chain(&by_min)
                .map(|&i| first_curve + i as u32),
        );
        self.bands.push(GpuBand {
            by_max: start,
            by_min: start + members.len() as u32,
            count: members.len() as u32,
        });
    }

    /// A segment's band: `members` of a segment's `curves` (in the curve list from
    /// `first_curve`), in the one ordering its walk takes, towards + (by descending max
    /// x): a segment's list ends at its right boundary.
    fn push_segment(&mut self, curves: &[PreparedCurve], first_curve: u32, members: &[usize]) {
        let mut by_max = members.to_vec();
        by_max.sort_by(|&a, &b| curves[b].max.x.total_cmp(&curves[a].max.x));
        let start = self.band_curves.len() as u32;
        self.band_curves
            .extend(by_max.iter().map(|&i| first_curve + i as u32));
        self.bands.push(GpuBand {
            by_max: start,
            by_min: start,
            count: members.len() as u32,
        });
    }

    /// Per entry of the band lists, its curve inline in two texels (`band_end_texels` and
    /// `band_middle_texels` in winding.wgsl): the end points p0.xy and p2.xy as f32 bits,
    /// from which `aa=area`'s walk tells where a monotone piece lies against a pixel (its
    /// control point lies within their box: `monotone_quads`), and p1.xy, the overlap
    /// mark and the parent, read only for the pieces across the pixel.
    pub fn band_entries_inline(&self) -> (Vec<[u32; 4]>, Vec<[u32; 4]>) {
        self.band_curves
            .iter()
            .map(|&c| {
                let curve = &self.curves[c as usize];
                let [x0, y0, x1, y1] = curve.p0p1.map(f32::to_bits);
                let [x2, y2] = curve.p2.map(f32::to_bits);
                (
                    [x0, y0, x2, y2],
                    [x1, y1, curve.overlaps.to_bits(), curve.parent],
                )
            })
            .unzip()
    }

    pub fn bytes(&self) -> usize {
        size_of_val(self.curves.as_slice())
            + size_of_val(self.glyphs.as_slice())
            + size_of_val(self.bands.as_slice())
            + size_of_val(self.band_curves.as_slice())
            + if self.area {
                8 * size_of_val(self.band_curves.as_slice())
            } else {
                0
            }
    }
}

/// How far `aa=area`'s bands reach beyond their boundaries, in bands: a pixel up to
/// 2 × this many bands tall whose centre is in a band lies wholly within its reach. A
/// pixel then takes bands a third of its height or more, and its band lists the curves
/// of 4/3 of its height at best, where half a band (bands a pixel tall, lists twice its
/// height) listed more: compare `curves_per_pixel` of `glyphscope render --case rotated
/// --method winding --stats S.json` at a7aab76 and at d602036, the commit before it.
const AREA_REACH: f64 = 1.5;

/// The band count `band_count` asks for across `range` of coordinate `across`.
fn resolve(
    band_count: BandCount,
    quads: &[PreparedCurve],
    across: usize,
    range: (f64, f64),
) -> u32 {
    match band_count {
        BandCount::Fixed(n) => n,
        BandCount::Auto => auto_band_count(quads, across, range),
    }
}

/// The curves of each of `count` equal bands across `range`, each reaching `reach` of a
/// band beyond its boundaries. Membership is by closed intervals widened by a further
/// 1/256 of a band, so a sample the shader rounds into a neighbouring band still finds
/// every curve at its height: a superset is harmless, a missing curve is not.
fn band_members(
    quads: &[PreparedCurve],
    across: usize,
    range: (f64, f64),
    count: u32,
    reach: f64,
) -> Vec<Vec<usize>> {
    let height = (range.1 - range.0) / f64::from(count);
    let slack = height * (reach + 1.0 / 256.0);
    (0..count)
        .map(|k| {
            let lo = range.0 + height * f64::from(k) - slack;
            let hi = range.0 + height * f64::from(k + 1) + slack;
            (0..quads.len())
                .filter(|&i| {
                    let (min, max) = quads[i].along(across);
                    !quads[i].is_left_out(across) && min <= hi && max >= lo
                })
                .collect()
        })
        .collect()
}

/// Doubles the band count while that still saves at least half a curve per band on
/// average, up to [`MAX_BANDS`].
fn auto_band_count(quads: &[PreparedCurve], across: usize, range: (f64, f64)) -> u32 {
    let mean = |count: u32| {
        let members = band_members(quads, across, range, count, 0.0);
        members.iter().map(Vec::len).sum::<usize>() as f64 / f64::from(count)
    };
    let mut count = 1;
    let mut current = mean(1);
    while count < MAX_BANDS {
        let doubled = mean(count * 2);
        if current - doubled < 0.5 {
            break;
        }
        count *= 2;
        current = doubled;
    }
    count
}

/// Most segments a glyph's bands are split into along x.
pub const MAX_SEGMENTS: u32 = 64;

/// Segment `j` (1 to `segments`) of `segments` equal ones across `span` (the glyph's x
/// bounds): its right boundary, as the GPU holds it.
fn segment_boundary(span: (f64, f64), segments: u32, j: u32) -> f64 {
    let width = (span.1 - span.0) / f64::from(segments);
    f64::from((span.0 + width * f64::from(j)) as f32)
}

/// The curves a pixel in segment `j` of `segments` across `span` walks, towards +x:
/// one whose right edge lies within the segment (at most its boundary, less a 256th of
/// a segment) and whose left edge lies at most two segments left of the boundary (a
/// 256th more), the shader's test (`area_band` in winding_area.wgsl). A curve wholly
/// left of that reach adds nothing to such a pixel.
///
/// Listed: the curves left of the boundary reaching that far; those across it, cut
/// where they meet it (their left part; a monotone piece meets it once); and vertical
/// lines on the boundary that add to any such pixel what every curve right of it (and
/// every cut-off right part) adds. Such a curve lies wholly right of the pixel and adds
/// A(end) − A(start), A the pixel's area below a height; summed over them, the sum
/// Σ sᵢ·A(yᵢ) over their ends (s = +1 at an end, −1 at a start) telescopes where one
/// piece ends and the next starts, leaving the heights where the outline crosses the
/// boundary. By Abel summation, with Sₖ the running sum of s up to the k-th height in
/// ascending order, it is Σₖ Sₖ·(A(yₖ) − A(yₖ₊₁)): Sₖ lines from yₖ₊₁ down to yₖ, and
/// where consecutive Sₖ are equal their lines join into one (the terms of the heights
/// between telescope).
///
/// Every piece right of the boundary, whole or cut off, adds one +1 and one −1, so the
/// signs sum to 0 and the lines end where they must, closed outline or not.
fn segment_curves(
    quads: &[PreparedCurve],
    span: (f64, f64),
    segments: u32,
    j: u32,
) -> Vec<PreparedCurve> {
    let width = (span.1 - span.0) / f64::from(segments);
    let boundary = segment_boundary(span, segments, j);
    let reach = span.0 + width * (f64::from(j) - 2.0 - 1.0 / 256.0);
    let mut listed = Vec::new();
    // The heights of the right side's ends, with their signs.
    let mut ends: Vec<(f64, i64)> = Vec::new();
    for q in quads {
        if q.max.x <= boundary {
            if q.max.x >= reach {
                listed.push(*q);
            }
            continue;
        }
        if q.min.x >= boundary {
            ends.extend([(q.p[2].y, 1), (q.p[0].y, -1)]);
            continue;
        }
        // Across the boundary: cut there, as the GPU will hold the cut (x exactly the
        // boundary, y rounded once), its middle control point kept within its ends' box.
        let t = t_at(q.p.map(|p| p.x), boundary);
        let y = f64::from(point_at(q.p, t).y as f32).clamp(q.min.y, q.max.y);
        let cut = DVec2::new(boundary, y);
        let rising = q.p[2].x > q.p[0].x;
        let (a, b) = if rising { (0.0, t) } else { (t, 1.0) };
        let middle = subcurve(q.p, a, b)[1].as_vec2().as_dvec2();
        let [start, end] = if rising { [q.p[0], cut] } else { [cut, q.p[2]] };
        let middle = middle.clamp(start.min(end), start.max(end));
        if start != end {
            listed.push(PreparedCurve {
                p: [start, middle, end],
                min: start.min(end),
                max: start.max(end),
                ..*q
            });
        }
        let (right_start, right_end) = if rising { (cut, q.p[2]) } else { (q.p[0], cut) };
        ends.extend([(right_end.y, 1), (right_start.y, -1)]);
    }
    ends.sort_by(|a, b| a.0.total_cmp(&b.0));
    // The heights where the running sum changes, and the sum from each to the next:
    // heights where one right-side piece ends and the next starts leave it as it was,
    // and one line (|sum| copies) spans the whole run. A line per pair of consecutive
    // end heights had split each stretch of ink at every right-side piece's end inside
    // it: 0.58 lines per covered pixel on arabic, up to 15.
    let (mut running, mut run_start, mut run_value) = (0, 0.0, 0);
    for (k, &(y, sign)) in ends.iter().enumerate() {
        running += sign;
        if ends.get(k + 1).is_some_and(|&(next, _)| next == y) || running == run_value {
            continue;
        }
        if run_value != 0 {
            // `run_value` lines from `y` down to `run_start` (up, where it is negative).
            let (from, to) = if run_value > 0 {
                (y, run_start)
            } else {
                (run_start, y)
            };
            let line = PreparedCurve {
                p: [
                    DVec2::new(boundary, from),
                    DVec2::new(
                        boundary,
                        f64::from((0.5 * (from + to)) as f32).clamp(run_start, y),
                    ),
                    DVec2::new(boundary, to),
                ],
                min: DVec2::new(boundary, run_start),
                max: DVec2::new(boundary, y),
                overlaps: false,
                counted: false,
                parent: u32::MAX,
            };
            listed.extend(std::iter::repeat_n(line, run_value.unsigned_abs() as usize));
        }
        (run_start, run_value) = (y, running);
    }
    debug_assert_eq!(
        running, 0,
        "each piece right of the boundary adds +1 and −1"
    );
    listed
}

/// How many segments a glyph's `aa=area` bands are split into: segments about a sixth
/// of the glyph's height wide (`SEGMENTS_PER_HEIGHT`), up to [`MAX_SEGMENTS`], in a
/// glyph at least twice as wide as tall with `LEAST_CURVES` monotone pieces or more: a
/// joined word, not a letter nor a dash. None otherwise.
///
/// Measured on the bench's scenes (`glyphscope render --case arabic|bengali --method
/// winding --stats S.json`, curves per covered pixel, mean, with this constant set to
/// 1, 2, 4, 6, 8 and 12): arabic 3.44, 3.14, 2.96, 2.89, 2.85, 2.93; bengali 4.17,
/// 3.33, 2.88, 2.77, 2.74, 2.68. Narrower segments shorten the walk to the boundary
/// but put more boundaries across Arabic's baseline strokes (each a cut piece and a
/// line in the lists of the bands there); a sixth holds less memory than a quarter or
/// an eighth (fewer levels are split: `split_levels`). Below 48 pieces, wide single
/// letters (Arabic's seen, its final yeh) took segments too and cost more drawn one by
/// one (`between=add`: 2.52 (11) → 2.56 (13)); the scene's wide joined words have 34
/// to 113 pieces, and the few under 48 keep their bands whole.
fn auto_segment_count(quads: &[PreparedCurve], (min, max): (DVec2, DVec2)) -> u32 {
    const SEGMENTS_PER_HEIGHT: f64 = 6.0;
    const LEAST_CURVES: usize = 48;
    let (width, height) = (max.x - min.x, max.y - min.y);
    if width < 2.0 * height || quads.len() < LEAST_CURVES {
        return 0;
    }
    ((SEGMENTS_PER_HEIGHT * width / height).ceil() as u32).min(MAX_SEGMENTS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::font::Font;
    use crate::geometry::DEFAULT_QUAD_TOLERANCE_EM;

    /// A font of the repository's `fonts/` (the crate embeds none): 0 DejaVu Sans
    /// (TrueType quadratics), 1 Latin Modern Roman (CFF cubics).
    fn shipped(index: usize) -> Font {
        let file = ["DejaVuSans.ttf", "lmroman10-regular.otf"][index];
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fonts")
            .join(file);
        Font::from_path(&path).expect("the repository's fonts parse")
    }

    fn glyph(font: &Font, c: char) -> Outline {
        let tolerance = DEFAULT_QUAD_TOLERANCE_EM * font.units_per_em();
        font.outline(font.glyph_for_char(c).unwrap())
            .to_quadratics(tolerance)
    }

    /// `aa=area`'s walk reads each list entry's curve inline: the end points in one
    /// texel, the control point, overlap mark and parent in the other, and tells the
    /// curve's zone from the end points alone, so every piece's control point lies in
    /// its ends' box. Read back texel by texel, every entry is its listed curve.
    #[test]
    fn inline_entries_are_their_curves_and_the_ends_bound_them() {
        let font = shipped(0);
        for c in "gS@&mWo".chars() {
            let mut data = GlyphData::default();
            data.push(&glyph(&font, c), 2048.0, BandCount::Auto, Layout::Area);
            let (ends, middles) = data.band_entries_inline();
            assert_eq!(
                (ends.len(), middles.len()),
                (data.band_curves.len(), data.band_curves.len())
            );
            for ((end, middle), &listed) in ends.iter().zip(&middles).zip(&data.band_curves) {
                let curve = &data.curves[listed as usize];
                let [x0, y0, x2, y2] = end.map(f32::from_bits);
                let (x1, y1) = (f32::from_bits(middle[0]), f32::from_bits(middle[1]));
                assert_eq!(
                    [x0, y0, x1, y1],
                    curve.p0p1,
                    "'{c}' entry of curve {listed}"
                );
                assert_eq!([x2, y2], curve.p2);
                assert_eq!(
                    (f32::from_bits(middle[2]), middle[3]),
                    (curve.overlaps, curve.parent)
                );
                assert!(
                    x0.min(x2) <= x1 && x1 <= x0.max(x2) && y0.min(y2) <= y1 && y1 <= y0.max(y2),
                    "'{c}': control point ({x1}, {y1}) outside its ends' box"
                );
            }
        }
    }

    /// Every curve that crosses a band's interior is in that band.
    #[test]
    fn bands_hold_every_curve_that_can_cross_them() {
        let font = shipped(0);
        for c in "gS@&mW".chars() {
            let mut data = GlyphData::default();
            data.push(&glyph(&font, c), 2048.0, BandCount::Fixed(7), Layout::Rays);
            let g = data.glyphs[0];
            let (lo, hi) = (g.bounds[1], g.bounds[3]);
            for k in 0..7 {
                let band = data.bands[k];
                let listed: Vec<u32> =
                    data.band_curves[band.by_max as usize..][..band.count as usize].to_vec();
                let y = lo + (hi - lo) * (k as f32 + 0.5) / 7.0;
                for (i, curve) in data.curves.iter().enumerate() {
                    let ys = [curve.p0p1[1], curve.p0p1[3], curve.p2[1]];
                    let crosses = ys.iter().any(|&v| v > y) && ys.iter().any(|&v| v <= y);
                    assert!(
                        !crosses || listed.contains(&(i as u32)),
                        "{c:?} band {k} lacks curve {i}"
                    );
                }
            }
        }
    }

    #[test]
    fn both_orderings_are_sorted_and_hold_the_same_curves() {
        let font = shipped(1);
        let mut data = GlyphData::default();
        data.push(&glyph(&font, '&'), 1000.0, BandCount::Auto, Layout::Rays);
        let g = data.glyphs[0];
        for (k, band) in data.bands.iter().enumerate() {
            let along =
                if (k as u32) < g.band_count_h || k as u32 == g.band_count_h + g.band_count_v {
                    0
                } else {
                    1
                };
            let ids = |start: u32| &data.band_curves[start as usize..][..band.count as usize];
            let max = |i: &u32| data.curves[*i as usize].max_min[along];
            let min = |i: &u32| data.curves[*i as usize].max_min[2 + along];
            assert!(
                ids(band.by_max)
                    .windows(2)
                    .all(|w| max(&w[0]) >= max(&w[1]))
            );
            assert!(
                ids(band.by_min)
                    .windows(2)
                    .all(|w| min(&w[0]) <= min(&w[1]))
            );
            let mut a = ids(band.by_max).to_vec();
            let mut b = ids(band.by_min).to_vec();
            a.sort();
            b.sort();
            assert_eq!(a, b);
        }
    }

    #[test]
    fn auto_bands_shrink_the_lists() {
        let font = shipped(0);
        let mut data = GlyphData::default();
        data.push(&glyph(&font, '@'), 2048.0, BandCount::Auto, Layout::Rays);
        let g = data.glyphs[0];
        assert!(g.band_count_h > 1 && g.band_count_v > 1, "{g:?}");
        let all = data.bands[(g.band_count_h + g.band_count_v) as usize].count;
        let mean_h: f64 = data.bands[..g.band_count_h as usize]
            .iter()
            .map(|b| f64::from(b.count))
            .sum::<f64>()
            / f64::from(g.band_count_h);
        assert!(
            mean_h < f64::from(all) / 3.0,
            "mean band {mean_h} of {all} curves"
        );
    }

    #[test]
    fn degenerate_pieces_are_dropped_and_lines_stay_exact() {
        let a = DVec2::new(0.0, 0.0);
        let b = DVec2::new(100.0, 30.0);
        let outline = Outline {
            contours: vec![crate::geometry::Contour {
                segments: vec![
                    Segment::Line(a, b),
                    Segment::Line(b, b),
                    Segment::Line(b, a),
                ],
            }],
        };
        let mut data = GlyphData::default();
        data.push(&outline, 1000.0, BandCount::Auto, Layout::Rays);
        assert_eq!(data.curves.len(), 2, "the zero-length line is gone");
        let c = data.curves[0];
        assert_eq!(
            [c.p0p1[2], c.p0p1[3]],
            [50.0, 15.0],
            "line control point is its midpoint"
        );
    }

    /// `push` is public: an outline with cubics, as a font gives it, is converted within
    /// the project's tolerance (the same curves as converting it first), never refused.
    #[test]
    fn a_pushed_cubic_becomes_the_quadratics_of_the_conversion() {
        let font = shipped(1);
        let units_per_em = font.units_per_em();
        let outline = font.outline(font.glyph_for_char('S').unwrap());
        assert!(
            outline.segments().any(|s| matches!(s, Segment::Cubic(..))),
            "Latin Modern's 'S' is drawn with cubics"
        );
        for layout in [Layout::Rays, Layout::Area] {
            let mut direct = GlyphData::default();
            direct.push(&outline, units_per_em, BandCount::Auto, layout);
            let mut converted = GlyphData::default();
            converted.push(
                &outline.to_quadratics(DEFAULT_QUAD_TOLERANCE_EM * units_per_em),
                units_per_em,
                BandCount::Auto,
                layout,
            );
            assert!(!direct.curves.is_empty());
            assert_eq!(direct.curves, converted.curves, "{layout:?}");
            assert_eq!(direct.glyphs, converted.glyphs, "{layout:?}");
            assert_eq!(direct.bands, converted.bands, "{layout:?}");
            assert_eq!(direct.band_curves, converted.band_curves, "{layout:?}");
        }
    }

    /// `aa=area`'s levels: at each level, for a pixel whose half height is at most half
    /// that level's band height, the band holding the pixel's centre lists every curve
    /// reaching the pixel's rows. The levels are found as `area_band` in winding_area.wgsl
    /// finds them: level 0 first, the band of all curves, then each coarser one.
    #[test]
    fn area_levels_hold_every_curve_at_a_pixels_height() {
        let font = shipped(0);
        for (c, count) in [('g', BandCount::Fixed(7)), ('@', BandCount::Auto)] {
            let mut data = GlyphData::default();
            data.push(&glyph(&font, c), 2048.0, count, Layout::Area);
            let g = data.glyphs[0];
            assert_eq!(g.band_count_v, 0, "{c:?}: a glyph about as wide as tall");
            let (lo, hi) = (f64::from(g.bounds[1]), f64::from(g.bounds[3]));
            let mut first = 0;
            let mut next = g.band_count_h as usize + 1;
            let mut count = g.band_count_h as usize;
            let mut height = (hi - lo) / count as f64;
            loop {
                let half = AREA_REACH * height;
                for step in 0..200 {
                    let centre = lo - half + (hi - lo + 2.0 * half) * f64::from(step) / 199.0;
                    let k = (((centre - lo) / height).floor().max(0.0) as usize).min(count - 1);
                    let band = data.bands[first + k];
                    let listed = &data.band_curves[band.by_max as usize..][..band.count as usize];
                    for (i, curve) in data.curves.iter().enumerate() {
                        let ys = [curve.p0p1[1], curve.p0p1[3], curve.p2[1]].map(f64::from);
                        let (min, max) = (ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]));
                        let reaches = max > centre - half && min < centre + half && min < max;
                        assert!(
                            !reaches || listed.contains(&(i as u32)),
                            "{c:?}: level of {count} bands, centre {centre}: curve {i} missing"
                        );
                    }
                }
                if count == 1 {
                    break;
                }
                first = next;
                height *= 2.0;
                count = count.div_ceil(2);
                next = first + count;
            }
            assert_eq!(next, data.bands.len(), "{c:?}: every level found");
        }
    }

    /// Flat curves add nothing to a pixel's integral and are left out of horizontal
    /// bands, unless the glyph has curves marked as overlapping: then `aa=area` counts
    /// every curve crossing a pixel.
    #[test]
    fn flat_curves_stay_only_where_overlaps_are_counted() {
        let square = |x: f64, y: f64| crate::geometry::Contour {
            segments: [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]
                .iter()
                .zip([(10.0, 0.0), (10.0, 10.0), (0.0, 10.0), (0.0, 0.0)])
                .map(|(&(ax, ay), (bx, by))| {
                    Segment::Line(DVec2::new(ax + x, ay + y), DVec2::new(bx + x, by + y))
                })
                .collect(),
        };
        for (contours, flat_kept) in [
            (vec![square(0.0, 0.0)], false),
            (vec![square(0.0, 0.0), square(5.0, 5.0)], true),
        ] {
            let mut data = GlyphData::default();
            data.push(
                &Outline { contours },
                1000.0,
                BandCount::Fixed(1),
                Layout::Area,
            );
            let members = data.bands[0].count as usize;
            let all = data.curves.len();
            assert_eq!(members == all, flat_kept, "{members} of {all} curves");
        }
    }

    /// `aa=area` takes curves monotone in x and y: a quadratic that turns in both is
    /// split in three pieces, each monotone, sharing their ends and their parent; rays
    /// keep it whole.
    #[test]
    fn area_curves_are_monotone_pieces_of_their_parent() {
        let (a, b, c) = (
            DVec2::new(0.0, 0.0),
            DVec2::new(10.0, 20.0),
            DVec2::new(-4.0, 2.0),
        );
        let outline = Outline {
            contours: vec![crate::geometry::Contour {
                segments: vec![Segment::Quad(a, b, c), Segment::Line(c, a)],
            }],
        };
        let mut rays = GlyphData::default();
        rays.push(&outline, 1000.0, BandCount::Fixed(1), Layout::Rays);
        assert_eq!(rays.curves.len(), 2);
        let mut area = GlyphData::default();
        area.push(&outline, 1000.0, BandCount::Fixed(1), Layout::Area);
        assert_eq!(
            area.curves.len(),
            4,
            "x and y each turn once inside the quadratic"
        );
        let pieces = &area.curves[..3];
        for (i, piece) in pieces.iter().enumerate() {
            assert_eq!(piece.parent, 0);
            let p = [
                [piece.p0p1[0], piece.p0p1[1]],
                [piece.p0p1[2], piece.p0p1[3]],
                piece.p2,
            ];
            for axis in 0..2 {
                let (lo, hi) = (p[0][axis].min(p[2][axis]), p[0][axis].max(p[2][axis]));
                assert!(
                    (lo..=hi).contains(&p[1][axis]),
                    "piece {i}, axis {axis}: {p:?}"
                );
            }
            if i > 0 {
                assert_eq!(pieces[i - 1].p2, p[0], "pieces share their ends");
            }
        }
        assert_eq!(area.curves[3].parent, 1);
    }

    /// A word's width of 'm's, each one's contours moved along by `spacing` times its
    /// width: a glyph much wider than tall, with many curves in each band (its letters
    /// apart for a spacing over 1, overlapping under it).
    fn word_of_ms(font: &Font, count: usize, spacing: f64) -> Outline {
        let m = glyph(font, 'm');
        let advance = m.control_bounds().unwrap().size().x * spacing;
        let contours = (0..count)
            .flat_map(|k| {
                let shift = DVec2::new(advance * k as f64, 0.0);
                (m.contours.iter()).map(move |c| crate::geometry::Contour {
                    segments: c.segments.iter().map(|s| s.map(|p| p + shift)).collect(),
                })
            })
            .collect();
        Outline { contours }
    }

    /// The list `area_band` in winding_area.wgsl reads for a pixel centred on `centre`
    /// whose half extents are `half` (local units), mirrored in f64: its curves, and
    /// whether it is a segment's (walked towards +x) or a band's.
    fn chosen_list(
        data: &GlyphData,
        g: &GpuGlyph,
        centre: DVec2,
        half: DVec2,
    ) -> (Vec<Quad>, bool) {
        let [x0, y0, x1, y1] = g.bounds.map(f64::from);
        let (segments, split_levels) = (g.band_count_v & 0xffff, g.band_count_v >> 16);
        let per_band = |level: u32| {
            if level < split_levels {
                1 + segments
            } else {
                1
            }
        };
        let mut height = (y1 - y0) / f64::from(g.band_count_h);
        let (mut first, mut count, mut level) = (g.first_band, g.band_count_h, 0);
        let mut next = first + count * per_band(0) + 1;
        while count > 1 && AREA_REACH * height < half.y {
            first = next;
            height *= 2.0;
            count = count.div_ceil(2);
            level += 1;
            next = first + count * per_band(level);
        }
        let per_band = per_band(level);
        let index = ((centre.y - y0) / height)
            .floor()
            .clamp(0.0, f64::from(count - 1)) as u32;
        let width = (x1 - x0) / f64::from(segments.max(1));
        let right = centre.x + half.x;
        let j = ((right - x0) / width + 1.0 / 256.0)
            .ceil()
            .clamp(1.0, f64::from(segments.max(1)));
        let boundary = x0 + j * width;
        let segment = per_band > 1
            && right <= boundary - width / 256.0
            && centre.x - half.x >= boundary - 2.0 * width + width / 256.0;
        let record = first + index * per_band + if segment { j as u32 } else { 0 };
        let band = data.bands[record as usize];
        let curves = data.band_curves[band.by_max as usize..][..band.count as usize]
            .iter()
            .map(|&i| {
                let c = data.curves[i as usize];
                [[c.p0p1[0], c.p0p1[1]], [c.p0p1[2], c.p0p1[3]], c.p2]
                    .map(|[x, y]| DVec2::new(f64::from(x), f64::from(y)))
            })
            .collect();
        (curves, segment)
    }

    /// A glyph split into segments: for pixels of many sizes, shapes and places, the
    /// segment `area_band` picks gives the pixel-averaged winding number (the CPU
    /// mirror's, `area::pixel_winding`, in f64) of every curve of the glyph — its cut
    /// pieces and boundary lines standing in for everything right of it — and a band's
    /// list gives it too where no segment fits. Most pixels find a segment. Two words:
    /// 'm's side by side (winding 0 or 1), and 'm's overlapping with one contour
    /// reversed (overlaps kept as a font gives them: winding 2 where two 'm's meet, −1
    /// and 0 where the reversed one lies), so that the boundary lines come in several
    /// copies and both orientations.
    #[test]
    fn a_segment_holds_what_its_pixels_integrate() {
        let font = shipped(0);
        let word = word_of_ms(&font, 5, 1.08);
        let mut overlapping = word_of_ms(&font, 6, 0.7);
        overlapping.contours[2] = overlapping.contours[2].reversed();
        // The overlapping word's boundaries do carry lines in copies and upwards.
        let (quads, min, max, segments) = pieces_of(&overlapping);
        let lines: Vec<PreparedCurve> = (1..segments)
            .flat_map(|j| segment_curves(&quads, (min.x, max.x), segments, j))
            .filter(|c| c.parent == u32::MAX)
            .collect();
        assert!(lines.iter().any(|l| l.p[0].y < l.p[2].y), "no line upwards");
        assert!(
            lines.windows(2).any(|pair| pair[0].p == pair[1].p),
            "no line in two copies"
        );
        for (name, word) in [("side by side", word), ("overlapping", overlapping)] {
            check_segments(name, &word);
        }
    }

    /// An outline's monotone pieces as `push` makes them, their bounds, and the segments
    /// `auto_segment_count` gives it (at least 8: the tests' words are wide).
    fn pieces_of(word: &Outline) -> (Vec<PreparedCurve>, DVec2, DVec2, u32) {
        let quads: Vec<PreparedCurve> = contours(word, DEFAULT_QUAD_TOLERANCE_EM * 2048.0)
            .concat()
            .iter()
            .flat_map(monotone_quads)
            .collect();
        let min = quads.iter().fold(DVec2::INFINITY, |m, q| m.min(q.min));
        let max = quads.iter().fold(DVec2::NEG_INFINITY, |m, q| m.max(q.max));
        let segments = auto_segment_count(&quads, (min, max));
        assert!(segments >= 8, "{segments} segments");
        (quads, min, max, segments)
    }

    fn check_segments(name: &str, word: &Outline) {
        use super::super::area::pixel_winding;
        let mut data = GlyphData::default();
        data.push(word, 2048.0, BandCount::Auto, Layout::Area);
        let g = data.glyphs[0];
        let segments = g.band_count_v & 0xffff;
        assert!(
            segments >= 8 && g.band_count_v >> 16 >= 1,
            "{name}: {segments} segments"
        );
        let curves: Vec<Quad> = word.segments().filter_map(Segment::as_quad).collect();
        let [x0, y0, x1, y1] = g.bounds.map(f64::from);
        // A small generator of its own: the same pixels on every run.
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut fitted, mut tried) = (0, 0);
        for _ in 0..3000 {
            // Pixels from a twentieth of a segment to three segments across, turned and
            // skewed a little, anywhere over the glyph and a little past it.
            let size = (x1 - x0) / f64::from(segments) * (0.05 + 3.0 * next() * next());
            let angle = 0.6 * (next() - 0.5);
            let skew = 0.4 * (next() - 0.5);
            let jx = DVec2::new(angle.cos(), angle.sin()) * size;
            let jy = DVec2::new(-angle.sin() + skew, angle.cos()) * size;
            let centre = DVec2::new(
                x0 - size + (x1 - x0 + 2.0 * size) * next(),
                y0 - size + (y1 - y0 + 2.0 * size) * next(),
            );
            let half = 0.5 * DVec2::new(jx.x.abs() + jy.x.abs(), jx.y.abs() + jy.y.abs());
            let (listed, segment) = chosen_list(&data, &g, centre, half);
            let whole = pixel_winding(&curves, centre, jx, jy);
            // (A band's list, walked either way, sums to the whole's too.)
            let from_list = pixel_winding(&listed, centre, jx, jy);
            assert!(
                (whole - from_list).abs() <= 1e-4,
                "{name}: pixel at {centre} of size {size}: {from_list} from its {} list of {} \
                 curves, {whole} from all",
                if segment { "segment's" } else { "band's" },
                listed.len()
            );
            fitted += usize::from(segment);
            tried += 1;
        }
        assert!(
            fitted * 2 > tried,
            "{name}: {fitted} of {tried} pixels found a segment"
        );
    }

    /// Segments go to glyphs much wider than tall with curves enough in their bands: a
    /// word, not a letter, not a dash.
    #[test]
    fn only_wide_glyphs_with_curves_to_save_take_segments() {
        let font = shipped(0);
        let segments = |outline: &Outline| {
            let mut data = GlyphData::default();
            data.push(outline, 2048.0, BandCount::Auto, Layout::Area);
            data.glyphs[0].band_count_v & 0xffff
        };
        assert_eq!(segments(&glyph(&font, 'm')), 0);
        assert_eq!(segments(&glyph(&font, '\u{2014}')), 0, "an em dash");
        assert!(segments(&word_of_ms(&font, 5, 1.08)) > 0);
        // Rays never split bands along x: their vertical bands are the other count.
        let mut rays = GlyphData::default();
        rays.push(
            &word_of_ms(&font, 5, 1.08),
            2048.0,
            BandCount::Fixed(4),
            Layout::Rays,
        );
        assert_eq!(rays.glyphs[0].band_count_v, 4);
    }

    /// Where a boundary crosses ink, one line stands for the whole stretch (a glyph
    /// whose winding is 0 or 1): a segment's lines are disjoint and none touches the
    /// next, and there are at most half as many as the pieces of the outline that cross
    /// the boundary (none of the word's points lies on a boundary, which would cross it
    /// with no piece counted). Right-side pieces that end inside the ink had split a
    /// stretch into a line per piece beside it, which every pixel of the segment walked.
    #[test]
    fn a_boundary_holds_one_line_per_stretch_of_ink() {
        let font = shipped(0);
        let (quads, min, max, segments) = pieces_of(&word_of_ms(&font, 5, 1.08));
        let mut inked = 0;
        for j in 1..segments {
            let boundary = segment_boundary((min.x, max.x), segments, j);
            assert!(
                (quads.iter()).all(|q| q.min.x != boundary && q.max.x != boundary),
                "boundary {j} meets a point of the word: choose another word for this test"
            );
            let crossings = (quads.iter())
                .filter(|q| q.min.x < boundary && q.max.x > boundary)
                .count();
            let mut lines: Vec<(f64, f64)> = segment_curves(&quads, (min.x, max.x), segments, j)
                .iter()
                .filter(|c| c.parent == u32::MAX)
                .map(|c| (c.min.y, c.max.y))
                .collect();
            lines.sort_by(|a, b| a.0.total_cmp(&b.0));
            assert!(
                2 * lines.len() <= crossings && (crossings == 0) == lines.is_empty(),
                "boundary {j}: {} lines for {crossings} crossings",
                lines.len()
            );
            for pair in lines.windows(2) {
                assert!(pair[0].1 < pair[1].0, "boundary {j}: lines {pair:?} meet");
            }
            inked += usize::from(!lines.is_empty());
        }
        assert!(
            inked * 2 >= segments as usize,
            "{inked} of {segments} boundaries cross ink"
        );
    }
}
