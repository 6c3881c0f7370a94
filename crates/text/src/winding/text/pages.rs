//! Where the text library's runs keep their coverage between `prepare` and `render`:
//! each run's rectangle of pixels packed into pages of a half-float array (shelf
//! packing, tallest first), so that what is drawn, cleared and composited grows with
//! the pixels the text covers, not with the number of runs times the viewport; and the
//! composite that blends each run's colour through its rectangle (`winding_text.wgsl`).

use crate::gpu::{Channels, GpuContext, kit};

/// A rectangle of whole pixels, [x0, x1) × [y0, y1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelRect {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

impl PixelRect {
    pub fn width(&self) -> u32 {
        self.x1 - self.x0
    }

    pub fn height(&self) -> u32 {
        self.y1 - self.y0
    }

    /// Whether the two share a pixel.
    pub fn meets(&self, other: &PixelRect) -> bool {
        self.x0 < other.x1 && other.x0 < self.x1 && self.y0 < other.y1 && other.y0 < self.y1
    }
}

/// Where a run's rectangle lies in the pages: which page, and its top-left corner there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Placement {
    pub page: u32,
    pub origin: [u32; 2],
}

/// Packs `rects` (each no larger than `page`) into pages of `page` pixels, in shelves
/// filled tallest first; writes each one's placement into `placements` (in `rects`'
/// order) and returns how many pages they take and how much of the pages' height they
/// use (the first page's, where there is one; all of it where there are more). `order`
/// is scratch space.
pub fn pack(
    rects: &[PixelRect],
    page: [u32; 2],
    order: &mut Vec<u32>,
    placements: &mut Vec<Placement>,
) -> (u32, u32) {
    order.clear();
    order.extend(0..rects.len() as u32);
    order.sort_by_key(|&i| std::cmp::Reverse(rects[i as usize].height()));
    placements.clear();
    placements.resize(rects.len(), Placement::default());
    let (mut page_index, mut x, mut y, mut shelf) = (0u32, 0u32, 0u32, 0u32);
    let mut used = 0u32;
    for &i in order.iter() {
        let (w, h) = (rects[i as usize].width(), rects[i as usize].height());
        debug_assert!(w <= page[0] && h <= page[1]);
        if x + w > page[0] {
            // The next shelf, below the tallest of this one.
            (x, y, shelf) = (0, y + shelf, 0);
        }
        if y + h > page[1] {
            (page_index, x, y, shelf) = (page_index + 1, 0, 0, 0);
        }
        placements[i as usize] = Placement {
            page: page_index,
            origin: [x, y],
        };
        x += w;
        shelf = shelf.max(h);
        used = if page_index > 0 {
            page[1]
        } else {
            used.max(y + h)
        };
    }
    let pages = if rects.is_empty() { 0 } else { page_index + 1 };
    (pages, used)
}

/// `CompositeRun` of `winding_text.wgsl`: a run's rectangle in the caller's target, where
/// its coverage lies, and its premultiplied colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct CompositeRun {
    pub screen: [f32; 4],
    pub offset: [i32; 2],
    pub page: u32,
    _pad: u32,
    pub colour: [f32; 4],
}

impl CompositeRun {
    pub fn new(rect: PixelRect, placement: Placement, colour: [f32; 4]) -> CompositeRun {
        let offset = |origin: u32, at: u32| origin as i32 - at as i32;
        CompositeRun {
            screen: [rect.x0, rect.y0, rect.x1, rect.y1].map(|v| v as f32),
            offset: [
                offset(placement.origin[0], rect.x0),
                offset(placement.origin[1], rect.y0),
            ],
            page: placement.page,
            _pad: 0,
            colour,
        }
    }
}

/// The composite's bind group layout and pipeline, for the caller's format.
pub struct Composite {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
}

