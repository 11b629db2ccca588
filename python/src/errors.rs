//! The exceptions of the package and the mapping of the facade's errors onto them.
//!
//! Every failure reaches Python as a subclass of `gmap.GmapError` carrying the message the
//! command line prints after `error: ` and, as attributes, where it lies: `path` (and its
//! older name `file`), `line`, and `item`, what the error is about when it names something
//! (`item_kind` says what: a dart numbered as the Python `GMap` numbers its darts, a cell
//! `(dim, dart)`, a simplex by its vertex labels, a region by its id, a facet of a list by
//! its index), all taken from the facade's typed `gmap::Error` (`kind`, `path`, `line`,
//! `item`, `is_io`). The subclass is chosen by the kind of the error, never by its text.

use std::path::Path;

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

create_exception!(gmap, GmapError, PyException, "Base class of every error raised by gmap.");
create_exception!(
    gmap,
    ParseError,
    GmapError,
    "A file that does not fit its format; `.path` (also `.file`) and `.line` (or None) say where."
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

/// What an error is about, as the exception's `item` (and `item_kind`) give it to Python.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Item {
    /// a dart, in the Python GMap's numbering (the file's for a map read from one): an int
    Dart(u64),
    /// the `dim`-cell of a dart (its smallest, as `GMap.cells` gives it): `(dim, dart)`
    Cell { dim: usize, dart: u64 },
    /// a simplex by its vertex labels: a tuple of ints
    Simplex(Vec<u64>),
    /// a region of an architectural complex by its id: a str
    Region(String),
    /// a facet of facets given from Python, by its index: an int
    Facet(usize),
}

impl Item {
    /// The facade's item in the package's terms (`None` for a kind of item this build does
    /// not know).
    fn of(item: &gmap::Item) -> Option<Item> {
        Some(match item {
            gmap::Item::Dart(d) => Item::Dart(*d),
            gmap::Item::Cell { dim, dart } => Item::Cell { dim: *dim, dart: *dart },
            gmap::Item::Simplex(v) => Item::Simplex(v.clone()),
            gmap::Item::Region(r) => Item::Region(r.clone()),
            _ => return None,
        })
    }

    /// `item_kind`: what the item is.
    fn kind(&self) -> &'static str {
        match self {
            Item::Dart(_) => "dart",
            Item::Cell { .. } => "cell",
            Item::Simplex(_) => "simplex",
            Item::Region(_) => "region",
            Item::Facet(_) => "facet",
        }
    }

    /// `item`: the Python value.
    fn to_py(&self, py: Python<'_>) -> PyResult<PyObject> {
        Ok(match self {
            Item::Dart(d) => d.into_pyobject(py)?.into_any().unbind(),
            Item::Cell { dim, dart } => (*dim, *dart).into_pyobject(py)?.into_any().unbind(),
            Item::Simplex(v) => pyo3::types::PyTuple::new(py, v)?.into_any().unbind(),
            Item::Region(r) => r.into_pyobject(py)?.into_any().unbind(),
            Item::Facet(f) => f.into_pyobject(py)?.into_any().unbind(),
        })
    }
}

/// A failure on its way to Python: the kind, the command line's message, and where it lies
/// when known.
#[derive(Debug)]
pub struct Failure {
    pub kind: Kind,
    pub message: String,
    pub path: Option<String>,
    pub line: Option<usize>,
    pub item: Option<Item>,
}

pub type Res<T> = Result<T, Failure>;

impl Failure {
    pub fn new(kind: Kind, message: impl Into<String>) -> Self {
        Failure { kind, message: message.into(), path: None, line: None, item: None }
    }

    pub fn input(message: impl Into<String>) -> Self {
        Failure::new(Kind::Input, message)
    }

    /// This failure about the file `path`.
    pub fn at_path(mut self, path: &Path) -> Self {
        self.path = Some(path.display().to_string());
        self
    }

    /// This failure naming dart `k` (the Python GMap's numbering).
    pub fn with_dart(mut self, k: usize) -> Self {
        self.item = Some(Item::Dart(k as u64));
        self
    }

    /// This failure naming the facet of index `k` of facets given from Python.
    pub fn with_facet(mut self, k: usize) -> Self {
        self.item = Some(Item::Facet(k));
        self
    }

    /// A reader's refusal of what was made in memory (facets, a cubical set): sorted into
    /// kinds, with its line and item, by the facade (as if read from a file without a
    /// name), its message the reader's own.
    pub fn in_memory(e: gmap::ops::import::ImportError) -> Self {
        let message = chain_message(&e);
        let f = Failure::from(gmap::Error::from(gmap::ops::import::FileError::new(Path::new(""), e)));
        Failure { message, path: None, ..f }
    }

    /// A map that breaks the G-map axioms (`GMap.check`, `GMap.from_alphas`), naming the
    /// dart where it fails (the dense numbering is the GMap's).
    pub fn validity(e: gmap::core::ValidityError) -> Self {
        use gmap::core::ValidityError as V;
        let dart = match &e {
            V::OutOfRange { dart, .. } | V::NotInvolution { dart, .. } | V::NotCommuting { dart, .. } => {
                Some(dart.index())
            }
            // the variants without a dart (a dimension out of range) name none
            _ => None,
        };
        let f = Failure::new(Kind::Validity, chain_message(&e));
        match dart {
            Some(k) => f.with_dart(k),
            None => f,
        }
    }

    /// A builder's refusal: its arguments (InputError), or the size of what it would make
    /// (LimitError).
    pub fn build(e: gmap::ops::build::BuildError) -> Self {
        use gmap::ops::build::BuildError as B;
        let kind = match e {
            B::TooManyDarts { .. } | B::MemoryLimit(_) => Kind::Limit,
            _ => Kind::Input,
        };
        Failure::new(kind, chain_message(&e))
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

impl From<gmap::Error> for Failure {
    fn from(e: gmap::Error) -> Self {
        use gmap::ErrorKind as K;
        // a file that cannot be opened, read or written is an OSError, whatever the stage
        let kind = match e.kind() {
            _ if e.is_io() => Kind::Io,
            K::Parse => Kind::Parse,
            K::Limit => Kind::Limit,
            K::Precondition => Kind::Precondition,
            K::Write => Kind::Io,
            K::Compute => Kind::Computation,
            _ => Kind::Input,
        };
        // an input made in memory is a file without a name, which the facade's messages name
        // first: an empty name before its ": " (a real file's name is never empty)
        let message = e.to_string();
        let message = message.strip_prefix(": ").map(str::to_string).unwrap_or(message);
        let path = e.path().filter(|p| !p.as_os_str().is_empty()).map(|p| p.display().to_string());
        let item = e.item().and_then(Item::of);
        Failure { kind, message, path, line: e.line(), item }
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
            let item: Option<PyObject> = f.item.as_ref().and_then(|i| i.to_py(py).ok());
            // attributes of a fresh exception object: setting them does not fail
            let _ = v.setattr("path", f.path.clone());
            let _ = v.setattr("file", f.path.clone());
            let _ = v.setattr("line", f.line);
            let _ = v.setattr("item", item);
            let _ = v.setattr("item_kind", f.item.as_ref().map(Item::kind));
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
