//! Every route of an input, timed by stage (`gmap bench`, and what a benchmark of the
//! library calls).
//!
//! Each route that [`crate::homology`] has for an input is run and timed: for a simplicial
//! complex the direct route (every face of every facet a cell), then the two routes of its
//! G-map, which say why they do not apply when the complex has none; for a G-map the cellular
//! route (cells and the C1/C2 checks, border operator, reduction, Smith form) and the
//! simplicial counterpart; for a cubical set the one-pass route (dimension ≤ 3), the cubical
//! complex reduced slab by slab and the whole cubical complex; for an architectural
//! complex the completion by zero of its boundary matrix. A route that does not apply gives a
//! run with its reason, and so does one whose estimated memory is over the policy
//! (`gmap_core::resources`): it is skipped before anything is allocated.
//!
//! **Peak memory per row.** Each row carries the peak resident memory of the process while
//! it ran ([`RouteRun::peak_rss`]): the kernel's high-water mark (`VmHWM`) is reset to the
//! resident memory of now through `/proc/self/clear_refs` before the file is read and again
//! after each row, and read when the row ends. A row's peak therefore counts what the process
//! already held (the program, the input as read, for the first row its reading too) and what
//! the route added on top; routes run one after the other in the calling process. Where the
//! reset is refused (no `/proc`, a sandbox) the field is `None` rather than the peak of the
//! whole process so far.

use std::path::{Path, PathBuf};
use std::time::Instant;

use gmap_homology::border::border_from_oriented;
use gmap_homology::{check_preconditions, homology_z_staged, simplicial_complex, ChainComplex, Homology};
use serde_json::{json, Value};

use gmap_core::DenseMap;
use gmap_ops::import::Level;

use crate::chains::{check_simplicial_size, face_complex_within};
use crate::cubes::Cubes;
use crate::error::{err, Result};
use crate::input::{Input, OpenOptions};
use crate::open_with;
use crate::options::Method;
use crate::progress::Progress;
use crate::route::Route;

/// Stage times of one route, in milliseconds; `None` for a stage the route does not have.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Times {
    /// reading the file (and making the G-map of a simplicial complex)
    pub read: f64,
    /// the cells and the C1/C2 checks
    pub cells: Option<f64>,
    /// the border operator (or the chain complex of the route)
    pub border: Option<f64>,
    /// the fill-free reduction and the sparse elimination
    pub reduction: Option<f64>,
    /// the Smith normal form of what is left
    pub smith: Option<f64>,
}

impl Times {
    /// The sum of the stages.
    pub fn total(&self) -> f64 {
        self.read
            + self.cells.unwrap_or(0.0)
            + self.border.unwrap_or(0.0)
            + self.reduction.unwrap_or(0.0)
            + self.smith.unwrap_or(0.0)
    }
}

/// One route of one input, run and timed.
#[derive(Clone, Debug)]
pub struct RouteRun {
    /// the input as named
    pub input: String,
    /// `direct`, `cellular`, `simplicial`, `one-pass` (a cubical set of dimension ≤ 3),
    /// `slabs`, `cubical`, or `read` for an input that could not be read
    pub route: &'static str,
    /// cells per dimension of the chain complex reduced (empty when the route failed first)
    pub cells: Vec<usize>,
    /// the stage times
    pub times: Times,
    /// the groups, or why the route does not apply
    pub result: std::result::Result<Homology, String>,
    /// whether every route that applies to this input gives the same groups
    pub agree: bool,
    /// the peak resident memory of the process while the row ran, in bytes (see the
    /// [module docs](self)); `None` where the high-water mark cannot be reset or read
    pub peak_rss: Option<u64>,
}

/// The high-water mark of resident memory, row by row.
struct PeakMark {
    resettable: bool,
}

impl PeakMark {
    /// Resets the mark: what follows is measured from now.
    fn start() -> Self {
        PeakMark { resettable: gmap_core::resources::reset_peak_rss() }
    }

