//! The figure of `winding aa=area` in docs/methods/winding.md: one quadratic curve
//! against one pixel, in the frame the integral runs in, coloured by the zone each part
//! of it lies in, with the curve's term from the CPU mirror. Left: a camera that neither
//! rotates nor skews the glyph (the pixel is a square); right: rotated 20° (in the
//! frame, which keeps the glyph's axes, the pixel is a turned square).
//!
//!     cargo run --release --example area_zones -- docs/area-zones.svg

use std::fmt::Write;

use glam::{DMat2, DVec2};
use glyphscope::geometry::{Quad, monotone_pieces};
use glyphscope::methods::winding::area::{self, PixelFrame};

/// Pixels of the figure per pixel width of the frame.
const SCALE: f64 = 64.0;
/// The part of the frame each panel shows.
const U_RANGE: (f64, f64) = (-2.4, 2.6);
const V_RANGE: (f64, f64) = (-1.7, 1.7);
const PANEL_W: f64 = (U_RANGE.1 - U_RANGE.0) * SCALE;
const PANEL_H: f64 = (V_RANGE.1 - V_RANGE.0) * SCALE;
const TOP: f64 = 44.0;
const BOTTOM: f64 = 96.0;

const OUTSIDE: &str = "#e4e4e4";
const LEFT: &str = "#fbf3dc";
const ACROSS: &str = "#cfe3ff";
const RIGHT: &str = "#d7f2d7";
const INK: [(&str, &str); 4] = [
    ("#9a9a9a", "outside the rows: no term"),
    ("#c8961e", "left of the pixel: no term"),
    ("#1f5fbf", "across: ∫ (u − L(v)) dv, cut at the sides"),
    ("#2e8b2e", "right: the pixel's area between the end heights"),
];

fn main() {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "docs/area-zones.svg".into());
    // One curve in local units, the pixel centred at the origin, one unit a pixel.
    let curve: Quad = [
        DVec2::new(-2.1, -1.4),
        DVec2::new(0.0, 0.4),
        DVec2::new(2.6, 0.8),
    ];
    let width = 2.0 * PANEL_W + 30.0;
    let height = TOP + PANEL_H + BOTTOM;
    let mut svg = format!(
        "<svg xmlns='http://www.w3.org/2000/svg' width='{width}' height='{height}' \
         font-family='sans-serif' font-size='12'>\n\
         <rect width='100%' height='100%' fill='white'/>\n"
    );
    for (k, degrees) in [0.0f64, 20.0].into_iter().enumerate() {
        // Local → image: a rotation with image y down; the pixel's steps in local units
        // are the inverse's columns.
        let to_image =
            DMat2::from_angle(degrees.to_radians()) * DMat2::from_diagonal(DVec2::new(1.0, -1.0));
        let to_local = to_image.inverse();
        let frame = PixelFrame::new(to_local.x_axis, to_local.y_axis, 1.0).expect("a pixel");
        let in_frame = curve.map(|p| frame.map(p));
        let term: f64 = monotone_pieces(in_frame)
            .into_iter()
            .flatten()
            .map(|piece| area::curve_term(piece, &frame))
            .sum();
        let x0 = k as f64 * (PANEL_W + 30.0);
        let title = if degrees == 0.0 {
            "no rotation: the pixel is a square".to_string()
        } else {
            format!("rotated {degrees}°: the pixel turns with it")
        };
        panel(&mut svg, x0, &frame, &in_frame, &title, term);
    }
    for (i, (colour, what)) in INK.iter().enumerate() {
        let (x, y) = (10.0, TOP + PANEL_H + 22.0 + i as f64 * 18.0);
        writeln!(
            svg,
            "<line x1='{x}' y1='{}' x2='{}' y2='{}' stroke='{colour}' stroke-width='4'/>\
             <text x='{}' y='{}'>{what}</text>",
            y - 4.0,
            x + 24.0,
            y - 4.0,
            x + 32.0,
            y
        )
        .unwrap();
    }
    svg.push_str("</svg>\n");
    std::fs::write(&path, svg).unwrap_or_else(|e| {
        eprintln!("error: cannot write '{path}': {e}");
        std::process::exit(2);
    });
    println!("wrote {path}");
}

