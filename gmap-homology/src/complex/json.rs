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
//! Points (`"point": [x, y, z]` on 0-regions) make the complex metrical: the reader refuses
//! one that does not conform ([`JsonError::NotConforming`]: the same point twice, a
//! T-junction, crossing edges; [`crate::arch::Shape`], TM §X) naming the cells, unless
//! [`JsonOptions::snap`] welds the points and splits the cells first
//! ([`crate::arch::snap`]). Regions whose signs are left out and whose boundary is open (a
//! room missing its roof or a party wall) are refused by [`ArchError::BoundaryOpen`].
//!
//! Both directions are O(R + E) (plus the validation of Def. 3.1 and the metrical check,
//! near-linear with its spatial grid).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde_json::Value;
use thiserror::Error;

use gmap_core::{LabelValue, Labels};

use crate::complex::arch::{
    orient_entries, ArchComplex, ArchError, MetricDefect, Region, RegionId, RegionNames, Shape,
};

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
    /// The data violates AC Def. 3.1 (or its signs left out cannot be chosen); the names
    /// are the file's (its ids, strings or numbers, and `name` labels).
    #[error("{}", .0.named(.1))]
    Arch(ArchError, Box<RegionNames>),
    /// The points do not make a conforming complex (TM §X): every defect found, within
    /// the tolerance, cells named as the file names them.
    #[error("{}", not_conforming(.defects, .names, *.tolerance))]
    NotConforming {
        /// what fails, in the order found
        defects: Vec<MetricDefect>,
        /// the file's names of the regions
        names: Box<RegionNames>,
        /// the tolerance of the decisions
        tolerance: f64,
    },
    /// `snap` was asked for a complex that cannot be snapped (weights given, a split it
    /// cannot make), or with a tolerance that is not a finite positive real.
    #[error("cannot snap: {0}")]
    Snap(String),
}

fn not_conforming(defects: &[MetricDefect], names: &RegionNames, tol: f64) -> String {
    let mut s = format!("the points do not make a conforming complex (tolerance {tol:e}): ");
    let list: Vec<String> = defects.iter().take(5).map(|d| d.named(names).to_string()).collect();
    s.push_str(&list.join("; "));
    if defects.len() > 5 {
        let _ = write!(s, "; and {} more", defects.len() - 5);
    }
    s.push_str(" (snapping welds near points and splits the cells at T-junctions: `--snap EPS`, `snap=` in Python)");
    s
}

/// How [`read_json_with`] reads a complex with points.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct JsonOptions {
    /// weld the points within this distance and split edges and faces where a point or an
    /// edge lies inside them ([`crate::arch::snap`]), before the metrical check
    pub snap: Option<f64>,
    /// read a complex whose points do not conform instead of refusing it (for the
    /// metrical edit check, which lists every defect)
    pub accept_nonconforming: bool,
}

impl JsonOptions {
    /// Options that snap within `eps` (`None`: no snapping).
    pub fn snap(eps: Option<f64>) -> Self {
        JsonOptions { snap: eps, accept_nonconforming: false }
    }

    /// Options that read a complex whose points do not conform.
    pub fn accepting_nonconforming() -> Self {
        JsonOptions { snap: None, accept_nonconforming: true }
    }
}

