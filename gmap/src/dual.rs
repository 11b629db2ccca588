//! Room graphs (`gmap graph FILE --dual faces|apertures|exterior`, Python's
//! `gmap.room_graph`): the dual graphs of TopologicPy's `Graph.ByTopology` on the rooms —
//! the top regions — of an architectural complex (or of the incidence graph of any other
//! input: a 3-map's volumes, a simplicial complex's facets).
//!
//! * [`Dual::Faces`] (TopologicPy's `direct`): two rooms are joined when they share a face
//!   (a region one dimension down on both);
//! * [`Dual::Apertures`] (`viaSharedApertures`): when they share a face whose `kind` label
//!   is an aperture — `door`, `window`, `aperture` or `opening`, any case;
//! * [`Dual::Exterior`] (`toExteriorTopologies`): each room to one node standing for the
//!   exterior, through its faces on no other room.
//!
//! Nodes are named as the file names them (its string ids, else the numbers, with the
//! `name` label); each edge lists its faces by id and name and, when every one of them has
//! points, their total area (half the norm of each face's vector area, holes subtracted).
//! Written as GraphML (undirected, for networkx, Gephi, yEd), DOT or JSON.
//!
//! O(R + E) after the incidence graph, plus the faces' boundaries for the areas.

use std::fmt::Write as _;

use gmap_core::{LabelValue, Labels};
use gmap_homology::arch::ArchComplex;
use gmap_homology::complex::{dot::quote, graphml::escape};

use crate::error::{err, Result};
use crate::input::Input;

/// Which rooms a room graph joins (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dual {
    /// rooms sharing a face (TopologicPy's `direct`)
    Faces,
    /// rooms sharing an aperture: a face whose `kind` is a door, window, aperture or opening
    /// (TopologicPy's `viaSharedApertures`)
    Apertures,
    /// each room to the exterior through its faces on no other room (TopologicPy's
    /// `toExteriorTopologies`)
    Exterior,
}

impl Dual {
    /// The name the command line and Python give it: `faces`, `apertures`, `exterior`.
    pub fn name(self) -> &'static str {
        match self {
            Dual::Faces => "faces",
            Dual::Apertures => "apertures",
            Dual::Exterior => "exterior",
        }
    }

    /// The kind named `faces`, `apertures` or `exterior`; another word is refused naming the
    /// three.
    pub fn parse(word: &str) -> Result<Self> {
        match word {
            "faces" => Ok(Dual::Faces),
            "apertures" => Ok(Dual::Apertures),
            "exterior" => Ok(Dual::Exterior),
            w => Err(err!(Usage, "dual graph '{w}': one of faces, apertures, exterior")),
        }
    }
}

/// The `kind` labels of the faces [`Dual::Apertures`] goes through (compared in lower case).
pub const APERTURE_KINDS: [&str; 4] = ["door", "window", "aperture", "opening"];

/// A node of a room graph: a room, or the exterior.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct RoomNode {
    /// the file's id of the room (its string id, else its number); `exterior` (with primes
    /// added if a room already has that id) for the exterior
    pub id: String,
    /// how messages name it: the id, then the `name` label in parentheses when it differs
    pub name: String,
    /// the room's region number (`None` for the exterior)
    pub region: Option<u64>,
    /// the room's labels
    pub labels: Labels,
}

/// An edge of a room graph: two rooms (or a room and the exterior) and the faces joining
/// them.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct RoomEdge {
    /// the node indices, the first below the second
    pub nodes: (usize, usize),
    /// the faces' ids, in region order
    pub faces: Vec<String>,
    /// the faces' names ([`ArchComplex::region_name`])
    pub face_names: Vec<String>,
    /// the faces' `kind` labels, `""` for none
    pub kinds: Vec<String>,
    /// the faces' total area, when every face has points
    pub area: Option<f64>,
}

/// A room graph (module docs).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct RoomGraph {
    /// which rooms it joins
    pub dual: Dual,
    /// the dimension of the rooms
    pub dim: usize,
    /// the rooms in region order, then the exterior for [`Dual::Exterior`]
    pub nodes: Vec<RoomNode>,
    /// the edges, in the order of their first face
    pub edges: Vec<RoomEdge>,
}

/// The room graph of any input with an incidence graph (the one `gmap convert` writes to
/// `.graphml`); `max_cells` bounds a simplicial complex's face poset.
pub fn room_graph(input: &Input, dual: Dual, max_cells: Option<u64>) -> Result<RoomGraph> {
    let x = crate::save::incidence_graph(input, max_cells)?;
    Ok(room_graph_of(&x, dual))
}

