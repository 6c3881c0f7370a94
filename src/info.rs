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
    Ok(format!(
        "name: {}\nbackend: {:?}\ndriver: {}\ndriver info: {}\ndevice type: {:?}\nadapter: {}\n",
        info.name,
        info.backend,
        info.driver,
        info.driver_info,
        info.device_type,
        gpu.adapter_name()
    ))
}

/// Font units as text, with no "-0".
fn units(value: f64) -> String {
    format!("{}", value + 0.0)
}
