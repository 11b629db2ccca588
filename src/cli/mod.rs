//! Command-line parsing and printing over the facade (`gmap::open`, `gmap::homology`,
//! `gmap::info`, `gmap::save_file`, `gmap::bench`, `gmap::view`). Nothing here chooses a route or decides
//! anything about the input: each subcommand is an argument struct, one call, and printing.
//!
//! Exit codes: 0 success, 1 bad input (one line `error: …` on stderr), 2 bad usage (clap's
//! own exit code).

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

mod curves;
mod graph;
mod persistence;
mod tm;
mod view;

/// Generalized maps: build, inspect, convert, and compute homology on the cells.
#[derive(Parser, Debug)]
#[command(name = "gmap", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
    /// the memory a command may use, in bytes with an optional K, M, G or T suffix (powers
    /// of 1024); larger estimated costs are refused. Default: half the physical memory, at
    /// most three quarters of the address-space limit (ulimit -v)
    #[arg(long, global = true, value_parser = parse_max_memory)]
    max_memory: Option<u64>,
    /// show no progress on stderr (it is shown only when stderr is a terminal)
    #[arg(long, short, global = true)]
    quiet: bool,
}

/// The help of an input file argument: every extension the registry reads.
fn input_help(what: &str) -> String {
    format!("{what} ({})", gmap::formats::input_help())
}

/// The help of `--box`: the formats of cubical sets.
fn box_help() -> String {
    format!(
        "for a cubical set ({}): its box as its first and last cubes, \"(0,0) (3,0)\" (default: the cubes' bounding box, or the file's `box` line)",
        gmap::formats::extensions_of(&[gmap::Kind::Cubical])
    )
}

fn parse_cubical_box(text: &str) -> Result<(Vec<i64>, Vec<i64>), String> {
    gmap::ops::import::parse_box(text)
}

fn parse_max_memory(text: &str) -> Result<u64, String> {
    gmap::core::resources::parse_size(text).map_err(|e| e.to_string())
}

/// Which chain complex `gmap homology` reduces.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Method {
    /// the cellular border operator (BO Def. 10), on the cells themselves
    Cellular,
    /// the simplicial counterpart (BO §6): one n-simplex per dart
    Simplicial,
}

/// Which generators `gmap homology --generators` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Generators {
    /// one cycle per summand, as the reduction finds it
    Any,
    /// those of H_1 a shortest basis over Z/2 (with --field 2)
    Shortest,
}

/// How `gmap homology` takes a simplicial complex (`.facets`, `.lex`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Via {
    /// every face of every facet is a cell (any simplicial complex)
    Direct,
    /// through the G-map of the facets (pure pseudo-manifolds)
    Gmap,
}

/// The options every command that reads a file shares.
#[derive(Args, Debug)]
struct Limits {
    /// refuse inputs whose G-map would have more darts than this (at most 2^32 - 2)
    #[arg(long)]
    max_darts: Option<u64>,
    /// refuse simplicial complexes with more faces than this on the direct route and in
    /// incidence graphs (default: what the memory budget holds)
    #[arg(long)]
    max_cells: Option<u64>,
}

/// Snapping a `.json` complex with points.
#[derive(Args, Debug, Clone, Copy)]
pub(crate) struct SnapArg {
    /// a .json complex with points: weld the points closer than EPS and split the edges and
    /// faces where a point or an edge lies inside them (T-junctions), printing on stderr
    /// what was welded and split; without it such a complex is refused naming the place
    #[arg(long, value_name = "EPS")]
    snap: Option<f64>,
}

/// Opens `file` with the dart limit and the snapping asked for; says on stderr what
/// snapping changed.
pub(crate) fn open_snapped(file: &std::path::Path, max_darts: Option<u64>, snap: SnapArg) -> gmap::Result<gmap::Input> {
    let input = gmap::open_with(file, &gmap::OpenOptions::max_darts(max_darts).with_snap(snap.snap))?;
    for n in input.notes() {
        eprintln!("snap: {n}");
    }
    Ok(input)
}

