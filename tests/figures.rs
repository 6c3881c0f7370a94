//! Figures copied from committed bench runs, checked against those runs, so that none
//! outlives the run it cites:
//!
//! - README's table of methods: each row's *page: × atlas · MAE /255 · max* cell
//!   against the `bench.json` of the run its *figures from* cell names, worked out here
//!   from the run's raw times and errors, to the digits the cell shows;
//! - docs/bench.md's quoted tables: each table under a marker
//!   `<!-- quotes bench/DIR/bench.md "## HEADING" -->` against the table the bench
//!   wrote under that heading, cell by cell (docs/motion.md and docs/survey.md quote
//!   their reports the same way).
//!
//! A failure names the file, the line, the row and the column, with both figures. The
//! checks are shown to fail on a wrong cell in the last tests here.

use serde_json::Value;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn read(path: &str) -> String {
    std::fs::read_to_string(format!("{ROOT}/{path}")).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// A Markdown table: the line of its header (from 1), the heading it sits under, its
/// columns and its rows of cells.
#[derive(Debug)]
struct Table {
    line: usize,
    heading: String,
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

/// The cells of one table line, trimmed: `| a | b |` is `["a", "b"]`.
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    inner.split('|').map(|c| c.trim().to_owned()).collect()
}

/// Whether `line` is a table's rule under its header (`|---|---:|`).
fn is_rule(line: &str) -> bool {
    let line = line.trim();
    line.starts_with('|') && line.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '))
}

/// Every table of `md`, in order.
fn tables(md: &str) -> Vec<Table> {
    let lines: Vec<&str> = md.lines().collect();
    let mut found = Vec::new();
    let mut heading = String::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if line.starts_with('#') {
            heading = line.trim().to_owned();
        }
        let starts_table =
            line.starts_with('|') && lines.get(i + 1).is_some_and(|next| is_rule(next));
        if !starts_table {
            i += 1;
            continue;
        }
        let mut rows = Vec::new();
        let mut j = i + 2;
        while j < lines.len() && lines[j].starts_with('|') {
            rows.push(cells(lines[j]));
            j += 1;
        }
        found.push(Table {
            line: i + 1,
            heading: heading.clone(),
            header: cells(line),
            rows,
        });
        i = j;
    }
    found
}

/// `actual` written with as many decimals as `shown` has, as the cell would read if it
/// held `actual`.
fn as_shown(shown: &str, actual: f64) -> String {
    let decimals = shown.split_once('.').map_or(0, |(_, d)| d.len());
    format!("{actual:.decimals$}")
}

/// The JSON a *figures from* cell names: the `bench.json` written by the `bench …
/// --out DIR` command in its first code span, or None where it names no bench run.
fn cited_run(cell: &str) -> Option<String> {
    let command = cell.split('`').nth(1)?;
    let words: Vec<&str> = command.split_whitespace().collect();
    if !words.contains(&"bench") {
        return None;
    }
    let out = words.iter().position(|w| *w == "--out")?;
    Some(format!("{}/bench.json", words.get(out + 1)?))
}

/// The first code span of `cell`: a method's name in README's first column.
fn code_span(cell: &str) -> Option<&str> {
    cell.split('`').nth(1)
}

/// The case of `method` at its default in the page's own view of the run `run`. The
/// baseline's cache size is pinned in its parameters in every case: it is not a
/// setting.
fn page_default<'a>(run: &'a Value, method: &str) -> Option<&'a Value> {
    run["cases"].as_array()?.iter().find(|c| {
        c["scene"] == "page"
            && c["view"] == "own"
            && c["method"] == method
            && c["params"]
                .as_array()
                .is_some_and(|p| p.iter().all(|kv| kv[0] == "cache_px_per_em"))
    })
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

