//! The docs are tested: every command shown in README.md and docs/*.md runs here and its
//! output is compared with the text shown.
//!
//! A command is shown in a fenced block whose info string is `console`: a line `$ gmap …`,
//! then what it prints (stdout, then stderr), up to the next `$ ` line or the end of the
//! block. In the expected text a line `...` stands for any number of lines and `[..]` for
//! any part of a line. A command that fails shows `? N` (its exit code) as the first line of
//! its output. Commands run from a temporary folder that links `tests`, `docs` and
//! `examples` of the repository, so `tests/data/…` paths work as from the root and the files
//! they write land in the temporary folder.
//!
//! Every other line that shows a command (an indented `    gmap …`, `$ gmap …` outside a
//! `console` block, a `sh` block) must be a usage synopsis (it has a placeholder such as
//! `FILE`, `IN`, `OUT` or `[`), be run by a `console` block somewhere in the docs, or be
//! listed in [`NOT_RUN`] with the reason; so a command example cannot be added without
//! being run.
//!
//! The `gmap …` commands written in prose, as inline code spans, and the usage synopses are
//! checked too: their subcommand exists and every option they show is one it takes
//! (against `gmap SUBCOMMAND --help`), so the prose cannot drift either.
//!
//! After a merge: `cargo test --profile test-release --test docs_commands` lists every
//! mismatch at once (file, line, the command, expected and actual output).

use std::path::{Path, PathBuf};
use std::process::Command;

/// Commands shown but not run, with the reason.
const NOT_RUN: &[(&str, &str)] = &[
    ("cargo run --release -- demo", "builds the release binary (fat LTO, minutes); `gmap demo` is run below instead"),
    ("scripts/test", "runs the whole test suite, this test included"),
    (
        "cargo run --release --example view -- OUT_DIR",
        "writes the pages of every demo object; tests/view_cli.rs runs the example",
    ),
    ("python3 benches/anchors/compare_gudhi.py", "a benchmark against GUDHI (minutes, needs the bench data)"),
    ("cargo bench --bench simplify_figures", "a benchmark"),
    ("cargo bench --bench simplify", "a benchmark"),
    (
        "cargo build --release -p gmap-mpi --features mpi",
        "needs Open MPI and libclang; .ci/run builds gmap-mpi and runs its tests under mpirun",
    ),
    (
        "python3 benches/anchors/make_images.py",
        "the MPI walkthrough's image; gmap-mpi's tests under mpirun make and read it",
    ),
    ("cargo test -p gmap-mpi --features mpi", "run by .ci/run after the workspace's tests (needs Open MPI)"),
    ("cargo build --release --example persistence_image", "builds the persistence benchmark's binary (fat LTO)"),
    (
        "python3 -m venv --system-site-packages /tmp/gmap-venv",
        "the persistence benchmarks' environment (a release wheel installed in it; minutes); python/run-tests.sh makes the tests' own",
    ),
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn doc_files() -> Vec<PathBuf> {
    let mut v = vec![root().join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    v.extend(docs);
    v
}

/// A command of a console block: its line in the file, the command, the expected output.
struct Case {
    line: usize,
    command: String,
    expected: Vec<String>,
}

/// The console blocks' commands, and the other command lines (line, text).
fn parse(text: &str) -> (Vec<Case>, Vec<(usize, String)>) {
    let mut cases = Vec::new();
    let mut others = Vec::new();
    let mut fence: Option<String> = None;
    for (k, line) in text.lines().enumerate() {
        let n = k + 1;
        if let Some(info) = line.strip_prefix("```") {
            fence = if fence.is_some() { None } else { Some(info.trim().to_string()) };
            continue;
        }
        match fence.as_deref() {
            Some("console") => {
                if let Some(cmd) = line.strip_prefix("$ ") {
                    cases.push(Case { line: n, command: cmd.to_string(), expected: Vec::new() });
                } else if let Some(c) = cases.last_mut() {
                    c.expected.push(line.to_string());
                }
            }
            Some(info) => {
                let t = line.trim_start();
                let shown = t.strip_prefix("$ ").unwrap_or(t);
                if (info == "sh" || info == "console" || t.starts_with("$ ")) && shown.starts_with("gmap") {
                    others.push((n, shown.to_string()));
                }
            }
            None => {
                if let Some(t) = line.strip_prefix("    ") {
                    let t = t.trim();
                    if ["gmap ", "cargo ", "scripts/", "python3 "].iter().any(|p| t.starts_with(p)) {
                        others.push((n, t.to_string()));
                    }
                }
            }
        }
    }
    for c in &mut cases {
        while c.expected.last().is_some_and(|l| l.trim().is_empty()) {
            c.expected.pop();
        }
    }
    (cases, others)
}

/// Whether `line` matches `pattern`, where `[..]` matches any text.
fn line_matches(pattern: &str, line: &str) -> bool {
    let parts: Vec<&str> = pattern.split("[..]").collect();
    if parts.len() == 1 {
        return pattern == line;
    }
    let Some(mut rest) = line.strip_prefix(parts[0]) else { return false };
    for (i, p) in parts.iter().enumerate().skip(1) {
        if i == parts.len() - 1 {
            return rest.ends_with(p);
        }
        match rest.find(p) {
            Some(at) => rest = &rest[at + p.len()..],
            None => return false,
        }
    }
    true
}

/// Whether the lines match the expected ones, `...` standing for any number of lines.
fn lines_match(expected: &[String], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((e, rest)) if e.trim() == "..." => (0..=actual.len()).any(|k| lines_match(rest, &actual[k..])),
        Some((e, rest)) => actual.first().is_some_and(|a| line_matches(e, a)) && lines_match(rest, &actual[1..]),
    }
}

/// Splits a command line into words: spaces separate, single and double quotes group.
fn words(cmd: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quote: Option<char> = None;
    let mut any = false;
    for ch in cmd.chars() {
        match (quote, ch) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => cur.push(c),
            (None, '\'' | '"') => {
                quote = Some(ch);
                any = true;
            }
            (None, ' ') => {
                if any || !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
                any = false;
            }
            (None, c) => cur.push(c),
        }
    }
    if any || !cur.is_empty() {
        out.push(cur);
    }
    out
}

