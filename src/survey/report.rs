//! What a survey writes from its rows: `survey.csv` (every row), `survey.json` (the
//! plan, per-method and per-font summaries, every row), `survey.md` (per method its
//! worst glyphs with the explorer link that opens each on its worst pixel; per font a
//! summary; every broken claim) and one contact sheet per method
//! (`worst-METHOD.png`: its worst glyphs magnified, coverage beside error).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use super::measure::{WORST_KEPT, tile_name, worst_by_method};
use super::plan::PlanFile;
use super::row::{Row, Verdict, file_safe, to_csv};
use crate::Error;
use crate::font::SHIPPED_FONTS;
use crate::link_text::encode;

/// The worst glyphs survey.md lists, and its contact sheets show, per method.
pub const WORST_LISTED: usize = WORST_KEPT;
/// Broken claims survey.md lists one by one (survey.csv has them all).
const BROKEN_LISTED: usize = 200;
/// Pane pixels left of and above a glyph's slot in a link's view.
const LINK_MARGIN_PX: f64 = 8.0;
/// The magnification a link opens at.
const LINK_MAGNIFY: u32 = 16;

/// A finished font: its rows and the folder its tiles are in.
pub struct FontRows {
    pub label: String,
    pub rows: Vec<Row>,
    pub tiles: PathBuf,
}

/// One method's figures over every glyph view it drew.
#[derive(Debug, Default, Serialize)]
pub struct MethodSummary {
    pub method: String,
    pub views: usize,
    pub ok: usize,
    pub limitation: usize,
    pub broken: usize,
    pub observed: usize,
    pub worst_max: f64,
    pub mean_mae_255: f64,
    pub mean_edge_mae_255: f64,
    pub views_over_025: usize,
    pub views_over_05: usize,
    pub invalid_pixels: usize,
    /// Fonts or faces it refused or failed on, with why.
    pub not_drawn: Vec<String>,
}

/// Every method's summary, in the plan's order.
pub fn summaries(methods: &[String], rows: &[Row]) -> Vec<MethodSummary> {
    methods
        .iter()
        .map(|method| {
            let mut s = MethodSummary {
                method: method.clone(),
                ..Default::default()
            };
            for r in rows.iter().filter(|r| &r.method == method) {
                if !r.is_measured() {
                    s.not_drawn.push(format!("{}: {}", font_cell(r), r.reason));
                    continue;
                }
                s.views += 1;
                match r.verdict {
                    Verdict::Ok => s.ok += 1,
                    Verdict::Limitation => s.limitation += 1,
                    Verdict::Broken => s.broken += 1,
                    _ => s.observed += 1,
                }
                s.worst_max = if r.max.is_nan() {
                    f64::INFINITY
                } else {
                    s.worst_max.max(r.max)
                };
                s.mean_mae_255 += r.mae_255;
                s.mean_edge_mae_255 += r.edge_mae_255;
                s.views_over_025 += usize::from(r.over_025 > 0);
                s.views_over_05 += usize::from(r.over_05 > 0);
                s.invalid_pixels += r.invalid;
            }
            let n = s.views.max(1) as f64;
            s.mean_mae_255 /= n;
            s.mean_edge_mae_255 /= n;
            s
        })
        .collect()
}

/// The `font` value a link opens `label`'s font with: a shipped font's number where
/// the file is one of them (a link that also opens on the web page), else its absolute
/// path (the desktop explorer's; the web page cannot open a local path).
fn font_in_link(label: &str) -> String {
    let path = Path::new(label);
    if let Ok(bytes) = std::fs::read(path)
        && let Some(index) = SHIPPED_FONTS
            .iter()
            .position(|(_, _, b)| *b == bytes.as_slice())
    {
        return index.to_string();
    }
    std::fs::canonicalize(path).map_or_else(|_| label.to_owned(), |p| p.display().to_string())
}

