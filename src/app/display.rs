//! What a pane shows of a coverage value. Only the picture changes: every error figure
//! stays in linear coverage against the reference. `display_color` is the CPU mirror of
//! `display_color` in composite.wgsl, which a test holds the shader to.

use serde::{Deserialize, Serialize};

/// The compositor's WGSL (`composite.wgsl`, the shared heat scale first), whose
/// `display_color` a test runs against this module's.
pub fn composite_wgsl() -> String {
    crate::gpu::shaders::Shader {
        file: "composite.wgsl",
        files: &["composite.wgsl"],
        body: include_str!("composite.wgsl"),
    }
    .source()
}

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

/// Stem darkening, applied at display time by one renderer's published rule.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Darkening {
    #[default]
    Off,
    /// FreeType's CFF (Adobe engine) curve: edges moved out by an amount set by the stem
    /// width in pixels ([`freetype_edge_darkening`]).
    FreeType,
    /// HarfBuzz's GPU path (`hb_gpu_stem_darken`, HarfBuzz 14): coverage raised to a
    /// power set by the text's brightness and the size ([`harfbuzz_exponent`]); it
    /// darkens dark text and lightens light text.
    HarfBuzzGpu,
}

impl Darkening {
    pub const ALL: [Darkening; 3] = [Darkening::Off, Darkening::FreeType, Darkening::HarfBuzzGpu];

    pub fn label(self) -> &'static str {
        match self {
            Darkening::Off => "no darkening",
            Darkening::FreeType => "FreeType darkening",
            Darkening::HarfBuzzGpu => "HarfBuzz GPU darkening",
        }
    }

    /// For a narrow combo box.
    pub fn short_label(self) -> &'static str {
        match self {
            Darkening::Off => "no darken",
            Darkening::FreeType => "FreeType",
            Darkening::HarfBuzzGpu => "HarfBuzz",
        }
    }

    /// What it does to the coverage of text of sRGB colour `text_srgb` (0–1 a channel)
    /// at `ppem`.
    pub fn adjust(self, ppem: f32, text_srgb: [f32; 3]) -> CoverageAdjust {
        match self {
            Darkening::Off => CoverageAdjust::NONE,
            Darkening::FreeType => CoverageAdjust {
                edge_px: freetype_edge_darkening(ppem),
                ..CoverageAdjust::NONE
            },
            Darkening::HarfBuzzGpu => CoverageAdjust {
                exponent: harfbuzz_exponent(ppem, text_srgb.iter().sum::<f32>() / 3.0),
                ..CoverageAdjust::NONE
            },
        }
    }
}

/// How a darkening changes a partly covered pixel's coverage `c`: `min(c + edge_px,
/// 1)`, then raised to `exponent`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoverageAdjust {
    pub edge_px: f32,
    pub exponent: f32,
}

impl CoverageAdjust {
    pub const NONE: CoverageAdjust = CoverageAdjust {
        edge_px: 0.0,
        exponent: 1.0,
    };
}

/// HarfBuzz's GPU stem darkening exponent (`hb_gpu_stem_darken` in
/// hb-gpu-draw-fragment.glsl): `mix(2^(brightness − ½), 1, smoothstep(8, 48, ppem))`, with
/// brightness the mean of the text colour's (sRGB) channels, as HarfBuzz's documentation
/// computes it. Below 8 ppem dark text gets coverage^0.71 (heavier), white text
/// coverage^1.41 (lighter); from 48 ppem, none.
pub fn harfbuzz_exponent(ppem: f32, brightness: f32) -> f32 {
    let t = ((ppem - 8.0) / (48.0 - 8.0)).clamp(0.0, 1.0);
    let smooth = t * t * (3.0 - 2.0 * t);
    let small = (brightness - 0.5).exp2();
    small + (1.0 - small) * smooth
}

/// FreeType's default `darkening-parameters` for its CFF stem darkening (ftdriver.h,
/// "darkening-parameters": 500, 400, 1000, 275, 1667, 275, 2333, 0): x is the stem width
/// and y the darkening amount, both in thousandths of a pixel; `cf2_computeDarkening`
/// (psfont.c) puts half the amount on each side of the stem; linear between the points,
/// constant outside them.
pub const FREETYPE_DARKENING: [(f32, f32); 4] = [
    (500.0, 400.0),
    (1000.0, 275.0),
    (1667.0, 275.0),
    (2333.0, 0.0),
];