fn is_synopsis(line: &str) -> bool {
    line.contains('[')
        || line.contains(" | ")
        || line.split_whitespace().any(|w| ["FILE", "IN", "OUT", "DIR", "FILE|DIR...", "OUT_DIR"].contains(&w))
}

#[test]
fn every_command_in_the_docs_runs_as_shown() {
    let work = tempfile::tempdir().unwrap();
    for d in ["tests", "docs", "examples"] {
        #[cfg(unix)]
        std::os::unix::fs::symlink(root().join(d), work.path().join(d)).unwrap();
    }
    let mut failures = Vec::new();
    let mut ran = 0;
    let mut shown = Vec::new();
    let mut run_somewhere = std::collections::BTreeSet::new();
    for file in doc_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        let name = file.strip_prefix(root()).unwrap_or(&file).display().to_string();
        let (cases, others) = parse(&text);
        shown.extend(others.into_iter().map(|(line, cmd)| (name.clone(), line, cmd)));
        for c in cases {
            run_somewhere.insert(c.command.clone());
            let w = words(&c.command);
            if w.first().map(String::as_str) != Some("gmap") {
                failures.push(format!("{name}:{}: `{}` is not a gmap command", c.line, c.command));
                continue;
            }
            let out = Command::new(env!("CARGO_BIN_EXE_gmap")).args(&w[1..]).current_dir(work.path()).output().unwrap();
            ran += 1;
            let mut actual = String::from_utf8_lossy(&out.stdout).into_owned();
            actual.push_str(&String::from_utf8_lossy(&out.stderr));
            let mut lines: Vec<&str> = actual.lines().collect();
            let code = format!("? {}", out.status.code().unwrap_or(-1));
            if !out.status.success() {
                lines.insert(0, &code);
            }
            while lines.last().is_some_and(|l| l.trim().is_empty()) {
                lines.pop();
            }
            if !lines_match(&c.expected, &lines) {
                failures.push(format!(
                    "{name}:{}: $ {}\n--- expected\n{}\n--- actual\n{}",
                    c.line,
                    c.command,
                    c.expected.join("\n"),
                    lines.join("\n")
                ));
            }
        }
    }
    for (name, line, cmd) in shown {
        if is_synopsis(&cmd) || run_somewhere.contains(&cmd) || NOT_RUN.iter().any(|(c, _)| cmd.starts_with(c)) {
            continue;
        }
        failures.push(format!(
            "{name}:{line}: `{cmd}` is shown but not run: put it in a ```console block with its output, or in NOT_RUN with the reason"
        ));
    }
    assert!(failures.is_empty(), "{} mismatches:\n\n{}", failures.len(), failures.join("\n\n"));
    assert!(ran >= 8, "only {ran} commands found");
}

