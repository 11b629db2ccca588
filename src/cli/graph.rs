//! `gmap graph FILE --dual faces|apertures|exterior [-o OUT] [--format F]`: the room graph
//! of a building (facade `gmap::room_graph`), written to OUT in the format of its extension
//! (`.graphml`, `.dot`, `.json`) or printed (JSON unless `--format`).

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::Limits;

/// Which rooms the graph joins.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(super) enum DualArg {
    /// rooms sharing a face (TopologicPy's `direct`)
    Faces,
    /// rooms sharing a door, window or opening (a face whose `kind` label says so;
    /// TopologicPy's `viaSharedApertures`)
    Apertures,
    /// each room to the exterior through its faces on no other room (TopologicPy's
    /// `toExteriorTopologies`)
    Exterior,
}

/// The printed format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(super) enum GraphFormat {
    Json,
    Graphml,
    Dot,
}

#[derive(Args, Debug)]
pub(super) struct GraphArgs {
    #[arg(help = super::input_help("the building: a .json architectural complex, or any input with an incidence graph"))]
    file: PathBuf,
    /// the dual graph: faces, apertures or exterior
    #[arg(long, value_enum)]
    dual: DualArg,
    /// the file to write: .graphml, .dot or .json (default: print it)
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// the format printed without --output (default json)
    #[arg(long, value_enum, conflicts_with = "output")]
    format: Option<GraphFormat>,
    #[command(flatten)]
    limits: Limits,
    #[command(flatten)]
    snap: super::SnapArg,
}

pub(super) fn run(a: GraphArgs) -> gmap::Result<String> {
    let input = super::open_snapped(&a.file, a.limits.max_darts, a.snap)?;
    let dual = match a.dual {
        DualArg::Faces => gmap::Dual::Faces,
        DualArg::Apertures => gmap::Dual::Apertures,
        DualArg::Exterior => gmap::Dual::Exterior,
    };
    let g = gmap::room_graph(&input, dual, a.limits.max_cells)?;
    match a.output {
        Some(out) => {
            let text = g.to_format(&out)?;
            gmap::core::io::write_atomic(&out, text.as_bytes())
                .map_err(|e| gmap::Error::new(gmap::ErrorKind::Write, format!("{}: {e}", out.display())))?;
            Ok(format!("wrote {}: {} nodes, {} edges\n", out.display(), g.nodes.len(), g.edges.len()))
        }
        None => Ok(match a.format.unwrap_or(GraphFormat::Json) {
            GraphFormat::Json => format!("{}\n", g.to_json()),
            GraphFormat::Graphml => g.to_graphml(),
            GraphFormat::Dot => g.to_dot(),
        }),
    }
}
