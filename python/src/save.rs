//! Writing any object of the package: `obj.save(path, lossy=False)` for every class, through
//! the facade's writers (`gmap::save`, the registry's row for the extension), refusing what
//! `gmap convert` refuses without `--lossy`.

use std::path::Path;

use pyo3::prelude::*;

use gmap::Input;

use crate::errors::Failure;

/// Writes `input` by the extension of `path` (`gmap::save`, the writers of `gmap convert`),
/// with the GIL released; without `lossy`, refuses (InputError) an output that would drop
/// what the input carries, as `gmap convert` does without `--lossy` (`gmap::save::dropped`).
pub fn save_input(py: Python<'_>, input: &Input, path: &Path, lossy: bool) -> PyResult<()> {
    let o = gmap::SaveOptions::default();
    py.allow_threads(|| {
        let dropped = gmap::save::dropped(input, path, &o);
        if !dropped.is_empty() && !lossy {
            return Err(Failure::input(format!(
                "{} drops {} of the {}; save with lossy=True to write it anyway",
                path.display(),
                dropped.join(", "),
                input.kind()
            ))
            .at_path(path));
        }
        gmap::save(input, path, &o).map_err(Failure::from)
    })?;
    Ok(())
}