/// Where README's table of methods differs from the runs it cites: one line per wrong
/// figure. `run` reads a `bench.json` by its path from the repository's root.
fn readme_errors(readme: &str, run: &dyn Fn(&str) -> Value) -> Vec<String> {
    let mut errors = Vec::new();
    let all = tables(readme);
    let table = all
        .iter()
        .find(|t| t.header.iter().any(|h| h.starts_with("page: ")))
        .expect("README has the table of methods, with a 'page: …' column");
    let column = |name: &dyn Fn(&str) -> bool| {
        table
            .header
            .iter()
            .position(|h| name(h.as_str()))
            .expect("the column")
    };
    let figures = column(&|h| h.starts_with("page: "));
    let source = column(&|h| h == "figures from");
    // "page: × atlas · MAE /255 · max": what each figure of a cell is.
    let kinds: Vec<&str> = table.header[figures]["page: ".len()..]
        .split(" · ")
        .collect();
    let mut cited = None;
    let mut checked = 0;
    for (i, row) in table.rows.iter().enumerate() {
        let line = table.line + 2 + i;
        let method = code_span(&row[0]).unwrap_or(&row[0]).to_owned();
        cited = match row[source].as_str() {
            "same" => cited,
            cell => cited_run(cell),
        };
        let cell = &row[figures];
        let Some(path) = &cited else {
            if cell.contains('×') {
                errors.push(format!(
                    "README.md:{line}, `{method}`: its figures cite no bench run"
                ));
            }
            continue;
        };
        let json = run(path);
        let Some(case) = page_default(&json, &method) else {
            errors.push(format!(
                "README.md:{line}, `{method}`: {path} has no default case of it on the page"
            ));
            continue;
        };
        let shown: Vec<&str> = cell.split(" · ").collect();
        if shown.len() != kinds.len() {
            errors.push(format!(
                "README.md:{line}, `{method}`: '{cell}' is not {}",
                kinds.join(" · ")
            ));
            continue;
        }
        for (kind, shown) in kinds.iter().zip(shown) {
            // The reference has no GPU time: its first ratio's place gives its CPU
            // rasterization, and any other ratio is "—".
            if shown == "—" && kind.starts_with("× ") && case["cpu_render_ms"].is_number() {
                continue;
            }
            let (figure, actual) = if let Some(ms) = shown
                .strip_prefix("— (")
                .and_then(|s| s.strip_suffix(" ms CPU)"))
            {
                (ms, number(&case["cpu_render_ms"]))
            } else {
                match *kind {
                    // "× atlas", "× glyphon": over that method's default in the same run,
                    // the run's own ratio with its interval where it kept one
                    // (`ratio_atlas`, `ratio_glyphon`: `V× (L–H)`, `*` after an
                    // unsettled one), else the ratio of the medians.
                    k if k.starts_with("× ") => {
                        let over = &k["× ".len()..];
                        let Some(base) = page_default(&json, over) else {
                            errors.push(format!(
                                "README.md:{line}, `{method}`: {path} has no default case \
                                 of {over} on the page"
                            ));
                            continue;
                        };
                        let field = &case[format!("ratio_{over}")];
                        if let Some(value) = field["value"].as_f64() {
                            let written = format!(
                                "{}× ({}–{}){}",
                                as_shown("0.00", value),
                                as_shown("0.00", number(&field["low"])),
                                as_shown("0.00", number(&field["high"])),
                                if field["settled"] == true { "" } else { "*" }
                            );
                            if shown != written {
                                errors.push(format!(
                                    "README.md:{line}, `{method}`, {kind}: {shown} where \
                                     {path} gives {written}"
                                ));
                            }
                            continue;
                        }
                        (
                            shown.trim_end_matches('×'),
                            number(&case["frame_ms"]) / number(&base["frame_ms"]),
                        )
                    }
                    "MAE /255" => (shown, number(&case["error"]["mae_255"])),
                    "max" => (shown, number(&case["error"]["max"])),
                    other => panic!("README's figure '{other}' is not one this test knows"),
                }
            };
            let expected = as_shown(figure, actual);
            if figure != expected {
                errors.push(format!(
                    "README.md:{line}, `{method}`, {kind}: {figure} where {path} gives {expected}"
                ));
            }
        }
        checked += 1;
    }
    if checked == 0 {
        errors.push("README.md: no row of the table of methods cites a bench run".into());
    }
    errors
}

/// Whether a quoted cell reads what the bench wrote: the same text, or a refusal
/// shortened to a word of its reason (`n/a — tilt` for `n/a — vello draws affine
/// transforms only: a tilt (35°) needs perspective`).
fn quotes(quoted: &str, written: &str) -> bool {
    quoted == written
        || match (
            quoted.strip_prefix("n/a — "),
            written.strip_prefix("n/a — "),
        ) {
            (Some(word), Some(reason)) => !word.is_empty() && reason.contains(word),
            _ => false,
        }
}

