//! Coverage images: one linear coverage value in [0, 1] per pixel, row-major, y down.

/// The values of an image before any clamp (see [`CoverageImage::range`]).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ValueRange {
    /// Smallest and largest finite value (∞ and −∞ when there is none).
    pub min: f64,
    pub max: f64,
    /// NaN and infinite values.
    pub non_finite: usize,
}

impl ValueRange {
    /// Whether every value is finite and within [lo, hi].
    pub fn within(&self, lo: f64, hi: f64) -> bool {
        self.non_finite == 0 && (self.min >= lo || self.min.is_infinite()) && self.max <= hi
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct CoverageImage {
    pub width: u32,
    pub height: u32,
    pub data: Vec<f32>,
}

impl CoverageImage {
    pub fn new(width: u32, height: u32) -> Self {
        CoverageImage {
            width,
            height,
            data: vec![0.0; width as usize * height as usize],
        }
    }

    pub fn get(&self, x: u32, y: u32) -> f32 {
        self.data[y as usize * self.width as usize + x as usize]
    }

    /// Total covered area in pixels.
    pub fn sum(&self) -> f64 {
        self.data.iter().map(|&v| f64::from(v)).sum()
    }

    /// What the values are before anything is clamped: the smallest and largest finite
    /// value, and how many are not finite.
    pub fn range(&self) -> ValueRange {
        let mut range = ValueRange {
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
            non_finite: 0,
        };
        for &v in &self.data {
            if v.is_finite() {
                range.min = range.min.min(f64::from(v));
                range.max = range.max.max(f64::from(v));
            } else {
                range.non_finite += 1;
            }
        }
        range
    }

    /// Takes coverage above 1 down to 1: where a method adds overlapping instances'
    /// coverage up, their union is at most 1. Nothing else is touched — a negative or
    /// non-finite value stays, for the metrics to count as the artifact it is.
    pub fn clamp_to_union(mut self) -> Self {
        for v in &mut self.data {
            if *v > 1.0 {
                *v = 1.0;
            }
        }
        self
    }
}
