//! Gmsh meshes (`.msh`, formats 2.2 and 4.1, ASCII or binary of either byte order) into a
//! [`Mesh`] and then a labelled map ([`crate::mesh`]).
//!
//! Read: `$MeshFormat` (2.2 or 4.1; binary with data size 8, its byte order given by the
//! binary `1` after the header), `$PhysicalNames`, `$Entities` (4.1: the physical tags of
//! each entity), `$Nodes`, `$Elements` of every Gmsh type with corners — lines, triangles,
//! quadrangles, tetrahedra, hexahedra, prisms and pyramids of any order, and points (the
//! higher-order ones as their corner cells, their other nodes in the label
//! [`HIGH_ORDER_LABEL`](super::high_order::HIGH_ORDER_LABEL), see [`super::high_order`]) —
//! and `$NodeData` / `$ElementData` (their values become labels named by the data's first
//! string tag). Other sections are read past; other versions, data sizes and element types
//! without corners are refused by name.
//!
//! Each element is labelled `gmsh:geometrical` (its entity's tag) and, when it has physical
//! tags (4.1: its entity's; 2.2: its first tag when not 0), `gmsh:physical` (the first; more
//! are `gmsh:physical.1`, …) and `gmsh:physical_name` (the name of the first in
//! `$PhysicalNames`), the names meshio uses. An element block whose entity `$Entities` does
//! not list is refused (its physical groups would be lost). Elements of lower dimension
//! (boundary triangles of a tetrahedral mesh, physical curves and points) must be faces,
//! edges or vertices of the top elements, whose labels they set. A file without `$Nodes` or
//! `$Elements`, or without an element, is refused naming the section.
//!
//! Errors name the file and the line; errors about cells name them by their element tags,
//! and vertices by their node tags. O(size of the file) plus [`Mesh::to_gmap`].

use std::path::Path;

use gmap_core::io::shorten;
use gmap_core::{LabelValue, LabelledGMap, Point};
use rustc_hash::FxHashMap;

use super::high_order::{gmsh_type, label_array, to_corners};
use super::{default_max_darts, FileError, ImportError};
use crate::mesh::{DataArray, Mesh, MeshCell, MeshError};

/// The file read token by token (ASCII) or value by value (binary sections), with the
/// byte order of a binary file.
struct Input<'a> {
    b: &'a [u8],
    pos: usize,
    binary: bool,
    big: bool,
}

impl<'a> Input<'a> {
    fn new(b: &'a [u8]) -> Self {
        Input { b, pos: 0, binary: false, big: false }
    }

    /// The line of the current position (counted when an error needs it).
    fn line(&self) -> usize {
        1 + self.b[..self.pos.min(self.b.len())].iter().filter(|&&c| c == b'\n').count()
    }

    fn err(&self, m: String) -> ImportError {
        ImportError::Syntax { line: self.line(), message: m }
    }

