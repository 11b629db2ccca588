//! Writing an input in another format (`gmap convert`), chosen by the output's extension.
//!
//! Outputs: `.gmap` (with the points, and from a `.gmap` input the cell labels too) and
//! `.moka` (gmap-core io), `.off` (2-maps with points), `.facets` (a simplicial complex's
//! facets; of a map, the barycentric subdivision: one simplex per dart), `.cub` (a full
//! cubical set's cubes), `.vtk` (maps of dimension ≤ 3 with points; from a
//! `.gmap`, the cell labels as cell data), the incidence graph as `.json` or `.dot` (from a
//! `.gmap`, each region with the labels of its cell) and LAR's `.lar.json`. A simplicial
//! complex writes `.facets` itself and the map formats through its G-map; an architectural
//! complex writes `.json` and `.dot`
//! itself and the other formats through the G-map of its face poset. Every writer goes
//! through a temporary file and a rename, so a failure leaves no partial output.

use std::path::Path;

use gmap_core::{DenseMap, LabelledGMap};
use gmap_homology::arch::ArchComplex;
use gmap_ops::import::PosetError;

use crate::error::{err, Error, ErrorKind, Result};
use crate::formats::{format_of, output_format, Writer};
use crate::input::{extension, split_lex_name, Input};
use crate::write;

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
    /// write an output that changes the space anyway (`gmap convert --lossy`, Python's
    /// `save(lossy=True)`): the G-map of a complex or cubical set pinched at a cell, which
    /// pulls the cell apart. Without it [`save`] refuses such an output naming the cell and
    /// the formats that keep it.
    pub lossy: bool,
    /// write the binary form of the output's format (`gmap convert --binary`): Gmsh's
    /// binary `.msh` 4.1; refused for other formats
    pub binary: bool,
}

impl SaveOptions {
    /// Options with a dart limit.
    pub fn max_darts(max_darts: Option<u64>) -> Self {
        SaveOptions { max_darts, max_cells: None, boundary: false, lossy: false, binary: false }
    }
}

/// Writes `input` to `output` in the format named by the output's extension (the writer of
/// its row in [`crate::formats::FORMATS`]). Refuses to write over the file the input was
/// read from, and a kind of input the format cannot hold.
///
/// An output written through a G-map that would be another space (a simplicial complex or
/// cubical set pinched at a cell: two triangles sharing only a vertex) is refused naming the
/// cell and the formats that keep it, unless `o.lossy` ([`write_checked`] says what it
/// changes).
pub fn save(input: &Input, output: impl AsRef<Path>, o: &SaveOptions) -> Result<()> {
    save_noting(input, output.as_ref(), o, "write it anyway with --lossy (Python: save(lossy=True))").map(drop)
}

/// [`save`], returning what the output changes of the space when `o.lossy` let it through;
/// `hint` ends a refusal of a change of space.
fn save_noting(input: &Input, output: &Path, o: &SaveOptions, hint: &str) -> Result<Option<String>> {
    refuse_same_file(input.path(), output)?;
    if o.boundary {
        return save_boundary(input, output).map(|()| None);
    }
    if let Input::Image(img) = input {
        return match format_of(output).map(|f| f.writer) {
            Some(Writer::Image(write)) => write(img, output).map(|()| None),
            _ => Err(err!(
                Unsupported,
                "{}: an image is written as .npy or .complex, not '.{}'",
                input.path().display(),
                gmap_core::io::shorten(extension(output).as_bytes(), 40)
            )),
        };
    }
    let writer = output_format(output)?.writer;
    if o.binary {
        // the formats with a binary form: .msh
        return match writer {
            Writer::Map { cubes, facets, .. } if extension(output).eq_ignore_ascii_case("msh") => save_through_map(
                input,
                output,
                (o, hint),
                (write::msh_binary, Some(write::labelled_msh_binary), cubes, facets),
            ),
            _ => Err(err!(
                Usage,
                "{}: --binary writes .msh only, not '.{}'",
                output.display(),
                gmap_core::io::shorten(extension(output).as_bytes(), 40)
            )),
        };
    }
    match writer {
        Writer::Graph(text) => write::text(output, &text(graph_of(input, output, o)?.as_ref())).map(|()| None),
        Writer::Map { map, labelled, cubes, facets } => {
            save_through_map(input, output, (o, hint), (map, labelled, cubes, facets))
        }
        Writer::Cubes(write) => match input {
            Input::Cubical(set) => write(set, output).map(|()| None),
            other => Err(err!(
                Unsupported,
                "{}: '.{}' holds cubical sets, not a {}",
                output.display(),
                extension(output),
                other.kind()
            )),
        },
        Writer::Image(_) | Writer::None => Err(err!(
            Unsupported,
            "{}: unsupported output format '.{}' for a {}: it holds images",
            output.display(),
            extension(output),
            input.kind()
        )),
    }
}

