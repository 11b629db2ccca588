//! Reading any supported input file, chosen by extension (docs/FORMATS.md §2).

use std::path::Path;

use anyhow::{bail, Result};
use gmap_core::DenseMap;

/// What an input file holds.
pub enum Loaded {
    /// a generalized map
    Map(DenseMap),
    /// an architectural complex / incidence graph (`.json`, docs/FORMATS.md §2)
    Complex(gmap_homology::arch::ArchComplex),
    /// a full cubical set (`.cub`, `.pbm`)
    Cubical(gmap_ops::import::CubicalSet),
}

/// The extensions [`load`] reads (the files `gmap bench` takes from a folder).
pub const INPUT_EXTENSIONS: &[&str] = &["gmap", "moka", "facets", "lex", "off", "json", "cub", "pbm"];

/// The lower-cased extension of a path. A `#` belongs to the file name (`run#3.gmap`) unless
/// the path names a `.lex` complex, `FILE.lex#name`, and no file has the whole path (see
/// [`split_lex_name`]): the extension is taken from the real path when it exists.
pub fn extension(path: &Path) -> String {
    let (file, name) = split_lex_name(path);
    let base = if name.is_some() && !path.exists() { file.as_path() } else { path };
    base.extension().map(|e| e.to_string_lossy().to_lowercase()).unwrap_or_default()
}

/// Reads `path` by its extension. A refusal for size gets the flag that raises the limit.
pub fn load(path: &Path, max_darts: Option<u64>) -> Result<Loaded> {
    load_any(path, max_darts).map_err(limit_hint)
}

/// Reads a `.gmap` file with its points and the labels of every dimension (what `load`
/// drops), with the same hint as [`load`] for a refusal for size.
pub fn load_labelled_gmap(path: &Path, max_darts: Option<u64>) -> Result<gmap_core::LabelledGMap> {
    let opts = gmap_core::io::ReadOptions { max_darts };
    gmap_core::io::read_labelled_gmap_with(path, &opts).map_err(|e| limit_hint(e.into()))
}

/// Adds the flag that raises the limit to a refusal for size.
fn limit_hint(e: anyhow::Error) -> anyhow::Error {
    let over_limit = e
        .downcast_ref::<gmap_ops::import::FileError>()
        .is_some_and(|f| matches!(f.error, gmap_ops::import::ImportError::TooManyDarts { .. }))
        || e.downcast_ref::<gmap_core::io::ReadError>()
            .is_some_and(|r| matches!(r.kind, gmap_core::io::ReadErrorKind::DartLimit { .. }));
    if over_limit {
        anyhow::anyhow!("{e:#}; raise the limit with --max-darts N")
    } else {
        e
    }
}

fn load_any(path: &Path, max_darts: Option<u64>) -> Result<Loaded> {
    let opts = gmap_core::io::ReadOptions { max_darts };
    match extension(path).as_str() {
        "gmap" => Ok(Loaded::Map(gmap_core::io::read_gmap_with(path, &opts)?)),
        "moka" => Ok(Loaded::Map(gmap_core::io::read_moka_with(path, &opts)?)),
        "facets" => Ok(Loaded::Map(gmap_ops::import::read_facets(path, max_darts)?)),
        "lex" if path.exists() => Ok(Loaded::Map(gmap_ops::import::read_lex(path, None, max_darts)?)),
        "lex" => {
            let (file, name) = split_lex_name(path);
            Ok(Loaded::Map(gmap_ops::import::read_lex(&file, name.as_deref(), max_darts)?))
        }
        "off" => Ok(Loaded::Map(gmap_ops::import::read_off_with(path, max_darts)?)),
        "json" => Ok(Loaded::Complex(gmap_homology::json::read_json_file(path)?)),
        "cub" => Ok(Loaded::Cubical(gmap_ops::import::read_cub(path)?)),
        "pbm" => Ok(Loaded::Cubical(gmap_ops::import::read_pbm(path)?)),
        // views: what they hold (polyhedra, drawings) does not give back the map
        "vtk" | "dot" => bail!(
            "{}: unsupported input format '.{}': it is written only, as a view (read the .gmap it came from)",
            path.display(),
            extension(path)
        ),
        other => {
            bail!("{}: unsupported input format '.{}'", path.display(), gmap_core::io::shorten(other.as_bytes(), 40))
        }
    }
}

/// A `.facets` or `.lex[#name]` input read as a simplicial complex, without making a G-map
/// of it (any finite simplicial complex); `None` for the other formats.
pub fn load_simplicial(path: &Path) -> Result<Option<gmap_ops::import::SimplicialComplex>> {
    use gmap_ops::import::{read_facets_complex, read_lex_complex};
    Ok(match extension(path).as_str() {
        "facets" => Some(read_facets_complex(path)?),
        "lex" if path.exists() => Some(read_lex_complex(path, None)?),
        "lex" => {
            let (file, name) = split_lex_name(path);
            Some(read_lex_complex(&file, name.as_deref())?)
        }
        _ => None,
    })
}

/// The direct route's chain complex of a simplicial complex (every face of every facet a
/// cell, `gmap_homology::simplices`), refused past `--max-darts` faces (default: what the
/// memory budget holds at its dimension), the error naming `file`; with `labels`, the
/// vertices of every face (to name generators).
pub fn face_complex_within(
    sc: &gmap_ops::import::SimplicialComplex,
    max_darts: Option<u64>,
    file: &str,
    labels: bool,
) -> Result<gmap_homology::simplices::FaceComplex> {
    use gmap_homology::simplices::{face_complex_of, FaceError};
    let limit = max_darts.unwrap_or_else(|| gmap_ops::import::default_max_faces(sc.dim()));
    face_complex_of(sc.facets(), limit, labels).map_err(|e| match e {
        FaceError::TooManyFaces { .. } => anyhow::anyhow!("{file}: {e}; raise the limit with --max-darts N"),
        e => anyhow::anyhow!("{file}: {e}"),
    })
}

/// Splits `FILE.lex#name` into the file and the complex name (none without `#`). The split
/// is at the first `#` after `.lex`, so names that hold `#` themselves (Lutz's
/// `manifold_lex_d3_n5_#1`) stay whole.
pub fn split_lex_name(path: &Path) -> (std::path::PathBuf, Option<String>) {
    let s = path.to_string_lossy();
    match s.to_ascii_lowercase().find(".lex#") {
        Some(k) => {
            let name = &s[k + 5..];
            (std::path::PathBuf::from(&s[..k + 4]), (!name.is_empty()).then(|| name.to_string()))
        }
        None => (path.to_path_buf(), None),
    }
}