#[derive(Args, Debug)]
struct InfoArgs {
    #[arg(help = input_help("the input file"))]
    file: PathBuf,
    /// print one JSON object
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    limits: Limits,
    #[command(flatten)]
    snap: SnapArg,
    #[arg(long, help = format!("for a cubical set ({}): identify the opposite faces of its box", gmap::formats::extensions_of(&[gmap::Kind::Cubical, gmap::Kind::Image])))]
    periodic: bool,
    #[arg(long = "box", value_name = "BOX", value_parser = parse_cubical_box, help = box_help())]
    cubical_box: Option<(Vec<i64>, Vec<i64>)>,
    #[arg(long, value_name = "T", help = format!("for an image ({}): its cubes of value ≤ T (default: the non-zero values)", gmap::formats::extensions_of(&[gmap::Kind::Image])))]
    level: Option<f64>,
}

#[derive(Args, Debug)]
struct HomologyArgs {
    #[arg(help = input_help("the input file"))]
    file: PathBuf,
    /// cellular (default) or simplicial
    #[arg(long, value_enum, default_value_t = Method::Cellular)]
    method: Method,
    /// a prime P: compute over Z/P
    #[arg(long)]
    field: Option<u64>,
    /// print one JSON object
    #[arg(long)]
    json: bool,
    /// print a representative cycle for each summand; `--generators shortest` (over Z/2,
    /// with --field 2): those of H_1 a shortest basis, lengths counted in edges
    #[arg(long, value_enum, num_args = 0..=1, require_equals = true, default_missing_value = "any", value_name = "KIND")]
    generators: Option<Generators>,
    /// with --generators: the most cells with entries per dimension of the reduced complex
    /// (default 2000; the cost grows as its cube; full cubical sets of dimension ≤ 3 need none)
    #[arg(long, value_name = "N", requires = "generators")]
    max_generator_cells: Option<usize>,
    /// reduce the map by homology-preserving removals and contractions first
    #[arg(long)]
    simplify: bool,
    /// for an architectural complex: apply Algorithm 8.16 first (topological Betti numbers)
    #[arg(long)]
    topological: bool,
    #[command(flatten)]
    limits: Limits,
    #[command(flatten)]
    snap: SnapArg,
    /// simplicial complexes: direct (default: every face a cell) or gmap (through the G-map)
    #[arg(long, value_enum)]
    via: Option<Via>,
    #[arg(long, help = format!("for a cubical set ({}): identify the opposite faces of its box (a torus)", gmap::formats::extensions_of(&[gmap::Kind::Cubical, gmap::Kind::Image])))]
    periodic: bool,
    #[arg(long = "box", value_name = "BOX", value_parser = parse_cubical_box, help = box_help())]
    cubical_box: Option<(Vec<i64>, Vec<i64>)>,
    #[arg(long, value_name = "T", help = format!("for an image ({}): its cubes of value ≤ T (default: the non-zero values)", gmap::formats::extensions_of(&[gmap::Kind::Image])))]
    level: Option<f64>,
    /// print the seconds of the reading stage and of the homology on stderr
    #[arg(long)]
    timings: bool,
}

#[derive(Args, Debug)]
struct BenchArgs {
    /// input files, or folders (every supported file in them, sorted)
    #[arg(required = true)]
    inputs: Vec<PathBuf>,
    /// print one JSON object
    #[arg(long, conflicts_with = "csv")]
    json: bool,
    /// print CSV: a header line, then one line per row
    #[arg(long)]
    csv: bool,
    #[command(flatten)]
    limits: Limits,
    #[arg(long, help = format!("for cubical sets ({}): identify the opposite faces of the box (a torus)", gmap::formats::extensions_of(&[gmap::Kind::Cubical, gmap::Kind::Image])))]
    periodic: bool,
}