/// The explorer link that opens `row`'s glyph as measured, magnified on its worst
/// pixel, its method beside the reference; None for a face of a collection other than
/// the first, which a link cannot name.
pub fn link(row: &Row, font: &str, transform: (f64, f64)) -> Option<String> {
    let glyph = row.glyph?;
    let mut variations = Vec::new();
    for part in row.face.split(' ').filter(|p| !p.is_empty()) {
        match part.split_once('=') {
            Some((tag, value)) => variations.push(format!("{tag}:{value}")),
            None if part == "face" => {}
            None if part == "0" => {}
            None => return None,
        }
    }
    let m = LINK_MARGIN_PX;
    let mut parts = vec![
        format!("font={}", encode(font)),
        format!("glyph={}", encode(&format!("#{glyph}"))),
    ];
    if !variations.is_empty() {
        parts.push(format!("var={}", encode(&variations.join(","))));
    }
    parts.extend([
        format!("size={}", row.size),
        format!("origin={},{}", row.origin_x + m, row.origin_y + m),
        format!("rotate={}", transform.0),
        format!("skew={}", transform.1),
        "layout=2".into(),
        format!("a={}", encode(&row.method)),
        "b=reference".into(),
        format!("magnify={LINK_MAGNIFY}"),
        format!(
            "focus={},{}",
            f64::from(row.worst_x) + m + 0.5,
            f64::from(row.worst_y) + m + 0.5
        ),
    ]);
    Some(format!("#{}", parts.join("&")))
}

/// Writes every output into `out` from the finished fonts, in the order given.
/// `plan` is the plan's description; `methods` its method labels in order;
/// `transforms` each transform's name with its (rotation, skew).
pub fn write(
    out: &Path,
    plan: &PlanFile,
    methods: &[String],
    transforms: &[(String, (f64, f64))],
    fonts: &[FontRows],
) -> Result<(), Error> {
    let rows: Vec<Row> = fonts.iter().flat_map(|f| f.rows.iter().cloned()).collect();
    let output = |path: &Path, e: &dyn std::fmt::Display| {
        Error::Output(format!("cannot write '{}': {e}", path.display()))
    };
    let write_text = |name: &str, text: String| {
        let path = out.join(name);
        std::fs::write(&path, text).map_err(|e| output(&path, &e))
    };
    write_text("survey.csv", to_csv(&rows))?;
    let summaries = summaries(methods, &rows);
    let fonts_in_links: BTreeMap<&str, String> = fonts
        .iter()
        .map(|f| (f.label.as_str(), font_in_link(&f.label)))
        .collect();
    let link_of = |r: &Row| {
        let transform = transforms
            .iter()
            .find(|(name, _)| *name == r.transform)
            .map_or((0.0, 0.0), |(_, t)| *t);
        link(r, &fonts_in_links[r.font.as_str()], transform)
    };
    let json = serde_json::json!({
        "plan": plan,
        "methods": summaries,
        "fonts": fonts.iter().map(|f| font_summary(f, methods)).collect::<Vec<_>>(),
        "rows": rows,
    });
    write_text(
        "survey.json",
        serde_json::to_string(&json).expect("rows serialize") + "\n",
    )?;
    let worst = worst_by_method(&rows, WORST_LISTED);
    write_text(
        "survey.md",
        markdown(plan, methods, &summaries, &worst, fonts, &rows, &link_of),
    )?;
    for method in methods {
        let Some(list) = worst.get(method.as_str()) else {
            continue;
        };
        // A tile that cannot be read is a grey square in its place, so the sheet keeps
        // the table's order.
        let tiles: Vec<(image::RgbImage, (u32, u32))> = list
            .iter()
            .map(|r| {
                fonts
                    .iter()
                    .find(|f| f.label == r.font)
                    .and_then(|font| image::open(font.tiles.join(tile_name(r))).ok())
                    .map_or_else(
                        || {
                            (
                                image::RgbImage::from_pixel(9, 9, image::Rgb([128, 128, 128])),
                                (0, 0),
                            )
                        },
                        |tile| (tile.to_rgb8(), (r.worst_x, r.worst_y)),
                    )
            })
            .collect();
        if tiles.is_empty() {
            continue;
        }
        let path = out.join(sheet_name(method));
        contact_sheet(&tiles)
            .save(&path)
            .map_err(|e| output(&path, &e))?;
    }
    Ok(())
}

