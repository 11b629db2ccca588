//! No import circle between the files of one crate, in every crate of the repository.
//!
//! The crates are read from the root manifest: the root package (`src/`), the workspace
//! members and the packages excluded from the workspace (`python/`), each scanned under its
//! `src/`, which must hold `.rs` files; only `fuzz/` is not scanned ([`NOT_SCANNED`] says
//! why). For every crate this reads each `*.rs` under its `src/`, finds the paths that reach
//! other files of the same crate (`use crate::…`, `use super::…`, `use self::…`,
//! `use child::…`, and `crate::x::y` / `super::x` paths written in code), resolves each one to
//! the file that defines the item (following `use` and `pub use` re-exports, so `crate::Dart`
//! leads to the file that defines `Dart`, not to `lib.rs`), and asserts that the graph of
//! files is acyclic. A failure prints every circle found, one per strongly connected part.
//!
//! Comments, strings and character literals are removed before the scan, so doc links and
//! examples are not imports. Inline modules (`mod tests { use super::*; }`) are followed, so
//! `super` is resolved from where it is written. A `mod` declaration is not an import. Items
//! under `#[cfg(test)]` or `#[cfg(doc)]` count like any other, as they do for the tools that
//! draw a crate's modules: unit tests that need a sibling which imports the tested file live
//! in a child file nothing imports (`gmap-core/src/edit/tests.rs`) or in `tests/`, and a doc
//! link names its target by path rather than through a `use`. The crates of
//! [`TESTS_LEFT_OUT`] are scanned without their `#[cfg(test)]` items, for the reason given
//! there. `LAYOUT_EDGES=1` prints every crate's graph of files.

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::path::{Path, PathBuf};

/// A module path from the crate root, e.g. `["io", "native"]`.
type ModPath = Vec<String>;

/// Everything the resolver knows about one crate.
#[derive(Default)]
struct Crate {
    /// module path → file that holds it (inline modules map to their file)
    modules: HashMap<ModPath, usize>,
    /// (module, name) → absolute path the name stands for, from that module's `use` items
    aliases: HashMap<(ModPath, String), ModPath>,
    /// module → absolute paths it imports with `*`
    globs: HashMap<ModPath, Vec<ModPath>>,
    /// (module, name) of the items defined in each module
    defs: HashSet<(ModPath, String)>,
    /// modules compiled only for unit tests (`#[cfg(test)] mod …`), when they are left out
    tests_only: HashSet<ModPath>,
    /// file names, relative to `src/`
    files: Vec<String>,
}

