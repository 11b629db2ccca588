//! `gmap homology FILE [--method] [--field P] [--json]`.

use std::path::PathBuf;

use anyhow::Result;

use super::load::load;
use super::Method;

/// Options of `gmap homology`.
#[allow(dead_code)]
pub struct Options {
    pub file: PathBuf,
    pub method: Method,
    pub field: Option<u64>,
    pub json: bool,
    pub generators: bool,
    pub simplify: bool,
    pub topological: bool,
    pub max_darts: Option<u64>,
}

pub fn run(o: &Options) -> Result<()> {
    let _ = load(&o.file, o.max_darts)?;
    anyhow::bail!("homology: in progress")
}
