//! `gmap curves shortest|edge-width|face-width FILE`: curves on a surface (facade
//! `gmap::curves`); `contractible|freely-homotopic|homotopic|simple FILE PATH…`: homotopy
//! tests of paths (facade `gmap::homotopy`, in `curves_paths.rs`).

use std::path::PathBuf;

use clap::{Args, Subcommand, ValueEnum};

#[path = "curves_paths.rs"]
mod paths;
use paths::{OnePath, Question, TwoPaths};

/// What `gmap curves` computes.
#[derive(Subcommand, Debug)]
pub enum CurvesCommand {
    /// The shortest non-contractible cycle (through the vertex of --through DART when given).
    Shortest(ShortestArgs),
    /// The edge width: a non-contractible cycle of the fewest edges.
    EdgeWidth(CurvesFile),
    /// The face width of a closed surface: the fewest faces a non-contractible closed curve
    /// meets, passing the graph at vertices only.
    FaceWidth(CurvesFile),
    /// Whether a closed path is contractible.
    Contractible(OnePath),
    /// Whether two closed paths are freely homotopic.
    FreelyHomotopic(TwoPaths),
    /// Whether two paths with the same ends are homotopic with their ends fixed.
    Homotopic(TwoPaths),
    /// Whether a closed path is homotopic to a simple closed curve.
    Simple(OnePath),
}

#[derive(Args, Debug)]
pub struct CurvesArgs {
    #[command(subcommand)]
    command: CurvesCommand,
}

#[derive(Args, Debug)]
pub struct CurvesFile {
    /// the surface: a 2-map (.gmap, .moka, .off, meshes) or a simplicial complex's G-map
    file: PathBuf,
    /// print one JSON object
    #[arg(long)]
    json: bool,
    /// refuse inputs whose G-map would have more darts than this
    #[arg(long)]
    max_darts: Option<u64>,
}

/// How edges are weighted.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum WeightsArg {
    /// every edge 1: lengths count edges
    Unit,
    /// the distance between the points of the edge's ends
    Length,
}

#[derive(Args, Debug)]
pub struct ShortestArgs {
    #[command(flatten)]
    file: CurvesFile,
    /// how edges are weighted
    #[arg(long, value_enum, default_value_t = WeightsArg::Unit)]
    weights: WeightsArg,
    /// a dart: the shortest non-contractible cycle through its vertex
    #[arg(long, value_name = "DART")]
    through: Option<u64>,
}

/// Runs `gmap curves …`: the text (or JSON) to print.
pub fn run(a: CurvesArgs) -> gmap::Result<String> {
    let open = |f: &CurvesFile| gmap::open_with(&f.file, &gmap::OpenOptions::max_darts(f.max_darts));
    let none = |json: bool, what: &str| {
        if json {
            "null\n".to_string()
        } else {
            format!("no {what}: every closed curve is contractible\n")
        }
    };
    match a.command {
        CurvesCommand::Shortest(s) => {
            let w = match s.weights {
                WeightsArg::Unit => gmap::curves::Weights::Unit,
                WeightsArg::Length => gmap::curves::Weights::Length,
            };
            let c = gmap::curves::shortest_non_contractible_cycle(&open(&s.file)?, &w, s.through)?;
            Ok(curve_text(c.as_ref(), s.file.json).unwrap_or_else(|| none(s.file.json, "non-contractible cycle")))
        }
        CurvesCommand::EdgeWidth(f) => {
            let c = gmap::curves::edge_width(&open(&f)?)?;
            Ok(curve_text(c.as_ref(), f.json).unwrap_or_else(|| none(f.json, "edge width")))
        }
        CurvesCommand::Contractible(p) => paths::one(Question::Contractible, &p),
        CurvesCommand::Simple(p) => paths::one(Question::Simple, &p),
        CurvesCommand::FreelyHomotopic(p) => paths::two(Question::Free, &p),
        CurvesCommand::Homotopic(p) => paths::two(Question::Fixed, &p),
        CurvesCommand::FaceWidth(f) => Ok(match gmap::curves::face_width(&open(&f)?)? {
            Some(w) if f.json => format!("{}\n", w.to_json()),
            Some(w) => w.to_text(),
            None => none(f.json, "face width"),
        }),
    }
}

/// A curve as text or JSON.
fn curve_text(c: Option<&gmap::curves::Curve>, json: bool) -> Option<String> {
    c.map(|c| if json { format!("{}\n", c.to_json()) } else { c.to_text() })
}
