//! The modules of `src/` form layers: each imports only from layers below it, so nothing
//! low reaches up and there is no import cycle; and no method module imports another
//! method's module (what two methods share lives in a lower layer or in the shared
//! part of `methods/`). The layer table is the one in `docs/architecture.md`, read
//! from there, so the map a reader sees and the rule checked here are one table. The
//! imports are read from the sources themselves: every `crate::name` a file's code
//! mentions (comments and unit tests aside).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The shared part of `methods/`: the `Method` trait and its helpers (`mod.rs`), the
/// registry that lists every method, the frame loop and the instance transforms. Every
/// other module of `methods/` is one method's own, and may use these but no other
/// method's.
const METHODS_SHARED: &[&str] = &["mod", "registry", "frame", "instances"];

/// The method modules: `methods/`'s folders and files outside the shared part.
fn method_modules(src: &Path) -> Vec<String> {
    std::fs::read_dir(src.join("methods"))
        .unwrap()
        .map(|e| module_path(Path::new(&e.unwrap().file_name()))[0].clone())
        .filter(|m| !METHODS_SHARED.contains(&m.as_str()))
        .collect()
}

const ARCHITECTURE: &str = include_str!("../docs/architecture.md");

/// The layer table of `docs/architecture.md`: the rows between its `layers` markers,
/// `| N | `module` | what it holds |`, as (module, layer).
fn layers() -> Vec<(String, u32)> {
    let table = ARCHITECTURE
        .split("<!-- layers -->")
        .nth(1)
        .and_then(|rest| rest.split("<!-- /layers -->").next())
        .expect("docs/architecture.md has a table between <!-- layers --> markers");
    table
        .lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            let layer = cells.get(1)?.parse().ok()?;
            let module = cells.get(2)?.trim_matches('`');
            Some((module.to_owned(), layer))
        })
        .collect()
}

fn layer_of(layers: &[(String, u32)], module: &str) -> Option<u32> {
    layers.iter().find(|(m, _)| m == module).map(|&(_, l)| l)
}

/// The module paths named as `crate::a::b…` in the code of `source`, each as its names
/// (`["methods", "winding", "area"]`; a path ends at its first item that is not a
/// lower-case name), grouped imports (`use crate::{a, b::c}`) expanded one level.
fn used_paths(source: &str) -> BTreeSet<Vec<String>> {
    let code = source.split("#[cfg(test)]").next().unwrap_or_default();
    let name_of = |part: &str| -> String {
        part.chars()
            .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '_')
            .collect()
    };
    let path_of = |text: &str| -> Vec<String> {
        text.split("::")
            .map(name_of)
            .take_while(|name| !name.is_empty())
            .collect()
    };
    let mut used = BTreeSet::new();
    for line in code.lines() {
        let line = line.trim_start();
        if line.starts_with("//") {
            continue;
        }
        for part in line.split("crate::").skip(1) {
            if let Some(group) = part.strip_prefix('{') {
                for item in group.split([',', '}']) {
                    let path = path_of(item.trim());
                    if !path.is_empty() {
                        used.insert(path);
                    }
                }
                continue;
            }
            // `crate::methods::{winding, atlas}`: the group's members under the prefix.
            if let Some((prefix, group)) = part.split_once("::{") {
                let prefix = path_of(prefix);
                if prefix.len() == prefix_len(part) {
                    let members = group.split('}').next().unwrap_or_default();
                    for item in members.split(',').filter(|i| !i.trim().is_empty()) {
                        let mut path = prefix.clone();
                        path.extend(path_of(item.trim()));
                        used.insert(path);
                    }
                    continue;
                }
            }
            let path = path_of(part);
            if !path.is_empty() {
                used.insert(path);
            }
        }
    }
    used
}

/// How many plain names `part` has before its first `::{` (if that is where it ends).
fn prefix_len(part: &str) -> usize {
    part.split("::{")
        .next()
        .unwrap_or_default()
        .split("::")
        .count()
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `file`'s path under `src/` as module names: `methods/winding/area.rs` →
/// `["methods", "winding", "area"]`.
fn module_path(relative: &Path) -> Vec<String> {
    relative
        .components()
        .map(|c| {
            c.as_os_str()
                .to_string_lossy()
                .trim_end_matches(".rs")
                .to_owned()
        })
        .collect()
}

/// The method a module path of `methods/` belongs to, None for the shared part.
fn method_of<'a>(methods: &[String], path: &'a [String]) -> Option<&'a str> {
    match path {
        [top, method, ..] if top == "methods" && methods.contains(method) => Some(method),
        _ => None,
    }
}