impl From<ArchError> for JsonError {
    fn from(e: ArchError) -> Self {
        JsonError::Arch(e, Box::default())
    }
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

fn get_key(obj: &Value, at: At<'_>, key: &str) -> Result<Key, JsonError> {
    let v = field(obj, at, key)?;
    match v {
        Value::String(t) => Ok(Key::Str(t.clone())),
        _ => as_u64(v, || at.path(key), " or a string").map(Key::Int),
    }
}

fn get_u64(obj: &Value, at: At<'_>, key: &str) -> Result<u64, JsonError> {
    as_u64(field(obj, at, key)?, || at.path(key), "")
}

/// `v` as a `u64`; an integer written without a fraction or exponent that is too large is
/// said to be so, anything else is "expected a non-negative integer`{or}`".
fn as_u64(v: &Value, at: impl Fn() -> String, or: &str) -> Result<u64, JsonError> {
    v.as_u64().ok_or_else(|| match v {
        Value::Number(x) if !x.to_string().contains(['.', 'e', 'E', '-']) => {
            schema(at(), format!("{x} does not fit a 64-bit integer"))
        }
        _ => schema(at(), format!("expected a non-negative integer{or}, found {v}")),
    })
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

/// A region's id in the file: a number or a string.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq, Hash)]
#[serde(untagged)]
enum Key {
    Int(u64),
    Str(String),
}

#[derive(Deserialize)]
struct RawRegion {
    id: Key,
    dim: u64,
    /// the region's own Betti numbers (AC Def. 8.1), when it is not a cell
    #[serde(default)]
    betti: Option<Vec<u64>>,
    /// the region's labels, in the order of the file
    #[serde(default)]
    labels: Option<RawLabels>,
    /// a vertex's coordinates
    #[serde(default)]
    point: Option<Vec<f64>>,
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

/// The optional `"betti"` of region `index`, as counts.
fn betti_counts(v: &[u64], index: usize) -> Result<Vec<usize>, JsonError> {
    v.iter()
        .map(|&b| usize::try_from(b).ok())
        .collect::<Option<Vec<usize>>>()
        .ok_or_else(|| schema(At { list: "regions", index }.path("betti"), "a Betti number is too large"))
}

#[derive(Deserialize)]
struct RawEntry {
    from: Key,
    to: Key,
    /// left out: chosen so that every boundary is a cycle (`arch::orient_entries`)
    #[serde(default)]
    weight: Option<i64>,
}

#[derive(Deserialize)]
struct Raw {
    dimension: Option<u64>,
    regions: Vec<RawRegion>,
    incidence: Vec<RawEntry>,
}

/// What the file says, before the ids become numbers.
struct Parsed {
    dim: Option<usize>,
    regions: Vec<(Key, usize)>,
    betti: Vec<(usize, Vec<usize>)>,
    labels: Vec<(usize, Labels)>,
    points: Vec<(usize, [f64; 3])>,
    entries: Vec<(Key, Key, Option<i64>)>,
}

/// A point of 2 or 3 finite coordinates (a missing z is 0).
fn point(v: &[f64], index: usize) -> Result<[f64; 3], JsonError> {
    match *v {
        [x, y] => Ok([x, y, 0.0]),
        [x, y, z] => Ok([x, y, z]),
        _ => Err(schema(
            At { list: "regions", index }.path("point"),
            format!("expected 2 or 3 coordinates, found {}", v.len()),
        )),
    }
}

/// Parses and validates a `.json` architectural complex. See the module docs.
///
/// Well-formed input is deserialised straight into typed records (no intermediate tree);
/// anything else is parsed again as a JSON tree to say exactly which field is wrong.
pub fn read_json(text: &str) -> Result<ArchComplex, JsonError> {
    read_json_with(text, &JsonOptions::default()).map(|x| x.0)
}

/// [`read_json`] with options: snapping, or accepting a complex whose points do not
/// conform. Returns the complex and, when snapped, one line per point welded and cell split.
pub fn read_json_with(text: &str, o: &JsonOptions) -> Result<(ArchComplex, Vec<String>), JsonError> {
    if let Some(d) = crate::complex::unique_keys::find_duplicate(text) {
        return Err(JsonError::DuplicateKey { key: d.key, line: d.line, column: d.column });
    }
    let raw: Raw = match serde_json::from_str(text) {
        Ok(raw) => raw,
        Err(_) => return build(read_json_slow(text)?, o),
    };
    let mut p = Parsed {
        dim: match raw.dimension {
            Some(d) => Some(check_dim(d, || "dimension".to_string())?),
            None => None,
        },
        regions: Vec::with_capacity(raw.regions.len()),
        betti: Vec::new(),
        labels: Vec::new(),
        points: Vec::new(),
        entries: raw.incidence.into_iter().map(|e| (e.from, e.to, e.weight)).collect(),
    };
    for (index, r) in raw.regions.into_iter().enumerate() {
        let dim = check_dim(r.dim, || At { list: "regions", index }.path("dim"))?;
        p.regions.push((r.id, dim));
        if let Some(b) = &r.betti {
            p.betti.push((index, betti_counts(b, index)?));
        }
        if let Some(l) = &r.labels {
            p.labels.push((index, region_labels(&l.0, index)?));
        }
        if let Some(v) = &r.point {
            p.points.push((index, point(v, index)?));
        }
    }
    build(p, o)
}

/// The complex of what the file says: string ids numbered after the largest number used,
/// signs left out chosen, errors naming regions as the file does.
/// The regions, names, entries and points of what the file says, ids numbered.
struct Numbered {
    regions: Vec<Region>,
    names: RegionNames,
    entries: Vec<(RegionId, RegionId, Option<i64>)>,
    pts: std::collections::HashMap<RegionId, [f64; 3]>,
    /// the first id not in use
    next: u64,
}

fn number_all(p: &Parsed) -> Result<Numbered, JsonError> {
    let mut next = p
        .regions
        .iter()
        .filter_map(|(k, _)| if let Key::Int(i) = k { Some(*i) } else { None })
        .max()
        .map_or(0, |m| m.saturating_add(1));
    let mut numbers: std::collections::HashMap<Key, RegionId> = std::collections::HashMap::new();
    let mut names = RegionNames::new();
    let mut number = |k: &Key, names: &mut RegionNames| -> Result<RegionId, JsonError> {
        match k {
            Key::Int(i) => Ok(RegionId(*i)),
            Key::Str(t) => {
                if let Some(&id) = numbers.get(k) {
                    return Ok(id);
                }
                if next == u64::MAX {
                    return Err(ArchError::IdsExhausted.into());
                }
                let id = RegionId(next);
                next += 1;
                numbers.insert(k.clone(), id);
                names.insert(id, t.clone());
                Ok(id)
            }
        }
    };
    let mut regions = Vec::with_capacity(p.regions.len());
    for (k, dim) in &p.regions {
        regions.push(Region { id: number(k, &mut names)?, dim: *dim });
    }
    for (k, l) in &p.labels {
        let key = match &p.regions[*k].0 {
            Key::Str(t) => Some(t.as_str()),
            Key::Int(_) => None,
        };
        let name = match l.get("name") {
            Some(LabelValue::Text(t)) => Some(t.as_str()),
            _ => None,
        };
        if let Some(n) = RegionNames::name_of(regions[*k].id, key, name) {
            names.insert(regions[*k].id, n);
        }
    }
    let mut entries = Vec::with_capacity(p.entries.len());
    for (f, t, w) in &p.entries {
        entries.push((number(f, &mut names)?, number(t, &mut names)?, *w));
    }
    let pts = p.points.iter().map(|&(k, q)| (regions[k].id, q)).collect();
    Ok(Numbered { regions, names, entries, pts, next })
}

/// The metrical defects of a `.json` text read without orienting or validating it (the
/// metrical edit of `gmap tm check`, which must name the defects of a complex that the
/// reader refuses), with the file's names and the tolerance.
pub fn json_metric_defects(text: &str) -> Result<(Vec<MetricDefect>, RegionNames, f64), JsonError> {
    if let Some(d) = crate::complex::unique_keys::find_duplicate(text) {
        return Err(JsonError::DuplicateKey { key: d.key, line: d.line, column: d.column });
    }
    let n = number_all(&read_json_slow(text)?)?;
    let shape = Shape::new(&n.regions, n.entries.iter().map(|e| (e.0, e.1)), &n.pts);
    Ok((shape.defects(), n.names, shape.tolerance()))
}

fn build(mut p: Parsed, o: &JsonOptions) -> Result<(ArchComplex, Vec<String>), JsonError> {
    let Numbered { mut regions, mut names, mut entries, mut pts, next } = number_all(&p)?;
    let dim = p.dim.unwrap_or_else(|| regions.iter().map(|r| r.dim).max().unwrap_or(0));
    let mut report = Vec::new();
    if let Some(eps) = o.snap {
        let s = crate::complex::arch::snap(eps, &regions, &entries, &pts, &names, next).map_err(JsonError::Snap)?;
        report = s.report;
        apply_snap(&mut p, &mut regions, &mut names, &s.removed, s.added);
        (entries, pts) = (s.entries, s.points);
    }
    if !o.accept_nonconforming && !pts.is_empty() {
        let defects = Shape::new(&regions, entries.iter().map(|e| (e.0, e.1)), &pts);
        let list = defects.defects();
        if !list.is_empty() {
            return Err(JsonError::NotConforming {
                defects: list,
                names: Box::new(names),
                tolerance: defects.tolerance(),
            });
        }
    }
    let wrap = |e: ArchError| JsonError::Arch(e, Box::new(names.clone()));
    let entries = if entries.iter().any(|e| e.2.is_none()) {
        orient_entries(dim, &regions, &entries, &pts).map_err(wrap)?
    } else {
        entries.into_iter().map(|(f, t, w)| (f, t, w.unwrap_or(0))).collect()
    };
    let ids: Vec<RegionId> = regions.iter().map(|r| r.id).collect();
    let mut x = ArchComplex::try_new(dim, regions, entries).map_err(wrap)?;
    for (k, b) in p.betti {
        x = x.with_region_betti(ids[k], b).map_err(wrap)?;
    }
    for (k, l) in p.labels {
        x = x.with_region_labels(ids[k], l).map_err(wrap)?;
    }
    for (&id, &q) in &pts {
        x = x.with_region_point(id, q).map_err(wrap)?;
    }
    for (k, (key, _)) in p.regions.into_iter().enumerate() {
        if let Key::Str(t) = key {
            x = x.with_region_key(ids[k], t).map_err(wrap)?;
        }
    }
    Ok((x, report))
}

/// The file's regions after snapping: the welded regions gone (with their Betti numbers,
/// labels and points), the new pieces added with the labels of the cell they were cut from
/// and keys `"<key>.<k>"`.
fn apply_snap(
    p: &mut Parsed,
    regions: &mut Vec<Region>,
    names: &mut RegionNames,
    removed: &std::collections::HashSet<RegionId>,
    added: Vec<(Region, RegionId, String)>,
) {
    let keep: Vec<bool> = regions.iter().map(|r| !removed.contains(&r.id)).collect();
    let mut new_index = vec![usize::MAX; regions.len()];
    let mut n = 0;
    for (k, &kept) in keep.iter().enumerate() {
        if kept {
            new_index[k] = n;
            n += 1;
        }
    }
    let remap = |k: usize| (new_index[k] != usize::MAX).then_some(new_index[k]);
    p.betti = std::mem::take(&mut p.betti).into_iter().filter_map(|(k, b)| Some((remap(k)?, b))).collect();
    p.labels = std::mem::take(&mut p.labels).into_iter().filter_map(|(k, l)| Some((remap(k)?, l))).collect();
    p.regions = std::mem::take(&mut p.regions).into_iter().zip(&keep).filter(|x| *x.1).map(|x| x.0).collect();
    regions.retain(|r| !removed.contains(&r.id));
    let index: std::collections::HashMap<RegionId, usize> =
        regions.iter().enumerate().map(|(k, r)| (r.id, k)).collect();
    for (r, from, key) in added.into_iter().filter(|a| !removed.contains(&a.0.id)) {
        if let Some(&k) = index.get(&from) {
            if let Some(l) = p.labels.iter().find(|x| x.0 == k).map(|x| x.1.clone()) {
                p.labels.push((regions.len(), l));
            }
        }
        names.insert(r.id, key.clone());
        p.regions.push((Key::Str(key), r.dim));
        regions.push(r);
    }
}

/// The tree-based reader, for its precise messages on malformed input.
fn read_json_slow(text: &str) -> Result<Parsed, JsonError> {
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
    let mut p = Parsed {
        dim: None,
        regions: Vec::with_capacity(regs.len()),
        betti: Vec::new(),
        labels: Vec::new(),
        points: Vec::new(),
        entries: Vec::new(),
    };
    for (index, r) in regs.iter().enumerate() {
        let at = At { list: "regions", index };
        let id = get_key(r, at, "id")?;
        let dim = check_dim(get_u64(r, at, "dim")?, || at.path("dim"))?;
        p.regions.push((id, dim));
        if let Some(v) = r.get("betti") {
            let list =
                v.as_array().and_then(|a| a.iter().map(Value::as_u64).collect::<Option<Vec<u64>>>()).ok_or_else(
                    || schema(at.path("betti"), format!("expected an array of non-negative integers, found {v}")),
                )?;
            p.betti.push((index, betti_counts(&list, index)?));
        }
        if let Some(v) = r.get("labels") {
            let members = v
                .as_object()
                .ok_or_else(|| schema(at.path("labels"), format!("expected an object of labels, found {v}")))?;
            let members: Vec<(String, Value)> = members.iter().map(|(k, v)| (k.clone(), v.clone())).collect();
            p.labels.push((index, region_labels(&members, index)?));
        }
        if let Some(v) = r.get("point") {
            let c = v
                .as_array()
                .and_then(|a| a.iter().map(Value::as_f64).collect::<Option<Vec<f64>>>())
                .ok_or_else(|| schema(at.path("point"), format!("expected an array of numbers, found {v}")))?;
            p.points.push((index, point(&c, index)?));
        }
    }
    if let Some(v) = obj.get("dimension") {
        let d = as_u64(v, || "dimension".to_string(), "")?;
        p.dim = Some(check_dim(d, || "dimension".to_string())?);
    }
    let inc = obj.get("incidence").ok_or_else(|| schema("incidence", "missing"))?;
    let inc = inc.as_array().ok_or_else(|| schema("incidence", "expected an array"))?;
    for (index, e) in inc.iter().enumerate() {
        let at = At { list: "incidence", index };
        let w = if e.get("weight").is_some() { Some(get_i64(e, at, "weight")?) } else { None };
        p.entries.push((get_key(e, at, "from")?, get_key(e, at, "to")?, w));
    }
    Ok(p)
}

/// Reads and validates a `.json` file; errors name the file (and the line for syntax).
///
/// The file is refused before it is read when the text and what is built from it (about
/// four times its size) would exceed the memory limit ([`gmap_core::resources`]).
pub fn read_json_file(path: &Path) -> Result<ArchComplex, JsonFileError> {
    read_json_file_with(path, &JsonOptions::default()).map(|x| x.0)
}

/// [`read_json_file`] with options ([`read_json_with`]).
pub fn read_json_file_with(path: &Path, o: &JsonOptions) -> Result<(ArchComplex, Vec<String>), JsonFileError> {
    let size = std::fs::metadata(path).map(|m| m.len()).unwrap_or(0);
    gmap_core::resources::check_memory("the file and its complex", size.checked_mul(4))
        .map_err(|e| JsonFileError { path: path.to_path_buf(), error: JsonError::MemoryLimit(e) })?;
    let text = std::fs::read_to_string(path)
        .map_err(|e| JsonFileError { path: path.to_path_buf(), error: JsonError::Io(e.to_string()) })?;
    read_json_with(&text, o).map_err(|error| JsonFileError { path: path.to_path_buf(), error })
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

/// The id of region `k` as the file writes it: its string id quoted, or its number.
fn key_text(x: &ArchComplex, k: usize) -> String {
    x.region_key(k).map_or_else(|| x.region(k).id.to_string(), json_string)
}

/// Writes the complex in the `.json` format, one region or entry per line; a region given
/// Betti numbers keeps them (`"betti"`), a region with labels keeps them (`"labels"`).
pub fn write_json(x: &ArchComplex) -> String {
    let mut s = String::with_capacity(32 * (x.regions().len() + x.entries().len()) + 64);
    let _ = write!(s, "{{\"dimension\": {},\n \"regions\": [", x.dim());
    for (k, r) in x.regions().iter().enumerate() {
        let sep = if k == 0 { "" } else { ",\n  " };
        let _ = write!(s, "{sep}{{\"id\": {}, \"dim\": {}", key_text(x, k), r.dim);
        if let Some([a, b, c]) = x.region_point(k) {
            let _ = write!(s, ", \"point\": [{a:?}, {b:?}, {c:?}]");
        }
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
    for (k, e) in x.entries().iter().enumerate() {
        let sep = if k == 0 { "" } else { ",\n  " };
        let (f, t, w) = (key_text(x, e.from), key_text(x, e.to), e.weight);
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
        assert_eq!(
            build(read_json_slow(&text).unwrap(), &JsonOptions::default()).unwrap().0.region_labels(2).get("count"),
            Some(&LabelValue::Int(-7))
        );
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
            // a node line is `  r<id> [label=…`; an edge line `  r<id> -> r<id>` (a label may hold `->`)
            let node = |l: &str| {
                l.strip_prefix("  r").is_some_and(|t| {
                    let rest = t.trim_start_matches(|c: char| c.is_ascii_digit());
                    rest.len() < t.len() && rest.starts_with(" [label=")
                })
            };
            let nodes = dot.lines().filter(|l| node(l)).count();
            proptest::prop_assert_eq!(nodes, x.regions().len());
        }
    }
}
