//! Gmsh meshes (`.msh`, format 4.1, ASCII or binary; docs/FORMATS.md). The reader is
//! [`crate::import::msh`].
//!
//! The cells, their corner orders (Gmsh's are VTK's for the linear cells: positive volumes)
//! and the labelled lower cells are those of [`super::cells`], as the element types 15
//! (point), 1 (line), 2 (triangle), 3 (quadrangle), 4 (tetrahedron), 5 (hexahedron), 6
//! (prism) and 7 (pyramid); Gmsh has no polygon of more than four corners and no polyhedron,
//! so a map with such cells is refused (write `.vtk` or `.vtu`). Nodes are tagged `1..` in
//! the order of the 0-cells, elements `1..` in the order they are written (by entity and
//! type); each `$ElementData` lists every element, NaN where it has no value.
//!
//! The labels the reader makes are written back as they are read: each cell is an element
//! of the entity `gmsh:geometrical` of its dimension, whose physical groups are the cell's
//! `gmsh:physical`, `gmsh:physical.1`, …, named in `$PhysicalNames` by `gmsh:physical_name`.
//! A cell without `gmsh:geometrical` goes on a new entity of its dimension (one per set of
//! physical groups), which reads back as its `gmsh:geometrical`. Refused: two cells of one
//! entity with different physical groups, a physical group whose cells have different names
//! (or a name without a group), tags that are not integers. Every other label is
//! `$ElementData` named by the label (Gmsh's data are reals: integers read back as reals);
//! texts other than the physical names are refused (`.vtk` and `.vtu` keep them). The output
//! is read back before it is written (ASCII; the binary file holds the same sections) and
//! refused when it would not give the same map and labels.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use gmap_core::{DenseLabels, DenseMap, LabelValue};

use super::cells::{mesh_out, MeshOut, Written};
use super::error::{write_atomic, ExportError};
use super::readback::Labelling;

/// One entity: its dimension and tag, its physical groups, its cells (indices into the
/// written cells).
struct Entity {
    dim: usize,
    tag: i64,
    physical: Vec<i64>,
    cells: Vec<usize>,
}

/// What a `.msh` file holds, before it is serialised.
struct MshOut {
    mesh: MeshOut,
    types: Vec<u8>,
    names: Vec<(usize, i64, String)>,
    entities: Vec<Entity>,
    data: Vec<(String, Vec<Option<f64>>)>,
}

fn refuse(reason: String) -> ExportError {
    ExportError::MeshWrite { format: ".msh", reason }
}

/// The Gmsh element type of a written cell.
fn gmsh_type(w: &Written) -> Result<u8, ExportError> {
    Ok(match (w.kind, w.conn.len()) {
        (1, _) => 15,
        (3, _) => 1,
        (5, _) => 2,
        (9, _) => 3,
        (10, _) => 4,
        (12, _) => 5,
        (13, _) => 6,
        (14, _) => 7,
        (_, k) => {
            let what = if w.dim == 3 {
                format!("a polyhedron of {} faces", w.faces.len())
            } else {
                format!("a polygon of {k} corners")
            };
            return Err(refuse(format!(
                "{}-cell {} is {what}, which Gmsh has no element for (write .vtk or .vtu)",
                w.dim, w.cell
            )));
        }
    })
}

/// The integer of a tag label.
fn tag(v: &LabelValue, name: &str) -> Result<i64, ExportError> {
    match v {
        LabelValue::Int(i) => Ok(*i),
        other => Err(refuse(format!("the label {name} is a tag and must be an integer, found {other:?}"))),
    }
}