/// The contact sheet's file name for a method label.
pub fn sheet_name(method: &str) -> String {
    let safe = file_safe(method);
    format!("worst-{safe}.png")
}

fn font_summary(font: &FontRows, methods: &[String]) -> serde_json::Value {
    let glyphs: std::collections::BTreeSet<(&str, u16)> = font
        .rows
        .iter()
        .filter(|r| r.is_measured())
        .filter_map(|r| Some((r.face.as_str(), r.glyph?)))
        .collect();
    let unreadable: Vec<String> = font
        .rows
        .iter()
        .filter(|r| r.verdict == Verdict::Unreadable)
        .map(|r| match r.glyph {
            Some(g) => format!("{} glyph {g}: {}", r.face, r.reason),
            None => format!("{}: {}", r.face, r.reason),
        })
        .collect();
    serde_json::json!({
        "font": font.label,
        "glyphs": glyphs.len(),
        "unreadable": unreadable,
        "methods": summaries(methods, &font.rows),
    })
}

/// Cells that print a number as the tables do (∞ for an invalid pixel).
fn num(v: f64, digits: usize) -> String {
    if v.is_finite() {
        format!("{v:.digits$}")
    } else {
        "∞".into()
    }
}

#[allow(clippy::too_many_arguments)]
fn markdown(
    plan: &PlanFile,
    methods: &[String],
    summaries: &[MethodSummary],
    worst: &std::collections::HashMap<&str, Vec<&Row>>,
    fonts: &[FontRows],
    rows: &[Row],
    link_of: &dyn Fn(&Row) -> Option<String>,
) -> String {
    let mut md = String::from("# Survey\n\n");
    let glyph_views = rows.iter().filter(|r| r.is_measured()).count();
    let broken: Vec<&Row> = rows
        .iter()
        .filter(|r| r.verdict == Verdict::Broken)
        .collect();
    let _ = writeln!(
        md,
        "{} font files; {glyph_views} rows measured (glyph × size × transform × method); \
         {} broken claims. The plan: `{}`.\n",
        fonts.len(),
        broken.len(),
        serde_json::to_string(plan).expect("a plan serializes")
    );
    md += "Each glyph sits alone in a slot of its frame with 3 clear pixels around its ink, at a \
           sub-pixel offset set by its id; its error is over its slot against the exact reference. \
           A claim is held to the bound the method's registry row sets for a glyph with the traits \
           found in its outline at that size and transform (docs/survey.md says how each is read).\n\n";
    md += "| method | views | ok | limitation | BROKEN | observed | worst max | mean MAE /255 | mean edge MAE /255 | views with px > 0.25 | views with px > 0.5 | invalid px |\n\
           |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for s in summaries {
        if s.views == 0 {
            let _ = writeln!(
                md,
                "| {} | 0 | drew nothing (below) | | | | | | | | | |",
                s.method
            );
            continue;
        }
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} | {} | {:.2} | {:.2} | {} | {} | {} |",
            s.method,
            s.views,
            s.ok,
            s.limitation,
            s.broken,
            s.observed,
            num(s.worst_max, 3),
            s.mean_mae_255,
            s.mean_edge_mae_255,
            s.views_over_025,
            s.views_over_05,
            s.invalid_pixels
        );
    }
    for s in summaries.iter().filter(|s| !s.not_drawn.is_empty()) {
        // Once each, with how often: a refusal repeats for every size and transform of a
        // font, or for every glyph it holds for.
        let mut distinct: Vec<(&str, usize)> = Vec::new();
        for why in &s.not_drawn {
            match distinct
                .iter_mut()
                .find(|(known, _)| *known == why.as_str())
            {
                Some((_, count)) => *count += 1,
                None => distinct.push((why, 1)),
            }
        }
        let listed: Vec<String> = distinct
            .iter()
            .map(|(why, count)| format!("{why} ({count}×)"))
            .collect();
        let _ = writeln!(md, "\n{} did not draw: {}", s.method, listed.join("; "));
    }
    for method in methods {
        let Some(list) = worst.get(method.as_str()) else {
            continue;
        };
        let _ = writeln!(
            md,
            "\n## {method}: its {} worst glyphs\n\n![{method}'s worst glyphs, coverage beside \
             error, in the order of the table]({})\n",
            list.len(),
            sheet_name(method)
        );
        md += "| # | font | glyph | size | transform | max | MAE /255 | edge MAE /255 | px > 0.25 | px > 0.5 | traits | verdict | open it |\n\
               |---:|---|---|---:|---|---:|---:|---:|---:|---:|---|---|---|\n";
        for (k, r) in list.iter().enumerate() {
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} | {:.2} | {:.2} | {} | {} | {} | {} | {} |",
                k + 1,
                font_cell(r),
                glyph_cell(r),
                r.size,
                r.transform,
                num(r.max, 3),
                r.mae_255,
                r.edge_mae_255,
                r.over_025,
                r.over_05,
                r.traits,
                verdict_word(r.verdict),
                link_cell(link_of(r)),
            );
        }
    }
    md += "\n## Per font\n\n| font | glyphs | unreadable | method | views | worst max | mean MAE /255 | BROKEN |\n\
           |---|---:|---:|---|---:|---:|---:|---:|\n";
    for font in fonts {
        let summary = font_summary(font, methods);
        let unreadable = summary["unreadable"].as_array().map_or(0, Vec::len);
        for s in summaries_of(font, methods) {
            let _ = writeln!(
                md,
                "| {} | {} | {unreadable} | {} | {} | {} | {:.2} | {} |",
                font.label,
                summary["glyphs"],
                s.method,
                s.views,
                num(s.worst_max, 3),
                s.mean_mae_255,
                s.broken
            );
        }
    }
    let unreadable: Vec<&Row> = rows
        .iter()
        .filter(|r| r.verdict == Verdict::Unreadable)
        .collect();
    if !unreadable.is_empty() {
        let _ = writeln!(md, "\n## Unreadable ({})\n", unreadable.len());
        for r in unreadable.iter().take(BROKEN_LISTED) {
            let glyph = r.glyph.map_or(String::new(), |g| format!(" glyph {g}"));
            let _ = writeln!(md, "- {}{glyph}: {}", font_cell(r), r.reason);
        }
        if unreadable.len() > BROKEN_LISTED {
            let _ = writeln!(
                md,
                "- … and {} more in survey.csv",
                unreadable.len() - BROKEN_LISTED
            );
        }
    }
    let _ = writeln!(md, "\n## Broken claims ({})\n", broken.len());
    if broken.is_empty() {
        md += "Every method kept its claim on every glyph.\n";
    }
    for r in broken.iter().take(BROKEN_LISTED) {
        let _ = writeln!(
            md,
            "- {} {} at {} px/em, {}: {} claims {} here ({}), measured max {}, MAE {:.2}/255 and edge MAE {:.2}/255 — {}",
            font_cell(r),
            glyph_cell(r),
            r.size,
            r.transform,
            r.method,
            r.bound,
            if r.traits.is_empty() {
                "no traits"
            } else {
                &r.traits
            },
            num(r.max, 3),
            r.mae_255,
            r.edge_mae_255,
            link_cell(link_of(r)),
        );
    }
    if broken.len() > BROKEN_LISTED {
        let _ = writeln!(
            md,
            "- … and {} more in survey.csv",
            broken.len() - BROKEN_LISTED
        );
    }
    md
}

