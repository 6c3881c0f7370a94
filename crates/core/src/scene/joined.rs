//! Instances whose ink overlaps, drawn as one glyph, whose fill under the nonzero rule
//! is their union.
//!
//! A method that draws each instance on its own adds the instances' coverages. That is
//! exact where their ink lies apart (box-filter coverage adds over disjoint areas, and
//! over areas that only touch) and counts the shared area twice where it overlaps:
//! Arabic letters joining the next, Bengali and Devanagari vowel signs over their bases,
//! box-drawing characters meeting, a kerned pair. The reference fills the union of every
//! outline it draws. Here the scene is rewritten so that a method drawing it instance by
//! instance fills that union too: instances whose ink overlaps are grouped
//! (transitively), and each group becomes one instance of a new glyph, the group's
//! outlines placed together in the frame of its first instance. It is then one glyph
//! with overlapping contours, the level below, which a method draws as it draws any
//! such glyph (`overlaps=merge` takes its nonzero union: [`Scene::with_overlaps_merged`]).
//!
//! The groups are found in the glyph run's own coordinates, before any camera: a
//! projective map keeps apart what is apart, so the same groups hold under every
//! transform. Only instances whose control bounds overlap have their ink intersected
//! (once per pair of glyphs at one relative position), and each distinct group (the same
//! glyphs at the same relative positions) is one glyph, so a repeated word is prepared,
//! and its union taken, once.

use std::borrow::Cow;
use std::collections::HashMap;

use glam::DVec2;

use super::model::{Glyph, Instance, Scene};
use crate::geometry::{Contour, Outline, Rect, groups_where, inks_overlap};

/// What joining found in a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct JoinCounts {
    /// Groups of two or more instances whose ink overlaps: one instance each once joined.
    pub groups: usize,
    /// Instances in those groups.
    pub instances: usize,
    /// Distinct joined glyphs: a group repeated elsewhere (the same glyphs at the same
    /// relative positions) is one.
    pub distinct: usize,
}

/// How far apart, in ems, two instances' control boxes may lie along x and still be
/// letters of one word for [`Scene::with_words_joined`]: more than the side bearings of
/// two letters (DejaVu Sans: up to about 0.09 em each), less than a space with them
/// (DejaVu Sans 0.318 em, Inter 0.281 em, before side bearings). Text without spaces
/// joins whole lines.
pub const WORD_GAP_EM: f64 = 0.2;

/// A position relative to a group's first instance, bit for bit.
type Offset = [u64; 2];

fn offset(from: DVec2, to: DVec2) -> Offset {
    let d = to - from;
    [d.x.to_bits(), d.y.to_bits()]
}

impl Scene {
    /// The same picture with each group of instances whose ink overlaps drawn as one
    /// instance of one glyph, their outlines together (see the module's text), and what
    /// was joined. Instances whose ink meets no other's stay as they are, as do two
    /// whose ink intersection cannot be told (drawn added, as without joining). Glyphs
    /// no instance draws any more are left out.
    pub fn with_overlapping_instances_joined(&self) -> (Scene, JoinCounts) {
        let mut pairs: HashMap<(u32, u32, Offset), bool> = HashMap::new();
        self.joined_where(0.0, |a, b| {
            let (a, b) = (self.instances[a], self.instances[b]);
            *pairs
                .entry((a.glyph, b.glyph, offset(a.position, b.position)))
                .or_insert_with(|| {
                    // In a's frame, so that far from the origin no precision is lost.
                    let b_in_a = translated(
                        &self.glyphs[b.glyph as usize].outline,
                        b.position - a.position,
                    );
                    let a = &self.glyphs[a.glyph as usize].outline;
                    inks_overlap(a, &b_in_a, self.units_per_em).unwrap_or(false)
                })
        })
    }

    /// The same picture with each word drawn as one instance of one glyph: instances
    /// whose control boxes lie less than [`WORD_GAP_EM`] of an em apart along x and
    /// overlap in y (letters of a word, and any instances whose ink overlaps) are
    /// grouped transitively and joined as
    /// [`with_overlapping_instances_joined`](Self::with_overlapping_instances_joined)
    /// joins, so the fill is still the union. A method drawing a quad per instance then
    /// draws one per word: fewer, larger quads, and a glyph per distinct word.
    pub fn with_words_joined(&self) -> (Scene, JoinCounts) {
        self.joined_where(0.5 * WORD_GAP_EM * self.units_per_em, |_, _| true)
    }

