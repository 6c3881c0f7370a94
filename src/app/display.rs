//! What a pane shows of a coverage value. Only the picture changes: every error figure
//! stays in linear coverage against the reference. `display_color` is the CPU mirror of
//! `display_color` in composite.wgsl, which a test holds the shader to.

use serde::{Deserialize, Serialize};

/// The compositor's WGSL, whose `display_color` a test runs against this module's.
pub use super::gpu_view::composite_wgsl;

/// How coverage weights the text colour over the background.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum DisplayMode {
    /// Coverage is the blend weight in linear light (physically right for a box filter).
    #[default]
    Linear,
    /// Coverage is the blend weight of sRGB-encoded colours: the naive blend most UIs do.
    Srgb,
    /// Coverage remapped so the blend's luminance is a blend in a perceptual
    /// (power 1/`PERCEPTUAL_GAMMA`) space: dark text on light gains weight, light text on
    /// dark loses it. This follows the idea of Skia's "gamma hack" (coverage corrected
    /// by a curve picked by the text's luminance; skia.org/docs/dev/design/raster_tragedy),
    /// written here as a closed form rather than Skia's tables.
    Gamma,
}

impl DisplayMode {
    pub const ALL: [DisplayMode; 3] = [DisplayMode::Linear, DisplayMode::Srgb, DisplayMode::Gamma];

    pub fn label(self) -> &'static str {
        match self {
            DisplayMode::Linear => "linear",
            DisplayMode::Srgb => "sRGB",
            DisplayMode::Gamma => "gamma",
        }
    }

    /// `display` in composite.wgsl.
    pub fn shader_index(self) -> u32 {
        match self {
            DisplayMode::Linear => 0,
            DisplayMode::Srgb => 1,
            DisplayMode::Gamma => 2,
        }
    }
}

/// The exponent of the perceptual space `DisplayMode::Gamma` blends luminance in. Our
/// choice, not a published constant: between linear light (1) and sRGB (about 2.2), so
/// the three modes show three distinct weights.
pub const PERCEPTUAL_GAMMA: f32 = 1.8;

/// FreeType's default `darkening-parameters` for its CFF stem darkening (FreeType docs,
/// "Driver properties": 500, 400, 1000, 275, 1667, 275, 2333, 0): x is the stem width
/// in thousandths of a pixel (stem width per 1000 em × ppem), y the darkening, the stem
/// widened by y thousandths of a pixel, half on each side; linear between the points,
/// constant outside them.
pub const FREETYPE_DARKENING: [(f32, f32); 4] = [
    (500.0, 400.0),
    (1000.0, 275.0),
    (1667.0, 275.0),
    (2333.0, 0.0),
];

/// The stem width the display-time darkening assumes, in thousandths of an em: the
/// coverage image knows no stems, so one regular-weight stem stands for all.
pub const NOMINAL_STEM_PER_1000_EM: f32 = 80.0;

/// How far each edge of a stem moves out at `ppem`, in pixels, by FreeType's curve for
/// a stem of `NOMINAL_STEM_PER_1000_EM`.
pub fn freetype_edge_darkening(ppem: f32) -> f32 {
    let x = NOMINAL_STEM_PER_1000_EM * ppem;
    let [first, .., last] = FREETYPE_DARKENING;
    let y = if x <= first.0 {
        first.1
    } else if x >= last.0 {
        last.1
    } else {
        FREETYPE_DARKENING
            .windows(2)
            .find(|pair| x <= pair[1].0)
            .map(|pair| {
                let t = (x - pair[0].0) / (pair[1].0 - pair[0].0);
                pair[0].1 + t * (pair[1].1 - pair[0].1)
            })
            .unwrap_or(last.1)
    };
    y / 1000.0 / 2.0
}

/// sRGB's transfer function (IEC 61966-2-1), linear light to encoded.
pub fn srgb_encode(linear: f32) -> f32 {
    let c = linear.clamp(0.0, 1.0);
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

fn luminance(rgb: [f32; 3]) -> f32 {
    // Rec. 709 / sRGB primaries.
    0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
}

/// The sRGB-encoded colour a pixel of `coverage` shows, text and background given in
/// linear light. `edge_darkening` (pixels, 0 for none) approximates FreeType's stem
/// darkening at display time: FreeType moves outline edges out before rasterizing; here
/// a partly covered pixel gains that much coverage, as a straight edge moved out by it
/// would give its pixel. Unlike FreeType it leaves empty pixels empty (no spill past
/// the edge pixel) and darkens every edge alike, not by each stem's own width.
pub fn display_color(
    coverage: f32,
    text: [f32; 3],
    background: [f32; 3],
    mode: DisplayMode,
    edge_darkening: f32,
) -> [f32; 3] {
    let c = coverage.clamp(0.0, 1.0);
    let c = if c > 0.0 {
        (c + edge_darkening).min(1.0)
    } else {
        c
    };
    let mix = |a: f32, b: f32, w: f32| a + (b - a) * w;
    let weight = match mode {
        DisplayMode::Srgb => {
            return std::array::from_fn(|i| {
                mix(srgb_encode(background[i]), srgb_encode(text[i]), c)
            });
        }
        DisplayMode::Linear => c,
        DisplayMode::Gamma => {
            let (lb, lt) = (luminance(background), luminance(text));
            if (lt - lb).abs() < 1e-6 {
                c
            } else {
                let g = PERCEPTUAL_GAMMA;
                let blended = mix(lb.powf(1.0 / g), lt.powf(1.0 / g), c).powf(g);
                (blended - lb) / (lt - lb)
            }
        }
    };
    std::array::from_fn(|i| srgb_encode(mix(background[i], text[i], weight)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn freetype_darkening_follows_the_published_points() {
        // x = 80 × ppem: 500 at 6.25 ppem, 1000 at 12.5, 2333 at 29.1625.
        assert_eq!(freetype_edge_darkening(4.0), 0.2);
        assert!((freetype_edge_darkening(12.5) - 0.1375).abs() < 1e-6);
        assert!((freetype_edge_darkening(15.0) - 0.1375).abs() < 1e-6);
        assert_eq!(freetype_edge_darkening(40.0), 0.0);
        // Halfway from 500 to 1000 (9.375 ppem): y = 337.5.
        assert!((freetype_edge_darkening(9.375) - 0.16875).abs() < 1e-6);
    }

    #[test]
    fn gamma_mode_weights_dark_on_light_up_and_light_on_dark_down() {
        let (black, white) = ([0.0; 3], [1.0; 3]);
        // Hand-worked: dark on light, weight 1 − 0.5^1.8 = 0.7128; light on dark 0.5^1.8.
        let dark = display_color(0.5, black, white, DisplayMode::Gamma, 0.0)[0];
        let light = display_color(0.5, white, black, DisplayMode::Gamma, 0.0)[0];
        assert!(
            (dark - srgb_encode(1.0 - 0.712_825_4)).abs() < 1e-5,
            "{dark}"
        );
        assert!((light - srgb_encode(0.287_174_6)).abs() < 1e-5, "{light}");
        // Naive sRGB blending of black and white is the coverage itself.
        let naive = display_color(0.25, white, black, DisplayMode::Srgb, 0.0);
        assert!(naive.iter().all(|v| (v - 0.25).abs() < 1e-6), "{naive:?}");
    }
}
