//! The `.json` incidence graph / architectural complex format (docs/FORMATS.md).
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
//! a distinct [`JsonError::Arch`] error naming the regions; an object with the same key
//! twice is [`JsonError::DuplicateKey`]. `"dimension"` may be omitted
//! (then the largest region dimension, 0 for no region). A region may carry its own
//! topology, `"betti": [1, 2, 1]` (a torus 2-region; AC Def. 8.1), checked by
//! [`ArchComplex::with_region_betti`] and used by Algorithm 8.16; without it a region is a
//! cell (see [`ArchComplex::region_betti`]). A region may carry labels, an object of named
//! values, `"labels": {"name": "kitchen", "storey": 0, "area": 14.0}`: a JSON integer is an
//! integer label (64 bits), any other number a real, a string a text; the order of the
//! members is kept ([`ArchComplex::region_labels`]), a name given twice is
//! [`JsonError::DuplicateKey`] like any repeated key, and any other value is a
//! [`JsonError::Schema`] error naming `regions[i].labels.<name>`.
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
use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde_json::Value;
use thiserror::Error;

use gmap_core::{LabelValue, Labels};

use crate::complex::arch::{ArchComplex, ArchError, Region, RegionId};

/// Why a `.json` text is not an architectural complex.
#[derive(Debug, Error)]
#[non_exhaustive]
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
    /// An object holds the same key twice (JSON leaves the meaning open; readers differ).
    #[error("line {line}, column {column}: the key \"{key}\" appears twice in one object")]
    DuplicateKey {
        /// the key (at most 80 characters of it)
        key: String,
        /// 1-based line of its second occurrence
        line: usize,
        /// 1-based column just after it
        column: usize,
    },
    /// The file is too large for the memory limit (`--max-memory`).
    #[error(transparent)]
    MemoryLimit(gmap_core::resources::MemoryLimit),
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

/// Where a value sits, formatted only when an error is reported.
#[derive(Clone, Copy)]
struct At<'a> {
    list: &'a str,
    index: usize,
}

impl At<'_> {
    fn path(self, key: &str) -> String {
        format!("{}[{}].{key}", self.list, self.index)
    }
}

fn field<'a>(obj: &'a Value, at: At<'_>, key: &str) -> Result<&'a Value, JsonError> {
    let o = obj.as_object().ok_or_else(|| schema(format!("{}[{}]", at.list, at.index), "expected an object"))?;
    o.get(key).ok_or_else(|| schema(at.path(key), "missing"))
}

fn get_u64(obj: &Value, at: At<'_>, key: &str) -> Result<u64, JsonError> {
    let v = field(obj, at, key)?;
    v.as_u64().ok_or_else(|| schema(at.path(key), format!("expected a non-negative integer, found {v}")))
}

fn get_i64(obj: &Value, at: At<'_>, key: &str) -> Result<i64, JsonError> {
    let v = field(obj, at, key)?;
    v.as_i64().ok_or_else(|| schema(at.path(key), format!("expected an integer in the range of i64, found {v}")))
}

fn check_dim(d: u64, path: impl FnOnce() -> String) -> Result<usize, JsonError> {
    usize::try_from(d)
        .ok()
        .filter(|&d| d <= 1 << 20)
        .ok_or_else(|| schema(path(), format!("dimension {d} is too large")))
}

#[derive(Deserialize)]
struct RawRegion {
    id: u64,
    dim: u64,
    /// the region's own Betti numbers (AC Def. 8.1), when it is not a cell
    #[serde(default)]
    betti: Option<Vec<u64>>,
    /// the region's labels, in the order of the file
    #[serde(default)]
    labels: Option<RawLabels>,
}

/// A `"labels"` object, its members in the order of the text.
struct RawLabels(Vec<(String, Value)>);