    /// The peak since the last reset, then a reset for the next row.
    fn row(&self) -> Option<u64> {
        if !self.resettable {
            return None;
        }
        let peak = gmap_core::resources::peak_rss();
        gmap_core::resources::reset_peak_rss();
        peak
    }
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1000.0
}

/// A `.txt` file that does not open as a Perseus file does (its first line a lone
/// dimension): a folder's notes and read-me files, left out of a folder's listing.
fn plain_text(f: &std::path::Path) -> bool {
    let txt = f.extension().is_some_and(|e| e.eq_ignore_ascii_case("txt"));
    let mut head = [0u8; 64];
    let n = std::fs::File::open(f).and_then(|mut h| std::io::Read::read(&mut h, &mut head)).unwrap_or(0);
    let first = String::from_utf8_lossy(&head[..n]).lines().next().unwrap_or("").trim().to_string();
    txt && first.parse::<u32>().is_err()
}

/// The files named by `inputs`: a file as given, a folder as its supported files sorted by
/// name (not recursive; a `.txt` only when it starts as a Perseus file), each with whether
/// it was found in a folder. A folder with no
/// supported file is an error.
pub fn expand_inputs(inputs: &[PathBuf]) -> Result<Vec<(PathBuf, bool)>> {
    let mut files = Vec::new();
    for p in inputs {
        if p.is_dir() {
            let mut found: Vec<PathBuf> = std::fs::read_dir(p)
                .map_err(|e| {
                    crate::Error::from_source(crate::ErrorKind::Parse, e)
                        .context(format!("{}: cannot read the folder", p.display()))
                })?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| f.is_file() && crate::formats::kind_of(f).is_some() && !plain_text(f))
                .collect();
            if found.is_empty() {
                return Err(err!(
                    Parse,
                    "{}: the folder holds no supported input ({})",
                    p.display(),
                    crate::formats::input_extensions().collect::<Vec<_>>().join(", ")
                ));
            }
            found.sort();
            files.extend(found.into_iter().map(|f| (f, true)));
        } else {
            files.push((p.clone(), false));
        }
    }
    Ok(files)
}

/// The runs of every input (files, or folders of them): a file found in a folder that
/// cannot be read is a run with route `read` and the reason; one named is an error.
pub fn bench(inputs: &[PathBuf], max_darts: Option<u64>, progress: &Progress) -> Result<Vec<RouteRun>> {
    bench_with(inputs, &BenchOptions { max_darts, max_cells: max_darts, periodic: false }, progress)
}

/// The limits and options of [`bench_with`] (`gmap bench`'s flags).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct BenchOptions {
    /// refuse maps of more darts than this
    pub max_darts: Option<u64>,
    /// the direct route: refuse more faces than this (default: what the memory budget holds)
    pub max_cells: Option<u64>,
    /// cubical sets: identify the opposite faces of the box (the torus)
    pub periodic: bool,
}

impl BenchOptions {
    /// The options of `gmap bench`'s flags.
    pub fn new(max_darts: Option<u64>, max_cells: Option<u64>, periodic: bool) -> Self {
        BenchOptions { max_darts, max_cells, periodic }
    }
}

/// [`bench()`] with its options.
pub fn bench_with(inputs: &[PathBuf], o: &BenchOptions, progress: &Progress) -> Result<Vec<RouteRun>> {
    let listed = expand_inputs(inputs)?;
    progress.steps(listed.len() as u64, "");
    let mut runs = Vec::new();
    for (f, in_folder) in &listed {
        progress.step(&f.display().to_string());
        let mark = PeakMark::start();
        match bench_file_from(f, o, &mark) {
            Ok(r) => runs.extend(r),
            Err(e) if *in_folder => runs.push(RouteRun {
                input: f.display().to_string(),
                route: "read",
                cells: Vec::new(),
                times: Times::default(),
                result: Err(format!("cannot read: {e}")),
                agree: true,
                peak_rss: mark.row(),
            }),
            Err(e) => return Err(e),
        }
    }
    Ok(runs)
}

