//! The characteristics of an input (`gmap info`): counts, components, validity,
//! orientability and the Euler characteristic, with a kind of its own for each kind of
//! input. Every kind serialises to the JSON object of docs/FORMATS.md (the keys of a map's
//! first, in that order) and renders as aligned `key  value` lines.

use serde::Serialize;

use gmap_core::DenseMap;
use gmap_homology::arch::ArchComplex;
use gmap_ops::import::{CubicalSet, ImportError, SimplicialComplex};

use crate::error::{err, Error, ErrorKind, Result};
use crate::input::{limit_hint, Input, Sourced};
use crate::progress::Progress;

/// Options of [`info`].
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct InfoOptions {
    /// refuse maps of more darts than this (a simplicial complex's G-map; its faces when it
    /// has none)
    pub max_darts: Option<u64>,
    /// refuse more faces than this where a simplicial complex's faces are counted
    pub max_cells: Option<u64>,
    /// a cubical set's box is a torus (opposite faces identified)
    pub periodic: bool,
    /// a cubical set's box as its first and last cubes (default: the cubes' bounding box, or
    /// the file's `box` line)
    pub cubical_box: Option<(Vec<i64>, Vec<i64>)>,
    /// an image's cubical set: the values `≤ T` (default: the non-zero values)
    pub level: Option<f64>,
    /// where the stages are shown
    pub progress: Progress,
}

/// The characteristics of an input, by kind.
#[derive(Clone, Debug, Serialize)]
#[serde(untagged)]
#[non_exhaustive]
pub enum Info {
    /// a G-map (also a simplicial complex through its G-map)
    Map(MapInfo),
    /// an architectural complex
    Arch(ArchInfo),
    /// a cubical set
    Cubical(CubicalInfo),
    /// a simplicial complex that has no G-map
    Simplicial(SimplicialInfo),
}

/// The characteristics of a G-map, in the key order of docs/FORMATS.md.
#[derive(Clone, Debug, Serialize)]
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
    /// why the boundaries are not complete (text output only)
    #[serde(skip)]
    pub boundary_defect: Option<String>,
    /// the vertices carry points
    pub points: bool,
    /// the names of the labels the cells carry, in order of first appearance, with the
    /// number of cells that carry one (`.gmap` and mesh inputs)
    pub labels: Vec<(String, usize)>,
}

/// The label names of a list of label sets, in order of first appearance, each with the
/// number of sets that carry it.
fn label_names<'a>(sets: impl Iterator<Item = &'a gmap_core::Labels>) -> Vec<(String, usize)> {
    let mut out: Vec<(String, usize)> = Vec::new();
    for l in sets {
        for (name, _) in l.iter() {
            match out.iter_mut().find(|(n, _)| n == name) {
                Some((_, k)) => *k += 1,
                None => out.push((name.to_string(), 1)),
            }
        }
    }
    out
}

fn labels_text(labels: &[(String, usize)]) -> String {
    if labels.is_empty() {
        return "none".to_string();
    }
    labels.iter().map(|(n, k)| format!("{n} ({k})")).collect::<Vec<_>>().join(", ")
}

