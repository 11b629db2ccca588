//! `gmap info FILE [--json]` (docs/FORMATS.md §1): reads FILE, validates it, prints its
//! characteristics. Each kind of [`Loaded`] input has its own arm in [`run`] that builds
//! the lines to print; the JSON object of a G-map is [`MapInfo`].

use std::io::IsTerminal;
use std::path::Path;
use std::time::Instant;

use anyhow::Result;
use gmap_core::DenseMap;
use gmap_homology::arch::ArchComplex;
use serde::Serialize;

use super::load::{load, Loaded};

/// The characteristics of a G-map, in the key order of docs/FORMATS.md §1.
#[derive(Debug, Serialize)]
pub struct MapInfo {
    /// n
    pub dimension: usize,
    /// number of darts
    pub darts: usize,
    /// `cells[i]`: number of i-cells (BO Def. 2)
    pub cells: Vec<usize>,
    /// number of connected components
    pub components: usize,
    /// BO Def. 1 holds (readers refuse invalid maps, so this is true for any loaded map)
    pub valid: bool,
    /// BO Def. 6 holds
    pub complete_boundaries: bool,
    /// BO Def. 7 holds
    pub orientable: bool,
    /// the alternating sum of `cells`
    pub euler_characteristic: i64,
    /// why the boundaries are not complete (human output only)
    #[serde(skip)]
    pub boundary_defect: Option<String>,
}

/// Progress messages on stderr, shown only when stderr is a terminal and the work is big.
struct Progress {
    on: bool,
    start: Instant,
}

impl Progress {
    fn new(file: &Path) -> Self {
        let big = std::fs::metadata(file).map(|m| m.len() > 8 << 20).unwrap_or(false);
        Progress { on: big && std::io::stderr().is_terminal(), start: Instant::now() }
    }

    fn step(&self, what: &str) {
        if self.on {
            eprintln!("[{:6.2} s] {what}…", self.start.elapsed().as_secs_f64());
        }
    }
}

/// Computes the characteristics of a valid map. O(N n) for the counts and orientation,
/// O(N n^2) for the self-bending test of BO Def. 6 (a few partitions, no sort).
pub fn map_info(map: &DenseMap) -> MapInfo {
    let (cells, components) = map.cell_counts_and_components();
    let euler_characteristic =
        cells.iter().enumerate().map(|(i, &c)| if i % 2 == 0 { c as i64 } else { -(c as i64) }).sum();
    let boundary = map.check_complete_boundaries();
    MapInfo {
        dimension: map.dim(),
        darts: map.dart_count(),
        cells,
        components,
        valid: map.is_valid(),
        complete_boundaries: boundary.is_ok(),
        orientable: map.is_orientable(),
        euler_characteristic,
        boundary_defect: boundary.err().map(|e| e.to_string()),
    }
}

/// Runs `gmap info`.
pub fn run(file: &Path, json: bool, max_darts: Option<u64>, periodic: bool) -> Result<()> {
    let progress = Progress::new(file);
    progress.step("reading");
    let loaded = match load(file, max_darts) {
        Ok(l) => l,
        Err(e) => match no_gmap_reason(file, &e) {
            Some(why) => return simplicial_run(file, json, max_darts, why),
            None => return Err(e),
        },
    };
    progress.step("computing");
    if periodic && !matches!(loaded, Loaded::Cubical(_)) {
        anyhow::bail!("{}: --periodic applies to cubical sets (.cub, .pbm)", file.display());
    }
    match loaded {
        Loaded::Map(map) => {
            let info = map_info(&map);
            progress.step("done");
            if json {
                outln!("{}", serde_json::to_string(&info)?)?;
            } else {
                print_lines(&map_lines(file, &info))?;
            }
        }
        Loaded::Complex(x) => {
            let info = complex_info(&x);
            progress.step("done");
            if json {
                outln!("{}", serde_json::to_string(&info)?)?;
            } else {
                print_lines(&complex_lines(file, &info))?;
            }
        }
        Loaded::Cubical(set) => super::cubical::run(file, &set, json, periodic)?,
    }
    Ok(())
}

/// The human-readable lines of a map's characteristics.
fn map_lines(file: &Path, info: &MapInfo) -> Vec<(&'static str, String)> {
    let yes = |b: bool| if b { "yes".to_string() } else { "no".to_string() };
    let cells = info.cells.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ");
    let complete = match &info.boundary_defect {
        None => yes(true),
        Some(why) => format!("no ({why})"),
    };
    vec![
        ("file", file.display().to_string()),
        ("dimension", info.dimension.to_string()),
        ("darts", info.darts.to_string()),
        ("cells (0..n)", cells),
        ("components", info.components.to_string()),
        ("valid", yes(info.valid)),
        ("complete boundaries", complete),
        ("orientable", yes(info.orientable)),
        ("euler characteristic", info.euler_characteristic.to_string()),
    ]
}

/// Prints `key  value` lines with the values aligned.
fn print_lines(lines: &[(&str, String)]) -> std::io::Result<()> {
    let width = lines.iter().map(|(k, _)| k.len()).max().unwrap_or(0);
    for (k, v) in lines {
        outln!("{k:<width$}  {v}")?;
    }
    Ok(())
}