    /// The scene with the groups of instances joined whose control boxes, grown along x
    /// by `grow` font units on each side, meet and `joins` says belong together (by
    /// index, each pair at most once; transitively).
    fn joined_where(
        &self,
        grow: f64,
        joins: impl FnMut(usize, usize) -> bool,
    ) -> (Scene, JoinCounts) {
        let placed = |i: &Instance| {
            let b = self.glyphs[i.glyph as usize].bounds;
            let by = DVec2::new(grow, 0.0);
            Rect {
                min: b.min + i.position - by,
                max: b.max + i.position + by,
            }
        };
        let bounds: Vec<Rect> = self.instances.iter().map(placed).collect();
        let groups = groups_where(&bounds, joins);

        let mut glyphs = self.glyphs.clone();
        let mut joined: HashMap<Vec<(u32, Offset)>, u32> = HashMap::new();
        let mut counts = JoinCounts::default();
        // (the first member's index in the scene, the instance drawn), to keep the
        // scene's order.
        let mut drawn: Vec<(usize, Instance)> = Vec::with_capacity(self.instances.len());
        for group in groups {
            let members: Vec<Instance> = group.iter().map(|&i| self.instances[i]).collect();
            if members.len() == 1 {
                drawn.push((group[0], members[0]));
                continue;
            }
            let first = members[0].position;
            let key = members
                .iter()
                .map(|m| (m.glyph, offset(first, m.position)))
                .collect();
            let glyph = *joined.entry(key).or_insert_with(|| {
                glyphs.push(self.joined(&members));
                counts.distinct += 1;
                glyphs.len() as u32 - 1
            });
            counts.groups += 1;
            counts.instances += members.len();
            drawn.push((
                group[0],
                Instance {
                    glyph,
                    position: first,
                },
            ));
        }
        drawn.sort_by_key(|&(index, _)| index);

        // Keep only the glyphs still drawn, in order of first use.
        let mut new_index: Vec<Option<u32>> = vec![None; glyphs.len()];
        let mut kept = Vec::new();
        let instances = drawn
            .into_iter()
            .map(|(_, instance)| {
                let slot = new_index[instance.glyph as usize].get_or_insert_with(|| {
                    kept.push(glyphs[instance.glyph as usize].clone());
                    kept.len() as u32 - 1
                });
                Instance {
                    glyph: *slot,
                    ..instance
                }
            })
            .collect();
        let scene = Scene {
            units_per_em: self.units_per_em,
            glyphs: kept,
            instances,
            source: self.source.clone(),
        };
        (scene, counts)
    }

    /// What a method draws under `between=union` (`join`: this scene joined, see
    /// [`Scene::with_overlapping_instances_joined`]) or `between=add` (it as it is).
    pub fn joined_if(&self, join: bool) -> Cow<'_, Scene> {
        if join {
            Cow::Owned(self.with_overlapping_instances_joined().0)
        } else {
            Cow::Borrowed(self)
        }
    }

    /// `members`' outlines in the frame of the first, as one glyph carrying the first's
    /// id: under the nonzero rule it fills their union (and [`Glyph::union`] merges
    /// its contours for the methods that want them merged).
    fn joined(&self, members: &[Instance]) -> Glyph {
        let first = members[0].position;
        let placed = members.iter().map(|m| {
            let glyph = &self.glyphs[m.glyph as usize];
            let by = m.position - first;
            let bounds = Rect {
                min: glyph.bounds.min + by,
                max: glyph.bounds.max + by,
            };
            (translated(&glyph.outline, by).contours, bounds)
        });
        let (contours, bounds): (Vec<Vec<Contour>>, Vec<Rect>) = placed.unzip();
        Glyph::new(
            self.glyphs[members[0].glyph as usize].id,
            Outline {
                contours: contours.concat(),
            },
            bounds
                .into_iter()
                .reduce(Rect::union)
                .expect("a group has members"),
        )
    }
}

