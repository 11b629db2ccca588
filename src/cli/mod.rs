//! Command-line parsing and dispatch. Exit codes: 0 success, 1 bad input (one line
//! `error: …` on stderr), 2 bad usage (clap's own exit code).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

/// `println!` that hands a write error back (`?`) instead of panicking: output piped into a
/// reader that stops early (`gmap … | head`) ends the command quietly.
macro_rules! outln {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($t)*)
    }};
}

/// `print!` counterpart of [`outln!`].
macro_rules! out {
    ($($t:tt)*) => {{
        use std::io::Write as _;
        write!(std::io::stdout().lock(), $($t)*)
    }};
}

mod bench;
mod convert;
mod cubical;
mod demo;
mod homology;
mod info;
pub mod load;

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
}

fn parse_max_memory(text: &str) -> Result<u64, String> {
    gmap_core::resources::parse_size(text).map_err(|e| e.to_string())
}

/// Which chain complex `gmap homology` reduces.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Method {
    /// the cellular border operator (BO Def. 10), on the cells themselves
    Cellular,
    /// the simplicial counterpart (BO §6): one n-simplex per dart
    Simplicial,
}

/// How `gmap homology` takes a simplicial complex (`.facets`, `.lex`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Via {
    /// every face of every facet is a cell (any simplicial complex)
    Direct,
    /// through the G-map of the facets (pure pseudo-manifolds)
    Gmap,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Build the classic objects and print one table row each.
    Demo,
    /// Read a file, validate it and print its characteristics.
    Info {
        /// the input file (.gmap, .moka, .off, .facets, .lex[#name], .json)
        file: PathBuf,
        /// print one JSON object
        #[arg(long)]
        json: bool,
        /// refuse inputs whose G-map would have more darts than this
        #[arg(long)]
        max_darts: Option<u64>,
        /// for a cubical set (.cub, .pbm): identify the opposite faces of its box
        #[arg(long)]
        periodic: bool,
    },
    /// Homology over Z, or over Z/P with --field P.
    Homology {
        /// the input file
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
        /// print a representative cycle for each summand
        #[arg(long)]
        generators: bool,
        /// reduce the map by homology-preserving removals and contractions first
        #[arg(long)]
        simplify: bool,
        /// for an architectural complex: apply Algorithm 8.16 first (topological Betti numbers)
        #[arg(long)]
        topological: bool,
        /// refuse inputs whose G-map would have more darts than this (direct route: more faces)
        #[arg(long)]
        max_darts: Option<u64>,
        /// simplicial complexes: direct (default: every face a cell) or gmap (through the G-map)
        #[arg(long, value_enum)]
        via: Option<Via>,
        /// for a cubical set (.cub, .pbm): identify the opposite faces of its box (a torus)
        #[arg(long)]
        periodic: bool,
    },
    /// Homology benchmark: one row per input and route, with stage times and the groups.
    Bench {
        /// input files, or folders (every supported file in them, sorted)
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// print one JSON object
        #[arg(long, conflicts_with = "csv")]
        json: bool,
        /// print CSV: a header line, then one line per row
        #[arg(long)]
        csv: bool,
        /// leave out the GUDHI column (otherwise filled for .facets inputs when python3 has gudhi)
        #[arg(long)]
        no_gudhi: bool,
        /// refuse inputs whose G-map would have more darts than this
        #[arg(long)]
        max_darts: Option<u64>,
    },
    /// Convert between formats, chosen by file extension.
    Convert {
        /// input file
        input: PathBuf,
        /// output file
        output: PathBuf,
        /// refuse inputs whose G-map would have more darts than this
        #[arg(long)]
        max_darts: Option<u64>,
    },
}

/// The one-line message of an error: its chain of causes joined by `: `, leaving out a cause
/// whose text the message already ends with (an error that quotes its source), with newlines
/// made spaces.
fn error_message(e: &anyhow::Error) -> String {
    let mut msg = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if msg.ends_with(&text) {
            continue;
        }
        if !msg.is_empty() {
            msg.push_str(": ");
        }
        msg.push_str(&text);
    }
    msg.replace('\n', " ")
}

/// Runs the command line; returns the process exit code.
pub fn run() -> ExitCode {
    let cli = Cli::parse();
    if let Some(bytes) = cli.max_memory {
        gmap_core::resources::set_max_memory(bytes);
    }
    let result = match cli.command {
        Command::Demo => demo::run(),
        Command::Info { file, json, max_darts, periodic } => info::run(&file, json, max_darts, periodic),
        Command::Homology {
            file,
            method,
            field,
            json,
            generators,
            simplify,
            topological,
            max_darts,
            via,
            periodic,
        } => homology::run(&homology::Options {
            file,
            method,
            field,
            json,
            generators,
            simplify,
            topological,
            max_darts,
            via,
            periodic,
        }),
        Command::Bench { inputs, json, csv, no_gudhi, max_darts } => {
            let format = match (json, csv) {
                (true, _) => bench::Format::Json,
                (_, true) => bench::Format::Csv,
                _ => bench::Format::Markdown,
            };
            bench::run(&bench::Options { inputs, format, max_darts, gudhi: !no_gudhi })
        }
        Command::Convert { input, output, max_darts } => convert::run(&input, &output, max_darts),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // the reader of our output went away: nothing left to say to anyone
        Err(e) if e.downcast_ref::<std::io::Error>().is_some_and(|x| x.kind() == std::io::ErrorKind::BrokenPipe) => {
            ExitCode::SUCCESS
        }
        Err(e) => {
            let msg = error_message(&e);
            eprintln!("error: {msg}");
            ExitCode::from(1)
        }
    }
}