/// The stem width the display-time darkening assumes, in thousandths of an em: the
/// coverage image knows no stems, so one stands for all — FreeType's own fallback when a
/// font gives no StdVW (75, in `cf2_font_setup`).
pub const NOMINAL_STEM_PER_1000_EM: f32 = 75.0;

/// How far each edge of a stem moves out at `ppem`, in pixels, by FreeType's curve for
/// a stem of `NOMINAL_STEM_PER_1000_EM`. (FreeType takes ppem as at least 4; that stem
/// is below the curve's first point there, 300 < 500, so it changes nothing here.)
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
/// linear light, after `darkening`'s change to partly covered pixels. FreeType's
/// darkening is approximated: FreeType moves outline edges out before rasterizing; here
/// a partly covered pixel gains `edge_px` of coverage, as a straight edge moved out by it
/// would give its pixel. Unlike FreeType it leaves empty pixels empty (no spill past
/// the edge pixel) and darkens every edge alike, not by each stem's own width.
/// HarfBuzz's is exact: it is a rule on coverage, as here.
pub fn display_color(
    coverage: f32,
    text: [f32; 3],
    background: [f32; 3],
    mode: DisplayMode,
    darkening: CoverageAdjust,
) -> [f32; 3] {
    let c = coverage.clamp(0.0, 1.0);
    let c = if c > 0.0 && c < 1.0 {
        (c + darkening.edge_px).min(1.0).powf(darkening.exponent)
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
        // x = 75 × ppem: 500 at 6.667 ppem, 1000 at 13.333, 1667 at 22.227, 2333 at 31.107;
        // each edge gets half of y.
        assert_eq!(freetype_edge_darkening(4.0), 0.2);
        assert!((freetype_edge_darkening(40.0 / 3.0) - 0.1375).abs() < 1e-6);
        assert!((freetype_edge_darkening(20.0) - 0.1375).abs() < 1e-6);
        assert_eq!(freetype_edge_darkening(40.0), 0.0);
        // Halfway from 500 to 1000 (x = 750, 10 ppem): y = 337.5.
        assert!((freetype_edge_darkening(10.0) - 0.16875).abs() < 1e-6);
    }

    #[test]
    fn harfbuzz_darkening_follows_its_formula() {
        // Hand-worked: below 8 ppem the exponent is 2^(b − ½): √2 for white, 1/√2 for
        // black; from 48 ppem 1; at 28 ppem smoothstep is ½.
        let sqrt2 = std::f32::consts::SQRT_2;
        assert!((harfbuzz_exponent(6.0, 1.0) - sqrt2).abs() < 1e-6);
        assert!((harfbuzz_exponent(6.0, 0.0) - 1.0 / sqrt2).abs() < 1e-6);
        assert_eq!(harfbuzz_exponent(48.0, 0.0), 1.0);
        assert!((harfbuzz_exponent(28.0, 1.0) - (sqrt2 + 1.0) / 2.0).abs() < 1e-6);
        // Black text at 6 ppem: 0.25 shows as 0.25^(1/√2) = 0.3752.
        let adjust = Darkening::HarfBuzzGpu.adjust(6.0, [0.0; 3]);
        let shown = display_color(0.25, [1.0; 3], [0.0; 3], DisplayMode::Linear, adjust)[0];
        assert!((shown - srgb_encode(0.375_214)).abs() < 1e-5, "{shown}");
        // Full and empty pixels stay as they are.
        for c in [0.0, 1.0] {
            let shown = display_color(c, [1.0; 3], [0.0; 3], DisplayMode::Linear, adjust)[0];
            assert_eq!(shown, srgb_encode(c));
        }
    }

    #[test]
    fn gamma_mode_weights_dark_on_light_up_and_light_on_dark_down() {
        let (black, white) = ([0.0; 3], [1.0; 3]);
        // Hand-worked: dark on light, weight 1 − 0.5^1.8 = 0.7128; light on dark 0.5^1.8.
        let dark = display_color(0.5, black, white, DisplayMode::Gamma, CoverageAdjust::NONE)[0];
        let light = display_color(0.5, white, black, DisplayMode::Gamma, CoverageAdjust::NONE)[0];
        assert!(
            (dark - srgb_encode(1.0 - 0.712_825_4)).abs() < 1e-5,
            "{dark}"
        );
        assert!((light - srgb_encode(0.287_174_6)).abs() < 1e-5, "{light}");
        // Naive sRGB blending of black and white is the coverage itself.
        let naive = display_color(0.25, white, black, DisplayMode::Srgb, CoverageAdjust::NONE);
        assert!(naive.iter().all(|v| (v - 0.25).abs() < 1e-6), "{naive:?}");
    }
}
