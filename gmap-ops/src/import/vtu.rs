//! XML VTK unstructured grids (`.vtu`) into a [`Mesh`] and then a labelled map
//! ([`crate::mesh`]).
//!
//! Every `Piece` of the `UnstructuredGrid` is read (their points numbered one after the
//! other): `Points`, the `Cells` arrays `connectivity`, `offsets`, `types` and, for
//! polyhedra (type 42), `faces` and `faceoffsets`; the arrays of `PointData` and
//! `CellData` become labels as in the legacy reader ([`super::vtk`]: the same cell types,
//! the same names for several components, the same missing values). Data arrays may be
//! `format="ascii"`, `"binary"` (base64 inline) or `"appended"` (in the `AppendedData`
//! block, `encoding="raw"` or `"base64"`), uncompressed or compressed by
//! `vtkZLibDataCompressor`, `vtkLZMADataCompressor` or `vtkLZ4DataCompressor` (a header
//! `[blocks, block size, last block size, compressed sizes…]` then one zlib stream, xz
//! stream or raw LZ4 block per block), with `UInt32` or `UInt64` headers and either byte
//! order. The grid's `FieldData` is read for the tables of texts of the mesh writers
//! only (an integer column and a field-data table `gmap:texts:<name>`). Cells of higher order (VTK 21–37, 68–81) are read as their corner cells, their
//! other points in the label [`HIGH_ORDER_LABEL`](super::high_order::HIGH_ORDER_LABEL).
//! Other compressors, `String` arrays and other datasets are refused, naming them; so are
//! a file without a `Piece` or a cell, a malformed XML declaration, a second
//! `AppendedData`, a second `Points`, `Cells`, `PointData` or `CellData` in a `Piece`, an
//! appended encoding other than `raw` and `base64`, and a data array without a `Name`.
//!
//! Errors name the file and the line of the XML element at fault. Sizes announced by
//! headers are checked against the values the arrays must hold before anything is
//! decompressed or allocated for them. O(size of the file, decompressed) plus
//! [`Mesh::to_gmap`].

use std::io::Read as _;
use std::path::Path;

use base64::Engine as _;
use gmap_core::io::shorten;
use gmap_core::{LabelValue, LabelledGMap};

use super::high_order::label_array;
use super::vtk::{check_data, corners_of, data_arrays, points_of, polyhedron, vtk_kind, Scalar, Value};
use super::{default_max_darts, FileError, ImportError};
use crate::mesh::{CellKind, Mesh, MeshCell};

/// How binary blocks are laid out in this file.
#[derive(Clone, Copy)]
struct Layout {
    big: bool,
    header: Scalar,
    compressor: Option<Compressor>,
}

/// The compressors VTK writes (`vtkZLibDataCompressor`, `vtkLZMADataCompressor`, an xz
/// stream per block, and `vtkLZ4DataCompressor`, a raw LZ4 block per block).
#[derive(Clone, Copy)]
enum Compressor {
    Zlib,
    Lzma,
    Lz4,
}

/// A writer refusing more than `limit` bytes: a block cannot inflate past its header's size.
struct Bounded {
    out: Vec<u8>,
    limit: usize,
}

impl std::io::Write for Bounded {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.out.len() + buf.len() > self.limit {
            return Err(std::io::Error::other("more bytes than the header says"));
        }
        self.out.extend_from_slice(buf);
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// Inflates one block of `size` bytes.
fn inflate_block(c: Compressor, data: &[u8], size: usize, out: &mut Vec<u8>) -> Result<(), String> {
    match c {
        Compressor::Zlib => {
            flate2::read::ZlibDecoder::new(data)
                .take(size as u64 + 1)
                .read_to_end(out)
                .map_err(|e| format!("zlib: {e}"))?;
        }
        Compressor::Lzma => {
            let mut w = Bounded { out: Vec::new(), limit: size };
            lzma_rs::xz_decompress(&mut std::io::BufReader::new(data), &mut w).map_err(|e| format!("LZMA: {e}"))?;
            out.extend_from_slice(&w.out);
        }
        Compressor::Lz4 => {
            out.extend_from_slice(&lz4_flex::block::decompress(data, size).map_err(|e| format!("LZ4: {e}"))?);
        }
    }
    Ok(())
}

/// The appended data: its bytes after the `_`, and whether they are base64 text.
struct Appended<'a> {
    bytes: &'a [u8],
    base64: bool,
}

