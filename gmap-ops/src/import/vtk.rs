//! Legacy VTK unstructured grids (`.vtk`), ASCII and binary, versions up to 4.2 (cells as
//! `CELLS n size` with a count before each cell, polyhedra as face streams) and 5.1
//! (`OFFSETS` and `CONNECTIVITY` arrays), into a [`Mesh`] and then a labelled map
//! ([`crate::mesh`]).
//!
//! Read: `POINTS`, `CELLS`, `CELL_TYPES` (vertex 1, line 3, triangle 5, polygon 7, quad 9,
//! tetra 10, hexahedron 12, wedge 13, pyramid 14, polyhedron 42 in versions up to 4.2; the
//! higher-order types 21–37, Lagrange 68–74 and Bézier 75–81 as their corner cells, their
//! other points in the label [`HIGH_ORDER_LABEL`](super::high_order::HIGH_ORDER_LABEL)),
//! and in `POINT_DATA` / `CELL_DATA` the arrays of `SCALARS`, `VECTORS`, `NORMALS`,
//! `TENSORS`, `TEXTURE_COORDINATES` and `FIELD` blocks, which become labels (an array of k
//! components the names `name.0` … `name.{k-1}`); `COLOR_SCALARS`, `LOOKUP_TABLE` tables,
//! `METADATA` and dataset-level `FIELD` data are read past, but for the tables of texts of
//! the mesh writers (an integer column and a field-data table `gmap:texts:<name>`). Binary
//! data are big-endian, as the format says. Values standing for "missing" in [`crate::export::vtk_string_with_labels`]
//! (`-2147483648` in an `int` array, `-9223372036854775808` in a 64-bit one,
//! `-1.7976931348623157e308` and non-finite reals in a real one, the empty text) give no
//! label; `string` arrays are read one text per line with VTK's `%XX` escapes. Other
//! datasets (`POLYDATA`, `STRUCTURED_GRID`…) and cell types are refused, naming them.
//!
//! Errors name the file and the line (for binary data, the line where the block starts and
//! the item within it). Counts in the headers are checked against what the file can hold
//! before anything is allocated for them. O(size of the file) plus [`Mesh::to_gmap`].

use std::path::Path;

use gmap_core::io::shorten;
use gmap_core::{LabelValue, LabelledGMap, Point};

use super::high_order::{label_array, to_corners, vtk_type};
use super::{default_max_darts, FileError, ImportError};
use crate::mesh::{CellKind, DataArray, Mesh, MeshCell};

/// The numeric types of VTK data arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Scalar {
    /// signed integers of this many bytes
    Int(u8),
    /// unsigned integers of this many bytes
    UInt(u8),
    /// reals of this many bytes
    Real(u8),
    /// texts (ASCII legacy files only)
    Text,
}

impl Scalar {
    /// A legacy type name (`int`, `double`, `vtktypeint64`…) or an XML one (`Int32`,
    /// `Float64`…).
    pub(crate) fn parse(name: &str) -> Option<Scalar> {
        let lower = name.to_ascii_lowercase();
        // vtktypeint32, vtktypefloat64…: the fixed-width names
        let name = lower.strip_prefix("vtktype").filter(|n| *n != "int64" && *n != "uint64").unwrap_or(&lower);
        Some(match name {
            "bit" | "unsigned_char" | "uint8" => Scalar::UInt(1),
            "char" | "int8" => Scalar::Int(1),
            "unsigned_short" | "uint16" => Scalar::UInt(2),
            "short" | "int16" => Scalar::Int(2),
            "unsigned_int" | "uint32" => Scalar::UInt(4),
            "int" | "int32" => Scalar::Int(4),
            "unsigned_long" | "vtktypeuint64" | "uint64" => Scalar::UInt(8),
            "long" | "vtktypeint64" | "vtkidtype" | "int64" => Scalar::Int(8),
            "float" | "float32" => Scalar::Real(4),
            "double" | "float64" => Scalar::Real(8),
            "string" => Scalar::Text,
            _ => return None,
        })
    }

