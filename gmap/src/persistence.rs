//! Persistent homology through the facade: [`persistence`] on an opened [`Input`] (a G-map
//! with a numeric label per cell, a cubical set as a 0/1 image) and [`persistence_file`],
//! which also reads what only persistence uses: grey images (`.npy`, DIPHA's `.complex`,
//! `.pgm`, `.png`) and `.facets` files with a value per facet. [`lower_star`] and
//! [`lower_star_file`] filter a simplicial complex by [`VertexValues`] instead (its lower
//! stars). The engine is `gmap_homology::persistence`; this module picks the reader and the
//! filtration.

use std::collections::HashMap;
use std::path::Path;

use gmap_homology::persistence::{
    cubical_persistence, morse_persistence, plot, Construction, CubicalOptions, Diagram, FilteredComplex, SimplexValues,
};
use gmap_ops::import::image::{Image, Order};
use gmap_ops::import::SimplicialComplex;

use crate::input::extension;
use crate::{Error, ErrorKind, Input, Result};

/// What `gmap persistence` computes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PersistenceOptions {
    /// coefficients `Z/p` (default 2)
    pub field: u32,
    /// for images: T (values on top cells, GUDHI's default) or V (on vertices, CubicalRipser's)
    pub construction: Construction,
    /// superlevel sets: from the largest value down (images and complexes)
    pub superlevel: bool,
    /// for images: identify the opposite faces of the box
    pub periodic: bool,
    /// a representative cycle per pair
    pub cycles: bool,
    /// for a `.gmap`: the numeric label giving each cell its value (default `value`)
    pub label: String,
}

impl Default for PersistenceOptions {
    fn default() -> Self {
        PersistenceOptions {
            field: 2,
            construction: Construction::T,
            superlevel: false,
            periodic: false,
            cycles: false,
            label: "value".into(),
        }
    }
}

/// A diagram with the 2-D image it came from, if it did (to draw cycles over).
#[derive(Clone, Debug)]
pub struct Persistence {
    /// the diagram
    pub diagram: Diagram,
    /// `(rows, cols, values)` of a 2-D image input
    pub image: Option<(usize, usize, Vec<f64>)>,
    /// whether the image's pixels are vertices (V-construction)
    pub vertex_centred: bool,
}

/// The engine's refusal as the facade's error: a value or option that makes no filtration
/// is a usage error, a complex past the engine's sizes a limit.
fn compute(e: gmap_homology::persistence::PersistenceError) -> Error {
    use gmap_homology::persistence::PersistenceError as E;
    let kind = match e {
        E::TooLarge(_) => ErrorKind::Limit,
        E::BadInput(_) | E::BadOption(_) => ErrorKind::Usage,
        _ => ErrorKind::Compute,
    };
    Error::from_source(kind, e)
}

/// Refuses, before any work, an image whose diagram would not fit the memory limit
/// ([`gmap_homology::persistence::memory_estimate`], the limit of `--max-memory`).
/// `shape` is in the engine's order (the values' fastest axis last).
pub fn check_image_memory(shape: &[usize], opts: &PersistenceOptions) -> Result<()> {
    let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
    let what = format!("the persistence diagram of a {} image", dims.join("×"));
    let estimate = gmap_homology::persistence::memory_estimate(shape, &cubical_options(opts));
    Ok(gmap_core::resources::check_memory(&what, estimate)?)
}