/// What `file` (its module path) imports that the rules forbid: a module of a layer
/// not below its own, or another method's module.
fn violations(
    layers: &[(String, u32)],
    methods: &[String],
    path: &[String],
    source: &str,
) -> Vec<String> {
    let top = &path[0];
    let own = layer_of(layers, top)
        .unwrap_or_else(|| panic!("src/{top} has no row in docs/architecture.md's layers"));
    let mut found = Vec::new();
    for used in used_paths(source) {
        // Macros and the crate's error type are exported at the root.
        let Some(theirs) = layer_of(layers, &used[0]) else {
            continue;
        };
        if &used[0] != top && theirs >= own {
            found.push(format!(
                "uses crate::{} (layer {theirs} ≥ {own})",
                used.join("::")
            ));
        }
        if let (Some(mine), Some(other)) = (method_of(methods, path), method_of(methods, &used))
            && mine != other
        {
            found.push(format!(
                "uses crate::{}, another method's module",
                used.join("::")
            ));
        }
    }
    found
}

#[test]
fn no_module_imports_a_layer_above_its_own_or_another_method() {
    let layers = layers();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let methods = method_modules(&src);
    assert!(methods.len() >= 6, "{methods:?}");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut wrong = Vec::new();
    for file in files {
        let path = module_path(file.strip_prefix(&src).unwrap());
        if path[0] == "lib" || path[0] == "main" {
            continue;
        }
        let source = std::fs::read_to_string(&file).unwrap();
        for v in violations(&layers, &methods, &path, &source) {
            wrong.push(format!("src/{}: {v}", path.join("/")));
        }
    }
    assert!(
        wrong.is_empty(),
        "imports against the layers:\n{}",
        wrong.join("\n")
    );
}

/// The table names every top-level module of `src/` once and nothing else.
#[test]
fn the_architecture_table_lists_every_module_once() {
    let layers = layers();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut on_disk: Vec<String> = std::fs::read_dir(&src)
        .unwrap()
        .map(|e| module_path(Path::new(&e.unwrap().file_name()))[0].clone())
        .filter(|m| m != "lib" && m != "main")
        .collect();
    on_disk.sort();
    let mut in_table: Vec<String> = layers.iter().map(|(m, _)| m.clone()).collect();
    in_table.sort();
    assert_eq!(in_table, on_disk);
}

/// The reader sees grouped imports and skips comments and unit tests; the rules catch
/// an upward import and a method reaching into another method's module (the shared
/// outline maths winding once took from sdf-cells), and let a method use the shared
/// part of `methods/` and its own modules.
#[test]
fn the_rules_catch_what_they_are_for() {
    let used = used_paths(
        "use crate::{camera::Camera, gpu};\n// crate::app\nfn f() { crate::metrics::x(); }\n\
         use crate::methods::{registry, winding::area};\n\
         #[cfg(test)]\nmod tests { use crate::bench; }",
    );
    let joined: Vec<String> = used.iter().map(|p| p.join("::")).collect();
    assert_eq!(
        joined,
        [
            "camera",
            "gpu",
            "methods::registry",
            "methods::winding::area",
            "metrics::x"
        ]
    );
    let layers: Vec<(String, u32)> = [("geometry", 0), ("methods", 6), ("app", 11)]
        .map(|(m, l)| (m.to_owned(), l))
        .to_vec();
    let methods: Vec<String> = ["winding", "sdf_cells", "atlas"].map(String::from).to_vec();
    let winding: Vec<String> = ["methods", "winding", "overlaps"]
        .map(String::from)
        .to_vec();
    let check = |path: &[String], source: &str| violations(&layers, &methods, path, source);
    let sibling = "use crate::methods::sdf_cells::curves::signed_area;";
    assert_eq!(check(&winding, sibling).len(), 1);
    assert_eq!(
        check(&winding, "fn f() { crate::methods::atlas::INFO; }").len(),
        1
    );
    assert_eq!(check(&winding, "use crate::app::Explorer;").len(), 1);
    let allowed = "use crate::geometry::signed_area;\nuse crate::methods::{Method, registry};\n\
                   use crate::methods::winding::area::Bezier;\nuse crate::methods::param;";
    assert!(check(&winding, allowed).is_empty());
    let registry: Vec<String> = ["methods", "registry"].map(String::from).to_vec();
    assert!(check(&registry, "&crate::methods::winding::INFO").is_empty());
}
