//! Writing any object of the package: `obj.save(path, lossy=False)` for every class, through
//! the facade's writers (`gmap::save`, the registry's row for the extension), refusing what
//! `gmap convert` refuses without `--lossy`.

use std::path::Path;

use pyo3::prelude::*;

use gmap::Input;

use crate::errors::Failure;

/// Writes `input` by the extension of `path` (`gmap::save`, the writers of `gmap convert`),
/// with the GIL released, under the rule `gmap convert` follows (`gmap::save::write_checked`):
/// without `lossy`, an output that would drop what the input carries or be another space is
/// refused (InputError); with it, what the output changes is said as a `UserWarning`.
pub fn save_input(py: Python<'_>, input: &Input, path: &Path, lossy: bool) -> PyResult<()> {
    let mut o = gmap::SaveOptions::default();
    o.lossy = lossy;
    let said = py
        .allow_threads(|| gmap::save::write_checked(input, path, &o, "save with lossy=True to write it anyway"))
        .map_err(Failure::from)?;
    if !said.is_empty() {
        let warn = py.import("warnings")?.getattr("warn")?;
        for s in said {
            warn.call1((s,))?;
        }
    }
    Ok(())
}