/// The incidence graph of any input ([`graph_of`]), its failures naming the input (room
/// graphs, [`crate::dual`]).
pub(crate) fn incidence_graph(input: &Input, max_cells: Option<u64>) -> Result<std::borrow::Cow<'_, ArchComplex>> {
    let o = SaveOptions { max_cells, ..SaveOptions::default() };
    graph_of(input, input.path(), &o)
}

/// The incidence graph of any input: a map's cells (with the labels of a labelled file), a
/// complex's face poset, an architectural complex itself.
fn graph_of<'a>(input: &'a Input, output: &Path, o: &SaveOptions) -> Result<std::borrow::Cow<'a, ArchComplex>> {
    use std::borrow::Cow;
    let cannot = |e: gmap_homology::arch::FromMapError| {
        Error::from_source(ErrorKind::Precondition, e)
            .context(format!("{}: cannot write the incidence graph", output.display()))
    };
    Ok(match input {
        Input::Map(m) => match m.labelled() {
            Some(g) => {
                let (d, labels, _) = gmap_core::to_dense_labels(g?);
                Cow::Owned(ArchComplex::from_map_with_labels(&d, &labels).map_err(cannot)?)
            }
            None => Cow::Owned(ArchComplex::from_map(m.map()).map_err(cannot)?),
        },
        Input::Simplicial(sc) => {
            Cow::Owned(crate::graph::simplicial(sc, o.max_cells, &sc.path().display().to_string())?)
        }
        Input::Cubical(set) => Cow::Owned(crate::graph::cubical(set, false, &set.path().display().to_string())?),
        Input::Arch(x) => Cow::Borrowed(x.get()),
        Input::Image(_) => return Err(err!(Unsupported, "{}: an image has no incidence graph", output.display())),
    })
}

/// Writes any input in a map format: a map as it is (with its labels and points where the
/// format has a writer for them), a simplicial complex through its G-map, an architectural
/// complex through the G-map of its cells, a full cubical set as its cubes or the G-map of
/// their union. A G-map that would pull a pinched cell apart is refused without `o.lossy`;
/// with it, what changes is returned.
fn save_through_map(
    input: &Input,
    output: &Path,
    (o, hint): (&SaveOptions, &str),
    (map, labelled, cubes, facets): (
        write::MapFn,
        Option<write::LabelledFn>,
        Option<write::CubesFn>,
        Option<write::FacetsFn>,
    ),
) -> Result<Option<String>> {
    let done = |r: Result<()>| r.map(|()| None);
    match input {
        Input::Map(m) => done(match (labelled, m.labelled()) {
            (Some(write), Some(g)) => write(g?, output),
            _ => map(m.map(), output),
        }),
        Input::Simplicial(sc) => match facets {
            Some(write) => done(write(sc, output)),
            None => {
                let m = sc.to_gmap_within(o.max_darts)?;
                let change = crate::pinch::check(crate::pinch::simplicial(sc, &m), input, output, o.lossy, hint)?;
                map(&m, output).map(|()| change)
            }
        },
        Input::Arch(x) => done(match labelled {
            Some(write) => write(&arch_to_labelled(x, o.max_darts, x.path(), output)?, output),
            None => map(&arch_to_map(x, o.max_darts, x.path(), output)?, output),
        }),
        // a .vtk of voxels and a G-map of d-cells hold the cubes only
        Input::Cubical(set) if !set.is_full() => {
            let what = if cubes.is_some() { ".vtk (voxels)" } else { "a G-map of its cubes" };
            let why = set.require_full(what).err().map(|e| e.to_string()).unwrap_or_default();
            Err(err!(Unsupported, "{}: {why}; write .json, .dot or .graphml (every cell)", set.path().display())
                .with_path(set.path()))
        }
        Input::Cubical(set) => match cubes {
            Some(write) => done(write(set, output)),
            None => {
                let pinched = set.pinched_cell(false).map(|(cell, groups)| crate::pinch::Pinch {
                    cell: format!("the cell {cell}"),
                    item: None,
                    groups,
                    pieces: "cubes",
                    shared: "facet",
                });
                let change = crate::pinch::check(pinched, input, output, o.lossy, hint)?;
                let m = set
                    .gmap(false)
                    .map_err(|e| Error::from_source(ErrorKind::Limit, e).context(set.path().display().to_string()))?;
                map(&m, output).map(|()| change)
            }
        },
        Input::Image(_) => {
            Err(err!(Unsupported, "{}: an image is written as .npy or .complex", input.path().display()))
        }
    }
}