/// The `gmap …` commands written in prose as inline code spans (`` `gmap homology FILE
/// --generators` ``, also across a line break), outside fenced blocks: (line, text).
fn inline_commands(text: &str) -> Vec<(usize, String)> {
    // the prose: fenced lines blanked, so that backticks pair up across lines
    let mut fenced = false;
    let prose: Vec<&str> = text
        .lines()
        .map(|line| {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
                ""
            } else if fenced {
                ""
            } else {
                line
            }
        })
        .collect();
    let prose = prose.join("\n");
    let mut out = Vec::new();
    let mut line = 1;
    // the odd pieces between single backticks are code
    for (k, piece) in prose.split('`').enumerate() {
        let span = piece.split_whitespace().collect::<Vec<_>>().join(" ");
        if k % 2 == 1 && span.starts_with("gmap ") {
            out.push((line, span));
        }
        line += piece.matches('\n').count();
    }
    out
}

/// The options and subcommands a `--help` text lists: its words that start with `-`, and
/// the first word of each line under `Commands:`.
fn help_words(help: &str) -> (std::collections::BTreeSet<String>, std::collections::BTreeSet<String>) {
    let mut flags = std::collections::BTreeSet::new();
    let mut commands = std::collections::BTreeSet::new();
    let mut in_commands = false;
    for line in help.lines() {
        if line.ends_with(':') && !line.starts_with(' ') {
            in_commands = line == "Commands:";
            continue;
        }
        if in_commands {
            if let Some(w) = line.split_whitespace().next() {
                commands.insert(w.to_string());
            }
        }
        for w in line.split_whitespace() {
            let w = w.trim_end_matches(',');
            let w = w.split(['=', '[', '<']).next().unwrap_or(w);
            if w.starts_with('-') && w.len() > 1 {
                flags.insert(w.to_string());
            }
        }
    }
    (flags, commands)
}

/// Why an inline `gmap …` command does not parse: an unknown subcommand, or a flag its
/// subcommand does not take. `help` runs `gmap ARGS… --help` (cached by the caller).
fn check_inline(cmd: &str, help: &mut dyn FnMut(&[String]) -> String) -> Option<String> {
    let w = words(cmd);
    // a message or a file's line that starts with the word (`gmap bench: [2/5] FILE`,
    // `gmap <n> <darts>`), not a command
    let command_like = |s: &str| s.starts_with('-') || s.chars().all(|c| c.is_ascii_lowercase() || c == '-');
    if w.first().map(String::as_str) != Some("gmap") || !w.get(1).is_some_and(|s| command_like(s)) {
        return None;
    }
    let (root_flags, root_commands) = help_words(&help(&[]));
    let mut path: Vec<String> = Vec::new();
    let mut commands = root_commands;
    let mut flags = root_flags.clone();
    for word in &w[1..] {
        if word.starts_with('-') {
            let flag = word.trim_matches(|c| "[]()|.…,;:".contains(c));
            let flag = flag.split('=').next().unwrap_or(flag);
            if flag.len() > 1 && !flags.contains(flag) && !root_flags.contains(flag) {
                return Some(format!("`{flag}` is not an option of `gmap {}`", path.join(" ")));
            }
            continue;
        }
        if commands.is_empty() || !word.starts_with(|c: char| c.is_ascii_alphanumeric()) {
            continue;
        }
        if !commands.contains(word.as_str()) {
            if path.is_empty() {
                return Some(format!("`{word}` is not a gmap subcommand"));
            }
            // the subcommand's own subcommands are optional; the rest are arguments
            commands.clear();
            continue;
        }
        path.push(word.clone());
        (flags, commands) = help_words(&help(&path));
    }
    None
}

