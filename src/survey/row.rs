//! One row of a survey: a glyph of a face at one size and transform, through one method,
//! against the reference; or a font, glyph or method that could not be measured, with
//! its reason. Rows are what a font's finished results hold, what shards merge and
//! what every output is written from.

use serde::{Deserialize, Serialize};

/// What a row says of its method on its glyph.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// Within the bound the method claims for a glyph with these traits.
    Ok,
    /// A glyph with a trait the claim leaves out, within its looser bound if it has one.
    Limitation,
    /// Over the bound it claims (NaN and out-of-range values are over every bound).
    Broken,
    /// A method with no claim (the atlas, a peer): measured, not judged.
    Observed,
    /// The method would not draw this font or view (a peer's documented limit).
    Refused,
    /// The method failed to prepare or draw.
    Failed,
    /// The font, or the glyph's outline, could not be read: `reason` says why.
    Unreadable,
}

/// One measured glyph view, or one thing that could not be measured.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// The font file, as found under `--fonts`.
    pub font: String,
    /// The face (of a collection) and instance, e.g. `face 1 wght=700`; empty for a
    /// single font at its default.
    pub face: String,
    /// The glyph id; None for a row about the whole font or method.
    pub glyph: Option<u16>,
    /// The glyph's name in the font, where it has one.
    pub name: String,
    pub size: f64,
    /// The transform, as `--transforms` names it.
    pub transform: String,
    /// The method and its settings, as `--methods` names it.
    pub method: String,
    /// The glyph's traits at this size and transform (see `survey::traits`).
    pub traits: String,
    /// The bound the method's claim sets here, as `info::Bound` writes it ("max ≤ 0.5
    /// and edge MAE ≤ 49/255"); empty for none.
    pub bound: String,
    pub max: f64,
    pub mae_255: f64,
    pub edge_mae_255: f64,
    #[serde(rename = "px_over_0.25")]
    pub over_025: usize,
    #[serde(rename = "px_over_0.5")]
    pub over_05: usize,
    #[serde(rename = "invalid_px")]
    pub invalid: usize,
    /// The worst pixel, in the glyph's slot (0, 0 at the slot's top-left).
    pub worst_x: u32,
    pub worst_y: u32,
    /// Where the glyph's pen lands in its slot, pixels: with the size and transform, it
    /// places the glyph on the pixel grid exactly as measured.
    pub origin_x: f64,
    pub origin_y: f64,
    pub verdict: Verdict,
    /// Why a row is refused, failed or unreadable.
    pub reason: String,
}

impl Row {
    /// A row for `font`/`face` that measured nothing, with its verdict and reason.
    pub fn unmeasured(font: &str, face: &str, verdict: Verdict, reason: String) -> Row {
        Row {
            font: font.to_owned(),
            face: face.to_owned(),
            glyph: None,
            name: String::new(),
            size: 0.0,
            transform: String::new(),
            method: String::new(),
            traits: String::new(),
            bound: String::new(),
            max: 0.0,
            mae_255: 0.0,
            edge_mae_255: 0.0,
            over_025: 0,
            over_05: 0,
            invalid: 0,
            worst_x: 0,
            worst_y: 0,
            origin_x: 0.0,
            origin_y: 0.0,
            verdict,
            reason,
        }
    }

    /// Whether this row measured a glyph (rather than saying why nothing was).
    pub fn is_measured(&self) -> bool {
        self.glyph.is_some()
            && matches!(
                self.verdict,
                Verdict::Ok | Verdict::Limitation | Verdict::Broken | Verdict::Observed
            )
    }

    /// Worst first: by largest error, then edge MAE; ties in the rows' own order.
    pub fn worse(a: &Row, b: &Row) -> std::cmp::Ordering {
        let key = |r: &Row| (nan_high(r.max), nan_high(r.edge_mae_255));
        let (ka, kb) = (key(a), key(b));
        kb.0.total_cmp(&ka.0).then(kb.1.total_cmp(&ka.1))
    }
}

/// NaN sorts as the worst value.
fn nan_high(v: f64) -> f64 {
    if v.is_nan() { f64::INFINITY } else { v }
}