    /// Bytes per value in binary data.
    pub(crate) fn size(self) -> usize {
        match self {
            Scalar::Int(b) | Scalar::UInt(b) | Scalar::Real(b) => b as usize,
            Scalar::Text => 1,
        }
    }

    /// Decodes one binary value (`bytes.len() == self.size()`), big- or little-endian.
    pub(crate) fn decode(self, bytes: &[u8], big: bool) -> Value {
        let mut b = [0u8; 8];
        let n = bytes.len().min(8);
        if big {
            b[8 - n..].copy_from_slice(&bytes[..n]);
            b[..8 - n].fill(if matches!(self, Scalar::Int(_)) && bytes[0] & 0x80 != 0 { 0xff } else { 0 });
        } else {
            b[..n].copy_from_slice(&bytes[..n]);
            b[n..].fill(if matches!(self, Scalar::Int(_)) && bytes[n - 1] & 0x80 != 0 { 0xff } else { 0 });
        }
        let raw = if big { u64::from_be_bytes(b) } else { u64::from_le_bytes(b) };
        match self {
            Scalar::Int(_) => Value::Int(raw as i64),
            Scalar::UInt(8) if raw > i64::MAX as u64 => Value::Real(raw as f64),
            Scalar::UInt(_) | Scalar::Text => Value::Int(raw as i64),
            Scalar::Real(4) => Value::Real(f32::from_bits(raw as u32) as f64),
            Scalar::Real(_) => Value::Real(f64::from_bits(raw)),
        }
    }

    /// Parses one text token as a value of this type.
    pub(crate) fn parse_token(self, tok: &[u8]) -> Option<Value> {
        let s = std::str::from_utf8(tok).ok()?;
        match self {
            Scalar::Int(_) | Scalar::UInt(_) => {
                s.parse::<i64>().ok().map(Value::Int).or_else(|| s.parse::<u64>().ok().map(|v| Value::Real(v as f64)))
            }
            Scalar::Real(_) => parse_real(s).map(Value::Real),
            Scalar::Text => Some(Value::Text(decode_text(tok))),
        }
    }

    /// The value standing for "missing" in arrays of this type.
    fn is_missing(self, v: &Value) -> bool {
        match (self, v) {
            (Scalar::Int(4), Value::Int(i)) => *i == i32::MIN as i64,
            (Scalar::Int(8), Value::Int(i)) => *i == i64::MIN,
            (_, Value::Real(r)) => !r.is_finite() || *r == f64::MIN,
            (_, Value::Text(t)) => t.is_empty(),
            _ => false,
        }
    }
}

/// A real in C's forms, `nan` and `inf` included (they become missing values).
fn parse_real(s: &str) -> Option<f64> {
    s.parse::<f64>().ok().or_else(|| match s.to_ascii_lowercase().trim_start_matches(['+', '-']) {
        "nan" | "-nan" | "1.#qnan" => Some(f64::NAN),
        "inf" | "infinity" | "1.#inf" => Some(if s.starts_with('-') { f64::NEG_INFINITY } else { f64::INFINITY }),
        _ => None,
    })
}

