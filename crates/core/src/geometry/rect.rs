//! Axis-aligned rectangles: bounds of outlines, views and pixels.

use glam::DVec2;

/// An axis-aligned rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    pub min: DVec2,
    pub max: DVec2,
}

impl Rect {
    pub fn enclosing(points: impl IntoIterator<Item = DVec2>) -> Option<Rect> {
        let mut it = points.into_iter();
        let first = it.next()?;
        Some(it.fold(
            Rect {
                min: first,
                max: first,
            },
            |r, p| Rect {
                min: r.min.min(p),
                max: r.max.max(p),
            },
        ))
    }

    pub fn union(self, other: Rect) -> Rect {
        Rect {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }

    pub fn corners(&self) -> [DVec2; 4] {
        [
            self.min,
            DVec2::new(self.max.x, self.min.y),
            self.max,
            DVec2::new(self.min.x, self.max.y),
        ]
    }

    pub fn overlaps(&self, other: &Rect) -> bool {
        self.min.x < other.max.x
            && other.min.x < self.max.x
            && self.min.y < other.max.y
            && other.min.y < self.max.y
    }
}

/// Groups rectangles that overlap, transitively (two rectangles apart are in one group
/// when a chain of overlapping ones joins them), by union-find over a sweep in x: each
/// group lists its rectangles' indices in increasing order, groups by their first.
pub fn overlapping_groups(rects: &[Rect]) -> Vec<Vec<usize>> {
    groups_where(rects, |_, _| true)
}

/// Like [`overlapping_groups`], but two overlapping rectangles join only where
/// `joins(a, b)` says so (their contents meet, say). `joins` is asked only of pairs
/// that overlap and are not yet in one group, so an expensive test runs no more often
/// than the groups need.
pub fn groups_where(
    rects: &[Rect],
    mut joins: impl FnMut(usize, usize) -> bool,
) -> Vec<Vec<usize>> {
    let mut parent: Vec<usize> = (0..rects.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut by_x: Vec<usize> = (0..rects.len()).collect();
    by_x.sort_by(|&a, &b| rects[a].min.x.total_cmp(&rects[b].min.x));
    for (k, &a) in by_x.iter().enumerate() {
        for &b in &by_x[k + 1..] {
            if rects[b].min.x >= rects[a].max.x {
                break;
            }
            if rects[a].overlaps(&rects[b]) {
                let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                if ra != rb && joins(a, b) {
                    parent[ra] = rb;
                }
            }
        }
    }
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut group_of_root = vec![usize::MAX; rects.len()];
    for i in 0..rects.len() {
        let r = root(&mut parent, i);
        if group_of_root[r] == usize::MAX {
            group_of_root[r] = groups.len();
            groups.push(Vec::new());
        }
        groups[group_of_root[r]].push(i);
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f64, x1: f64, y0: f64, y1: f64) -> Rect {
        Rect {
            min: DVec2::new(x0, y0),
            max: DVec2::new(x1, y1),
        }
    }

    /// A chain joins its ends; touching edges are not an overlap; a rectangle that
    /// overlaps in x but not in y stays alone.
    #[test]
    fn groups_are_chains_of_overlaps() {
        let rects = [
            rect(0.0, 2.0, 0.0, 1.0),
            rect(10.0, 11.0, 0.0, 1.0),
            rect(1.0, 3.0, 0.0, 1.0),
            rect(2.5, 4.0, 0.0, 1.0),
            rect(4.0, 5.0, 0.0, 1.0),
            rect(0.0, 4.0, 2.0, 3.0),
        ];
        assert_eq!(
            overlapping_groups(&rects),
            vec![vec![0, 2, 3], vec![1], vec![4], vec![5]]
        );
        assert!(overlapping_groups(&[]).is_empty());
        // Asked only of overlapping pairs in different groups: 0–2 and 2–3 overlap,
        // 0–2 is refused, 2–3 joined.
        let mut asked = Vec::new();
        let groups = groups_where(&rects, |a, b| {
            asked.push((a.min(b), a.max(b)));
            (a.min(b), a.max(b)) == (2, 3)
        });
        asked.sort();
        assert_eq!(asked, vec![(0, 2), (2, 3)]);
        assert_eq!(groups, vec![vec![0], vec![1], vec![2, 3], vec![4], vec![5]]);
    }
}