impl<'de> Deserialize<'de> for RawLabels {
    fn deserialize<D: serde::Deserializer<'de>>(de: D) -> Result<Self, D::Error> {
        struct Members;
        impl<'de> serde::de::Visitor<'de> for Members {
            type Value = RawLabels;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("an object of labels")
            }
            fn visit_map<M: serde::de::MapAccess<'de>>(self, mut m: M) -> Result<RawLabels, M::Error> {
                let mut out = Vec::new();
                while let Some((k, v)) = m.next_entry::<String, Value>()? {
                    out.push((k, v));
                }
                Ok(RawLabels(out))
            }
        }
        de.deserialize_map(Members)
    }
}

/// The labels of region `index` from the members of its `"labels"` object: a JSON integer
/// is an integer label (it must fit i64), another number a real, a string a text.
fn region_labels(members: &[(String, Value)], index: usize) -> Result<Labels, JsonError> {
    let mut out = Labels::new();
    for (name, v) in members {
        let at = || format!("regions[{index}].labels.{name}");
        let value = match v {
            Value::String(t) => LabelValue::Text(t.clone()),
            Value::Number(x) => match x.as_i64() {
                Some(i) => LabelValue::Int(i),
                None if x.is_u64() || !x.to_string().contains(['.', 'e', 'E']) => {
                    return Err(schema(at(), format!("{x} does not fit a 64-bit integer")))
                }
                None => match x.as_f64() {
                    Some(r) if r.is_finite() => LabelValue::Real(r),
                    _ => return Err(schema(at(), format!("{x} is not a finite real"))),
                },
            },
            other => return Err(schema(at(), format!("expected an integer, a real or a text, found {other}"))),
        };
        out.set(name, value);
    }
    Ok(out)
}

/// The complex with the labels given to its regions (`(region id, labels)`).
fn with_labels(mut x: ArchComplex, labels: Vec<(RegionId, Labels)>) -> Result<ArchComplex, JsonError> {
    for (id, l) in labels {
        x = x.with_region_labels(id, l)?;
    }
    Ok(x)
}

/// The optional `"betti"` of region `index`, as counts.
fn betti_counts(v: &[u64], index: usize) -> Result<Vec<usize>, JsonError> {
    v.iter()
        .map(|&b| usize::try_from(b).ok())
        .collect::<Option<Vec<usize>>>()
        .ok_or_else(|| schema(At { list: "regions", index }.path("betti"), "a Betti number is too large"))
}

/// The complex with the Betti numbers given to its regions (`(region id, numbers)`).
fn with_betti(mut x: ArchComplex, betti: Vec<(RegionId, Vec<usize>)>) -> Result<ArchComplex, JsonError> {
    for (id, b) in betti {
        x = x.with_region_betti(id, b)?;
    }
    Ok(x)
}

#[derive(Deserialize)]
struct RawEntry {
    from: u64,
    to: u64,
    weight: i64,
}

#[derive(Deserialize)]
struct Raw {
    dimension: Option<u64>,
    regions: Vec<RawRegion>,
    incidence: Vec<RawEntry>,
}

/// Parses and validates a `.json` architectural complex. See the module docs.
///
/// Well-formed input is deserialised straight into typed records (no intermediate tree);
/// anything else is parsed again as a JSON tree to say exactly which field is wrong.
pub fn read_json(text: &str) -> Result<ArchComplex, JsonError> {
    if let Some(d) = crate::complex::unique_keys::find_duplicate(text) {
        return Err(JsonError::DuplicateKey { key: d.key, line: d.line, column: d.column });
    }
    let raw: Raw = match serde_json::from_str(text) {
        Ok(raw) => raw,
        Err(_) => return read_json_slow(text),
    };
    let mut regions = Vec::with_capacity(raw.regions.len());
    let mut betti = Vec::new();
    let mut labels = Vec::new();
    for (index, r) in raw.regions.iter().enumerate() {
        let dim = check_dim(r.dim, || At { list: "regions", index }.path("dim"))?;
        regions.push(Region { id: RegionId(r.id), dim });
        if let Some(b) = &r.betti {
            betti.push((RegionId(r.id), betti_counts(b, index)?));
        }
        if let Some(l) = &r.labels {
            labels.push((RegionId(r.id), region_labels(&l.0, index)?));
        }
    }
    let dim = match raw.dimension {
        Some(d) => check_dim(d, || "dimension".to_string())?,
        None => regions.iter().map(|r| r.dim).max().unwrap_or(0),
    };
    let entries = raw.incidence.iter().map(|e| (RegionId(e.from), RegionId(e.to), e.weight)).collect();
    with_labels(with_betti(ArchComplex::try_new(dim, regions, entries)?, betti)?, labels)
}

