//! `glyphscope info`: which outline table a font's glyphs come from and where each
//! requested glyph is placed — the figures behind [`Font::outline`](crate::font::Font::outline) and
//! [`Font::advance`](crate::font::Font::advance), printed without opening a display;
//! or which GPU adapter the other commands draw with ([`gpu`]).

use std::fmt::Write;
use std::path::PathBuf;

use crate::Error;
use crate::font::{GlyphId, OutlineTable, describe_sfnt_version};
use crate::gpu::GpuContext;
use crate::shaping;
use crate::view_args::load_font;

/// The font and the glyphs to report on.
#[derive(Clone, Debug)]
pub struct InfoOptions {
    /// The font file; the embedded DejaVu Sans when None.
    pub font: Option<PathBuf>,
    /// Report the glyphs this text shapes to, in order of first use.
    pub text: Option<String>,
    /// Report this glyph, by its id in the font (when there is no text).
    pub glyph_id: Option<u32>,
    /// Variable-font axis values, (tag, value).
    pub variation: Vec<(String, f32)>,
}

/// The report: the font's outline table and why, units per em, axes (tags quoted so their
/// padding shows), and per requested glyph its advance, lsb, xMin and the applied shift.
pub fn run(options: &InfoOptions) -> Result<String, Error> {
    let font = load_font(options.font.as_deref(), &options.variation)?;
    let glyphs: Vec<GlyphId> = match (&options.text, options.glyph_id) {
        (Some(text), _) => {
            let mut ids = Vec::new();
            for shaped in shaping::shape(&font, text)? {
                if !ids.contains(&shaped.glyph) {
                    ids.push(shaped.glyph);
                }
            }
            ids
        }
        (None, Some(id)) => vec![font.check_glyph_id(id)?],
        (None, None) => Vec::new(),
    };
    let mut out = String::new();
    let table = font.outline_table();
    let version = describe_sfnt_version(font.sfnt_version());
    let why = match table {
        OutlineTable::Glyf => format!("sfntVersion {version} is not 'OTTO'"),
        OutlineTable::Cff | OutlineTable::Cff2 => format!("sfntVersion {version}"),
    };
    let _ = writeln!(out, "font: {}", font.name());
    let _ = writeln!(out, "outline table: '{}' ({why})", table.tag());
    let _ = writeln!(out, "units per em: {}", font.units_per_em());
    let axes = font.axes();
    if axes.is_empty() {
        let _ = writeln!(out, "axes: none");
    }
    for axis in axes {
        let _ = writeln!(
            out,
            "axis '{}': {}..{}, default {}",
            axis.tag, axis.min, axis.max, axis.default
        );
    }
    for (tag, value) in font.variations() {
        let _ = writeln!(out, "instance: '{tag}' = {value}");
    }
    for glyph in glyphs {
        let placed = font.placement(glyph);
        let _ = write!(
            out,
            "glyph {glyph}: advance {}, lsb {}",
            units(placed.advance),
            units(placed.lsb)
        );
        let _ = match placed.x_min {
            Some(x_min) => write!(
                out,
                ", xMin {}, pp1.x {}, shift {}",
                units(x_min),
                units(-placed.shift),
                units(placed.shift)
            ),
            None => write!(out, ", shift 0 (CFF has no phantom points)"),
        };
        if placed.metrics_glyph != glyph {
            let _ = write!(
                out,
                " (metrics of glyph {}, flagged USE_MY_METRICS)",
                placed.metrics_glyph
            );
        }
        out.push('\n');
    }
    Ok(out)
}

/// The report of the adapter `render`, `bench` and `motion` open when given `adapter`
/// (see [`GpuContext::open`]): one `key: value` line each for its name, backend,
/// driver, driver info, device type and the description every report quotes. With
/// `require_hardware`, a CPU implementation (wgpu's [`wgpu::DeviceType::Cpu`]:
/// lavapipe, SwiftShader) is an error instead, so that a script measuring a GPU stops
/// before it writes figures that measure a CPU.
pub fn gpu(adapter: Option<&str>, require_hardware: bool) -> Result<String, Error> {
    let gpu = GpuContext::open(adapter)?;
    let info = gpu
        .adapter_info()
        .ok_or_else(|| Error::Internal("an adapter glyphscope opened has its info".into()))?;
    if require_hardware && info.device_type == wgpu::DeviceType::Cpu {
        return Err(Error::Input(format!(
            "the adapter is a CPU implementation, not a GPU: {} (device type Cpu); \
             choose a GPU with --adapter NAME or WGPU_ADAPTER_NAME",
            gpu.adapter_name()
        )));
    }
    let class = AdapterClass::of(&info);
    Ok(format!(
        "name: {}\nbackend: {:?}\ndriver: {}\ndriver info: {}\ndevice type: {:?}\nclass: {}\nadapter: {}\n{}\n",
        info.name,
        info.backend,
        info.driver,
        info.driver_info,
        info.device_type,
        class.name(),
        gpu.adapter_name(),
        adapter_class_sentence(&class),
    ))
}