/// Comments, string and character literals blanked out (lifetimes kept).
fn strip(src: &str) -> String {
    let b: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(b.len());
    let mut i = 0;
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < b.len() && b[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            let mut depth = 0;
            while i < b.len() {
                if b[i] == '/' && b.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if b[i] == '*' && b.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            out.push(' ');
        } else if (c == 'r' || (c == 'b' && next == Some('r'))) && (i == 0 || !ident(b[i - 1])) && {
            let mut j = i + if c == 'b' { 2 } else { 1 };
            while b.get(j) == Some(&'#') {
                j += 1;
            }
            b.get(j) == Some(&'"')
        } {
            // raw string r#"…"#
            let mut j = i + if c == 'b' { 2 } else { 1 };
            let mut hashes = 0;
            while b[j] == '#' {
                hashes += 1;
                j += 1;
            }
            j += 1;
            loop {
                if b[j] == '"' && (1..=hashes).all(|h| b.get(j + h) == Some(&'#')) {
                    i = j + 1 + hashes;
                    break;
                }
                j += 1;
            }
            out.push_str("\"\"");
        } else if c == '"' {
            i += 1;
            while b[i] != '"' {
                i += if b[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if c == '\'' && next == Some('\\') {
            i += 2;
            while b[i] != '\'' {
                i += 1;
            }
            i += 1;
            out.push_str("' '");
        } else if c == '\'' && b.get(i + 2) == Some(&'\'') {
            i += 3;
            out.push_str("' '");
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// The tokens that matter to paths: identifiers, `::`, and single punctuation characters.
fn tokens(src: &str) -> Vec<String> {
    let b: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_alphanumeric() || c == '_' {
            let s = i;
            while i < b.len() && (b[i].is_alphanumeric() || b[i] == '_') {
                i += 1;
            }
            out.push(b[s..i].iter().collect());
        } else if c == ':' && b.get(i + 1) == Some(&':') {
            out.push("::".into());
            i += 2;
        } else {
            if !c.is_whitespace() {
                out.push(c.to_string());
            }
            i += 1;
        }
    }
    out
}

/// The leaves of a use tree starting at `toks[*i]`, each as (path, name it binds or `None`
/// for a glob); `*i` ends past the tree.
fn use_tree(toks: &[String], i: &mut usize, prefix: &[String], out: &mut Vec<(ModPath, Option<String>)>) {
    let mut path = prefix.to_vec();
    loop {
        match toks.get(*i).map(String::as_str) {
            Some("::") => *i += 1,
            Some("{") => {
                *i += 1;
                while toks.get(*i).is_some_and(|t| t != "}") {
                    use_tree(toks, i, &path, out);
                    if toks.get(*i).is_some_and(|t| t == ",") {
                        *i += 1;
                    }
                }
                *i += 1;
                return;
            }
            Some("*") => {
                *i += 1;
                out.push((path, None));
                return;
            }
            Some(t) if t.chars().all(|c| c.is_alphanumeric() || c == '_') => {
                path.push(t.to_string());
                *i += 1;
                if toks.get(*i).is_some_and(|t| t == "as") {
                    let name = toks[*i + 1].clone();
                    *i += 2;
                    out.push((path, Some(name)));
                    return;
                }
                if toks.get(*i).is_none_or(|t| t != "::") {
                    if path.last().is_some_and(|l| l == "self") {
                        path.pop();
                    }
                    let name = path.last().cloned();
                    out.push((path, name));
                    return;
                }
            }
            _ => return,
        }
    }
}

/// One path written in a file: where it is written (module) and its segments as written.
struct Written {
    file: usize,
    at: ModPath,
    path: ModPath,
}

/// The module path of a file under `src/`: `lib.rs`/`main.rs` → root, `a/mod.rs` → `a`.
fn module_of(rel: &Path) -> ModPath {
    let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    let last = parts.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if !(parts.is_empty() && (stem == "lib" || stem == "main")) && stem != "mod" {
        parts.push(stem.to_string());
    }
    parts
}

fn rs_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rs_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// What the scan of a crate reads.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Scope {
    /// every `use` item and every path, whatever `#[cfg]` it is under
    Everything,
    /// everything but the items under `#[cfg(test)]` (see [`TESTS_LEFT_OUT`])
    WithoutUnitTests,
}

/// Reads a crate's `src/` and returns its resolver and the paths written in its files.
fn scan(src: &Path, scope: Scope) -> (Crate, Vec<Written>) {
    let mut files = Vec::new();
    rs_files(src, &mut files);
    let mut krate = Crate::default();
    let mut written = Vec::new();
    for (f, path) in files.iter().enumerate() {
        let rel = path.strip_prefix(src).unwrap();
        krate.files.push(rel.to_string_lossy().into_owned());
        let module = module_of(rel);
        krate.modules.insert(module.clone(), f);
        let toks = tokens(&strip(&std::fs::read_to_string(path).unwrap()));
        // inline modules: (module path, brace depth inside it)
        let mut stack: Vec<(ModPath, usize)> = vec![(module.clone(), 0)];
        let mut depth = 0usize;
        let mut i = 0;
        // after `#[cfg(test)]`, in `Scope::WithoutUnitTests`: the next item is left out
        let mut cfg_test = false;
        while i < toks.len() {
            let at = stack.last().unwrap().0.clone();
            let cfg = toks[i..].starts_with(&["#", "[", "cfg", "(", "test", ")", "]"].map(String::from));
            if cfg && scope == Scope::WithoutUnitTests {
                cfg_test = true;
                i += 7;
                continue;
            }
            let test_use = cfg_test && toks[i] == "use";
            let item = ["mod", "fn", "struct", "enum", "use", "impl", "const", "static", "trait", "type", ";", "{"];
            if cfg_test && item.contains(&toks[i].as_str()) {
                if toks[i] == "mod" {
                    let mut inner = at.clone();
                    inner.push(toks[i + 1].clone());
                    krate.tests_only.insert(inner);
                }
                cfg_test = false;
            }
            match toks[i].as_str() {
                "{" => depth += 1,
                "}" => {
                    if stack.len() > 1 && stack.last().unwrap().1 == depth {
                        stack.pop();
                    }
                    depth = depth.checked_sub(1).expect("balanced braces after stripping");
                }
                "mod" if toks.get(i + 2).is_some_and(|t| t == "{") => {
                    let mut inner = at.clone();
                    inner.push(toks[i + 1].clone());
                    krate.modules.insert(inner.clone(), f);
                    depth += 1;
                    stack.push((inner, depth));
                    i += 3;
                    continue;
                }
                "struct" | "enum" | "fn" | "trait" | "type" | "const" | "static" | "union" | "macro_rules" => {
                    if let Some(name) = toks.get(i + 1).filter(|t| t.chars().all(|c| c.is_alphanumeric() || c == '_')) {
                        krate.defs.insert((at.clone(), name.clone()));
                    } else if let Some(name) = toks.get(i + 2).filter(|_| toks[i + 1] == "!") {
                        krate.defs.insert((at.clone(), name.clone()));
                    }
                }
                "use" => {
                    i += 1;
                    let mut leaves = Vec::new();
                    use_tree(&toks, &mut i, &[], &mut leaves);
                    for (path, name) in leaves.into_iter().filter(|_| !test_use) {
                        match name {
                            Some(n) => {
                                krate.aliases.insert((at.clone(), n), path.clone());
                            }
                            None => krate.globs.entry(at.clone()).or_default().push(path.clone()),
                        }
                        written.push(Written { file: f, at: at.clone(), path });
                    }
                    continue;
                }
                t @ ("crate" | "super" | "self")
                    if toks.get(i + 1).is_some_and(|t| t == "::") && (i == 0 || toks[i - 1] != "::") =>
                {
                    let mut path = vec![t.to_string()];
                    i += 1;
                    while toks.get(i).is_some_and(|t| t == "::")
                        && toks.get(i + 1).is_some_and(|t| t.chars().all(|c| c.is_alphanumeric() || c == '_'))
                    {
                        path.push(toks[i + 1].clone());
                        i += 2;
                    }
                    written.push(Written { file: f, at, path });
                    continue;
                }
                _ => {}
            }
            i += 1;
        }
    }
    // aliases and globs hold paths as written: make them absolute (None: another crate)
    let raw: Vec<_> = krate.aliases.iter().map(|(k, v)| (k.clone(), v.clone())).collect();
    for ((at, name), path) in raw {
        match absolute(&krate, &at, &path) {
            Some(p) => krate.aliases.insert((at, name), p),
            None => krate.aliases.remove(&(at, name)),
        };
    }
    let raw: Vec<_> = krate.globs.drain().collect();
    for (at, paths) in raw {
        let abs = paths.iter().filter_map(|p| absolute(&krate, &at, p)).collect();
        krate.globs.insert(at, abs);
    }
    (krate, written)
}

/// A path written in module `at` made absolute, or `None` when it names another crate.
fn absolute(k: &Crate, at: &ModPath, path: &[String]) -> Option<ModPath> {
    let mut out;
    let mut rest = path;
    match path.first().map(String::as_str) {
        Some("crate") => {
            out = Vec::new();
            rest = &path[1..];
        }
        Some("super" | "self") => {
            out = at.clone();
            while let Some(s) = rest.first().filter(|s| *s == "super" || *s == "self") {
                if s == "super" {
                    out.pop()?;
                }
                rest = &rest[1..];
            }
        }
        Some(first) => {
            let mut child = at.clone();
            child.push(first.to_string());
            if k.modules.contains_key(&child) {
                out = at.clone();
            } else if let Some(target) = k.aliases.get(&(at.clone(), first.to_string())) {
                if target.first().is_some_and(|t| t == first) {
                    return None; // `use other_crate::x;` names another crate
                }
                out = at.clone();
            } else {
                return None;
            }
        }
        None => return None,
    }
    out.extend(rest.iter().cloned());
    Some(out)
}

/// The file that defines what the absolute path `path` names.
fn resolve(k: &Crate, path: &[String], fuel: usize) -> Option<usize> {
    if fuel == 0 {
        return None;
    }
    let mut cur: ModPath = Vec::new();
    for (i, seg) in path.iter().enumerate() {
        let mut cand = cur.clone();
        cand.push(seg.clone());
        if k.modules.contains_key(&cand) {
            cur = cand;
            continue;
        }
        if k.defs.contains(&(cur.clone(), seg.clone())) {
            return k.modules.get(&cur).copied();
        }
        if let Some(target) = k.aliases.get(&(cur.clone(), seg.clone())) {
            if *target != cand {
                let mut t = target.clone();
                t.extend(path[i + 1..].iter().cloned());
                return resolve(k, &t, fuel - 1);
            }
        }
        // through a glob import when it leads somewhere that defines the name
        for g in k.globs.get(&cur).into_iter().flatten() {
            let mut t = g.clone();
            t.extend(path[i..].iter().cloned());
            let mut m = g.clone();
            m.push(seg.clone());
            let key = (g.clone(), seg.clone());
            if k.modules.contains_key(&m) || k.defs.contains(&key) || k.aliases.contains_key(&key) {
                return resolve(k, &t, fuel - 1);
            }
        }
        return k.modules.get(&cur).copied();
    }
    k.modules.get(&cur).copied()
}

/// The graph of a crate's files: `edges[f]` the files that `f` imports from.
fn file_graph(src: &Path, scope: Scope) -> (Vec<String>, Vec<BTreeSet<usize>>) {
    let (k, written) = scan(src, scope);
    let mut edges = vec![BTreeSet::new(); k.files.len()];
    for w in &written {
        if (0..=w.at.len()).any(|l| k.tests_only.contains(&w.at[..l])) {
            continue;
        }
        if let Some(abs) = absolute(&k, &w.at, &w.path) {
            if let Some(t) = resolve(&k, &abs, 32) {
                if t != w.file {
                    edges[w.file].insert(t);
                }
            }
        }
    }
    (k.files, edges)
}

/// One circle in each strongly connected part of more than one node, each as the list of
/// its nodes in order (the first node's predecessor is the last).
fn cycles(edges: &[BTreeSet<usize>]) -> Vec<Vec<usize>> {
    strongly_connected(edges).iter().map(|part| shortest_circle(edges, part)).collect()
}

/// The strongly connected parts of more than one node (Tarjan), each sorted.
fn strongly_connected(edges: &[BTreeSet<usize>]) -> Vec<Vec<usize>> {
    let n = edges.len();
    let (mut index, mut low) = (vec![usize::MAX; n], vec![0; n]);
    let (mut on, mut stack, mut next) = (vec![false; n], Vec::new(), 0);
    let mut parts = Vec::new();
    fn visit(
        v: usize,
        e: &[BTreeSet<usize>],
        st: &mut (&mut Vec<usize>, &mut Vec<usize>, &mut Vec<bool>, &mut Vec<usize>, &mut usize),
        parts: &mut Vec<Vec<usize>>,
    ) {
        st.0[v] = *st.4;
        st.1[v] = *st.4;
        *st.4 += 1;
        st.3.push(v);
        st.2[v] = true;
        for &w in &e[v] {
            if st.0[w] == usize::MAX {
                visit(w, e, st, parts);
                st.1[v] = st.1[v].min(st.1[w]);
            } else if st.2[w] {
                st.1[v] = st.1[v].min(st.0[w]);
            }
        }
        if st.1[v] == st.0[v] {
            let mut part = Vec::new();
            loop {
                let w = st.3.pop().unwrap();
                st.2[w] = false;
                part.push(w);
                if w == v {
                    break;
                }
            }
            if part.len() > 1 {
                parts.push(part);
            }
        }
    }
    for v in 0..n {
        if index[v] == usize::MAX {
            visit(v, edges, &mut (&mut index, &mut low, &mut on, &mut stack, &mut next), &mut parts);
        }
    }
    for part in &mut parts {
        part.sort();
    }
    parts
}

/// A shortest circle through the smallest node of a strongly connected part (breadth first).
fn shortest_circle(edges: &[BTreeSet<usize>], part: &[usize]) -> Vec<usize> {
    let inside: BTreeSet<usize> = part.iter().copied().collect();
    let start = *inside.iter().next().unwrap();
    let mut prev: BTreeMap<usize, usize> = BTreeMap::new();
    let mut queue = std::collections::VecDeque::from([start]);
    while let Some(v) = queue.pop_front() {
        for &w in edges[v].iter().filter(|w| inside.contains(w)) {
            if w == start {
                let mut circle = vec![v];
                while *circle.last().unwrap() != start {
                    circle.push(prev[circle.last().unwrap()]);
                }
                circle.reverse();
                return circle;
            }
            if let std::collections::btree_map::Entry::Vacant(e) = prev.entry(w) {
                e.insert(v);
                queue.push_back(w);
            }
        }
    }
    unreachable!("a strongly connected part has a circle through each node")
}

/// The circles among the files of the crate whose sources are in `src`, one line each
/// (empty when there is none); panics when `src` holds no `.rs` file.
fn circles_in(src: &Path, scope: Scope) -> Vec<String> {
    assert!(src.is_dir(), "{} has no src/ directory", src.display());
    let (files, edges) = file_graph(src, scope);
    assert!(!files.is_empty(), "no sources found under {}", src.display());
    if std::env::var_os("LAYOUT_EDGES").is_some() {
        eprintln!("== {} ({scope:?})", src.display());
        for (f, e) in edges.iter().enumerate() {
            eprintln!("{} -> {:?}", files[f], e.iter().map(|&t| files[t].as_str()).collect::<Vec<_>>());
        }
    }
    strongly_connected(&edges)
        .iter()
        .map(|part| {
            let mut names: Vec<&str> = shortest_circle(&edges, part).iter().map(|&f| files[f].as_str()).collect();
            names.push(names[0]);
            let all: Vec<&str> = part.iter().map(|&f| files[f].as_str()).collect();
            format!("{}   (the files in circles with them: {})", names.join(" -> "), all.join(", "))
        })
        .collect()
}

/// The quoted strings of the array `key = [ … ]` in the `[workspace]` table of a manifest.
fn workspace_list(manifest: &str, key: &str) -> Vec<String> {
    let mut in_workspace = false;
    let mut found = None;
    for (n, line) in manifest.lines().enumerate() {
        let line = line.trim();
        if line.starts_with('[') {
            in_workspace = line == "[workspace]";
        } else if in_workspace && line.split('=').next().is_some_and(|k| k.trim() == key) {
            found = Some(n);
            break;
        }
    }
    let Some(start) = found else { return Vec::new() };
    let text: String = manifest.lines().skip(start).collect::<Vec<_>>().join("\n");
    let array = &text[text.find('[').expect("an array")..text.find(']').expect("a closed array")];
    array.split('"').skip(1).step_by(2).map(str::to_string).collect()
}

/// The packages of the repository, as directories relative to its root (`""`: the root
/// package), read from the root manifest: the root package, the workspace members, and
/// the packages excluded from the workspace (each with a manifest of its own).
fn repository_crates() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let manifest = std::fs::read_to_string(root.join("Cargo.toml")).unwrap();
    let mut crates = Vec::new();
    if manifest.lines().any(|l| l.trim() == "[package]") {
        crates.push(String::new());
    }
    crates.extend(workspace_list(&manifest, "members"));
    for dir in workspace_list(&manifest, "exclude") {
        let own = std::fs::read_to_string(root.join(&dir).join("Cargo.toml"))
            .unwrap_or_else(|e| panic!("{dir}/ is excluded from the workspace but has no readable Cargo.toml: {e}"));
        assert!(own.lines().any(|l| l.trim() == "[package]"), "{dir}/Cargo.toml declares no package");
        crates.push(dir);
    }
    crates
}

/// The excluded package not scanned, and why: its binaries are cargo-fuzz targets, one file
/// each under `fuzz_targets/` (no `src/`), sharing `fuzz_targets/shared/mod.rs` through a
/// `#[path]` attribute, which the scanner does not follow.
const NOT_SCANNED: &[&str] = &["fuzz"];

/// The crates whose scan leaves out the items under `#[cfg(test)]`, and why. The test fails
/// when an entry is no longer needed.
const TESTS_LEFT_OUT: &[(&str, &str)] = &[];

#[test]
fn no_import_circle_in_any_crate() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let crates = repository_crates();
    let named = NOT_SCANNED.iter().chain(TESTS_LEFT_OUT.iter().map(|(c, _)| c));
    for dir in named {
        assert!(crates.iter().any(|c| c == dir), "{dir} is named by the test but is no package of the repository");
    }
    let mut failures = Vec::new();
    let mut scanned = Vec::new();
    for dir in crates.iter().filter(|c| !NOT_SCANNED.contains(&c.as_str())) {
        let src = root.join(dir).join("src");
        let name = if dir.is_empty() { "src".to_string() } else { format!("{dir}/src") };
        let lenient = TESTS_LEFT_OUT.iter().any(|(c, _)| c == dir);
        let scope = if lenient { Scope::WithoutUnitTests } else { Scope::Everything };
        let found = circles_in(&src, scope);
        if !found.is_empty() {
            failures.push(format!("import circles between the files of {name}:\n  {}", found.join("\n  ")));
        }
        if lenient && found.is_empty() && circles_in(&src, Scope::Everything).is_empty() {
            failures.push(format!("{dir} needs no entry in TESTS_LEFT_OUT any more: its unit tests make no circle"));
        }
        let why = TESTS_LEFT_OUT.iter().find(|(c, _)| c == dir).map(|(_, why)| format!(": {why}"));
        scanned.push(format!("{name} ({scope:?}{})", why.unwrap_or_default()));
    }
    eprintln!("scanned: {}", scanned.join(", "));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn cycle_finder_finds_circles_and_only_circles() {
    let g = |edges: &[(usize, usize)], n: usize| {
        let mut e = vec![BTreeSet::new(); n];
        for &(a, b) in edges {
            e[a].insert(b);
        }
        e
    };
    // a chain and a diamond: acyclic
    assert!(cycles(&g(&[(0, 1), (1, 2), (2, 3)], 4)).is_empty());
    assert!(cycles(&g(&[(0, 1), (0, 2), (1, 3), (2, 3)], 4)).is_empty());
    // a pair, and a triangle hanging off a chain
    assert_eq!(cycles(&g(&[(0, 1), (1, 0)], 2)), vec![vec![0, 1]]);
    assert_eq!(cycles(&g(&[(0, 1), (1, 2), (2, 3), (3, 1)], 4)), vec![vec![1, 2, 3]]);
    // two separate circles, and the shortest circle of a part with two
    assert_eq!(cycles(&g(&[(0, 1), (1, 0), (2, 3), (3, 2)], 4)).len(), 2);
    assert_eq!(cycles(&g(&[(0, 1), (1, 2), (2, 3), (3, 0), (1, 0)], 4)), vec![vec![0, 1]]);
}

#[test]
fn scanner_resolves_paths_to_the_defining_file() {
    let dir = tempfile::tempdir().unwrap();
    let w = |p: &str, s: &str| {
        let p = dir.path().join(p);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, s).unwrap();
    };
    // lib re-exports Leaf from ids; a uses it through the root, b through a glob, c names
    // b in code; c's test module uses `super::*` (c itself); strings and comments are skipped
    w("lib.rs", "mod ids; mod a; mod m; pub use ids::Leaf;\n");
    w("ids.rs", "pub struct Leaf; // use crate::a::A;\nconst S: &str = \"crate::m::b::B\";\n");
    w("a.rs", "use crate::Leaf;\npub struct A(Leaf);\n");
    w("m/mod.rs", "mod b; mod c; pub use self::b::*;\n");
    w("m/b.rs", "use super::super::{a::A, Leaf as L};\npub struct B;\n");
    w("m/c.rs", "fn f() -> super::B { crate::m::b::B }\n#[cfg(test)]\nmod tests { use super::*; }\n");
    let (files, edges) = file_graph(dir.path(), Scope::Everything);
    let id = |n: &str| files.iter().position(|f| f == n).unwrap();
    let out = |n: &str| edges[id(n)].iter().map(|&t| files[t].as_str()).collect::<Vec<_>>();
    assert_eq!(out("ids.rs"), Vec::<&str>::new());
    assert_eq!(out("a.rs"), vec!["ids.rs"]);
    assert_eq!(out("m/b.rs"), vec!["a.rs", "ids.rs"]);
    assert_eq!(out("m/c.rs"), vec!["m/b.rs"]);
    assert!(cycles(&edges).is_empty());
    // and a circle through a re-export is seen
    w("ids.rs", "pub struct Leaf(crate::m::B);\n");
    let (files, edges) = file_graph(dir.path(), Scope::Everything);
    let found = cycles(&edges);
    assert_eq!(found.len(), 1);
    let mut names: Vec<&str> = found[0].iter().map(|&f| files[f].as_str()).collect();
    names.sort();
    assert_eq!(names, vec!["a.rs", "ids.rs", "m/b.rs"]);
}

#[test]
fn manifest_lists_are_read_from_the_workspace_table() {
    let manifest = "[package]\nname = \"x\"\nexclude = [\"not-this\"]\n\n[workspace]\nmembers = [\n  \"a\",\n  \"b/c\", # the second\n]\nexclude = [\"py\"]\n\n[workspace.dependencies]\nmembers = [\"nor-this\"]\n";
    assert_eq!(workspace_list(manifest, "members"), vec!["a", "b/c"]);
    assert_eq!(workspace_list(manifest, "exclude"), vec!["py"]);
    assert_eq!(workspace_list(manifest, "default-members"), Vec::<String>::new());
}

#[test]
fn test_and_doc_items_count_unless_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let w = |p: &str, s: &str| {
        let p = dir.path().join(p);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, s).unwrap();
    };
    let circles = |scope| cycles(&file_graph(dir.path(), scope).1).len();
    // y uses x; x's unit tests use y: a circle, unless unit tests are left out
    w("lib.rs", "mod x; mod y;\n");
    w("x.rs", "pub struct X;\n#[cfg(test)]\nmod tests { use crate::y::Y; }\n");
    w("y.rs", "use crate::x::X;\npub struct Y(X);\n");
    assert_eq!(circles(Scope::Everything), 1);
    assert_eq!(circles(Scope::WithoutUnitTests), 0);
    // the same tests in a child file that nothing imports: no circle
    w("x.rs", "pub struct X;\n#[cfg(test)]\nmod tests;\n");
    w("x/tests.rs", "use crate::y::Y;\n");
    assert_eq!(circles(Scope::Everything), 0);
    // a `use` for a doc link counts in both scopes
    w("x.rs", "#[cfg(doc)]\nuse crate::y::Y;\n/// Not a [`Y`].\npub struct X;\n");
    assert_eq!(circles(Scope::Everything), 1);
    assert_eq!(circles(Scope::WithoutUnitTests), 1);
}
