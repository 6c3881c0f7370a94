//! A texture of per-glyph images, one quad per instance sampling its glyph's image:
//! the atlas baseline's coverage bitmaps and msdf's distance fields are packed,
//! uploaded, described to the shader (`shaders/glyph_atlas.wgsl`) and bound the same
//! way. Each image is a raster with rows top first, and knows where its glyph's local
//! origin lies in it.

use glam::DVec2;

use crate::gpu::GpuContext;
use crate::gpu::kit::{self, PerTarget, Slot};
use crate::gpu::shaders::Shader;

/// One glyph image's place in the atlas: `Entry` in `glyph_atlas.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Entry {
    quad: [f32; 4],
    origin: [f32; 2],
    texels_per_unit: f32,
    _pad: f32,
    texels: [f32; 4],
}

impl Entry {
    /// An image of `size` texels placed with its top-left texel at `corner`, whose
    /// glyph's local origin lies at `origin` in it (texels, y down), at
    /// `texels_per_unit` texels per font unit.
    pub fn new(size: (u32, u32), corner: (u32, u32), origin: DVec2, texels_per_unit: f64) -> Entry {
        let (w, h) = (f64::from(size.0), f64::from(size.1));
        // Image texel (X, Y) shows local (x, y) = ((X − ox) / s, (oy − Y) / s).
        let quad = [-origin.x, origin.y - h, w - origin.x, origin.y].map(|v| v / texels_per_unit);
        let corner = DVec2::new(f64::from(corner.0), f64::from(corner.1));
        Entry {
            quad: quad.map(|v| v as f32),
            origin: (corner + origin).as_vec2().to_array(),
            texels_per_unit: texels_per_unit as f32,
            _pad: 0.0,
            texels: [corner.x, corner.y, corner.x + w, corner.y + h].map(|v| v as f32),
        }
    }
}

/// What a method drawing from a glyph atlas keeps of its pipeline: the layout of
/// `@group(1)` (entries, texture, sampler), the module, its pipelines per target and a
/// bilinear sampler.
pub struct AtlasPipeline {
    pub layout: wgpu::BindGroupLayout,
    pub pipeline_layout: wgpu::PipelineLayout,
    pub module: wgpu::ShaderModule,
    pub pipelines: PerTarget<wgpu::RenderPipeline>,
    pub sampler: wgpu::Sampler,
}

impl AtlasPipeline {
    pub fn new(gpu: &GpuContext, label: &str, shader: &Shader) -> AtlasPipeline {
        let layout = kit::layout(gpu, label, &[Slot::Storage, Slot::Texture, Slot::Sampler]);
        let pipeline_layout = kit::pipeline_layout(gpu, label, Some(&layout));
        let sampler = gpu.device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some(label),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        AtlasPipeline {
            module: shader.module(&gpu.device),
            layout,
            pipeline_layout,
            pipelines: PerTarget::default(),
            sampler,
        }
    }

    /// `@group(1)`: the entries and the texture.
    pub fn bind_group(
        &self,
        gpu: &GpuContext,
        label: &str,
        entries: &wgpu::Buffer,
        texture: &wgpu::Texture,
    ) -> wgpu::BindGroup {
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        kit::bind_group(
            gpu,
            label,
            &self.layout,
            &[
                entries.as_entire_binding(),
                wgpu::BindingResource::TextureView(&view),
                wgpu::BindingResource::Sampler(&self.sampler),
            ],
        )
    }
}

/// Where each image goes in the texture.
pub struct Shelves {
    pub width: u32,
    pub height: u32,
    /// Each image's top-left texel, in the images' order.
    pub corners: Vec<(u32, u32)>,
}