/// The entities, the physical names and the element data of mesh cells (see the module
/// documentation).
fn msh_out(mesh: MeshOut) -> Result<MshOut, ExportError> {
    let types = mesh.cells.iter().map(gmsh_type).collect::<Result<Vec<u8>, _>>()?;
    let col = |name: &str| mesh.columns.iter().find(|c| c.name == name);
    let mut physical_cols: Vec<&super::cells::LabelColumn> = Vec::new();
    while let Some(c) = col(&if physical_cols.is_empty() {
        "gmsh:physical".to_string()
    } else {
        format!("gmsh:physical.{}", physical_cols.len())
    }) {
        physical_cols.push(c);
    }
    let geo = col("gmsh:geometrical");
    let pname = col("gmsh:physical_name");
    // entities by (dim, tag); cells without a tag on new entities by (dim, groups)
    let mut by_key: BTreeMap<(usize, i64), usize> = BTreeMap::new();
    let mut entities: Vec<Entity> = Vec::new();
    let mut next_tag = [0i64; 4];
    if let Some(g) = geo {
        for (k, v) in g.values.iter().enumerate() {
            if let Some(v) = v {
                let d = mesh.cells[k].dim;
                next_tag[d] = next_tag[d].max(tag(v, "gmsh:geometrical")?);
            }
        }
    }
    let mut fresh: BTreeMap<(usize, Vec<i64>), i64> = BTreeMap::new();
    let mut names: BTreeMap<(usize, i64), Option<String>> = BTreeMap::new();
    for (k, w) in mesh.cells.iter().enumerate() {
        let mut physical = Vec::new();
        for c in &physical_cols {
            match &c.values[k] {
                Some(v) => physical.push(tag(v, &c.name)?),
                None => break,
            }
        }
        let name = match pname.and_then(|c| c.values[k].as_ref()) {
            Some(LabelValue::Text(s)) => Some(s.clone()),
            Some(other) => return Err(refuse(format!("gmsh:physical_name is {other:?}, not a text"))),
            None => None,
        };
        match (physical.first(), &name) {
            (None, Some(n)) => {
                return Err(refuse(format!(
                    "{}-cell {} is named {n:?} but is in no physical group (gmsh:physical)",
                    w.dim, w.cell
                )))
            }
            (Some(&p), _) => {
                let known = names.entry((w.dim, p)).or_insert_with(|| name.clone());
                if *known != name {
                    return Err(refuse(format!(
                        "the cells of physical group {p} of dimension {} have the names {known:?} and {name:?}",
                        w.dim
                    )));
                }
            }
            _ => {}
        }
        let t = match geo.and_then(|g| g.values[k].as_ref()) {
            Some(v) => tag(v, "gmsh:geometrical")?,
            None => *fresh.entry((w.dim, physical.clone())).or_insert_with(|| {
                next_tag[w.dim] += 1;
                next_tag[w.dim]
            }),
        };
        let e = *by_key.entry((w.dim, t)).or_insert_with(|| {
            entities.push(Entity { dim: w.dim, tag: t, physical: physical.clone(), cells: Vec::new() });
            entities.len() - 1
        });
        if entities[e].physical != physical {
            return Err(refuse(format!(
                "the cells of entity {t} of dimension {} are in different physical groups, {:?} and {physical:?}",
                w.dim, entities[e].physical
            )));
        }
        entities[e].cells.push(k);
    }
    let mut data = Vec::new();
    for c in &mesh.columns {
        if c.name == "gmsh:geometrical"
            || c.name == "gmsh:physical_name"
            || physical_cols.iter().any(|p| p.name == c.name)
        {
            continue;
        }
        let mut values = Vec::with_capacity(c.values.len());
        for v in &c.values {
            let x = match v {
                None => {
                    values.push(None);
                    continue;
                }
                Some(LabelValue::Int(i)) if i.unsigned_abs() <= 1 << 53 => *i as f64,
                Some(LabelValue::Real(r)) => *r,
                Some(other) => {
                    return Err(refuse(format!(
                        "the label {} has the value {other:?}: Gmsh's data are reals, and it holds texts only as \
                         physical names (gmsh:physical_name); write .vtk or .vtu",
                        c.name
                    )))
                }
            };
            values.push(Some(x));
        }
        data.push((c.name.clone(), values));
    }
    let names = names.into_iter().filter_map(|((d, p), n)| n.map(|n| (d, p, n))).collect();
    Ok(MshOut { mesh, types, names, entities, data })
}