#[derive(Args, Debug)]
struct ConvertArgs {
    #[arg(help = input_help("input file"))]
    input: PathBuf,
    #[arg(help = format!("output file: {}", gmap::formats::output_help()))]
    output: PathBuf,
    #[command(flatten)]
    limits: Limits,
    /// write even when the output format drops what the input carries (labels, points,
    /// volumes); what is dropped is said on stderr
    #[arg(long)]
    lossy: bool,
    /// .off of a 3-map: write its boundary surface
    #[arg(long)]
    boundary: bool,
    /// .msh: write Gmsh's binary form (format 4.1, data size 8) rather than its text
    #[arg(long)]
    binary: bool,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Build the classic objects and print one table row each.
    Demo,
    /// Read a file, validate it and print its characteristics.
    Info(InfoArgs),
    /// Homology over Z, or over Z/P with --field P.
    Homology(HomologyArgs),
    /// Homology benchmark: one row per input and route, with stage times and the groups.
    Bench(BenchArgs),
    /// Convert between formats, chosen by file extension.
    Convert(ConvertArgs),
    /// Write one self-contained HTML page to look at the input in a browser.
    View(view::ViewArgs),
    /// Persistence diagram of a filtration: an image, valued facets, a labelled .gmap.
    Persistence(persistence::PersistenceArgs),
    /// Corbett's topological models (docs/TM.md): the edit check and the views of a model.
    Tm(tm::TmArgs),
    /// Curves on a surface (a 2-map): the shortest non-contractible cycle, the edge width,
    /// the face width.
    Curves(curves::CurvesArgs),
    /// Rooms from walls: the 3-cells of faces in space (.off polygon soup, .json 2-complex
    /// with points), written as a 3-complex whose volumes are the rooms (docs/LAR.md).
    Rooms(RoomsArgs),
    /// Room graphs: rooms joined through shared faces, through apertures (doors, windows),
    /// or to the exterior, named by the file's ids, faces and areas on the edges.
    Graph(graph::GraphArgs),
}

#[derive(Args, Debug)]
struct RoomsArgs {
    /// the faces: an .off polygon soup or a .json 2-complex with points
    input: PathBuf,
    /// the rooms: .json, .dot, or a map format (.gmap, .moka, .vtk, ...)
    output: PathBuf,
    #[command(flatten)]
    limits: Limits,
}

/// The arguments with `--generators any|shortest` written `--generators=…`: the kind is
/// optional, so `--generators` takes a value only when it is joined to it, and `gmap
/// homology --generators FILE` keeps reading FILE as the input (a file named `shortest`
/// or `any` right after the flag is written `./shortest`).
fn generators_joined(args: impl Iterator<Item = std::ffi::OsString>) -> Vec<std::ffi::OsString> {
    let mut out: Vec<std::ffi::OsString> = Vec::new();
    for a in args {
        let kind = a == "any" || a == "shortest";
        match out.last_mut() {
            Some(last) if kind && last == "--generators" => {
                last.push("=");
                last.push(&a);
            }
            _ => out.push(a),
        }
    }
    out
}

/// Runs the command line; returns the process exit code.
pub fn run() -> ExitCode {
    let cli = Cli::parse_from(generators_joined(std::env::args_os()));
    if let Some(bytes) = cli.max_memory {
        gmap::core::resources::set_max_memory(bytes);
    }
    let quiet = cli.quiet;
    let text = match cli.command {
        Command::Demo => Ok(gmap::demo::demo_table()),
        Command::Info(a) => info(a, quiet),
        Command::Homology(a) => {
            // written as it is formed: the generators of a large image are hundreds of MB
            let json = a.json;
            return match homology(a, quiet) {
                Ok(report) => {
                    let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout().lock());
                    let written = if json {
                        report.write_json(&mut out).and_then(|()| out.write_all(b"\n"))
                    } else {
                        report.write_text(&mut out)
                    };
                    exit_after_writing(written.and_then(|()| out.flush()))
                }
                Err(e) => exit_after_error(&e),
            };
        }
        Command::Bench(a) => bench(a, quiet),
        Command::View(a) => view::view(a, quiet),
        Command::Persistence(a) => persistence::persistence(a),
        Command::Tm(a) => return tm::run(a),
        Command::Curves(a) => curves::run(a),
        Command::Rooms(a) => gmap::rooms_file(&a.input, &a.output, a.limits.max_darts).map(|r| r.to_text()),
        Command::Convert(a) => convert(a, quiet),
        Command::Graph(a) => graph::run(a),
    };
    match text {
        Ok(text) => exit_after_writing(std::io::stdout().lock().write_all(text.as_bytes())),
        Err(e) => exit_after_error(&e),
    }
}

/// The exit code once the output is written: a reader of our output that went away
/// (`gmap … | head`) ends the command quietly, another write error is reported.
fn exit_after_writing(written: std::io::Result<()>) -> ExitCode {
    match written {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            eprintln!("error: {e}");
            ExitCode::from(1)
        }
        _ => ExitCode::SUCCESS,
    }
}

