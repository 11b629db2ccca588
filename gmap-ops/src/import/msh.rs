//! Gmsh meshes (`.msh`, format 4.1, ASCII) into a [`Mesh`] and then a labelled map
//! ([`crate::mesh`]).
//!
//! Read: `$MeshFormat` (4.1, ASCII; binary files are refused), `$PhysicalNames`,
//! `$Entities` (the physical tags of each entity), `$Nodes`, `$Elements` of the linear
//! types 1 (line), 2 (triangle), 3 (quadrangle), 4 (tetrahedron), 5 (hexahedron), 6
//! (prism), 7 (pyramid) and 15 (point), and `$NodeData` / `$ElementData` (their values
//! become labels named by the data's first string tag). Other sections are read past.
//!
//! Each element is labelled `gmsh:geometrical` (its entity's tag) and, when its entity has
//! physical tags, `gmsh:physical` (the first; more are `gmsh:physical.1`, …) and
//! `gmsh:physical_name` (the name of the first in `$PhysicalNames`), the names meshio uses.
//! Elements of lower dimension (boundary triangles of a tetrahedral mesh, physical curves
//! and points) must be faces, edges or vertices of the top elements, whose labels they set.
//!
//! Errors name the file and the line; errors about cells name them by their element tags,
//! and vertices by their node tags. O(size of the file) plus [`Mesh::to_gmap`].

use std::path::Path;

use gmap_core::io::shorten;
use gmap_core::{LabelValue, LabelledGMap, Point};
use rustc_hash::FxHashMap;

use super::{default_max_darts, FileError, ImportError};
use crate::mesh::{CellKind, DataArray, Mesh, MeshCell, MeshError};

/// The tokens of the text with their line numbers.
struct Tokens<'a> {
    lines: std::iter::Peekable<std::iter::Enumerate<std::str::Lines<'a>>>,
    current: std::str::SplitAsciiWhitespace<'a>,
    line: usize,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str) -> Self {
        Tokens { lines: text.lines().enumerate().peekable(), current: "".split_ascii_whitespace(), line: 0 }
    }

    fn err(&self, m: String) -> ImportError {
        ImportError::Syntax { line: self.line.max(1), message: m }
    }

    /// The next token, across lines.
    fn next(&mut self) -> Option<&'a str> {
        loop {
            if let Some(t) = self.current.next() {
                return Some(t);
            }
            let (k, l) = self.lines.next()?;
            self.line = k + 1;
            self.current = l.split_ascii_whitespace();
        }
    }

    fn expect(&mut self, what: &str) -> Result<&'a str, ImportError> {
        self.next().ok_or_else(|| self.err(format!("the file ends before {what}")))
    }

    fn num<T: std::str::FromStr>(&mut self, what: &str) -> Result<T, ImportError> {
        let t = self.expect(what)?;
        t.parse().map_err(|_| self.err(format!("{what} '{}' is not a valid number", shorten(t.as_bytes(), 40))))
    }

    fn real(&mut self, what: &str) -> Result<f64, ImportError> {
        let v: f64 = self.num(what)?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(format!("{what} is not finite")))
        }
    }

    /// A count, refused when the rest of the text cannot hold `per` tokens for each.
    fn count(&mut self, what: &str, left: usize, per: usize) -> Result<usize, ImportError> {
        let n: usize = self.num(what)?;
        if n.saturating_mul(per.max(1)) > left.saturating_mul(1) / 2 + 1 {
            return Err(self.err(format!("{what} {n}: the rest of the file cannot hold them")));
        }
        Ok(n)
    }

    /// Skips to the line `$End<name>`.
    fn skip_section(&mut self, name: &str) -> Result<(), ImportError> {
        let end = format!("$End{name}");
        while let Some(t) = self.next() {
            if t == end {
                return Ok(());
            }
        }
        Err(self.err(format!("no {end}")))
    }
}

/// A quoted string token sequence: `"a b"` may span several tokens.
fn quoted(t: &mut Tokens, what: &str) -> Result<String, ImportError> {
    let first = t.expect(what)?;
    if !first.starts_with('"') {
        return Ok(first.to_string());
    }
    let mut s = first.to_string();
    while !(s.len() >= 2 && s.ends_with('"')) {
        let more = t.expect(what)?;
        s.push(' ');
        s.push_str(more);
    }
    Ok(s[1..s.len() - 1].to_string())
}

