//! Corrupted fonts through every row and peer: the shipped fonts damaged in the tables
//! a renderer reads — bytes flipped, 0xFFFFFFFF written, the file cut inside the table —
//! by a seeded generator, each drawn by the reference and by every GPU row and peer the
//! bench compares. A case may draw or be refused (an error value: the command line's
//! exit 2); nothing may panic past the method boundary, and no case may run past its
//! time limit. The damage that once broke a row is kept in
//! `tests/data/corrupt-fonts.txt` and run first.

mod common;

use std::ops::Range;
use std::sync::mpsc;
use std::time::Duration;

use glam::DVec2;
use glyphscope::Error;
use glyphscope::camera::Camera;
use glyphscope::font::{Font, SHIPPED_FONTS};
use glyphscope::methods::{frame, registry};
use glyphscope::reference;
use glyphscope::scene::Scene;

/// The tables damaged, where a font has them.
const TABLES: [&[u8; 4]; 13] = [
    b"glyf", b"loca", b"CFF ", b"gvar", b"cmap", b"hmtx", b"GSUB", b"GPOS", b"fvar", b"head",
    b"hhea", b"maxp", b"HVAR",
];
const TEXT: &str = "Hamburg 12 ÅÉ";
const SEEDS: [u64; 3] = [0x51, 0x52, 0x53];
const CASES_PER_SEED: usize = 70;
/// Far past what a case takes (a few tens of milliseconds): reaching it is a hang.
const LIMIT: Duration = Duration::from_secs(30);

/// One way to damage a font: which shipped font, which table, and what is done there.
#[derive(Clone, Debug)]
struct Damage {
    font: usize,
    table: [u8; 4],
    kind: Kind,
    /// Where in the table, as a fraction of its length.
    at: f64,
    /// For `Flip`: the bytes xored in.
    bytes: Vec<u8>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Flip,
    Ones,
    Truncate,
    /// Bytes written at an exact offset into the table (the kept cases).
    Write(usize),
}

/// A fixed pseudo-random sequence.
struct Sequence(u64);

impl Sequence {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 16
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Where `tag` lies in a single font's bytes, from its table directory.
fn table_range(bytes: &[u8], tag: &[u8; 4]) -> Option<Range<usize>> {
    let u16_at = |at: usize| u16::from_be_bytes([bytes[at], bytes[at + 1]]) as usize;
    let u32_at = |at: usize| {
        u32::from_be_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]) as usize
    };
    (0..u16_at(4)).find_map(|k| {
        let record = 12 + 16 * k;
        (&bytes[record..record + 4] == tag).then(|| {
            let start = u32_at(record + 8);
            start..start + u32_at(record + 12)
        })
    })
}

/// `count` damages made by the sequence seeded with `seed`.
fn damages(seed: u64, count: usize) -> Vec<Damage> {
    let mut random = Sequence(seed);
    let mut out = Vec::with_capacity(count);
    while out.len() < count {
        let font = random.below(SHIPPED_FONTS.len());
        let table = *TABLES[random.below(TABLES.len())];
        if table_range(SHIPPED_FONTS[font].2, &table).is_none() {
            continue;
        }
        let kind = [Kind::Flip, Kind::Ones, Kind::Truncate][random.below(3)];
        let at = random.below(1 << 20) as f64 / f64::from(1 << 20);
        let bytes = (0..1 + random.below(4))
            .map(|_| 1 + random.below(255) as u8)
            .collect();
        out.push(Damage {
            font,
            table,
            kind,
            at,
            bytes,
        });
    }
    out
}

/// The damaged font's bytes.
fn damaged(d: &Damage) -> Vec<u8> {
    let mut bytes = SHIPPED_FONTS[d.font].2.to_vec();
    let range = table_range(&bytes, &d.table).expect("chosen among the font's tables");
    let len = range.len().max(1);
    let at = range.start + ((d.at * len as f64) as usize).min(len - 1);
    match d.kind {
        Kind::Flip => {
            for (k, b) in d.bytes.iter().enumerate() {
                if let Some(byte) = bytes.get_mut(at + k) {
                    *byte ^= b;
                }
            }
        }
        Kind::Ones => {
            let at = at & !1;
            for byte in bytes.iter_mut().skip(at).take(4) {
                *byte = 0xFF;
            }
        }
        Kind::Truncate => bytes.truncate(at),
        Kind::Write(offset) => {
            for (k, b) in d.bytes.iter().enumerate() {
                bytes[range.start + offset + k] = *b;
            }
        }
    }
    bytes
}