/// The file's id of region `index`: its string id, else its number.
fn id_of(x: &ArchComplex, index: usize) -> String {
    x.region_key(index).map_or_else(|| x.region(index).id.to_string(), str::to_string)
}

/// The area of face `f` from the points of its edges' ends: half the norm of its vector
/// area `Σ w_e (p_from × p_to)`; `None` when an edge has not two ends with points.
pub fn face_area(x: &ArchComplex, f: usize) -> Option<f64> {
    let mut a = [0.0f64; 3];
    if x.down(f).is_empty() {
        return None;
    }
    for e in x.down(f) {
        let ends = x.down(e.to);
        let from = ends.iter().find(|d| d.weight < 0)?;
        let to = ends.iter().find(|d| d.weight > 0)?;
        let (p, q) = (x.region_point(from.to)?, x.region_point(to.to)?);
        let c = [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
        for i in 0..3 {
            a[i] += e.weight as f64 * c[i];
        }
    }
    Some(0.5 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt())
}

/// The `kind` label of region `index` in lower case, `""` for none.
fn kind_of(x: &ArchComplex, index: usize) -> String {
    match x.region_labels(index).get("kind") {
        Some(LabelValue::Text(t)) => t.to_lowercase(),
        _ => String::new(),
    }
}

/// The room graph of an architectural complex (module docs).
pub fn room_graph_of(x: &ArchComplex, dual: Dual) -> RoomGraph {
    let top = x.dim();
    let rooms = x.regions_of_dim(top);
    let mut node_of = vec![usize::MAX; x.regions().len()];
    let mut nodes = Vec::with_capacity(rooms.len() + 1);
    for &r in rooms {
        let r = r as usize;
        node_of[r] = nodes.len();
        nodes.push(RoomNode {
            id: id_of(x, r),
            name: x.region_name(r),
            region: Some(x.region(r).id.0),
            labels: x.region_labels(r).clone(),
        });
    }
    let exterior = nodes.len();
    if dual == Dual::Exterior {
        let mut id = "exterior".to_string();
        while nodes.iter().any(|n| n.id == id) {
            id.push('\'');
        }
        nodes.push(RoomNode { id: id.clone(), name: id, region: None, labels: Labels::default() });
    }
    let mut edges: Vec<RoomEdge> = Vec::new();
    let mut edge_of: std::collections::HashMap<(usize, usize), usize> = std::collections::HashMap::new();
    let faces: &[u32] = if top == 0 { &[] } else { x.regions_of_dim(top - 1) };
    for &f in faces {
        let f = f as usize;
        let on: Vec<usize> =
            x.up_of(f).map(|e| e.from).filter(|&r| x.region(r).dim == top).map(|r| node_of[r]).collect();
        let kind = kind_of(x, f);
        let pairs: Vec<(usize, usize)> = match dual {
            Dual::Exterior if on.len() == 1 => vec![(on[0], exterior)],
            Dual::Exterior => vec![],
            Dual::Apertures if !APERTURE_KINDS.contains(&kind.as_str()) => vec![],
            Dual::Faces | Dual::Apertures => {
                let mut v = Vec::new();
                for (i, &a) in on.iter().enumerate() {
                    for &b in &on[i + 1..] {
                        if a != b {
                            v.push((a.min(b), a.max(b)));
                        }
                    }
                }
                v
            }
        };
        let area = face_area(x, f);
        for pair in pairs {
            let k = *edge_of.entry(pair).or_insert_with(|| {
                edges.push(RoomEdge {
                    nodes: pair,
                    faces: Vec::new(),
                    face_names: Vec::new(),
                    kinds: Vec::new(),
                    area: Some(0.0),
                });
                edges.len() - 1
            });
            let e = &mut edges[k];
            e.faces.push(id_of(x, f));
            e.face_names.push(x.region_name(f));
            e.kinds.push(kind.clone());
            e.area = match (e.area, area) {
                (Some(s), Some(a)) => Some(s + a),
                _ => None,
            };
        }
    }
    RoomGraph { dual, dim: top, nodes, edges }
}

/// A label's value as text (numbers in their `.gmap` text form).
fn label_text(v: &LabelValue) -> String {
    match v {
        LabelValue::Text(t) => t.clone(),
        v => v.to_string(),
    }
}

impl RoomGraph {
    /// The GraphML node id of node `k`: `r<region number>`, `exterior` for the exterior (XML
    /// name tokens; the file's id is the node's `id` data).
    fn xml_id(&self, k: usize) -> String {
        match self.nodes[k].region {
            Some(r) => format!("r{r}"),
            None => "exterior".to_string(),
        }
    }

    /// GraphML, undirected: each node with `id` (the file's id), `name` and its labels as
    /// string data; each edge with `faces` and `face_names` (joined by `; `), `count` (the
    /// number of faces) and `area` when known.
    pub fn to_graphml(&self) -> String {
        let mut keys: Vec<String> = Vec::new();
        for n in &self.nodes {
            for (name, _) in n.labels.iter() {
                if name != "name" && name != "id" && !keys.iter().any(|k| k == name) {
                    keys.push(name.to_string());
                }
            }
        }
        let mut s = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        s.push_str("<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\">\n");
        s.push_str("  <key id=\"id\" for=\"node\" attr.name=\"id\" attr.type=\"string\"/>\n");
        s.push_str("  <key id=\"name\" for=\"node\" attr.name=\"name\" attr.type=\"string\"/>\n");
        for (k, name) in keys.iter().enumerate() {
            let _ = write!(s, "  <key id=\"l{k}\" for=\"node\" attr.name=\"");
            escape(&mut s, name);
            s.push_str("\" attr.type=\"string\"/>\n");
        }
        s.push_str("  <key id=\"faces\" for=\"edge\" attr.name=\"faces\" attr.type=\"string\"/>\n");
        s.push_str("  <key id=\"face_names\" for=\"edge\" attr.name=\"face_names\" attr.type=\"string\"/>\n");
        s.push_str("  <key id=\"count\" for=\"edge\" attr.name=\"count\" attr.type=\"int\"/>\n");
        s.push_str("  <key id=\"area\" for=\"edge\" attr.name=\"area\" attr.type=\"double\"/>\n");
        let _ = writeln!(s, "  <graph id=\"{}\" edgedefault=\"undirected\">", self.dual.name());
        for (k, n) in self.nodes.iter().enumerate() {
            let _ = write!(s, "    <node id=\"{}\"><data key=\"id\">", self.xml_id(k));
            escape(&mut s, &n.id);
            s.push_str("</data><data key=\"name\">");
            escape(&mut s, &n.name);
            s.push_str("</data>");
            for (name, v) in n.labels.iter() {
                if let Some(i) = keys.iter().position(|k| k == name) {
                    let _ = write!(s, "<data key=\"l{i}\">");
                    escape(&mut s, &label_text(v));
                    s.push_str("</data>");
                }
            }
            s.push_str("</node>\n");
        }
        for e in &self.edges {
            let _ = write!(
                s,
                "    <edge source=\"{}\" target=\"{}\"><data key=\"faces\">",
                self.xml_id(e.nodes.0),
                self.xml_id(e.nodes.1)
            );
            escape(&mut s, &e.faces.join("; "));
            s.push_str("</data><data key=\"face_names\">");
            escape(&mut s, &e.face_names.join("; "));
            let _ = write!(s, "</data><data key=\"count\">{}</data>", e.faces.len());
            if let Some(a) = e.area {
                let _ = write!(s, "<data key=\"area\">{a:?}</data>");
            }
            s.push_str("</edge>\n");
        }
        s.push_str("  </graph>\n</graphml>\n");
        s
    }

    /// DOT (`graph`, undirected): nodes by the file's ids, labelled by their names; edges
    /// labelled by their faces' names and area, carrying `faces` and `area`.
    pub fn to_dot(&self) -> String {
        let mut s = format!("graph {} {{\n", self.dual.name());
        for n in &self.nodes {
            s.push_str("  ");
            quote(&mut s, &n.id);
            s.push_str(" [label=");
            quote(&mut s, &n.name);
            for (name, v) in n.labels.iter().filter(|(k, _)| *k != "name") {
                s.push_str(", ");
                quote(&mut s, name);
                s.push('=');
                quote(&mut s, &label_text(v));
            }
            s.push_str("];\n");
        }
        for e in &self.edges {
            s.push_str("  ");
            quote(&mut s, &self.nodes[e.nodes.0].id);
            s.push_str(" -- ");
            quote(&mut s, &self.nodes[e.nodes.1].id);
            let label = match e.area {
                Some(a) => format!("{}\n{a}", e.face_names.join(", ")),
                None => e.face_names.join(", "),
            };
            s.push_str(" [label=");
            quote(&mut s, &label);
            s.push_str(", \"faces\"=");
            quote(&mut s, &e.faces.join("; "));
            if let Some(a) = e.area {
                let _ = write!(s, ", \"area\"=\"{a}\"");
            }
            s.push_str("];\n");
        }
        s.push_str("}\n");
        s
    }

    /// JSON: `{"dual", "dim", "nodes": [{"id", "name", "region", "labels"}], "edges":
    /// [{"source", "target", "faces", "face_names", "kinds", "area"}]}` with `source` and
    /// `target` the nodes' ids; `region` and `area` are null when absent.
    pub fn to_json(&self) -> String {
        use serde_json::{json, Map, Value};
        let label = |v: &LabelValue| match v {
            LabelValue::Int(i) => json!(i),
            LabelValue::Real(f) => json!(f),
            LabelValue::Text(t) => json!(t),
        };
        let nodes: Vec<Value> = self
            .nodes
            .iter()
            .map(|n| {
                let labels: Map<String, Value> = n.labels.iter().map(|(k, v)| (k.to_string(), label(v))).collect();
                json!({"id": n.id, "name": n.name, "region": n.region, "labels": labels})
            })
            .collect();
        let edges: Vec<Value> = self
            .edges
            .iter()
            .map(|e| {
                json!({
                    "source": self.nodes[e.nodes.0].id,
                    "target": self.nodes[e.nodes.1].id,
                    "faces": e.faces,
                    "face_names": e.face_names,
                    "kinds": e.kinds,
                    "area": e.area,
                })
            })
            .collect();
        json!({"dual": self.dual.name(), "dim": self.dim, "nodes": nodes, "edges": edges}).to_string()
    }

    /// The text of the graph in the format of `output`'s extension: `.graphml`, `.dot` or
    /// `.json`; another extension is refused naming the three.
    pub fn to_format(&self, output: &std::path::Path) -> Result<String> {
        match crate::input::extension(output).as_str() {
            "graphml" => Ok(self.to_graphml()),
            "dot" | "gv" => Ok(self.to_dot()),
            "json" => Ok(self.to_json()),
            e => Err(err!(
                Unsupported,
                "{}: a room graph is written as .graphml, .dot or .json, not '.{e}'",
                output.display()
            )
            .with_path(output)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_rooms() -> ArchComplex {
        // two rooms (3, 4) sharing the face 2, each with a face (0, 1) of its own
        let x = ArchComplex::try_from_ids(
            3,
            &[(0, 2), (1, 2), (2, 2), (3, 3), (4, 3)],
            &[(3, 0, 0), (3, 2, 0), (4, 1, 0), (4, 2, 0)],
        )
        .unwrap();
        let door: Labels = [("kind", LabelValue::Text("Door".into()))].into_iter().collect();
        x.with_region_labels(gmap_homology::arch::RegionId(2), door).unwrap()
    }

    #[test]
    fn the_three_duals_of_two_rooms_and_a_door() {
        let x = two_rooms();
        let g = room_graph_of(&x, Dual::Faces);
        assert_eq!(g.nodes.iter().map(|n| n.id.as_str()).collect::<Vec<_>>(), ["3", "4"]);
        assert_eq!(g.edges.len(), 1);
        assert_eq!(
            (g.edges[0].nodes, g.edges[0].faces.clone(), g.edges[0].area),
            ((0, 1), vec!["2".to_string()], None)
        );
        let g = room_graph_of(&x, Dual::Apertures);
        assert_eq!(g.edges.len(), 1);
        assert_eq!(g.edges[0].kinds, ["door"]);
        let g = room_graph_of(&x, Dual::Exterior);
        assert_eq!(g.nodes.last().unwrap().id, "exterior");
        let ends: Vec<_> = g.edges.iter().map(|e| (e.nodes, e.faces.clone())).collect();
        assert_eq!(ends, [((0, 2), vec!["0".to_string()]), ((1, 2), vec!["1".to_string()])]);
        assert!(g.to_graphml().contains("<edge source=\"r3\" target=\"exterior\">"));
        assert!(g.to_dot().contains("  \"4\" -- \"exterior\" [label=\"1\", \"faces\"=\"1\"];\n"), "{}", g.to_dot());
    }

    #[test]
    fn no_door_no_aperture_edge() {
        let x = ArchComplex::try_from_ids(3, &[(0, 2), (3, 3), (4, 3)], &[(3, 0, 0), (4, 0, 0)]).unwrap();
        assert!(room_graph_of(&x, Dual::Apertures).edges.is_empty());
        assert_eq!(room_graph_of(&x, Dual::Faces).edges.len(), 1);
        assert!(Dual::parse("walls").is_err());
    }
}
