//! Written by `glyphscope stability --out DIR` (the full sweep) as
//! `DIR/worst-cameras.rs`, and pasted here: the camera where each method was worst on
//! each case, which the CI grid runs besides its own.

use super::cases::WorstCamera;

pub const WORST_CAMERAS: &[WorstCamera] = &[];
