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
}