/// An image's pixels for [`image_persistence`], C order: held as `f64`, or read one by one
/// (a memory-mapped file, converted as read).
#[derive(Clone, Copy)]
pub enum Pixels<'a> {
    /// every value, in memory
    Slice(&'a [f64]),
    /// pixel `i`'s value
    Read(&'a (dyn Fn(usize) -> f64 + Sync)),
    /// every value, C order, written by the function into memory [`image_persistence`]
    /// allocates: values that are had only by copying them (a strided numpy view), copied
    /// when the whole grid fits, or past its limit when the copy does (the lower stars are
    /// then read from the copy); else refused with the whole grid's estimate before
    /// anything is copied
    Copied(&'a (dyn Fn(&mut [f64]) + Sync)),
}

/// The diagram of the image of shape `shape` (the engine's order, the fastest axis last).
/// When its estimate fits the memory limit ([`check_image_memory`]) the whole grid is
/// built (the values copied once if they are read one by one); past it, the Morse complex
/// of its lower stars ([`gmap_homology::persistence::gradient`]) is computed from the pixels
/// as they are read, holding only its critical cells: refused with the estimate if the
/// image is periodic, has more than 4 axes or cycles are asked for (that route takes none
/// of these), and with the count if its critical cells pass the limit.
pub fn image_persistence(shape: &[usize], pixels: Pixels<'_>, opts: &PersistenceOptions) -> Result<Diagram> {
    let engine = cubical_options(opts);
    let copy = |fill: &dyn Fn(&mut [f64])| -> Result<Vec<f64>> {
        let n = shape.iter().try_fold(1usize, |p, &s| p.checked_mul(s));
        let mut v = Vec::new();
        if n.is_none_or(|n| v.try_reserve_exact(n).is_err()) {
            return Err(Error::new(ErrorKind::Limit, format!("cannot hold the values of an image of shape {shape:?}")));
        }
        v.resize(n.unwrap_or(0), 0.0);
        fill(&mut v);
        Ok(v)
    };
    match check_image_memory(shape, opts) {
        Ok(()) => {
            let owned: Vec<f64>;
            let values = match pixels {
                Pixels::Slice(v) => v,
                Pixels::Read(f) => {
                    owned = (0..shape.iter().product()).map(f).collect();
                    &owned
                }
                Pixels::Copied(fill) => {
                    owned = copy(fill)?;
                    &owned
                }
            };
            cubical_persistence(shape, values, &engine).map_err(compute)
        }
        Err(e) if opts.periodic || opts.cycles || shape.len() > 4 => Err(e.flattened(
            "; past the limit an image is computed from its lower stars, which takes 1 to 4 axes and neither periodic images nor cycles",
        )),
        Err(whole) => {
            let limit = gmap_core::resources::max_memory();
            let diagram = match pixels {
                Pixels::Slice(v) => morse_persistence(shape, &|i| v[i], &engine, limit),
                Pixels::Read(f) => morse_persistence(shape, f, &engine, limit),
                Pixels::Copied(fill) => {
                    // the copy, with the program itself, must fit under the limit
                    let bytes = shape.iter().try_fold(8u64, |b, &s| b.checked_mul(s as u64));
                    let bytes = bytes.and_then(|b| b.checked_add(gmap_homology::persistence::image::PROCESS_BYTES));
                    if bytes.is_none_or(|b| b > limit) {
                        return Err(whole);
                    }
                    let v = copy(fill)?;
                    morse_persistence(shape, &|i| v[i], &engine, limit)
                }
            };
            diagram.map_err(compute)
        }
    }
}

/// The engine's options for an image (`gmap_homology::persistence::cubical_persistence`);
/// public for callers that hold the values themselves (the Python package's numpy arrays).
pub fn cubical_options(o: &PersistenceOptions) -> CubicalOptions {
    CubicalOptions {
        construction: o.construction,
        superlevel: o.superlevel,
        periodic: o.periodic,
        field: o.field,
        cycles: o.cycles,
    }
}

/// Refuses the options that only images take (periodic, the V-construction) for a
/// complex filtered by its own values, rather than ignore them.
fn complex_options(opts: &PersistenceOptions, what: &str) -> Result<()> {
    let refused = if opts.periodic {
        Some("periodic applies to images")
    } else if opts.construction == Construction::V {
        Some("the V-construction applies to images")
    } else {
        None
    };
    match refused {
        Some(why) => Err(Error::new(ErrorKind::Unsupported, format!("persistence of {what}: {why}"))),
        None => Ok(()),
    }
}

/// The diagram of an opened input: a G-map by the label `opts.label` of its cells (a
/// `.gmap` file), an architectural complex (`.json`) by the label `opts.label` of its
/// regions (the chain complex `gmap homology` computes for it), a cubical set as the image
/// with 0 on its cubes and 1 elsewhere, a simplicial complex by the values its `.facets`
/// file gives its facets ([`Sourced::facet_values`](crate::Sourced::facet_values), as
/// [`persistence_file`] reads them; without them it is refused: [`lower_star`] takes
/// values per vertex). With
/// `opts.superlevel` a G-map or an architectural complex is filtered from the largest value
/// down (a cell lowered to its faces' minimum); both refuse the options only images take
/// (periodic, the V-construction).
pub fn persistence(input: &Input, opts: &PersistenceOptions) -> Result<Diagram> {
    match input {
        Input::Map(m) => {
            complex_options(opts, "a G-map").map_err(|e| e.with_path(m.path()))?;
            let g = m.labelled().ok_or_else(|| {
                Error::new(ErrorKind::Unsupported, "a map carries values only as labels in a .gmap file")
                    .with_path(m.path())
            })??;
            let f = if opts.superlevel {
                FilteredComplex::from_labelled_gmap_superlevel(g, &opts.label)
            } else {
                FilteredComplex::from_labelled_gmap(g, &opts.label)
            }.map_err(|e| compute(e).with_path(m.path()))?;
            f.diagram(opts.field, opts.cycles).map_err(compute)
        }
        Input::Cubical(c) => {
            c.require_full("the image of 0 on the cubes and 1 elsewhere")
                .map_err(|e| Error::new(ErrorKind::Unsupported, e.to_string()).with_path(c.path()))?;
            // the set's cubes, axis 0 fastest, as a C-order array of the reversed shape
            let mut shape = c.shape().to_vec();
            shape.reverse();
            let bits = c.bits();
            let value = |i: usize| if bits[i] != 0 { 0.0 } else { 1.0 };
            image_persistence(&shape, Pixels::Read(&value), opts).map_err(|e| e.with_path(c.path()))
        }
        Input::Image(img) => {
            let mut shape = img.shape().to_vec();
            if img.order() == Order::Fortran {
                shape.reverse();
            }
            let value = |i: usize| img.value(i);
            image_persistence(&shape, Pixels::Read(&value), opts).map_err(|e| e.with_path(img.path()))
        }
        // a `.facets` file's values per facet are the filtration it was opened with
        Input::Simplicial(s) => match s.facet_values() {
            Some(values) => facet_persistence(s, values, opts).map_err(|e| e.with_path(s.path())),
            None => Err(Error::new(
                ErrorKind::Unsupported,
                "a simplicial complex needs values: a .facets file with `: VALUE` after each facet, or a value per vertex (--vertex-values, vertex_values=)",
            )
            .with_path(s.path())),
        },
        Input::Arch(a) => {
            complex_options(opts, "an architectural complex").map_err(|e| e.with_path(a.path()))?;
            let f = if opts.superlevel {
                FilteredComplex::from_arch_superlevel(a, &opts.label)
            } else {
                FilteredComplex::from_arch(a, &opts.label)
            }.map_err(|e| compute(e).with_path(a.path()))?;
            f.diagram(opts.field, opts.cycles).map_err(compute)
        }
    }
}

/// Reads `path` and computes its diagram: images by content (`.npy`, `.complex`, `.pgm`,
/// `.png`, Perseus cubical `.txt`), `.facets` with values, Perseus simplicial `.txt` (a
/// value per simplex, a face taking the minimum of its cofaces' as GUDHI's `insert` does), anything else through [`crate::open`] and
/// [`persistence`].
pub fn persistence_file(path: &Path, opts: &PersistenceOptions) -> Result<Persistence> {
    read_and_compute(path, opts).map_err(|e| naming(e, path))
}

/// An error that names `path` in its text (once) and carries it.
fn naming(e: Error, path: &Path) -> Error {
    e.about_file(path)
}

fn read_and_compute(path: &Path, opts: &PersistenceOptions) -> Result<Persistence> {
    // a `.facets` file's values per facet are read with it (an opened complex has none)
    if crate::formats::format_of(path).is_some_and(|f| f.extension == "facets") {
        let (sc, values) = read_valued(path)?;
        let values = values.ok_or_else(|| {
            Error::new(
                ErrorKind::Unsupported,
                "no values: write `: VALUE` after each facet, or give a value per vertex (--vertex-values)",
            )
            .with_path(path)
        })?;
        let diagram = facet_persistence(&sc, &values, opts).map_err(|e| e.with_path(path))?;
        return Ok(Persistence { diagram, image: None, vertex_centred: false });
    }
    // a Perseus simplicial file's values per simplex are read with it (an opened complex has none)
    if crate::formats::format_of(path).is_some_and(|f| f.extension == "txt") {
        if let gmap_ops::import::perseus::Perseus::Simplicial(simplices, values) = perseus_file(path)? {
            let diagram = given_facet_persistence(simplices, &values, opts).map_err(|e| e.with_path(path))?;
            return Ok(Persistence { diagram, image: None, vertex_centred: false });
        }
    }
    match crate::open(path)? {
        Input::Image(img) => image_file(&img, path, opts),
        input => Ok(Persistence { diagram: persistence(&input, opts)?, image: None, vertex_centred: false }),
    }
}

/// The diagram of a grey image read from `path`; a 2-D image with cycles is kept to draw
/// them over.
fn image_file(img: &Image, path: &Path, opts: &PersistenceOptions) -> Result<Persistence> {
    let mut shape = img.shape().to_vec();
    if img.order() == Order::Fortran {
        shape.reverse();
    }
    let value = |i: usize| img.value(i);
    // its values are read once, and the same copy is the whole grid's (cycles come from no
    // other route; past the limit nothing is read before the refusal)
    let keep = shape.len() == 2 && img.order() == Order::C && opts.cycles;
    let kept: Option<Vec<f64>> =
        (keep && check_image_memory(&shape, opts).is_ok()).then(|| (0..img.len()).map(value).collect());
    let pixels = match &kept {
        Some(v) => Pixels::Slice(v),
        None => Pixels::Read(&value),
    };
    let diagram = image_persistence(&shape, pixels, opts).map_err(|e| e.with_path(path))?;
    let image = kept.map(|v| (shape[0], shape[1], v));
    Ok(Persistence { diagram, image, vertex_centred: opts.construction == Construction::V })
}

/// A `.facets` file's complex and its values per facet, if it has them.
fn read_valued(path: &Path) -> Result<(SimplicialComplex, Option<Vec<f64>>)> {
    gmap_ops::import::simplicial::read_valued_facets(path)
        .map_err(|e| Error::from_source(ErrorKind::Parse, e).naming_path(path))
}

/// The diagram of a simplicial complex filtered by `values`, sublevel or superlevel as
/// `opts` says; refuses the options of images.
fn simplicial_diagram(sc: &SimplicialComplex, values: SimplexValues<'_>, opts: &PersistenceOptions) -> Result<Diagram> {
    complex_options(opts, "a simplicial complex")?;
    let facets: Vec<Vec<u64>> = sc.facets().map(<[u64]>::to_vec).collect();
    let f = if opts.superlevel {
        FilteredComplex::from_simplices_superlevel(&facets, values)
    } else {
        FilteredComplex::from_simplices(&facets, values)
    };
    f.map_err(compute)?.diagram(opts.field, opts.cycles).map_err(compute)
}

/// The diagram of a simplicial complex with `values[i]` on its i-th facet, in the order of
/// [`SimplicialComplex::facets`]; a face takes the minimum of its facets' values (GUDHI's
/// `SimplexTree`); with `opts.superlevel`, from the largest value down, a face taking the
/// maximum. Refuses a count of values other than the facets' and the options of images
/// (periodic, the V-construction).
pub fn facet_persistence(sc: &SimplicialComplex, values: &[f64], opts: &PersistenceOptions) -> Result<Diagram> {
    let facets = sc.facets().count();
    if values.len() != facets {
        return Err(Error::new(
            ErrorKind::Usage,
            format!("{} values for {facets} facets: give one value per facet", values.len()),
        ));
    }
    simplicial_diagram(sc, SimplexValues::PerSimplex(values), opts)
}

/// The diagram of the simplicial complex of `facets` with `values[k]` on `facets[k]`, in
/// the order given (the complex puts its largest facets first: each value follows its
/// facet, by the facet's place in the input); a face takes the minimum of its facets'
/// values (GUDHI's `SimplexTree::insert`), with `opts.superlevel` the maximum. Refuses a
/// count of values other than the facets', the errors of
/// [`SimplicialComplex::from_facets`] (a repeated vertex or facet) and the options of
/// images.
pub fn given_facet_persistence(facets: Vec<Vec<u64>>, values: &[f64], opts: &PersistenceOptions) -> Result<Diagram> {
    if values.len() != facets.len() {
        return Err(Error::new(
            ErrorKind::Usage,
            format!("{} values for {} facets: give one value per facet", values.len(), facets.len()),
        ));
    }
    let sc = SimplicialComplex::from_facets(facets).map_err(|e| Error::from_source(ErrorKind::Parse, e))?;
    // facet k of the input is on line k + 1
    let ordered: Vec<f64> = sc.facet_lines().map(|line| values[line - 1]).collect();
    facet_persistence(&sc, &ordered, opts)
}

/// The diagram of the image of shape `shape` (the engine's order, the fastest axis last)
/// whose axis `k` wraps when `periodic[k]` (GUDHI's `periodic_dimensions`), `opts.periodic`
/// ignored. All axes alike go to [`image_persistence`]; otherwise each axis that does not
/// wrap gets one more layer of cells valued `+inf` (`-inf` with `opts.superlevel`) and the
/// whole box wraps: its sublevel sets at every finite value are those of the box with
/// those axes open, so the pairs are the same, and a cycle's or a pair's cells keep their
/// coordinates (the layer comes after the last cell of its axis and holds none of them: a
/// cell of the layer enters at infinity). Refuses `periodic` of another length than
/// `shape` and values other than one per pixel.
pub fn axes_periodic_persistence(
    shape: &[usize],
    values: &[f64],
    periodic: &[bool],
    opts: &PersistenceOptions,
) -> Result<Diagram> {
    if periodic.len() != shape.len() {
        return Err(Error::new(
            ErrorKind::Usage,
            format!("{} periodic flags for an image of {} axes: give one per axis", periodic.len(), shape.len()),
        ));
    }
    if shape.iter().try_fold(1usize, |p, &s| p.checked_mul(s)) != Some(values.len()) {
        return Err(Error::new(
            ErrorKind::Usage,
            format!("{} values for an image of shape {shape:?}: give one per pixel", values.len()),
        ));
    }
    let mut o = opts.clone();
    if periodic.iter().all(|&p| p) || periodic.iter().all(|&p| !p) {
        o.periodic = periodic.first().copied().unwrap_or(false);
        return image_persistence(shape, Pixels::Slice(values), &o);
    }
    o.periodic = true;
    let padded: Vec<usize> = shape.iter().zip(periodic).map(|(&s, &p)| if p { s } else { s + 1 }).collect();
    // a periodic box is computed whole: its estimate first, before the copy is made
    check_image_memory(&padded, &o)?;
    let wall = if opts.superlevel { f64::NEG_INFINITY } else { f64::INFINITY };
    let n = padded.iter().try_fold(1usize, |p, &s| p.checked_mul(s));
    let mut v = Vec::new();
    if n.is_none_or(|n| v.try_reserve_exact(n).is_err()) {
        return Err(Error::new(ErrorKind::Limit, format!("cannot hold the values of an image of shape {padded:?}")));
    }
    let mut at = vec![0usize; shape.len()];
    let (mut src, total) = (0usize, n.unwrap_or(0));
    for _ in 0..total {
        if at.iter().zip(shape).all(|(&i, &s)| i < s) {
            v.push(values[src]);
            src += 1;
        } else {
            v.push(wall);
        }
        // the next index in C order (the last axis fastest)
        for k in (0..at.len()).rev() {
            at[k] += 1;
            if at[k] < padded[k] {
                break;
            }
            at[k] = 0;
        }
    }
    image_persistence(&padded, Pixels::Slice(&v), &o)
}

/// Reads a Perseus file, cubical (GUDHI's `perseus_file`: the sizes, the first axis
/// fastest, which axes wrap, the top cells' values in that order) or simplicial (each
/// simplex with its birth value).
pub fn perseus_file(path: &Path) -> Result<gmap_ops::import::perseus::Perseus> {
    gmap_ops::import::perseus::read_perseus(path).map_err(|e| Error::from_source(ErrorKind::Parse, e).naming_path(path))
}

/// Reads a Perseus cubical file ([`perseus_file`]); a simplicial one is refused.
pub fn perseus_cubical(path: &Path) -> Result<gmap_ops::import::perseus::PerseusCubical> {
    match perseus_file(path)? {
        gmap_ops::import::perseus::Perseus::Cubical(p) => Ok(p),
        _ => Err(Error::new(ErrorKind::Unsupported, "a Perseus simplicial file, not a cubical one").with_path(path)),
    }
}

/// Keeps the pairs of `d` that live longer than `min` (death − birth > `min`, GUDHI's
/// `min_persistence`; an essential pair always), with their cycles and cells.
pub fn keep_persistent(d: &mut Diagram, min: f64) {
    let keep: Vec<bool> = d.pairs.iter().map(|p| (p.death - p.birth).abs() > min).collect();
    let mut k = keep.iter();
    d.pairs.retain(|_| *k.next().unwrap_or(&true));
    if !d.cycles.is_empty() {
        let mut k = keep.iter();
        d.cycles.retain(|_| *k.next().unwrap_or(&true));
    }
    if !d.cells.is_empty() {
        let mut k = keep.iter();
        d.cells.retain(|_| *k.next().unwrap_or(&true));
    }
}

/// Values on the vertices of a simplicial complex, by label: the lower-star filtration
/// (a simplex takes the largest value of its vertices, GUDHI's lower-star convention).
/// Labels that no vertex of the complex has are ignored; every vertex of the complex
/// needs a value.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VertexValues {
    by_label: HashMap<u64, f64>,
}

impl VertexValues {
    /// Values from `(label, value)` pairs; refuses a NaN and a label given twice.
    pub fn from_pairs<I: IntoIterator<Item = (u64, f64)>>(pairs: I) -> Result<Self> {
        let mut by_label = HashMap::new();
        for (label, value) in pairs {
            if value.is_nan() {
                return Err(Error::new(ErrorKind::Parse, format!("vertex {label} has the value NaN")));
            }
            if by_label.insert(label, value).is_some() {
                return Err(Error::new(ErrorKind::Parse, format!("vertex {label} has two values")));
            }
        }
        Ok(VertexValues { by_label })
    }

    /// Reads a vertex-values file (docs/FORMATS.md: a label and a value per line).
    pub fn read(path: &Path) -> Result<Self> {
        let pairs = gmap_ops::import::read_vertex_values(path)
            .map_err(|e| Error::from_source(ErrorKind::Parse, e).naming_path(path))?;
        Self::from_pairs(pairs).map_err(|e| e.with_path(path))
    }

    /// The value of vertex `label`.
    pub fn get(&self, label: u64) -> Option<f64> {
        self.by_label.get(&label).copied()
    }

    /// The number of labels with a value.
    pub fn len(&self) -> usize {
        self.by_label.len()
    }

    /// Whether no label has a value.
    pub fn is_empty(&self) -> bool {
        self.by_label.is_empty()
    }
}

/// The lower-star diagram of a simplicial complex: each simplex takes the largest value
/// of its vertices (with `opts.superlevel`, the upper star: the smallest, from the largest
/// value down). Refuses a vertex without a value (naming it) and the options of images
/// (periodic, the V-construction).
pub fn lower_star_complex(sc: &SimplicialComplex, values: &VertexValues, opts: &PersistenceOptions) -> Result<Diagram> {
    let value = |label: u64| values.get(label);
    simplicial_diagram(sc, SimplexValues::LowerStar(&value), opts)
}

/// [`lower_star_complex`] of an opened input, which must be a simplicial complex (`.facets`,
/// `.lex`); a G-map takes its vertex values as labels ([`persistence`]).
pub fn lower_star(input: &Input, values: &VertexValues, opts: &PersistenceOptions) -> Result<Diagram> {
    match input {
        Input::Simplicial(s) if s.facet_values().is_some() => Err(Error::new(
            ErrorKind::Unsupported,
            "the facets have values (`: VALUE`) and the vertices too: give one filtration",
        )
        .with_path(s.path())),
        Input::Simplicial(s) => lower_star_complex(s, values, opts).map_err(|e| e.with_path(s.path())),
        Input::Map(m) => Err(Error::new(
            ErrorKind::Unsupported,
            "vertex values are for simplicial complexes: a G-map carries them as a numeric label on its vertices (--label)",
        )
        .with_path(m.path())),
        other => Err(Error::new(
            ErrorKind::Unsupported,
            format!("vertex values are for simplicial complexes, not a {}", other.kind()),
        )
        .with_path(other.path())),
    }
}

/// Reads the simplicial complex at `path` (`.facets` without values, `.lex`) and computes
/// its lower-star diagram ([`lower_star`]). A `.facets` file with values per facet is
/// refused: one filtration at a time.
pub fn lower_star_file(path: &Path, values: &VertexValues, opts: &PersistenceOptions) -> Result<Persistence> {
    let diagram = read_lower_star(path, values, opts).map_err(|e| naming(e, path))?;
    Ok(Persistence { diagram, image: None, vertex_centred: false })
}

fn read_lower_star(path: &Path, values: &VertexValues, opts: &PersistenceOptions) -> Result<Diagram> {
    let format = crate::formats::format_of(path);
    if format.is_some_and(|f| f.is_image()) {
        return Err(Error::new(
            ErrorKind::Unsupported,
            "vertex values are for simplicial complexes: an image's values are its pixels (--construction V puts them on vertices)",
        ));
    }
    if format.is_none_or(|f| f.extension != "facets") {
        return lower_star(&crate::open(path)?, values, opts);
    }
    let (sc, facet_values) = read_valued(path)?;
    if facet_values.is_some() {
        return Err(Error::new(
            ErrorKind::Unsupported,
            "the facets have values (`: VALUE`) and the vertices too: give one filtration",
        ));
    }
    lower_star_complex(&sc, values, opts)
}

/// A picture format, by the output's extension.
enum PictureFormat {
    Svg,
    Png,
}

fn picture_format(out: &Path) -> Result<PictureFormat> {
    match extension(out).as_str() {
        "svg" => Ok(PictureFormat::Svg),
        "png" => Ok(PictureFormat::Png),
        _ => Err(Error::new(ErrorKind::Unsupported, "plots are written as .svg or .png").with_path(out)),
    }
}

/// A raster as PNG bytes (8-bit RGB).
pub fn png_bytes(r: &plot::Raster) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    let mut enc = png::Encoder::new(&mut bytes, r.width, r.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut w = enc.write_header().map_err(|e| Error::from_source(ErrorKind::Write, e))?;
    w.write_image_data(&r.rgb).map_err(|e| Error::from_source(ErrorKind::Write, e))?;
    w.finish().map_err(|e| Error::from_source(ErrorKind::Write, e))?;
    Ok(bytes)
}

fn write_picture(out: &Path, svg: impl FnOnce() -> String, raster: impl FnOnce() -> plot::Raster) -> Result<()> {
    let bytes = match picture_format(out)? {
        PictureFormat::Svg => svg().into_bytes(),
        PictureFormat::Png => png_bytes(&raster()).map_err(|e| e.with_path(out))?,
    };
    // the error names the picture asked for, not the temporary file it is written through
    gmap_core::io::write_atomic(out, &bytes).map_err(|e| crate::write::cannot_write(out, e).with_path(out))
}

/// Writes the diagram as a picture to `out`, SVG or PNG by its extension (other
/// extensions are refused); with `barcode`, the barcode. The PNG has the SVG's marks
/// without its text.
pub fn plot_file(p: &Persistence, out: &Path, barcode: bool) -> Result<()> {
    if barcode {
        write_picture(out, || plot::barcode_svg(&p.diagram, 600), || plot::barcode_raster(&p.diagram, 600))
    } else {
        write_picture(out, || plot::diagram_svg(&p.diagram, 500), || plot::diagram_raster(&p.diagram, 500))
    }
}

/// Writes the 2-D image with the cycle of pair `k` drawn over it, SVG or PNG by the
/// extension of `out`.
pub fn plot_cycle_file(p: &Persistence, k: usize, out: &Path) -> Result<()> {
    let chain = p.diagram.cycles.get(k).ok_or_else(|| {
        Error::new(
            ErrorKind::Usage,
            format!("no cycle for pair {k} ({} pairs; cycles asked for?)", p.diagram.pairs.len()),
        )
    })?;
    let (rows, cols, values) =
        p.image.as_ref().ok_or_else(|| Error::new(ErrorKind::Usage, "cycles are drawn over 2-D images only"))?;
    let scale = (800 / (*rows).max(*cols)).clamp(1, 20) as u32;
    write_picture(
        out,
        || plot::image_with_chain_svg(*rows, *cols, values, chain, p.vertex_centred, scale),
        || plot::image_with_chain_raster(*rows, *cols, values, chain, p.vertex_centred, scale),
    )
}