/// VTK's `%XX` escapes decoded.
fn decode_text(tok: &[u8]) -> String {
    let mut out = Vec::with_capacity(tok.len());
    let mut k = 0;
    while k < tok.len() {
        if tok[k] == b'%' && k + 2 < tok.len() {
            if let Ok(v) = u8::from_str_radix(std::str::from_utf8(&tok[k + 1..k + 3]).unwrap_or("zz"), 16) {
                out.push(v);
                k += 3;
                continue;
            }
        }
        out.push(tok[k]);
        k += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// One value read.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Value {
    Int(i64),
    Real(f64),
    Text(String),
}

impl Value {
    /// As an index (a non-negative integer below 2^32).
    pub(crate) fn index(&self) -> Option<u32> {
        match self {
            Value::Int(i) => u32::try_from(*i).ok().filter(|&v| v != u32::MAX),
            _ => None,
        }
    }

    /// As a coordinate.
    pub(crate) fn real(&self) -> Option<f64> {
        match self {
            Value::Int(i) => Some(*i as f64),
            Value::Real(r) => Some(*r),
            Value::Text(_) => None,
        }
    }

    /// As an integer.
    pub(crate) fn int(&self) -> Option<i64> {
        match self {
            Value::Int(i) => Some(*i),
            _ => None,
        }
    }
}

/// Label arrays of `values` read as `tuples × comps` of type `ty` (missing values dropped):
/// `name`, or `name.0` … for several components.
pub(crate) fn data_arrays(name: &str, comps: usize, ty: Scalar, values: Vec<Value>) -> Vec<DataArray> {
    let tuples = values.len().checked_div(comps).unwrap_or(0);
    (0..comps)
        .map(|c| DataArray {
            name: if comps == 1 { name.to_string() } else { format!("{name}.{c}") },
            values: (0..tuples)
                .map(|t| {
                    let v = &values[t * comps + c];
                    (!ty.is_missing(v)).then(|| match v {
                        Value::Int(i) => LabelValue::Int(*i),
                        Value::Real(r) => LabelValue::Real(*r),
                        Value::Text(s) => LabelValue::Text(s.clone()),
                    })
                })
                .collect(),
        })
        .collect()
}

/// Points from `3 n` coordinates. Error: a coordinate that is not a finite number.
pub(crate) fn points_of(values: &[Value], what: impl Fn(usize) -> ImportError) -> Result<Vec<Point>, ImportError> {
    let mut pts = Vec::with_capacity(values.len() / 3);
    for (k, c) in values.chunks_exact(3).enumerate() {
        let mut p = [0.0; 3];
        for j in 0..3 {
            p[j] = c[j].real().filter(|x| x.is_finite()).ok_or_else(|| what(3 * k + j))?;
        }
        pts.push(p);
    }
    Ok(pts)
}

/// A polyhedron's cell from its face stream `nFaces, n_0, ids…, n_1, ids…`; `Err` says why
/// the stream is malformed.
pub(crate) fn polyhedron(stream: &[u32]) -> Result<MeshCell, String> {
    let (&nf, mut rest) = stream.split_first().ok_or("an empty face stream")?;
    let mut faces = Vec::new();
    for f in 0..nf {
        let (&k, r) = rest.split_first().ok_or_else(|| format!("the face stream ends before face {f} of {nf}"))?;
        if (k as usize) > r.len() {
            return Err(format!("face {f} announces {k} points, {} are left", r.len()));
        }
        faces.push(r[..k as usize].to_vec());
        rest = &r[k as usize..];
    }
    if !rest.is_empty() {
        return Err(format!("{} values after the {nf} faces", rest.len()));
    }
    let mut nodes: Vec<u32> = faces.iter().flatten().copied().collect();
    nodes.sort_unstable();
    nodes.dedup();
    Ok(MeshCell { kind: CellKind::Polyhedron, nodes, faces })
}

/// A reader over the bytes of a legacy file that counts lines.
struct Cursor<'a> {
    b: &'a [u8],
    pos: usize,
    line: usize,
    /// the line of the last section header read
    head: usize,
}

impl<'a> Cursor<'a> {
    fn err(&self, message: String) -> ImportError {
        ImportError::Syntax { line: self.line, message }
    }

    /// Skips spaces and line ends.
    fn skip_space(&mut self) {
        while let Some(&c) = self.b.get(self.pos) {
            if c == b'\n' {
                self.line += 1;
            } else if !c.is_ascii_whitespace() {
                break;
            }
            self.pos += 1;
        }
    }

