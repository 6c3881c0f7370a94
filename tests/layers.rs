//! The modules of `src/` form layers (docs/modules.md): each imports only from layers
//! below it, so nothing low reaches up and there is no import cycle. Read from the
//! sources themselves: every `crate::name` a file's code mentions (comments and unit
//! tests aside).

use std::collections::BTreeSet;
use std::path::Path;

/// Each top-level module and its layer, lowest first. A module may use modules of a
/// lower layer only.
const LAYERS: &[(&str, u32)] = &[
    ("geometry", 0),
    ("coverage", 0),
    ("font", 1),
    ("metrics", 1),
    ("shaping", 2),
    ("scene", 3),
    ("camera", 4),
    ("reference", 5),
    ("view", 5),
    ("outline", 5),
    ("magnify", 6),
    ("info", 6),
    ("gpu", 5),
    ("methods", 6),
    ("measure", 7),
    ("stability", 8),
    ("bench", 8),
    ("named_views", 9),
    ("cli", 10),
    ("app", 11),
];

fn layer(module: &str) -> Option<u32> {
    LAYERS.iter().find(|(m, _)| *m == module).map(|&(_, l)| l)
}

/// The top-level modules named as `crate::name` in the code of `source`.
fn used_modules(source: &str) -> BTreeSet<String> {
    let code = source.split("#[cfg(test)]").next().unwrap_or_default();
    let mut used = BTreeSet::new();
    for line in code.lines() {
        let line = line.trim_start();
        if line.starts_with("//") {
            continue;
        }
        for part in line.split("crate::").skip(1) {
            let name: String = part
                .chars()
                .take_while(|c| c.is_ascii_lowercase() || *c == '_')
                .collect();
            if !name.is_empty() {
                used.insert(name);
            }
        }
        // `use crate::{a, b}` names several at once.
        if let Some(group) = line.strip_prefix("use crate::{") {
            for name in group.split([',', '}']) {
                let name = name.trim().split("::").next().unwrap_or_default();
                if name.chars().all(|c| c.is_ascii_lowercase() || c == '_') && !name.is_empty() {
                    used.insert(name.to_owned());
                }
            }
        }
    }
    used
}

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

#[test]
fn no_module_imports_a_layer_above_its_own() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut upward = Vec::new();
    for file in files {
        let relative = file.strip_prefix(&src).unwrap();
        let top = relative
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_owned();
        if top == "lib" || top == "main" {
            continue;
        }
        let own = layer(&top).unwrap_or_else(|| panic!("src/{top} has no layer in LAYERS"));
        let source = std::fs::read_to_string(&file).unwrap();
        for used in used_modules(&source) {
            // Macros and the crate's error type are exported at the root.
            let Some(theirs) = layer(&used) else { continue };
            if used != top && theirs >= own {
                upward.push(format!("{} uses crate::{used}", relative.display()));
            }
        }
    }
    assert!(
        upward.is_empty(),
        "imports that reach up:\n{}",
        upward.join("\n")
    );
}

/// The reader works: it sees a grouped import and skips comments and unit tests.
#[test]
fn the_import_reader_sees_what_code_uses() {
    let used = used_modules(
        "use crate::{camera::Camera, gpu};\n// crate::app\nfn f() { crate::metrics::x(); }\n\
         #[cfg(test)]\nmod tests { use crate::bench; }",
    );
    let names: Vec<&str> = used.iter().map(String::as_str).collect();
    assert_eq!(names, ["camera", "gpu", "metrics"]);
}