fn kind_of(t: i64) -> Option<CellKind> {
    Some(match t {
        1 => CellKind::Line,
        2 => CellKind::Triangle,
        3 => CellKind::Quad,
        4 => CellKind::Tetra,
        5 => CellKind::Hexahedron,
        6 => CellKind::Wedge,
        7 => CellKind::Pyramid,
        15 => CellKind::Vertex,
        _ => return None,
    })
}

/// A parsed `.msh`: the mesh, and the node and element tags of its points and cells.
pub struct MshFile {
    /// the mesh, points and cells in file order
    pub mesh: Mesh,
    /// the node tag of each point
    pub node_tags: Vec<u64>,
    /// the element tag of each cell
    pub element_tags: Vec<u64>,
}

/// Parses a Gmsh 4.1 ASCII mesh (see the module documentation).
pub fn parse_msh(text: &str) -> Result<MshFile, ImportError> {
    let total = text.len();
    let mut t = Tokens::new(text);
    let mut names: FxHashMap<(i64, i64), String> = FxHashMap::default();
    let mut physicals: FxHashMap<(i64, i64), Vec<i64>> = FxHashMap::default();
    let mut node_index: FxHashMap<u64, u32> = FxHashMap::default();
    let mut mesh = Mesh::default();
    let mut node_tags: Vec<u64> = Vec::new();
    let mut element_tags: Vec<u64> = Vec::new();
    let mut element_index: FxHashMap<u64, usize> = FxHashMap::default();
    let mut entity_of: Vec<(i64, i64)> = Vec::new();
    let mut seen_format = false;
    let (mut seen_nodes, mut seen_elements, mut seen_entities) = (false, false, false);
    let mut node_data: Vec<DataArray> = Vec::new();
    let mut element_data: Vec<(DataArray, usize)> = Vec::new();
    while let Some(head) = t.next() {
        let Some(name) = head.strip_prefix('$') else {
            return Err(
                t.err(format!("expected a section ($MeshFormat, $Nodes…), found '{}'", shorten(head.as_bytes(), 40)))
            );
        };
        if !seen_format && name != "MeshFormat" {
            return Err(t.err("the file does not start with $MeshFormat".into()));
        }
        match name {
            "MeshFormat" => {
                let v = t.expect("the version")?;
                if v != "4.1" {
                    return Err(t.err(format!("version {} is not read: only 4.1", shorten(v.as_bytes(), 20))));
                }
                let ft: i64 = t.num("the file type")?;
                if ft != 0 {
                    return Err(t.err("binary .msh files are not read: only ASCII".into()));
                }
                let _size: i64 = t.num("the data size")?;
                seen_format = true;
                t.skip_section(name)?;
            }
            "PhysicalNames" => {
                let n = t.count("the number of names", total, 3)?;
                for _ in 0..n {
                    let dim: i64 = t.num("a dimension")?;
                    let tag: i64 = t.num("a physical tag")?;
                    names.insert((dim, tag), quoted(&mut t, "a name")?);
                }
                t.skip_section(name)?;
            }
            "Entities" => {
                let counts: Vec<usize> =
                    (0..4).map(|_| t.count("a number of entities", total, 5)).collect::<Result<_, _>>()?;
                for (dim, &n) in counts.iter().enumerate() {
                    for _ in 0..n {
                        let tag: i64 = t.num("an entity tag")?;
                        for _ in 0..if dim == 0 { 3 } else { 6 } {
                            t.real("a coordinate")?;
                        }
                        let np = t.count("a number of physical tags", total, 1)?;
                        let tags: Vec<i64> = (0..np).map(|_| t.num("a physical tag")).collect::<Result<_, _>>()?;
                        physicals.insert((dim as i64, tag), tags);
                        if dim > 0 {
                            let nb = t.count("a number of bounding entities", total, 1)?;
                            for _ in 0..nb {
                                t.num::<i64>("a bounding entity")?;
                            }
                        }
                    }
                }
                seen_entities = true;
                t.skip_section(name)?;
            }
            "Nodes" => {
                seen_nodes = true;
                let blocks = t.count("the number of entity blocks", total, 4)?;
                let n = t.count("the number of nodes", total, 4)?;
                let _min: u64 = t.num("the smallest node tag")?;
                let _max: u64 = t.num("the largest node tag")?;
                mesh.points.reserve(n);
                for _ in 0..blocks {
                    let dim: i64 = t.num("an entity dimension")?;
                    let _tag: i64 = t.num("an entity tag")?;
                    let param: i64 = t.num("the parametric flag")?;
                    let k = t.count("a number of nodes", total, 4)?;
                    let start = node_tags.len();
                    for _ in 0..k {
                        let tag: u64 = t.num("a node tag")?;
                        let index = u32::try_from(node_tags.len())
                            .ok()
                            .filter(|&i| i != u32::MAX)
                            .ok_or_else(|| t.err("too many nodes".into()))?;
                        if node_index.insert(tag, index).is_some() {
                            return Err(t.err(format!("node tag {tag} appears twice")));
                        }
                        node_tags.push(tag);
                    }
                    for _ in start..node_tags.len() {
                        let p: Point = [t.real("x")?, t.real("y")?, t.real("z")?];
                        if param == 1 {
                            for _ in 0..dim.clamp(0, 3) {
                                t.real("a parametric coordinate")?;
                            }
                        }
                        mesh.points.push(p);
                    }
                }
                t.skip_section(name)?;
            }
            "Elements" => {
                seen_elements = true;
                let blocks = t.count("the number of entity blocks", total, 4)?;
                let _n = t.count("the number of elements", total, 2)?;
                let _min: u64 = t.num("the smallest element tag")?;
                let _max: u64 = t.num("the largest element tag")?;
                for _ in 0..blocks {
                    let dim: i64 = t.num("an entity dimension")?;
                    let tag: i64 = t.num("an entity tag")?;
                    let ty: i64 = t.num("an element type")?;
                    let kind = kind_of(ty).ok_or_else(|| {
                        t.err(format!("element type {ty} is not read (1 line, 2 triangle, 3 quadrangle, 4 tetrahedron, 5 hexahedron, 6 prism, 7 pyramid, 15 point)"))
                    })?;
                    if kind.dim() as i64 != dim {
                        return Err(t.err(format!("element type {ty} has dimension {}, its entity {dim}", kind.dim())));
                    }
                    if seen_entities && !physicals.contains_key(&(dim, tag)) {
                        return Err(t.err(format!(
                            "an element block of entity {tag} (dimension {dim}), which $Entities does not list: its physical groups are unknown"
                        )));
                    }
                    let k = t.count("a number of elements", total, 2)?;
                    let per = kind.points().expect("a fixed kind");
                    for _ in 0..k {
                        let et: u64 = t.num("an element tag")?;
                        let mut nodes = Vec::with_capacity(per);
                        for _ in 0..per {
                            let nt: u64 = t.num("a node tag")?;
                            nodes.push(
                                *node_index
                                    .get(&nt)
                                    .ok_or_else(|| t.err(format!("element {et}: no node with tag {nt}")))?,
                            );
                        }
                        if element_index.insert(et, mesh.cells.len()).is_some() {
                            return Err(t.err(format!("element tag {et} appears twice")));
                        }
                        element_tags.push(et);
                        entity_of.push((dim, tag));
                        mesh.cells.push(MeshCell { kind, nodes, faces: Vec::new() });
                    }
                }
                t.skip_section(name)?;
            }
            "NodeData" | "ElementData" => {
                let nodes = name == "NodeData";
                let ns = t.count("the number of string tags", total, 1)?;
                let strings: Vec<String> = (0..ns).map(|_| quoted(&mut t, "a string tag")).collect::<Result<_, _>>()?;
                let nr = t.count("the number of real tags", total, 1)?;
                for _ in 0..nr {
                    t.real("a real tag")?;
                }
                let ni = t.count("the number of integer tags", total, 1)?;
                let ints: Vec<i64> = (0..ni).map(|_| t.num("an integer tag")).collect::<Result<_, _>>()?;
                let comps = usize::try_from(*ints.get(1).unwrap_or(&1))
                    .ok()
                    .filter(|&c| (1..=9).contains(&c))
                    .ok_or_else(|| t.err("the number of components is not 1 to 9".into()))?;
                let count = usize::try_from(*ints.get(2).unwrap_or(&0))
                    .ok()
                    .filter(|&c| c.saturating_mul(comps + 1) <= total / 2 + 1)
                    .ok_or_else(|| t.err("the number of values cannot be held by the file".into()))?;
                let label = strings.first().cloned().unwrap_or_else(|| "data".into());
                let line = t.line;
                let mut arrays: Vec<Vec<(u64, f64)>> = vec![Vec::with_capacity(count); comps];
                for _ in 0..count {
                    let tag: u64 = t.num("a node or element tag")?;
                    for a in arrays.iter_mut() {
                        a.push((tag, t.num("a value")?));
                    }
                }
                for (c, a) in arrays.into_iter().enumerate() {
                    let n = if nodes { node_tags.len() } else { mesh.cells.len() };
                    let mut values = vec![None; n];
                    for (tag, v) in a {
                        let at = if nodes {
                            node_index.get(&tag).map(|&i| i as usize)
                        } else {
                            element_index.get(&tag).copied()
                        };
                        let at = at.ok_or_else(|| ImportError::Syntax {
                            line,
                            message: format!(
                                "{name} '{}': no {} with tag {tag}",
                                shorten(label.as_bytes(), 40),
                                if nodes { "node" } else { "element" }
                            ),
                        })?;
                        values[at] = v.is_finite().then_some(LabelValue::Real(v));
                    }
                    let name = if comps == 1 { label.clone() } else { format!("{label}.{c}") };
                    if nodes {
                        node_data.push(DataArray { name, values });
                    } else {
                        element_data.push((DataArray { name, values }, line));
                    }
                }
                t.skip_section(name)?;
            }
            other => t.skip_section(other)?,
        }
    }
    if !seen_format {
        return Err(ImportError::MissingSection { section: "$MeshFormat".into(), empty: false });
    }
    for (seen, section) in [(seen_nodes, "$Nodes"), (seen_elements, "$Elements")] {
        if !seen {
            return Err(ImportError::MissingSection { section: section.into(), empty: false });
        }
    }
    if mesh.cells.is_empty() {
        return Err(ImportError::MissingSection { section: "$Elements".into(), empty: true });
    }
    // tags as labels
    let n = mesh.cells.len();
    let mut geometrical = Vec::with_capacity(n);
    let mut physical: Vec<DataArray> = Vec::new();
    let mut physical_name = Vec::with_capacity(n);
    for (c, &(dim, tag)) in entity_of.iter().enumerate() {
        geometrical.push(Some(LabelValue::Int(tag)));
        let tags = physicals.get(&(dim, tag)).map(Vec::as_slice).unwrap_or(&[]);
        for (k, &p) in tags.iter().enumerate() {
            if physical.len() <= k {
                let name = if k == 0 { "gmsh:physical".to_string() } else { format!("gmsh:physical.{k}") };
                physical.push(DataArray { name, values: vec![None; n] });
            }
            physical[k].values[c] = Some(LabelValue::Int(p));
        }
        physical_name.push(tags.first().and_then(|&p| names.get(&(dim, p))).map(|s| LabelValue::Text(s.clone())));
    }
    mesh.cell_data.extend(physical);
    if physical_name.iter().any(Option::is_some) {
        mesh.cell_data.push(DataArray { name: "gmsh:physical_name".into(), values: physical_name });
    }
    mesh.cell_data.push(DataArray { name: "gmsh:geometrical".into(), values: geometrical });
    // data given before the elements were read are checked here
    for (mut a, line) in element_data {
        if a.values.len() != n {
            return Err(ImportError::Syntax {
                line,
                message: format!("$ElementData '{}' comes before $Elements", shorten(a.name.as_bytes(), 40)),
            });
        }
        a.values.truncate(n);
        mesh.cell_data.push(a);
    }
    for a in &node_data {
        if a.values.len() != mesh.points.len() {
            return Err(ImportError::Format(format!(
                "$NodeData '{}' comes before $Nodes",
                shorten(a.name.as_bytes(), 40)
            )));
        }
    }
    mesh.point_data = node_data;
    Ok(MshFile { mesh, node_tags, element_tags })
}

impl MshFile {
    /// The map of the mesh ([`Mesh::to_gmap`]), its errors naming elements and nodes by
    /// their tags.
    pub fn to_gmap(&self, max_darts: u64) -> Result<LabelledGMap, MeshError> {
        self.mesh.to_gmap(max_darts).map_err(|e| {
            e.renumber(|k| self.element_tags.get(k).map_or(k, |&t| t as usize))
                .renumber_vertices(|v| self.node_tags.get(v as usize).copied().unwrap_or(v))
        })
    }
}

/// Reads a Gmsh 4.1 ASCII `.msh` file into a labelled map (see the module documentation
/// and [`crate::mesh`]), refusing more than `max_darts` darts (default:
/// [`default_max_darts`]`(3)`).
pub fn read_msh(path: &Path, max_darts: Option<u64>) -> Result<LabelledGMap, FileError> {
    let text = super::common::read_text(path)?;
    let file = parse_msh(&text).map_err(|e| FileError::new(path, e))?;
    file.to_gmap(max_darts.unwrap_or_else(|| default_max_darts(3))).map_err(|e| FileError::new(path, e.into()))
}