impl Composite {
    pub fn new(
        gpu: &GpuContext,
        module: &wgpu::ShaderModule,
        format: wgpu::TextureFormat,
    ) -> Composite {
        let device = &gpu.device;
        let entry = |binding, visibility, ty| wgpu::BindGroupLayoutEntry {
            binding,
            visibility,
            ty,
            count: None,
        };
        let both = wgpu::ShaderStages::VERTEX;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("text composite"),
            entries: &[
                entry(
                    0,
                    wgpu::ShaderStages::FRAGMENT,
                    wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2Array,
                        multisampled: false,
                    },
                ),
                entry(
                    1,
                    both,
                    wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: true },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                ),
                entry(
                    2,
                    wgpu::ShaderStages::VERTEX,
                    wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                ),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("text composite"),
            bind_group_layouts: &[None, None, Some(&layout)],
            immediate_size: 0,
        });
        // Each run's colour, premultiplied, over what the caller drew.
        let pipeline = kit::PipelineBuilder::new("text composite", &pipeline_layout, module)
            .entry_points("vs_composite", "fs_composite")
            .topology(wgpu::PrimitiveTopology::TriangleStrip)
            .build_into(
                device,
                wgpu::ColorTargetState {
                    format,
                    blend: Some(wgpu::BlendState::PREMULTIPLIED_ALPHA_BLENDING),
                    write_mask: wgpu::ColorWrites::ALL,
                },
            );
        Composite { layout, pipeline }
    }
}

/// The pages, the runs' composite records and the caller's target size on the GPU.
pub struct Pages {
    /// Each page's size, pixels.
    pub size: [u32; 2],
    pub count: u32,
    /// One view per page, to draw coverage into.
    pub views: Vec<wgpu::TextureView>,
    runs: wgpu::Buffer,
    target_size: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
}

impl Pages {
    /// Pages that hold `count` pages of at least `size` and `runs` composite records:
    /// `current` where it does, else made anew (at least twice the records, and twice
    /// the height up to `most`, so that a growing UI does not make them every frame).
    pub fn fitting(
        current: Option<Pages>,
        gpu: &GpuContext,
        composite: &Composite,
        size: [u32; 2],
        most: [u32; 2],
        count: u32,
        runs: usize,
    ) -> Pages {
        let room = |p: &Pages| (p.runs.size() as usize) / size_of::<CompositeRun>();
        let holds = |p: &Pages| p.size[0] >= size[0] && p.size[1] >= size[1];
        match current {
            Some(p)
                if holds(&p) && p.size[0] <= most[0] && p.count >= count && room(&p) >= runs =>
            {
                p
            }
            current => {
                let runs = match &current {
                    Some(p) if room(p) >= runs => room(p),
                    _ => runs.max(16).next_power_of_two(),
                };
                let (size, count) = match &current {
                    Some(p) if p.size[0] == size[0] => (
                        [size[0], size[1].max(2 * p.size[1]).min(most[1])],
                        count.max(p.count),
                    ),
                    _ => (size, count),
                };
                Pages::new(gpu, composite, size, count.max(1), runs)
            }
        }
    }