    /// The next non-blank line, trimmed, leaving the cursor at the start of the following
    /// line; `None` at the end.
    fn next_line(&mut self) -> Option<&'a [u8]> {
        self.skip_space();
        if self.pos >= self.b.len() {
            return None;
        }
        self.head = self.line;
        Some(self.raw_line())
    }

    /// The rest of the current line, without its end.
    fn raw_line(&mut self) -> &'a [u8] {
        let start = self.pos;
        let end = self.b[start..].iter().position(|&c| c == b'\n').map_or(self.b.len(), |k| start + k);
        self.pos = (end + 1).min(self.b.len());
        if end < self.b.len() {
            self.line += 1;
        }
        let mut l = &self.b[start..end];
        while let [rest @ .., last] = l {
            if last.is_ascii_whitespace() {
                l = rest;
            } else {
                break;
            }
        }
        l
    }

    /// The next whitespace-separated token.
    fn token(&mut self) -> Option<&'a [u8]> {
        self.skip_space();
        let start = self.pos;
        while self.pos < self.b.len() && !self.b[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
        (self.pos > start).then(|| &self.b[start..self.pos])
    }

    /// `n` values of type `ty`: tokens in ASCII, big-endian bytes in binary (then one line
    /// end). `what` names the block in errors.
    fn values(&mut self, n: usize, ty: Scalar, binary: bool, what: &str) -> Result<Vec<Value>, ImportError> {
        let start = self.head;
        let at_head = |m: String| ImportError::Syntax { line: start, message: m };
        if binary {
            if ty == Scalar::Text {
                return Err(self.err(format!("{what}: binary string arrays are not read")));
            }
            let bytes = n.checked_mul(ty.size()).filter(|&b| b <= self.b.len() - self.pos).ok_or_else(|| {
                at_head(format!("{what}: {n} values of {} bytes do not fit in the rest of the file", ty.size()))
            })?;
            let block = &self.b[self.pos..self.pos + bytes];
            self.pos += bytes;
            self.line += block.iter().filter(|&&c| c == b'\n').count();
            if self.b.get(self.pos) == Some(&b'\n') {
                self.pos += 1;
                self.line += 1;
            }
            return Ok(block.chunks_exact(ty.size()).map(|c| ty.decode(c, true)).collect());
        }
        if ty == Scalar::Text {
            // one text per line
            let mut out = Vec::with_capacity(n.min(self.b.len() - self.pos));
            for k in 0..n {
                if self.pos >= self.b.len() {
                    return Err(self.err(format!("{what}: the file ends at text {k} of {n}")));
                }
                out.push(Value::Text(decode_text(self.raw_line())));
            }
            return Ok(out);
        }
        // a value takes two bytes at least (a digit and a separator)
        if n > (self.b.len() - self.pos).div_ceil(2) + 1 {
            return Err(at_head(format!("{what}: {n} values announced, the rest of the file cannot hold them")));
        }
        let mut out = Vec::with_capacity(n);
        for k in 0..n {
            let tok = self.token().ok_or_else(|| at_head(format!("{what}: the file ends at value {k} of {n}")))?;
            out.push(ty.parse_token(tok).ok_or_else(|| {
                self.err(format!("{what}: value {k} '{}' is not a number of type {ty:?}", shorten(tok, 40)))
            })?);
        }
        Ok(out)
    }
}

/// Parses a count.
fn count(tok: Option<&[u8]>, what: &str, line: usize) -> Result<usize, ImportError> {
    let t = tok.ok_or_else(|| ImportError::Syntax { line, message: format!("missing {what}") })?;
    std::str::from_utf8(t)
        .ok()
        .and_then(|s| s.parse::<usize>().ok())
        .ok_or_else(|| ImportError::Syntax { line, message: format!("{what} '{}' is not a count", shorten(t, 40)) })
}

fn words(line: &[u8]) -> Vec<&[u8]> {
    line.split(|c| c.is_ascii_whitespace()).filter(|w| !w.is_empty()).collect()
}

fn text(w: &[u8]) -> String {
    String::from_utf8_lossy(w).into_owned()
}

/// A legacy file's cells as read: the cell list or the connectivity, the offsets, the
/// line of its header and the count that header gives.
type Connectivity = (Vec<Value>, Option<Vec<Value>>, usize, usize);