/// Finds `needle` in `hay`.
fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

fn b64(text: &[u8]) -> Result<Vec<u8>, String> {
    let clean: Vec<u8> = text.iter().copied().filter(|c| !c.is_ascii_whitespace()).collect();
    base64::engine::general_purpose::STANDARD.decode(&clean).map_err(|e| format!("bad base64: {e}"))
}

/// The characters of the base64 text of `n` bytes.
fn b64_len(n: usize) -> usize {
    n.div_ceil(3) * 4
}

/// Reads a header word.
fn word(l: &Layout, bytes: &[u8], k: usize) -> Result<usize, String> {
    let s = l.header.size();
    let w = bytes.get(k * s..(k + 1) * s).ok_or("the block header is cut short")?;
    match l.header.decode(w, l.big) {
        Value::Int(v) => usize::try_from(v).map_err(|_| format!("header value {v} is not a size")),
        _ => Err("the header is not an integer".into()),
    }
}

/// Decompresses the blocks described by `header` from `data`, expecting `want` bytes.
fn inflate(l: &Layout, header: &[u8], data: &[u8], want: usize) -> Result<Vec<u8>, String> {
    let nb = word(l, header, 0)?;
    let bs = word(l, header, 1)?;
    let last = word(l, header, 2)?;
    let total = match nb {
        0 => 0,
        _ => (nb - 1)
            .checked_mul(bs)
            .and_then(|t| t.checked_add(if last == 0 { bs } else { last }))
            .ok_or("sizes overflow")?,
    };
    if total != want {
        return Err(format!("the compressed blocks hold {total} bytes, the array needs {want}"));
    }
    let mut out = Vec::with_capacity(want);
    let mut at = 0usize;
    for b in 0..nb {
        let c = word(l, header, 3 + b)?;
        let end =
            at.checked_add(c).filter(|&e| e <= data.len()).ok_or_else(|| format!("block {b} runs past the data"))?;
        let size = if b + 1 == nb && last != 0 { last } else { bs };
        let before = out.len();
        let c = l.compressor.ok_or("no compressor")?;
        inflate_block(c, &data[at..end], size, &mut out).map_err(|e| format!("block {b}: {e}"))?;
        if out.len() - before != size {
            return Err(format!("block {b} inflates to {} bytes, its header says {size}", out.len() - before));
        }
        at = end;
    }
    Ok(out)
}

/// The bytes of a binary block given as raw bytes (starting at its header).
fn raw_block(l: &Layout, b: &[u8], want: usize) -> Result<Vec<u8>, String> {
    let hs = l.header.size();
    if l.compressor.is_some() {
        let nb = word(l, b, 0)?;
        let hlen = nb
            .checked_add(3)
            .and_then(|w| w.checked_mul(hs))
            .filter(|&h| h <= b.len())
            .ok_or("the block header runs past the data")?;
        inflate(l, &b[..hlen], &b[hlen..], want)
    } else {
        let n = word(l, b, 0)?;
        if n != want {
            return Err(format!("the block holds {n} bytes, the array needs {want}"));
        }
        b.get(hs..hs + n).map(<[u8]>::to_vec).ok_or_else(|| "the block runs past the data".into())
    }
}