/// The runs of one file: reading it timed, then [`routes`].
pub fn bench_file(path: &Path, max_darts: Option<u64>) -> Result<Vec<RouteRun>> {
    let o = BenchOptions { max_darts, max_cells: max_darts, periodic: false };
    bench_file_from(path, &o, &PeakMark::start())
}

fn bench_file_from(path: &Path, o: &BenchOptions, mark: &PeakMark) -> Result<Vec<RouteRun>> {
    let t = Instant::now();
    let input = open_with(path, &OpenOptions::max_darts(o.max_darts))?;
    let read = ms(t);
    routes_timed(&input, read, o, mark)
}

/// Every route of an input, run and timed (reading not included). A simplicial complex
/// whose faces are over `max_darts` is an error (its direct route is where its groups come
/// from); a route that does not apply is a run with the reason.
pub fn routes(input: &Input, max_darts: Option<u64>) -> Result<Vec<RouteRun>> {
    let o = BenchOptions { max_darts, max_cells: max_darts, periodic: false };
    routes_timed(input, 0.0, &o, &PeakMark::start())
}

fn routes_timed(input: &Input, read: f64, o: &BenchOptions, mark: &PeakMark) -> Result<Vec<RouteRun>> {
    let name = input.path().display().to_string();
    let mut runs = Vec::new();
    // a simplicial complex's G-map, made once for both of its map routes (timed as reading)
    let mut gmap: Option<(f64, std::result::Result<DenseMap, String>)> = None;
    for route in crate::route::candidates(input, o.periodic) {
        let row = match (route, input) {
            (Route::Gmap(method), Input::Simplicial(sc)) => {
                let (map_read, map) = gmap.get_or_insert_with(|| {
                    let t = Instant::now();
                    // a G-map that pulls a face apart is another space: its routes do not apply
                    let m = sc.to_gmap_within(o.max_darts).and_then(|m| {
                        crate::pinch::check_route(sc, &m, &name)?;
                        Ok(m)
                    });
                    let m = m.map_err(|e| format!("does not apply: {e}"));
                    (read + ms(t), m)
                });
                match map {
                    Ok(map) => map_row(method, map, *map_read, &name),
                    Err(why) => Row::failed(Times { read: *map_read, ..Times::default() }, why.clone()),
                }
            }
            (Route::Cellular, Input::Map(m)) => map_row(Method::Cellular, m.map(), read, &name),
            (Route::Simplicial, Input::Map(m)) => map_row(Method::Simplicial, m.map(), read, &name),
            (Route::Direct, Input::Simplicial(sc)) => {
                let mut times = Times { read, ..Times::default() };
                let t = Instant::now();
                // the direct route is where a complex's groups come from: its refusal is an error
                let fc = face_complex_within(sc, o.max_cells, &name, false)?;
                times.border = Some(ms(t));
                Row::reduced(&fc.chain, times)
            }
            (Route::Arch, Input::Arch(x)) => {
                let mut times = Times { read, ..Times::default() };
                let t = Instant::now();
                let c = x.chain_complex();
                times.border = Some(ms(t));
                Row::reduced(&c, times)
            }
            (route, Input::Cubical(set)) => cubical_row(route, Cubes::Set(set), read, o.periodic)?,
            (route, Input::Image(img)) => cubical_row(route, Cubes::Image(img, Level::Nonzero), read, o.periodic)?,
            (route, _) => Row::failed(Times { read, ..Times::default() }, format!("{} does not apply", route.name())),
        };
        runs.push(row.into_run(&name, route, mark.row()));
    }
    let ok: Vec<&Homology> = runs.iter().filter_map(|r| r.result.as_ref().ok()).collect();
    let agree = ok.windows(2).all(|w| w[0] == w[1]);
    for r in &mut runs {
        r.agree = agree;
    }
    Ok(runs)
}