#[test]
fn inline_commands_name_real_subcommands_and_options() {
    let mut cache: std::collections::HashMap<Vec<String>, String> = std::collections::HashMap::new();
    let mut help = |path: &[String]| {
        cache
            .entry(path.to_vec())
            .or_insert_with(|| {
                let out = Command::new(env!("CARGO_BIN_EXE_gmap")).args(path).arg("--help").output().unwrap();
                String::from_utf8_lossy(&out.stdout).into_owned()
            })
            .clone()
    };
    let mut failures = Vec::new();
    let mut checked = 0;
    for file in doc_files() {
        let text = std::fs::read_to_string(&file).unwrap();
        let name = file.strip_prefix(root()).unwrap_or(&file).display().to_string();
        let (_, others) = parse(&text);
        for (line, cmd) in inline_commands(&text).into_iter().chain(others) {
            if !cmd.starts_with("gmap ") {
                continue;
            }
            checked += 1;
            if let Some(why) = check_inline(&cmd, &mut help) {
                failures.push(format!("{name}:{line}: `{cmd}`: {why}"));
            }
        }
    }
    assert!(failures.is_empty(), "{} commands in the prose do not parse:\n{}", failures.len(), failures.join("\n"));
    assert!(checked >= 20, "only {checked} inline commands found");
    // the checker refuses what it should
    assert!(check_inline("gmap homologie FILE", &mut help).is_some());
    assert!(check_inline("gmap homology FILE --generator", &mut help).is_some());
    assert!(check_inline("gmap info FILE --generators", &mut help).is_some());
    assert!(check_inline("gmap tm check FILE --cell 3", &mut help).is_some());
    assert_eq!(check_inline("gmap bench: [2/5] FILE", &mut help), None);
    assert_eq!(check_inline("gmap homology FILE [--generators] --max-memory 1G -q", &mut help), None);
    assert_eq!(check_inline("gmap tm views FILE --cell 3", &mut help), None);
}

#[test]
fn the_matcher_reads_ellipses_and_wildcards() {
    let e: Vec<String> = ["a", "...", "c [..] e"].iter().map(|s| s.to_string()).collect();
    assert!(lines_match(&e, &["a", "b", "b", "c d e"]));
    assert!(lines_match(&e, &["a", "c  e"]));
    assert!(!lines_match(&e, &["a", "c d f"]));
    assert!(!lines_match(&e, &["x", "c d e"]));
    assert_eq!(words(r#"gmap homology 'a b.lex#x' --json"#), ["gmap", "homology", "a b.lex#x", "--json"]);
    assert!(is_synopsis("gmap info FILE [--json]"));
    assert!(!is_synopsis("gmap info tests/data/rp2.facets"));
    let _ = Path::new("");
}

#[test]
fn help_lists_every_input_format() {
    for cmd in ["info", "homology", "convert"] {
        let out = Command::new(env!("CARGO_BIN_EXE_gmap")).args([cmd, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&out.stdout);
        for ext in gmap::formats::input_extensions() {
            assert!(help.contains(&format!(".{ext}")), "gmap {cmd} --help does not name .{ext}:\n{help}");
        }
    }
}