/// Parses a legacy VTK unstructured grid (see the module documentation).
pub fn parse_vtk(bytes: &[u8]) -> Result<Mesh, ImportError> {
    let mut c = Cursor { b: bytes, pos: 0, line: 1, head: 1 };
    let header = c.raw_line();
    let version = header
        .strip_prefix(b"# vtk DataFile Version ")
        .ok_or_else(|| ImportError::Syntax { line: 1, message: "expected '# vtk DataFile Version x.y'".into() })?;
    let major: u32 =
        std::str::from_utf8(version).ok().and_then(|v| v.trim().split('.').next()?.parse().ok()).ok_or_else(|| {
            ImportError::Syntax { line: 1, message: format!("version '{}' is not a number", shorten(version, 20)) }
        })?;
    let _title = c.raw_line();
    let fl = c.line;
    let binary = match c.next_line().map(|l| l.to_ascii_uppercase()) {
        Some(l) if l == b"ASCII" => false,
        Some(l) if l == b"BINARY" => true,
        _ => return Err(ImportError::Syntax { line: fl, message: "expected ASCII or BINARY".into() }),
    };
    let mut mesh = Mesh::default();
    let mut points: Option<Vec<Point>> = None;
    // (the cell list or the connectivity, the offsets, its line, the count of its header)
    let mut conn: Option<Connectivity> = None;
    let mut types: Option<(Vec<Value>, usize)> = None;
    let mut active: Option<(bool, usize)> = None; // (cell data?, count)
    let mut dataset = false;
    let mut field_data: Vec<DataArray> = Vec::new();
    while let Some(line) = c.next_line() {
        let ln = c.head;
        let w = words(line);
        let key = w[0].to_ascii_uppercase();
        let err = |m: String| ImportError::Syntax { line: ln, message: m };
        let ty_of = |t: Option<&&[u8]>| -> Result<Scalar, ImportError> {
            let t = t.ok_or_else(|| err("missing the data type".into()))?;
            Scalar::parse(&text(t)).ok_or_else(|| err(format!("unknown data type '{}'", shorten(t, 40))))
        };
        match key.as_slice() {
            b"DATASET" => {
                let kind = w.get(1).map(|k| text(k).to_ascii_uppercase()).unwrap_or_default();
                if kind != "UNSTRUCTURED_GRID" {
                    return Err(err(format!(
                        "DATASET {} is not read: only UNSTRUCTURED_GRID",
                        shorten(kind.as_bytes(), 40)
                    )));
                }
                dataset = true;
            }
            b"FIELD" if active.is_none() => {
                // dataset-level field data: kept for the tables of texts only
                let k = count(w.get(2).copied(), "the number of arrays", ln)?;
                for _ in 0..k {
                    field_data.extend(read_field_array(&mut c, binary, Some(()))?.into_iter().flatten());
                }
            }
            b"POINTS" => {
                let n = count(w.get(1).copied(), "the number of points", ln)?;
                let ty = ty_of(w.get(2))?;
                let n3 = n.checked_mul(3).ok_or_else(|| err(format!("{n} points: too many")))?;
                let v = c.values(n3, ty, binary, "POINTS")?;
                points = Some(points_of(&v, |k| {
                    err(format!("POINTS: coordinate {k} (point {}) is not a finite number", k / 3))
                })?);
            }
            b"CELLS" => {
                let a = count(w.get(1).copied(), "the number of cells", ln)?;
                let b = count(w.get(2).copied(), "the size of the cell list", ln)?;
                if major >= 5 {
                    let offsets = named_array(&mut c, "OFFSETS", a, binary)?;
                    let connectivity = named_array(&mut c, "CONNECTIVITY", b, binary)?;
                    conn = Some((connectivity, Some(offsets), ln, a));
                } else {
                    conn = Some((c.values(b, Scalar::Int(4), binary, "CELLS")?, None, ln, a));
                }
            }
            b"CELL_TYPES" => {
                let n = count(w.get(1).copied(), "the number of cell types", ln)?;
                types = Some((c.values(n, Scalar::Int(4), binary, "CELL_TYPES")?, ln));
            }
            b"POINT_DATA" | b"CELL_DATA" => {
                let n = count(w.get(1).copied(), "the number of values", ln)?;
                active = Some((key == b"CELL_DATA", n));
            }
            b"SCALARS" | b"VECTORS" | b"NORMALS" | b"TENSORS" | b"TEXTURE_COORDINATES" | b"COLOR_SCALARS" => {
                let (cell, n) = active.ok_or_else(|| err(format!("{} before POINT_DATA or CELL_DATA", text(w[0]))))?;
                let name = text(w.get(1).ok_or_else(|| err("missing the array name".into()))?);
                let name = decode_text(name.as_bytes());
                let (comps, ty) = match key.as_slice() {
                    b"SCALARS" => {
                        (w.get(3).map_or(Ok(1), |t| count(Some(t), "the number of components", ln))?, ty_of(w.get(2))?)
                    }
                    b"VECTORS" | b"NORMALS" => (3, ty_of(w.get(2))?),
                    b"TENSORS" => (9, ty_of(w.get(2))?),
                    b"TEXTURE_COORDINATES" => (count(w.get(2).copied(), "the dimension", ln)?, ty_of(w.get(3))?),
                    _ => (
                        count(w.get(2).copied(), "the number of values", ln)?,
                        if binary { Scalar::UInt(1) } else { Scalar::Real(4) },
                    ),
                };
                if key == b"SCALARS" {
                    // the LOOKUP_TABLE line (optional in practice)
                    let save = (c.pos, c.line);
                    match c.next_line() {
                        Some(l) if l.to_ascii_uppercase().starts_with(b"LOOKUP_TABLE") => {}
                        _ => (c.pos, c.line) = save,
                    }
                }
                let total = n.checked_mul(comps).ok_or_else(|| err("too many values".into()))?;
                let v = c.values(total, ty, binary, &name)?;
                push_arrays(&mut mesh, cell, data_arrays(&name, comps, ty, v));
            }
            b"LOOKUP_TABLE" => {
                let n = count(w.get(2).copied(), "the table size", ln)?;
                let ty = if binary { Scalar::UInt(1) } else { Scalar::Real(4) };
                c.values(n.checked_mul(4).ok_or_else(|| err("too many values".into()))?, ty, binary, "LOOKUP_TABLE")?;
            }
            b"FIELD" => {
                let (cell, _) = active.expect("matched above");
                let k = count(w.get(2).copied(), "the number of arrays", ln)?;
                for _ in 0..k {
                    if let Some(arrays) = read_field_array(&mut c, binary, Some(()))? {
                        push_arrays(&mut mesh, cell, arrays);
                    }
                }
            }
            b"METADATA" => skip_metadata(&mut c),
            _ => return Err(err(format!("unknown section '{}'", shorten(w[0], 40)))),
        }
    }
    if !dataset {
        return Err(ImportError::Format("no DATASET UNSTRUCTURED_GRID".into()));
    }
    mesh.points = points.ok_or(ImportError::MissingSection { section: "POINTS".into(), empty: false })?;
    if conn.is_none() {
        return Err(ImportError::MissingSection { section: "CELLS".into(), empty: false });
    }
    let (types, tl) = types.ok_or(ImportError::MissingSection { section: "CELL_TYPES".into(), empty: false })?;
    let typed: Vec<(CellKind, Option<HigherOrder>)> =
        types.iter().enumerate().map(|(k, t)| vtk_kind(t.int().unwrap_or(-1), k, tl)).collect::<Result<_, _>>()?;
    let kinds: Vec<CellKind> = typed.iter().map(|t| t.0).collect();
    mesh.cells = match conn {
        None if kinds.is_empty() => Vec::new(),
        None => return Err(ImportError::Format("CELL_TYPES without CELLS".into())),
        Some((list, offsets, cl, n)) => {
            let expected = if offsets.is_some() { kinds.len() + 1 } else { kinds.len() };
            if n != expected {
                return Err(ImportError::Syntax {
                    line: cl,
                    message: format!("CELLS announces {n}, CELL_TYPES lists {} cells", kinds.len()),
                });
            }
            cells_of(&list, offsets.as_deref(), &kinds, cl)?
        }
    };
    if mesh.cells.is_empty() {
        return Err(ImportError::MissingSection { section: "CELLS".into(), empty: true });
    }
    let mut extra = Vec::with_capacity(mesh.cells.len());
    for (k, (cell, (_, higher))) in mesh.cells.iter_mut().zip(&typed).enumerate() {
        extra.push(match higher {
            Some(h) => {
                Some(corners_of(cell, h, &mesh.points, k).map_err(|m| ImportError::Syntax { line: tl, message: m })?)
            }
            None => None,
        });
    }
    mesh.cell_data.extend(label_array(extra));
    crate::mesh::texts::apply_text_tables(&mut mesh.cell_data, &field_data).map_err(ImportError::Format)?;
    check_data(&mesh)?;
    Ok(mesh)
}

