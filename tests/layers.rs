//! The crate's arrows point down only: each top-level module of the library imports only
//! modules of lower layers, so there is no import circle between them, and no lower layer
//! (params, model, solve, render, racket, intake, study) knows of the experiments, the report or the
//! command line. The check reads the sources: every `crate::` path (`use crate::x::...`,
//! `use crate::{x::..., y::...}`, an inline `crate::x::f()`) and every `super::` chain that
//! climbs out of its top-level module, outside comments.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The layers, lowest first. A module may import its own layer's module and any lower one.
/// `cli` (with `main.rs`) is the binary on top: the library never names it, and the test
/// checks that too (no `crate::cli` anywhere in the library).
const LAYERS: &[&[&str]] = &[
    // numerical tools apart from the physics (roots, rank-one modes, short turns, buffers); how
    // numbers are written; the one error type; warnings as data
    &["numeric"],
    &["numfmt"],
    &["error"],
    // a running command's control (cancel, progress): read by the solvers, given by the commands
    &["control"],
    &["diagnostic"],
    &["params"],
    &["model"],
    &["solve"],
    &["render"],
    &["racket"],
    &["intake"],
    &["study"],
    &["experiments"],
    &["report"],
    // the commands as requests beneath both front ends
    &["command"],
    &["cli"],
];

/// Modules outside the order: the test-only random numbers any unit test may use.
const ANYWHERE: &[&str] = &["test_rng"];

fn layer(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            sources(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// The code of a file without its comments (line comments, doc comments and block comments);
/// string literals are kept (a path in a message is rare, and would only be checked too).
fn code(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let bytes = text.as_bytes();
    let (mut i, mut in_str, mut depth) = (0, false, 0usize);
    while i < bytes.len() {
        let rest = &text[i..];
        if depth > 0 {
            if rest.starts_with("*/") {
                depth -= 1;
                i += 2;
            } else if rest.starts_with("/*") {
                depth += 1;
                i += 2;
            } else {
                i += rest.chars().next().unwrap().len_utf8();
            }
            continue;
        }
        if in_str {
            if rest.starts_with("\\\"") || rest.starts_with("\\\\") {
                out.push_str(&rest[..2]);
                i += 2;
                continue;
            }
            if rest.starts_with('"') {
                in_str = false;
            }
        } else if rest.starts_with("//") {
            let end = rest.find('\n').unwrap_or(rest.len());
            i += end;
            continue;
        } else if rest.starts_with("/*") {
            depth = 1;
            i += 2;
            continue;
        } else if rest.starts_with('"') && !text[..i].ends_with('\'') {
            in_str = true;
        }
        let c = rest.chars().next().unwrap();
        out.push(c);
        i += c.len_utf8();
    }
    out
}

/// The top-level module names a path starting at `after` (the text just after `crate::` or an
/// escaping `super::` chain) reaches: `x` for `x::...`, each group member for `{x::.., y}`.
fn reached(after: &str) -> Vec<String> {
    let after = after.trim_start();
    if let Some(group) = after.strip_prefix('{') {
        // the members at the group's top level
        let (mut names, mut depth, mut start) = (Vec::new(), 0usize, 0usize);
        for (i, c) in group.char_indices() {
            match c {
                '{' => depth += 1,
                '}' if depth == 0 => {
                    names.push(group[start..i].to_string());
                    break;
                }
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    names.push(group[start..i].to_string());
                    start = i + 1;
                }
                _ => {}
            }
        }
        return names.iter().filter_map(|n| first_ident(n.trim())).collect();
    }
    first_ident(after).into_iter().collect()
}

fn first_ident(s: &str) -> Option<String> {
    let name: String = s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
    (!name.is_empty()).then_some(name)
}

/// One import of a top-level module by another: (from, to, file, line).
type Edge = (String, String, String, usize);

/// Every import between top-level modules of the library.
fn edges() -> Vec<Edge> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    let mut out = Vec::new();
    for file in files {
        let rel = file.strip_prefix(&src).unwrap();
        let parts: Vec<String> = rel.iter().map(|s| s.to_string_lossy().into_owned()).collect();
        let top = parts[0].trim_end_matches(".rs").to_string();
        if top == "lib" {
            continue; // the crate root declares and re-exports every module
        }
        let from = if top == "main" { "cli".to_string() } else { top };
        // the file's module path below its top-level module (`mod.rs` is its folder's module)
        let mut depth = parts.len();
        if parts.last().is_some_and(|p| p == "mod.rs") {
            depth -= 1;
        }
        let text = code(&std::fs::read_to_string(&file).unwrap());
        for (n, line) in text.lines().enumerate() {
            let mut targets = Vec::new();
            for (i, _) in line.match_indices("crate::") {
                // (`racket_impact::` in the binary is the library: it is `crate::` there)
                let before = &line[..i];
                if before.ends_with(|c: char| c.is_alphanumeric() || c == '_') && !before.ends_with("racket_impact::") {
                    continue;
                }
                targets.extend(reached(&line[i + "crate::".len()..]));
            }
            if from == "cli" {
                for (i, _) in line.match_indices("racket_impact::") {
                    targets.extend(reached(&line[i + "racket_impact::".len()..]));
                }
            }
            // a chain of `super::` as long as the file's depth climbs to the crate root
            let chain = "super::".repeat(depth);
            for (i, _) in line.match_indices(chain.as_str()) {
                let rest = &line[i + chain.len()..];
                if !rest.starts_with("super::") && !line[..i].ends_with("::") {
                    targets.extend(reached(rest));
                }
            }
            for to in targets {
                if to != from && (layer(&to).is_some() || ANYWHERE.contains(&to.as_str())) {
                    out.push((from.clone(), to, rel.display().to_string(), n + 1));
                }
            }
        }
    }
    out
}

