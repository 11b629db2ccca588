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
use gmap_ops::import::{FacePoset, PosetError};

use crate::error::{err, Error, ErrorKind, Result};
use crate::input::{extension, split_lex_name, Input};

/// Options of [`save`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SaveOptions {
    /// refuse to make maps of more darts than this (a complex written through its G-map)
    pub max_darts: Option<u64>,
}

impl SaveOptions {
    /// Options with a dart limit.
    pub fn max_darts(max_darts: Option<u64>) -> Self {
        SaveOptions { max_darts }
    }
}

/// Writes `input` to `output` in the format named by the output's extension. Refuses to
/// write over the file the input was read from, and a kind of input the format cannot hold.
pub fn save(input: &Input, output: impl AsRef<Path>, o: &SaveOptions) -> Result<()> {
    let output = output.as_ref();
    refuse_same_file(input.path(), output)?;
    if let Input::Map(m) = input {
        // the labels of the cells live in the labelled map of a `.gmap` file
        let labelled_output = match extension(output).as_str() {
            "gmap" | "vtk" | "dot" => true,
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
        Input::Simplicial(sc) => save_map(&sc.to_gmap_within(o.max_darts)?, output),
        Input::Arch(x) => save_arch_from(x, input.path(), output, o.max_darts),
        Input::Cubical(_) => {
            Err(err!(Unsupported, "{}: a cubical set cannot be converted; use gmap homology", input.path().display()))
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

/// Reads `input` and writes it to `output` (`gmap convert`): the output is checked not to
/// be the input file before anything is read.
pub fn save_file(input: impl AsRef<Path>, output: impl AsRef<Path>, o: &SaveOptions) -> Result<()> {
    let (input, output) = (input.as_ref(), output.as_ref());
    refuse_same_file(input, output)?;
    let opened = crate::input::open_with(input, &crate::input::OpenOptions::max_darts(o.max_darts))?;
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
        "off" => gmap_ops::export::write_off(m, output).map_err(|e| cannot_write(output, &e))?,
        "facets" => gmap_ops::export::write_barycentric_facets(m, output)?,
        "vtk" => gmap_ops::export::write_vtk(m, output).map_err(|e| cannot_write(output, &e))?,
        "json" if is_lar(output) => {
            let text = Lar::from_map(m).to_json().map_err(|e| Error::from_source(ErrorKind::Write, &e))?;
            write_text(output, &text)?
        }
        "json" => write_text(output, &write_json(&arch_of(m, output)?))?,
        "dot" => write_text(output, &write_dot(&arch_of(m, output)?))?,
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
            write_text(output, &if ext == "dot" { write_dot(&x) } else { write_json(&x) })
        }
    }
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
/// its G-map (the flag construction of a regular complex's face poset, gmap-ops).
pub fn save_arch(x: &ArchComplex, output: &Path, max_darts: Option<u64>) -> Result<()> {
    save_arch_from(x, Path::new(""), output, max_darts)
}

/// [`save_arch`] of a complex read from `input`: a refusal names the input file and the
/// regions by the file's ids and names.
fn save_arch_from(x: &ArchComplex, input: &Path, output: &Path, max_darts: Option<u64>) -> Result<()> {
    let file = if input.as_os_str().is_empty() { output } else { input };
    match extension(output).as_str() {
        "json" if !is_lar(output) => write_text(output, &write_json(x)),
        "dot" => write_text(output, &write_dot(x)),
        _ => {
            let m = arch_to_map(x, max_darts).map_err(|e| match e {
                PosetError::TooManyDarts { .. } | PosetError::MemoryLimit(_) => {
                    err!(Limit, "{}: {e}; raise the limit with --max-darts N or --max-memory BYTES", file.display())
                }
                e => Error::new(ErrorKind::Precondition, poset_error_named(x, &e)).context(format!(
                    "{}: the complex is not the face poset of a regular cell complex",
                    file.display()
                )),
            })?;
            save_map(&m, output)
        }
    }
}

/// A face-poset refusal with the regions named as the file names them (the poset's cells
/// are the complex's regions, in order).
fn poset_error_named(x: &ArchComplex, e: &PosetError) -> String {
    let n = |c: usize| if c < x.regions().len() { x.region_name(c) } else { c.to_string() };
    match *e {
        PosetError::EdgeVertices { edge, vertices } => {
            format!("edge {} has {vertices} vertices, not 2: not a regular complex", n(edge))
        }
        PosetError::Diamond { lower, upper, dim, count } => format!(
            "diamond property fails: {count} regions of dimension {dim} lie between region {} and region {} (2 expected)",
            n(lower),
            n(upper)
        ),
        PosetError::TooManyCofaces { cell, dim, count } => {
            format!("region {} of dimension {dim} lies in {count} regions of dimension {} (at most 2)", n(cell), dim + 1)
        }
        PosetError::NotPure { cell, dim, top } => {
            format!("region {} of dimension {dim} is not part of any {top}-region: the complex is not pure", n(cell))
        }
        PosetError::NotConsecutive { higher, higher_dim, lower, lower_dim } => format!(
            "region {} (dimension {lower_dim}) is given as a face of region {} (dimension {higher_dim}): dimensions must differ by one",
            n(lower),
            n(higher)
        ),
        PosetError::Duplicate { higher, lower } => format!("incidence ({}, {}) is given twice", n(higher), n(lower)),
        ref other => other.to_string(),
    }
}

/// The G-map of an architectural complex whose entries between consecutive dimensions are
/// the covering pairs of a regular cell complex's face poset.
fn arch_to_map(x: &ArchComplex, max_darts: Option<u64>) -> std::result::Result<DenseMap, PosetError> {
    let mut p = FacePoset::new();
    for r in x.regions() {
        p.add_cell(r.dim);
    }
    for e in x.entries() {
        if x.region(e.from).dim == x.region(e.to).dim + 1 {
            p.add_cover(e.from, e.to);
        }
    }
    p.to_gmap(max_darts.unwrap_or_else(|| gmap_ops::import::default_max_darts(x.dim())))
}
