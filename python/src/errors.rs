//! The exceptions of the package and the mapping of the library's errors onto them.
//!
//! Every failure of the library reaches Python as a subclass of `gmap.GmapError` carrying
//! the message the command line prints after `error: ` (the chain of causes joined by
//! `: `). Which subclass is chosen by the kind of the error, not by its text.

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(gmap, GmapError, PyException, "Base class of every error raised by gmap.");
create_exception!(
    gmap,
    ParseError,
    GmapError,
    "A file that does not fit its format; `.file` and `.line` (or None) say where."
);
create_exception!(
    gmap,
    LimitError,
    GmapError,
    "An input refused for its size: over the dart, face or work limit, or the memory policy."
);
create_exception!(
    gmap,
    PreconditionError,
    GmapError,
    "A method that does not apply to this input (conditions C1/C2 of the cellular method, an Euler operator's precondition)."
);
create_exception!(gmap, InputError, GmapError, "An argument that is not a valid input (bad facets, shapes, options).");
create_exception!(gmap, ValidityError, GmapError, "A map that breaks the G-map axioms (`GMap.check`).");
create_exception!(gmap, ComputationError, GmapError, "A computation that could not finish (overflow, internal check).");

/// The kind of a failure: which exception it becomes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// [`ParseError`]
    Parse,
    /// [`LimitError`]
    Limit,
    /// [`PreconditionError`]
    Precondition,
    /// [`InputError`]
    Input,
    /// [`ValidityError`]
    Validity,
    /// [`ComputationError`]
    Computation,
    /// `OSError` (a file that cannot be opened or written)
    Io,
}

/// A failure on its way to Python: the kind, the command line's message, and where in a
/// file it lies when known.
#[derive(Debug)]
pub struct Failure {
    pub kind: Kind,
    pub message: String,
    pub file: Option<String>,
    pub line: Option<usize>,
}

pub type Res<T> = Result<T, Failure>;

impl Failure {
    pub fn new(kind: Kind, message: impl Into<String>) -> Self {
        Failure { kind, message: message.into(), file: None, line: None }
    }

    pub fn input(message: impl Into<String>) -> Self {
        Failure::new(Kind::Input, message)
    }

    /// Prefixes the message with `what: ` (the command line's context) and records the file.
    pub fn in_file(mut self, file: &str) -> Self {
        if !self.message.starts_with(file) {
            self.message = format!("{file}: {}", self.message);
        }
        if self.file.is_none() {
            self.file = Some(file.to_string());
        }
        self
    }
}