/// A text in Gmsh's double quotes (a quote or a backslash in it is refused by Gmsh's own
/// reader: they are kept as they are, and the read-back refuses what does not read back).
fn quoted(s: &str) -> String {
    format!("\"{s}\"")
}

/// The bounding box of an entity's cells.
fn bbox(m: &MshOut, e: &Entity) -> [f64; 6] {
    let mut b = [f64::INFINITY, f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];
    for &k in &e.cells {
        for &v in &m.mesh.cells[k].conn {
            for (a, &x) in m.mesh.points[v as usize].iter().enumerate() {
                b[a] = b[a].min(x);
                b[a + 3] = b[a + 3].max(x);
            }
        }
    }
    b
}

/// A sink for the sections of either encoding.
struct Out {
    bytes: Vec<u8>,
    binary: bool,
}

impl Out {
    fn text(&mut self, s: &str) {
        self.bytes.extend_from_slice(s.as_bytes());
    }
    /// An `int` (binary) or a word (ASCII).
    fn int(&mut self, v: i64, end: &str) {
        if self.binary {
            self.bytes.extend_from_slice(&(v as i32).to_le_bytes());
        } else {
            self.text(&format!("{v}{end}"));
        }
    }
    /// A `size_t` (binary) or a word (ASCII).
    fn size(&mut self, v: usize, end: &str) {
        if self.binary {
            self.bytes.extend_from_slice(&(v as u64).to_le_bytes());
        } else {
            self.text(&format!("{v}{end}"));
        }
    }
    fn real(&mut self, v: f64, end: &str) {
        if self.binary {
            self.bytes.extend_from_slice(&v.to_le_bytes());
        } else {
            self.text(&format!("{v:?}{end}"));
        }
    }
    /// The end of a section: binary data are followed by a newline.
    fn end(&mut self, name: &str) {
        if self.binary {
            self.text("\n");
        }
        self.text(&format!("$End{name}\n"));
    }
}

fn entities_section(o: &mut Out, m: &MshOut) {
    o.text("$Entities\n");
    for d in 0..4 {
        o.size(m.entities.iter().filter(|e| e.dim == d).count(), if d == 3 { "\n" } else { " " });
    }
    for d in 0..4 {
        for e in m.entities.iter().filter(|e| e.dim == d) {
            o.int(e.tag, " ");
            let b = bbox(m, e);
            for x in if d == 0 { &b[..3] } else { &b[..] } {
                o.real(*x, " ");
            }
            o.size(e.physical.len(), " ");
            for &p in &e.physical {
                o.int(p, " ");
            }
            if d > 0 {
                o.size(0, "");
            }
            if !o.binary {
                o.text("\n");
            }
        }
    }
    o.end("Entities");
}

fn nodes_section(o: &mut Out, m: &MshOut) {
    let np = m.mesh.points.len();
    o.text("$Nodes\n");
    let blocks = usize::from(np > 0);
    o.size(blocks, " ");
    o.size(np, " ");
    o.size(1.min(np), " ");
    o.size(np, "\n");
    if np > 0 {
        let e = &m.entities[0];
        o.int(e.dim as i64, " ");
        o.int(e.tag, " ");
        o.int(0, " ");
        o.size(np, "\n");
        for k in 1..=np {
            o.size(k, "\n");
        }
        for p in &m.mesh.points {
            o.real(p[0], " ");
            o.real(p[1], " ");
            o.real(p[2], "\n");
        }
    }
    o.end("Nodes");
}

/// The element blocks, one per entity and element type: (entity, type, cells).
fn blocks(m: &MshOut) -> Vec<(usize, u8, Vec<usize>)> {
    let mut out = Vec::new();
    for (e, ent) in m.entities.iter().enumerate() {
        let mut types: Vec<u8> = ent.cells.iter().map(|&k| m.types[k]).collect();
        types.sort_unstable();
        types.dedup();
        for t in types {
            out.push((e, t, ent.cells.iter().copied().filter(|&k| m.types[k] == t).collect()));
        }
    }
    out
}