/// The array after `CELLS` in version 5 files: a line `NAME type`, then `n` values.
fn named_array(c: &mut Cursor, name: &str, n: usize, binary: bool) -> Result<Vec<Value>, ImportError> {
    let l = c.next_line().unwrap_or_default();
    let w = words(l);
    if !w.first().is_some_and(|x| x.eq_ignore_ascii_case(name.as_bytes())) {
        return Err(c.err(format!("expected {name} after CELLS")));
    }
    let ty = w
        .get(1)
        .and_then(|t| Scalar::parse(&text(t)))
        .filter(|t| *t != Scalar::Text)
        .ok_or_else(|| c.err(format!("{name}: missing or unknown data type")))?;
    c.values(n, ty, binary, name)
}

fn push_arrays(mesh: &mut Mesh, cell: bool, arrays: Vec<DataArray>) {
    if cell {
        mesh.cell_data.extend(arrays);
    } else {
        mesh.point_data.extend(arrays);
    }
}

/// Reads one array of a `FIELD` block (`name comps tuples type`, its values, perhaps a
/// `METADATA` block); `keep` = `None` reads past it.
fn read_field_array(c: &mut Cursor, binary: bool, keep: Option<()>) -> Result<Option<Vec<DataArray>>, ImportError> {
    let l = c.next_line().ok_or_else(|| c.err("the file ends inside a FIELD block".into()))?;
    let ln = c.head;
    let w = words(l);
    if w.len() < 4 {
        return Err(ImportError::Syntax {
            line: ln,
            message: format!("expected 'name components tuples type', found '{}'", shorten(l, 40)),
        });
    }
    let name = decode_text(w[0]);
    let comps = count(Some(w[1]), "the number of components", ln)?;
    let tuples = count(Some(w[2]), "the number of tuples", ln)?;
    let ty = Scalar::parse(&text(w[3])).ok_or_else(|| ImportError::Syntax {
        line: ln,
        message: format!("unknown data type '{}'", shorten(w[3], 40)),
    })?;
    let total =
        comps.checked_mul(tuples).ok_or_else(|| ImportError::Syntax { line: ln, message: "too many values".into() })?;
    let v = c.values(total, ty, binary, &name)?;
    let save = (c.pos, c.line);
    match c.next_line() {
        Some(l) if l.eq_ignore_ascii_case(b"METADATA") => skip_metadata(c),
        _ => (c.pos, c.line) = save,
    }
    Ok(keep.map(|_| data_arrays(&name, comps.max(1), ty, v)))
}

