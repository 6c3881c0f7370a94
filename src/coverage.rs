//! Coverage images: one linear coverage value in [0, 1] per pixel, row-major, y down.

use std::path::Path;

use crate::Error;

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

    /// 8-bit grayscale, linear (255 = covered), no gamma.
    pub fn to_gray8(&self) -> image::GrayImage {
        let pixels = self
            .data
            .iter()
            .map(|&v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
            .collect();
        image::GrayImage::from_raw(self.width, self.height, pixels).expect("size matches")
    }

    pub fn from_gray8(img: &image::GrayImage) -> Self {
        CoverageImage {
            width: img.width(),
            height: img.height(),
            data: img.as_raw().iter().map(|&v| f32::from(v) / 255.0).collect(),
        }
    }

    pub fn save_png(&self, path: &Path) -> Result<(), Error> {
        self.to_gray8()
            .save(path)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))
    }

    pub fn load_png(path: &Path) -> Result<Self, Error> {
        let img = image::open(path)
            .map_err(|e| Error::Input(format!("cannot read image '{}': {e}", path.display())))?;
        Ok(Self::from_gray8(&img.to_luma8()))
    }
}