/// The tree-based reader, for its precise messages on malformed input.
fn read_json_slow(text: &str) -> Result<ArchComplex, JsonError> {
    let root: Value = serde_json::from_str(text).map_err(|e| JsonError::Syntax {
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
    })?;
    let Some(obj) = root.as_object() else {
        return Err(schema("top level", "expected an object with \"regions\" and \"incidence\""));
    };
    let regs = obj.get("regions").ok_or_else(|| schema("regions", "missing"))?;
    let regs = regs.as_array().ok_or_else(|| schema("regions", "expected an array"))?;
    let mut regions = Vec::with_capacity(regs.len());
    let mut betti = Vec::new();
    let mut labels = Vec::new();
    for (index, r) in regs.iter().enumerate() {
        let at = At { list: "regions", index };
        let id = get_u64(r, at, "id")?;
        let dim = check_dim(get_u64(r, at, "dim")?, || at.path("dim"))?;
        regions.push(Region { id: RegionId(id), dim });
        if let Some(v) = r.get("betti") {
            let list =
                v.as_array().and_then(|a| a.iter().map(Value::as_u64).collect::<Option<Vec<u64>>>()).ok_or_else(
                    || schema(at.path("betti"), format!("expected an array of non-negative integers, found {v}")),
                )?;
            betti.push((RegionId(id), betti_counts(&list, index)?));
        }
        if let Some(v) = r.get("labels") {
            let members = v
                .as_object()
                .ok_or_else(|| schema(at.path("labels"), format!("expected an object of labels, found {v}")))?;
            let members: Vec<(String, Value)> = members.iter().map(|(k, v)| (k.clone(), v.clone())).collect();
            labels.push((RegionId(id), region_labels(&members, index)?));
        }
    }
    let dim = match obj.get("dimension") {
        Some(v) => {
            let d =
                v.as_u64().ok_or_else(|| schema("dimension", format!("expected a non-negative integer, found {v}")))?;
            check_dim(d, || "dimension".to_string())?
        }
        None => regions.iter().map(|r| r.dim).max().unwrap_or(0),
    };
    let inc = obj.get("incidence").ok_or_else(|| schema("incidence", "missing"))?;
    let inc = inc.as_array().ok_or_else(|| schema("incidence", "expected an array"))?;
    let mut entries = Vec::with_capacity(inc.len());
    for (index, e) in inc.iter().enumerate() {
        let at = At { list: "incidence", index };
        entries.push((RegionId(get_u64(e, at, "from")?), RegionId(get_u64(e, at, "to")?), get_i64(e, at, "weight")?));
    }
    with_labels(with_betti(ArchComplex::try_new(dim, regions, entries)?, betti)?, labels)
}

