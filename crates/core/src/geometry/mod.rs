//! Bézier geometry, written once and shared by the reference, the methods' CPU
//! preparation and the tests. Curve evaluation, splitting, flattening and bounds come
//! from lyon_geom; what is ours is the outline model, the error-bounded conversion
//! policy around it, and the quadratic's own math.
//!
//! The files point one way, from the leaves up: `rect`, `distance` and `quadratic`
//! import nothing of the folder; `segment` the quadratic; `projection` the rectangle;
//! `cubic` segments and distances; `outline` segments, the conversion and rectangles;
//! `overlaps` the outline and segments. This file only names them and lists what the
//! crate sees.

mod cubic;
mod distance;
mod outline;
mod overlaps;
mod projection;
mod quadratic;
mod rect;
mod segment;

pub use cubic::{DEFAULT_QUAD_TOLERANCE_EM, cubic_to_quadratics, max_distance_to_cubic};
pub use distance::{distance_between_segments, distance_to_segment};
pub use outline::{Contour, Outline, kurbo_path};
pub use overlaps::{inks_overlap, merge_overlaps};
pub use projection::{jacobian_bound, keeps_axes, project, steps_lean_apart};
pub use quadratic::{
    Quad, blossom_value, chord_deviation, halved_until_flat, integral_x_dy, line_as_quad, monomial,
    monotone_pieces, point_at, signed_area, subcurve, t_at, winding_number,
};
pub use rect::{Rect, groups_where, overlapping_groups};
pub use segment::{Segment, segment_points};
pub use segment::{from_lyon, lyon_cubic, lyon_quad, to_lyon};
