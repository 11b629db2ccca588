//! `gmap bench FILE|DIR... [--json|--csv] [--max-darts N] [--no-gudhi]`: homology
//! benchmarking (docs/FORMATS.md §1, `gmap bench`).
//!
//! Each input (a folder stands for its supported files, sorted) is read once, then each route
//! that `gmap homology` has for it is run and timed by stage: for a simplicial complex
//! (`.facets`, `.lex`) the direct route (every face of every facet a cell), then the two
//! routes of its G-map, which say why they do not apply when the complex has none; for a
//! G-map the cellular route
//! (cells and the C1/C2 checks, border operator, reduction) and the simplicial counterpart
//! (building the complex, reduction); for an architectural complex (`.json`) the completion
//! by zero of its boundary matrix. A route that does not apply gives a row with its reason,
//! and so does one whose estimated memory is over the policy (`--max-memory`,
//! `gmap_core::resources`): it is skipped before anything is allocated.
//! Rows are gathered first and printed at the end: an unreadable input ends the command with
//! `error: …` and exit code 1 before anything is printed on stdout.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use gmap_homology::border::border_from_oriented;
use gmap_homology::{check_preconditions, homology_z_staged, simplicial_complex, ChainComplex, Homology};
use serde_json::{json, Value};

use super::load::{extension, face_complex_within, load, load_simplicial, Loaded, INPUT_EXTENSIONS};

/// The output shape of `gmap bench`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Markdown,
    Json,
    Csv,
}

/// Options of `gmap bench`.
pub struct Options {
    pub inputs: Vec<PathBuf>,
    pub format: Format,
    pub max_darts: Option<u64>,
    pub gudhi: bool,
}

/// The Python of the GUDHI column, run as `python3 -c SCRIPT FILE.facets...`.
const GUDHI_SCRIPT: &str = include_str!("../../benches/anchors/bench_gudhi.py");

/// Stage times of one route, in milliseconds; `None` for a stage the route does not have.
#[derive(Clone, Debug, Default)]
struct Times {
    read: f64,
    cells: Option<f64>,
    border: Option<f64>,
    reduction: Option<f64>,
    smith: Option<f64>,
}

impl Times {
    fn total(&self) -> f64 {
        self.read
            + self.cells.unwrap_or(0.0)
            + self.border.unwrap_or(0.0)
            + self.reduction.unwrap_or(0.0)
            + self.smith.unwrap_or(0.0)
    }
}

/// One row: an input and a route.
struct Row {
    input: String,
    route: &'static str,
    /// cells per dimension of the chain complex reduced (empty when the route failed first)
    cells: Vec<usize>,
    times: Times,
    result: Result<Homology, String>,
    /// whether every route that applies to this input gives the same groups
    agree: bool,
    gudhi_ms: Option<f64>,
}

impl Row {
    fn ratio(&self) -> Option<f64> {
        self.gudhi_ms.filter(|&g| g > 0.0).map(|g| self.times.total() / g)
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1000.0
}

/// Progress on stderr, only when it is a terminal.
fn progress(msg: &str) {
    if std::io::stderr().is_terminal() {
        eprintln!("gmap bench: {msg}");
    }
}

/// The files named by the inputs: a file as given, a folder as its supported files sorted by
/// name (not recursive), each with whether it was found in a folder. A folder with no
/// supported file is an error.
fn expand(inputs: &[PathBuf]) -> Result<Vec<(PathBuf, bool)>> {
    let mut files = Vec::new();
    for p in inputs {
        if p.is_dir() {
            let mut found: Vec<PathBuf> = std::fs::read_dir(p)
                .with_context(|| format!("{}: cannot read the folder", p.display()))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| f.is_file() && INPUT_EXTENSIONS.contains(&extension(f).as_str()))
                .collect();
            if found.is_empty() {
                bail!("{}: the folder holds no supported input ({})", p.display(), INPUT_EXTENSIONS.join(", "));
            }
            found.sort();
            files.extend(found.into_iter().map(|f| (f, true)));
        } else {
            files.push((p.clone(), false));
        }
    }
    Ok(files)
}

/// Runs `gmap bench`.
pub fn run(o: &Options) -> Result<()> {
    let listed = expand(&o.inputs)?;
    let mut rows = Vec::new();
    for (k, (f, in_folder)) in listed.iter().enumerate() {
        progress(&format!("[{}/{}] {}", k + 1, listed.len(), f.display()));
        match bench_one(f, o.max_darts) {
            Ok(r) => rows.extend(r),
            // a file found in a folder that cannot be read is a row; one named is an error
            Err(e) if *in_folder => rows.push(Row {
                input: f.display().to_string(),
                route: "read",
                cells: Vec::new(),
                times: Times::default(),
                result: Err(format!("cannot read: {}", super::error_message(&e))),
                agree: true,
                gudhi_ms: None,
            }),
            Err(e) => return Err(e),
        }
    }
    let files: Vec<PathBuf> = listed.into_iter().map(|(f, _)| f).collect();
    if o.gudhi {
        add_gudhi(&mut rows, &files);
    }
    match o.format {
        Format::Json => print_json(&rows),
        Format::Csv => print_csv(&rows),
        Format::Markdown => print_markdown(&rows),
    }
}

