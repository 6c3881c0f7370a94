//! How a cell's curve list reaches the shader: one u32 per cell.
//!
//! **Packed** (the encoding of kocsis1david's font-demo, bit for bit): three loops of
//! consecutive curves,
//!
//! ```text
//!   bits 0–1 len0 · 2–4 len1 · 5–7 len2 · 8–15 begin0 · 16–23 begin1 · 24–31 begin2
//! ```
//!
//! where `begin` is a slot (point index / 2) and `len` a number of curves: at most
//! 3 + 7 + 7 = 17 curves in three runs, starting within the first 256 slots (font-demo's
//! 512 points). A run may take in curves the cell does not need, to bridge a gap.
//!
//! **List** (general): where font-demo's word cannot hold a cell, the word escapes to a
//! list: all three lengths zero (a pattern font-demo never needs, since every cell lists
//! a curve) and bits 8–31 the offset, from the glyph's first word, of `count` followed
//! by `count` slots. Any cell fits; `encoding=list` escapes every cell.

use super::curves::CurveLayout;

/// Capacity of the three loops of a packed cell, in curves.
pub const LOOP_CAPACITY: [u32; 3] = [3, 7, 7];
/// The last slot a packed loop can begin at.
pub const MAX_BEGIN_SLOT: u32 = 255;
/// Bit offsets of each loop's length and begin fields.
const LEN_SHIFT: [u32; 3] = [0, 2, 5];
const BEGIN_SHIFT: [u32; 3] = [8, 16, 24];

/// A run of consecutive curves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Run {
    pub begin: u32,
    pub len: u32,
}

impl Run {
    pub fn slots(self) -> std::ops::Range<u32> {
        self.begin..self.begin + self.len
    }
}

/// The packed word for three runs that fit their loops.
pub fn pack(runs: [Run; 3]) -> u32 {
    (0..3).fold(0, |word, k| {
        debug_assert!(runs[k].len <= LOOP_CAPACITY[k] && runs[k].begin <= MAX_BEGIN_SLOT);
        word | runs[k].len << LEN_SHIFT[k] | runs[k].begin << BEGIN_SHIFT[k]
    })
}

/// The three runs of a packed word (what `cell_curve` in the shader reads).
pub fn unpack(word: u32) -> [Run; 3] {
    std::array::from_fn(|k| Run {
        begin: (word >> BEGIN_SHIFT[k]) & 0xFF,
        len: (word >> LEN_SHIFT[k]) & LOOP_CAPACITY[k],
    })
}

/// The packed word covering `slots` (ascending) with the fewest curves, or `None` when
/// no three runs within contours fit the loops. Returns the word and how many curves
/// its runs hold.
pub fn pack_cell(slots: &[u32], layout: &CurveLayout) -> Option<(u32, u32)> {
    let n = slots.len();
    if n == 0 {
        return Some((0, 0));
    }
    if n > LOOP_CAPACITY.iter().sum::<u32>() as usize {
        return None;
    }
    // A run covering slots[i..=j]: within one contour and beginning in reach.
    let run = |i: usize, j: usize| -> Option<Run> {
        let (first, last) = (slots[i], slots[j]);
        let contour = layout.slot_contour[first as usize]?;
        (layout.slot_contour[last as usize] == Some(contour) && first <= MAX_BEGIN_SLOT).then(
            || Run {
                begin: first,
                len: last - first + 1,
            },
        )
    };
    let mut best: Option<([Run; 3], u32)> = None;
    // Split the sorted slots into up to three consecutive groups at cuts a ≤ b.
    for a in 1..=n {
        for b in a..=n {
            let groups = [(0, a), (a, b), (b, n)];
            let mut runs = [Run::default(); 3];
            let mut fits = true;
            for (k, &(i, j)) in groups.iter().enumerate() {
                if i < j {
                    match run(i, j - 1) {
                        Some(r) => runs[k] = r,
                        None => fits = false,
                    }
                }
            }
            if !fits {
                continue;
            }
            // The shortest run goes to the 3-curve loop.
            runs.sort_by_key(|r| r.len);
            if (0..3).any(|k| runs[k].len > LOOP_CAPACITY[k]) {
                continue;
            }
            let total = runs.iter().map(|r| r.len).sum();
            if best.is_none_or(|(_, t)| total < t) {
                best = Some((runs, total));
            }
        }
    }
    best.map(|(runs, total)| (pack(runs), total))
}

/// Escape words keep their offset in bits 8–31.
const ESCAPE_SHIFT: u32 = 8;
/// The largest offset an escape word can hold.
pub const MAX_ESCAPE_OFFSET: usize = (1 << (32 - ESCAPE_SHIFT)) - 1;

/// A glyph's cells as the shader reads them: one word per cell, then the escaped cells'
/// lists.
#[derive(Clone, Debug, PartialEq)]
pub struct EncodedCells {
    pub words: Vec<u32>,
    /// Cells whose word escapes to a list.
    pub escaped: usize,
}

impl EncodedCells {
    /// Packs every cell of `lists` that font-demo's word can hold (all of them when
    /// `pack`, none otherwise) and lists the others. `None` when the lists are too long
    /// for an escape word's offset (over 16 million words for one glyph).
    pub fn new(lists: &[Vec<u32>], layout: &CurveLayout, pack: bool) -> Option<EncodedCells> {
        let mut words = vec![0; lists.len()];
        let mut escaped = 0;
        for (index, list) in lists.iter().enumerate() {
            match pack_cell(list, layout).filter(|_| pack) {
                Some((word, _)) => words[index] = word,
                None => {
                    if words.len() > MAX_ESCAPE_OFFSET {
                        return None;
                    }
                    words[index] = (words.len() as u32) << ESCAPE_SHIFT;
                    words.push(list.len() as u32);
                    words.extend_from_slice(list);
                    escaped += 1;
                }
            }
        }
        Some(EncodedCells { words, escaped })
    }

