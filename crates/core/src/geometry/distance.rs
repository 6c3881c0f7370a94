//! Distances between points and straight segments.

use glam::DVec2;

/// Distance from `p` to the segment [a, b].
pub fn distance_to_segment(p: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + ab * t).distance(p)
}

/// The distance between the segments [p, q] and [r, s]: 0 where they cross, else the
/// nearest of each one's ends to the other segment (the nearest points of two segments
/// that do not cross include an end of one of them).
pub fn distance_between_segments(p: DVec2, q: DVec2, r: DVec2, s: DVec2) -> f64 {
    let side = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    if side(p, q, r) * side(p, q, s) < 0.0 && side(r, s, p) * side(r, s, q) < 0.0 {
        return 0.0;
    }
    distance_to_segment(p, r, s)
        .min(distance_to_segment(q, r, s))
        .min(distance_to_segment(r, p, q))
        .min(distance_to_segment(s, p, q))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn distance_to_a_segment_is_to_its_nearest_point() {
        let (a, b) = (v(0.0, 0.0), v(10.0, 0.0));
        // Above the inside: straight down; beyond an end: to that end (a 3-4-5 triangle).
        assert_eq!(distance_to_segment(v(5.0, 3.0), a, b), 3.0);
        assert_eq!(distance_to_segment(v(13.0, 4.0), a, b), 5.0);
        assert_eq!(distance_to_segment(v(-3.0, -4.0), a, b), 5.0);
        // A segment that is a point: the distance to it.
        assert_eq!(distance_to_segment(v(3.0, 4.0), a, a), 5.0);
    }

    #[test]
    fn distance_between_segments_by_hand() {
        // An X: they cross.
        let cross = distance_between_segments(v(0.0, 0.0), v(2.0, 2.0), v(0.0, 2.0), v(2.0, 0.0));
        assert_eq!(cross, 0.0);
        // A T whose stem stops 2 short of the bar.
        let t = distance_between_segments(v(0.0, 0.0), v(10.0, 0.0), v(5.0, 2.0), v(5.0, 7.0));
        assert_eq!(t, 2.0);
        // Parallel, 3 apart; on one line, 3 apart end to end.
        let parallel =
            distance_between_segments(v(0.0, 0.0), v(4.0, 0.0), v(1.0, 3.0), v(6.0, 3.0));
        assert_eq!(parallel, 3.0);
        let in_line = distance_between_segments(v(0.0, 0.0), v(1.0, 0.0), v(4.0, 0.0), v(6.0, 0.0));
        assert_eq!(in_line, 3.0);
        // Apart diagonally: end (4, 0) to end (7, 4), a 3-4-5 triangle.
        let apart = distance_between_segments(v(0.0, 0.0), v(4.0, 0.0), v(7.0, 4.0), v(9.0, 9.0));
        assert_eq!(apart, 5.0);
    }
}