/// One route's figures: the cells reduced, the stage times, the groups or why not.
struct Row {
    cells: Vec<usize>,
    times: Times,
    result: std::result::Result<Homology, String>,
}

impl Row {
    /// The table's row of `route` on input `name`: a simplicial complex's G-map routes named
    /// by their method, an architectural complex's as `cellular` (its cells are its regions).
    fn into_run(self, name: &str, route: Route, peak_rss: Option<u64>) -> RouteRun {
        let route = match route {
            Route::Gmap(method) => method.name(),
            Route::Arch => "cellular",
            route => route.name(),
        };
        let (cells, times, result) = (self.cells, self.times, self.result);
        RouteRun { input: name.to_string(), route, cells, times, result, agree: true, peak_rss }
    }

    fn failed(times: Times, why: String) -> Self {
        Row { cells: Vec::new(), times, result: Err(why) }
    }

    /// The chain complex `c` reduced, its stages timed into `times`.
    fn reduced(c: &ChainComplex, mut times: Times) -> Self {
        let (cells, result) = reduce(c, &mut times);
        Row { cells, times, result }
    }
}

/// A map's route: cellular (cells and C1/C2 checks, border, reduction) or its simplicial
/// counterpart, one n-simplex per dart, within the memory policy (its size is exponential
/// in the dimension).
fn map_row(method: Method, map: &DenseMap, read: f64, name: &str) -> Row {
    let mut times = Times { read, ..Times::default() };
    match method {
        Method::Cellular => {
            let t = Instant::now();
            let checked = check_preconditions(map);
            times.cells = Some(ms(t));
            match checked {
                Ok(oriented) => {
                    let t = Instant::now();
                    let c = border_from_oriented(map, &oriented);
                    times.border = Some(ms(t));
                    drop(oriented);
                    Row::reduced(&c.chain, times)
                }
                Err(e) => Row { cells: map.cell_counts(), times, result: Err(format!("does not apply: {e}")) },
            }
        }
        Method::Simplicial => match check_simplicial_size(map, name) {
            Ok(()) => {
                let t = Instant::now();
                let s = simplicial_complex(map);
                times.border = Some(ms(t));
                Row::reduced(&s, times)
            }
            Err(e) => Row::failed(times, format!("skipped: {e}")),
        },
    }
}

/// A cubical route of a cubical input: the one pass (dimension ≤ 3), the cubical complex
/// built and reduced slab by slab (read in memory order), or the whole cubical complex of
/// the closure after collapses of free faces (an image made a bitmap first, timed as
/// reading; a set's own lower cells marked on the grid).
fn cubical_row(route: Route, cubes: Cubes<'_>, read: f64, periodic: bool) -> Result<Row> {
    let shape = cubes.shape();
    let mut times = Times { read, ..Times::default() };
    let t = Instant::now();
    Ok(match route {
        Route::OnePass => {
            let r = gmap_homology::cubical::pass::betti_one_pass(&shape, |s, out| cubes.fill(s, out));
            times.reduction = Some(ms(t));
            let r = r.map(|p| Homology {
                coefficients: gmap_homology::homology::Coefficients::Integers,
                betti: p.betti.iter().map(|&b| usize::try_from(b).unwrap_or(usize::MAX)).collect(),
                torsion: vec![Vec::new(); shape.len() + 1],
            });
            Row { cells: Vec::new(), times, result: r.map_err(|e| e.to_string()) }
        }
        Route::Cubical { whole: false } => {
            let slab = crate::cubes::slab_layers(&shape);
            let c = gmap_homology::cubical::slabs::cubical_complex_slabs(
                &shape,
                |s, out| cubes.fill(s, out),
                periodic,
                slab,
                false,
            );
            times.border = Some(ms(t));
            match c {
                Ok(c) => {
                    let mut row = Row::reduced(&c.complex.chain, times);
                    row.result = row.result.and_then(|h| c.absolute(h).map_err(|e| e.to_string()));
                    row
                }
                Err(e) => Row::failed(times, e.to_string()),
            }
        }
        _ => whole_cubical_row(cubes, times, periodic)?,
    })
}