/// The rows of one input, one per route.
fn bench_one(path: &Path, max_darts: Option<u64>) -> Result<Vec<Row>> {
    let input = path.display().to_string();
    let mut rows = Vec::new();
    let row = |route, cells: Vec<usize>, times, result| Row {
        input: input.clone(),
        route,
        cells,
        times,
        result,
        agree: true,
        gudhi_ms: None,
    };
    // a simplicial complex: the direct route first (every face of every facet a cell, as
    // `gmap homology` does by default); it applies to any complex, so a complex that has no
    // G-map still gets its groups, and the two G-map routes say why they do not apply
    let simplicial = if matches!(extension(path).as_str(), "facets" | "lex") {
        let t = Instant::now();
        let sc = load_simplicial(path)?.with_context(|| format!("{input}: not a simplicial complex"))?;
        let mut times = Times { read: ms(t), ..Times::default() };
        let t = Instant::now();
        let fc = face_complex_within(&sc, max_darts, &input, false)?;
        times.border = Some(ms(t));
        let (cells, r) = reduce(&fc.chain, &mut times);
        rows.push(row("direct", cells, times, r));
        true
    } else {
        false
    };
    let t = Instant::now();
    let loaded = match load(path, max_darts) {
        Ok(loaded) => loaded,
        Err(e) if simplicial => {
            let why = format!("does not apply: {}", super::error_message(&e));
            let times = Times { read: ms(t), ..Times::default() };
            rows.push(row("cellular", Vec::new(), times.clone(), Err(why.clone())));
            rows.push(row("simplicial", Vec::new(), times, Err(why)));
            return Ok(rows);
        }
        Err(e) => return Err(e),
    };
    let read = ms(t);
    match loaded {
        Loaded::Map(map) => {
            // cellular: cells and C1/C2 checks, border, reduction
            let mut times = Times { read, ..Times::default() };
            let t = Instant::now();
            let checked = check_preconditions(&map);
            times.cells = Some(ms(t));
            match checked {
                Ok(oriented) => {
                    let t = Instant::now();
                    let c = border_from_oriented(&map, &oriented);
                    times.border = Some(ms(t));
                    drop(oriented);
                    let (cells, r) = reduce(&c.chain, &mut times);
                    rows.push(row("cellular", cells, times, r));
                }
                Err(e) => {
                    let cells = map.cell_counts();
                    rows.push(row("cellular", cells, times, Err(format!("does not apply: {e}"))));
                }
            }
            // simplicial counterpart: one n-simplex per dart, within the memory policy (its size
            // is exponential in the dimension: a 5-map of 2.6 M darts would ask for 166 M simplices)
            let mut times = Times { read, ..Times::default() };
            match super::homology::check_simplicial_size(&map, &input) {
                Ok(()) => {
                    let t = Instant::now();
                    let s = simplicial_complex(&map);
                    times.border = Some(ms(t));
                    let (cells, r) = reduce(&s, &mut times);
                    rows.push(row("simplicial", cells, times, r));
                }
                Err(e) => {
                    let why = format!("skipped: {}", super::error_message(&e));
                    rows.push(row("simplicial", Vec::new(), times, Err(why)));
                }
            }
        }
        Loaded::Cubical(set) => {
            // the cubical complex of the closure, after collapses of free faces
            let mut times = Times { read, ..Times::default() };
            let t = Instant::now();
            let c = gmap_homology::cubical::cubical_complex_with(set.shape(), set.bits(), false, true);
            times.border = Some(ms(t));
            match c {
                Ok(c) => {
                    let (cells, r) = reduce(&c.chain, &mut times);
                    rows.push(row("cubical", cells, times, r));
                }
                Err(e) => rows.push(row("cubical", Vec::new(), times, Err(e.to_string()))),
            }
        }
        Loaded::Complex(x) => {
            let mut times = Times { read, ..Times::default() };
            let t = Instant::now();
            let c = x.chain_complex();
            times.border = Some(ms(t));
            let (cells, r) = reduce(&c, &mut times);
            rows.push(row("cellular", cells, times, r));
        }
    }
    let ok: Vec<&Homology> = rows.iter().filter_map(|r| r.result.as_ref().ok()).collect();
    let agree = ok.windows(2).all(|w| w[0] == w[1]);
    for r in &mut rows {
        r.agree = agree;
    }
    Ok(rows)
}

/// Integer homology of `c`, its sparse reduction and its Smith form timed apart.
fn reduce(c: &ChainComplex, times: &mut Times) -> (Vec<usize>, Result<Homology, String>) {
    let (h, stages) = homology_z_staged(c);
    times.reduction = Some(stages.reduction.as_secs_f64() * 1e3);
    times.smith = Some(stages.smith.as_secs_f64() * 1e3);
    (c.counts().to_vec(), h.map_err(|e| e.to_string()))
}

