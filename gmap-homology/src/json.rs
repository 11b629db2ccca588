//! The `.json` incidence graph / architectural complex format (CONTRACT §2).
//!
//! ```json
//! {"dimension": 2,
//!  "regions": [{"id": 0, "dim": 0}, {"id": 1, "dim": 1}, {"id": 2, "dim": 2}],
//!  "incidence": [{"from": 2, "to": 1, "weight": 0}, {"from": 1, "to": 0, "weight": 0}]}
//! ```
//!
//! `regions` are the cells (or regions), `incidence` exactly the defined entries of the
//! partial boundary matrix: `from` a region of dimension k, `to` a lower region adhering to
//! it, `weight` the signed incidence number (0 kept). [`read_json`] parses and validates the
//! whole of AC Def. 3.1 through [`ArchComplex::try_new`]: a cycle, a dimension that does not
//! decrease, a non-zero weight across a gap, duplicate ids or entries and `δ² ≠ 0` are each
//! a distinct [`JsonError::Arch`] error naming the regions. `"dimension"` may be omitted
//! (then the largest region dimension, 0 for no region).
//!
//! ```
//! use gmap_homology::json::{read_json, write_json};
//! let text = r#"{"dimension": 1, "regions": [{"id": 0, "dim": 0}, {"id": 1, "dim": 1}],
//!                "incidence": [{"from": 1, "to": 0, "weight": 0}]}"#;
//! let x = read_json(text).unwrap();
//! assert_eq!(x.region_counts(), vec![1, 1]);
//! assert_eq!(read_json(&write_json(&x)).unwrap(), x);
//! ```
//!
//! Both directions are O(R + E) (plus the validation of Def. 3.1).

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

use serde_json::Value;
use thiserror::Error;

use crate::arch::{ArchComplex, ArchError, Region};

/// Why a `.json` text is not an architectural complex.
#[derive(Debug, Error)]
pub enum JsonError {
    /// Not JSON at all.
    #[error("line {line}, column {column}: invalid JSON: {message}")]
    Syntax {
        /// 1-based line
        line: usize,
        /// 1-based column
        column: usize,
        /// what the parser said
        message: String,
    },
    /// A required field is missing or has the wrong type.
    #[error("{path}: {problem}")]
    Schema {
        /// where, e.g. `regions[3].dim`
        path: String,
        /// what is wrong
        problem: String,
    },
    /// The file could not be read.
    #[error("cannot read: {0}")]
    Io(String),
    /// The data violates AC Def. 3.1.
    #[error(transparent)]
    Arch(#[from] ArchError),
}

fn schema(path: impl Into<String>, problem: impl Into<String>) -> JsonError {
    JsonError::Schema { path: path.into(), problem: problem.into() }
}

fn field<'a>(obj: &'a Value, path: &str, key: &str) -> Result<&'a Value, JsonError> {
    let o = obj.as_object().ok_or_else(|| schema(path, "expected an object"))?;
    o.get(key).ok_or_else(|| schema(format!("{path}.{key}"), "missing"))
}

fn as_u64(v: &Value, path: &str) -> Result<u64, JsonError> {
    v.as_u64().ok_or_else(|| schema(path, format!("expected a non-negative integer, found {v}")))
}

fn as_i64(v: &Value, path: &str) -> Result<i64, JsonError> {
    v.as_i64().ok_or_else(|| schema(path, format!("expected an integer in the range of i64, found {v}")))
}

fn as_dim(v: &Value, path: &str) -> Result<usize, JsonError> {
    let d = as_u64(v, path)?;
    usize::try_from(d).ok().filter(|&d| d <= 1 << 20).ok_or_else(|| schema(path, format!("dimension {d} is too large")))
}

/// Parses and validates a `.json` architectural complex. See the module docs.
pub fn read_json(text: &str) -> Result<ArchComplex, JsonError> {
    let root: Value = serde_json::from_str(text).map_err(|e| JsonError::Syntax {
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
    })?;
    if !root.is_object() {
        return Err(schema("top level", "expected an object with \"regions\" and \"incidence\""));
    }
    let regs =
        field(&root, "top level", "regions")?.as_array().ok_or_else(|| schema("regions", "expected an array"))?;
    let mut regions = Vec::with_capacity(regs.len());
    for (k, r) in regs.iter().enumerate() {
        let p = format!("regions[{k}]");
        let id = as_u64(field(r, &p, "id")?, &format!("{p}.id"))?;
        let dim = as_dim(field(r, &p, "dim")?, &format!("{p}.dim"))?;
        regions.push(Region { id, dim });
    }
    let dim = match root.get("dimension") {
        Some(v) => as_dim(v, "dimension")?,
        None => regions.iter().map(|r| r.dim).max().unwrap_or(0),
    };
    let inc = match root.get("incidence") {
        Some(v) => v.as_array().ok_or_else(|| schema("incidence", "expected an array"))?.as_slice(),
        None => return Err(schema("incidence", "missing")),
    };
    let mut entries = Vec::with_capacity(inc.len());
    for (k, e) in inc.iter().enumerate() {
        let p = format!("incidence[{k}]");
        let from = as_u64(field(e, &p, "from")?, &format!("{p}.from"))?;
        let to = as_u64(field(e, &p, "to")?, &format!("{p}.to"))?;
        let weight = as_i64(field(e, &p, "weight")?, &format!("{p}.weight"))?;
        entries.push((from, to, weight));
    }
    Ok(ArchComplex::try_new(dim, regions, entries)?)
}

/// Reads and validates a `.json` file; errors name the file (and the line for syntax).
pub fn read_json_file(path: &Path) -> Result<ArchComplex, JsonFileError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| JsonFileError { path: path.to_path_buf(), error: JsonError::Io(e.to_string()) })?;
    read_json(&text).map_err(|error| JsonFileError { path: path.to_path_buf(), error })
}

/// A [`JsonError`] with the file it comes from.
#[derive(Debug, Error)]
#[error("{}: {error}", path.display())]
pub struct JsonFileError {
    /// the file
    pub path: PathBuf,
    /// what is wrong
    pub error: JsonError,
}

/// Writes `text` to `path` through a temporary file in the same directory and a rename,
/// so that a failure never leaves a partial file.
pub fn write_text_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = path.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default();
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Writes the complex in the `.json` format, one region or entry per line.
pub fn write_json(x: &ArchComplex) -> String {
    let mut s = String::with_capacity(32 * (x.regions().len() + x.entries().len()) + 64);
    let _ = write!(s, "{{\"dimension\": {},\n \"regions\": [", x.dim());
    for (k, r) in x.regions().iter().enumerate() {
        let sep = if k == 0 { "" } else { ",\n  " };
        let _ = write!(s, "{sep}{{\"id\": {}, \"dim\": {}}}", r.id, r.dim);
    }
    s.push_str("],\n \"incidence\": [");
    for (k, (f, t, w)) in x.entry_ids().into_iter().enumerate() {
        let sep = if k == 0 { "" } else { ",\n  " };
        let _ = write!(s, "{sep}{{\"from\": {f}, \"to\": {t}, \"weight\": {w}}}");
    }
    s.push_str("]}\n");
    s
}
