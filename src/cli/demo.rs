//! `gmap demo`: the classic objects, one table row each.

use anyhow::Result;

pub fn run() -> Result<()> {
    anyhow::bail!("demo: in progress")
}