fn summaries_of(font: &FontRows, methods: &[String]) -> Vec<MethodSummary> {
    summaries(methods, &font.rows)
}

fn font_cell(r: &Row) -> String {
    if r.face.is_empty() {
        r.font.clone()
    } else {
        format!("{} ({})", r.font, r.face)
    }
}

fn glyph_cell(r: &Row) -> String {
    match (r.glyph, r.name.is_empty()) {
        (Some(g), true) => format!("#{g}"),
        (Some(g), false) => format!("#{g} `{}`", r.name),
        (None, _) => String::new(),
    }
}

fn link_cell(link: Option<String>) -> String {
    link.map_or("(a collection's later face: no link)".into(), |l| {
        format!("`glyphscope --view '{l}'`")
    })
}

fn verdict_word(v: Verdict) -> String {
    serde_json::to_value(v)
        .ok()
        .and_then(|v| v.as_str().map(str::to_uppercase))
        .unwrap_or_default()
}

/// The tiles, each magnified to about 160 px tall (1× to 8×, whole pixels), five to a
/// row, the worst pixel framed in both halves of each.
fn contact_sheet(tiles: &[(image::RgbImage, (u32, u32))]) -> image::RgbImage {
    const COLUMNS: usize = 5;
    const GAP: u32 = 8;
    let factor = |tile: &image::RgbImage| (160 / tile.height().max(1)).clamp(1, 8);
    let cell_w = tiles
        .iter()
        .map(|(t, _)| t.width() * factor(t))
        .max()
        .unwrap_or(1)
        + GAP;
    let cell_h = tiles
        .iter()
        .map(|(t, _)| t.height() * factor(t))
        .max()
        .unwrap_or(1)
        + GAP;
    let rows = tiles.len().div_ceil(COLUMNS) as u32;
    let columns = tiles.len().min(COLUMNS) as u32;
    let mut sheet = image::RgbImage::from_pixel(
        columns * cell_w + GAP,
        rows * cell_h + GAP,
        image::Rgb([235, 235, 235]),
    );
    for (k, (tile, worst)) in tiles.iter().enumerate() {
        let f = factor(tile);
        let (x0, y0) = (
            GAP + (k % COLUMNS) as u32 * cell_w,
            GAP + (k / COLUMNS) as u32 * cell_h,
        );
        for (x, y, p) in tile.enumerate_pixels() {
            for dy in 0..f {
                for dx in 0..f {
                    sheet.put_pixel(x0 + x * f + dx, y0 + y * f + dy, *p);
                }
            }
        }
        // The worst pixel framed, in the coverage half and the error half.
        let half = (tile.width() - 1) / 2;
        for left in [worst.0, worst.0 + half + 1] {
            frame_block(&mut sheet, x0 + left * f, y0 + worst.1 * f, f);
        }
    }
    sheet
}

