//! Reading any supported input file, chosen by extension (CONTRACT §2).

use std::path::Path;

use anyhow::{bail, Result};
use gmap_core::DenseMap;

/// What an input file holds.
pub enum Loaded {
    /// a generalized map
    Map(DenseMap),
}

/// The lower-cased extension of a path, after stripping a `#name` suffix (for `.lex`).
pub fn extension(path: &Path) -> String {
    let s = path.to_string_lossy();
    let base = s.split('#').next().unwrap_or("");
    Path::new(base).extension().map(|e| e.to_string_lossy().to_lowercase()).unwrap_or_default()
}

/// Reads `path` by its extension.
pub fn load(path: &Path, max_darts: Option<u64>) -> Result<Loaded> {
    let opts = gmap_core::io::ReadOptions { max_darts };
    match extension(path).as_str() {
        "gmap" => Ok(Loaded::Map(gmap_core::io::read_gmap_with(path, &opts)?)),
        "moka" => Ok(Loaded::Map(gmap_core::io::read_moka_with(path, &opts)?)),
        "facets" => Ok(Loaded::Map(gmap_ops::import::read_facets(path, max_darts)?)),
        "lex" => {
            let (file, name) = split_lex_name(path);
            Ok(Loaded::Map(gmap_ops::import::read_lex(&file, name.as_deref(), max_darts)?))
        }
        "off" => Ok(Loaded::Map(gmap_ops::import::read_off(path)?)),
        other => bail!("{}: unsupported input format '.{other}'", path.display()),
    }
}

/// Splits `FILE.lex#name` into the file and the complex name (none without `#`).
pub fn split_lex_name(path: &Path) -> (std::path::PathBuf, Option<String>) {
    let s = path.to_string_lossy();
    match s.rsplit_once('#') {
        Some((file, name)) if !name.is_empty() => (std::path::PathBuf::from(file), Some(name.to_string())),
        Some((file, _)) => (std::path::PathBuf::from(file), None),
        None => (path.to_path_buf(), None),
    }
}
