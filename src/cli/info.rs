//! `gmap info FILE [--json]`.

use std::path::Path;

use anyhow::Result;

use super::load::load;

pub fn run(file: &Path, _json: bool, max_darts: Option<u64>) -> Result<()> {
    let _ = load(file, max_darts)?;
    anyhow::bail!("info: in progress")
}