    /// The slots the shader visits for cell `index`, in its order.
    pub fn cell_slots(&self, index: usize) -> Vec<u32> {
        let word = self.words[index];
        if is_escape(word) {
            let at = (word >> ESCAPE_SHIFT) as usize;
            let count = self.words[at] as usize;
            return self.words[at + 1..at + 1 + count].to_vec();
        }
        unpack(word).into_iter().flat_map(Run::slots).collect()
    }
}

/// Whether a cell's word escapes to a list (`cell_curves` in the shader).
pub fn is_escape(word: u32) -> bool {
    word & 0xFF == 0 && word != 0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Contour, Outline, Segment};
    use glam::DVec2;

    /// Contours of `sizes[k]` lines each (regular polygons, far apart).
    fn layout(sizes: &[usize]) -> CurveLayout {
        let contours = sizes
            .iter()
            .enumerate()
            .map(|(c, &n)| {
                let p: Vec<DVec2> = (0..n)
                    .map(|k| {
                        let a = -(k as f64) / n as f64 * std::f64::consts::TAU;
                        DVec2::new(1000.0 * c as f64 + 100.0 * a.cos(), 100.0 * a.sin())
                    })
                    .collect();
                Contour {
                    segments: (0..n)
                        .map(|k| Segment::Line(p[k], p[(k + 1) % n]))
                        .collect(),
                }
            })
            .collect();
        CurveLayout::new(&Outline { contours })
    }

    #[test]
    fn words_follow_font_demos_bit_layout() {
        let runs = [
            Run { begin: 5, len: 3 },
            Run { begin: 200, len: 7 },
            Run { begin: 255, len: 6 },
        ];
        let word = pack(runs);
        // font-demo's decoder, verbatim in spirit.
        assert_eq!(word & 3, 3);
        assert_eq!((word >> 2) & 7, 7);
        assert_eq!((word >> 5) & 7, 6);
        assert_eq!((word >> 8) & 0xFF, 5);
        assert_eq!((word >> 16) & 0xFF, 200);
        assert_eq!((word >> 24) & 0xFF, 255);
        assert_eq!(unpack(word), runs);
    }

    #[test]
    fn packing_covers_the_list_with_the_fewest_curves() {
        // Contour 0 has slots 1..=20, contour 1 slots 24..=43.
        let layout = layout(&[20, 20]);
        let covered = |word: u32| -> Vec<u32> {
            let mut s: Vec<u32> = unpack(word).into_iter().flat_map(Run::slots).collect();
            s.sort();
            s
        };
        // Five groups in two contours: one gap is bridged, the third run takes the
        // other contour (2 + 4 + 2 curves, or 5 + 1 + 2).
        let slots = [2, 3, 5, 6, 8, 24, 25];
        let (word, total) = pack_cell(&slots, &layout).unwrap();
        assert!(slots.iter().all(|s| covered(word).contains(s)));
        assert_eq!(total, 8, "{:?}", unpack(word));
        // Runs never cross from one contour into the next.
        let (word, _) = pack_cell(&[19, 20, 24], &layout).unwrap();
        assert!(
            covered(word)
                .iter()
                .all(|s| layout.slot_contour[*s as usize].is_some())
        );
        // Four separate groups cannot be three runs once bridging overflows a loop.
        assert!(pack_cell(&[1, 10, 24, 36], &layout).is_none());
        // 18 curves never fit.
        let many: Vec<u32> = (1..=18).collect();
        assert!(pack_cell(&many, &layout).is_none());
        // 17 consecutive curves need 3 + 7 + 7 exactly.
        let (word, total) = pack_cell(&(1..=17).collect::<Vec<_>>(), &layout).unwrap();
        assert_eq!((total, covered(word)), (17, (1..=17).collect::<Vec<_>>()));
    }

    #[test]
    fn slots_past_font_demos_reach_do_not_pack() {
        // 300 curves in one contour: slots 1..=300.
        let layout = layout(&[300]);
        assert!(pack_cell(&[250, 255], &layout).is_some());
        assert!(pack_cell(&[256], &layout).is_none());
    }

    #[test]
    fn cells_the_word_cannot_hold_escape_to_a_list() {
        let layout = layout(&[300]);
        let lists = vec![vec![3, 4], vec![280], vec![], vec![5]];
        let cells = EncodedCells::new(&lists, &layout, true).unwrap();
        // The second cell escapes to its list after the four cell words.
        assert_eq!(cells.escaped, 1);
        assert_eq!(cells.words[1], 4 << 8);
        assert_eq!(&cells.words[4..], &[1, 280]);
        assert!(!is_escape(cells.words[0]) && !is_escape(cells.words[2]));
        let everything = EncodedCells::new(&lists, &layout, false).unwrap();
        assert_eq!(everything.escaped, 4);
        for (index, list) in lists.iter().enumerate() {
            assert_eq!(&cells.cell_slots(index), list);
            assert_eq!(&everything.cell_slots(index), list);
        }
    }
}
