//! Writing an input in another format (`gmap convert`), chosen by the output's extension.
//!
//! Outputs: `.gmap` (with the points, and from a `.gmap` input the cell labels too) and
//! `.moka` (gmap-core io), `.off` (2-maps with points), `.facets` (the barycentric
//! subdivision: one simplex per dart), `.vtk` (maps of dimension ≤ 3 with points; from a
//! `.gmap`, the cell labels as cell data), the incidence graph as `.json` or `.dot` (from a
//! `.gmap`, each region with the labels of its cell) and LAR's `.lar.json`. A simplicial
//! complex is written through its G-map; an architectural complex writes `.json` and `.dot`
//! itself and the other formats through the G-map of its face poset. Every writer goes
//! through a temporary file and a rename, so a failure leaves no partial output.

use std::path::Path;

use gmap_core::{DenseMap, LabelledGMap};
use gmap_homology::arch::ArchComplex;
use gmap_homology::dot::write_dot;
use gmap_homology::json::write_json;
use gmap_homology::lar::Lar;
use gmap_ops::import::PosetError;

use crate::error::{err, Error, ErrorKind, Result};
use crate::input::{extension, split_lex_name, Input};

/// Options of [`save`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SaveOptions {
    /// refuse to make maps of more darts than this (a complex written through its G-map)
    pub max_darts: Option<u64>,
    /// refuse incidence graphs of more faces than this (a simplicial complex's face poset)
    pub max_cells: Option<u64>,
    /// `.off` of a 3-map: write its boundary surface
    pub boundary: bool,
}

impl SaveOptions {
    /// Options with a dart limit.
    pub fn max_darts(max_darts: Option<u64>) -> Self {
        SaveOptions { max_darts, max_cells: None, boundary: false }
    }
}

/// Writes `input` to `output` in the format named by the output's extension. Refuses to
/// write over the file the input was read from, and a kind of input the format cannot hold.
pub fn save(input: &Input, output: impl AsRef<Path>, o: &SaveOptions) -> Result<()> {
    let output = output.as_ref();
    refuse_same_file(input.path(), output)?;
    if o.boundary {
        return save_boundary(input, output);
    }
    if let Input::Map(m) = input {
        // the labels of the cells live in the labelled map of a `.gmap` file
        let labelled_output = match extension(output).as_str() {
            "gmap" | "vtk" | "dot" | "graphml" => true,
            "json" => !is_lar(output),
            _ => false,
        };
        if let (true, Some(g)) = (labelled_output, m.labelled()) {
            let g = g?;
            return match extension(output).as_str() {
                "gmap" => Ok(gmap_core::io::write_labelled_gmap(g, output)?),
                _ => write_labelled(g, output),
            };
        }
    }
    match input {
        Input::Map(m) => save_map(m.map(), output),
        // the incidence graph of any complex is its face poset
        Input::Simplicial(sc) if is_graph(output) => {
            write_graph(&crate::graph::simplicial(sc, o.max_cells, &sc.path().display().to_string())?, output)
        }
        Input::Simplicial(sc) => save_map(&sc.to_gmap_within(o.max_darts)?, output),
        Input::Arch(x) => write_arch(x, x.path(), output, o.max_darts),
        Input::Cubical(set) if is_graph(output) => {
            write_graph(&crate::graph::cubical(set, false, &set.path().display().to_string())?, output)
        }
        // .vtk voxels and a G-map of d-cells hold the cubes only
        Input::Cubical(set) if !set.is_full() => {
            let what = if extension(output) == "vtk" { ".vtk (voxels)" } else { "a G-map of its cubes" };
            let why = set.require_full(what).err().map(|e| e.to_string()).unwrap_or_default();
            Err(err!(Unsupported, "{}: {why}; write .json, .dot or .graphml (every cell)", set.path().display())
                .with_path(set.path()))
        }
        Input::Cubical(set) if extension(output) == "vtk" => {
            gmap_ops::export::write_cubical_vtk(set, output).map_err(|e| cannot_write(output, &e))
        }
        Input::Cubical(set) => {
            let m = set
                .gmap_of_union(false)
                .map_err(|e| Error::from_source(ErrorKind::Limit, &e).context(set.path().display().to_string()))?;
            save_map(&m, output)
        }
        // an image is written as an image: numpy's .npy as it is, DIPHA's as f64
        Input::Image(img) => {
            let written = match crate::input::extension(output).as_str() {
                "npy" => img.write_npy(output),
                "complex" => img.write_dipha(output),
                other => {
                    return Err(err!(
                        Unsupported,
                        "{}: an image is written as .npy or .complex, not '.{}'",
                        input.path().display(),
                        gmap_core::io::shorten(other.as_bytes(), 40)
                    ))
                }
            };
            written.map_err(|e| err!(Write, "{}: {e}", output.display()).with_path(output))
        }
    }
}

