//! The Python package is thin: its Rust sources (`python/src`) call the facade (`gmap`)
//! and name none of the library crates below it, and none of its rules is written twice
//! (the field rule lives in `gmap/src/options.rs`, the facade refuses a bad field). Its
//! Cargo.toml depends on the facade only, and no two of its files import each other.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The names a file of `python/src` must not hold: the library crates, as Rust paths.
const CRATES: [&str; 3] = ["gmap_core", "gmap_ops", "gmap_homology"];

/// The field rule's text, which only the facade states.
const FIELD_RULE: &str = "prime P below 2^31";

fn python() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("python")
}

/// Every `.rs` file of `python/src`, with its text.
fn sources() -> Vec<(String, String)> {
    let dir = python().join("src");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    out.sort();
    out
}

#[test]
fn python_src_names_no_library_crate_and_no_field_rule() {
    let files = sources();
    assert!(files.iter().any(|(name, _)| name == "lib.rs"), "python/src/lib.rs not found");
    let mut found = Vec::new();
    for (name, text) in &files {
        for (n, line) in text.lines().enumerate() {
            for word in CRATES.iter().chain([&FIELD_RULE]) {
                if line.contains(word) {
                    found.push(format!("python/src/{name}:{}: {word}: {}", n + 1, line.trim()));
                }
            }
        }
    }
    assert!(found.is_empty(), "python/src goes around the facade:\n{}", found.join("\n"));
}

#[test]
fn python_cargo_toml_depends_on_the_facade_only() {
    let toml = std::fs::read_to_string(python().join("Cargo.toml")).unwrap();
    // the [dependencies] table (and its target-specific forms), up to the next table
    let mut in_deps = false;
    let mut deps = Vec::new();
    for line in toml.lines() {
        let t = line.trim();
        if t.starts_with('[') {
            in_deps = t.trim_matches(|c| c == '[' || c == ']').split('.').any(|part| part.ends_with("dependencies"));
            continue;
        }
        if in_deps && !t.is_empty() && !t.starts_with('#') {
            deps.push(t.split(['=', ' ']).next().unwrap_or("").trim_matches('"').to_string());
        }
    }
    assert!(deps.iter().any(|d| d == "gmap"), "python/Cargo.toml does not depend on the facade: {deps:?}");
    for lib in ["gmap-core", "gmap-ops", "gmap-homology"] {
        assert!(!deps.iter().any(|d| d == lib), "python/Cargo.toml depends on {lib}: {deps:?}");
    }
}

#[test]
fn no_two_files_of_python_src_import_each_other_in_a_circle() {
    let files = sources();
    let modules: BTreeSet<String> = files.iter().map(|(n, _)| n.trim_end_matches(".rs").to_string()).collect();
    // who names whom: `crate::m` or `m::` after a `use`, for m a module of the package
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (name, text) in &files {
        let me = name.trim_end_matches(".rs").to_string();
        for m in &modules {
            if *m != me && text.contains(&format!("crate::{m}")) {
                edges.entry(me.clone()).or_default().insert(m.clone());
            }
        }
    }
    // lib.rs declares the modules: only the others' uses make circles
    edges.remove("lib");
    // depth-first search for a cycle
    fn visit(
        m: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|x| x == m) {
            let mut cycle = path[at..].to_vec();
            cycle.push(m.to_string());
            return Some(cycle);
        }
        if done.contains(m) {
            return None;
        }
        path.push(m.to_string());
        for n in edges.get(m).into_iter().flatten() {
            if let Some(c) = visit(n, edges, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.insert(m.to_string());
        None
    }
    let mut done = BTreeSet::new();
    for m in &modules {
        if let Some(cycle) = visit(m, &edges, &mut Vec::new(), &mut done) {
            panic!("python/src imports in a circle: {}", cycle.join(" -> "));
        }
    }
}