/// The bytes of a binary block given as base64 text (starting at its header).
fn b64_block(l: &Layout, t: &[u8], want: usize) -> Result<Vec<u8>, String> {
    let t: Vec<u8> = t.iter().copied().filter(|c| !c.is_ascii_whitespace()).collect();
    let hs = l.header.size();
    if l.compressor.is_some() {
        let first = b64(t.get(..b64_len(3 * hs)).ok_or("the block header is cut short")?)?;
        let nb = word(l, &first, 0)?;
        let hlen = nb.checked_add(3).and_then(|w| w.checked_mul(hs)).ok_or("the block header is too long")?;
        let hchars = b64_len(hlen);
        let header = b64(t.get(..hchars).ok_or("the block header runs past the data")?)?;
        let csize: usize = (0..nb).map(|b| word(l, &header, 3 + b)).sum::<Result<usize, String>>()?;
        let data = b64(t.get(hchars..(hchars + b64_len(csize)).min(t.len())).unwrap_or_default())?;
        inflate(l, &header, &data, want)
    } else {
        // the header encoded on its own (then padded) or with the data
        let hchars = b64_len(hs);
        let separate = t.get(hchars - 1) == Some(&b'=');
        let (n, data) = if separate {
            let header = b64(&t[..hchars])?;
            let n = word(l, &header, 0)?;
            (n, b64(t.get(hchars..(hchars + b64_len(n)).min(t.len())).unwrap_or_default())?)
        } else {
            let all = b64(&t[..(b64_len(hs + want)).min(t.len())])?;
            let n = word(l, &all, 0)?;
            (n, all.get(hs..).unwrap_or_default().to_vec())
        };
        if n != want {
            return Err(format!("the block holds {n} bytes, the array needs {want}"));
        }
        data.get(..n).map(<[u8]>::to_vec).ok_or_else(|| "the block is cut short".into())
    }
}

/// Reads a `DataArray` element of `count` values (its components included).
fn array(
    node: roxmltree::Node,
    count: usize,
    l: &Layout,
    app: Option<&Appended>,
    line: usize,
) -> Result<(Scalar, Vec<Value>), ImportError> {
    let name = node.attribute("Name").unwrap_or("");
    let err =
        |m: String| ImportError::Syntax { line, message: format!("DataArray '{}': {m}", shorten(name.as_bytes(), 40)) };
    let ty_name = node.attribute("type").ok_or_else(|| err("no type".into()))?;
    let ty = Scalar::parse(ty_name)
        .filter(|t| *t != Scalar::Text)
        .ok_or_else(|| err(format!("type '{}' is not read", shorten(ty_name.as_bytes(), 40))))?;
    let format = node.attribute("format").unwrap_or("ascii");
    if format == "ascii" {
        let text = node.text().unwrap_or("");
        let mut out = Vec::with_capacity(count.min(text.len() / 2 + 1));
        for (k, tok) in text.split_ascii_whitespace().enumerate() {
            if k >= count {
                return Err(err(format!("more than the {count} values expected")));
            }
            out.push(ty.parse_token(tok.as_bytes()).ok_or_else(|| {
                err(format!("value {k} '{}' is not a number of type {ty_name}", shorten(tok.as_bytes(), 40)))
            })?);
        }
        if out.len() != count {
            return Err(err(format!("{} values, {count} expected", out.len())));
        }
        return Ok((ty, out));
    }
    let want = count.checked_mul(ty.size()).ok_or_else(|| err("too many values".into()))?;
    let bytes = match format {
        "binary" => b64_block(l, node.text().unwrap_or("").as_bytes(), want),
        "appended" => {
            let app = app.ok_or_else(|| err("format appended, but the file has no AppendedData".into()))?;
            let off: usize = node
                .attribute("offset")
                .and_then(|o| o.trim().parse().ok())
                .ok_or_else(|| err("an appended array needs an offset".into()))?;
            let at = app.bytes.get(off..).ok_or_else(|| err(format!("offset {off} is past the appended data")))?;
            if app.base64 {
                b64_block(l, at, want)
            } else {
                raw_block(l, at, want)
            }
        }
        other => return Err(err(format!("format '{}' is not read", shorten(other.as_bytes(), 20)))),
    }
    .map_err(err)?;
    Ok((ty, bytes.chunks_exact(ty.size()).map(|c| ty.decode(c, l.big)).collect()))
}