/// Writes the boundary surface of a 3-map (or of the G-map of a simplicial complex) as `.off`.
fn save_boundary(input: &Input, output: &Path) -> Result<()> {
    if extension(output) != "off" {
        return Err(err!(Usage, "{}: --boundary writes the boundary surface of a 3-map as .off", output.display()));
    }
    let m = input.to_map()?;
    if m.dim() != 3 {
        return Err(err!(
            Usage,
            "{}: --boundary writes the boundary surface of a 3-map; this map has dimension {}",
            input.path().display(),
            m.dim()
        ));
    }
    gmap_ops::export::write_boundary_off(&m, output).map_err(|e| cannot_write(output, &e))
}

/// What writing `input` to `output` leaves out, for `gmap convert` to say (and to refuse
/// without `--lossy`): `"the labels"` of its cells or regions, `"the points"` of its
/// vertices. Empty when the output keeps everything (or cannot hold the input at all,
/// which [`save`] refuses with that reason).
/// Reads the labels of a `.gmap` input (once; [`MapInput::labelled`]).
///
/// [`MapInput::labelled`]: crate::MapInput::labelled
pub fn dropped(input: &Input, output: &Path, o: &SaveOptions) -> Vec<&'static str> {
    let ext = extension(output);
    let graph = is_graph(output);
    let mut out = Vec::new();
    let (labels, keeps_labels) = match input {
        Input::Map(m) => (
            matches!(m.dense_labels(), Some(Ok((_, l))) if !l.is_empty()),
            graph || matches!(ext.as_str(), "gmap" | "vtk"),
        ),
        Input::Arch(x) => (
            (0..x.regions().len()).any(|r| !x.region_labels(r).is_empty()),
            graph || (ext == "gmap" && x.dim() <= gmap_core::labels::MAX_LABELLED_DIM),
        ),
        _ => (false, true),
    };
    if labels && (!keeps_labels || o.boundary) {
        out.push("the labels");
    }
    let points = match input {
        Input::Map(m) => m.map().has_points() && !matches!(ext.as_str(), "gmap" | "moka" | "off" | "vtk"),
        // the regions' points: in an incidence graph's .json, and in a .gmap when every
        // vertex of the cut map is a vertex region with a point (a cut may add vertices)
        Input::Arch(x) if (0..x.regions().len()).any(|r| x.region_point(r).is_some()) => match ext.as_str() {
            "json" if graph => false,
            "gmap" => !matches!(arch_to_labelled(x, o.max_darts, Path::new(""), output), Ok(g) if g.has_points()),
            _ => true,
        },
        _ => false,
    };
    if points {
        out.push("the points");
    }
    // an .off that cannot hold the map is refused for that, first
    if ext == "off" && !o.boundary && input.dim() != 2 {
        out.clear();
    }
    out
}

/// Reads `input` and writes it to `output` (`gmap convert`): the output is checked not to
/// be the input file before anything is read.
pub fn save_file(input: impl AsRef<Path>, output: impl AsRef<Path>, o: &SaveOptions) -> Result<()> {
    let (input, output) = (input.as_ref(), output.as_ref());
    refuse_same_file(input, output)?;
    let opened = crate::input::open_with(input, &crate::input::OpenOptions::max_darts(o.max_darts))?;
    save(&opened, output, o)
}

