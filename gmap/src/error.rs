//! The facade's error: what kind of failure, the message the command line prints, the
//! item it is about, and the library's typed error it came from.
//!
//! An [`Error`] keeps its [`ErrorKind`] (what a program, or the Python package's exception
//! classes, dispatch on), the file and line it concerns, the offending [`Item`] (a dart, a
//! cell, a simplex, a region) in the user's terms, and the typed error of the library crate
//! that refused as its [`std::error::Error::source`] (downcast it with
//! [`Error::source_as`]); nobody needs to read the text to know what went wrong. The text
//! is the chain of messages that led to the error, outermost first (`FILE:LINE: message`,
//! then its causes), joined with `": "`, leaving out a cause whose text the message
//! already ends with (an error that quotes its source), so each fact is said once.

use std::fmt;
use std::path::{Path, PathBuf};

/// What kind of failure an [`Error`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The input could not be read or parsed: a missing file, bad syntax, an invalid map.
    Parse,
    /// The input's format is not one the facade reads (or is written only, as a view).
    Unsupported,
    /// A limit refused the work before it started: darts, faces, memory or work.
    Limit,
    /// The route asked for does not apply to this input (a condition such as C1/C2 fails,
    /// a flag that does not fit the input).
    Precondition,
    /// The options contradict each other or name no valid value (`--field 4`).
    Usage,
    /// Writing an output failed.
    Write,
    /// The computation itself failed (an overflow the engine refused, for instance).
    Compute,
}

/// What an error is about, in the user's terms: darts numbered as in the file (from 0),
/// simplices by their vertex labels, regions by their ids.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Item {
    /// a dart
    Dart(u64),
    /// the `dim`-cell of a dart
    Cell {
        /// the dimension of the cell
        dim: usize,
        /// a dart of the cell (its smallest)
        dart: u64,
    },
    /// a simplex (a facet, a ridge) by its vertex labels
    Simplex(Vec<u64>),
    /// a region of an architectural complex, by its id
    Region(String),
}

/// The library error an [`Error`] came from.
type Source = std::sync::Arc<dyn std::error::Error + Send + Sync + 'static>;

/// A failure of the facade: its kind, the file it concerns when one does, the item it is
/// about, the chain of messages (outermost first) and the library error it came from.
#[derive(Clone, Debug)]
pub struct Error {
    kind: ErrorKind,
    path: Option<PathBuf>,
    line: Option<usize>,
    item: Option<Item>,
    chain: Vec<String>,
    source: Option<Source>,
    /// a refusal for the number of darts (or faces), which `--max-darts` raises
    dart_limit: bool,
    /// a limit that no option raises (the most darts a G-map indexes)
    hard_limit: bool,
    /// the message names the file (`path`) already
    names_path: bool,
}

