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
pub fn load(path: &Path, _max_darts: Option<u64>) -> Result<Loaded> {
    match extension(path).as_str() {
        other => bail!("{}: unsupported input format '.{other}'", path.display()),
    }
}
