//! `glyphscope render` as a user runs it: outputs for good input, one clear line and
//! exit code 2 for bad input, never a panic, never an image.

mod common;

use std::path::PathBuf;

use common::binary::{bin, run, run_within, scratch};

/// Runs `args` and checks the command succeeded, showing its stderr if not.
fn run_ok(args: &[&str]) {
    let result = run(args);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
}

/// Runs `render` with `args` plus an output path and checks it fails cleanly, with a
/// message containing `expect`.
fn fails(name: &str, args: &[&str], expect: &str) {
    let out = scratch(&format!("{name}.png"));
    let _ = std::fs::remove_file(&out);
    let mut all = vec!["render"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let result = run(&all);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(
        result.status.code(),
        Some(2),
        "{name}: exit {:?}, stderr: {stderr}",
        result.status
    );
    assert!(!stderr.contains("panicked"), "{name}: panic: {stderr}");
    assert!(
        stderr.to_lowercase().contains(&expect.to_lowercase()),
        "{name}: stderr lacks {expect:?}: {stderr}"
    );
    assert!(!out.exists(), "{name}: an image was written");
}

#[test]
fn reference_render_writes_png_and_stats() {
    let out = scratch("ok.png");
    let stats = scratch("ok.json");
    run_ok(&[
        "render",
        "--text",
        "Hello\\nworld",
        "--size",
        "24",
        "--method",
        "reference",
        "--matrix",
        "1,0.2,0,1",
        "--out",
        out.to_str().unwrap(),
        "--stats",
        stats.to_str().unwrap(),
    ]);
    let img = image::open(&out).unwrap();
    assert_eq!(img.color(), image::ColorType::L8, "8-bit grayscale");
    let gray = img.to_luma8();
    assert!(gray.pixels().any(|p| p.0[0] == 255) && gray.pixels().any(|p| p.0[0] == 0));
    // The default frame keeps the margin free of ink.
    assert!((0..gray.width()).all(|x| gray.get_pixel(x, 0).0[0] == 0));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(json["method"], "reference");
    assert!(json["gpu_ms"].is_null());
    assert!(json["cpu_prepare_ms"].as_f64().unwrap() >= 0.0);
    assert_eq!(json["gpu_bytes"], 0);
    assert_eq!(json["width"], gray.width());
    assert!(json["adapter"].as_str().unwrap().contains("cpu"));
}

#[test]
fn error_image_compares_with_the_reference() {
    let (out, err, stats) = (scratch("e.png"), scratch("e-err.png"), scratch("e.json"));
    run_ok(&[
        "render",
        "--text",
        "Ag",
        "--size",
        "30",
        "--method",
        "bounds",
        "--out",
        out.to_str().unwrap(),
        "--error-image",
        err.to_str().unwrap(),
        "--stats",
        stats.to_str().unwrap(),
    ]);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    // Glyph boxes cover far more than the glyphs: red, and a large error.
    let error = &json["error"];
    assert!(error["mae_255"].as_f64().unwrap() > 10.0, "{error}");
    assert!(error["pixels_over_05"].as_u64().unwrap() > 0);
    let diff = image::open(&err).unwrap().to_rgb8();
    assert!(
        diff.pixels().any(|p| p.0[0] > 200 && p.0[2] == 0),
        "no red where boxes over-cover"
    );
    assert!(
        json["gpu_ms"].as_f64().unwrap() > 0.0,
        "lavapipe has timestamps"
    );
}

#[test]
fn glyph_id_fonts_and_variations() {
    for (font, extra) in [
        ("fonts/lmroman10-regular.otf", vec!["--glyph-id", "40"]),
        (
            "fonts/Inter-roman.var.ttf",
            vec!["--text", "W", "--variation", "wght=900"],
        ),
    ] {
        let out = scratch("font.png");
        let mut args = vec![
            "render",
            "--font",
            font,
            "--size",
            "40",
            "--method",
            "reference",
        ];
        args.extend(extra);
        args.extend(["--out", out.to_str().unwrap()]);
        let result = run(&args);
        assert!(
            result.status.success(),
            "{font}: {}",
            String::from_utf8_lossy(&result.stderr)
        );
        assert!(
            image::open(&out)
                .unwrap()
                .to_luma8()
                .pixels()
                .any(|p| p.0[0] > 0)
        );
    }
}

#[test]
fn heavier_weight_covers_more() {
    let area = |wght: &str| {
        let stats = scratch(&format!("w{wght}.json"));
        let out = scratch(&format!("w{wght}.png"));
        run_ok(&[
            "render",
            "--font",
            "fonts/Inter-roman.var.ttf",
            "--text",
            "Wo",
            "--size",
            "64",
            "--width",
            "160",
            "--height",
            "90",
            "--origin",
            "5,70",
            "--variation",
            &format!("wght={wght}"),
            "--method",
            "reference",
            "--out",
            out.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ]);
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        json["covered_area_px"].as_f64().unwrap()
    };
    assert!(area("900") > area("100") * 1.5);
}

#[test]
fn bad_input_fails_cleanly() {
    let garbage = scratch("garbage.ttf");
    std::fs::write(&garbage, b"definitely not a font, just some bytes").unwrap();
    let g = garbage.to_str().unwrap();
    let base = ["--size", "20", "--method", "reference"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut v: Vec<&'static str> = extra.to_vec();
        v.extend_from_slice(&base);
        v
    };
    fails(
        "missing font",
        &with(&["--font", "no/such/font.ttf", "--text", "a"]),
        "cannot read font",
    );
    fails(
        "corrupt font",
        &[&["--font", g, "--text", "a"][..], &base].concat(),
        "not a usable font",
    );
    fails("glyph id", &with(&["--glyph-id", "99999"]), "out of range");
    fails("missing char", &with(&["--text", "a\u{E000}"]), "U+E000");
    fails("empty text", &with(&["--text", ""]), "empty");
    fails("blank text", &with(&["--text", "   "]), "empty");
    for size in ["0", "-3", "nan", "inf", "5e9"] {
        fails(
            size,
            &["--text", "a", "--method", "reference", "--size", size],
            "size",
        );
    }
    fails(
        "huge image",
        &with(&["--text", "a", "--width", "20000", "--height", "20"]),
        "limit",
    );
    fails(
        "huge default frame",
        &["--text", "abc", "--size", "900000", "--method", "reference"],
        "--width",
    );
    fails(
        "unknown method",
        &["--text", "a", "--size", "20", "--method", "magic"],
        "unknown method",
    );
    fails(
        "unknown param",
        &with(&["--text", "a", "--param", "rays=2"]),
        "takes no parameters",
    );
    fails(
        "malformed param",
        &with(&["--text", "a", "--param", "rays"]),
        "KEY=VALUE",
    );
    fails(
        "malformed origin",
        &with(&["--text", "a", "--origin", "1,x"]),
        "not a number",
    );
    fails(
        "short matrix",
        &with(&["--text", "a", "--matrix", "1,0,0"]),
        "4 comma-separated",
    );
    fails(
        "singular matrix",
        &with(&["--text", "a", "--matrix", "1,1,1,1"]),
        "singular",
    );
    fails("tilt", &with(&["--text", "a", "--tilt", "95"]), "tilt");
    fails(
        "no axis",
        &with(&["--text", "a", "--variation", "wght=700"]),
        "not variable",
    );
    fails(
        "axis range",
        &[
            "--font",
            "fonts/Inter-roman.var.ttf",
            "--text",
            "a",
            "--size",
            "20",
            "--method",
            "reference",
            "--variation",
            "wght=5000",
        ],
        "outside the axis range",
    );
    fails(
        "unknown axis",
        &[
            "--font",
            "fonts/Inter-roman.var.ttf",
            "--text",
            "a",
            "--size",
            "20",
            "--method",
            "reference",
            "--variation",
            "opsz=14",
        ],
        "has no variation axis 'opsz' (it has: 'wght')",
    );
    fails(
        "long axis tag",
        &with(&["--text", "a", "--variation", "wghts=700"]),
        "1 to 4 ASCII",
    );
    fails(
        "non-ASCII axis tag",
        &with(&["--text", "a", "--variation", "wé=700"]),
        "1 to 4 ASCII",
    );
    fails("no text", &base, "give --text or --glyph-id");
    // cosmic-text panics on a font size of 0, which 1e-50 px/em is in its f32.
    fails(
        "vanishing size for glyphon",
        &["--text", "a", "--size", "1e-50", "--method", "glyphon"],
        "rounds to 0",
    );
}

/// `bytes`, a TrueType or OpenType font, with its `hhea` ascender and descender
/// overwritten (the rest intact, the table's checksum left stale, as a damaged file
/// has it). The table directory is read here by hand, from the OpenType specification's
/// layout: `numTables` at byte 4, 16-byte records (tag, checksum, offset, length) from
/// byte 12; `hhea` holds `ascender` at byte 4 and `descender` at byte 6, big-endian.
fn with_hhea_extents(mut bytes: Vec<u8>, ascender: i16, descender: i16) -> Vec<u8> {
    let be16 = |b: &[u8], at: usize| usize::from(u16::from_be_bytes([b[at], b[at + 1]]));
    let be32 = |b: &[u8], at: usize| u32::from_be_bytes(b[at..at + 4].try_into().unwrap());
    let hhea = (0..be16(&bytes, 4))
        .map(|i| 12 + 16 * i)
        .find(|&record| &bytes[record..record + 4] == b"hhea")
        .map(|record| be32(&bytes, record + 8) as usize)
        .expect("the font has an hhea table");
    bytes[hhea + 4..hhea + 6].copy_from_slice(&ascender.to_be_bytes());
    bytes[hhea + 6..hhea + 8].copy_from_slice(&descender.to_be_bytes());
    bytes
}

/// A font whose `hhea` gives lines a negative height (DejaVu Sans with ascender −10 629
/// and descender +23 581, line gap 0: −34 210 units) once hung glyphon, inside
/// cosmic-text's layout. Every method and peer must end within seconds, by a drawn frame
/// (exit 0) or one line naming what it cannot draw (exit 2), never a panic; glyphon's
/// line names the height. The run is bounded, so a hang fails here.
#[test]
fn a_font_with_negative_line_height_ends_every_method_within_seconds() {
    let font = scratch("negative-line-height.ttf");
    let dejavu = std::fs::read("fonts/DejaVuSans.ttf").unwrap();
    std::fs::write(&font, with_hhea_extents(dejavu, -10629, 23581)).unwrap();
    let limit = std::time::Duration::from_secs(30);
    for method in glyphscope::methods::registry::names() {
        let out = scratch(&format!("negative-line-height-{method}.png"));
        let _ = std::fs::remove_file(&out);
        let args = [
            "render",
            "--font",
            font.to_str().unwrap(),
            "--text",
            "Hamburgefonstiv ffi 123\\nline two",
            "--size",
            "24",
            "--method",
            method,
            "--out",
            out.to_str().unwrap(),
        ];
        let started = std::time::Instant::now();
        let result = run_within(&args, limit)
            .unwrap_or_else(|| panic!("{method}: still running after {limit:?}"));
        let stderr = String::from_utf8_lossy(&result.stderr);
        let code = result.status.code();
        println!("{method}: exit {code:?} in {:?}", started.elapsed());
        assert!(!stderr.contains("panicked"), "{method}: panic: {stderr}");
        match method {
            // The file is a usable font: a method of glyphscope's draws it.
            "winding" => assert_eq!(code, Some(0), "{method}: {stderr}"),
            "glyphon" => {
                assert_eq!(code, Some(2), "{method}: {stderr}");
                assert!(
                    stderr.contains("-34210 units high") && stderr.lines().count() == 1,
                    "{method}: {stderr}"
                );
            }
            _ => assert!(matches!(code, Some(0 | 2)), "{method}: {code:?}, {stderr}"),
        }
        assert_eq!(out.exists(), code == Some(0), "{method}: image iff drawn");
    }
}

/// Runs `info` with no display to open, returning (exit code, stdout, stderr).
fn info(args: &[&str]) -> (Option<i32>, String, String) {
    let result = bin()
        .arg("info")
        .args(args)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the binary runs");
    (
        result.status.code(),
        String::from_utf8_lossy(&result.stdout).into_owned(),
        String::from_utf8_lossy(&result.stderr).into_owned(),
    )
}

#[test]
fn info_reports_the_outline_table_and_each_glyphs_placement() {
    // The variable twin of tests/fonts/placement.ttf at SHFT 0.5 (tables in
    // tools/make_test_fonts.py): A's xMin 100, hmtx lsb 40 and advance 600; gvar moves pp1
    // by 0.5 × 30 = 15 and pp2 by 0.5 × 80 = 40. pp1.x = 100 − 40 + 15 = 75, shift −75,
    // advance (60 + 600 + 40) − 75 = 625.
    let (code, out, err) = info(&[
        "--font",
        "tests/fonts/placement-var.ttf",
        "--variation",
        "SHFT=0.5",
        "--text",
        "AA",
    ]);
    assert_eq!(code, Some(0), "{err}");
    for line in [
        "outline table: 'glyf' (sfntVersion 0x00010000 is not 'OTTO')",
        "units per em: 1000",
        "axis 'SHFT': 0..1, default 0",
        "glyph 1: advance 625, lsb 40, xMin 100, pp1.x 75, shift -75",
    ] {
        assert!(
            out.lines().any(|l| l == line),
            "no line {line:?} in:\n{out}"
        );
    }
    // Glyph A appears once however often the text uses it.
    assert_eq!(out.matches("glyph 1:").count(), 1, "{out}");
    let (code, out, err) = info(&["--font", "tests/fonts/both-outlines.otf", "--glyph-id", "1"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("outline table: 'CFF ' (sfntVersion 'OTTO')"),
        "{out}"
    );
    assert!(
        out.contains("glyph 1: advance 600, lsb 100, shift 0"),
        "{out}"
    );
}

#[test]
fn short_axis_tags_are_padded_on_the_command_line() {
    let font = "tests/fonts/short-tags.ttf";
    for variation in ["M1=0.5", "M1  =0.5", " M1=0.5"] {
        let (code, out, err) = info(&["--font", font, "--variation", variation]);
        assert_eq!(code, Some(0), "{variation}: {err}");
        assert!(out.contains("axis 'M1  ': 0..1, default 0"), "{out}");
        assert!(out.contains("instance: 'M1  ' = 0.5"), "{variation}: {out}");
    }
    let out = scratch("short-tags.png");
    run_ok(&[
        "render",
        "--font",
        font,
        "--text",
        "A",
        "--size",
        "20",
        "--method",
        "reference",
        "--variation",
        "M1=0.5,HV=50",
        "--out",
        out.to_str().unwrap(),
    ]);
}

#[test]
fn info_fails_cleanly_on_bad_input() {
    for (args, expect) in [
        (vec!["--font", "no/such/font.ttf"], "cannot read font file"),
        (vec!["--glyph-id", "999999"], "out of range"),
        (vec!["--text", "\u{E000}"], "U+E000"),
        (
            vec![
                "--font",
                "tests/fonts/short-tags.ttf",
                "--variation",
                "M2=0.5",
            ],
            "has no variation axis 'M2  ' (it has: 'M1  ', 'HV  ')",
        ),
        (vec!["--variation", "MOVE1=0.5"], "1 to 4 ASCII"),
    ] {
        let (code, out, err) = info(&args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(expect), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
    }
}

#[test]
fn xor_stencil_renders_from_the_command_line() {
    let (out, stats, err) = (
        scratch("xor.png"),
        scratch("xor.json"),
        scratch("xor-err.png"),
    );
    run_ok(&[
        "render",
        "--text",
        "Ag",
        "--size",
        "40",
        "--method",
        "xor-stencil",
        "--param",
        "fill=evenodd",
        "--param",
        "passes=2",
        "--out",
        out.to_str().unwrap(),
        "--stats",
        stats.to_str().unwrap(),
        "--error-image",
        err.to_str().unwrap(),
    ]);
    assert_eq!(image::open(&out).unwrap().color(), image::ColorType::L8);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    // DejaVu has no overlaps: even-odd is nonzero here, up to sampling.
    assert!(json["error"]["mae_255"].as_f64().unwrap() < 5.0, "{json}");
    assert!(json["curves_per_pixel"]["mean"].as_f64().unwrap() > 0.0);
    assert!(json["gpu_ms"].as_f64().unwrap() > 0.0);

    let overlay = scratch("xor-wire.png");
    run_ok(&[
        "render",
        "--text",
        "Ag",
        "--size",
        "40",
        "--method",
        "xor-stencil",
        "--param",
        "overlay=wireframe",
        "--out",
        overlay.to_str().unwrap(),
    ]);
    assert_eq!(
        image::open(&overlay).unwrap().color(),
        image::ColorType::Rgb8
    );

    let xor = |param: &'static str| -> Vec<&'static str> {
        vec![
            "--text",
            "a",
            "--size",
            "20",
            "--method",
            "xor-stencil",
            "--param",
            param,
        ]
    };
    fails("xor msaa", &xor("msaa=16"), "msaa must be 1 or 4");
    fails("xor passes", &xor("passes=0"), "passes must be");
    fails("xor fill", &xor("fill=odd"), "nonzero or evenodd");
    fails(
        "xor overlay",
        &xor("overlay=purple"),
        "overlay must be none or wireframe",
    );
}

/// `stability` runs the sweep on the cases and methods named, prints the table and
/// writes each worst frame, its error map and the table; unknown names are bad input.
#[test]
fn stability_sweeps_the_named_cases_and_rejects_unknown_names() {
    let dir = scratch("stability");
    let _ = std::fs::remove_dir_all(&dir);
    let result = run(&[
        "stability",
        "--quick",
        "--cases",
        "pentagram,thin-stem",
        "--methods",
        "winding,sdf-cells exact",
        "--out",
        dir.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&result.stdout);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    // Pentagram crosses itself: a limitation of exact distances, shown with its numbers.
    assert!(
        stdout.contains("| pentagram | sdf-cells exact |"),
        "{stdout}"
    );
    assert!(stdout.contains("limitation"), "{stdout}");
    assert!(stdout.contains("| thin-stem | winding |"), "{stdout}");
    for file in [
        "stability.md",
        "stability.json",
        "pentagram--winding.png",
        "pentagram--winding-error.png",
        "thin-stem--sdf-cells-exact-error.png",
    ] {
        assert!(dir.join(file).is_file(), "{file} missing");
    }
    for (flag, name) in [("--cases", "no-such-case"), ("--methods", "no-such-method")] {
        let result = run(&["stability", "--quick", flag, name]);
        assert_eq!(result.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&result.stderr).contains(name));
    }
}

/// `render --magnify N --focus worst`: each N×N block of the picture is the pixel the
/// plain render wrote at the window's place, and the window is centred on the pixel
/// the error statistics name as the worst.
#[test]
fn magnified_blocks_are_the_rendered_pixels_around_the_worst() {
    let view = [
        "render",
        "--text",
        "Hamburg",
        "--size",
        "12",
        "--width",
        "160",
        "--height",
        "96",
        "--method",
        "winding",
        "--param",
        "aa=rays",
        "--param",
        "samples=1",
    ];
    let (plain, plain_stats, error) = (scratch("m.png"), scratch("m.json"), scratch("m-e.png"));
    let mut args = view.to_vec();
    args.extend([
        "--out",
        plain.to_str().unwrap(),
        "--stats",
        plain_stats.to_str().unwrap(),
        "--error-image",
        error.to_str().unwrap(),
    ]);
    run_ok(&args);
    let (picture, picture_stats) = (scratch("m16.png"), scratch("m16.json"));
    let mut args = view.to_vec();
    args.extend([
        "--magnify",
        "16",
        "--focus",
        "worst",
        "--out",
        picture.to_str().unwrap(),
        "--stats",
        picture_stats.to_str().unwrap(),
    ]);
    run_ok(&args);
    let read = |p: &PathBuf| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
    };
    let (plain_json, window) = (
        read(&plain_stats),
        read(&picture_stats)["magnified"].clone(),
    );
    let worst = &plain_json["error"]["worst_pixel"];
    assert!(
        plain_json["error"]["max"].as_f64().unwrap() > 0.05,
        "{plain_json}"
    );
    assert_eq!(window["focus"], *worst, "{window}");
    let coverage = image::open(&plain).unwrap().to_luma8();
    let magnified = image::open(&picture).unwrap().to_rgb8();
    assert_eq!(magnified.dimensions(), coverage.dimensions());
    let field = |k: &str| window[k].as_u64().unwrap() as u32;
    let (x0, y0, cols, rows) = (field("x0"), field("y0"), field("cols"), field("rows"));
    // The focus lies inside the window.
    let (fx, fy) = (
        worst[0].as_u64().unwrap() as u32,
        worst[1].as_u64().unwrap() as u32,
    );
    assert!((x0..x0 + cols).contains(&fx) && (y0..y0 + rows).contains(&fy));
    let mut inked = 0;
    for j in 0..rows {
        for i in 0..cols {
            // Inside the block, off the grid line on its top and left edge.
            let (px, py) = (i * 16 + 8, j * 16 + 8);
            if px >= magnified.width() || py >= magnified.height() {
                continue;
            }
            let shown = magnified.get_pixel(px, py).0;
            let value = coverage.get_pixel(x0 + i, y0 + j).0[0];
            assert_eq!(
                shown,
                [value; 3],
                "block ({i}, {j}) of pixel ({}, {})",
                x0 + i,
                y0 + j
            );
            inked += usize::from(value > 0);
        }
    }
    assert!(inked > 10, "the window shows ink: {inked} blocks");
}

/// From ×32 the picture writes values and draws the outline; bad magnifier input is one
/// line and exit 2.
#[test]
fn magnified_picture_draws_error_outline_and_refuses_bad_input() {
    let picture = scratch("m32.png");
    run_ok(&[
        "render",
        "--text",
        "o",
        "--size",
        "10",
        "--method",
        "tessellation",
        "--magnify",
        "32",
        "--overlay",
        "error,outline",
        "--width",
        "64",
        "--height",
        "64",
        "--out",
        picture.to_str().unwrap(),
    ]);
    let img = image::open(&picture).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (64, 64));
    let orange = img.pixels().filter(|p| p.0 == [255, 170, 0]).count();
    assert!(orange > 20, "the outline is drawn: {orange} pixels");
    let base = ["--text", "a", "--size", "20", "--method", "reference"];
    let with = |extra: &[&'static str]| [&base[..], extra].concat();
    fails("magnify 0", &with(&["--magnify", "0"]), "magnify");
    fails("magnify 65", &with(&["--magnify", "65"]), "magnify");
    fails("focus word", &with(&["--focus", "middle"]), "focus");
    fails("focus outside", &with(&["--focus", "5000,1"]), "outside");
    fails("overlay name", &with(&["--overlay", "sparkles"]), "overlay");
}

/// The explorer where there is no display (ssh, CI): one line saying what it needs, the
/// window's libraries named, and exit 2; never a panic.
#[cfg(all(feature = "app", target_os = "linux"))]
#[test]
fn the_explorer_without_a_display_says_so_in_one_line() {
    let result = bin()
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    for named in [
        "needs a display",
        "libxkbcommon-x11-0",
        "libwayland-client0",
    ] {
        assert!(stderr.contains(named), "names {named}: {stderr}");
    }
}

/// A headless command opens no display: with no display in the environment (as on CI or
/// over ssh) a GPU render says nothing of one. Mesa's device-select layer, which wgpu's
/// window-system extensions wake, used to print "XDG_RUNTIME_DIR is invalid or not set"
/// twice on every `render`.
#[test]
fn headless_render_probes_no_display() {
    let out = scratch("headless.png");
    let result = bin()
        .args([
            "render", "--text", "Hi", "--size", "24", "--method", "winding",
        ])
        .args(["--out", out.to_str().unwrap()])
        .env_remove("XDG_RUNTIME_DIR")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("DISPLAY")
        .env_remove("NODEVICE_SELECT")
        .env_remove("MESA_VK_DEVICE_SELECT")
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(result.status.success(), "{stderr}");
    assert!(out.is_file());
    for display in ["XDG_RUNTIME_DIR", "wayland", "DISPLAY"] {
        assert!(
            !stderr.to_lowercase().contains(&display.to_lowercase()),
            "a headless render probed a display: {stderr}"
        );
    }
}

/// `--case` draws a named view: a bench scene's picture is byte for byte the one its own
/// command line draws, and a hard case's frame has the case's size; mixing `--case` with
/// view options, or an unknown name, fails cleanly.
#[test]
fn render_case_draws_a_named_view_and_refuses_mixing() {
    let by_case = scratch("case-headlines.png");
    run_ok(&[
        "render",
        "--case",
        "headlines",
        "--method",
        "reference",
        "--out",
        by_case.to_str().unwrap(),
    ]);
    let by_args = scratch("args-headlines.png");
    let line = glyphscope::bench::scenes::scene("headlines")
        .unwrap()
        .args
        .command_line();
    let mut args = vec!["render"];
    args.extend(line.iter().map(String::as_str));
    args.extend(["--method", "reference", "--out", by_args.to_str().unwrap()]);
    run_ok(&args);
    let (a, b) = (
        image::open(&by_case).unwrap(),
        image::open(&by_args).unwrap(),
    );
    assert_eq!(
        a.as_bytes(),
        b.as_bytes(),
        "--case headlines and its command line differ"
    );

    let skew = scratch("case-skew.png");
    run_ok(&[
        "render",
        "--case",
        "strong-skew",
        "--method",
        "reference",
        "--out",
        skew.to_str().unwrap(),
    ]);
    let (_, camera) = glyphscope::named_views::build("strong-skew").unwrap();
    let png = image::open(&skew).unwrap();
    assert_eq!((png.width(), png.height()), (camera.width, camera.height));

    fails(
        "case-unknown",
        &["--case", "nope", "--method", "reference"],
        "unknown case",
    );
    fails(
        "case-and-text",
        &[
            "--case",
            "strong-skew",
            "--text",
            "hi",
            "--method",
            "reference",
        ],
        "cannot be used with",
    );
    fails(
        "case-and-size",
        &[
            "--case",
            "strong-skew",
            "--size",
            "12",
            "--method",
            "reference",
        ],
        "cannot be used with",
    );
    // Without --case, the view's own options are required.
    fails(
        "no-size",
        &["--text", "a", "--method", "reference"],
        "give --size",
    );
    fails(
        "no-text",
        &["--size", "20", "--method", "reference"],
        "give --text",
    );
}

/// Each peer renders through `render` as a method does, with time, error and edge
/// error in `--stats`; a view it cannot draw (a tilt, for all but msdf) exits 2 with
/// one line naming its limit, and writes no image.
#[test]
fn render_draws_the_peers_and_refuses_what_they_cannot_draw() {
    let peers = glyphscope::methods::registry::METHODS
        .iter()
        .filter(|m| m.is_peer())
        .map(|m| m.name);
    for peer in peers {
        let (out, err, stats) = (
            scratch(&format!("{peer}.png")),
            scratch(&format!("{peer}-err.png")),
            scratch(&format!("{peer}.json")),
        );
        run_ok(&[
            "render",
            "--case",
            "tiny",
            "--method",
            peer,
            "--out",
            out.to_str().unwrap(),
            "--error-image",
            err.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ]);
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        assert_eq!(json["method"], peer);
        assert!(json["frame_ms"].as_f64().unwrap() > 0.0, "{peer}: {json}");
        let error = &json["error"];
        assert!(error["mae_255"].as_f64().unwrap().is_finite(), "{peer}");
        assert!(error["edge"]["pixels"].as_u64().unwrap() > 0, "{peer}");
        assert!(error["edge"]["mae_255"].as_f64().unwrap() > 0.0, "{peer}");
        // msdf draws through the quads every method shares: any camera, a tilt too.
        if peer == "msdf" {
            run_ok(&[
                "render",
                "--case",
                "rotated",
                "--method",
                peer,
                "--out",
                out.to_str().unwrap(),
            ]);
            continue;
        }
        fails(
            &format!("{peer}-tilted"),
            &["--case", "rotated", "--method", peer],
            &format!("{peer} draws"),
        );
    }
    fails(
        "glyphon-turned",
        &[
            "--text",
            "Turned",
            "--size",
            "20",
            "--matrix",
            "0.866,-0.5,0.5,0.866",
            "--method",
            "glyphon",
        ],
        "translation and uniform scale only",
    );
}

/// `--view` opens the explorer on a link; given with a subcommand it is a mistake, said
/// in one line before anything runs.
#[test]
fn a_view_link_takes_no_subcommand() {
    let result = run(&["--view", "#a=winding", "info", "--text", "a"]);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
    assert!(stderr.contains("--view opens the explorer"), "{stderr}");
}

/// The binary run with `args` where only the command line chooses the adapter: no
/// adapter named in the environment, and the Vulkan loader finding its drivers itself.
fn run_choosing_the_adapter(args: &[&str]) -> std::process::Output {
    bin()
        .args(args)
        .env_remove("WGPU_ADAPTER_NAME")
        .env_remove("VK_ICD_FILENAMES")
        .env_remove("VK_DRIVER_FILES")
        .env_remove("VK_ADD_DRIVER_FILES")
        .output()
        .expect("the binary runs")
}

/// SwiftShader's manifest, which CI's chromium package installs: without it the tests
/// of `--adapter swiftshader` fail saying so, rather than pass having checked nothing.
fn swiftshader_manifest() {
    let manifest = glyphscope::gpu::SWIFTSHADER_MANIFEST;
    assert!(
        std::path::Path::new(manifest).is_file(),
        "{manifest} is missing: SwiftShader's Vulkan driver comes with Debian's chromium \
         package (apt-get install chromium; tools/setup.sh installs it)"
    );
}

#[test]
fn an_adapter_no_name_matches_is_one_line_listing_those_found() {
    swiftshader_manifest();
    let out = scratch("no-such-gpu.png");
    let result = run_choosing_the_adapter(&[
        "render",
        "--text",
        "x",
        "--size",
        "24",
        "--method",
        "atlas",
        "--adapter",
        "no-such-gpu",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    // The list names what CI installs: lavapipe, and SwiftShader, offered to the loader
    // because an adapter was asked for by name.
    for expected in ["no-such-gpu", "found:", "llvmpipe", "SwiftShader"] {
        assert!(stderr.contains(expected), "lacks {expected:?}: {stderr}");
    }
    assert!(!out.exists(), "an image was written");
}

#[test]
fn swiftshader_draws_when_asked_for_and_the_default_adapter_stays() {
    swiftshader_manifest();
    let adapter_of = |name: &str, extra: &[&str]| -> String {
        let (out, stats) = (
            scratch(&format!("{name}.png")),
            scratch(&format!("{name}.json")),
        );
        let mut args = vec![
            "render",
            "--text",
            "Hi",
            "--size",
            "24",
            "--method",
            "atlas",
            "--out",
            out.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let result = run_choosing_the_adapter(&args);
        assert!(
            result.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&result.stderr)
        );
        let gray = image::open(&out).unwrap().to_luma8();
        assert!(gray.pixels().any(|p| p.0[0] == 255), "{name}: no ink");
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        json["adapter"].as_str().unwrap().to_string()
    };
    let swiftshader = adapter_of("swiftshader", &["--adapter", "swiftshader"]);
    // The name as SwiftShader gives it, and its driver beside it (reports name both).
    assert!(
        swiftshader.starts_with("SwiftShader Device") && swiftshader.contains("driver"),
        "{swiftshader}"
    );
    // SwiftShader comes first in the loader's list, so offering it to every command would
    // make it wgpu's default: it is offered only where an adapter is asked for by name.
    let default = adapter_of("default-adapter", &[]);
    assert!(!default.contains("SwiftShader"), "{default}");
}

#[test]
fn info_reports_the_adapter_and_refuses_a_cpu_one_where_hardware_is_required() {
    // lavapipe, which CI installs, is a CPU implementation of Vulkan (Mesa's llvmpipe).
    let result = run_choosing_the_adapter(&["info", "--gpu", "--adapter", "llvmpipe"]);
    let stdout = String::from_utf8_lossy(&result.stdout);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    for line in ["backend: Vulkan", "driver: llvmpipe", "device type: Cpu"] {
        assert!(
            stdout.lines().any(|l| l == line),
            "lacks {line:?}: {stdout}"
        );
    }
    let result = run_choosing_the_adapter(&[
        "info",
        "--gpu",
        "--adapter",
        "llvmpipe",
        "--require-hardware",
    ]);
    assert_refuses_lavapipe(&result);
    assert!(
        result.stdout.is_empty(),
        "a refused adapter is reported on stdout"
    );
}

/// Exit 2 and one line saying lavapipe is a CPU implementation: how `info --gpu
/// --require-hardware` and the GPU report refuse it.
fn assert_refuses_lavapipe(result: &std::process::Output) {
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    assert!(
        stderr.contains("CPU implementation") && stderr.contains("llvmpipe"),
        "{stderr}"
    );
}

#[test]
fn the_gpu_report_refuses_a_cpu_adapter_with_one_line_and_writes_nothing() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let reports = root.join("docs/bench/gpu");
    let listing = || -> Vec<PathBuf> {
        std::fs::read_dir(&reports).map_or(Vec::new(), |dir| {
            dir.map(|entry| entry.unwrap().path()).collect()
        })
    };
    let before = listing();
    // lavapipe by name, so the script meets a CPU adapter on any machine CI runs on; the
    // built binary, so the script does not build one.
    let result = std::process::Command::new("bash")
        .arg("tools/gpu-report.sh")
        .current_dir(&root)
        .env("GLYPHSCOPE_BIN", env!("CARGO_BIN_EXE_glyphscope"))
        .env("WGPU_ADAPTER_NAME", "llvmpipe")
        .output()
        .expect("bash runs");
    assert_refuses_lavapipe(&result);
    assert_eq!(
        listing(),
        before,
        "a refused report wrote into docs/bench/gpu"
    );
}

/// `render --method msdf:KEY=VALUE` draws with the parameters after the colons (as
/// `motion` and `bench` take them) and writes the field's memory and the error; a bad
/// value, given either way, exits 2 with one line.
#[test]
fn render_takes_parameters_after_the_method_name() {
    let stats = scratch("msdf-sdf.json");
    let error = scratch("msdf-sdf-error.png");
    let out = scratch("msdf-sdf.png");
    run_ok(&[
        "render",
        "--text",
        "Ag",
        "--size",
        "40",
        "--method",
        "msdf:field=sdf:em_px=48",
        "--out",
        out.to_str().unwrap(),
        "--stats",
        stats.to_str().unwrap(),
        "--error-image",
        error.to_str().unwrap(),
    ]);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    let params: Vec<String> = json["params"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| format!("{}={}", p[0].as_str().unwrap(), p[1].as_str().unwrap()))
        .collect();
    assert_eq!(params, ["field=sdf", "em_px=48"], "{json}");
    // One byte a texel for a single-channel field, inside what the method holds.
    let field = json["cache_bytes"].as_u64().unwrap();
    assert!(
        field > 0 && field < json["gpu_bytes"].as_u64().unwrap(),
        "{json}"
    );
    assert!(
        json["error"]["mae_255"].as_f64().unwrap().is_finite(),
        "{json}"
    );
    let text = ["--text", "a", "--size", "20"];
    let with = |method: &'static str, extra: &[&'static str]| -> Vec<&'static str> {
        [&text[..], &["--method", method], extra].concat()
    };
    fails("msdf em_px=0", &with("msdf:em_px=0", &[]), "em_px must be");
    fails(
        "msdf range",
        &with("msdf", &["--param", "range=banana"]),
        "range must be",
    );
    fails("msdf no value", &with("msdf:field", &[]), "KEY=VALUE");
}
