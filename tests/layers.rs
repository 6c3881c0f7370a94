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

/// The tree of a `use` statement (`pub` or not), None for any other statement.
fn use_tree(statement: &str) -> Option<&str> {
    statement
        .strip_prefix("pub use ")
        .or_else(|| statement.strip_prefix("pub(crate) use "))
        .or_else(|| statement.strip_prefix("use "))
}

/// The crate paths the code of `source` uses, as absolute module paths seen from the
/// module `module` (`["methods", "winding"]` for `methods/winding/mod.rs`): every `use`
/// statement's tree, nested groups and line breaks included, and every `crate::…`,
/// `super::…` and `self::…` path written in the code.
fn used_paths(module: &[String], source: &str) -> BTreeSet<Vec<String>> {
    let code = code_of(source);
    let mut trees = Vec::new();
    for statement in code.split(';') {
        let statement = statement.trim();
        match use_tree(statement) {
            Some(tree) => expand_tree(&[], tree, &mut trees),
            None => {
                for part in statement.split("crate::").skip(1) {
                    expand_tree(&["crate".to_owned()], part, &mut trees);
                }
                for (start, up) in path_starts(statement, &["super::", "self::"]) {
                    expand_tree(
                        &[up.trim_end_matches("::").to_owned()],
                        &statement[start..],
                        &mut trees,
                    );
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

/// Where each path in `code` that begins with one of `starts` continues, with the start
/// it began with. A path begins where no name or `::` stands just before it: `Self::`
/// and the second `super::` of `super::super::x` begin none (the first one's path
/// holds them).
fn path_starts<'a>(code: &str, starts: &[&'a str]) -> Vec<(usize, &'a str)> {
    let bytes = code.as_bytes();
    let mut found = Vec::new();
    for (at, _) in code.char_indices() {
        let begins_path = at == 0
            || !(bytes[at - 1].is_ascii_alphanumeric() || matches!(bytes[at - 1], b'_' | b':'));
        if let Some(start) = starts
            .iter()
            .find(|s| begins_path && code[at..].starts_with(**s))
        {
            found.push((at + start.len(), *start));
        }
    }
    found
}

/// The paths the code of `source` names from where it stands, without `crate::`,
/// `self::` or `super::`: `use run::run_to` and `run::markdown(..)` in a `mod.rs` name
/// its child `run`. Names from outside the crate (`std::fmt`) come out too; the caller
/// keeps those that name a child module.
fn relative_paths(source: &str) -> Vec<Vec<String>> {
    let code = code_of(source);
    let mut trees = Vec::new();
    for statement in code.split(';') {
        let statement = statement.trim();
        match use_tree(statement) {
            Some(tree) => expand_tree(&[], tree, &mut trees),
            None => {
                let bytes = statement.as_bytes();
                for (at, _) in statement.char_indices() {
                    let begins_path = bytes[at].is_ascii_lowercase()
                        && (at == 0
                            || !(bytes[at - 1].is_ascii_alphanumeric()
                                || matches!(bytes[at - 1], b'_' | b':')));
                    let name = name_of(&statement[at..]);
                    if begins_path && statement[at + name.len()..].starts_with("::") {
                        expand_tree(&[], &statement[at..], &mut trees);
                    }
                }
            }
        }
    }
    trees
        .into_iter()
        .filter(|path| {
            path.first()
                .is_some_and(|p| !matches!(p.as_str(), "crate" | "self" | "super"))
        })
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

/// An import between two entries of one folder: a file of `from` uses `used`, which lies
/// in `to`. A folder's entries are its files (`mod.rs` too) and its subfolders, each
/// subfolder taken whole.
#[derive(Debug, Clone)]
struct FolderEdge {
    from: String,
    to: String,
    file: String,
    used: String,
}

/// The imports between entries of the same folder, for every folder below `src/`, as
/// (folder, edge). `files` are (module path under `src/`, source); `is_entry(folder,
/// name)` says whether `name` is a file or subfolder of `folder`, so that a path naming
/// an item of the folder's `mod.rs` (`super::Thing`, `crate::bench::run_to`) is an
/// import of `mod.rs`.
fn folder_edges(
    files: &[(Vec<String>, String)],
    is_entry: impl Fn(&[String], &str) -> bool,
) -> Vec<(Vec<String>, FolderEdge)> {
    let mut edges = Vec::new();
    for (path, source) in files {
        let module: Vec<String> = match path.split_last() {
            Some((last, parent)) if last == "mod" => parent.to_vec(),
            _ => path.clone(),
        };
        // A `mod.rs` also names its children without a prefix (`pub use run::run_to`).
        let children = relative_paths(source)
            .into_iter()
            .filter(|relative| {
                path.last().is_some_and(|last| last == "mod") && is_entry(&module, &relative[0])
            })
            .map(|relative| [module.as_slice(), &relative].concat());
        for used in used_paths(&module, source).into_iter().chain(children) {
            // Every folder holding the file (the root aside: its modules are layers).
            for depth in 1..path.len() {
                let folder = &path[..depth];
                if !used.starts_with(folder) {
                    continue;
                }
                let mine = &path[depth];
                let theirs = match used.get(depth) {
                    Some(name) if is_entry(folder, name) => name.clone(),
                    _ => "mod".to_owned(),
                };
                if *mine != theirs {
                    edges.push((
                        folder.to_vec(),
                        FolderEdge {
                            from: mine.clone(),
                            to: theirs,
                            file: path.join("/"),
                            used: used.join("::"),
                        },
                    ));
                }
            }
        }
    }
    edges
}

/// A loop among `edges` (one folder's), as the edges around it, if there is one: a
/// depth-first walk that meets an entry still on its stack.
fn a_loop(edges: &[FolderEdge]) -> Option<Vec<FolderEdge>> {
    fn walk(
        node: &str,
        edges: &[FolderEdge],
        stack: &mut Vec<FolderEdge>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<FolderEdge>> {
        for edge in edges.iter().filter(|e| e.from == node) {
            if let Some(start) = stack.iter().position(|e| e.from == edge.to) {
                let mut cycle = stack[start..].to_vec();
                cycle.push(edge.clone());
                return Some(cycle);
            }
            if done.contains(&edge.to) {
                continue;
            }
            stack.push(edge.clone());
            if let Some(cycle) = walk(&edge.to, edges, stack, done) {
                return Some(cycle);
            }
            stack.pop();
        }
        done.insert(node.to_owned());
        None
    }
    let mut done = BTreeSet::new();
    let nodes: BTreeSet<&str> = edges.iter().map(|e| e.from.as_str()).collect();
    nodes
        .into_iter()
        .find_map(|node| walk(node, edges, &mut Vec::new(), &mut done))
}

/// Each folder's loops, one line each: `bench: run → motion → run (…)`. The loops are
/// found one at a time: each found loop's last edge is set aside so the next walk can
/// find another.
fn folder_loops(src: &str, edges: Vec<(Vec<String>, FolderEdge)>) -> Vec<String> {
    let mut folders: std::collections::BTreeMap<Vec<String>, Vec<FolderEdge>> = Default::default();
    for (folder, edge) in edges {
        folders.entry(folder).or_default().push(edge);
    }
    let mut found = Vec::new();
    for (folder, mut edges) in folders {
        while let Some(cycle) = a_loop(&edges) {
            let names: Vec<&str> = cycle
                .iter()
                .map(|e| e.from.as_str())
                .chain(cycle.last().map(|e| e.to.as_str()))
                .collect();
            let evidence: Vec<String> = cycle
                .iter()
                .map(|e| format!("{src}/{}.rs uses crate::{}", e.file, e.used))
                .collect();
            found.push(format!(
                "{src}/{}/: {} ({})",
                folder.join("/"),
                names.join(" → "),
                evidence.join("; ")
            ));
            let last = cycle.last().unwrap();
            edges.retain(|e| !(e.from == last.from && e.to == last.to));
        }
    }
    found
}

/// No two files of one folder import each other, directly or around a loop, so each
/// can be read and changed alone: a folder's files point one way, with `mod.rs` (which
/// declares the others) one of them. In every crate of the workspace: this package's
/// `src/` and each `crates/*/src/` (between crates, cargo forbids a loop itself).
#[test]
fn no_files_of_one_folder_import_each_other_around_a_loop() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sources = vec![root.join("src")];
    for entry in std::fs::read_dir(root.join("crates")).unwrap() {
        sources.push(entry.unwrap().path().join("src"));
    }
    assert!(sources.len() >= 4, "{sources:?}");
    let mut loops = Vec::new();
    for src in sources {
        let mut paths = Vec::new();
        rust_files(&src, &mut paths);
        let files: Vec<(Vec<String>, String)> = paths
            .iter()
            .map(|file| {
                (
                    module_path(file.strip_prefix(&src).unwrap()),
                    std::fs::read_to_string(file).unwrap(),
                )
            })
            .collect();
        let is_entry = |folder: &[String], name: &str| {
            let dir = folder.iter().fold(src.clone(), |dir, part| dir.join(part));
            dir.join(format!("{name}.rs")).is_file() || dir.join(name).is_dir()
        };
        let name = src.strip_prefix(root).unwrap().display().to_string();
        loops.extend(folder_loops(&name, folder_edges(&files, is_entry)));
    }
    assert!(
        loops.is_empty(),
        "files of one folder that import each other around a loop:\n{}",
        loops.join("\n")
    );
}

/// The folder check sees a loop through `mod.rs` (a child using an item of `mod.rs`
/// that imports the child back), a loop of three siblings, and one between two
/// subfolders seen from their parent; and it passes a folder whose files point one way.
#[test]
fn the_folder_check_catches_what_it_is_for() {
    let file = |path: &str, source: &str| {
        (
            path.split('/').map(str::to_owned).collect::<Vec<_>>(),
            source.to_owned(),
        )
    };
    let entries = [
        "bench/run",
        "bench/report",
        "bench/scaling",
        "bench/result",
        "methods/winding",
        "methods/registry",
        "methods/info",
        "methods/winding/area",
    ];
    let is_entry = |folder: &[String], name: &str| {
        entries.contains(&format!("{}/{name}", folder.join("/")).as_str())
    };
    let looped = [
        file("bench/mod", "pub use run::run_to;"),
        file("bench/run", "use super::Options;"),
        file("bench/report", "fn f() { std::fmt::Write; }"),
        file("bench/report", "use super::scaling::markdown;"),
        file("bench/scaling", "use crate::bench::result::Outcome;"),
        file("bench/result", "fn f() { super::report::sig(1.0); }"),
        file(
            "methods/registry",
            "static M: &Info = &super::winding::INFO;",
        ),
        file(
            "methods/winding/area",
            "use crate::methods::registry::Role;",
        ),
    ];
    let loops = folder_loops("src", folder_edges(&looped, is_entry));
    assert_eq!(loops.len(), 3, "{loops:#?}");
    assert!(
        loops
            .iter()
            .any(|l| l.starts_with("src/bench/: mod → run → mod")),
        "{loops:#?}"
    );
    assert!(
        loops
            .iter()
            .any(|l| l.contains("report → scaling → result → report")),
        "{loops:#?}"
    );
    assert!(
        loops
            .iter()
            .any(|l| l.starts_with("src/methods/: registry → winding → registry")),
        "{loops:#?}"
    );
    let one_way = [
        file("bench/mod", "pub use run::run_to;"),
        file("bench/run", "use super::{report, result::Outcome};"),
        file(
            "bench/report",
            "use super::{scaling::markdown, result::Outcome};",
        ),
        file("bench/scaling", "use crate::bench::result::Outcome;"),
        file(
            "methods/registry",
            "static M: &Info = &super::winding::INFO;",
        ),
        file(
            "methods/winding/area",
            "use crate::methods::info::Role;\nuse super::super::info;",
        ),
        file(
            "methods/winding/mod",
            "use self::area::ramp;\nuse super::info::Info;",
        ),
    ];
    assert_eq!(
        folder_loops("src", folder_edges(&one_way, is_entry)),
        Vec::<String>::new()
    );
}