/// What one case did: per row, drawn or refused (and whether a caught panic refused
/// it); None where the font or its text was refused before any row.
type Outcome = Option<Vec<(&'static str, Result<(), String>)>>;

fn run(bytes: Vec<u8>) -> Outcome {
    let font = Font::from_bytes(bytes, "corrupt.ttf").ok()?;
    let scene = Scene::from_text(&font, TEXT).ok()?;
    let camera = Camera::new(160, 32, 16.0, DVec2::new(4.0, 24.0));
    let mut rows = vec![(
        "reference",
        reference::rasterize(&scene, &camera)
            .map(|_| ())
            .map_err(|e| e.to_string()),
    )];
    // Every row the registry makes a GPU method of: the project's methods, the
    // baseline and the peers, which read the font themselves.
    for name in registry::names().filter(|&n| n != "reference") {
        let drawn = registry::create(name, &[]).and_then(|mut method| {
            method.prepare(common::gpu(), &scene)?;
            frame::render_image(common::gpu(), method.as_mut(), &camera).map(|_| ())
        });
        let drawn = drawn.map_err(|e| {
            let line = e.to_string();
            assert!(
                !line.contains('\n'),
                "{name}: a refusal is one line: {line}"
            );
            assert!(
                matches!(
                    e,
                    Error::Refused(_) | Error::Input(_) | Error::Font(_) | Error::Gpu(_)
                ),
                "{name}: {e:?}"
            );
            line
        });
        rows.push((name, drawn));
    }
    Some(rows)
}

/// Runs `damage` on a thread of its own, within the time limit; panics (fails the
/// test) on a panic past the method boundary or a hang, naming the damage.
fn run_within_limit(damage: &Damage) -> Outcome {
    let bytes = damaged(damage);
    let (send, receive) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(std::panic::catch_unwind(|| run(bytes)));
    });
    match receive.recv_timeout(LIMIT) {
        Ok(Ok(outcome)) => outcome,
        Ok(Err(_)) => panic!("a panic past the method boundary: {damage:?}"),
        Err(_) => panic!("past {LIMIT:?}: {damage:?}"),
    }
}

/// The damages kept in tests/data/corrupt-fonts.txt: `font-file table offset hex`.
fn kept() -> Vec<Damage> {
    include_str!("data/corrupt-fonts.txt")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            let font = SHIPPED_FONTS
                .iter()
                .position(|f| f.1 == fields[0])
                .expect("a shipped font");
            let table = fields[1].as_bytes().try_into().expect("a four-letter tag");
            let offset = fields[2].parse().expect("an offset");
            let bytes = (0..fields[3].len() / 2)
                .map(|k| u8::from_str_radix(&fields[3][2 * k..2 * k + 2], 16).unwrap())
                .collect();
            Damage {
                font,
                table,
                kind: Kind::Write(offset),
                at: 0.0,
                bytes,
            }
        })
        .collect()
}

/// The kept cases first: Inter with its weight axis's maximum overwritten (below its
/// minimum), which glyphon's rasterizer clamped the wrong way round and panicked on, is
/// refused where the font is read, in one line, for every row alike.
#[test]
fn kept_corruptions_are_refused_or_drawn_never_a_panic() {
    for damage in kept() {
        let refused = Font::from_bytes(damaged(&damage), "inter-broken-axis.ttf");
        match refused {
            Err(Error::Font(why)) => {
                assert!(why.contains("variation axis 'wght' is broken"), "{why}");
                assert!(!why.contains('\n'));
            }
            other => panic!("{damage:?}: {:?}", other.map(|_| "read")),
        }
        assert!(run_within_limit(&damage).is_none());
    }
}

/// Three seeds of damaged fonts through every row: 0 panics, 0 hangs; what is drawn
/// and refused, per row, printed.
#[test]
fn corrupted_fonts_through_every_row_never_panic_nor_hang() {
    for seed in SEEDS {
        let (mut unread, mut drawn, mut refused, mut caught) = (0, 0, 0, 0);
        for damage in damages(seed, CASES_PER_SEED) {
            match run_within_limit(&damage) {
                None => unread += 1,
                Some(rows) => {
                    for (name, result) in rows {
                        match result {
                            Ok(()) => drawn += 1,
                            Err(why) => {
                                refused += 1;
                                if why.contains("a panic, caught") {
                                    caught += 1;
                                    println!("seed {seed:#x}: {name}: {why} ({damage:?})");
                                }
                            }
                        }
                    }
                }
            }
        }
        println!(
            "seed {seed:#x}: {CASES_PER_SEED} fonts, {unread} refused when read; {drawn} \
             renders drawn, {refused} refused ({caught} of them a row's panic, caught)"
        );
        // The damage reaches the rows: most damaged fonts are still read and drawn.
        assert!(drawn > 0 && unread < CASES_PER_SEED, "seed {seed:#x}");
    }
}
