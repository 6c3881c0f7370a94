//! The text library's prepared glyphs: every distinct outline of every font met so far
//! (joined groups included), prepared once as the `winding` row prepares it, uploaded
//! when new ones arrive, and compacted by a trim when many are no longer drawn.

use std::collections::HashMap;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};

use super::super::uploaded::Uploaded;
use super::super::{BandCount, GlyphData, Layout};
use crate::Error;
use crate::geometry::{Outline, Rect};
use crate::gpu::GpuContext;
use crate::scene::Glyph;

/// One prepared glyph, kept so that a compaction can prepare it again.
struct Kept {
    key: (usize, u64),
    outline: Outline,
    /// The outline is a nonzero union ([`GlyphData::push_union`]).
    union: bool,
    units_per_em: f64,
}

#[derive(Default)]
pub struct PreparedGlyphs {
    data: GlyphData,
    index: HashMap<(usize, u64), u32>,
    kept: Vec<Kept>,
    bounds: Vec<Rect>,
    /// How many glyphs the buffers bound by `group` hold.
    uploaded: usize,
    group: Option<wgpu::BindGroup>,
    buffer_bytes: u64,
}

impl PreparedGlyphs {
    /// The index of `glyph` of font `font`, preparing it — its overlapping contours
    /// merged, as the row draws by default (`overlaps=merge`) — if it was not met
    /// before. The merge, the costly part, is taken only for a glyph not met before.
    pub fn index_of(&mut self, font: usize, glyph: &Glyph, units_per_em: f64) -> u32 {
        let key = (font, outline_key(glyph));
        if let Some(&index) = self.index.get(&key) {
            return index;
        }
        let (outline, union) = match glyph.union(units_per_em) {
            Some(union) => (union.clone(), true),
            None => (glyph.outline.clone(), glyph.merged),
        };
        self.push(key, outline, union, units_per_em, glyph.bounds)
    }

    fn push(
        &mut self,
        key: (usize, u64),
        outline: Outline,
        union: bool,
        units_per_em: f64,
        bounds: Rect,
    ) -> u32 {
        let (bands, layout) = (BandCount::Auto, Layout::Area);
        let index = if union {
            self.data.push_union(&outline, units_per_em, bands, layout)
        } else {
            self.data.push(&outline, units_per_em, bands, layout)
        };
        self.bounds.push(bounds);
        self.index.insert(key, index);
        self.kept.push(Kept {
            key,
            outline,
            union,
            units_per_em,
        });
        index
    }

    /// Glyphs prepared.
    pub fn len(&self) -> usize {
        self.bounds.len()
    }

    /// The control bounds of glyph `index`, font units.
    pub fn bounds(&self, index: u32) -> &Rect {
        &self.bounds[index as usize]
    }

    /// Whether glyph `index` has curves marked as overlapping (the row's variant).
    pub fn marked(&self, index: u32) -> bool {
        self.data.marked[index as usize]
    }

    /// Whether glyphs were prepared since the last upload (whatever happened to the
    /// `prepare` that prepared them).
    pub fn need_upload(&self) -> bool {
        self.group.is_none() || self.uploaded != self.len()
    }

    /// Uploads every prepared glyph's data and binds it in `layout` (the row's
    /// `@group(1)`); the bytes uploaded.
    pub fn upload(
        &mut self,
        gpu: &GpuContext,
        layout: &wgpu::BindGroupLayout,
    ) -> Result<u64, Error> {
        let uploaded = Uploaded::new(gpu, "text", &self.data, layout)?;
        self.buffer_bytes = uploaded.bytes;
        self.group = Some(uploaded.bind_group);
        self.uploaded = self.len();
        Ok(self.buffer_bytes)
    }

    /// Forgets the upload (one that failed on the GPU): the next frame uploads anew.
    pub fn forget_upload(&mut self) {
        self.group = None;
        self.uploaded = 0;
    }

    /// The glyph buffers' bind group, once uploaded.
    pub fn bind_group(&self) -> Option<&wgpu::BindGroup> {
        self.group.as_ref()
    }

    /// Bytes of the glyph data on the GPU.
    pub fn gpu_bytes(&self) -> u64 {
        self.buffer_bytes
    }

    /// Keeps only the glyphs `used` marks, prepared again in their order (the next
    /// `prepare` uploads them); each old index's new one, None for a glyph dropped.
    pub fn compact(&mut self, used: &[bool]) -> Vec<Option<u32>> {
        let old = std::mem::take(self);
        let mut new_index = Vec::with_capacity(old.kept.len());
        for ((kept, bounds), &used) in old.kept.into_iter().zip(old.bounds).zip(used) {
            new_index.push(used.then(|| {
                self.push(
                    kept.key,
                    kept.outline,
                    kept.union,
                    kept.units_per_em,
                    bounds,
                )
            }));
        }
        new_index
    }
}

/// A glyph's identity within its font: its id and every point of its outline (a group
/// of joined instances carries its first glyph's id, so the outline tells groups apart).
fn outline_key(glyph: &Glyph) -> u64 {
    let mut hasher = DefaultHasher::new();
    glyph.id.hash(&mut hasher);
    for segment in glyph.outline.segments() {
        for p in crate::geometry::segment_points(segment) {
            p.x.to_bits().hash(&mut hasher);
            p.y.to_bits().hash(&mut hasher);
        }
    }
    hasher.finish()
}
