//! CPU preparation for `winding`: each distinct glyph's quadratic curves, and its bands,
//! laid out as the shader reads them.
//!
//! A band lists every curve whose control-point bounds overlap it across the ray, so a
//! ray cast inside the band meets no other curve. Each band keeps its curves twice:
//! by descending max (rays cast towards +) and by ascending min (rays cast towards −);
//! a ray then stops at the first curve lying wholly behind it.
//!
//! `aa=area` needs every curve at the height of a whole pixel, not of one ray, so its
//! bands ([`Layout::Area`]) overlap: each reaches one and a half bands beyond its
//! boundaries, and a pixel up to three bands tall lies wholly inside the band holding
//! its centre. Pixels taller than that take a coarser level: the same at twice the
//! height, four times, … up to one band for the glyph.

use glam::DVec2;

use super::overlaps::overlap_flags;
use crate::geometry::{
    DEFAULT_QUAD_TOLERANCE_EM, Outline, Quad, Segment, cubic_to_quadratics, monotone_pieces,
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
    /// twice as tall (and as far apart) as the last, down to a single band.
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
            data.push(&glyph.outline, scene.units_per_em, band_count, layout);
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
        let contours = contours(outline, DEFAULT_QUAD_TOLERANCE_EM * units_per_em);
        // Only `aa=area` reads the marks (rays never integrate a pixel as a whole).
        let overlaps: Vec<bool> = match layout {
            Layout::Rays => vec![false; contours.iter().map(Vec::len).sum()],
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
        self.curves.extend(quads.iter().map(|q| GpuCurve {
            p0p1: [
                q.p[0].x as f32,
                q.p[0].y as f32,
                q.p[1].x as f32,
                q.p[1].y as f32,
            ],
            p2: [q.p[2].x as f32, q.p[2].y as f32],
            overlaps: f32::from(u8::from(q.overlaps)),
            parent: q.parent,
            max_min: [
                q.max.x as f32,
                q.max.y as f32,
                q.min.x as f32,
                q.min.y as f32,
            ],
        }));
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
                self.push_bands(&quads, first_curve, 1, (min.y, max.y), count_h, AREA_REACH);
                self.push_band(&quads, first_curve, &all, 0);
                let (mut height, mut count) = ((max.y - min.y) / f64::from(count_h), count_h);
                while count > 1 {
                    height *= 2.0;
                    count = count.div_ceil(2);
                    let range = (min.y, min.y + height * f64::from(count));
                    self.push_bands(&quads, first_curve, 1, range, count, AREA_REACH);
                }
                0
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
            assert_eq!(g.band_count_v, 0);
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
}