/// Reports a failed command on one line of stderr; exit code 1.
fn exit_after_error(e: &gmap::Error) -> ExitCode {
    eprintln!("error: {}", e.to_string().replace('\n', " "));
    ExitCode::from(1)
}

fn info(a: InfoArgs, quiet: bool) -> gmap::Result<String> {
    let progress = gmap::Progress::stderr("gmap info", quiet);
    progress.stage("reading");
    let input = open_snapped(&a.file, a.limits.max_darts, a.snap)?;
    let mut o = gmap::InfoOptions::default();
    (o.max_darts, o.periodic, o.level, o.progress) = (a.limits.max_darts, a.periodic, a.level, progress.clone());
    o.max_cells = a.limits.max_cells;
    o.cubical_box = a.cubical_box;
    let info = gmap::info(&input, &o);
    progress.finish();
    let info = info?;
    Ok(if a.json { format!("{}\n", info.to_json()) } else { info.to_text(&a.file.display().to_string()) })
}

fn homology(a: HomologyArgs, quiet: bool) -> gmap::Result<gmap::Report> {
    let mut o = gmap::HomologyOptions::default();
    o.method = match a.method {
        Method::Cellular => gmap::Method::Cellular,
        Method::Simplicial => gmap::Method::Simplicial,
    };
    o.via = a.via.map(|v| match v {
        Via::Direct => gmap::Via::Direct,
        Via::Gmap => gmap::Via::Gmap,
    });
    (o.field, o.simplify, o.topological) = (a.field, a.simplify, a.topological);
    (o.generators, o.shortest) = (a.generators.is_some(), a.generators == Some(Generators::Shortest));
    (o.max_darts, o.max_cells, o.periodic, o.level) = (a.limits.max_darts, a.limits.max_cells, a.periodic, a.level);
    o.max_generator_cells = a.max_generator_cells;
    o.cubical_box = a.cubical_box;
    o.progress = gmap::Progress::stderr("gmap homology", quiet);
    let report = if a.timings || a.snap.snap.is_some() {
        // the two stages apart: reading (an image: its header and a map) and homology
        let t = std::time::Instant::now();
        let input = open_snapped(&a.file, a.limits.max_darts, a.snap);
        let read = t.elapsed().as_secs_f64();
        let t = std::time::Instant::now();
        let report = input.and_then(|input| gmap::homology(&input, &o));
        if a.timings {
            eprintln!("timings: read {read:.6} s, homology {:.6} s", t.elapsed().as_secs_f64());
        }
        report
    } else {
        gmap::homology_file(&a.file, &o)
    };
    o.progress.finish();
    report
}

fn bench(a: BenchArgs, quiet: bool) -> gmap::Result<String> {
    let progress = gmap::Progress::stderr("gmap bench", quiet);
    let o = gmap::bench::BenchOptions::new(a.limits.max_darts, a.limits.max_cells, a.periodic);
    let runs = gmap::bench::bench_with(&a.inputs, &o, &progress);
    progress.finish();
    let runs = runs?;
    Ok(if a.json {
        format!("{}\n", gmap::bench::to_json(&runs))
    } else if a.csv {
        gmap::bench::to_csv(&runs)
    } else {
        gmap::bench::to_markdown(&runs)
    })
}

/// `gmap convert`: refuses an output that drops what the input carries or is another space
/// unless `--lossy` (the facade's rule, `gmap::save::write_checked`), and says on stderr
/// what the written output changes.
fn convert(a: ConvertArgs, quiet: bool) -> gmap::Result<String> {
    let progress = gmap::Progress::stderr("gmap convert", quiet);
    progress.stage(&format!("converting {} to {}", a.input.display(), a.output.display()));
    let mut o = gmap::SaveOptions::max_darts(a.limits.max_darts);
    (o.max_cells, o.boundary) = (a.limits.max_cells, a.boundary);
    (o.lossy, o.binary) = (a.lossy, a.binary);
    let done = gmap::save::save_checked(&a.input, &a.output, &o, "convert with --lossy to write it anyway");
    for change in done.iter().flatten() {
        eprintln!("gmap convert: {change}");
    }
    progress.finish();
    done.map(|_| String::new())
}
