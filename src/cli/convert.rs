//! `gmap convert IN OUT`: read by the input's extension, write by the output's.
//!
//! Outputs: `.gmap` and `.moka` (gmap-core io), `.off` (2-maps with points) and `.facets`
//! (the barycentric subdivision: one simplex per dart). Every writer goes through a
//! temporary file and a rename, so a failure leaves no partial output.

use std::path::Path;

use anyhow::{bail, Result};
use gmap_core::DenseMap;

use super::load::{extension, load, Loaded};

/// Runs `gmap convert`.
pub fn run(input: &Path, output: &Path, max_darts: Option<u64>) -> Result<()> {
    match load(input, max_darts)? {
        Loaded::Map(m) => write_map(&m, output),
    }
}

/// Writes a map in the format named by the extension of `output`.
pub fn write_map(m: &DenseMap, output: &Path) -> Result<()> {
    match extension(output).as_str() {
        "gmap" => gmap_core::io::write_gmap(m, output)?,
        "moka" => gmap_core::io::write_moka(m, output)?,
        "off" => gmap_ops::export::write_off(m, output)?,
        "facets" => gmap_ops::export::write_barycentric_facets(m, output)?,
        other => bail!("{}: unsupported output format '.{other}'", output.display()),
    }
    Ok(())
}