/// `$Elements`: the blocks, elements tagged `1..` in the order they are written.
fn elements_section(o: &mut Out, m: &MshOut, blocks: &[(usize, u8, Vec<usize>)]) {
    let nc = m.mesh.cells.len();
    o.text("$Elements\n");
    o.size(blocks.len(), " ");
    o.size(nc, " ");
    o.size(1.min(nc), " ");
    o.size(nc, "\n");
    let mut tag = 0;
    for (e, t, cells) in blocks {
        let ent = &m.entities[*e];
        o.int(ent.dim as i64, " ");
        o.int(ent.tag, " ");
        o.int(i64::from(*t), " ");
        o.size(cells.len(), "\n");
        for &k in cells {
            tag += 1;
            o.size(tag, " ");
            let conn = &m.mesh.cells[k].conn;
            for (j, &v) in conn.iter().enumerate() {
                o.size(v as usize + 1, if j + 1 == conn.len() { "\n" } else { " " });
            }
        }
    }
    o.end("Elements");
}

/// The bytes of the file.
fn serialise(m: &MshOut, binary: bool) -> Vec<u8> {
    let mut o = Out { bytes: Vec::new(), binary };
    if binary {
        o.text("$MeshFormat\n4.1 1 8\n");
        o.bytes.extend_from_slice(&1i32.to_le_bytes());
        o.text("\n$EndMeshFormat\n");
    } else {
        o.text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
    }
    if !m.names.is_empty() {
        let mut s = format!("$PhysicalNames\n{}\n", m.names.len());
        for (d, p, n) in &m.names {
            let _ = writeln!(s, "{d} {p} {}", quoted(n));
        }
        s.push_str("$EndPhysicalNames\n");
        o.text(&s);
    }
    entities_section(&mut o, m);
    nodes_section(&mut o, m);
    let blocks = blocks(m);
    elements_section(&mut o, m, &blocks);
    // element data over every element, in the order of the tags (NaN: no value), as meshio
    // reads them
    let order: Vec<usize> = blocks.iter().flat_map(|b| b.2.iter().copied()).collect();
    for (name, values) in &m.data {
        o.text(&format!("$ElementData\n1\n{}\n1\n0.0\n3\n0\n1\n{}\n", quoted(name), order.len()));
        for (tag, k) in order.iter().enumerate() {
            o.int(tag as i64 + 1, " ");
            o.real(values[*k].unwrap_or(f64::NAN), "\n");
        }
        o.end("ElementData");
    }
    o.bytes
}

/// The `.msh` 4.1 bytes of a map of dimension at most 3 with points and the labels of its
/// cells, ASCII or binary (see the module documentation). The ASCII text is read back before
/// either is returned. O(N n) plus the data and its reading.
pub fn msh_bytes_with_labels(map: &DenseMap, labels: &DenseLabels, binary: bool) -> Result<Vec<u8>, ExportError> {
    let m = msh_out(mesh_out(map, labels, ".msh")?)?;
    let ascii = serialise(&m, false);
    super::readback::check(map, labels, ".msh", Labelling::Gmsh, || {
        let text = std::str::from_utf8(&ascii).map_err(|e| crate::import::ImportError::Format(e.to_string()))?;
        crate::import::parse_msh(text.as_bytes()).map(|f| f.mesh)
    })?;
    Ok(if binary { serialise(&m, true) } else { ascii })
}

/// Writes a map and the labels of its cells as `.msh` 4.1 (see [`msh_bytes_with_labels`]);
/// nothing is written when it is refused.
pub fn write_msh_with_labels(
    map: &DenseMap,
    labels: &DenseLabels,
    binary: bool,
    path: &Path,
) -> Result<(), ExportError> {
    write_atomic(path, &msh_bytes_with_labels(map, labels, binary)?)
}