/// What kind of device an adapter is, for what its timings can tell.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum AdapterClass {
    /// A CPU implementation of the API (lavapipe, SwiftShader): its "GPU" is the CPU,
    /// its SIMD lanes run every branch, and ratios between methods measure that.
    Software,
    /// A GPU sharing the CPU's package and memory (a laptop's or a console's).
    Integrated,
    /// A graphics card of a desktop or a laptop.
    Discrete,
    /// A data-centre accelerator (NVIDIA's H100, H200, A100, L4, T4…, AMD's Instinct):
    /// its compute units are the whole chip, its graphics units (rasterizer, ROPs) a
    /// small part of it (an H100 scores below an integrated Radeon 680M in 3DMark Time
    /// Spy).
    DataCentre,
    /// Anything else (a virtual device, an unknown type).
    Other,
}

/// Names of data-centre accelerators, as their adapters name them (case-insensitive,
/// whole words or model prefixes).
const DATA_CENTRE_NAMES: &[&str] = &[
    "h100", "h200", "h800", "gh200", "b100", "b200", "gb200", "a100", "a800", "a30", "a40", "a10",
    "a16", "a2", "l4", "l40", "t4", "v100", "p100", "instinct", "mi100", "mi210", "mi250", "mi300",
];

impl AdapterClass {
    /// The class of the adapter `info` describes.
    pub fn of(info: &wgpu::AdapterInfo) -> AdapterClass {
        match info.device_type {
            wgpu::DeviceType::Cpu => AdapterClass::Software,
            wgpu::DeviceType::IntegratedGpu => AdapterClass::Integrated,
            wgpu::DeviceType::DiscreteGpu if is_data_centre(&info.name) => AdapterClass::DataCentre,
            wgpu::DeviceType::DiscreteGpu => AdapterClass::Discrete,
            _ => AdapterClass::Other,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            AdapterClass::Software => "software",
            AdapterClass::Integrated => "integrated",
            AdapterClass::Discrete => "discrete",
            AdapterClass::DataCentre => "data-centre",
            AdapterClass::Other => "other",
        }
    }
}

/// Whether an adapter's name is a data-centre accelerator's: a word of it (split at
/// anything but letters and digits) is one of [`DATA_CENTRE_NAMES`], alone or with a
/// memory size or form factor after it (`H100`, `H100-SXM5-80GB`, `A100 80GB PCIe`).
fn is_data_centre(name: &str) -> bool {
    name.to_lowercase()
        .split(|c: char| !c.is_ascii_alphanumeric())
        .any(|word| DATA_CENTRE_NAMES.contains(&word))
}

/// One sentence for a report's header: the adapter's class and what its ratios can and
/// cannot tell.
pub fn adapter_class_sentence(class: &AdapterClass) -> String {
    match class {
        AdapterClass::Software => "Class: software — a CPU runs the shaders, every lane of a \
            SIMD group through every branch; ratios between fragment-shader methods here \
            measure that CPU, and a gain found here is checked on the other software \
            implementation before it is called the method's."
            .into(),
        AdapterClass::DataCentre => "Class: data-centre GPU — its graphics units (rasterizer \
            and ROPs) are a small part of a chip built for compute (an H100 scores below an \
            integrated Radeon 680M in 3DMark Time Spy): ratios of fragment-shader methods \
            here against each other, against compute renderers (vello) or against glyphon \
            do not represent desktop or laptop GPUs."
            .into(),
        AdapterClass::Integrated => "Class: integrated GPU.".into(),
        AdapterClass::Discrete => "Class: discrete GPU.".into(),
        AdapterClass::Other => "Class: other (neither a known GPU type nor a CPU).".into(),
    }
}

/// Font units as text, with no "-0".
fn units(value: f64) -> String {
    format!("{}", value + 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_centre_names_are_told_from_desktop_ones() {
        for name in [
            "NVIDIA H100 80GB HBM3",
            "NVIDIA H200",
            "NVIDIA A100-SXM4-40GB",
            "Tesla T4",
        ] {
            assert!(is_data_centre(name), "{name}");
        }
        for name in [
            "NVIDIA GeForce RTX 4090",
            "AMD Radeon RX 7900 XTX",
            "NVIDIA RTX A4000",
            "Apple M2",
        ] {
            assert!(!is_data_centre(name), "{name}");
        }
    }
}
