//! The quadratic Bézier ([`Quad`]) and the signed area a closed chain of them encloses.

use glam::DVec2;

/// A quadratic Bézier: start, control, end.
pub type Quad = [DVec2; 3];

/// Signed area enclosed by a closed chain of quadratics (positive counter-clockwise,
/// y up): the polygon of their endpoints plus, for each, the parabolic segment between
/// the curve and its chord, 2/3 of its control triangle.
pub fn signed_area(contour: &[Quad]) -> f64 {
    contour
        .iter()
        .map(|[a, b, c]| 0.5 * a.perp_dot(*c) + (b - a).perp_dot(c - a) / 3.0)
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parabola_area_is_two_thirds_of_its_triangle() {
        // y = x(2 - x)·… : the chord (0,0)-(2,0) and control (1,2) enclose 4/3.
        let q = [DVec2::ZERO, DVec2::new(1.0, 2.0), DVec2::new(2.0, 0.0)];
        let back = [DVec2::new(2.0, 0.0), DVec2::new(1.0, 0.0), DVec2::ZERO];
        assert!((signed_area(&[q, back]) + 4.0 / 3.0).abs() < 1e-12);
    }
}