/// `text` as a file name: every character but ASCII letters, digits, `-`, `.` and `_`
/// replaced by `_`.
pub fn file_safe(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-._".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// `rows` as CSV: a header naming [`Row`]'s fields as serde does, a record per row
/// (the csv crate's quoting and number forms).
pub fn to_csv(rows: &[Row]) -> String {
    let mut writer = csv::WriterBuilder::new().from_writer(Vec::new());
    if rows.is_empty() {
        // The header comes with the first record: without one, it is the header of a
        // row written and dropped.
        return csv_header() + "\n";
    }
    for row in rows {
        writer.serialize(row).expect("a row serializes");
    }
    String::from_utf8(writer.into_inner().expect("a Vec takes every byte"))
        .expect("the csv crate writes UTF-8")
}

/// The header [`to_csv`] writes.
pub fn csv_header() -> String {
    let row = Row::unmeasured("", "", Verdict::Unreadable, String::new());
    to_csv(&[row]).lines().next().unwrap_or_default().to_owned()
}

/// Rows read back from [`to_csv`]'s text (what a finished font keeps), or why not.
pub fn from_csv(text: &str) -> Result<Vec<Row>, String> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header = reader.headers().map_err(|e| e.to_string())?;
    if header.iter().collect::<Vec<_>>().join(",") != csv_header() {
        return Err("not a survey's rows: the header differs".into());
    }
    reader
        .deserialize()
        .enumerate()
        .map(|(k, row)| row.map_err(|e| format!("row {}: {e}", k + 1)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_quotes_what_needs_it_and_has_a_column_per_field() {
        let mut row = Row::unmeasured("a,b.ttf", "", Verdict::Unreadable, "say \"no\"".into());
        row.max = f64::INFINITY;
        let csv = to_csv(&[row]);
        let line = csv.lines().nth(1).unwrap();
        assert!(line.starts_with("\"a,b.ttf\","), "{line}");
        assert!(line.ends_with(",unreadable,\"say \"\"no\"\"\""), "{line}");
        assert!(line.contains(",inf,"), "{line}");
        let fields = serde_json::to_value(Row::unmeasured("", "", Verdict::Ok, String::new()))
            .unwrap()
            .as_object()
            .unwrap()
            .len();
        assert_eq!(csv_header().split(',').count(), fields);
    }

    #[test]
    fn rows_read_back_as_written() {
        let mut measured = Row {
            glyph: Some(36),
            name: "A".into(),
            size: 12.5,
            transform: "rotate:30".into(),
            method: "winding".into(),
            traits: "SubpixelDetail".into(),
            bound: "0.02/0.1".into(),
            max: 0.1 + 0.2,
            mae_255: f64::NAN,
            origin_x: 3.015625,
            ..Row::unmeasured("dir/a,\"b\".ttf", "face 1", Verdict::Broken, String::new())
        };
        measured.reason = "two\nlines".into();
        let rows = vec![
            measured,
            Row::unmeasured("x.ttf", "", Verdict::Unreadable, "no".into()),
        ];
        let back = from_csv(&to_csv(&rows)).unwrap();
        assert_eq!(back.len(), 2);
        assert!(back[0].mae_255.is_nan());
        let same =
            |a: &Row, b: &Row| to_csv(std::slice::from_ref(a)) == to_csv(std::slice::from_ref(b));
        assert!(same(&back[0], &rows[0]) && back[1] == rows[1]);
        assert!(from_csv("a,b\n").unwrap_err().contains("header"));
    }

    #[test]
    fn worse_puts_the_largest_error_and_nan_first() {
        let at = |max: f64, edge: f64| Row {
            max,
            edge_mae_255: edge,
            ..Row::unmeasured("f", "", Verdict::Ok, String::new())
        };
        let mut rows = [at(0.1, 5.0), at(f64::NAN, 0.0), at(0.3, 1.0), at(0.3, 2.0)];
        rows.sort_by(Row::worse);
        let order: Vec<(f64, f64)> = rows.iter().map(|r| (r.max, r.edge_mae_255)).collect();
        assert!(order[0].0.is_nan());
        assert_eq!(&order[1..], [(0.3, 2.0), (0.3, 1.0), (0.1, 5.0)]);
    }
}