/// Fills the GUDHI column of the direct rows of `.facets` inputs (the same simplices),
/// when `python3` can import `gudhi`; leaves it empty otherwise.
fn add_gudhi(rows: &mut [Row], files: &[PathBuf]) {
    let facets: Vec<&PathBuf> = files.iter().filter(|f| extension(f) == "facets").collect();
    if facets.is_empty() {
        return;
    }
    progress(&format!("GUDHI on {} .facets file(s)", facets.len()));
    let out = std::process::Command::new("python3")
        .arg("-c")
        .arg(GUDHI_SCRIPT)
        .args(&facets)
        .stdin(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .output();
    let Ok(out) = out else { return };
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let Ok(v) = serde_json::from_str::<Value>(line) else { continue };
        let (Some(file), Some(t)) = (v["file"].as_str(), v["ms"].as_f64()) else { continue };
        for r in rows.iter_mut().filter(|r| r.input == file && r.route == "direct") {
            r.gudhi_ms = Some(t);
        }
    }
}

fn groups(r: &Row) -> String {
    match &r.result {
        Ok(h) => h.to_string(),
        Err(e) => format!("n/a: {e}"),
    }
}

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, |v| json!(v))
}

fn print_json(rows: &[Row]) -> Result<()> {
    let list: Vec<Value> = rows
        .iter()
        .map(|r| {
            let mut v = json!({
                "input": r.input,
                "route": r.route,
                "cells": r.cells,
                "times_ms": {
                    "read": r.times.read,
                    "cells": opt(r.times.cells),
                    "border": opt(r.times.border),
                    "reduction": opt(r.times.reduction),
                    "smith": opt(r.times.smith),
                    "total": r.times.total(),
                },
                "agree": r.agree,
                "gudhi_ms": opt(r.gudhi_ms),
                "ratio": opt(r.ratio()),
            });
            match &r.result {
                Ok(h) => {
                    v["groups"] = json!(h.to_string());
                    v["betti"] = json!(h.betti);
                    v["torsion"] = json!(h.torsion);
                    v["error"] = Value::Null;
                }
                Err(e) => {
                    v["groups"] = Value::Null;
                    v["betti"] = Value::Null;
                    v["torsion"] = Value::Null;
                    v["error"] = json!(e);
                }
            }
            v
        })
        .collect();
    outln!("{}", json!({ "rows": list }))?;
    Ok(())
}

fn num(x: Option<f64>) -> String {
    x.map_or(String::new(), |v| format!("{v:.3}"))
}

/// A CSV field, quoted when it holds a comma, a quote or a line break.
fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn cells_text(r: &Row) -> String {
    r.cells.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ")
}

fn print_csv(rows: &[Row]) -> Result<()> {
    outln!(
        "input,route,cells,read_ms,cells_ms,border_ms,reduction_ms,smith_ms,total_ms,groups,betti,torsion,agree,gudhi_ms,ratio"
    )?;
    for r in rows {
        let (betti, torsion) = match &r.result {
            Ok(h) => (json!(h.betti).to_string(), json!(h.torsion).to_string()),
            Err(_) => (String::new(), String::new()),
        };
        let fields = [
            r.input.clone(),
            r.route.to_string(),
            cells_text(r),
            num(Some(r.times.read)),
            num(r.times.cells),
            num(r.times.border),
            num(r.times.reduction),
            num(r.times.smith),
            num(Some(r.times.total())),
            groups(r),
            betti,
            torsion,
            r.agree.to_string(),
            num(r.gudhi_ms),
            num(r.ratio()),
        ];
        let line: Vec<String> = fields.iter().map(|f| csv_field(f)).collect();
        outln!("{}", line.join(","))?;
    }
    Ok(())
}

fn print_markdown(rows: &[Row]) -> Result<()> {
    let dash = |x: Option<f64>| x.map_or("–".to_string(), |v| format!("{v:.2}"));
    outln!("| input | route | cells | read ms | cells+checks ms | border ms | reduction ms | Smith ms | total ms | homology | agree | GUDHI ms | ratio |")?;
    outln!("|---|---|---|---:|---:|---:|---:|---:|---:|---|---|---:|---:|")?;
    for r in rows {
        outln!(
            "| {} | {} | {} | {:.2} | {} | {} | {} | {} | {:.2} | {} | {} | {} | {} |",
            r.input.replace('|', "\\|"),
            r.route,
            cells_text(r),
            r.times.read,
            dash(r.times.cells),
            dash(r.times.border),
            dash(r.times.reduction),
            dash(r.times.smith),
            r.times.total(),
            groups(r).replace('|', "\\|"),
            if r.agree { "yes" } else { "NO" },
            dash(r.gudhi_ms),
            dash(r.ratio()),
        )?;
    }
    Ok(())
}