    fn new(
        gpu: &GpuContext,
        composite: &Composite,
        size: [u32; 2],
        count: u32,
        runs: usize,
    ) -> Pages {
        let device = &gpu.device;
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("text coverage pages"),
            size: wgpu::Extent3d {
                width: size[0],
                height: size[1],
                depth_or_array_layers: count,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: Channels::Coverage.format(),
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let page_view = |layer| {
            texture.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2),
                base_array_layer: layer,
                array_layer_count: Some(1),
                ..Default::default()
            })
        };
        let views = (0..count).map(page_view).collect();
        let array = texture.create_view(&wgpu::TextureViewDescriptor {
            dimension: Some(wgpu::TextureViewDimension::D2Array),
            ..Default::default()
        });
        let runs = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("text runs"),
            size: (runs * size_of::<CompositeRun>()) as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let target_size = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("text target size"),
            size: 16,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("text composite"),
            layout: &composite.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&array),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: runs.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: target_size.as_entire_binding(),
                },
            ],
        });
        Pages {
            size,
            count,
            views,
            runs,
            target_size,
            bind_group,
        }
    }

    /// Writes the runs' composite records and the target's size; the bytes uploaded.
    pub fn write(&self, gpu: &GpuContext, viewport: [u32; 2], runs: &[CompositeRun]) -> u64 {
        let size = [viewport[0] as f32, viewport[1] as f32, 0.0, 0.0];
        gpu.queue
            .write_buffer(&self.target_size, 0, bytemuck::cast_slice(&size));
        if !runs.is_empty() {
            gpu.queue
                .write_buffer(&self.runs, 0, bytemuck::cast_slice(runs));
        }
        (size_of_val(&size) + size_of_val(runs)) as u64
    }

    /// Records the composite of the first `runs` records into `pass`.
    pub fn composite(&self, composite: &Composite, pass: &mut wgpu::RenderPass<'_>, runs: u32) {
        if runs == 0 {
            return;
        }
        pass.set_pipeline(&composite.pipeline);
        pass.set_bind_group(2, &self.bind_group, &[]);
        pass.draw(0..4, 0..runs);
    }

    /// Bytes held on the GPU: the pages, the records and the size.
    pub fn gpu_bytes(&self) -> u64 {
        let texel = u64::from(Channels::Coverage.texel_bytes());
        let pages =
            u64::from(self.size[0]) * u64::from(self.size[1]) * u64::from(self.count) * texel;
        pages + self.runs.size() + self.target_size.size()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(w: u32, h: u32) -> PixelRect {
        PixelRect {
            x0: 5,
            y0: 7,
            x1: 5 + w,
            y1: 7 + h,
        }
    }

    /// No two placed rectangles share a pixel, each lies inside its page, and the pages
    /// counted are the pages used: checked pixel by pixel on small pages.
    #[test]
    fn packed_rectangles_never_overlap_and_fit_their_pages() {
        let page = [40, 30];
        // Sizes from a fixed sequence, up to a whole page.
        let mut seed = 12345u32;
        let mut next = |n: u32| {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12345);
            1 + (seed >> 16) % n
        };
        let rects: Vec<PixelRect> = (0..200).map(|_| rect(next(40), next(30))).collect();
        let (mut order, mut placements) = (Vec::new(), Vec::new());
        let (pages, used) = pack(&rects, page, &mut order, &mut placements);
        assert!(used <= page[1] && (pages <= 1 || used == page[1]));
        let mut owner = vec![None; (pages * 40 * 30) as usize];
        for (i, (r, p)) in rects.iter().zip(&placements).enumerate() {
            assert!(p.page < pages);
            assert!(p.origin[0] + r.width() <= page[0] && p.origin[1] + r.height() <= page[1]);
            for y in p.origin[1]..p.origin[1] + r.height() {
                for x in p.origin[0]..p.origin[0] + r.width() {
                    let at = &mut owner[((p.page * 30 + y) * 40 + x) as usize];
                    assert_eq!(*at, None, "rectangles {i} and {at:?} share a pixel");
                    *at = Some(i);
                }
            }
        }
        let used: std::collections::BTreeSet<u32> = placements.iter().map(|p| p.page).collect();
        assert_eq!(used.len() as u32, pages);
        // The area packed is at least a third of the pages' (shelves waste, not pages).
        let area: u32 = rects.iter().map(|r| r.width() * r.height()).sum();
        assert!(
            area * 3 >= (pages - 1) * 40 * 30,
            "{area} px in {pages} pages"
        );
    }

    #[test]
    fn nothing_packs_into_no_pages() {
        let (mut order, mut placements) = (Vec::new(), Vec::new());
        assert_eq!(pack(&[], [64, 64], &mut order, &mut placements), (0, 0));
        let one = [rect(64, 20)];
        assert_eq!(pack(&one, [64, 64], &mut order, &mut placements), (1, 20));
        assert_eq!(
            placements,
            [Placement {
                page: 0,
                origin: [0, 0]
            }]
        );
    }
}