/// The characteristics of an architectural complex (`.json`): the keys of a map's with
/// regions for cells, no darts, orientability undefined (`null`), then its own counts.
#[derive(Clone, Debug, Serialize)]
pub struct ArchInfo {
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
    /// the names of the labels the regions carry, with the number of regions that carry one
    pub labels: Vec<(String, usize)>,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

/// The characteristics of a cubical set: the keys of a map's with the cells of the closure,
/// no darts, then its own.
#[derive(Clone, Debug, Serialize)]
pub struct CubicalInfo {
    /// d
    pub dimension: usize,
    /// always 0
    pub darts: usize,
    /// cells of the closure per dimension (of the torus when periodic)
    pub cells: Vec<usize>,
    /// `"cubical set"`
    pub kind: &'static str,
    /// cubes of the set
    pub cubes: usize,
    /// the listed cells of lower dimension on no cube (a cubical cell complex); absent for a
    /// full set
    #[serde(skip_serializing_if = "is_zero")]
    pub lower_cells: usize,
    /// the box: minimal vertex
    pub box_min: Vec<i64>,
    /// the box: cubes per axis
    pub box_shape: Vec<usize>,
    /// opposite faces of the box identified
    pub periodic: bool,
    /// the alternating sum of `cells`
    pub euler_characteristic: i64,
}

/// The characteristics of a simplicial complex that has no G-map: the keys of a map's with
/// simplices for cells, `"darts": 0`, `complete_boundaries` and `orientable` `null`, then
/// `kind`, `"gmap": null` and `why`.
#[derive(Clone, Debug, Serialize)]
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

/// The characteristics of an input. A simplicial complex is described by its G-map when it
/// has one, else by its simplices with the reason it has none.
pub fn info(input: &Input, o: &InfoOptions) -> Result<Info> {
    let file = input.path().display().to_string();
    if o.cubical_box.is_some() && !matches!(input, Input::Cubical(_)) {
        return Err(err!(Usage, "{file}: --box applies to cubical sets (.cub, .cel, .pbm)"));
    }
    o.progress.stage("computing");
    let simplicial = match input {
        Input::Simplicial(sc) => match sc.get().to_gmap_within(o.max_darts) {
            Ok(map) => Err(map),
            Err(e) => match no_gmap_reason(sc, &e) {
                Some(why) => Ok(simplicial_info(sc, o.max_cells, &file, why)?),
                None => return Err(limit_hint(gmap_ops::import::FileError::new(sc.path(), e).into())),
            },
        },
        _ => Err(DenseMap::new(0, 0)),
    };
    let made_map = match simplicial {
        Ok(info) => return Ok(Info::Simplicial(info)),
        Err(map) => map,
    };
    if o.periodic && !matches!(input, Input::Cubical(_) | Input::Image(_)) {
        return Err(err!(Usage, "{file}: --periodic applies to cubical sets (.cub, .cel, .pbm, .npy, .complex)"));
    }
    if o.level.is_some() && !matches!(input, Input::Image(_)) {
        return Err(err!(Usage, "{file}: --level applies to images (.npy, .complex)"));
    }
    Ok(match input {
        Input::Map(m) => {
            let mut i = map_info(m.map());
            if let Some(Ok(g)) = m.labelled() {
                i.labels = label_names(gmap_core::labels_by_dimension(g).into_iter().flatten());
            }
            Info::Map(i)
        }
        Input::Simplicial(_) => Info::Map(map_info(&made_map)),
        Input::Arch(x) => Info::Arch(arch_info(x)),
        Input::Cubical(set) => match &o.cubical_box {
            Some((first, last)) => {
                let boxed = set.with_box(first, last).map_err(|e| err!(Usage, "{file}: --box: {e}"))?;
                Info::Cubical(cubical_info(&boxed, o.periodic, &file)?)
            }
            None => Info::Cubical(cubical_info(set, o.periodic, &file)?),
        },
        Input::Image(img) => {
            let level = o.level.map_or(gmap_ops::import::Level::Nonzero, gmap_ops::import::Level::AtMost);
            let set =
                img.to_cubical_set(level).map_err(|e| Error::from_source(ErrorKind::Limit, e).context(file.clone()))?;
            Info::Cubical(cubical_info(&set, o.periodic, &file)?)
        }
    })
}

/// The characteristics of a valid map. O(N n) for the counts and orientation, O(N n^2) for
/// the self-bending test of BO Def. 6 (a few partitions, no sort).
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
        points: map.has_points(),
        labels: Vec::new(),
    }
}

/// The characteristics of an architectural complex. O(R + E).
pub fn arch_info(x: &ArchComplex) -> ArchInfo {
    let complete = (0..x.regions().len())
        .all(|r| x.region(r).dim == 0 || x.down(r).iter().any(|e| x.region(e.to).dim + 1 == x.region(r).dim));
    ArchInfo {
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
        labels: label_names((0..x.regions().len()).map(|r| x.region_labels(r))),
    }
}

/// The characteristics of a cubical set: the cells of its closure (of the torus when
/// `periodic`).
pub fn cubical_info(set: &CubicalSet, periodic: bool, file: &str) -> Result<CubicalInfo> {
    let cells = set.lower_cells_in_box();
    let c = gmap_homology::cubical::cubical_cell_complex_with(set.shape(), set.bits(), &cells, periodic, false)
        .map_err(|e| Error::from_source(ErrorKind::Limit, e).context(file.to_string()))?;
    Ok(CubicalInfo {
        dimension: set.dim(),
        darts: 0,
        euler_characteristic: c.chain.euler_characteristic(),
        cells: c.chain.counts().to_vec(),
        kind: "cubical set",
        cubes: set.cube_count(),
        lower_cells: set.lower_cell_count(),
        box_min: set.min().to_vec(),
        box_shape: set.shape().to_vec(),
        periodic,
    })
}

/// Why a simplicial complex has no G-map, when that is why making it failed: a ridge in
/// three or more facets, or facets of mixed dimensions (also when the dart count, checked
/// first, was over the limit).
fn no_gmap_reason(sc: &SimplicialComplex, e: &ImportError) -> Option<String> {
    if matches!(e, ImportError::RidgeInManyFacets { .. } | ImportError::MixedDimension { .. }) {
        return Some(e.to_string());
    }
    (!sc.is_pure()).then(|| {
        format!(
            "mixed dimensions: {} of its {} facets have dimension {}, the others fewer vertices",
            sc.facet_count(),
            sc.total_facet_count(),
            sc.dim()
        )
    })
}