/// Where `doc`'s quoted tables differ from the tables the bench wrote; `doc_name`
/// names it in the messages, and `source` reads a report by its path from docs/.
fn quote_errors(doc_name: &str, doc: &str, source: &dyn Fn(&str) -> String) -> Vec<String> {
    let mut errors = Vec::new();
    let lines: Vec<&str> = doc.lines().collect();
    let quoted_tables = tables(doc);
    let mut markers = 0;
    for (n, line) in lines.iter().enumerate() {
        let Some(marker) = line
            .trim()
            .strip_prefix("<!-- quotes ")
            .and_then(|m| m.strip_suffix(" -->"))
        else {
            continue;
        };
        markers += 1;
        let at = format!("{doc_name}:{}", n + 1);
        let Some((path, heading)) = marker
            .split_once(' ')
            .map(|(p, h)| (p, h.trim_matches('"')))
        else {
            errors.push(format!("{at}: the marker names no heading"));
            continue;
        };
        let Some(quote) = quoted_tables.iter().find(|t| t.line > n + 1) else {
            errors.push(format!("{at}: no table follows the marker"));
            continue;
        };
        let written = tables(&source(path));
        let Some(table) = written
            .iter()
            .find(|t| t.heading == heading && quote.header.iter().all(|h| t.header.contains(h)))
        else {
            errors.push(format!(
                "{at}: {path} has no table under '{heading}' with the columns {:?}",
                quote.header
            ));
            continue;
        };
        // Rows are found by their first cells: as few as tell the table's rows apart.
        let key_len = (1..=table.header.len())
            .find(|&k| {
                let keys: Vec<&[String]> =
                    table.rows.iter().map(|r| &r[..k.min(r.len())]).collect();
                keys.iter()
                    .enumerate()
                    .all(|(i, key)| !keys[..i].contains(key))
            })
            .unwrap_or(table.header.len());
        if quote.rows.is_empty() {
            errors.push(format!(
                "{doc_name}:{}: the quoted table is empty",
                quote.line
            ));
        }
        for (i, row) in quote.rows.iter().enumerate() {
            let line = quote.line + 2 + i;
            let key = &row[..key_len.min(row.len())];
            let Some(found) = table.rows.iter().find(|r| r.get(..key_len) == Some(key)) else {
                errors.push(format!(
                    "{doc_name}:{line}: {path} under '{heading}' has no row {key:?}"
                ));
                continue;
            };
            for (column, cell) in quote.header.iter().zip(row) {
                let at_column = table.header.iter().position(|h| h == column);
                let written = at_column
                    .and_then(|c| found.get(c))
                    .map_or("", String::as_str);
                if !quotes(cell, written) {
                    errors.push(format!(
                        "{doc_name}:{line}, row {key:?}, column '{column}': '{cell}' where \
                         {path} has '{written}'"
                    ));
                }
            }
        }
    }
    if markers == 0 {
        errors.push(format!("{doc_name}: no quoted table is marked"));
    }
    errors
}