/// The characteristics of an architectural complex (`.json`): the keys of a map's
/// (docs/FORMATS.md §1) with regions for cells, no darts, orientability undefined (`null`), then
/// its own counts.
#[derive(Debug, Serialize)]
pub struct ComplexInfo {
    /// n
    pub dimension: usize,
    /// always 0: a complex has regions, not darts
    pub darts: usize,
    /// `cells[i]`: number of i-regions
    pub cells: Vec<usize>,
    /// connected components of the incidence graph
    pub components: usize,
    /// AC Def. 3.1 holds (the reader refuses anything else)
    pub valid: bool,
    /// every region of dimension k >= 1 has a defined entry to a (k-1)-region
    pub complete_boundaries: bool,
    /// not defined for an architectural complex
    pub orientable: Option<bool>,
    /// the alternating sum of `cells` (AC Cor. 3.11)
    pub euler_characteristic: i64,
    /// `"architectural complex"`
    pub kind: &'static str,
    /// number of regions
    pub regions: usize,
    /// number of defined entries of the partial boundary matrix
    pub incidences: usize,
}

/// Computes the characteristics of an architectural complex. O(R + E).
pub fn complex_info(x: &ArchComplex) -> ComplexInfo {
    let complete = (0..x.regions().len())
        .all(|r| x.region(r).dim == 0 || x.down(r).iter().any(|e| x.region(e.to).dim + 1 == x.region(r).dim));
    ComplexInfo {
        dimension: x.dim(),
        darts: 0,
        cells: x.region_counts(),
        components: x.component_count(),
        valid: true,
        complete_boundaries: complete,
        orientable: None,
        euler_characteristic: x.euler_characteristic(),
        kind: "architectural complex",
        regions: x.regions().len(),
        incidences: x.entries().len(),
    }
}

/// The human-readable lines of a complex's characteristics.
fn complex_lines(file: &Path, info: &ComplexInfo) -> Vec<(&'static str, String)> {
    let yes = |b: bool| if b { "yes".to_string() } else { "no".to_string() };
    let cells = info.cells.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ");
    vec![
        ("file", file.display().to_string()),
        ("kind", info.kind.to_string()),
        ("dimension", info.dimension.to_string()),
        ("regions (0..n)", cells),
        ("incidences", info.incidences.to_string()),
        ("components", info.components.to_string()),
        ("valid", yes(info.valid)),
        ("complete boundaries", yes(info.complete_boundaries)),
        ("euler characteristic", info.euler_characteristic.to_string()),
    ]
}

/// Why a simplicial complex has no G-map, when that is why loading failed: a ridge in three
/// or more facets, or facets of mixed dimensions (also when the dart count, checked first,
/// was over the limit).
fn no_gmap_reason(file: &Path, e: &anyhow::Error) -> Option<String> {
    use gmap_ops::import::{FileError, ImportError};
    if let Some(f) = e.downcast_ref::<FileError>() {
        if matches!(f.error, ImportError::RidgeInManyFacets { .. } | ImportError::MixedDimension { .. }) {
            return Some(f.error.to_string());
        }
    }
    let sc = super::load::load_simplicial(file).ok()??;
    (!sc.is_pure()).then(|| {
        format!(
            "mixed dimensions: {} of its {} facets have dimension {}, the others fewer vertices",
            sc.facet_count(),
            sc.total_facet_count(),
            sc.dim()
        )
    })
}

/// The characteristics of a simplicial complex that has no G-map: the keys of a map's
/// (docs/FORMATS.md §1) with simplices for cells, `"darts": 0`, `complete_boundaries` and
/// `orientable` `null`, then `kind`, `"gmap": null` and `why`.
#[derive(Debug, Serialize)]
pub struct SimplicialInfo {
    /// the largest facets' dimension
    pub dimension: usize,
    /// always 0: no G-map
    pub darts: usize,
    /// `cells[i]`: number of i-simplices
    pub cells: Vec<usize>,
    /// connected components
    pub components: usize,
    /// a simplicial complex (the reader refuses anything else)
    pub valid: bool,
    /// not defined without a G-map
    pub complete_boundaries: Option<bool>,
    /// not defined without a G-map
    pub orientable: Option<bool>,
    /// the alternating sum of `cells`
    pub euler_characteristic: i64,
    /// `"simplicial complex"`
    pub kind: &'static str,
    /// always `null`: the complex has no G-map
    pub gmap: Option<()>,
    /// why it has no G-map
    pub why: String,
}

/// `gmap info` on a simplicial complex without a G-map: its simplices, straight from the
/// facets (`gmap_homology::simplices`).
fn simplicial_run(file: &Path, json: bool, max_darts: Option<u64>, why: String) -> Result<()> {
    let sc = super::load::load_simplicial(file)?
        .ok_or_else(|| anyhow::anyhow!("{}: not a simplicial complex", file.display()))?;
    let fc = super::load::face_complex_within(&sc, max_darts, &file.display().to_string(), false)?;
    // components: the vertices' classes, joined along each facet
    let mut classes = gmap_core::union_find::UnionFind::new(fc.vertices.len());
    let idx = |v: &u64| fc.vertices.binary_search(v).unwrap_or(0) as u32;
    for f in sc.facets() {
        for v in &f[1..] {
            classes.union(idx(&f[0]), idx(v));
        }
    }
    let components = (0..fc.vertices.len() as u32).filter(|&x| classes.find(x) == x).count();
    let info = SimplicialInfo {
        dimension: fc.dim(),
        darts: 0,
        cells: fc.chain.counts().to_vec(),
        components,
        valid: true,
        complete_boundaries: None,
        orientable: None,
        euler_characteristic: fc.chain.euler_characteristic(),
        kind: "simplicial complex",
        gmap: None,
        why,
    };
    if json {
        outln!("{}", serde_json::to_string(&info)?)?;
    } else {
        let cells = info.cells.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(" ");
        print_lines(&[
            ("file", file.display().to_string()),
            ("kind", info.kind.to_string()),
            ("dimension", info.dimension.to_string()),
            ("simplices (0..n)", cells),
            ("components", info.components.to_string()),
            ("euler characteristic", info.euler_characteristic.to_string()),
            ("gmap", format!("none: {}", info.why)),
        ])?;
    }
    Ok(())
}
