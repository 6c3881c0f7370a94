//! The crate an app adds for text, `glyphscope-text`, depends on what it draws with and
//! nothing of the explorer: no peer renderer, no UI toolkit, no command-line or plotting
//! crate, fewer crates in all than glyphon's own tree in the same lockfile; and the
//! core below it holds no GPU. Read from `cargo tree` on the workspace's lockfile, so
//! a dependency added to the wrong crate fails here, not in a user's build.

use std::collections::BTreeSet;
use std::process::Command;

/// The unique crates (names) in `package`'s tree of normal dependencies, itself
/// included, as the lockfile resolves them.
fn tree(package: &str) -> BTreeSet<String> {
    let output = Command::new(env!("CARGO"))
        .args([
            "tree",
            "--offline",
            "--locked",
            "-e",
            "normal",
            "--prefix",
            "none",
        ])
        .args(["-p", package])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo runs");
    assert!(
        output.status.success(),
        "cargo tree -p {package}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .filter_map(|line| line.split_whitespace().next())
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_text_library_depends_on_what_it_uses_only() {
    let text = tree("glyphscope-text");
    for unwanted in [
        "glyphscope",
        "glyphon",
        "vello",
        "vello_cpu",
        "fdsm",
        "egui",
        "eframe",
        "egui-wgpu",
        "egui_plot",
        "clap",
        "plotters",
        "rayon",
        "indicatif",
        "png",
        "image",
        "lyon_tessellation",
    ] {
        assert!(
            !text.contains(unwanted),
            "glyphscope-text depends on {unwanted}"
        );
    }
    // What it draws with is there: the check above is not passing on an empty list.
    for wanted in [
        "glyphscope-core",
        "glyphscope-gpu",
        "wgpu",
        "rustybuzz",
        "ttf-parser",
    ] {
        assert!(
            text.contains(wanted),
            "glyphscope-text's tree lacks {wanted}: {text:?}"
        );
    }
    let glyphon = tree("glyphon");
    assert!(
        text.len() < glyphon.len(),
        "glyphscope-text's tree has {} crates, glyphon's {}",
        text.len(),
        glyphon.len()
    );
}

#[test]
fn the_core_holds_no_gpu() {
    let core = tree("glyphscope-core");
    for unwanted in ["wgpu", "naga", "glyphscope-gpu", "image"] {
        assert!(
            !core.contains(unwanted),
            "glyphscope-core depends on {unwanted}"
        );
    }
    assert!(core.contains("ttf-parser"), "{core:?}");
}