/// An orange frame one pixel outside a block of `side` at (x, y).
fn frame_block(sheet: &mut image::RgbImage, x: u32, y: u32, side: u32) {
    let (x0, y0) = (x.saturating_sub(1), y.saturating_sub(1));
    let (x1, y1) = (x + side, y + side);
    for j in y0..=y1.min(sheet.height() - 1) {
        for i in x0..=x1.min(sheet.width() - 1) {
            if i == x0 || i == x1 || j == y0 || j == y1 {
                sheet.put_pixel(i, j, image::Rgb([255, 140, 0]));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_places_the_glyph_as_measured_and_focuses_its_worst_pixel() {
        let row = Row {
            glyph: Some(36),
            size: 24.0,
            transform: "rotate:30".into(),
            method: "winding:aa=rays".into(),
            origin_x: 3.25,
            origin_y: 20.5,
            worst_x: 4,
            worst_y: 7,
            face: "wght=700".into(),
            ..Row::unmeasured("f.ttf", "", Verdict::Ok, String::new())
        };
        let link = link(&row, "/a b/f.ttf", (30.0, 0.0)).unwrap();
        assert_eq!(
            link,
            "#font=%2Fa%20b%2Ff.ttf&glyph=%2336&var=wght:700&size=24&origin=11.25,28.5&rotate=30\
             &skew=0&layout=2&a=winding:aa%3Drays&b=reference&magnify=16&focus=12.5,15.5"
        );
        let later_face = Row {
            face: "face 2".into(),
            ..row
        };
        assert_eq!(super::link(&later_face, "x", (0.0, 0.0)), None);
    }

    #[test]
    fn a_shipped_font_is_linked_by_its_number() {
        assert_eq!(font_in_link("fonts/Inter-roman.var.ttf"), "2");
        assert!(font_in_link("Cargo.toml").ends_with("Cargo.toml"));
    }
}