/// Writes the boundary surface of a 3-map (or of the G-map of a simplicial complex) as `.off`.
fn save_boundary(input: &Input, output: &Path) -> Result<()> {
    if format_of(output).map(|f| f.extension) != Some("off") {
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
    write::boundary_off(&m, output)
}

/// What writing `input` to `output` leaves out, for `gmap convert` to say (and to refuse
/// without `--lossy`): `"the labels"` of its cells or regions, `"the points"` of its
/// vertices, as the output's row in [`crate::formats::FORMATS`] says what it keeps. Empty
/// when the output keeps everything (or cannot hold the input at all, which [`save`]
/// refuses with that reason). Reads the labels of a `.gmap` input (once;
/// [`MapInput::labelled`]).
///
/// [`MapInput::labelled`]: crate::MapInput::labelled
pub fn dropped(input: &Input, output: &Path, o: &SaveOptions) -> Vec<&'static str> {
    let Some(f) = format_of(output).filter(|f| f.is_written()) else { return Vec::new() };
    // a format that cannot hold the input drops nothing: save refuses it with the reason
    let holds = match f.writer {
        Writer::Cubes(_) => matches!(input, Input::Cubical(_)),
        Writer::Image(_) => matches!(input, Input::Image(_)),
        _ => true,
    };
    if !holds {
        return Vec::new();
    }
    let with_labels = matches!(f.writer, Writer::Map { labelled: Some(_), .. });
    let mut out = Vec::new();
    let (labels, keeps_labels) = match input {
        Input::Map(m) => (matches!(m.dense_labels(), Some(Ok((_, l))) if !l.is_empty()), f.is_graph() || with_labels),
        Input::Arch(x) => (
            (0..x.regions().len()).any(|r| !x.region_labels(r).is_empty()),
            f.is_graph() || (with_labels && x.dim() <= gmap_core::labels::MAX_LABELLED_DIM),
        ),
        _ => (false, true),
    };
    if labels && (!keeps_labels || o.boundary) {
        out.push("the labels");
    }
    let points = match input {
        // a map's incidence graph has no points
        Input::Map(m) => m.map().has_points() && (f.is_graph() || !f.keeps_points),
        // the regions' points: in an incidence graph that keeps them, and in a map format
        // with a writer of points and labels when every vertex of the cut map is a vertex
        // region with a point (a cut may add vertices)
        Input::Arch(x) if (0..x.regions().len()).any(|r| x.region_point(r).is_some()) => {
            if f.is_graph() {
                !f.keeps_points
            } else {
                !(with_labels
                    && f.keeps_points
                    && matches!(arch_to_labelled(x, o.max_darts, Path::new(""), output), Ok(g) if g.has_points()))
            }
        }
        _ => false,
    };
    if points {
        out.push("the points");
    }
    // the filtration values a valued .facets file gives its facets: no writer keeps them
    if matches!(input, Input::Simplicial(s) if s.facet_values().is_some()) {
        out.push("the facet values");
    }
    // an .off that cannot hold the map is refused for that, first
    if f.extension == "off" && !o.boundary && input.dim() != 2 {
        out.clear();
    }
    out
}