    /// The next whitespace-separated token.
    fn next(&mut self) -> Option<&'a [u8]> {
        while self.b.get(self.pos).is_some_and(u8::is_ascii_whitespace) {
            self.pos += 1;
        }
        let start = self.pos;
        while self.b.get(self.pos).is_some_and(|c| !c.is_ascii_whitespace()) {
            self.pos += 1;
        }
        (self.pos > start).then(|| &self.b[start..self.pos])
    }

    fn expect(&mut self, what: &str) -> Result<&'a [u8], ImportError> {
        self.next().ok_or_else(|| self.err(format!("the file ends before {what}")))
    }

    /// A number written as text.
    fn num<T: std::str::FromStr>(&mut self, what: &str) -> Result<T, ImportError> {
        let t = self.expect(what)?;
        std::str::from_utf8(t)
            .ok()
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| self.err(format!("{what} '{}' is not a valid number", shorten(t, 40))))
    }

    /// `n` raw bytes of a binary section.
    fn raw<const N: usize>(&mut self, what: &str) -> Result<[u8; N], ImportError> {
        let b = self.b.get(self.pos..self.pos + N).ok_or_else(|| self.err(format!("the file ends before {what}")))?;
        self.pos += N;
        let mut a = [0u8; N];
        a.copy_from_slice(b);
        if self.big {
            a.reverse();
        }
        Ok(a)
    }

    /// An `int` (4 bytes in a binary section).
    fn int(&mut self, what: &str) -> Result<i64, ImportError> {
        if self.binary {
            Ok(i32::from_le_bytes(self.raw(what)?) as i64)
        } else {
            self.num(what)
        }
    }

    /// A `size_t` (8 bytes in a binary section: data size 8).
    fn size(&mut self, what: &str) -> Result<u64, ImportError> {
        if self.binary {
            Ok(u64::from_le_bytes(self.raw(what)?))
        } else {
            self.num(what)
        }
    }

    /// A `double`, any value.
    fn double(&mut self, what: &str) -> Result<f64, ImportError> {
        if self.binary {
            Ok(f64::from_le_bytes(self.raw(what)?))
        } else {
            self.num(what)
        }
    }

    /// A finite `double`.
    fn real(&mut self, what: &str) -> Result<f64, ImportError> {
        let v = self.double(what)?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(format!("{what} is not finite")))
        }
    }

    /// A count (`size_t`, or an ASCII number with `ascii`), refused when the rest of the
    /// file cannot hold `per` bytes for each (binary), or a token for each (ASCII).
    fn count(&mut self, what: &str, per: usize, ascii: bool) -> Result<usize, ImportError> {
        let n = if ascii { self.num::<u64>(what)? } else { self.size(what)? };
        let left = self.b.len() - self.pos.min(self.b.len());
        let each = if self.binary { per.max(1) } else { 2 };
        usize::try_from(n)
            .ok()
            .filter(|n| n.saturating_mul(each) <= left + 2)
            .ok_or_else(|| self.err(format!("{what} {n}: the rest of the file cannot hold them")))
    }

    /// Expects `$End<name>`, ending a section read in full.
    fn end(&mut self, name: &str) -> Result<(), ImportError> {
        let end = format!("$End{name}");
        match self.next() {
            Some(t) if t == end.as_bytes() => Ok(()),
            Some(t) => Err(self.err(format!("expected {end}, found '{}'", shorten(t, 40)))),
            None => Err(self.err(format!("the file ends before {end}"))),
        }
    }

    /// Skips to after `$End<name>` (a section not read).
    fn skip_section(&mut self, name: &str) -> Result<(), ImportError> {
        let end = format!("$End{name}");
        let rest = &self.b[self.pos..];
        match rest.windows(end.len()).position(|w| w == end.as_bytes()) {
            Some(at) => {
                self.pos += at + end.len();
                Ok(())
            }
            None => Err(self.err(format!("no {end}"))),
        }
    }
}