/// Where the side from corner `p` up to corner `q` is at height `v`.
fn along(p: DVec2, q: DVec2, v: f64) -> f64 {
    if q.y == p.y {
        p.x.min(q.x)
    } else {
        p.x + (q.x - p.x) * (v - p.y) / (q.y - p.y)
    }
}

/// The chord of the pixel at height `v`: its left and right ends, if it has one. The
/// left side runs from the bottom corner through `left` to the top one, the right side
/// through the opposite corner.
fn chord(v: f64, f: &PixelFrame) -> Option<(f64, f64)> {
    let (bottom, top, left) = (f.bottom, -f.bottom, f.left);
    if v < bottom.y || v > top.y {
        return None;
    }
    let side = |middle: DVec2| {
        if v <= middle.y {
            along(bottom, middle, v)
        } else {
            along(middle, top, v)
        }
    };
    Some((side(left), side(-left)))
}

fn zone_of(p: DVec2, f: &PixelFrame) -> usize {
    match chord(p.y, f) {
        None => 0,
        Some((left, _)) if p.x < left => 1,
        Some((_, right)) if p.x > right => 3,
        Some(_) => 2,
    }
}

fn panel(svg: &mut String, x0: f64, f: &PixelFrame, curve: &Quad, title: &str, term: f64) {
    let at = |p: DVec2| {
        (
            x0 + (p.x - U_RANGE.0) * SCALE,
            TOP + (V_RANGE.1 - p.y) * SCALE,
        )
    };
    let polygon = |points: &[DVec2], fill: &str| {
        let list: Vec<String> = points
            .iter()
            .map(|&p| {
                let (x, y) = at(p);
                format!("{x:.1},{y:.1}")
            })
            .collect();
        format!("<polygon points='{}' fill='{fill}'/>\n", list.join(" "))
    };
    let (bottom, top, left) = (f.bottom, -f.bottom, f.left);
    let (lo, hi) = U_RANGE;
    let corner = |u: f64, v: f64| DVec2::new(u, v);
    svg.push_str(&polygon(
        &[
            corner(lo, V_RANGE.0),
            corner(hi, V_RANGE.0),
            corner(hi, V_RANGE.1),
            corner(lo, V_RANGE.1),
        ],
        OUTSIDE,
    ));
    // The rows left of the pixel's left side, the pixel, the rows right of its right
    // side.
    svg.push_str(&polygon(
        &[corner(lo, bottom.y), bottom, left, top, corner(lo, top.y)],
        LEFT,
    ));
    svg.push_str(&polygon(&[bottom, -left, top, left], ACROSS));
    svg.push_str(&polygon(
        &[bottom, corner(hi, bottom.y), corner(hi, top.y), top, -left],
        RIGHT,
    ));
    // The curve, each short piece in its zone's ink.
    let point = |t: f64| {
        curve[0] * ((1.0 - t) * (1.0 - t)) + curve[1] * (2.0 * t * (1.0 - t)) + curve[2] * (t * t)
    };
    let steps = 400;
    for s in 0..steps {
        let (a, b) = (
            point(s as f64 / steps as f64),
            point((s + 1) as f64 / steps as f64),
        );
        let colour = INK[zone_of((a + b) * 0.5, f)].0;
        let ((xa, ya), (xb, yb)) = (at(a), at(b));
        writeln!(
            svg,
            "<line x1='{xa:.2}' y1='{ya:.2}' x2='{xb:.2}' y2='{yb:.2}' stroke='{colour}' \
             stroke-width='3' stroke-linecap='round'/>"
        )
        .unwrap();
    }
    let (tx, ty) = at(corner(lo, V_RANGE.1));
    writeln!(
        svg,
        "<text x='{}' y='{}' font-weight='bold'>{title}</text>\
         <text x='{}' y='{}'>this curve's term: {term:.4} (the pixel's area is 1)</text>",
        tx + 4.0,
        ty - 24.0,
        tx + 4.0,
        ty - 8.0
    )
    .unwrap();
}
