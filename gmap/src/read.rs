//! The readers of the format registry ([`crate::formats::FORMATS`]): one function per
//! format, each reading a whole file into an [`Input`] under the memory policy and the dart
//! limit of its [`OpenOptions`]. The library crates parse; these functions choose the call
//! and sort its errors into the facade's kinds.

use std::path::Path;

use gmap_ops::import::{self, Image};

use crate::error::{err, Error, ErrorKind, Result};
use crate::input::{split_lex_name, Input, OpenOptions, Source};
use gmap_homology::json::JsonOptions;

/// A reader of the registry.
pub(crate) type ReadFn = fn(&Path, &OpenOptions) -> Result<Input>;

fn read_options(opts: &OpenOptions) -> gmap_core::io::ReadOptions {
    gmap_core::io::ReadOptions { max_darts: opts.max_darts }
}

/// `.gmap`: the map; its labels are read when first asked for ([`crate::MapInput::labelled`]).
pub(crate) fn gmap(path: &Path, opts: &OpenOptions) -> Result<Input> {
    let map = gmap_core::io::read_gmap_with(path, &read_options(opts))?;
    Ok(Input::map_from(map, Source::labelled_file(path, opts)))
}

/// `.moka`.
pub(crate) fn moka(path: &Path, opts: &OpenOptions) -> Result<Input> {
    Ok(Input::map_from(gmap_core::io::read_moka_with(path, &read_options(opts))?, Source::file(path, opts)))
}

/// `.off`: a polygon mesh sewn into a 2-map.
pub(crate) fn off(path: &Path, opts: &OpenOptions) -> Result<Input> {
    Ok(Input::map_from(import::read_off_with(path, opts.max_darts)?, Source::file(path, opts)))
}

/// `.vtk`, `.vtu`, `.msh`: the mesh's cells sewn face to face, its data as labels.
pub(crate) fn mesh(path: &Path, opts: &OpenOptions) -> Result<Input> {
    let g = import::read_mesh(path, opts.max_darts)
        .ok_or_else(|| err!(Unsupported, "{}: not a mesh file", path.display()).naming_path(path))??;
    Ok(Input::labelled_map_from(g, Source::file(path, opts)))
}

/// `.facets`.
pub(crate) fn facets(path: &Path, opts: &OpenOptions) -> Result<Input> {
    // facets may carry values (`: VALUE`): the complex's filtration, kept with it
    let (sc, values) = import::simplicial::read_valued_facets(path)?;
    Ok(Input::Simplicial(Source::file(path, opts).valued(values).holding(sc)))
}

/// `.lex`, or `FILE.lex#name` for one complex of the file.
pub(crate) fn lex(path: &Path, opts: &OpenOptions) -> Result<Input> {
    let sc = if path.exists() {
        import::read_lex_complex(path, None)?
    } else {
        let (file, name) = split_lex_name(path);
        import::read_lex_complex(&file, name.as_deref())?
    };
    Ok(Input::Simplicial(Source::file(path, opts).holding(sc)))
}

/// `.json`: an architectural complex or incidence graph.
pub(crate) fn json(path: &Path, opts: &OpenOptions) -> Result<Input> {
    let (x, notes) = gmap_homology::json::read_json_file_with(path, &JsonOptions::snap(opts.snap))
        .map_err(|e| Error::from_source(json_error_kind(&e.error), e).naming_path(path))?;
    Ok(Input::Arch(Source::file(path, opts).noting(notes).holding(x)))
}

/// The kind of a `.json` reader's refusal: over the memory limit, or not the format.
pub(crate) fn json_error_kind(e: &gmap_homology::json::JsonError) -> ErrorKind {
    match e {
        gmap_homology::json::JsonError::MemoryLimit(_) => ErrorKind::Limit,
        _ => ErrorKind::Parse,
    }
}

/// `.cub`, `.cel`: CHomP's cubes and cells.
pub(crate) fn cub(path: &Path, opts: &OpenOptions) -> Result<Input> {
    Ok(Input::Cubical(Source::file(path, opts).holding(import::read_cub(path)?)))
}

/// `.pbm`: black pixels as unit squares.
pub(crate) fn pbm(path: &Path, opts: &OpenOptions) -> Result<Input> {
    Ok(Input::Cubical(Source::file(path, opts).holding(import::read_pbm(path)?)))
}

/// `.npy`, `.complex`: memory-mapped, the values read when used.
pub(crate) fn image(path: &Path, opts: &OpenOptions) -> Result<Input> {
    Ok(Input::Image(Source::file(path, opts).holding(Image::read(path)?)))
}

/// `.pgm`, `.png`: the grey values of a picture.
pub(crate) fn raster(path: &Path, opts: &OpenOptions) -> Result<Input> {
    let img =
        import::raster::read_raster(path).map_err(|e| Error::from_source(ErrorKind::Parse, e).naming_path(path))?;
    Ok(Input::Image(Source::file(path, opts).holding(img)))
}

/// `.txt`: a Perseus cubical file (GUDHI's `perseus_file`) as the image of its top cells,
/// the first axis fastest. Refused: a file with a periodic axis (a negative size; an image
/// has no periodicity to carry it, `gmap.gudhi.PeriodicCubicalComplex(perseus_file=…)` reads
/// it) and a simplicial one (its values are what it holds: `crate::persistence_file`
/// reads them).
pub(crate) fn perseus(path: &Path, opts: &OpenOptions) -> Result<Input> {
    let read =
        import::perseus::read_perseus(path).map_err(|e| Error::from_source(ErrorKind::Parse, e).naming_path(path));
    let p = match read? {
        import::perseus::Perseus::Cubical(p) => p,
        _ => {
            return Err(Error::new(
                ErrorKind::Unsupported,
                "a Perseus simplicial file: a complex opened keeps no values; its diagram is `gmap persistence FILE` (gmap.persistence(path))",
            )
            .with_path(path))
        }
    };
    if p.periodic.iter().any(|&w| w) {
        return Err(Error::new(
            ErrorKind::Unsupported,
            format!(
                "a Perseus file with periodic axes {:?} (negative sizes): an image does not wrap; gmap.gudhi.PeriodicCubicalComplex(perseus_file=...) reads it",
                p.periodic
            ),
        )
        .with_path(path));
    }
    let img = Image::from_values(&p.sizes, import::image::Order::Fortran, p.values)
        .map_err(|e| Error::from_source(ErrorKind::Parse, e).naming_path(path))?;
    Ok(Input::Image(Source::file(path, opts).holding(img)))
}

/// `.cgal.xml`: CGAL's XML generalized maps, vertex points kept.
pub(crate) fn cgal_xml(path: &Path, opts: &OpenOptions) -> Result<Input> {
    Ok(Input::map_from(import::read_cgal_xml(path, opts.max_darts)?, Source::file(path, opts)))
}