/// Skips a `METADATA` block: up to a blank line.
fn skip_metadata(c: &mut Cursor) {
    while c.pos < c.b.len() {
        if c.raw_line().is_empty() {
            return;
        }
    }
}

/// Cuts the cell list into cells: classic (`count ids…` per cell) or with offsets.
fn cells_of(
    list: &[Value],
    offsets: Option<&[Value]>,
    kinds: &[CellKind],
    line: usize,
) -> Result<Vec<MeshCell>, ImportError> {
    let err = |m: String| ImportError::Syntax { line, message: m };
    let ids: Vec<u32> = list
        .iter()
        .enumerate()
        .map(|(k, v)| v.index().ok_or_else(|| err(format!("cell list value {k} is not a point index"))))
        .collect::<Result<_, _>>()?;
    let mut cells = Vec::with_capacity(kinds.len());
    match offsets {
        Some(off) => {
            let off: Vec<usize> = off
                .iter()
                .enumerate()
                .map(|(k, v)| v.index().map(|x| x as usize).ok_or_else(|| err(format!("offset {k} is not an index"))))
                .collect::<Result<_, _>>()?;
            if off.len() != kinds.len() + 1 {
                return Err(err(format!("{} offsets for {} cells (one more is needed)", off.len(), kinds.len())));
            }
            for (k, &kind) in kinds.iter().enumerate() {
                let (a, b) = (off[k], off[k + 1]);
                if a > b || b > ids.len() {
                    return Err(err(format!(
                        "cell {k}: offsets {a}..{b} outside the {} connectivity values",
                        ids.len()
                    )));
                }
                if kind == CellKind::Polyhedron {
                    return Err(err(format!("cell {k}: polyhedra of version 5 files are not read")));
                }
                cells.push(MeshCell { kind, nodes: ids[a..b].to_vec(), faces: Vec::new() });
            }
        }
        None => {
            let mut at = 0;
            for (k, &kind) in kinds.iter().enumerate() {
                let n =
                    *ids.get(at).ok_or_else(|| err(format!("the cell list ends before cell {k} of {}", kinds.len())))?
                        as usize;
                let body = ids
                    .get(at + 1..at + 1 + n)
                    .ok_or_else(|| err(format!("cell {k}: {n} values announced past the end of the list")))?;
                at += 1 + n;
                if kind == CellKind::Polyhedron {
                    cells.push(polyhedron(body).map_err(|m| err(format!("cell {k} (polyhedron): {m}")))?);
                } else {
                    cells.push(MeshCell { kind, nodes: body.to_vec(), faces: Vec::new() });
                }
            }
            if at != ids.len() {
                return Err(err(format!("{} values in the cell list after the {} cells", ids.len() - at, kinds.len())));
            }
        }
    }
    Ok(cells)
}