/// A quoted string token sequence: `"a b"` may span several tokens.
fn quoted(t: &mut Input, what: &str) -> Result<String, ImportError> {
    let first = String::from_utf8_lossy(t.expect(what)?).into_owned();
    if !first.starts_with('"') {
        return Ok(first);
    }
    let mut s = first;
    while !(s.len() >= 2 && s.ends_with('"')) {
        let more = t.expect(what)?;
        s.push(' ');
        s.push_str(&String::from_utf8_lossy(more));
    }
    Ok(s[1..s.len() - 1].to_string())
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

/// What the sections read so far hold.
#[derive(Default)]
struct State {
    /// 2 or 4: the major version
    version: u8,
    names: FxHashMap<(i64, i64), String>,
    physicals: FxHashMap<(i64, i64), Vec<i64>>,
    node_index: FxHashMap<u64, u32>,
    mesh: Mesh,
    node_tags: Vec<u64>,
    element_tags: Vec<u64>,
    element_index: FxHashMap<u64, usize>,
    /// the (dimension, entity) of each element
    entity_of: Vec<(i64, i64)>,
    /// the physical tag of each element of a version 2 file (0: none)
    physical_of: Vec<i64>,
    high_order: Vec<Option<LabelValue>>,
    node_data: Vec<DataArray>,
    element_data: Vec<(DataArray, usize)>,
    seen: Vec<&'static str>,
}

/// Parses a Gmsh mesh, version 2.2 or 4.1, ASCII or binary (see the module documentation).
pub fn parse_msh(bytes: &[u8]) -> Result<MshFile, ImportError> {
    let mut t = Input::new(bytes);
    let mut st = State::default();
    while let Some(head) = t.next() {
        let Some(name) = head.strip_prefix(b"$") else {
            return Err(t.err(format!("expected a section ($MeshFormat, $Nodes…), found '{}'", shorten(head, 40))));
        };
        let name = String::from_utf8_lossy(name).into_owned();
        if t.binary && t.b.get(t.pos) == Some(&b'\n') {
            t.pos += 1; // a binary section starts on the next line
        }
        if st.version == 0 && name != "MeshFormat" {
            return Err(t.err("the file does not start with $MeshFormat".into()));
        }
        match name.as_str() {
            "MeshFormat" => mesh_format(&mut t, &mut st)?,
            "PhysicalNames" => physical_names(&mut t, &mut st)?,
            "Entities" if st.version == 4 => entities(&mut t, &mut st)?,
            "Nodes" if st.version == 4 => nodes4(&mut t, &mut st)?,
            "Nodes" => nodes2(&mut t, &mut st)?,
            "Elements" if st.version == 4 => elements4(&mut t, &mut st)?,
            "Elements" => elements2(&mut t, &mut st)?,
            "NodeData" | "ElementData" => data(&mut t, &mut st, name == "NodeData")?,
            other => {
                t.skip_section(other)?;
                continue;
            }
        }
        t.end(&name)?;
    }
    finish(st)
}

fn mesh_format(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let v = t.expect("the version")?;
    st.version = match v {
        b"4.1" => 4,
        b"2.2" => 2,
        _ => return Err(t.err(format!("version {} is not read: only 2.2 and 4.1", shorten(v, 20)))),
    };
    let ft: i64 = t.num("the file type")?;
    let size: i64 = t.num("the data size")?;
    match ft {
        0 => {}
        1 => {
            if size != 8 {
                return Err(t.err(format!("binary .msh of data size {size} is not read: only 8")));
            }
            // the line ends, then the binary int 1 gives the byte order
            while t.b.get(t.pos).is_some_and(|&c| c != b'\n') {
                t.pos += 1;
            }
            t.pos += 1;
            let one: [u8; 4] = t.raw("the binary one")?;
            t.big = match (i32::from_le_bytes(one), i32::from_be_bytes(one)) {
                (1, _) => false,
                (_, 1) => true,
                _ => return Err(t.err("the binary one after the file type is not 1 in either byte order".into())),
            };
            t.binary = true;
        }
        _ => return Err(t.err(format!("file type {ft} is not read: 0 (ASCII) or 1 (binary)"))),
    }
    st.seen.push("$MeshFormat");
    Ok(())
}

/// `$PhysicalNames`: text in binary files too.
fn physical_names(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let binary = std::mem::replace(&mut t.binary, false);
    let n = t.count("the number of names", 3, true)?;
    for _ in 0..n {
        let dim: i64 = t.num("a dimension")?;
        let tag: i64 = t.num("a physical tag")?;
        st.names.insert((dim, tag), quoted(t, "a name")?);
    }
    t.binary = binary;
    Ok(())
}

fn entities(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let counts: Vec<usize> = (0..4).map(|_| t.count("a number of entities", 16, false)).collect::<Result<_, _>>()?;
    for (dim, &n) in counts.iter().enumerate() {
        for _ in 0..n {
            let tag = t.int("an entity tag")?;
            for _ in 0..if dim == 0 { 3 } else { 6 } {
                t.double("a coordinate")?;
            }
            let np = t.count("a number of physical tags", 4, false)?;
            let tags: Vec<i64> = (0..np).map(|_| t.int("a physical tag")).collect::<Result<_, _>>()?;
            st.physicals.insert((dim as i64, tag), tags);
            if dim > 0 {
                let nb = t.count("a number of bounding entities", 4, false)?;
                for _ in 0..nb {
                    t.int("a bounding entity")?;
                }
            }
        }
    }
    st.seen.push("$Entities");
    Ok(())
}

impl State {
    fn add_node(&mut self, t: &Input, tag: u64) -> Result<(), ImportError> {
        let index = u32::try_from(self.node_tags.len())
            .ok()
            .filter(|&i| i != u32::MAX)
            .ok_or_else(|| t.err("too many nodes".into()))?;
        if self.node_index.insert(tag, index).is_some() {
            return Err(t.err(format!("node tag {tag} appears twice")));
        }
        self.node_tags.push(tag);
        Ok(())
    }

    /// Adds an element of Gmsh type `ty` on the node tags `nodes`.
    fn add_element(
        &mut self,
        t: &Input,
        et: u64,
        ty: i64,
        nodes: &[u64],
        entity: (i64, i64),
    ) -> Result<(), ImportError> {
        let (kind, _) = gmsh_type(ty).map_err(|m| t.err(m))?;
        let nodes: Vec<u32> = nodes
            .iter()
            .map(|nt| {
                self.node_index.get(nt).copied().ok_or_else(|| t.err(format!("element {et}: no node with tag {nt}")))
            })
            .collect::<Result<_, _>>()?;
        if self.element_index.insert(et, self.mesh.cells.len()).is_some() {
            return Err(t.err(format!("element tag {et} appears twice")));
        }
        let mut cell = MeshCell { kind, nodes, faces: Vec::new() };
        let extra = if cell.nodes.len() > kind.points().unwrap_or(usize::MAX) {
            Some(to_corners(&mut cell, &self.mesh.points).map_err(|m| t.err(format!("element {et}: {m}")))?)
        } else {
            None
        };
        self.high_order.push(extra);
        self.element_tags.push(et);
        self.entity_of.push(entity);
        self.mesh.cells.push(cell);
        Ok(())
    }
}

fn nodes4(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let blocks = t.count("the number of entity blocks", 16, false)?;
    let n = t.count("the number of nodes", 16, false)?;
    let _min = t.size("the smallest node tag")?;
    let _max = t.size("the largest node tag")?;
    st.mesh.points.reserve(n);
    for _ in 0..blocks {
        let dim = t.int("an entity dimension")?;
        let _tag = t.int("an entity tag")?;
        let param = t.int("the parametric flag")?;
        let k = t.count("a number of nodes", 16, false)?;
        let start = st.node_tags.len();
        for _ in 0..k {
            let tag = t.size("a node tag")?;
            st.add_node(t, tag)?;
        }
        for _ in start..st.node_tags.len() {
            let p: Point = [t.real("x")?, t.real("y")?, t.real("z")?];
            if param == 1 {
                for _ in 0..dim.clamp(0, 3) {
                    t.double("a parametric coordinate")?;
                }
            }
            st.mesh.points.push(p);
        }
    }
    st.seen.push("$Nodes");
    Ok(())
}

/// `$Nodes` of version 2.2: the count as text, then `tag x y z` (binary: int, 3 doubles).
fn nodes2(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let n = t.count("the number of nodes", 28, true)?;
    if t.binary {
        t.pos += 1; // the end of the count's line
    }
    st.mesh.points.reserve(n);
    for _ in 0..n {
        let tag = t.int("a node tag")?;
        let tag = u64::try_from(tag).map_err(|_| t.err(format!("node tag {tag} is negative")))?;
        st.add_node(t, tag)?;
        st.mesh.points.push([t.real("x")?, t.real("y")?, t.real("z")?]);
    }
    st.seen.push("$Nodes");
    Ok(())
}

fn elements4(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let entities = st.seen.contains(&"$Entities");
    let blocks = t.count("the number of entity blocks", 16, false)?;
    let _n = t.count("the number of elements", 16, false)?;
    let _min = t.size("the smallest element tag")?;
    let _max = t.size("the largest element tag")?;
    let mut nodes: Vec<u64> = Vec::new();
    for _ in 0..blocks {
        let dim = t.int("an entity dimension")?;
        let tag = t.int("an entity tag")?;
        let ty = t.int("an element type")?;
        let (kind, per) = gmsh_type(ty).map_err(|m| t.err(m))?;
        if kind.dim() as i64 != dim {
            return Err(t.err(format!("element type {ty} has dimension {}, its entity {dim}", kind.dim())));
        }
        if entities && !st.physicals.contains_key(&(dim, tag)) {
            return Err(t.err(format!(
                "an element block of entity {tag} (dimension {dim}), which $Entities does not list: its physical groups are unknown"
            )));
        }
        let k = t.count("a number of elements", 8 * (per + 1), false)?;
        for _ in 0..k {
            let et = t.size("an element tag")?;
            nodes.clear();
            for _ in 0..per {
                nodes.push(t.size("a node tag")?);
            }
            st.add_element(t, et, ty, &nodes, (dim, tag))?;
        }
    }
    st.seen.push("$Elements");
    Ok(())
}

/// `$Elements` of version 2.2: ASCII `tag type ntags tags… nodes…`; binary blocks of a
/// header (type, count, ntags) and `count` elements of ints. The first tag is the physical
/// group (0: none), the second the elementary entity.
fn elements2(t: &mut Input, st: &mut State) -> Result<(), ImportError> {
    let n = t.count("the number of elements", 12, true)?;
    if t.binary {
        t.pos += 1;
    }
    let mut nodes: Vec<u64> = Vec::new();
    let mut read = 0usize;
    while read < n {
        let (ty, k, ntags) = if t.binary {
            (t.int("an element type")?, t.int("a number of elements")?, t.int("a number of tags")?)
        } else {
            (-1, 1, 0)
        };
        let k = usize::try_from(k)
            .ok()
            .filter(|&k| k >= 1 && k <= n - read)
            .ok_or_else(|| t.err(format!("an element block of {k} elements, {} left to read", n - read)))?;
        for _ in 0..k {
            let et = t.int("an element tag")?;
            let (ty, ntags) =
                if t.binary { (ty, ntags) } else { (t.int("an element type")?, t.int("a number of tags")?) };
            let ntags = usize::try_from(ntags)
                .ok()
                .filter(|&x| x <= 64)
                .ok_or_else(|| t.err(format!("element {et}: {ntags} tags")))?;
            let tags: Vec<i64> = (0..ntags).map(|_| t.int("a tag")).collect::<Result<_, _>>()?;
            let (kind, per) = gmsh_type(ty).map_err(|m| t.err(m))?;
            nodes.clear();
            for _ in 0..per {
                let v = t.int("a node tag")?;
                nodes.push(u64::try_from(v).map_err(|_| t.err(format!("element {et}: node tag {v} is negative")))?);
            }
            let et = u64::try_from(et).map_err(|_| t.err(format!("element tag {et} is negative")))?;
            let entity = (kind.dim() as i64, tags.get(1).copied().unwrap_or(0));
            st.add_element(t, et, ty, &nodes, entity)?;
            st.physical_of.push(tags.first().copied().unwrap_or(0));
        }
        read += k;
    }
    st.seen.push("$Elements");
    Ok(())
}

/// `$NodeData` or `$ElementData`: the tags as text, then `tag values…` (binary: an int and
/// doubles).
fn data(t: &mut Input, st: &mut State, nodes: bool) -> Result<(), ImportError> {
    let name = if nodes { "$NodeData" } else { "$ElementData" };
    let binary = std::mem::replace(&mut t.binary, false);
    let ns = t.count("the number of string tags", 1, true)?;
    let strings: Vec<String> = (0..ns).map(|_| quoted(t, "a string tag")).collect::<Result<_, _>>()?;
    let nr = t.count("the number of real tags", 1, true)?;
    for _ in 0..nr {
        t.real("a real tag")?;
    }
    let ni = t.count("the number of integer tags", 1, true)?;
    let ints: Vec<i64> = (0..ni).map(|_| t.num("an integer tag")).collect::<Result<_, _>>()?;
    let comps = usize::try_from(*ints.get(1).unwrap_or(&1))
        .ok()
        .filter(|&c| (1..=9).contains(&c))
        .ok_or_else(|| t.err("the number of components is not 1 to 9".into()))?;
    let count = usize::try_from(*ints.get(2).unwrap_or(&0))
        .ok()
        .filter(|&c| c.saturating_mul(comps + 1) <= t.b.len().saturating_sub(t.pos) / 2 + 1)
        .ok_or_else(|| t.err("the number of values cannot be held by the file".into()))?;
    if binary {
        t.pos += 1;
        t.binary = true;
    }
    let label = strings.first().cloned().unwrap_or_else(|| "data".into());
    let line = t.line();
    let mut arrays: Vec<Vec<(u64, f64)>> = vec![Vec::with_capacity(count); comps];
    for _ in 0..count {
        let tag = t.int("a node or element tag")?;
        let tag = u64::try_from(tag).map_err(|_| t.err(format!("tag {tag} is negative")))?;
        for a in arrays.iter_mut() {
            a.push((tag, t.double("a value")?));
        }
    }
    for (c, a) in arrays.into_iter().enumerate() {
        let n = if nodes { st.node_tags.len() } else { st.mesh.cells.len() };
        let mut values = vec![None; n];
        for (tag, v) in a {
            let at =
                if nodes { st.node_index.get(&tag).map(|&i| i as usize) } else { st.element_index.get(&tag).copied() };
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
            st.node_data.push(DataArray { name, values });
        } else {
            st.element_data.push((DataArray { name, values }, line));
        }
    }
    Ok(())
}

/// Checks that the sections a mesh needs were met, and makes the labels.
fn finish(st: State) -> Result<MshFile, ImportError> {
    let State {
        version,
        names,
        physicals,
        mut mesh,
        node_tags,
        element_tags,
        entity_of,
        physical_of,
        high_order,
        node_data,
        element_data,
        seen,
        ..
    } = st;
    for section in ["$MeshFormat", "$Nodes", "$Elements"] {
        if !seen.contains(&section) {
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
        let own;
        let tags = if version == 2 {
            own = [physical_of[c]];
            if own[0] == 0 {
                &[][..]
            } else {
                &own[..]
            }
        } else {
            physicals.get(&(dim, tag)).map(Vec::as_slice).unwrap_or(&[])
        };
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
    mesh.cell_data.extend(label_array(high_order));
    // data given before the elements were read are checked here
    for (a, line) in element_data {
        if a.values.len() != n {
            return Err(ImportError::Syntax {
                line,
                message: format!("$ElementData '{}' comes before $Elements", shorten(a.name.as_bytes(), 40)),
            });
        }
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
    let bytes = super::common::read_bytes(path)?;
    let file = parse_msh(&bytes).map_err(|e| FileError::new(path, e))?;
    file.to_gmap(max_darts.unwrap_or_else(|| default_max_darts(3))).map_err(|e| FileError::new(path, e.into()))
}
