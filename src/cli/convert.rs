//! `gmap convert IN OUT`.

use std::path::Path;

use anyhow::Result;

use super::load::load;

pub fn run(input: &Path, _output: &Path, max_darts: Option<u64>) -> Result<()> {
    let _ = load(input, max_darts)?;
    anyhow::bail!("convert: in progress")
}