/// Reads and validates a `.json` file; errors name the file (and the line for syntax).
///
/// The file is refused before it is read when the text and what is built from it (about
/// four times its size) would exceed the memory limit ([`gmap_core::resources`]).
pub fn read_json_file(path: &Path) -> Result<ArchComplex, JsonFileError> {
    let size = std::fs::metadata(path).map(|m| m.len()).unwrap_or(0);
    gmap_core::resources::check_memory("the file and its complex", size.checked_mul(4))
        .map_err(|e| JsonFileError { path: path.to_path_buf(), error: JsonError::MemoryLimit(e) })?;
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

/// A JSON string literal of `t`.
fn json_string(t: &str) -> String {
    serde_json::Value::String(t.to_string()).to_string()
}

/// Writes the complex in the `.json` format, one region or entry per line; a region given
/// Betti numbers keeps them (`"betti"`), a region with labels keeps them (`"labels"`).
pub fn write_json(x: &ArchComplex) -> String {
    let mut s = String::with_capacity(32 * (x.regions().len() + x.entries().len()) + 64);
    let _ = write!(s, "{{\"dimension\": {},\n \"regions\": [", x.dim());
    for (k, r) in x.regions().iter().enumerate() {
        let sep = if k == 0 { "" } else { ",\n  " };
        let _ = write!(s, "{sep}{{\"id\": {}, \"dim\": {}", r.id, r.dim);
        if x.has_region_betti(k) {
            let b: Vec<String> = x.region_betti(k).iter().map(|b| b.to_string()).collect();
            let _ = write!(s, ", \"betti\": [{}]", b.join(", "));
        }
        let labels = x.region_labels(k);
        if !labels.is_empty() {
            s.push_str(", \"labels\": {");
            for (j, (name, v)) in labels.iter().enumerate() {
                if j > 0 {
                    s.push_str(", ");
                }
                s.push_str(&json_string(name));
                s.push_str(": ");
                match v {
                    LabelValue::Int(i) => {
                        let _ = write!(s, "{i}");
                    }
                    // `{:?}` always shows a `.` or an exponent, so the reader sees a real
                    LabelValue::Real(r) => {
                        let _ = write!(s, "{r:?}");
                    }
                    LabelValue::Text(t) => s.push_str(&json_string(t)),
                }
            }
            s.push('}');
        }
        s.push('}');
    }
    s.push_str("],\n \"incidence\": [");
    for (k, (f, t, w)) in x.entry_ids().into_iter().enumerate() {
        let sep = if k == 0 { "" } else { ",\n  " };
        let _ = write!(s, "{sep}{{\"from\": {f}, \"to\": {t}, \"weight\": {w}}}");
    }
    s.push_str("]}\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labelled() -> ArchComplex {
        let x = ArchComplex::try_from_ids(1, &[(0, 0), (1, 0), (2, 1)], &[(2, 0, 1), (2, 1, -1)]).unwrap();
        let beam: Labels = [
            ("name", LabelValue::Text("main \"beam\"\n\u{e9}".into())),
            ("length", LabelValue::Real(2.0)),
            ("count", LabelValue::Int(-7)),
            ("big", LabelValue::Int(i64::MAX)),
            ("tiny", LabelValue::Real(1e-300)),
        ]
        .into_iter()
        .collect();
        x.with_region_labels(RegionId(2), beam).unwrap()
    }

    #[test]
    fn labels_round_trip_typed_and_in_order() {
        let x = labelled();
        let text = write_json(&x);
        assert!(
            text.contains(
                r#"{"id": 2, "dim": 1, "labels": {"name": "main \"beam\"\né", "length": 2.0, "count": -7, "big": 9223372036854775807, "tiny": 1e-300}}"#
            ),
            "{text}"
        );
        assert!(text.contains(r#"{"id": 0, "dim": 0},"#), "{text}");
        let back = read_json(&text).unwrap();
        assert_eq!(back, x);
        let names: Vec<&str> = back.region_labels(2).iter().map(|(n, _)| n).collect();
        assert_eq!(names, ["name", "length", "count", "big", "tiny"]);
        assert_eq!(back.region_labels(2).get("length"), Some(&LabelValue::Real(2.0)));
        assert!(back.region_labels(0).is_empty());
        // the tree-based reader (taken when the fast one fails) keeps them too
        assert_eq!(read_json_slow(&text).unwrap().region_labels(2).get("count"), Some(&LabelValue::Int(-7)));
    }

    #[test]
    fn bad_labels_are_refused_with_their_place() {
        let with = |labels: &str| {
            format!(
                r#"{{"regions": [{{"id": 0, "dim": 0}}, {{"id": 5, "dim": 0, "labels": {labels}}}], "incidence": []}}"#
            )
        };
        let err = |labels: &str| read_json(&with(labels)).unwrap_err().to_string();
        assert_eq!(err(r#"{"a": true}"#), "regions[1].labels.a: expected an integer, a real or a text, found true");
        assert_eq!(err(r#"{"a": null}"#), "regions[1].labels.a: expected an integer, a real or a text, found null");
        assert_eq!(err(r#"{"a": [1]}"#), "regions[1].labels.a: expected an integer, a real or a text, found [1]");
        assert_eq!(
            err(r#"{"a": 9223372036854775808}"#),
            "regions[1].labels.a: 9223372036854775808 does not fit a 64-bit integer"
        );
        assert_eq!(err(r#"[1, 2]"#), "regions[1].labels: expected an object of labels, found [1,2]");
        assert_eq!(err(r#""kitchen""#), "regions[1].labels: expected an object of labels, found \"kitchen\"");
        assert!(matches!(
            read_json(&with(r#"{"name": "a", "name": "b"}"#)),
            Err(JsonError::DuplicateKey { ref key, .. }) if key == "name"
        ));
        // an empty object is no label; a real written with an exponent is a real
        let x = read_json(&with(r#"{}"#)).unwrap();
        assert!(x.region_labels(1).is_empty());
        let x = read_json(&with(r#"{"e": 1e2, "n": -0}"#)).unwrap();
        assert_eq!(x.region_labels(1).get("e"), Some(&LabelValue::Real(100.0)));
        assert_eq!(x.region_labels(1).get("n"), Some(&LabelValue::Int(0)));
    }

    #[test]
    fn a_label_that_is_not_finite_is_refused() {
        let x = ArchComplex::try_from_ids(0, &[(3, 0)], &[]).unwrap();
        let l: Labels = [("w", LabelValue::Real(f64::NAN))].into_iter().collect();
        assert_eq!(
            x.with_region_labels(RegionId(3), l).unwrap_err().to_string(),
            "region 3: the label `w` is not a finite real"
        );
    }

    fn label_value() -> impl proptest::strategy::Strategy<Value = LabelValue> {
        use proptest::prelude::*;
        prop_oneof![
            any::<i64>().prop_map(LabelValue::Int),
            any::<f64>().prop_filter("finite", |x| x.is_finite()).prop_map(LabelValue::Real),
            "\\PC{0,8}|[\"\\\\\n\t\u{0}-\u{1f}]{0,4}".prop_map(LabelValue::Text),
        ]
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// Any labels on the regions of a path of edges are written and read back as they
        /// were, in order and typed; the `.dot` text keeps one node per line.
        #[test]
        fn labels_write_and_read_back(
            labels in proptest::collection::vec(
                proptest::collection::vec(("\\PC{0,6}", label_value()), 0..4),
                1..6,
            )
        ) {
            let n = labels.len() as u64;
            let regions: Vec<(u64, usize)> = (0..n).map(|k| (k, 0)).chain((0..n - 1).map(|k| (n + k, 1))).collect();
            let entries: Vec<(u64, u64, i64)> =
                (0..n - 1).flat_map(|k| [(n + k, k, -1), (n + k, k + 1, 1)]).collect();
            let mut x = ArchComplex::try_from_ids(1, &regions, &entries).unwrap();
            for (k, l) in labels.into_iter().enumerate() {
                let l: Labels = l.into_iter().collect();
                x = x.with_region_labels(RegionId(k as u64), l).unwrap();
            }
            let text = write_json(&x);
            let back = read_json(&text).unwrap();
            proptest::prop_assert_eq!(&back, &x);
            proptest::prop_assert_eq!(write_json(&back), text);
            let dot = crate::complex::dot::write_dot(&x);
            let nodes = dot.lines().filter(|l| l.starts_with("  r") && l.contains(" [label=") && !l.contains("->")).count();
            proptest::prop_assert_eq!(nodes, x.regions().len());
        }
    }
}