fn translated(outline: &Outline, by: DVec2) -> Outline {
    Outline {
        contours: outline
            .contours
            .iter()
            .map(|c| Contour {
                segments: c.segments.iter().map(|s| s.map(|p| p + by)).collect(),
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Segment;

    /// A 100-unit square with its lower left corner at `x`, counter-clockwise.
    fn square(x: f64) -> Outline {
        let p = [(x, 0.0), (x + 100.0, 0.0), (x + 100.0, 100.0), (x, 100.0)]
            .map(|(x, y)| DVec2::new(x, y));
        Outline {
            contours: vec![Contour {
                segments: (0..4)
                    .map(|i| Segment::Line(p[i], p[(i + 1) % 4]))
                    .collect(),
            }],
        }
    }

    /// Two glyphs overlapping by half, twice (far apart); a third glyph alone; and a
    /// fourth touching the third along an edge, which shares no area.
    #[test]
    fn overlapping_instances_join_once_per_distinct_group() {
        let at = |x: f64| DVec2::new(x, 0.0);
        let scene = Scene::from_outlines(
            1000.0,
            vec![
                (square(0.0), at(0.0)),
                (square(0.0), at(50.0)),
                (square(0.0), at(10_000.0)),
                (square(0.0), at(10_050.0)),
                (square(0.0), at(20_000.0)),
                (square(0.0), at(20_100.0)),
            ],
        );
        // from_outlines makes each outline its own glyph: six glyphs, all squares.
        let (joined, counts) = scene.with_overlapping_instances_joined();
        assert_eq!(
            counts,
            JoinCounts {
                groups: 2,
                instances: 4,
                distinct: 2
            },
            "the two pairs are of different glyph ids, so two distinct groups"
        );
        assert_eq!(joined.instances.len(), 4);
        assert_eq!(
            joined.glyphs.len(),
            4,
            "the four glyphs joined are left out"
        );
        let pair = &joined.glyphs[joined.instances[0].glyph as usize];
        assert_eq!(pair.outline.contours.len(), 2);
        assert_eq!(pair.bounds.min, DVec2::ZERO);
        assert_eq!(pair.bounds.max, DVec2::new(150.0, 100.0));
        assert_eq!(joined.instances[0].position, at(0.0));
        assert_eq!(joined.instances[1].position, at(10_000.0));
        // The touching pair stays two instances, in the scene's order.
        assert_eq!(joined.instances[2].position, at(20_000.0));
        assert_eq!(joined.instances[3].position, at(20_100.0));
        assert_eq!(joined.ink_bounds(), scene.ink_bounds());
    }

    /// Letters of a word (boxes less than 0.2 em apart along x) join into one glyph,
    /// words a space apart do not, nor a letter on another line, and a group whose ink
    /// overlaps joins as well; a repeated word is one glyph. Squares 100 units wide and
    /// tall in a 1000-unit em: 20 units apart is a word's letters, 400 a space.
    #[test]
    fn words_join_letters_a_gap_apart() {
        let at = |x: f64, y: f64| DVec2::new(x, y);
        let mut scene = Scene::from_outlines(1000.0, vec![(square(0.0), DVec2::ZERO)]);
        // "aaa aa aaa", a square alone far off and one on the line below the first;
        // the last word's last two overlap by half.
        scene.instances = [
            0.0, 120.0, 240.0, 740.0, 860.0, 1360.0, 1480.0, 1600.0, 1650.0,
        ]
        .into_iter()
        .map(|x| at(x, 0.0))
        .chain([at(9000.0, 0.0), at(0.0, -120.0)])
        .map(|position| Instance { glyph: 0, position })
        .collect();
        let (joined, counts) = scene.with_words_joined();
        assert_eq!(
            counts,
            JoinCounts {
                groups: 3,
                instances: 9,
                distinct: 3
            }
        );
        let widths: Vec<(f64, f64, usize)> = (joined.instances.iter())
            .map(|i| {
                let g = &joined.glyphs[i.glyph as usize];
                let size = g.bounds.max - g.bounds.min;
                (size.x, size.y, g.outline.contours.len())
            })
            .collect();
        assert_eq!(
            widths,
            [
                (340.0, 100.0, 3),
                (220.0, 100.0, 2),
                (390.0, 100.0, 4),
                (100.0, 100.0, 1),
                (100.0, 100.0, 1)
            ],
            "each word's squares, its box as wide as they span (not grown)"
        );
        assert_eq!(joined.ink_bounds(), scene.ink_bounds());
        // The gap is WORD_GAP_EM: letters 0.19 em apart join, 0.21 em do not.
        let pair = |gap: f64| {
            let mut two = scene.clone();
            two.instances.truncate(2);
            two.instances[1].position = at(100.0 + gap, 0.0);
            two.with_words_joined().1.groups
        };
        assert_eq!((pair(190.0), pair(210.0)), (1, 0));
    }

    /// The same glyphs at the same relative positions are one distinct group: a
    /// repeated word is prepared once.
    #[test]
    fn a_repeated_group_is_one_glyph() {
        let mut scene = Scene::from_outlines(1000.0, vec![(square(0.0), DVec2::ZERO)]);
        scene.instances = [0.0, 60.0, 5000.0, 5060.0, 9000.0]
            .map(|x| Instance {
                glyph: 0,
                position: DVec2::new(x, 0.0),
            })
            .to_vec();
        let (joined, counts) = scene.with_overlapping_instances_joined();
        assert_eq!(
            counts,
            JoinCounts {
                groups: 2,
                instances: 4,
                distinct: 1
            }
        );
        assert_eq!(joined.glyphs.len(), 2, "the pair and the square alone");
        assert_eq!(joined.instances[0].glyph, joined.instances[1].glyph);
    }
}
