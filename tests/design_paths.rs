//! docs/DESIGN.md is the map of the code: every module path it names (`gmap_ops::import::off`,
//! `gmap::route::candidates`, `gmap/src/route.rs`, `gmap_ops::import::{vtk,vtu,msh}`) must
//! exist. A path is followed from its crate's `lib.rs` one segment at a time: a child module
//! file, an item declared in the current file (whose associated items are not followed), or
//! a name the current file re-exports (followed to the module file of that name).

use std::path::{Path, PathBuf};

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The `src` folder of a crate as code names it (`gmap::core` is gmap-core).
fn crate_src(first: &str, second: Option<&str>) -> Option<(PathBuf, usize)> {
    let root = repo();
    Some(match (first, second) {
        ("gmap", Some("core")) => (root.join("gmap-core/src"), 2),
        ("gmap", Some("ops")) => (root.join("gmap-ops/src"), 2),
        ("gmap", Some("algebra")) => (root.join("gmap-homology/src"), 2),
        ("gmap", _) => (root.join("gmap/src"), 1),
        ("gmap_core", _) => (root.join("gmap-core/src"), 1),
        ("gmap_ops", _) => (root.join("gmap-ops/src"), 1),
        ("gmap_homology", _) => (root.join("gmap-homology/src"), 1),
        _ => return None,
    })
}

/// Whether `text` declares an item or module called `name`.
fn declares(text: &str, name: &str) -> bool {
    ["fn", "struct", "enum", "trait", "type", "const", "static", "mod"].iter().any(|kw| {
        text.match_indices(&format!("{kw} {name}")).any(|(i, m)| {
            let after = text[i + m.len()..].chars().next();
            !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
    })
}

/// Whether a `pub use` of `text` names `name` (as a word).
fn re_exports(text: &str, name: &str) -> bool {
    let mut rest = text;
    while let Some(at) = rest.find("pub use ") {
        let stmt = &rest[at..rest[at..].find(';').map_or(rest.len(), |e| at + e)];
        let words = stmt.split(|c: char| !(c.is_alphanumeric() || c == '_'));
        if words.into_iter().any(|w| w == name) {
            return true;
        }
        rest = &rest[at + 8..];
    }
    false
}

/// Every `.rs` file below `dir`.
fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The module file of `name` anywhere in the crate (`name.rs` or `name/mod.rs`).
fn module_anywhere(src: &Path, name: &str) -> Option<PathBuf> {
    let mut all = Vec::new();
    files(src, &mut all);
    all.into_iter().find(|p| {
        p.file_stem().is_some_and(|s| s == name)
            || (p.ends_with("mod.rs") && p.parent().is_some_and(|d| d.ends_with(name)))
    })
}

fn resolves(src: &Path, segments: &[&str]) -> bool {
    let mut file = src.join("lib.rs");
    for seg in segments {
        let dir = if file.ends_with("lib.rs") || file.ends_with("mod.rs") {
            file.parent().unwrap().to_path_buf()
        } else {
            file.with_extension("")
        };
        if dir.join(format!("{seg}.rs")).is_file() {
            file = dir.join(format!("{seg}.rs"));
            continue;
        }
        if dir.join(seg).join("mod.rs").is_file() {
            file = dir.join(seg).join("mod.rs");
            continue;
        }
        let text = std::fs::read_to_string(&file).unwrap_or_default();
        if re_exports(&text, seg) {
            match module_anywhere(src, seg) {
                Some(m) => file = m,
                // a re-exported item: what follows is one of its associated items
                None => return true,
            }
            continue;
        }
        return declares(&text, seg);
    }
    true
}

/// The module paths of a text: `gmap_x::a::b` and `gmap_x::a::{b,c}` (each of `b`, `c`).
fn paths(text: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let b = text.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut i = 0;
    while let Some(at) = text[i..].find("gmap") {
        let start = i + at;
        i = start + 4;
        if start > 0 && (ident(b[start - 1]) || b[start - 1] == b'-') {
            continue;
        }
        let mut j = start;
        while j < b.len() && (ident(b[j]) || b[j] == b':') {
            j += 1;
        }
        let path = text[start..j].trim_end_matches(':');
        if !path.contains("::") {
            continue;
        }
        let segs: Vec<String> = path.split("::").map(str::to_string).collect();
        if text[j..].starts_with('{') && text[..j].ends_with("::") {
            let end = j + text[j..].find('}').unwrap_or(0);
            for name in text[j + 1..end].split(',') {
                let mut s = segs.clone();
                s.push(name.trim().to_string());
                out.push(s);
            }
        } else {
            out.push(segs);
        }
        i = j;
    }
    out
}

#[test]
fn every_module_path_of_the_design_exists() {
    let design = std::fs::read_to_string(repo().join("docs/DESIGN.md")).unwrap();
    let mut missing = Vec::new();
    let found = paths(&design);
    assert!(found.len() > 40, "the design names {} module paths", found.len());
    for segs in &found {
        let Some((src, skip)) = crate_src(&segs[0], segs.get(1).map(String::as_str)) else { continue };
        let rest: Vec<&str> = segs[skip..].iter().map(String::as_str).collect();
        if !resolves(&src, &rest) {
            missing.push(segs.join("::"));
        }
    }
    // files named by their path
    for word in design.split(|c: char| c.is_whitespace() || "`(),;:".contains(c)) {
        if word.ends_with(".rs") && word.split('/').any(|part| part == "src") && !repo().join(word).is_file() {
            missing.push(word.to_string());
        }
    }
    assert!(missing.is_empty(), "docs/DESIGN.md names paths that do not exist: {missing:?}");
}

#[test]
fn a_missing_path_is_found_missing() {
    let (src, skip) = crate_src("gmap_ops", None).unwrap();
    assert_eq!(skip, 1);
    assert!(resolves(&src, &["import", "off"]));
    assert!(!resolves(&src, &["import", "no_such_reader"]));
    assert_eq!(paths("`gmap_ops::import::{vtk,vtu}` and gmap::route::plan").len(), 3);
}

#[test]
fn the_formats_table_is_the_registry() {
    let text = std::fs::read_to_string(repo().join("docs/FORMATS.md")).unwrap();
    let mut rows = std::collections::BTreeMap::new();
    for line in text.lines() {
        let cols: Vec<&str> = line.split('|').map(str::trim).collect();
        if cols.len() > 4 && cols[1].starts_with("`.") && cols[1].ends_with('`') {
            let ext = cols[1].trim_matches('`').trim_start_matches('.');
            rows.insert(ext.to_string(), (cols[2].starts_with("yes"), cols[3].starts_with("yes")));
        }
    }
    for f in gmap::FORMATS {
        let row = rows.remove(f.extension);
        assert_eq!(
            row,
            Some((f.reads().is_some(), f.is_written())),
            "docs/FORMATS.md's row of .{} (read, write) against the registry",
            f.extension
        );
    }
    assert!(rows.is_empty(), "docs/FORMATS.md lists formats the registry does not have: {rows:?}");
}
