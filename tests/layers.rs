//! The modules of `src/` form layers: each imports only from layers below it, so nothing
//! low reaches up and there is no import cycle; and no method module imports another
//! method's module (what two methods share lives in a lower layer or in the shared
//! part of `methods/`). The layer table is the one in `docs/architecture.md`, read
//! from there, so the map a reader sees and the rule checked here are one table. The
//! imports are read from the sources themselves: every `crate::name` a file's code
//! mentions (comments and unit tests aside).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The shared part of `methods/`, as `docs/architecture.md` lists it between its
/// `methods-shared` markers: each item's first `name.rs`. Every other module of
/// `methods/` is one method's own, and may use these but no other method's.
fn methods_shared() -> Vec<String> {
    let list = ARCHITECTURE
        .split("<!-- methods-shared -->")
        .nth(1)
        .and_then(|rest| rest.split("<!-- /methods-shared -->").next())
        .expect("docs/architecture.md lists the shared part of methods/ between markers");
    list.lines()
        .filter_map(|line| line.strip_prefix("- `"))
        .filter_map(|item| item.split_once(".rs`"))
        .map(|(name, _)| name.to_owned())
        .collect()
}

/// The method modules: `methods/`'s folders and files outside the shared part, which
/// must exist.
fn method_modules(src: &Path) -> Vec<String> {
    let shared = methods_shared();
    let on_disk: Vec<String> = std::fs::read_dir(src.join("methods"))
        .unwrap()
        .map(|e| module_path(Path::new(&e.unwrap().file_name()))[0].clone())
        .collect();
    for module in &shared {
        assert!(
            on_disk.contains(module),
            "methods/{module}.rs is listed as shared"
        );
    }
    on_disk
        .into_iter()
        .filter(|m| !shared.contains(m))
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

/// The code of `source` without comments and unit tests, on one line.
fn code_of(source: &str) -> String {
    let code = source.split("#[cfg(test)]").next().unwrap_or_default();
    code.lines()
        .map(|line| line.split("//").next().unwrap_or_default().trim())
        .collect::<Vec<_>>()
        .join(" ")
}

/// The lower-case name at the start of `text` (a module, not a type or a macro).
fn name_of(text: &str) -> String {
    text.chars()
        .take_while(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || *c == '_')
        .collect()
}

/// Every path a use tree names, its groups expanded at any depth: `a::{b, c::{d}}`
/// gives `a::b` and `a::c::d`. Names are cut at the first one that is not a module's.
fn expand_tree(prefix: &[String], tree: &str, out: &mut Vec<Vec<String>>) {
    let mut path = prefix.to_vec();
    let mut rest = tree.trim();
    loop {
        if let Some(group) = rest.strip_prefix('{') {
            let inner = &group[..group.rfind('}').unwrap_or(group.len())];
            let (mut depth, mut start, mut items) = (0, 0, Vec::new());
            for (k, c) in inner.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        items.push(&inner[start..k]);
                        start = k + 1;
                    }
                    _ => {}
                }
            }
            items.push(&inner[start..]);
            // A trailing comma leaves an empty item: nothing to name.
            for item in items.into_iter().filter(|i| !i.trim().is_empty()) {
                expand_tree(&path, item, out);
            }
            return;
        }
        let name = name_of(rest);
        if name.is_empty() {
            break;
        }
        path.push(name.clone());
        match rest[name.len()..].strip_prefix("::") {
            Some(next) => rest = next.trim_start(),
            None => break,
        }
    }
    out.push(path);
}

/// `path` as seen from the module at `module`: `crate::` dropped, `super::` and
/// `self::` resolved against the module's own path. None for a path from outside the
/// crate.
fn absolute(module: &[String], path: &[String]) -> Option<Vec<String>> {
    match path.first().map(String::as_str) {
        Some("crate") => Some(path[1..].to_vec()),
        Some("self") => Some([module, &path[1..]].concat()),
        Some("super") => {
            let ups = path.iter().take_while(|p| *p == "super").count();
            let base = module.get(..module.len().checked_sub(ups)?)?;
            Some([base, &path[ups..]].concat())
        }
        _ => None,
    }
}

