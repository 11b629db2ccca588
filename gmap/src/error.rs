//! The facade's error: what kind of failure, and the message the command line prints.
//!
//! An [`Error`] keeps the chain of texts that led to it, outermost first, as the errors of
//! the library crates report it (`FILE:LINE: message`, then its causes). Its `Display` joins
//! the chain with `": "`, leaving out a cause whose text the message already ends with (an
//! error that quotes its source), so each fact is said once. The [`ErrorKind`] tells a
//! program (or the Python package's exception classes) what went wrong without reading the
//! text.

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

/// A failure of the facade: its kind, the file it concerns when one does, and the chain of
/// messages (outermost first).
#[derive(Clone, Debug)]
pub struct Error {
    kind: ErrorKind,
    path: Option<PathBuf>,
    line: Option<usize>,
    chain: Vec<String>,
    /// a refusal for the number of darts (or faces), which `--max-darts` raises
    dart_limit: bool,
}

/// `Result` with the facade's [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    /// An error of `kind` with one message.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error { kind, path: None, line: None, chain: vec![message.into()], dart_limit: false }
    }

    /// An error of `kind` made from a library error and its chain of sources.
    pub fn from_source(kind: ErrorKind, e: &(dyn std::error::Error + 'static)) -> Self {
        let mut chain = vec![e.to_string()];
        let mut cause = e.source();
        while let Some(c) = cause {
            chain.push(c.to_string());
            cause = c.source();
        }
        Error { kind, path: None, line: None, chain, dart_limit: false }
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

impl std::error::Error for Error {}

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
        let out = Error::from_source(kind, &e).with_path(&path).with_line(line);
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
            I::TooManyDarts { .. } | I::MemoryLimit(_) | I::OutOfMemory { .. } => (ErrorKind::Limit, None),
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
        let darts = matches!(e.error, I::TooManyDarts { .. });
        let path = e.path.clone();
        let out = Error::from_source(kind, &e).with_path(&path).with_line(line);
        if darts {
            out.dart_limit()
        } else {
            out
        }
    }
}

impl From<gmap_core::io::WriteError> for Error {
    fn from(e: gmap_core::io::WriteError) -> Self {
        Error::from_source(ErrorKind::Write, &e)
    }
}

impl From<gmap_ops::export::ExportError> for Error {
    fn from(e: gmap_ops::export::ExportError) -> Self {
        Error::from_source(ErrorKind::Write, &e)
    }
}

impl From<gmap_homology::HomologyError> for Error {
    fn from(e: gmap_homology::HomologyError) -> Self {
        Error::from_source(ErrorKind::Compute, &e)
    }
}

impl From<gmap_core::resources::MemoryLimit> for Error {
    fn from(e: gmap_core::resources::MemoryLimit) -> Self {
        Error::from_source(ErrorKind::Limit, &e)
    }
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