/// The characteristics of a simplicial complex without a G-map: its simplices, straight from
/// the facets (`gmap_homology::simplices`).
fn simplicial_info(
    sc: &Sourced<SimplicialComplex>,
    max_cells: Option<u64>,
    file: &str,
    why: String,
) -> Result<SimplicialInfo> {
    let fc = crate::face_complex_within(sc, max_cells, file, false)?;
    // components: the vertices' classes, joined along each facet
    let mut classes = gmap_core::union_find::UnionFind::new(fc.vertices.len());
    let idx = |v: &u64| fc.vertices.binary_search(v).unwrap_or(0) as u32;
    for f in sc.facets() {
        for v in &f[1..] {
            classes.union(idx(&f[0]), idx(v));
        }
    }
    let components = (0..fc.vertices.len() as u32).filter(|&x| classes.find(x) == x).count();
    Ok(SimplicialInfo {
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
    })
}

impl Info {
    /// The JSON object `gmap info --json` prints.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }

    /// The `key  value` lines `gmap info` prints, the first naming `file`.
    pub fn lines(&self, file: &str) -> Vec<(&'static str, String)> {
        let file = ("file", file.to_string());
        let mut rows = match self {
            Info::Map(i) => map_lines(i),
            Info::Arch(i) => arch_lines(i),
            Info::Cubical(i) => cubical_lines(i),
            Info::Simplicial(i) => simplicial_lines(i),
        };
        rows.insert(0, file);
        rows
    }

    /// The lines of [`Info::lines`] as text, the values aligned.
    pub fn to_text(&self, file: &str) -> String {
        let lines = self.lines(file);
        let width = lines.iter().map(|(k, _)| k.len()).max().unwrap_or(0);
        lines.iter().map(|(k, v)| format!("{k:<width$}  {v}\n")).collect()
    }
}

/// `yes` or `no`.
fn yes(b: bool) -> String {
    if b { "yes" } else { "no" }.to_string()
}

/// Numbers joined by `sep`.
fn list(v: &[usize], sep: &str) -> String {
    v.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(sep)
}

/// The lines of a map after its file.
fn map_lines(i: &MapInfo) -> Vec<(&'static str, String)> {
    let complete = match &i.boundary_defect {
        None => yes(true),
        Some(why) => format!("no ({why})"),
    };
    let mut lines = vec![
        ("dimension", i.dimension.to_string()),
        ("darts", i.darts.to_string()),
        ("cells (0..n)", list(&i.cells, " ")),
        ("components", i.components.to_string()),
        ("valid", yes(i.valid)),
        ("complete boundaries", complete),
        ("orientable", yes(i.orientable)),
        ("euler characteristic", i.euler_characteristic.to_string()),
        ("points", yes(i.points)),
        ("labels", labels_text(&i.labels)),
    ];
    if let Some((name, k)) = i.labels.iter().find(|(n, _)| n == gmap_ops::import::high_order::HIGH_ORDER_LABEL) {
        lines.push((
            "higher order",
            format!("{k} cells read as their corner cells; their other nodes are kept in the label {name}"),
        ));
    }
    lines
}

/// The lines of an architectural complex after its file.
fn arch_lines(i: &ArchInfo) -> Vec<(&'static str, String)> {
    vec![
        ("kind", i.kind.to_string()),
        ("dimension", i.dimension.to_string()),
        ("regions (0..n)", list(&i.cells, " ")),
        ("incidences", i.incidences.to_string()),
        ("components", i.components.to_string()),
        ("valid", yes(i.valid)),
        ("complete boundaries", yes(i.complete_boundaries)),
        ("euler characteristic", i.euler_characteristic.to_string()),
        ("labels", labels_text(&i.labels)),
    ]
}

/// The lines of a cubical set after its file.
fn cubical_lines(i: &CubicalInfo) -> Vec<(&'static str, String)> {
    let mut rows = vec![
        ("kind", i.kind.to_string()),
        ("dimension", i.dimension.to_string()),
        ("cubes", i.cubes.to_string()),
        ("box min", i.box_min.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(" ")),
        ("box shape", list(&i.box_shape, " x ")),
        ("periodic", yes(i.periodic)),
        ("cells (0..n)", list(&i.cells, " ")),
        ("euler characteristic", i.euler_characteristic.to_string()),
    ];
    if i.lower_cells > 0 {
        rows.insert(3, ("cells on no cube", i.lower_cells.to_string()));
    }
    rows
}

/// The lines of a simplicial complex without a G-map after its file.
fn simplicial_lines(i: &SimplicialInfo) -> Vec<(&'static str, String)> {
    vec![
        ("kind", i.kind.to_string()),
        ("dimension", i.dimension.to_string()),
        ("simplices (0..n)", list(&i.cells, " ")),
        ("components", i.components.to_string()),
        ("euler characteristic", i.euler_characteristic.to_string()),
        ("gmap", format!("none: {}", i.why)),
    ]
}