/// The one-line message of an error, as the command line prints it: the chain of causes
/// joined by `: `, a cause left out when the message already ends with it.
pub fn chain_message(e: &(dyn std::error::Error + 'static)) -> String {
    let mut msg = String::new();
    let mut cur: Option<&(dyn std::error::Error + 'static)> = Some(e);
    while let Some(c) = cur {
        let text = c.to_string();
        if !msg.ends_with(&text) {
            if !msg.is_empty() {
                msg.push_str(": ");
            }
            msg.push_str(&text);
        }
        cur = c.source();
    }
    msg.replace('\n', " ")
}

fn import_kind(e: &gmap_ops::import::ImportError) -> (Kind, Option<usize>) {
    use gmap_ops::import::ImportError as E;
    match e {
        E::Io(_) => (Kind::Io, None),
        E::Syntax { line, .. } => (Kind::Parse, Some(*line)),
        E::MixedDimension { line, .. } | E::RepeatedVertex { line, .. } => (Kind::Parse, Some(*line)),
        E::RidgeInManyFacets { lines, .. } => (Kind::Precondition, lines.first().copied()),
        E::TooManyDarts { .. } | E::OutOfMemory { .. } | E::MemoryLimit(_) => (Kind::Limit, None),
        E::EdgeInManyPolygons { lines, .. } => (Kind::Precondition, lines.first().copied()),
        _ => (Kind::Parse, None),
    }
}

impl From<gmap_ops::import::ImportError> for Failure {
    fn from(e: gmap_ops::import::ImportError) -> Self {
        let (kind, line) = import_kind(&e);
        Failure { kind, message: chain_message(&e), file: None, line }
    }
}

impl From<gmap_ops::import::FileError> for Failure {
    fn from(e: gmap_ops::import::FileError) -> Self {
        let (kind, line) = import_kind(&e.error);
        let file = e.path.display().to_string();
        Failure { kind, message: chain_message(&e), file: Some(file), line }
    }
}

impl From<gmap_core::io::ReadError> for Failure {
    fn from(e: gmap_core::io::ReadError) -> Self {
        use gmap_core::io::ReadErrorKind as K;
        let kind = match &e.kind {
            K::Io(_) => Kind::Io,
            K::DartLimit { .. } => Kind::Limit,
            _ => Kind::Parse,
        };
        Failure { kind, message: chain_message(&e), file: Some(e.file.clone()), line: e.line }
    }
}

impl From<gmap_core::io::WriteError> for Failure {
    fn from(e: gmap_core::io::WriteError) -> Self {
        Failure::new(Kind::Io, chain_message(&e))
    }
}

impl From<gmap_homology::json::JsonFileError> for Failure {
    fn from(e: gmap_homology::json::JsonFileError) -> Self {
        let kind = if matches!(e.error, gmap_homology::json::JsonError::Io(_)) { Kind::Io } else { Kind::Parse };
        Failure { kind, message: chain_message(&e), file: Some(e.path.display().to_string()), line: None }
    }
}

impl From<gmap_homology::json::JsonError> for Failure {
    fn from(e: gmap_homology::json::JsonError) -> Self {
        Failure::new(Kind::Parse, chain_message(&e))
    }
}

impl From<gmap_homology::HomologyError> for Failure {
    fn from(e: gmap_homology::HomologyError) -> Self {
        use gmap_homology::HomologyError as E;
        let kind = match &e {
            E::NotPrime(_) => Kind::Input,
            E::MemoryLimit(_) | E::GeneratorsTooLarge { .. } => Kind::Limit,
            _ => Kind::Computation,
        };
        Failure::new(kind, chain_message(&e))
    }
}

impl From<gmap_homology::PreconditionError> for Failure {
    fn from(e: gmap_homology::PreconditionError) -> Self {
        Failure::new(Kind::Precondition, chain_message(&e))
    }
}

impl From<gmap_homology::simplices::FaceError> for Failure {
    fn from(e: gmap_homology::simplices::FaceError) -> Self {
        use gmap_homology::simplices::FaceError as E;
        let kind = match &e {
            E::TooManyFaces { .. } | E::FacetTooLarge(_) => Kind::Limit,
            _ => Kind::Input,
        };
        Failure::new(kind, chain_message(&e))
    }
}

impl From<gmap_homology::cubical::CubicalError> for Failure {
    fn from(e: gmap_homology::cubical::CubicalError) -> Self {
        use gmap_homology::cubical::CubicalError as E;
        let kind = if matches!(e, E::BadShape(_)) { Kind::Input } else { Kind::Limit };
        Failure::new(kind, chain_message(&e))
    }
}

impl From<gmap_core::resources::MemoryLimit> for Failure {
    fn from(e: gmap_core::resources::MemoryLimit) -> Self {
        Failure::new(Kind::Limit, chain_message(&e))
    }
}

impl From<gmap_core::ValidityError> for Failure {
    fn from(e: gmap_core::ValidityError) -> Self {
        Failure::new(Kind::Validity, chain_message(&e))
    }
}

impl From<gmap_core::EditError> for Failure {
    fn from(e: gmap_core::EditError) -> Self {
        Failure::new(Kind::Precondition, chain_message(&e))
    }
}

impl From<gmap_ops::euler::EulerError> for Failure {
    fn from(e: gmap_ops::euler::EulerError) -> Self {
        Failure::new(Kind::Precondition, chain_message(&e))
    }
}

impl From<gmap_ops::build::BuildError> for Failure {
    fn from(e: gmap_ops::build::BuildError) -> Self {
        Failure::new(Kind::Input, chain_message(&e))
    }
}

impl From<std::io::Error> for Failure {
    fn from(e: std::io::Error) -> Self {
        Failure::new(Kind::Io, chain_message(&e))
    }
}

impl From<gmap::Error> for Failure {
    fn from(e: gmap::Error) -> Self {
        use gmap::ErrorKind as K;
        let kind = match e.kind() {
            K::Parse if e.line().is_none() && e.chain().iter().any(|c| c.contains("os error")) => Kind::Io,
            K::Parse => Kind::Parse,
            K::Limit => Kind::Limit,
            K::Precondition => Kind::Precondition,
            K::Write => Kind::Io,
            K::Compute => Kind::Computation,
            _ => Kind::Input,
        };
        // an input made in memory has no file: its messages open with ": "
        let message = e.to_string();
        let message = message.strip_prefix(": ").map(str::to_string).unwrap_or(message);
        let file = e.path().map(|p| p.display().to_string()).filter(|p| !p.is_empty());
        Failure { kind, message, file, line: e.line() }
    }
}

impl From<Failure> for PyErr {
    fn from(f: Failure) -> PyErr {
        let err = match f.kind {
            Kind::Parse => ParseError::new_err(f.message.clone()),
            Kind::Limit => LimitError::new_err(f.message.clone()),
            Kind::Precondition => PreconditionError::new_err(f.message.clone()),
            Kind::Input => InputError::new_err(f.message.clone()),
            Kind::Validity => ValidityError::new_err(f.message.clone()),
            Kind::Computation => ComputationError::new_err(f.message.clone()),
            Kind::Io => pyo3::exceptions::PyOSError::new_err(f.message.clone()),
        };
        Python::with_gil(|py| {
            let v = err.value(py);
            let _ = v.setattr("file", f.file.clone());
            let _ = v.setattr("line", f.line);
            let _ = v.setattr("message", f.message.clone());
        });
        err
    }
}

/// Registers the exceptions on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("GmapError", py.get_type::<GmapError>())?;
    m.add("ParseError", py.get_type::<ParseError>())?;
    m.add("LimitError", py.get_type::<LimitError>())?;
    m.add("PreconditionError", py.get_type::<PreconditionError>())?;
    m.add("InputError", py.get_type::<InputError>())?;
    m.add("ValidityError", py.get_type::<ValidityError>())?;
    m.add("ComputationError", py.get_type::<ComputationError>())?;
    Ok(())
}