fn child<'a, 'i>(node: roxmltree::Node<'a, 'i>, name: &str) -> Option<roxmltree::Node<'a, 'i>> {
    node.children().find(|c| c.has_tag_name(name))
}

/// The one child element `name` of `node`, refusing a second one.
fn only_child<'a, 'i>(
    node: roxmltree::Node<'a, 'i>,
    name: &str,
    line_of: &dyn Fn(roxmltree::Node) -> usize,
) -> Result<Option<roxmltree::Node<'a, 'i>>, ImportError> {
    let mut found = node.children().filter(|c| c.has_tag_name(name));
    let first = found.next();
    match found.next() {
        Some(second) => Err(ImportError::Syntax {
            line: line_of(second),
            message: format!("a second {name} element in {}: it has one", node.tag_name().name()),
        }),
        None => Ok(first),
    }
}

/// The value of `name="…"` in the text of a start tag.
fn attribute_in<'t>(tag: &'t str, name: &str) -> Option<&'t str> {
    let mut rest = tag;
    while let Some(at) = rest.find(name) {
        let before = rest[..at].chars().next_back();
        let after = rest[at + name.len()..].trim_start();
        if before.is_some_and(char::is_whitespace) {
            if let Some(v) = after.strip_prefix('=') {
                let v = v.trim_start();
                let q = v.chars().next()?;
                if q == '"' || q == '\'' {
                    return v[1..].find(q).map(|end| &v[1..1 + end]);
                }
            }
        }
        rest = &rest[at + name.len()..];
    }
    None
}

/// Checks the XML declaration, when there is one, against XML 1.0 (§2.8): `version` first
/// (`1.x`), then optionally `encoding` (UTF-8 here) and `standalone` (`yes`, `no`), quoted,
/// closed by `?>`; a declaration anywhere but at the start is refused too.
fn check_declaration(text: &str) -> Result<(), ImportError> {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let bad = |m: String| ImportError::Syntax { line: 1, message: format!("XML declaration: {m}") };
    if let Some(at) = body.get(1..).and_then(|b| b.find("<?xml")) {
        let next = body[at + 6..].chars().next();
        if next.is_none_or(|c| c.is_whitespace() || c == '?') {
            let line = 1 + body[..at + 1].matches('\n').count();
            return Err(ImportError::Syntax { line, message: "an XML declaration after the start of the file".into() });
        }
    }
    let Some(rest) = body.strip_prefix("<?xml") else { return Ok(()) };
    let end = rest.find("?>").ok_or_else(|| bad("not closed by '?>'".into()))?;
    let mut attrs = rest[..end].trim_end();
    if !attrs.starts_with(char::is_whitespace) {
        return Err(bad("'<?xml' is not followed by a space".into()));
    }
    let mut names = Vec::new();
    while !attrs.trim_start().is_empty() {
        let a = attrs.trim_start();
        let eq = a.find('=').ok_or_else(|| bad(format!("'{}' is not name=\"value\"", shorten(a.as_bytes(), 30))))?;
        let name = a[..eq].trim_end();
        let v = a[eq + 1..].trim_start();
        let q = v
            .chars()
            .next()
            .filter(|&q| q == '"' || q == '\'')
            .ok_or_else(|| bad(format!("{name}: the value is not quoted")))?;
        let close = v[1..].find(q).ok_or_else(|| bad(format!("{name}: the quote is not closed")))?;
        let value = &v[1..1 + close];
        let ok = match name {
            "version" => {
                names.is_empty()
                    && value.len() >= 3
                    && value.starts_with("1.")
                    && value[2..].bytes().all(|b| b.is_ascii_digit())
            }
            "encoding" => names == ["version"] && value.eq_ignore_ascii_case("utf-8"),
            "standalone" => {
                names.first() == Some(&"version") && !names.contains(&"standalone") && (value == "yes" || value == "no")
            }
            _ => false,
        };
        if !ok {
            return Err(bad(format!(
                "{}=\"{}\" is not a version 1.x, an encoding UTF-8 and standalone yes or no, in that order",
                shorten(name.as_bytes(), 30),
                shorten(value.as_bytes(), 30)
            )));
        }
        names.push(name);
        attrs = &v[2 + close..];
        if !(attrs.is_empty() || attrs.starts_with(char::is_whitespace)) {
            return Err(bad(format!("no space after {name}")));
        }
    }
    if names.first() != Some(&"version") {
        return Err(bad("no version".into()));
    }
    Ok(())
}

