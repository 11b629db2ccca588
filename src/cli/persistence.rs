//! `gmap persistence FILE`: arguments, one facade call, printing.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

/// Where an image's values sit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum Construction {
    /// on top cells, lower cells take the minimum (GUDHI's default)
    #[value(name = "T", alias = "t")]
    T,
    /// on vertices, higher cells take the maximum (CubicalRipser's default)
    #[value(name = "V", alias = "v")]
    V,
}

#[derive(Args, Debug)]
pub(crate) struct PersistenceArgs {
    #[arg(help = format!(
        "the input: an image ({}), a .facets file with `: VALUE` per facet (or any simplicial complex with --vertex-values), a .gmap with a numeric label per cell, a cubical set ({})",
        gmap::formats::extensions_of(&[gmap::Kind::Image]),
        gmap::formats::extensions_of(&[gmap::Kind::Cubical]),
    ))]
    file: PathBuf,
    /// coefficients Z/P, P a prime below 2^31
    #[arg(long, default_value_t = 2)]
    field: u32,
    /// for images: T or V
    #[arg(long, value_enum, default_value_t = Construction::T)]
    construction: Construction,
    /// superlevel sets: from the largest value down (images and complexes)
    #[arg(long)]
    superlevel: bool,
    /// for images: identify the opposite faces of the box
    #[arg(long)]
    periodic: bool,
    /// a representative cycle per pair
    #[arg(long)]
    cycles: bool,
    /// for a .gmap: the label giving each cell its value
    #[arg(long, default_value = "value")]
    label: String,
    /// for a simplicial complex (.facets without values, .lex): a file with a vertex label
    /// and its value per line; each simplex takes its vertices' largest value (lower star)
    #[arg(long, value_name = "FILE")]
    vertex_values: Option<PathBuf>,
    /// print one JSON object: {"field", "pairs": [[dim, birth, death], …], "cycles"}
    #[arg(long)]
    json: bool,
    /// draw the persistence diagram to OUT.svg or OUT.png
    #[arg(long)]
    plot: Option<PathBuf>,
    /// draw the barcode to OUT.svg or OUT.png
    #[arg(long)]
    barcode: Option<PathBuf>,
    /// with --cycles, on a 2-D image: draw the image with pair K's cycle (K counts the
    /// printed pairs from 0) to OUT.svg or OUT.png
    #[arg(long, num_args = 2, value_names = ["K", "OUT"], alias = "plot-cycle")]
    draw_cycle: Option<Vec<String>>,
}

pub(crate) fn persistence(a: PersistenceArgs) -> gmap::Result<String> {
    let opts = gmap::PersistenceOptions {
        field: a.field,
        construction: match a.construction {
            Construction::T => gmap::algebra::persistence::Construction::T,
            Construction::V => gmap::algebra::persistence::Construction::V,
        },
        superlevel: a.superlevel,
        periodic: a.periodic,
        cycles: a.cycles,
        label: a.label,
    };
    let p = match &a.vertex_values {
        Some(v) => gmap::lower_star_file(&a.file, &gmap::VertexValues::read(v)?, &opts)?,
        None => gmap::persistence_file(&a.file, &opts)?,
    };
    if let Some(out) = &a.plot {
        gmap::persistence::plot_file(&p, out, false)?;
    }
    if let Some(out) = &a.barcode {
        gmap::persistence::plot_file(&p, out, true)?;
    }
    if let Some(v) = &a.draw_cycle {
        let k: usize = v[0].parse().map_err(|_| {
            gmap::Error::new(gmap::ErrorKind::Usage, format!("--draw-cycle: {:?} is not a pair number", v[0]))
        })?;
        gmap::persistence::plot_cycle_file(&p, k, std::path::Path::new(&v[1]))?;
    }
    if a.json {
        return Ok(format!("{}\n", p.diagram.to_json()));
    }
    let mut out = String::new();
    for (i, pair) in p.diagram.pairs.iter().enumerate() {
        out.push_str(&format!("{} {} {}\n", pair.dim, pair.birth, pair.death));
        if let Some(c) = p.diagram.cycles.get(i) {
            let cells: Vec<String> = c.iter().map(|(n, x)| format!("{x}*{n}")).collect();
            out.push_str(&format!("  cycle: {}\n", cells.join(" + ")));
        }
    }
    Ok(out)
}
