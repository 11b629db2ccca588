//! Cubical sets (`.cub`, `.pbm`) in `gmap homology` and `gmap info`: the cubical complex of
//! the closure, built on the set's box (docs/FORMATS.md), `--periodic` for the d-torus.

use std::path::Path;

use anyhow::{bail, Context, Result};
use gmap_homology::cubical::cubical_complex_with;
use gmap_homology::ChainComplex;
use gmap_ops::import::CubicalSet;
use serde::Serialize;

use super::homology::Options;
use super::Method;

/// A cell of the cubical complex in the input's coordinates: its minimal vertex and its
/// extent (0 or 1) per axis.
pub type CubeName = (Vec<i64>, Vec<u8>);

/// The chain complex of a set (after collapses of free faces) and, with `--generators`, the
/// names of its cells; empty names otherwise.
pub fn complex(set: &CubicalSet, o: &Options, file: &str) -> Result<(ChainComplex, Vec<Vec<CubeName>>)> {
    if o.method == Method::Simplicial {
        bail!("{file}: a cubical set has no simplicial counterpart here; use --method cellular");
    }
    if o.simplify || o.topological {
        bail!("{file}: --simplify and --topological do not apply to cubical sets");
    }
    let c = cubical_complex_with(set.shape(), set.bits(), o.periodic, true).with_context(|| file.to_string())?;
    let names = if o.generators {
        let min = set.min();
        let name = |k: usize, i: usize| -> CubeName {
            let coords = c.coordinates(k, i);
            let lo = coords.iter().enumerate().map(|(a, &x)| min.get(a).copied().unwrap_or(0) + (x / 2) as i64);
            (lo.collect(), coords.iter().map(|&x| (x % 2) as u8).collect())
        };
        (0..c.cells.len()).map(|k| (0..c.cells[k].len()).map(|i| name(k, i)).collect()).collect()
    } else {
        vec![Vec::new(); c.cells.len()]
    };
    Ok((c.chain, names))
}

/// `gmap info` on a cubical set: the keys of a map's (docs/FORMATS.md §1) with the cells of
/// the closure, no darts, then its own.
#[derive(Debug, Serialize)]
pub struct CubicalInfo {
    /// d
    pub dimension: usize,
    /// always 0
    pub darts: usize,
    /// cells of the closure per dimension (of the torus with `--periodic`)
    pub cells: Vec<usize>,
    /// `"cubical set"`
    pub kind: &'static str,
    /// cubes of the set
    pub cubes: usize,
    /// the box: minimal vertex
    pub box_min: Vec<i64>,
    /// the box: cubes per axis
    pub box_shape: Vec<usize>,
    /// opposite faces of the box identified
    pub periodic: bool,
    /// the alternating sum of `cells`
    pub euler_characteristic: i64,
}

/// Prints the characteristics of a set.
pub fn run(file: &Path, set: &CubicalSet, json: bool, periodic: bool) -> Result<()> {
    let c =
        cubical_complex_with(set.shape(), set.bits(), periodic, false).with_context(|| file.display().to_string())?;
    let cells = c.chain.counts().to_vec();
    let info = CubicalInfo {
        dimension: set.dim(),
        darts: 0,
        euler_characteristic: c.chain.euler_characteristic(),
        cells,
        kind: "cubical set",
        cubes: set.cube_count(),
        box_min: set.min().to_vec(),
        box_shape: set.shape().to_vec(),
        periodic,
    };
    if json {
        outln!("{}", serde_json::to_string(&info)?)?;
        return Ok(());
    }
    let join = |v: Vec<String>, sep: &str| v.join(sep);
    let lines = [
        ("file", file.display().to_string()),
        ("kind", info.kind.to_string()),
        ("dimension", info.dimension.to_string()),
        ("cubes", info.cubes.to_string()),
        ("box min", join(info.box_min.iter().map(|x| x.to_string()).collect(), " ")),
        ("box shape", join(info.box_shape.iter().map(|x| x.to_string()).collect(), " x ")),
        ("periodic", if periodic { "yes" } else { "no" }.to_string()),
        ("cells (0..n)", join(info.cells.iter().map(|x| x.to_string()).collect(), " ")),
        ("euler characteristic", info.euler_characteristic.to_string()),
    ];
    let width = lines.iter().map(|(k, _)| k.len()).max().unwrap_or(0);
    for (k, v) in &lines {
        outln!("{k:<width$}  {v}")?;
    }
    Ok(())
}