fn attr_count(node: roxmltree::Node, name: &str, line: usize) -> Result<usize, ImportError> {
    node.attribute(name).and_then(|v| v.trim().parse().ok()).ok_or_else(|| ImportError::Syntax {
        line,
        message: format!("{} needs a count {name}", node.tag_name().name()),
    })
}

/// Parses a `.vtu` file (see the module documentation).
pub fn parse_vtu(bytes: &[u8]) -> Result<Mesh, ImportError> {
    // the appended data may be raw bytes, not XML: cut it off before parsing
    let (xml_bytes, app) = match find(bytes, b"<AppendedData") {
        Some(at) => {
            let line = 1 + bytes[..at].iter().filter(|&&c| c == b'\n').count();
            let tag_end = at
                + bytes[at..].iter().position(|&c| c == b'>').ok_or_else(|| ImportError::Syntax {
                    line,
                    message: "the AppendedData tag is not closed".into(),
                })?;
            if find(&bytes[at + 1..], b"<AppendedData").is_some() {
                return Err(ImportError::Syntax {
                    line,
                    message: "a second AppendedData element: a file has one".into(),
                });
            }
            let tag = String::from_utf8_lossy(&bytes[at..tag_end]);
            let base64 = match attribute_in(&tag, "encoding") {
                Some("raw") => false,
                Some("base64") => true,
                Some(other) => {
                    return Err(ImportError::Syntax {
                        line,
                        message: format!(
                            "AppendedData encoding '{}' is not read (raw, base64)",
                            shorten(other.as_bytes(), 40)
                        ),
                    })
                }
                None => {
                    return Err(ImportError::Syntax {
                        line,
                        message: "AppendedData needs an encoding (raw, base64)".into(),
                    })
                }
            };
            let under = tag_end
                + 1
                + bytes[tag_end + 1..].iter().position(|&c| c == b'_').ok_or_else(|| ImportError::Syntax {
                    line,
                    message: "the appended data do not start with '_'".into(),
                })?;
            let end =
                bytes.windows(15).rposition(|w| w == b"</AppendedData>").filter(|&e| e > under).unwrap_or(bytes.len());
            let mut xml = bytes[..at].to_vec();
            xml.extend_from_slice(b"</VTKFile>");
            (xml, Some(Appended { bytes: &bytes[under + 1..end], base64 }))
        }
        None => (bytes.to_vec(), None),
    };
    let text = std::str::from_utf8(&xml_bytes).map_err(|e| {
        let at = e.valid_up_to();
        let line = 1 + xml_bytes[..at].iter().filter(|&&c| c == b'\n').count();
        ImportError::Syntax { line, message: format!("not UTF-8 text: invalid byte at offset {at}") }
    })?;
    check_declaration(text)?;
    let doc = roxmltree::Document::parse(text)
        .map_err(|e| ImportError::Syntax { line: e.pos().row as usize, message: format!("XML: {e}") })?;
    let line_of = |n: roxmltree::Node| doc.text_pos_at(n.range().start).row as usize;
    let root = doc.root_element();
    if !root.has_tag_name("VTKFile") {
        return Err(ImportError::Syntax { line: line_of(root), message: "the root element is not VTKFile".into() });
    }
    let kind = root.attribute("type").unwrap_or("");
    if kind != "UnstructuredGrid" {
        return Err(ImportError::Syntax {
            line: line_of(root),
            message: format!("type '{}' is not read: only UnstructuredGrid", shorten(kind.as_bytes(), 40)),
        });
    }
    let layout = Layout {
        big: root.attribute("byte_order") == Some("BigEndian"),
        header: match root.attribute("header_type").unwrap_or("UInt32") {
            "UInt32" => Scalar::UInt(4),
            "UInt64" => Scalar::UInt(8),
            other => {
                return Err(ImportError::Syntax {
                    line: line_of(root),
                    message: format!("header_type '{}' is not read (UInt32, UInt64)", shorten(other.as_bytes(), 20)),
                })
            }
        },
        compressor: match root.attribute("compressor") {
            None | Some("") => None,
            Some("vtkZLibDataCompressor") => Some(Compressor::Zlib),
            Some("vtkLZMADataCompressor") => Some(Compressor::Lzma),
            Some("vtkLZ4DataCompressor") => Some(Compressor::Lz4),
            Some(other) => {
                return Err(ImportError::Syntax {
                    line: line_of(root),
                    message: format!(
                    "compressor '{}' is not read (vtkZLibDataCompressor, vtkLZMADataCompressor, vtkLZ4DataCompressor)",
                    shorten(other.as_bytes(), 40)
                ),
                })
            }
        },
    };
    let grid = child(root, "UnstructuredGrid")
        .ok_or_else(|| ImportError::Syntax { line: line_of(root), message: "no UnstructuredGrid element".into() })?;
    let mut mesh = Mesh::default();
    let pieces: Vec<_> = grid.children().filter(|c| c.has_tag_name("Piece")).collect();
    if pieces.is_empty() {
        return Err(ImportError::MissingSection { section: "<Piece>".into(), empty: false });
    }
    let mut extra = Vec::new();
    for piece in pieces {
        read_piece(piece, &layout, app.as_ref(), &line_of, &mut mesh, &mut extra)?;
    }
    if mesh.cells.is_empty() {
        return Err(ImportError::MissingSection { section: "<Piece>".into(), empty: true });
    }
    extra.resize(mesh.cells.len(), None);
    mesh.cell_data.extend(label_array(extra));
    let field_data = read_field_data(grid, &layout, app.as_ref(), &line_of)?;
    crate::mesh::texts::apply_text_tables(&mut mesh.cell_data, &field_data).map_err(ImportError::Format)?;
    check_data(&mesh)?;
    Ok(mesh)
}