#[test]
fn every_top_level_module_has_a_layer() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut unknown = Vec::new();
    for entry in std::fs::read_dir(&src).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().trim_end_matches(".rs").to_string();
        if !["lib", "main"].contains(&name.as_str()) && layer(&name).is_none() && !ANYWHERE.contains(&name.as_str()) {
            unknown.push(name);
        }
    }
    assert!(unknown.is_empty(), "give these modules a layer in tests/layers.rs: {unknown:?}");
}

#[test]
fn imports_point_down_only() {
    let up: Vec<String> = edges()
        .into_iter()
        .filter(|(from, to, ..)| match (layer(from), layer(to)) {
            (Some(f), Some(t)) => t > f,
            _ => false,
        })
        .map(|(from, to, file, line)| format!("src/{file}:{line}: {from} imports {to}, a higher layer"))
        .collect();
    assert!(up.is_empty(), "upward imports:\n{}", up.join("\n"));
}

#[test]
fn no_import_circle_between_top_level_modules() {
    // (implied by the layers, checked on its own so that a change of the order cannot hide one)
    let edges: BTreeSet<(String, String)> = edges().into_iter().map(|(f, t, ..)| (f, t)).collect();
    let modules: BTreeSet<&String> = edges.iter().flat_map(|(f, t)| [f, t]).collect();
    for start in &modules {
        // every module reachable from `start`; a circle is `start` reached again
        let mut seen: BTreeSet<&String> = BTreeSet::new();
        let mut stack: Vec<&String> = vec![start];
        while let Some(m) = stack.pop() {
            for (_, t) in edges.iter().filter(|(f, _)| f == m) {
                assert!(t != *start, "import circle through {start} (via {m} -> {t})");
                if seen.insert(t) {
                    stack.push(t);
                }
            }
        }
    }
}

#[test]
fn the_scan_sees_every_form_of_import() {
    // the reader of the sources itself: a group, a nested group, an inline path, comments
    assert_eq!(reached("{error::Result, params::{keys, Params}};"), ["error", "params"]);
    assert_eq!(reached("render::table::Table;"), ["render"]);
    let text = code("let a = 1; // crate::report\n/* crate::cli */ crate::study::x(\"//\");");
    assert!(!text.contains("report") && !text.contains("cli") && text.contains("crate::study"), "{text}");
    // and the library as it stands: the layers of the house are all present
    let seen: BTreeSet<String> = edges().into_iter().map(|(f, ..)| f).collect();
    for m in ["params", "model", "solve", "render", "racket", "study", "experiments", "report", "cli"] {
        assert!(seen.contains(m), "{m} imports nothing? {seen:?}");
    }
}