/// Shelf packing of images of `sizes`, tallest first, into a texture about as wide as
/// it is tall; None if it would need a side over `max_side`. Each image carries its own
/// border, so they can touch. Worked out from the sizes alone, before anything is
/// drawn: a cache that cannot fit is refused at once.
pub fn pack(sizes: &[(u32, u32)], max_side: u32) -> Option<Shelves> {
    let area: u64 = sizes
        .iter()
        .map(|&(w, h)| u64::from(w) * u64::from(h))
        .sum();
    let widest = sizes.iter().map(|s| s.0).max().unwrap_or(1);
    let width = ((area as f64).sqrt() * 1.1).ceil().max(f64::from(widest));
    if width > f64::from(max_side) {
        return None;
    }
    let width = width as u32;
    let mut order: Vec<usize> = (0..sizes.len()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(sizes[i].1));
    let mut corners = vec![(0, 0); sizes.len()];
    let (mut x, mut y, mut shelf_height) = (0u32, 0u32, 0u32);
    for &i in &order {
        let (w, h) = sizes[i];
        if x + w > width {
            (x, y, shelf_height) = (0, y + shelf_height, 0);
        }
        corners[i] = (x, y);
        x += w;
        shelf_height = shelf_height.max(h);
    }
    let height = (y + shelf_height).max(1);
    (height <= max_side).then_some(Shelves {
        width,
        height,
        corners,
    })
}

impl Shelves {
    /// The texture's bytes: each image, given as its width and its rows of
    /// `texel_bytes`-byte texels, at its corner; zero elsewhere.
    pub fn fill<'a>(
        &self,
        images: impl IntoIterator<Item = (u32, &'a [u8])>,
        texel_bytes: usize,
    ) -> Vec<u8> {
        let row_bytes = self.width as usize * texel_bytes;
        let mut texels = vec![0u8; row_bytes * self.height as usize];
        for ((width, bytes), &(x, y)) in images.into_iter().zip(&self.corners) {
            let line_bytes = width as usize * texel_bytes;
            for (row, line) in bytes.chunks_exact(line_bytes).enumerate() {
                let start = (y as usize + row) * row_bytes + x as usize * texel_bytes;
                texels[start..start + line.len()].copy_from_slice(line);
            }
        }
        texels
    }

    /// A sampled texture of `format` holding `texels` (from [`Shelves::fill`]).
    pub fn upload(
        &self,
        gpu: &GpuContext,
        label: &str,
        format: wgpu::TextureFormat,
        texels: &[u8],
    ) -> wgpu::Texture {
        kit::sampled_texture(gpu, label, [self.width, self.height], format, texels)
    }

    /// The texture's size in bytes at `texel_bytes` a texel.
    pub fn bytes(&self, texel_bytes: u64) -> u64 {
        u64::from(self.width) * u64::from(self.height) * texel_bytes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_images_never_overlap_and_fill_puts_each_at_its_corner() {
        let sizes = [(3, 2), (1, 4), (2, 2), (5, 1)];
        let packed = pack(&sizes, 64).expect("fits");
        for (i, (&(w, h), &(x, y))) in sizes.iter().zip(&packed.corners).enumerate() {
            assert!(
                x + w <= packed.width && y + h <= packed.height,
                "image {i} inside"
            );
            for (j, (&(w2, h2), &(x2, y2))) in sizes.iter().zip(&packed.corners).enumerate() {
                let apart = x + w <= x2 || x2 + w2 <= x || y + h <= y2 || y2 + h2 <= y;
                assert!(i == j || apart, "images {i} and {j} overlap");
            }
        }
        // Two bytes a texel, each image filled with its own index + 1.
        let images: Vec<Vec<u8>> = sizes
            .iter()
            .enumerate()
            .map(|(i, &(w, h))| vec![i as u8 + 1; (w * h * 2) as usize])
            .collect();
        let texels = packed.fill(sizes.iter().zip(&images).map(|(s, b)| (s.0, &b[..])), 2);
        let at = |x: u32, y: u32| texels[((y * packed.width + x) * 2) as usize];
        for (i, (&(w, h), &(x, y))) in sizes.iter().zip(&packed.corners).enumerate() {
            assert_eq!(at(x, y), i as u8 + 1);
            assert_eq!(at(x + w - 1, y + h - 1), i as u8 + 1);
        }
        let filled = texels.iter().filter(|&&b| b != 0).count();
        let area: u32 = sizes.iter().map(|&(w, h)| w * h * 2).sum();
        assert_eq!(filled, area as usize);
    }

    #[test]
    fn a_texture_over_the_largest_side_is_refused() {
        assert!(pack(&[(65, 1)], 64).is_none());
        assert!(pack(&[(8, 8); 100], 64).is_none());
    }
}