/// [`save_file`] that first hands what the output drops ([`dropped`]) to `check`, which may
/// refuse (`gmap convert` without `--lossy`).
pub fn save_checked(
    input: impl AsRef<Path>,
    output: impl AsRef<Path>,
    o: &SaveOptions,
    check: impl FnOnce(&[&'static str]) -> Result<()>,
) -> Result<()> {
    let (input, output) = (input.as_ref(), output.as_ref());
    refuse_same_file(input, output)?;
    let opened = crate::input::open_with(input, &crate::input::OpenOptions::max_darts(o.max_darts))?;
    // a complex that cannot be cut into cells is refused for that first
    if let (Input::Arch(x), false) = (&opened, is_graph(output)) {
        arch_to_map(x, o.max_darts, input, output)?;
    }
    check(&dropped(&opened, output, o))?;
    save(&opened, output, o)
}

fn refuse_same_file(input: &Path, output: &Path) -> Result<()> {
    if same_file(input, output) {
        return Err(err!(
            Usage,
            "{}: the output is the input file {}: convert to another file (the input would be replaced)",
            output.display(),
            input.display()
        ));
    }
    Ok(())
}

/// Whether `output` names the file `input` reads (the same path, through `./`, `..` or a
/// symbolic link, or a hard link to it). A `.lex#name` input is the `.lex` file.
fn same_file(input: &Path, output: &Path) -> bool {
    let (file, name) = split_lex_name(input);
    let input = if name.is_some() && !input.exists() { file.as_path() } else { input };
    let (Ok(a), Ok(b)) = (std::fs::metadata(input), std::fs::metadata(output)) else {
        return false;
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if a.dev() == b.dev() && a.ino() == b.ino() {
            return true;
        }
    }
    let _ = (a, b);
    matches!((input.canonicalize(), output.canonicalize()), (Ok(x), Ok(y)) if x == y)
}

fn cannot_write(output: &Path, e: &(dyn std::error::Error + 'static)) -> Error {
    Error::from_source(ErrorKind::Write, e).context(format!("{}: cannot write", output.display()))
}

/// Writes a map in the format named by the extension of `output`.
pub fn save_map(m: &DenseMap, output: &Path) -> Result<()> {
    match extension(output).as_str() {
        "gmap" => gmap_core::io::write_gmap(m, output)?,
        "moka" => gmap_core::io::write_moka(m, output)?,
        "off" if m.dim() == 3 => {
            return Err(err!(
                Unsupported,
                "{}: .off holds 2-maps (surfaces), this map has dimension 3; gmap convert --boundary writes its boundary surface",
                output.display()
            ))
        }
        "off" => gmap_ops::export::write_off(m, output).map_err(|e| cannot_write(output, &e))?,
        "facets" => gmap_ops::export::write_barycentric_facets(m, output)?,
        "vtk" => gmap_ops::export::write_vtk(m, output).map_err(|e| cannot_write(output, &e))?,
        "json" if is_lar(output) => {
            let text = Lar::from_map(m).to_json().map_err(|e| Error::from_source(ErrorKind::Write, &e))?;
            write_text(output, &text)?
        }
        "json" | "dot" | "graphml" => write_graph(&arch_of(m, output)?, output)?,
        other => {
            return Err(err!(
                Unsupported,
                "{}: unsupported output format '.{}'",
                output.display(),
                gmap_core::io::shorten(other.as_bytes(), 40)
            ))
        }
    }
    Ok(())
}

/// Writes a labelled map as `.vtk` (labels as cell data) or as its incidence graph, `.json`
/// or `.dot` (labels on the regions).
fn write_labelled(g: &LabelledGMap, output: &Path) -> Result<()> {
    let (m, labels, _) = gmap_core::to_dense_labels(g);
    match extension(output).as_str() {
        "vtk" => gmap_ops::export::write_vtk_with_labels(&m, &labels, output).map_err(|e| cannot_write(output, &e)),
        ext => {
            let x = ArchComplex::from_map_with_labels(&m, &labels).map_err(|e| {
                Error::from_source(ErrorKind::Precondition, &e)
                    .context(format!("{}: cannot write the incidence graph", output.display()))
            })?;
            let _ = ext;
            write_graph(&x, output)
        }
    }
}

/// Whether the output is an incidence graph: `.json` (not `.lar.json`), `.dot`, `.graphml`.
fn is_graph(p: &Path) -> bool {
    match extension(p).as_str() {
        "json" => !is_lar(p),
        "dot" | "graphml" => true,
        _ => false,
    }
}

/// Writes an incidence graph in the format of the output's extension ([`is_graph`]).
fn write_graph(x: &ArchComplex, output: &Path) -> Result<()> {
    let text = match extension(output).as_str() {
        "dot" => write_dot(x),
        "graphml" => gmap_homology::graphml::write_graphml(x),
        _ => write_json(x),
    };
    write_text(output, &text)
}

/// Whether the output is a LAR file (`.lar.json`) rather than an incidence graph.
fn is_lar(p: &Path) -> bool {
    p.to_string_lossy().to_lowercase().ends_with(".lar.json")
}

/// The architectural complex of a map's cells (AC Remark 3.3), or why it has none.
fn arch_of(m: &DenseMap, output: &Path) -> Result<ArchComplex> {
    ArchComplex::from_map(m).map_err(|e| {
        Error::from_source(ErrorKind::Precondition, &e)
            .context(format!("{}: cannot write the incidence graph", output.display()))
    })
}

fn write_text(path: &Path, text: &str) -> Result<()> {
    gmap_core::io::write_atomic(path, text.as_bytes()).map_err(|e| cannot_write(path, &e))
}

/// Writes an architectural complex: `.json` and `.dot` directly; any other format through
/// the G-map of its cells (the flag construction, gmap-ops), after cutting the regions that
/// are not cells so that the map is the same space ([`crate::arch_cells`]; refused with the
/// region's name where that cannot be done).
pub fn save_arch(x: &ArchComplex, output: &Path, max_darts: Option<u64>) -> Result<()> {
    write_arch(x, Path::new(""), output, max_darts)
}

/// [`save_arch`] of a complex read from `input` (refusals name it first).
fn write_arch(x: &ArchComplex, input: &Path, output: &Path, max_darts: Option<u64>) -> Result<()> {
    match extension(output).as_str() {
        _ if is_graph(output) => write_graph(x, output),
        // a .gmap holds the regions' labels on their cells and the vertices' points
        "gmap" => Ok(gmap_core::io::write_labelled_gmap(&arch_to_labelled(x, max_darts, input, output)?, output)?),
        _ => save_map(&arch_to_map(x, max_darts, input, output)?, output),
    }
}

/// The G-map of an architectural complex's cells ([`crate::arch_cells`]).
/// Refusals name the input first (`input`, when not empty) and say that `output` is not
/// written.
pub(crate) fn arch_to_map(x: &ArchComplex, max_darts: Option<u64>, input: &Path, output: &Path) -> Result<DenseMap> {
    arch_to_flags(x, max_darts, input, output).map(|(map, _, _)| map)
}

/// The G-map of an architectural complex's cells with each cell's labels and each vertex's
/// point: an `i`-cell of the map that is (a piece of) an `i`-region carries that region's
/// labels (`i ≤ 5`) and its string id as the label `id` (unless it has one); the cells that
/// cut a region (its new edges and vertices) carry none.
/// Vertices get their regions' points when every vertex has one. O(darts · n).
pub(crate) fn arch_to_labelled(
    x: &ArchComplex,
    max_darts: Option<u64>,
    input: &Path,
    output: &Path,
) -> Result<LabelledGMap> {
    let (map, flags, origin) = arch_to_flags(x, max_darts, input, output)?;
    let w = map.dim() + 1;
    // the region an i-cell of the map is, when it has the region's dimension
    let region = |k: usize, i: usize| Some(origin[flags[k * w + i] as usize]).filter(|&r| x.region(r).dim == i);
    let (mut g, ids) = LabelledGMap::from_dense_with_attributes(&map);
    let vertices = map.cells(0);
    let points: Option<Vec<[f64; 3]>> =
        vertices.reps.iter().map(|d| region(d.index(), 0).and_then(|r| x.region_point(r))).collect();
    for (c, d) in vertices.reps.iter().enumerate() {
        if let Some(p) = points.as_ref().map(|p| p[c]) {
            g.set_point(ids[d.index()], Some(p));
        }
    }
    for i in 0..=map.dim().min(gmap_core::labels::MAX_LABELLED_DIM) {
        for d in map.cells(i).reps {
            let Some(r) = region(d.index(), i) else { continue };
            let mut l = x.region_labels(r).clone();
            if let (Some(key), None) = (x.region_key(r), l.get("id")) {
                l.set("id", gmap_core::LabelValue::Text(key.to_string()));
            }
            if l.is_empty() {
                continue;
            }
            let at = ids[d.index()];
            let set = match i {
                0 => g.try_set_attribute::<0>(at, l).map(drop),
                1 => g.try_set_attribute::<1>(at, l).map(drop),
                2 => g.try_set_attribute::<2>(at, l).map(drop),
                3 => g.try_set_attribute::<3>(at, l).map(drop),
                4 => g.try_set_attribute::<4>(at, l).map(drop),
                _ => g.try_set_attribute::<5>(at, l).map(drop),
            };
            set.map_err(|e| err!(Compute, "the labels of region {}: {e}", x.region_name(r)))?;
        }
    }
    Ok(g)
}

/// [`arch_to_map`] with the flags of its darts and the region of each cell of the face
/// poset the map was made from (`FacePoset::to_gmap_with_flags`).
fn arch_to_flags(
    x: &ArchComplex,
    max_darts: Option<u64>,
    input: &Path,
    output: &Path,
) -> Result<(DenseMap, Vec<u32>, Vec<usize>)> {
    let limit = max_darts.unwrap_or_else(|| gmap_ops::import::default_max_darts(x.dim()));
    let not_written = format!("(nothing written to {})", output.display());
    let named = |e: Error| {
        let e = e.flattened(&format!(" {not_written}"));
        if input.as_os_str().is_empty() {
            e
        } else {
            e.context(input.display().to_string())
        }
    };
    let cells = crate::arch_cells::cells(x).map_err(named)?;
    let (map, flags) = cells.poset.to_gmap_with_flags(limit).map_err(|e| match e {
        PosetError::TooManyDarts { .. } | PosetError::MemoryLimit(_) => {
            err!(Limit, "{}: {e}; raise the limit with --max-darts N or --max-memory BYTES", output.display())
        }
        e => named(err!(
            Precondition,
            "the complex is not the face poset of a regular cell complex: {}",
            crate::arch_cells::name_poset_error(x, &cells, &e)
        )),
    })?;
    crate::arch_cells::check_solids(x, &cells, limit).map_err(named)?;
    Ok((map, flags, cells.origin))
}
