//! Even-odd's layers: instances split so that no two of a layer can touch, since the
//! parity is a per-outline rule and overlapping glyphs must unite, not cancel.

use crate::geometry::Rect;
use crate::scene::Scene;

/// Assigns each instance a layer such that no two instances of a layer have bounds
/// (pen position + control bounds, grown by `gap` font units) that touch; greedy, left
/// to right. Instances of one layer then never share a sample, however the camera maps
/// the scene: it maps the whole plane by one invertible transform.
pub(super) fn disjoint_layers(scene: &Scene, gap: f64) -> Vec<u32> {
    let rects: Vec<Rect> = scene
        .instances
        .iter()
        .map(|i| {
            let b = scene.glyphs[i.glyph as usize].bounds;
            Rect {
                min: b.min + i.position - gap,
                max: b.max + i.position + gap,
            }
        })
        .collect();
    let mut order: Vec<usize> = (0..rects.len()).collect();
    order.sort_by(|&a, &b| rects[a].min.x.total_cmp(&rects[b].min.x));
    // Per layer, its members that may still reach instances further right.
    let mut open: Vec<Vec<Rect>> = Vec::new();
    let mut layers = vec![0; rects.len()];
    for i in order {
        let rect = rects[i];
        let mut chosen = None;
        for (layer, members) in open.iter_mut().enumerate() {
            members.retain(|m| m.max.x > rect.min.x);
            if !members.iter().any(|m| m.overlaps(&rect)) {
                chosen = Some(layer);
                break;
            }
        }
        let layer = chosen.unwrap_or_else(|| {
            open.push(Vec::new());
            open.len() - 1
        });
        open[layer].push(rect);
        layers[i] = layer as u32;
    }
    layers
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layers_hold_instances_that_cannot_touch() {
        let font = crate::font::default_font();
        let scene = Scene::from_text(&font, "ffi WAVE\nfjord Tj").unwrap();
        let gap = scene.units_per_em / 1024.0;
        let layers = disjoint_layers(&scene, gap);
        let rect = |i: usize| {
            let inst = scene.instances[i];
            let b = scene.glyphs[inst.glyph as usize].bounds;
            Rect {
                min: b.min + inst.position - gap,
                max: b.max + inst.position + gap,
            }
        };
        let n = scene.instances.len();
        for a in 0..n {
            for b in a + 1..n {
                if layers[a] == layers[b] {
                    assert!(
                        !rect(a).overlaps(&rect(b)),
                        "{a} and {b} share layer {}",
                        layers[a]
                    );
                }
            }
        }
        let count = layers.iter().max().unwrap() + 1;
        assert!((2..=4).contains(&count), "{count} layers");
    }
}