/// The arrays of the grid's `FieldData` that are tables of texts of the mesh writers
/// (`gmap:texts:<name>`); other field data are read past.
fn read_field_data(
    grid: roxmltree::Node,
    l: &Layout,
    app: Option<&Appended>,
    line_of: &dyn Fn(roxmltree::Node) -> usize,
) -> Result<Vec<crate::mesh::DataArray>, ImportError> {
    let mut out = Vec::new();
    let Some(fd) = child(grid, "FieldData") else { return Ok(out) };
    for da in fd.children().filter(|c| c.has_tag_name("DataArray")) {
        let name = da.attribute("Name").unwrap_or("");
        if !name.starts_with(crate::mesh::texts::TABLE_PREFIX) {
            continue;
        }
        let line = line_of(da);
        let n = attr_count(da, "NumberOfTuples", line)?;
        let (ty, v) = array(da, n, l, app, line)?;
        out.extend(data_arrays(name, 1, ty, v));
    }
    Ok(out)
}

fn read_piece(
    piece: roxmltree::Node,
    l: &Layout,
    app: Option<&Appended>,
    line_of: &dyn Fn(roxmltree::Node) -> usize,
    mesh: &mut Mesh,
    extra: &mut Vec<Option<LabelValue>>,
) -> Result<(), ImportError> {
    let pl = line_of(piece);
    let np = attr_count(piece, "NumberOfPoints", pl)?;
    let nc = attr_count(piece, "NumberOfCells", pl)?;
    let base = mesh.points.len();
    let (cells_before, points_before) = (mesh.cells.len(), mesh.points.len());
    let missing = |what: &str, line: usize| ImportError::Syntax { line, message: format!("no {what}") };
    for name in ["Points", "Cells", "PointData", "CellData"] {
        only_child(piece, name, line_of)?;
    }
    if np > 0 {
        let pts = child(piece, "Points").ok_or_else(|| missing("Points element", pl))?;
        let da = child(pts, "DataArray").ok_or_else(|| missing("DataArray in Points", line_of(pts)))?;
        let line = line_of(da);
        let n3 = np.checked_mul(3).ok_or_else(|| ImportError::Syntax { line, message: "too many points".into() })?;
        let (_, v) = array(da, n3, l, app, line)?;
        mesh.points.extend(points_of(&v, |k| ImportError::Syntax {
            line,
            message: format!("Points: coordinate {k} (point {}) is not a finite number", k / 3),
        })?);
    }
    if nc > 0 {
        let cells = child(piece, "Cells").ok_or_else(|| missing("Cells element", pl))?;
        let cl = line_of(cells);
        let named =
            |name: &str| cells.children().find(|c| c.has_tag_name("DataArray") && c.attribute("Name") == Some(name));
        let get = |name: &str, count: usize| -> Result<Vec<Value>, ImportError> {
            let da = named(name).ok_or_else(|| missing(&format!("DataArray '{name}' in Cells"), cl))?;
            Ok(array(da, count, l, app, line_of(da))?.1)
        };
        let index = |v: &Value, what: &str, k: usize, line: usize| -> Result<usize, ImportError> {
            v.index()
                .map(|x| x as usize)
                .ok_or_else(|| ImportError::Syntax { line, message: format!("{what} value {k} is not an index") })
        };
        let offsets = get("offsets", nc)?;
        let ol = named("offsets").map_or(cl, line_of);
        let offsets: Vec<usize> =
            offsets.iter().enumerate().map(|(k, v)| index(v, "offsets", k, ol)).collect::<Result<_, _>>()?;
        let total = *offsets.last().unwrap_or(&0);
        let conn = get("connectivity", total)?;
        let types = get("types", nc)?;
        let (faces, faceoffsets) = match named("faces") {
            Some(_) => {
                let fo = get("faceoffsets", nc)?;
                let fo: Vec<i64> = fo.iter().map(|v| v.int().unwrap_or(-1)).collect();
                let nf = fo.iter().copied().max().unwrap_or(0).max(0) as usize;
                (get("faces", nf)?, fo)
            }
            None => (Vec::new(), Vec::new()),
        };
        let tl = named("types").map_or(cl, line_of);
        let mut start = 0usize;
        let mut face_start = 0usize;
        for k in 0..nc {
            let end = offsets[k];
            let err = |m: String| ImportError::Syntax { line: cl, message: format!("cell {}: {m}", cells_before + k) };
            if end < start || end > conn.len() {
                return Err(err(format!("offsets {start}..{end} outside the {} connectivity values", conn.len())));
            }
            let shift = |v: &Value| -> Result<u32, ImportError> {
                v.index()
                    .and_then(|x| u32::try_from(x as usize + base).ok())
                    .filter(|&x| x != u32::MAX)
                    .ok_or_else(|| err("a point index that is not an index".into()))
            };
            let t = types[k].int().unwrap_or(-1);
            let (kind, higher) = vtk_kind(t, cells_before + k, tl)?;
            if kind == CellKind::Polyhedron {
                let fe = faceoffsets.get(k).copied().unwrap_or(-1);
                if fe < 0 {
                    return Err(err("a polyhedron needs the arrays faces and faceoffsets".into()));
                }
                let fe = fe as usize;
                if fe < face_start || fe > faces.len() {
                    return Err(err(format!("faceoffsets {face_start}..{fe} outside the {} face values", faces.len())));
                }
                let stream: Vec<u32> = faces[face_start..fe].iter().map(&shift).collect::<Result<_, _>>()?;
                mesh.cells.push(polyhedron(&stream).map_err(|m| err(format!("polyhedron: {m}")))?);
                face_start = fe;
            } else {
                let nodes: Vec<u32> = conn[start..end].iter().map(&shift).collect::<Result<_, _>>()?;
                let mut cell = MeshCell { kind, nodes, faces: Vec::new() };
                if let Some(h) = higher {
                    let v = corners_of(&mut cell, &h, &mesh.points, cells_before + k)
                        .map_err(|m| ImportError::Syntax { line: tl, message: m })?;
                    extra.resize(cells_before + k, None);
                    extra.push(Some(v));
                }
                mesh.cells.push(cell);
            }
            start = end;
        }
    }
    for (section, n, before, cell) in [("PointData", np, points_before, false), ("CellData", nc, cells_before, true)] {
        let Some(sec) = child(piece, section) else { continue };
        for da in sec.children().filter(|c| c.has_tag_name("DataArray")) {
            let line = line_of(da);
            let name = da.attribute("Name").filter(|n| !n.is_empty()).map(str::to_string).ok_or_else(|| {
                ImportError::Syntax {
                    line,
                    message: format!("a DataArray of {section} without a Name: labels are named"),
                }
            })?;
            let comps = match da.attribute("NumberOfComponents") {
                Some(c) => c.trim().parse::<usize>().ok().filter(|&c| c > 0).ok_or_else(|| ImportError::Syntax {
                    line,
                    message: format!("DataArray '{}': NumberOfComponents is not a count", shorten(name.as_bytes(), 40)),
                })?,
                None => 1,
            };
            let total =
                n.checked_mul(comps).ok_or_else(|| ImportError::Syntax { line, message: "too many values".into() })?;
            let (ty, v) = array(da, total, l, app, line)?;
            let target = if cell { &mut mesh.cell_data } else { &mut mesh.point_data };
            for a in data_arrays(&name, comps, ty, v) {
                // arrays of earlier pieces: pad them, or start this one padded
                match target.iter_mut().find(|x| x.name == a.name) {
                    Some(x) => {
                        x.values.resize(before, None);
                        x.values.extend(a.values);
                    }
                    None => {
                        let mut values = vec![None; before];
                        values.extend(a.values);
                        target.push(crate::mesh::DataArray { name: a.name, values });
                    }
                }
            }
        }
    }
    // arrays this piece lacks
    let (np_all, nc_all) = (mesh.points.len(), mesh.cells.len());
    for a in &mut mesh.point_data {
        a.values.resize(np_all, None);
    }
    for a in &mut mesh.cell_data {
        a.values.resize(nc_all, None);
    }
    Ok(())
}

/// Reads a `.vtu` unstructured grid into a labelled map (see the module documentation and
/// [`crate::mesh`]), refusing more than `max_darts` darts (default:
/// [`default_max_darts`]`(3)`).
pub fn read_vtu(path: &Path, max_darts: Option<u64>) -> Result<LabelledGMap, FileError> {
    let bytes = super::common::read_bytes(path)?;
    let mesh = parse_vtu(&bytes).map_err(|e| FileError::new(path, e))?;
    mesh.to_gmap(max_darts.unwrap_or_else(|| default_max_darts(3))).map_err(|e| FileError::new(path, e.into()))
}