/// `Result` with the facade's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// An error of `kind` with one message.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error {
            kind,
            path: None,
            line: None,
            item: None,
            chain: vec![message.into()],
            source: None,
            dart_limit: false,
            hard_limit: false,
            names_path: false,
        }
    }

    /// An error of `kind` made from a library error, kept as its source, and its chain of
    /// messages.
    pub fn from_source<E: std::error::Error + Send + Sync + 'static>(kind: ErrorKind, e: E) -> Self {
        let mut chain = vec![e.to_string()];
        let mut cause = e.source();
        while let Some(c) = cause {
            chain.push(c.to_string());
            cause = c.source();
        }
        Error { chain, source: Some(std::sync::Arc::new(e)), ..Error::new(kind, String::new()) }
    }

    /// The library error this one came from, as a `T`, when it is one (searched down the
    /// chain of sources).
    pub fn source_as<T: std::error::Error + 'static>(&self) -> Option<&T> {
        let mut cause = std::error::Error::source(self);
        while let Some(c) = cause {
            if let Some(t) = c.downcast_ref::<T>() {
                return Some(t);
            }
            cause = c.source();
        }
        None
    }

    /// Whether an operating system's I/O error is among the sources (a file that cannot be
    /// opened, read or written).
    pub fn is_io(&self) -> bool {
        self.source_as::<std::io::Error>().is_some()
            || self
                .source_as::<gmap_core::io::ReadError>()
                .is_some_and(|e| matches!(e.kind, gmap_core::io::ReadErrorKind::Io(_)))
            || self.source_as::<gmap_core::io::WriteError>().is_some()
            // the importers' and the .json reader's errors hold the I/O error without
            // making it their source (its message is part of theirs)
            || self
                .source_as::<gmap_ops::import::FileError>()
                .is_some_and(|e| matches!(e.error, gmap_ops::import::ImportError::Io(_)))
            || self
                .source_as::<gmap_homology::json::JsonFileError>()
                .is_some_and(|e| matches!(e.error, gmap_homology::json::JsonError::Io(_)))
    }

    /// This error with the item it is about.
    pub fn with_item(mut self, item: Option<Item>) -> Self {
        if item.is_some() {
            self.item = item;
        }
        self
    }

    /// The item the error is about, when it names one.
    pub fn item(&self) -> Option<&Item> {
        self.item.as_ref()
    }

    /// Whether this is a refusal for a limit no option raises.
    pub(crate) fn is_hard_limit(&self) -> bool {
        self.hard_limit
    }

    /// This error with `message` in front (the outer context), as `anyhow`'s `context`.
    pub fn context(mut self, message: impl Into<String>) -> Self {
        self.chain.insert(0, message.into());
        self
    }

    /// This error's whole text as one message (each link joined by `": "`, none left out),
    /// followed by `suffix`: the chain becomes one link.
    pub(crate) fn flattened(mut self, suffix: &str) -> Self {
        let text = self.chain.join(": ");
        self.chain = vec![format!("{text}{suffix}")];
        self
    }

    /// This error with the file it concerns.
    pub fn with_path(mut self, path: &Path) -> Self {
        self.path = Some(path.to_path_buf());
        self
    }

    /// This error with the file it concerns, which its message names already.
    pub(crate) fn naming_path(mut self, path: &Path) -> Self {
        self.names_path = true;
        self.with_path(path)
    }

    /// This error with its message starting with the file it concerns (`FILE: message`),
    /// unless the message names it already.
    pub fn about_file(self, path: &Path) -> Self {
        if self.names_path && self.path.as_deref() == Some(path) {
            return self;
        }
        self.context(path.display().to_string()).naming_path(path)
    }

    /// This error with the line (from 1) of the file that holds the fault.
    pub fn with_line(mut self, line: Option<usize>) -> Self {
        self.line = line;
        self
    }

    /// This error marked as a refusal for the number of darts or faces.
    pub(crate) fn dart_limit(mut self) -> Self {
        self.dart_limit = true;
        self
    }

    /// Whether this is a refusal for the number of darts or faces (raised by `max_darts`).
    pub fn is_dart_limit(&self) -> bool {
        self.dart_limit
    }

    /// What kind of failure this is.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// The file the error concerns, when one does.
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// The line (from 1) of the file that holds the fault, when one applies.
    pub fn line(&self) -> Option<usize> {
        self.line
    }

    /// The messages of the chain, outermost first.
    pub fn chain(&self) -> &[String] {
        &self.chain
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut msg = String::new();
        for text in &self.chain {
            if msg.ends_with(text.as_str()) {
                continue;
            }
            if !msg.is_empty() {
                msg.push_str(": ");
            }
            msg.push_str(text);
        }
        f.write_str(&msg)
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.source.as_deref().map(|e| e as &(dyn std::error::Error + 'static))
    }
}

/// Builds an [`Error`] of a kind from a format string: `err!(Usage, "--field {p}: …")`.
macro_rules! err {
    ($kind:ident, $($t:tt)*) => {
        $crate::error::Error::new($crate::error::ErrorKind::$kind, format!($($t)*))
    };
}
pub(crate) use err;

/// Errors of the library crates, sorted into kinds.
impl From<gmap_core::io::ReadError> for Error {
    fn from(e: gmap_core::io::ReadError) -> Self {
        use gmap_core::io::ReadErrorKind as K;
        let darts = matches!(e.kind, K::DartLimit { .. });
        let kind = if darts { ErrorKind::Limit } else { ErrorKind::Parse };
        let (path, line) = (PathBuf::from(&e.file), e.line);
        let item = match &e.kind {
            K::Invalid(v) => validity_item(v),
            _ => None,
        };
        let out = Error::from_source(kind, e).naming_path(&path).with_line(line).with_item(item);
        if darts {
            out.dart_limit()
        } else {
            out
        }
    }
}

impl From<gmap_ops::import::FileError> for Error {
    fn from(e: gmap_ops::import::FileError) -> Self {
        use gmap_ops::import::ImportError as I;
        let (kind, line) = match &e.error {
            I::TooManyDarts { .. }
            | I::MemoryLimit(_)
            | I::OutOfMemory { .. }
            | I::Mesh(gmap_ops::mesh::MeshError::TooManyDarts { .. }) => (ErrorKind::Limit, None),
            I::Syntax { line, .. }
            | I::MixedDimension { line, .. }
            | I::RepeatedVertex { line, .. }
            | I::DegeneratePolygon { line, .. } => (ErrorKind::Parse, Some(*line)),
            I::RepeatedFacet { second, .. } => (ErrorKind::Parse, Some(*second)),
            I::RidgeInManyFacets { lines, .. } | I::EdgeInManyPolygons { lines, .. } => {
                (ErrorKind::Parse, lines.first().copied())
            }
            _ => (ErrorKind::Parse, None),
        };
        let darts = matches!(e.error, I::TooManyDarts { .. } | I::Mesh(gmap_ops::mesh::MeshError::TooManyDarts { .. }));
        let hard = matches!(e.error, I::TooManyDarts { limit, .. } if limit >= u64::from(u32::MAX) - 1);
        let item = match &e.error {
            I::RidgeInManyFacets { ridge, .. } => Some(Item::Simplex(ridge.clone())),
            I::EdgeInManyPolygons { u, v, .. } => Some(Item::Simplex(vec![u64::from(*u), u64::from(*v)])),
            _ => None,
        };
        let path = e.path.clone();
        let mut out = Error::from_source(kind, e).naming_path(&path).with_line(line).with_item(item);
        out.hard_limit = hard;
        if darts {
            out.dart_limit()
        } else {
            out
        }
    }
}

impl From<gmap_core::io::WriteError> for Error {
    fn from(e: gmap_core::io::WriteError) -> Self {
        Error::from_source(ErrorKind::Write, e)
    }
}

impl From<gmap_ops::export::ExportError> for Error {
    fn from(e: gmap_ops::export::ExportError) -> Self {
        Error::from_source(ErrorKind::Write, e)
    }
}

impl From<gmap_homology::HomologyError> for Error {
    fn from(e: gmap_homology::HomologyError) -> Self {
        Error::from_source(ErrorKind::Compute, e)
    }
}

impl From<gmap_homology::curves::CurveError> for Error {
    /// A surface, a weight or a path refused, about the dart or cell it names.
    fn from(e: gmap_homology::curves::CurveError) -> Self {
        use gmap_homology::curves::CurveError as C;
        let (kind, item) = match &e {
            C::OpenCell { dart, .. } => (ErrorKind::Precondition, Some(Item::Dart(u64::from(*dart)))),
            C::Boundary { dart, .. } => (ErrorKind::Precondition, Some(Item::Cell { dim: 1, dart: u64::from(*dart) })),
            C::NotAPath { dart, .. } => (ErrorKind::Usage, Some(Item::Dart(u64::from(*dart)))),
            C::WeightCount { .. }
            | C::BadWeight { .. }
            | C::NoSuchVertex { .. }
            | C::NoPoint { .. }
            | C::NoEdge { .. }
            | C::NotClosed { .. }
            | C::EndsDiffer { .. } => (ErrorKind::Usage, None),
            C::TooLarge { .. } => (ErrorKind::Limit, None),
            _ => (ErrorKind::Precondition, None),
        };
        Error::from_source(kind, e).with_item(item)
    }
}

impl From<gmap_core::resources::MemoryLimit> for Error {
    fn from(e: gmap_core::resources::MemoryLimit) -> Self {
        Error::from_source(ErrorKind::Limit, e)
    }
}

impl From<gmap_homology::PreconditionError> for Error {
    /// A condition of the cellular method that fails, about the cell that fails it.
    fn from(e: gmap_homology::PreconditionError) -> Self {
        let item = precondition_item(&e);
        Error::from_source(ErrorKind::Precondition, e).with_item(item)
    }
}

/// The dart a validity error is about.
fn validity_item(e: &gmap_core::ValidityError) -> Option<Item> {
    use gmap_core::ValidityError as V;
    match e {
        V::OutOfRange { dart, .. } | V::NotInvolution { dart, .. } => Some(Item::Dart(u64::from(dart.get()))),
        _ => None,
    }
}

/// The cell a failed condition of the cellular method is about.
pub(crate) fn precondition_item(e: &gmap_homology::PreconditionError) -> Option<Item> {
    use gmap_core::CellDefect as C;
    use gmap_homology::PreconditionError as P;
    let (dim, dart) = match e {
        P::C1(C::IncompleteBoundary { dim, dart, .. } | C::NotOrientable { dim, dart, .. }) => (*dim, *dart),
        P::C2 { dim, dart, .. } => (*dim, *dart),
        _ => return None,
    };
    Some(Item::Cell { dim, dart: u64::from(dart.get()) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cause_the_message_already_ends_with_is_said_once() {
        let mut e = Error::new(ErrorKind::Parse, "a: b");
        e.chain.extend(["b".to_string(), "c".to_string()]);
        assert_eq!(e.to_string(), "a: b: c");
        assert_eq!(e.context("f").to_string(), "f: a: b: c");
    }

    #[test]
    fn flattening_keeps_every_link() {
        let e = Error::new(ErrorKind::Limit, "x: y").context("f").flattened("; more");
        assert_eq!(e.chain(), ["f: x: y; more"]);
    }
}