fn committed_run(path: &str) -> Value {
    serde_json::from_str(&read(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn committed_report(path: &str) -> String {
    read(&format!("docs/{path}"))
}

#[test]
fn readme_method_figures_are_the_cited_runs() {
    let errors = readme_errors(&read("README.md"), &committed_run);
    assert!(errors.is_empty(), "\n{}", errors.join("\n"));
}

#[test]
fn docs_bench_tables_quote_the_committed_reports() {
    for doc in ["docs/bench.md", "docs/motion.md", "docs/survey.md"] {
        let errors = quote_errors(doc, &read(doc), &committed_report);
        assert!(errors.is_empty(), "\n{}", errors.join("\n"));
    }
}

/// A table read as written by hand: its line, heading, columns and cells; the rule
/// under the header is not a row, and a table ends at the first line not a row.
#[test]
fn tables_read_as_written() {
    let md = "# Title\n\ntext | not a table\n\n## Part\n\n| a | b c |\n|---|---:|\n\
              | 1 | `x` · 2 |\n|  3 |4|\nafter\n";
    let found = tables(md);
    assert_eq!(found.len(), 1, "{found:?}");
    let t = &found[0];
    assert_eq!((t.line, t.heading.as_str()), (7, "## Part"));
    assert_eq!(t.header, ["a", "b c"]);
    assert_eq!(t.rows, [vec!["1", "`x` · 2"], vec!["3", "4"]]);
    assert_eq!(as_shown("1.78", 1.7849), "1.78");
    assert_eq!(as_shown("361", 361.06), "361");
    assert_eq!(
        cited_run("`cargo run --release -- bench --out docs/bench`; limits: …").as_deref(),
        Some("docs/bench/bench.json")
    );
    assert_eq!(cited_run("`cargo test --release --test gpu_smoke`"), None);
}

/// README with one figure changed (sdf-cells' max, 0.417 → 0.418), with the reference's
/// CPU time changed, and with a ratio to each yardstick changed: each wrong cell is
/// named, and nothing else.
#[test]
fn a_wrong_readme_figure_is_named() {
    let readme = read("README.md");
    for (right, wrong, named) in [
        (
            "16.72× (14.73–18.91)* · 0.36 · 0.417",
            "16.72× (14.73–18.91)* · 0.36 · 0.418",
            "`sdf-cells`, max: 0.418 where docs/bench/peers/bench.json gives 0.417",
        ),
        (
            "— (460 ms CPU)",
            "— (360 ms CPU)",
            "`reference`, × atlas: 360 where docs/bench/peers/bench.json gives 460",
        ),
        (
            "0.69× (0.68–0.70) · 1.00× · 3.21",
            "0.70× (0.68–0.70) · 1.00× · 3.21",
            "`glyphon`, × atlas: 0.70× (0.68–0.70) where docs/bench/peers/bench.json gives \
             0.69× (0.68–0.70)",
        ),
        (
            "2.00× (1.97–2.10) · 3.01× (2.90–3.14) · 0.00",
            "2.00× (1.97–2.10) · 3.01× (2.90–3.15) · 0.00",
            "`winding`, × glyphon: 3.01× (2.90–3.15) where docs/bench/peers/bench.json gives \
             3.01× (2.90–3.14)",
        ),
        (
            "32.35× (31.17–37.09)* · 0.62",
            "32.35× (31.17–37.09) · 0.62",
            "`xor-stencil`, × glyphon: 32.35× (31.17–37.09) where \
             docs/bench/peers/bench.json gives 32.35× (31.17–37.09)*",
        ),
    ] {
        assert_eq!(
            readme.matches(right).count(),
            1,
            "README holds '{right}' once"
        );
        let errors = readme_errors(&readme.replace(right, wrong), &committed_run);
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(errors[0].contains(named), "{errors:?}");
    }
}

/// docs/bench.md with one quoted cell changed (the page's winding ratio in the peers'
/// table) and one row the report lacks: each is named.
#[test]
fn a_wrong_quoted_cell_is_named() {
    let doc = read("docs/bench.md");
    let right = "| page | own | 2.00× (1.97–2.10) · 3.01× (2.90–3.14) · 0.00 · 0.03 · 0.001 · 0 |";
    assert_eq!(doc.matches(right).count(), 1);
    let wrong = doc.replace(
        right,
        "| page | own | 2.00× (1.97–2.20) · 3.01× (2.90–3.14) · 0.00 · 0.03 · 0.001 · 0 |",
    );
    let errors = quote_errors("docs/bench.md", &wrong, &committed_report);
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("row [\"page\", \"own\"], column 'winding': '2.00× (1.97–2.20)"),
        "{errors:?}"
    );
    let refusal =
        "| rotated | own | 2.41× (2.34–2.52) · n/a · 0.00 · 0.04 · 0.001 · 0 | n/a — tilt |";
    assert_eq!(doc.matches(refusal).count(), 1);
    let wrong = doc.replace(
        refusal,
        "| rotated | own | 2.41× (2.34–2.52) · n/a · 0.00 · 0.04 · 0.001 · 0 | n/a — turns |",
    );
    let errors = quote_errors("docs/bench.md", &wrong, &committed_report);
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(
        errors[0].contains("column 'vello': 'n/a — turns'"),
        "{errors:?}"
    );
    let extra = doc.replacen(
        "| reference | default | 466 (CPU)",
        "| nothing | default | 1 |\n| reference | default | 466 (CPU)",
        1,
    );
    let errors = quote_errors("docs/bench.md", &extra, &committed_report);
    assert!(
        errors
            .iter()
            .any(|e| e.contains("has no row [\"nothing\", \"default\"]")),
        "{errors:?}"
    );
}