/// The row of the whole cubical complex of the closure of the cubes (and lower cells) after
/// collapses of free faces.
fn whole_cubical_row(cubes: Cubes<'_>, mut times: Times, periodic: bool) -> Result<Row> {
    let t = Instant::now();
    let image_set;
    let set = match cubes {
        Cubes::Image(img, level) => {
            image_set = img.to_cubical_set(level).map_err(|e| crate::Error::from_source(crate::ErrorKind::Limit, e))?;
            times.read += ms(t);
            &image_set
        }
        Cubes::Set(set) => set,
        Cubes::Borrowed(_) => return Ok(Row::failed(times, "cubes in memory are not benched".to_string())),
    };
    let t = Instant::now();
    let cells = set.lower_cells_in_box();
    let c = gmap_homology::cubical::cubical_cell_complex_with(set.shape(), set.bits(), &cells, periodic, true);
    times.border = Some(ms(t));
    Ok(match c {
        Ok(c) => Row::reduced(&c.chain, times),
        Err(e) => Row::failed(times, e.to_string()),
    })
}

/// Integer homology of `c`, its sparse reduction and its Smith form timed apart.
fn reduce(c: &ChainComplex, times: &mut Times) -> (Vec<usize>, std::result::Result<Homology, String>) {
    let (h, stages) = homology_z_staged(c);
    times.reduction = Some(stages.reduction.as_secs_f64() * 1e3);
    times.smith = Some(stages.smith.as_secs_f64() * 1e3);
    (c.counts().to_vec(), h.map_err(|e| e.to_string()))
}

fn groups(r: &RouteRun) -> String {
    match &r.result {
        Ok(h) => h.to_string(),
        Err(e) => format!("n/a: {e}"),
    }
}

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, |v| json!(v))
}

fn cells_text(r: &RouteRun) -> String {
    r.cells.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ")
}

/// The runs as one JSON object `{"rows": [...]}`.
pub fn to_json(runs: &[RouteRun]) -> Value {
    let list: Vec<Value> = runs
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
                "peak_rss_bytes": r.peak_rss,
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
    json!({ "rows": list })
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

/// The runs as CSV: a header line, then one line per run.
pub fn to_csv(runs: &[RouteRun]) -> String {
    let mut out = String::from(
        "input,route,cells,read_ms,cells_ms,border_ms,reduction_ms,smith_ms,total_ms,groups,betti,torsion,agree,peak_rss_bytes\n",
    );
    for r in runs {
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
            r.peak_rss.map_or(String::new(), |b| b.to_string()),
        ];
        let line: Vec<String> = fields.iter().map(|f| csv_field(f)).collect();
        out.push_str(&line.join(","));
        out.push('\n');
    }
    out
}

/// The runs as a Markdown table.
pub fn to_markdown(runs: &[RouteRun]) -> String {
    use std::fmt::Write as _;
    let dash = |x: Option<f64>| x.map_or("–".to_string(), |v| format!("{v:.2}"));
    let mut out = String::from(
        "| input | route | cells | read ms | cells+checks ms | border ms | reduction ms | Smith ms | total ms | homology | agree | peak RSS MB |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|---|---|---:|\n",
    );
    for r in runs {
        let _ = writeln!(
            out,
            "| {} | {} | {} | {:.2} | {} | {} | {} | {} | {:.2} | {} | {} | {} |",
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
            r.peak_rss.map_or("–".to_string(), |b| format!("{:.1}", b as f64 / (1 << 20) as f64)),
        );
    }
    out
}
