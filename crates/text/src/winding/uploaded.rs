//! `@group(1)` of crates/text/shaders/winding.wgsl: a [`GlyphData`] on the GPU, as the `winding` row
//! and the text library both bind it. The glyphs, read once per quad, are a storage
//! buffer; the bands, read once per fragment, the band lists and the curves, read at
//! every step of a pixel's walk, are data textures ([`kit::data_texture`]): on lavapipe
//! the walk reads them 2× faster than from storage buffers (the library bench's 500
//! moving labels: the walk 46.7 → 20.2 ms); SwiftShader's frame did not change beyond
//! its runs' noise. docs/methods/winding.md has the figures and their commands. A GPU's
//! texture path reads them as fast as its storage path, or faster. For `aa=area`, two
//! more hold each list entry's curve inline: its end points, all its walk reads, and
//! the rest, read for the curves across the pixel only
//! ([`GlyphData::band_entries_inline`]).

use super::bands::GlyphData;
use crate::Error;
use crate::gpu::GpuContext;
use crate::gpu::kit::{self, Slot};

/// The layout of `@group(1)`: glyphs (storage), bands, band curves, curves, band
/// entries' end points, their other halves (textures).
pub fn group_layout(gpu: &GpuContext, label: &str) -> wgpu::BindGroupLayout {
    kit::layout(
        gpu,
        label,
        &[
            Slot::Storage,
            Slot::DataTexture,
            Slot::DataTexture,
            Slot::DataTexture,
            Slot::DataTexture,
            Slot::DataTexture,
        ],
    )
}

/// `data` uploaded and bound in a layout made by [`group_layout`].
pub struct Uploaded {
    /// Keeps what it binds alive.
    pub bind_group: wgpu::BindGroup,
    /// Bytes on the GPU, row padding included.
    pub bytes: u64,
}

impl Uploaded {
    /// Uploads `data`. Band lists or curves too many for the device's tallest texture
    /// are an [`Error::Gpu`] that says so.
    pub fn new(
        gpu: &GpuContext,
        label: &str,
        data: &GlyphData,
        layout: &wgpu::BindGroupLayout,
    ) -> Result<Uploaded, Error> {
        let storage = wgpu::BufferUsages::STORAGE;
        let glyphs = gpu.buffer_of(&format!("{label} glyphs"), &data.glyphs, storage);
        // A band a texel: its two orderings' offsets and its count.
        let band_texels: Vec<[u32; 4]> = data
            .bands
            .iter()
            .map(|b| [b.by_max, b.by_min, b.count, 0])
            .collect();
        // aa=rays never reads them.
        let (ends, middles) = if data.area {
            data.band_entries_inline()
        } else {
            (Vec::new(), Vec::new())
        };
        use wgpu::TextureFormat::{R32Uint, Rgba32Uint};
        let textures = [
            texture(gpu, label, "bands", &band_texels, Rgba32Uint)?,
            texture(gpu, label, "band curves", &data.band_curves, R32Uint)?,
            texture(gpu, label, "curves", &data.curves, Rgba32Uint)?,
            texture(gpu, label, "band ends", &ends, Rgba32Uint)?,
            texture(gpu, label, "band middles", &middles, Rgba32Uint)?,
        ];
        let views = textures
            .each_ref()
            .map(|(t, _)| t.create_view(&Default::default()));
        let entries: Vec<wgpu::BindingResource> = std::iter::once(glyphs.as_entire_binding())
            .chain(views.iter().map(wgpu::BindingResource::TextureView))
            .collect();
        let bind_group = kit::bind_group(gpu, label, layout, &entries);
        Ok(Uploaded {
            bind_group,
            bytes: glyphs.size() + textures.iter().map(|(_, bytes)| bytes).sum::<u64>(),
        })
    }
}

/// `items` as a data texture named `name`; none as one zeroed texel (a texture cannot
/// be empty, and a glyph of no curves binds one all the same).
fn texture<T: bytemuck::Pod>(
    gpu: &GpuContext,
    label: &str,
    name: &str,
    items: &[T],
    format: wgpu::TextureFormat,
) -> Result<(wgpu::Texture, u64), Error> {
    let zero = [T::zeroed()];
    let items = if items.is_empty() { &zero[..] } else { items };
    kit::data_texture(gpu, &format!("{label} {name}"), items, format)
}

#[cfg(test)]
mod tests {
    use crate::gpu::kit::DATA_TEXTURE_WIDTH;

    /// The shader finds a texel by a shift that must be the row width the textures are
    /// laid out with.
    #[test]
    fn the_shader_reads_rows_as_wide_as_they_are_laid_out() {
        let source = include_str!("../../shaders/winding.wgsl");
        let line = source
            .lines()
            .find(|l| l.starts_with("const DATA_ROW_SHIFT: u32 = "))
            .expect("winding.wgsl declares DATA_ROW_SHIFT");
        let shift: u32 = line
            .trim_start_matches("const DATA_ROW_SHIFT: u32 = ")
            .trim_end_matches("u;")
            .parse()
            .expect("a number");
        assert_eq!(1 << shift, DATA_TEXTURE_WIDTH);
    }
}
