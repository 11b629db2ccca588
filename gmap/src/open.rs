//! [`open`]: any input file, read by the reader its extension names in the format registry
//! ([`crate::formats`]).

use std::path::Path;

use crate::error::Result;
use crate::input::{limit_hint, Input, OpenOptions};

/// Reads `path` by its extension, with the default options.
pub fn open(path: impl AsRef<Path>) -> Result<Input> {
    open_with(path, &OpenOptions::default())
}

/// Reads `path` by its extension. A refusal for size names the option that raises the
/// limit.
pub fn open_with(path: impl AsRef<Path>, opts: &OpenOptions) -> Result<Input> {
    let path = path.as_ref();
    crate::formats::read(path, opts).map_err(limit_hint)
}
