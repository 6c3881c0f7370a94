//! The meshes on the GPU: every mesh held, packed into one vertex buffer, one index
//! buffer each for triangles and edges, and one storage buffer of markers. A mesh is
//! keyed by its glyph and, where it depends on the scale, its scale bucket; a draw
//! names a mesh by the ranges it was packed at.
//!
//! Meshes are added as frames first need them and repacked then (a few hundred KB
//! copied, only when the scale crosses a bucket). At each repack, meshes no frame has
//! used for [`KEEP_FRAMES`] frames are dropped, so that a zoom does not pile up every
//! scale it passed through, and a camera hovering at a bucket's edge does not rebuild
//! the same two meshes each frame.

use std::collections::BTreeMap;
use std::ops::Range;

use super::mesh::{GlyphMesh, Marker};
use crate::gpu::GpuContext;
use crate::methods::GlyphMeshStats;

/// Frames an unused mesh is kept for (two seconds at 60 frames a second).
pub const KEEP_FRAMES: u64 = 120;

/// Which mesh: a distinct glyph of the scene, and the scale bucket it was built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct MeshKey {
    pub glyph: u32,
    pub scale_bucket: Option<i32>,
}

/// Where a mesh was packed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ranges {
    pub base_vertex: i32,
    pub triangles: Range<u32>,
    pub edges: Range<u32>,
    pub markers: Range<u32>,
}

struct Entry {
    mesh: GlyphMesh,
    stats: GlyphMeshStats,
    last_used: u64,
    ranges: Ranges,
}

pub struct Packed {
    pub vertices: wgpu::Buffer,
    pub triangles: wgpu::Buffer,
    pub edges: wgpu::Buffer,
    pub markers: wgpu::Buffer,
}

#[derive(Default)]
pub struct MeshStore {
    entries: BTreeMap<MeshKey, Entry>,
    packed: Option<Packed>,
}

impl MeshStore {
    pub fn contains(&self, key: &MeshKey) -> bool {
        self.entries.contains_key(key)
    }

    /// Adds a mesh; it reaches the GPU at the next [`pack`](Self::pack).
    pub fn insert(&mut self, key: MeshKey, mesh: GlyphMesh, stats: GlyphMeshStats, frame: u64) {
        let ranges = Ranges {
            base_vertex: 0,
            triangles: 0..0,
            edges: 0..0,
            markers: 0..0,
        };
        self.entries.insert(
            key,
            Entry {
                mesh,
                stats,
                last_used: frame,
                ranges,
            },
        );
        self.packed = None;
    }

    /// Notes that `frame` draws the mesh.
    pub fn touch(&mut self, key: &MeshKey, frame: u64) {
        if let Some(entry) = self.entries.get_mut(key) {
            entry.last_used = frame;
        }
    }

    /// Packs the meshes into new GPU buffers if any were added since the last pack,
    /// dropping those unused for [`KEEP_FRAMES`] frames first. Returns whether the
    /// buffers changed.
    pub fn pack(&mut self, gpu: &GpuContext, frame: u64) -> bool {
        if self.packed.is_some() {
            return false;
        }
        self.entries
            .retain(|_, e| frame.saturating_sub(e.last_used) <= KEEP_FRAMES);
        let mut vertices: Vec<[f32; 2]> = Vec::new();
        let mut triangles: Vec<u32> = Vec::new();
        let mut edges: Vec<u32> = Vec::new();
        let mut markers: Vec<Marker> = Vec::new();
        for entry in self.entries.values_mut() {
            let mesh = &entry.mesh;
            let span = |start: usize, added: usize| start as u32..(start + added) as u32;
            entry.ranges = Ranges {
                base_vertex: vertices.len() as i32,
                triangles: span(triangles.len(), mesh.triangles.len()),
                edges: span(edges.len(), mesh.edges.len()),
                markers: span(markers.len(), mesh.markers.len()),
            };
            vertices.extend(&mesh.vertices);
            triangles.extend(&mesh.triangles);
            edges.extend(&mesh.edges);
            markers.extend(&mesh.markers);
        }
        self.packed = Some(Packed {
            vertices: gpu.buffer_of("mesh vertices", &vertices, wgpu::BufferUsages::VERTEX),
            triangles: gpu.buffer_of("mesh triangles", &triangles, wgpu::BufferUsages::INDEX),
            edges: gpu.buffer_of("mesh edges", &edges, wgpu::BufferUsages::INDEX),
            markers: gpu.buffer_of("mesh points", &markers, wgpu::BufferUsages::STORAGE),
        });
        true
    }

    /// The packed buffers (after a [`pack`](Self::pack)).
    pub fn packed(&self) -> Option<&Packed> {
        self.packed.as_ref()
    }

    /// Where a packed mesh lies.
    pub fn ranges(&self, key: &MeshKey) -> Option<&Ranges> {
        self.entries.get(key).map(|e| &e.ranges)
    }

    /// Statistics of every mesh held, in key order.
    pub fn stats(&self) -> impl Iterator<Item = &GlyphMeshStats> {
        self.entries.values().map(|e| &e.stats)
    }

    pub fn bytes(&self) -> u64 {
        self.packed.as_ref().map_or(0, |p| {
            p.vertices.size() + p.triangles.size() + p.edges.size() + p.markers.size()
        })
    }
}
