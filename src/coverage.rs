//! Coverage images (`glyphscope_core::coverage`) and their 8-bit PNG files, which only
//! the command line, the lab and the explorer write and read.

use std::path::Path;

pub use glyphscope_core::coverage::*;

use crate::Error;

/// A coverage image as an 8-bit grayscale PNG: linear (255 = covered), no gamma.
pub trait Png: Sized {
    /// 8-bit grayscale, each value clamped to [0, 1] and rounded.
    fn to_gray8(&self) -> image::GrayImage;
    /// The coverage an 8-bit grayscale image holds.
    fn from_gray8(img: &image::GrayImage) -> Self;
    /// Writes [`Png::to_gray8`] to `path`.
    fn save_png(&self, path: &Path) -> Result<(), Error>;
    /// Reads a PNG (any colour type, taken as luma).
    fn load_png(path: &Path) -> Result<Self, Error>;
}

impl Png for CoverageImage {
    fn to_gray8(&self) -> image::GrayImage {
        let pixels = self
            .data
            .iter()
            .map(|&v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
            .collect();
        image::GrayImage::from_raw(self.width, self.height, pixels).expect("size matches")
    }

    fn from_gray8(img: &image::GrayImage) -> Self {
        CoverageImage {
            width: img.width(),
            height: img.height(),
            data: img.as_raw().iter().map(|&v| f32::from(v) / 255.0).collect(),
        }
    }

    fn save_png(&self, path: &Path) -> Result<(), Error> {
        self.to_gray8()
            .save(path)
            .map_err(|e| Error::Output(format!("cannot write '{}': {e}", path.display())))
    }

    fn load_png(path: &Path) -> Result<Self, Error> {
        let img = image::open(path)
            .map_err(|e| Error::Input(format!("cannot read image '{}': {e}", path.display())))?;
        Ok(Self::from_gray8(&img.to_luma8()))
    }
}

/// The overlay picture of a [`Channels::Picture`](crate::gpu::Channels::Picture)
/// target ([`CoverageTarget::readback_rgb8`](crate::gpu::CoverageTarget::readback_rgb8)) as an RGB image.
pub fn read_overlay(
    gpu: &crate::gpu::GpuContext,
    target: &crate::gpu::CoverageTarget,
) -> Result<image::RgbImage, Error> {
    let rgb = target.readback_rgb8(gpu)?;
    Ok(image::RgbImage::from_raw(target.width, target.height, rgb).expect("size matches"))
}