/// Reads `input` and writes it to `output` (`gmap convert`): the output is checked not to
/// be the input file before anything is read.
pub fn save_file(input: impl AsRef<Path>, output: impl AsRef<Path>, o: &SaveOptions) -> Result<()> {
    let (input, output) = (input.as_ref(), output.as_ref());
    refuse_same_file(input, output)?;
    let opened = crate::open_with(input, &crate::input::OpenOptions::max_darts(o.max_darts))?;
    save(&opened, output, o)
}

/// Reads `input` and writes it to `output` under the rule of [`write_checked`] (`gmap
/// convert`): the output is checked not to be the input file before anything is read.
pub fn save_checked(
    input: impl AsRef<Path>,
    output: impl AsRef<Path>,
    o: &SaveOptions,
    hint: &str,
) -> Result<Vec<String>> {
    let (input, output) = (input.as_ref(), output.as_ref());
    refuse_same_file(input, output)?;
    let opened = crate::open_with(input, &crate::input::OpenOptions::max_darts(o.max_darts))?;
    // a complex that cannot be cut into cells is refused for that first
    if let (Input::Arch(x), false) = (&opened, format_of(output).is_some_and(|f| f.is_graph())) {
        arch_to_map(x.get(), o.max_darts, input, output)?;
    }
    write_checked(&opened, output, o, hint)
}

/// The rule of every write of `gmap convert` and of the Python package's `save`: an output
/// that drops what the input carries ([`dropped`]: its labels, its points) or that is
/// another space (a G-map pulling a pinched cell apart, see [`save`]) is refused, naming
/// what, unless `o.lossy`; `hint` says how to write it anyway in the caller's terms
/// (`convert with --lossy to write it anyway`). Returns what the written output changes,
/// one sentence each, for the caller to say (stderr, a Python warning).
pub fn write_checked(input: &Input, output: &Path, o: &SaveOptions, hint: &str) -> Result<Vec<String>> {
    let dropped = dropped(input, output, o);
    let mut said = Vec::new();
    if !dropped.is_empty() {
        let source = match input.path().as_os_str().is_empty() {
            true => format!("the {}", input.kind()),
            false => input.path().display().to_string(),
        };
        let what = format!("{} drops {} of {source}", output.display(), dropped.join(", "));
        if !o.lossy {
            return Err(err!(Usage, "{what}; {hint}").with_path(output));
        }
        said.push(what);
    }
    refuse_same_file(input.path(), output)?;
    said.extend(save_noting(input, output, o, hint)?);
    Ok(said)
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

/// Writes a map in the format named by the extension of `output` (its plain map writer: no
/// labels).
pub fn save_map(m: &DenseMap, output: &Path) -> Result<()> {
    match output_format(output)?.writer {
        Writer::Map { map, .. } => map(m, output),
        Writer::Graph(text) => {
            let x = ArchComplex::from_map(m).map_err(|e| {
                Error::from_source(ErrorKind::Precondition, e)
                    .context(format!("{}: cannot write the incidence graph", output.display()))
            })?;
            write::text(output, &text(&x))
        }
        Writer::Cubes(_) => {
            Err(err!(Unsupported, "{}: '.{}' holds cubical sets, not a map", output.display(), extension(output)))
        }
        Writer::Image(_) | Writer::None => Err(err!(
            Unsupported,
            "{}: unsupported output format '.{}' for a map: it holds images",
            output.display(),
            extension(output)
        )),
    }
}

/// Writes an architectural complex: `.json`, `.dot` and `.graphml` directly; any other
/// format through the G-map of its cells (the flag construction, gmap-ops), after cutting
/// the regions that are not cells so that the map is the same space (the facade's `arch_cells`;
/// refused with the region's name where that cannot be done).
pub fn save_arch(x: &ArchComplex, output: &Path, max_darts: Option<u64>) -> Result<()> {
    let o = SaveOptions::max_darts(max_darts);
    save(&Input::Arch(crate::Sourced::new(x.clone())), output, &o)
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