/// A VTK higher-order cell type: its number of points when fixed, and its name.
pub(crate) type HigherOrder = (Option<usize>, &'static str);

/// The corner kind of VTK cell type `t` (cell `k`, listed on line `line`), with what makes
/// it of higher order; unknown types are refused by number.
pub(crate) fn vtk_kind(t: i64, k: usize, line: usize) -> Result<(CellKind, Option<HigherOrder>), ImportError> {
    if let Some(kind) = CellKind::from_vtk(t) {
        return Ok((kind, None));
    }
    match vtk_type(t) {
        Some((kind, n, name)) => Ok((kind, Some((n, name)))),
        None => Err(ImportError::Syntax {
            line,
            message: format!("cell {k}: cell type {t} is not read (vertex 1, line 3, triangle 5, polygon 7, quad 9, tetra 10, hexahedron 12, wedge 13, pyramid 14, polyhedron 42, and the higher-order 21 to 37 and 68 to 81 as their corners)"),
        }),
    }
}

/// Cuts higher-order cell `k` to its corners, returning the label of its other nodes.
pub(crate) fn corners_of(
    cell: &mut MeshCell,
    h: &HigherOrder,
    points: &[Point],
    k: usize,
) -> Result<LabelValue, String> {
    if let Some(n) = h.0 {
        if cell.nodes.len() != n {
            return Err(format!("cell {k}: {} points, a {} has {n}", cell.nodes.len(), h.1));
        }
    }
    to_corners(cell, points).map_err(|m| format!("cell {k} ({}): {m}", h.1))
}

/// Checks that every data array has a value per point or per cell.
pub(crate) fn check_data(mesh: &Mesh) -> Result<(), ImportError> {
    for (arrays, n, what) in
        [(&mesh.point_data, mesh.points.len(), "points"), (&mesh.cell_data, mesh.cells.len(), "cells")]
    {
        if let Some(a) = arrays.iter().find(|a| a.values.len() != n) {
            return Err(ImportError::Format(format!(
                "data array '{}' has {} values for {n} {what}",
                shorten(a.name.as_bytes(), 40),
                a.values.len()
            )));
        }
    }
    Ok(())
}

/// Reads a legacy `.vtk` unstructured grid into a labelled map (see the module
/// documentation and [`crate::mesh`]), refusing more than `max_darts` darts (default:
/// [`default_max_darts`]`(3)`).
pub fn read_vtk(path: &Path, max_darts: Option<u64>) -> Result<LabelledGMap, FileError> {
    let bytes = super::common::read_bytes(path)?;
    let mesh = parse_vtk(&bytes).map_err(|e| FileError::new(path, e))?;
    mesh.to_gmap(max_darts.unwrap_or_else(|| default_max_darts(3))).map_err(|e| FileError::new(path, e.into()))
}
