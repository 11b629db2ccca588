//! `gmap convert IN OUT`: read by the input's extension, write by the output's.
//!
//! Outputs: `.gmap` (with the points, and from a `.gmap` input the cell labels too) and
//! `.moka` (gmap-core io), `.off` (2-maps with points), `.facets`
//! (the barycentric subdivision: one simplex per dart), `.vtk` (maps of dimension ≤ 3
//! with points; from a `.gmap`, the cell labels as cell data) and the incidence graph as
//! `.json` or `.dot` (from a `.gmap`, each region with the labels of its cell). Every writer goes through a
//! temporary file and a rename, so a failure leaves no partial output.

use std::path::Path;

use anyhow::{bail, Context, Result};
use gmap_core::DenseMap;
use gmap_homology::arch::ArchComplex;
use gmap_homology::dot::write_dot;
use gmap_homology::json::write_json;
use gmap_homology::lar::Lar;
use gmap_ops::import::{FacePoset, PosetError};

use super::load::{extension, load, load_labelled_gmap, split_lex_name, Loaded};

/// Runs `gmap convert`.
pub fn run(input: &Path, output: &Path, max_darts: Option<u64>) -> Result<()> {
    if same_file(input, output) {
        bail!(
            "{}: the output is the input file {}: convert to another file (the input would be replaced)",
            output.display(),
            input.display()
        );
    }
    if extension(input) == "gmap" {
        // the dense map of `load` would drop the labels of the cells
        match extension(output).as_str() {
            "gmap" => {
                let g = load_labelled_gmap(input, max_darts)?;
                gmap_core::io::write_labelled_gmap(&g, output)?;
                return Ok(());
            }
            "vtk" | "dot" => return write_labelled(&load_labelled_gmap(input, max_darts)?, output),
            "json" if !is_lar(output) => return write_labelled(&load_labelled_gmap(input, max_darts)?, output),
            _ => {}
        }
    }
    match load(input, max_darts)? {
        Loaded::Map(m) => write_map(&m, output),
        Loaded::Complex(x) => write_complex(&x, output, max_darts),
        Loaded::Cubical(_) => {
            anyhow::bail!("{}: a cubical set cannot be converted; use gmap homology", input.display())
        }
    }
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

/// Writes a map in the format named by the extension of `output`.
pub fn write_map(m: &DenseMap, output: &Path) -> Result<()> {
    match extension(output).as_str() {
        "gmap" => gmap_core::io::write_gmap(m, output)?,
        "moka" => gmap_core::io::write_moka(m, output)?,
        "off" => {
            gmap_ops::export::write_off(m, output).with_context(|| format!("{}: cannot write", output.display()))?
        }
        "facets" => gmap_ops::export::write_barycentric_facets(m, output)?,
        "vtk" => {
            gmap_ops::export::write_vtk(m, output).with_context(|| format!("{}: cannot write", output.display()))?
        }
        "json" if is_lar(output) => write_text(output, &Lar::from_map(m).to_json()?)?,
        "json" => write_text(output, &write_json(&complex_of(m, output)?))?,
        "dot" => write_text(output, &write_dot(&complex_of(m, output)?))?,
        other => {
            bail!("{}: unsupported output format '.{}'", output.display(), gmap_core::io::shorten(other.as_bytes(), 40))
        }
    }
    Ok(())
}

/// Writes a labelled map as `.vtk` (labels as cell data) or as its incidence graph, `.json`
/// or `.dot` (labels on the regions).
fn write_labelled(g: &gmap_core::LabelledGMap, output: &Path) -> Result<()> {
    let (m, labels, _) = gmap_core::to_dense_labels(g);
    match extension(output).as_str() {
        "vtk" => gmap_ops::export::write_vtk_with_labels(&m, &labels, output)
            .with_context(|| format!("{}: cannot write", output.display())),
        ext => {
            let x = ArchComplex::from_map_with_labels(&m, &labels)
                .with_context(|| format!("{}: cannot write the incidence graph", output.display()))?;
            write_text(output, &if ext == "dot" { write_dot(&x) } else { write_json(&x) })
        }
    }
}

/// Whether the output is a LAR file (`.lar.json`) rather than an incidence graph.
fn is_lar(p: &Path) -> bool {
    p.to_string_lossy().to_lowercase().ends_with(".lar.json")
}

/// The architectural complex of a map's cells (AC Remark 3.3), or why it has none.
fn complex_of(m: &DenseMap, output: &Path) -> Result<ArchComplex> {
    ArchComplex::from_map(m).with_context(|| format!("{}: cannot write the incidence graph", output.display()))
}

fn write_text(path: &Path, text: &str) -> Result<()> {
    gmap_core::io::write_atomic(path, text.as_bytes()).with_context(|| format!("{}: cannot write", path.display()))
}

/// Writes an architectural complex: `.json` and `.dot` directly; any other format through
/// its G-map (the flag construction of a regular complex's face poset, gmap-ops).
pub fn write_complex(x: &ArchComplex, output: &Path, max_darts: Option<u64>) -> Result<()> {
    match extension(output).as_str() {
        "json" if !is_lar(output) => write_text(output, &write_json(x)),
        "dot" => write_text(output, &write_dot(x)),
        _ => {
            let m = complex_to_map(x, max_darts).map_err(|e| match e {
                PosetError::TooManyDarts { .. } | PosetError::MemoryLimit(_) => {
                    anyhow::anyhow!(
                        "{}: {e}; raise the limit with --max-darts N or --max-memory BYTES",
                        output.display()
                    )
                }
                e => anyhow::Error::new(e).context(format!(
                    "{}: the complex is not the face poset of a regular cell complex",
                    output.display()
                )),
            })?;
            write_map(&m, output)
        }
    }
}

/// The G-map of an architectural complex whose entries between consecutive dimensions are
/// the covering pairs of a regular cell complex's face poset.
fn complex_to_map(x: &ArchComplex, max_darts: Option<u64>) -> Result<DenseMap, PosetError> {
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
