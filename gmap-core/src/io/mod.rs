//! Reading and writing G-maps: the native `.gmap` text format and Moka's ascii `.moka`.
//!
//! Both readers work on the raw bytes in one pass, without a `String` per line, and never
//! panic on bad input: every failure is a [`ReadError`] whose `Display` is
//! `FILE:LINE: message`, where the line is the physical line of the file (from 1) that
//! holds the fault. In both formats dart `k` (from 0) is the `k`-th data line, so a
//! violation of BO Def. 1 found after parsing is reported on the line of the first
//! offending dart, with the involution indices.
//!
//! Allocation is bounded by the input: a header announcing more darts than the file could
//! hold reserves only what the file's size allows, a dimension above [`crate::MAX_DIM`] is
//! refused before anything is allocated, and sizes are multiplied with overflow checks.
//!
//! Writers go through a temporary file in the destination's directory, renamed over the
//! destination once complete, so a failure never leaves a partial file.
//!
//! | format | reader | writer | byte parser (fuzzing, tests) |
//! | --- | --- | --- | --- |
//! | native `.gmap` | [`read_gmap`] | [`write_gmap`] | [`parse_gmap`] |
//! | `.gmap` with labels | [`read_labelled_gmap`] | [`write_labelled_gmap`] | [`parse_labelled_gmap`] |
//! | Moka `.moka` | [`read_moka`] | [`write_moka`] | [`parse_moka`] |
//!
//! ```
//! use gmap_core::{examples, io};
//! let m = examples::cylinder();
//! let text = io::format_gmap(&m);
//! assert!(text.starts_with(b"gmap 2 8\n1 7 5\n"));
//! assert_eq!(io::parse_gmap(&text, "cyl.gmap").unwrap(), m);
//! let bad = b"gmap 1 2\n1 0\n0 0\n";
//! let err = io::parse_gmap(bad, "bad.gmap").unwrap_err();
//! assert_eq!(err.to_string(), "bad.gmap:3: not a G-map (BO Def. 1): \
//!     dart 1 is linked along alpha_1 to dart 0, which is linked back to dart 0 instead");
//! ```

mod common;
mod moka;
mod native;

pub use crate::text::shorten;
pub use common::{write_atomic, write_atomic_with, ReadError, ReadErrorKind, ReadOptions, WriteError};

pub use moka::{
    format_moka, parse_moka, parse_moka_with, read_moka, read_moka_with, write_moka, write_moka_to, MOKA_HEADER,
};
pub use native::{
    format_gmap, format_labelled_gmap, parse_gmap, parse_gmap_with, parse_labelled_gmap, parse_labelled_gmap_with,
    read_gmap, read_gmap_with, read_labelled_gmap, read_labelled_gmap_with, write_gmap, write_gmap_to,
    write_labelled_gmap,
};