/// The crate paths the code of `source` uses, as absolute module paths seen from the
/// module `module` (`["methods", "winding"]` for `methods/winding/mod.rs`): every `use`
/// statement's tree, nested groups and line breaks included, and every `crate::…`
/// written in the code.
fn used_paths(module: &[String], source: &str) -> BTreeSet<Vec<String>> {
    let code = code_of(source);
    let mut trees = Vec::new();
    for statement in code.split(';') {
        let statement = statement.trim();
        let tree = statement
            .strip_prefix("pub use ")
            .or_else(|| statement.strip_prefix("pub(crate) use "))
            .or_else(|| statement.strip_prefix("use "));
        match tree {
            Some(tree) => expand_tree(&[], tree, &mut trees),
            None => {
                for part in statement.split("crate::").skip(1) {
                    expand_tree(&["crate".to_owned()], part, &mut trees);
                }
            }
        }
    }
    trees
        .iter()
        .filter_map(|path| absolute(module, path))
        .filter(|path| !path.is_empty())
        .collect()
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
    // The module a file is: `winding/mod.rs` is `winding`, `winding/area.rs` is `area`.
    let module: Vec<String> = match path.split_last() {
        Some((last, parent)) if last == "mod" => parent.to_vec(),
        _ => path.to_vec(),
    };
    for used in used_paths(&module, source) {
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
    let names = |path: &[&str]| -> Vec<String> { path.iter().map(|p| p.to_string()).collect() };
    let used = used_paths(
        &names(&["app"]),
        "use crate::{camera::Camera, gpu};\n// crate::app\nfn f() { crate::metrics::x(); }\n\
         use crate::methods::{\n    registry,\n    winding::{area, bands},\n};\n\
         use super::shaping;\nuse self::canvas::CanvasState;\nuse std::sync::Arc;\n\
         #[cfg(test)]\nmod tests { use crate::bench; }",
    );
    let joined: Vec<String> = used.iter().map(|p| p.join("::")).collect();
    assert_eq!(
        joined,
        [
            "app::canvas",
            "camera",
            "gpu",
            "methods::registry",
            "methods::winding::area",
            "methods::winding::bands",
            "metrics::x",
            "shaping"
        ]
    );
    let layers: Vec<(String, u32)> = [("geometry", 0), ("methods", 6), ("app", 11)]
        .map(|(m, l)| (m.to_owned(), l))
        .to_vec();
    let methods = names(&["winding", "sdf_cells", "atlas", "bounds"]);
    let overlaps = names(&["methods", "winding", "overlaps"]);
    let check = |path: &[String], source: &str| violations(&layers, &methods, path, source);
    for sibling in [
        "use crate::methods::sdf_cells::curves::signed_area;",
        "use crate::methods::{\n    sdf_cells::{curves},\n};",
        "use super::super::sdf_cells::curves;",
        "fn f() { crate::methods::atlas::INFO; }",
        "use crate::app::Explorer;",
    ] {
        assert_eq!(check(&overlaps, sibling).len(), 1, "{sibling}");
    }
    let atlas = names(&["methods", "atlas"]);
    assert_eq!(check(&atlas, "use super::bounds::Bounds;").len(), 1);
    let allowed = "use crate::geometry::signed_area;\nuse crate::methods::{Method, registry};\n\
                   use crate::methods::winding::area::Bezier;\nuse crate::methods::param;\n\
                   use super::area::{Bezier, t_at};\nuse super::super::registry::Role;";
    assert!(check(&overlaps, allowed).is_empty());
    assert!(check(&atlas, "use super::registry::{MethodInfo, Role};").is_empty());
    let registry = names(&["methods", "registry"]);
    assert!(check(&registry, "&crate::methods::winding::INFO").is_empty());
}
