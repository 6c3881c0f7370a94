//! The text library's layout cache: each run's content (a string, or glyphs by id and
//! position) laid out once per font, found again each frame without allocating, and
//! dropped by [`LayoutCache::evict_unused`] once no frame has used it since the last trim.

use std::collections::HashMap;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

use glam::DVec2;

/// A run's layout in font units: (prepared glyph, pen position) per instance, shared by
/// the cache and the frames that draw it.
pub type RunLayout = Arc<[(u32, DVec2)]>;

/// What a run draws, as the cache compares it: borrowed from the caller each frame.
#[derive(Clone, Copy)]
pub enum ContentRef<'a> {
    Text(&'a str),
    /// The glyphs, and the run's size, whose bits are part of the key (it turns their
    /// text-space pixels into font units).
    Glyphs(&'a [PositionedGlyph], f32),
}

/// One glyph of a run given by id: its id in the font and its pen position in the run's
/// text space (pixels at the run's size, x right, y down, the run's origin at 0, 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PositionedGlyph {
    /// The glyph's id in the run's font.
    pub id: u16,
    /// Its pen position, text-space pixels right of the run's origin.
    pub x: f32,
    /// Its pen position, text-space pixels below the run's origin (y down).
    pub y: f32,
}

/// The same, owned by the cache.
enum Key {
    Text(Box<str>),
    Glyphs(Box<[(u16, u32, u32)]>, u32),
}

impl Key {
    fn of(content: ContentRef<'_>) -> Key {
        match content {
            ContentRef::Text(text) => Key::Text(text.into()),
            ContentRef::Glyphs(glyphs, size) => Key::Glyphs(
                glyphs
                    .iter()
                    .map(|g| (g.id, g.x.to_bits(), g.y.to_bits()))
                    .collect(),
                size.to_bits(),
            ),
        }
    }

    fn is(&self, content: ContentRef<'_>) -> bool {
        match (self, content) {
            (Key::Text(owned), ContentRef::Text(text)) => **owned == *text,
            (Key::Glyphs(owned, owned_size), ContentRef::Glyphs(glyphs, size)) => {
                *owned_size == size.to_bits()
                    && owned.len() == glyphs.len()
                    && owned.iter().zip(glyphs).all(|(&(id, x, y), g)| {
                        id == g.id && x == g.x.to_bits() && y == g.y.to_bits()
                    })
            }
            _ => false,
        }
    }
}

struct Entry {
    font: usize,
    key: Key,
    layout: RunLayout,
    /// The frame that last drew it.
    last_used: u64,
}

/// Layouts by a hash of their font and content; a bucket holds the (rare) collisions.
#[derive(Default)]
pub struct LayoutCache {
    buckets: HashMap<u64, Vec<Entry>>,
    len: usize,
}

fn hash_of(font: usize, content: ContentRef<'_>) -> u64 {
    let mut hasher = DefaultHasher::new();
    font.hash(&mut hasher);
    match content {
        ContentRef::Text(text) => {
            0u8.hash(&mut hasher);
            text.hash(&mut hasher);
        }
        ContentRef::Glyphs(glyphs, size) => {
            1u8.hash(&mut hasher);
            size.to_bits().hash(&mut hasher);
            for g in glyphs {
                (g.id, g.x.to_bits(), g.y.to_bits()).hash(&mut hasher);
            }
        }
    }
    hasher.finish()
}

impl LayoutCache {
    /// The layout of `content` in `font`, marked as used in `frame`; None if it was not
    /// laid out (or was dropped). Allocates nothing.
    pub fn get(&mut self, font: usize, content: ContentRef<'_>, frame: u64) -> Option<RunLayout> {
        let bucket = self.buckets.get_mut(&hash_of(font, content))?;
        let entry = bucket
            .iter_mut()
            .find(|e| e.font == font && e.key.is(content))?;
        entry.last_used = frame;
        Some(entry.layout.clone())
    }

    /// Keeps `layout` as the layout of `content` in `font`, used in `frame`.
    pub fn insert(&mut self, font: usize, content: ContentRef<'_>, layout: RunLayout, frame: u64) {
        self.buckets
            .entry(hash_of(font, content))
            .or_default()
            .push(Entry {
                font,
                key: Key::of(content),
                layout,
                last_used: frame,
            });
        self.len += 1;
    }

    /// Drops the layouts no frame after `frame` used; how many were dropped.
    pub fn evict_unused(&mut self, frame: u64) -> usize {
        let before = self.len;
        self.buckets.retain(|_, bucket| {
            bucket.retain(|e| e.last_used > frame);
            !bucket.is_empty()
        });
        self.len = self.buckets.values().map(Vec::len).sum();
        before - self.len
    }

    /// Layouts kept.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Every kept layout, to find which prepared glyphs are still drawn.
    pub fn layouts(&self) -> impl Iterator<Item = &RunLayout> {
        self.buckets.values().flatten().map(|e| &e.layout)
    }

    /// Rewrites every kept layout's glyph indices through `new_index` (after the
    /// prepared glyphs were compacted; every glyph a kept layout draws has one).
    pub fn renumber(&mut self, new_index: &[Option<u32>]) {
        for entry in self.buckets.values_mut().flatten() {
            entry.layout = entry
                .layout
                .iter()
                .map(|&(glyph, pen)| {
                    let glyph = new_index[glyph as usize].expect("a kept layout's glyph is kept");
                    (glyph, pen)
                })
                .collect();
        }
    }
}
