//! One self-contained HTML page to look at a map or a cell complex in a browser.
//!
//! A [`Scene`] is what the page draws; [`html_string`] writes it as one HTML file whose
//! script (a small WebGL 2 renderer written for this page, `viewer.js`, no library) and
//! data are inline: nothing is fetched when the page is viewed, and a
//! `Content-Security-Policy` forbids any fetch. It opens from `file://` in Chromium and
//! Firefox.
//!
//! # Scenes
//!
//! * A **map** ([`Scene::from_map`]): the page receives the involutions (`(n + 1)` 32-bit
//!   numbers per dart) and one point per vertex, and computes everything else itself: the
//!   cells of every dimension (union–find over the involutions, numbered by smallest dart
//!   like [`DenseMap::cells`]), the centres of faces and volumes, the exploded darts. The
//!   vertices' points are the map's when every vertex has a finite one; otherwise the
//!   1-skeleton subdivided once (a node per vertex and per edge, so loops and parallel
//!   edges separate) is laid out by [`layout::graph_layout`] and the page draws each edge
//!   through its own node.
//! * A **complex** without darts ([`Scene::complex`], [`Scene::from_cubical`]): points and
//!   cells given by their shapes (a point, a segment, polygons), and links between points
//!   (the entries of an incidence graph). Cubical sets give one cell per cube, placed at its
//!   lattice coordinates; more cubes can be added for generators ([`Scene::add_cube`]).
//!
//! Every scene carries the labels of its cells ([`Scene::set_labels`]) and highlighted
//! chains ([`Scene::add_generator`]: cells of one dimension in the scene's numbering, each
//! generator drawn in its own colour).
//!
//! # The page
//!
//! Three views, switched by buttons: *darts* (each dart a short segment from near its vertex
//! towards its edge's middle, pulled towards the centres of its face and volume; `alpha_i`
//! links drawn as connectors, one colour per i, with a legend; free darts marked), *cells*
//! (faces filled and coloured by a chosen label with a legend, the top cells pushed apart by
//! an "explode" slider), *homology* (each generator in its own colour, with a list to show
//! or hide each). The mouse rotates (left), pans (right or shift-left) and zooms (wheel); a
//! click selects the nearest dart and shows its id, its `alpha_i` images, its i-cell for
//! every i and their labels; keys `0`…`9` (or the buttons) highlight its i-cell. Above
//! [`HtmlOptions::dart_limit`] darts the darts view shows the darts of one top cell in k,
//! and says so. Above dimension 3 the page states its rule (a projection: the points or the
//! layout are 3-D, and darts are pulled towards the centres of their orbits
//! `<alpha_0 … alpha_(k-1)>` for every k up to n).
//!
//! # Size
//!
//! The data travel as base64 (a third more than the bytes): the involutions as one varint
//! per dart and `i`, `alpha_i(d) - d` zigzag-encoded (one byte when `|alpha_i(d) - d| < 64`,
//! as within the cells of built and imported maps; at most five), 12 bytes per vertex
//! (points), and with a layout 12 more per edge; everything else is computed in the
//! browser. The 32³ grid of cubes (1,572,864 darts) makes a page of 11.0 MB, 7.0 bytes per
//! dart; the script and style add about 45 KB to every page.

use std::path::Path;

use base64::Engine as _;
use gmap_core::{AlphaSet, DenseLabels, DenseMap, LabelValue, Labels};
use rustc_hash::FxHashMap;
use serde_json::{json, Value};

use super::{write_atomic, ExportError};
use crate::import::CubicalSet;

pub mod layout;

/// The script of the page.
const VIEWER_JS: &str = include_str!("viewer.js");
/// The style sheet of the page.
const VIEWER_CSS: &str = include_str!("viewer.css");

/// The default [`HtmlOptions::dart_limit`].
pub const DEFAULT_DART_LIMIT: usize = 200_000;

/// Cubical sets with more cubes than this draw only the squares of their cubes that no
/// other cube of the set shares (the page says so).
pub const CUBICAL_ALL_FACES_LIMIT: usize = 50_000;

/// The shape of a cell of a complex scene: point numbers from [`Scene::add_point`].
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// drawn as a dot
    Point(u32),
    /// drawn as a line
    Segment(u32, u32),
    /// drawn as filled polygons (each a cycle of points, fanned from its first point)
    Polygons(Vec<Vec<u32>>),
}

/// One highlighted chain: cells of dimension `dim` in the scene's numbering (for a map,
/// that of [`DenseMap::cells`]; for a complex, the order of [`Scene::add_cell`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ViewGenerator {
    /// the name shown in the list (`H1 #0 (Z)`, …)
    pub name: String,
    /// the dimension of its cells
    pub dim: usize,
    /// the cells
    pub cells: Vec<u32>,
}

/// Which view the page opens with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewKind {
    /// the exploded darts
    Darts,
    /// the faces, coloured by a label
    Cells,
    /// the generators
    Homology,
}

impl ViewKind {
    fn name(self) -> &'static str {
        match self {
            ViewKind::Darts => "darts",
            ViewKind::Cells => "cells",
            ViewKind::Homology => "homology",
        }
    }
}

/// How the page is written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HtmlOptions {
    /// the label that colours the cells view (default: the first text label of the highest
    /// dimension that has labels); it must be a label of some cell
    pub color_by: Option<String>,
    /// above this many darts, the darts view is thinned (the darts of one top cell in k)
    pub dart_limit: usize,
    /// the view shown first (default: homology when there are generators, else darts when
    /// the map has at most `dart_limit` darts, else cells)
    pub view: Option<ViewKind>,
}

impl Default for HtmlOptions {
    fn default() -> Self {
        HtmlOptions { color_by: None, dart_limit: DEFAULT_DART_LIMIT, view: None }
    }
}

/// The darts of a map scene.
#[derive(Clone, Debug)]
struct MapPart {
    /// `alpha[d * (n + 1) + i]`
    alpha: Vec<u32>,
    /// whether the points hold a node per edge after those of the vertices (a layout)
    edge_points: bool,
}

/// The cells of a complex scene, as drawing primitives.
#[derive(Clone, Debug, Default)]
struct ComplexPart {
    tri: Vec<u32>,
    tri_cell: Vec<u32>,
    seg: Vec<u32>,
    seg_cell: Vec<u32>,
    dot: Vec<u32>,
    dot_cell: Vec<u32>,
    cell_dim: Vec<u8>,
    cell_shown: Vec<u8>,
    links: Vec<u32>,
    /// lattice point → point number (cubical scenes)
    lattice: FxHashMap<Vec<i64>, u32>,
}

/// What a page draws: a map's darts or a complex's cells, their points, labels and
/// highlighted chains. See the module documentation.
#[derive(Clone, Debug)]
pub struct Scene {
    title: String,
    dim: usize,
    points: Vec<[f32; 3]>,
    placement: String,
    rule: Option<String>,
    notes: Vec<String>,
    map: Option<MapPart>,
    complex: Option<ComplexPart>,
    counts: Vec<usize>,
    labels: Vec<Vec<(u32, Labels)>>,
    generators: Vec<ViewGenerator>,
}

/// The rule stated on the page for maps above dimension 3.
fn projection_rule(n: usize) -> String {
    format!(
        "This {n}-map is drawn in 3-D by a projection: its vertices have the 3-D positions stated above. Each dart is \
         pulled towards the centres of its orbits <α0 α1> (its face), <α0 α1 α2> (its volume), …, \
         <α0 … α{}> (its {n}-cell), so the {n}-cells come apart; the connectors of α0 … α{n} have one colour \
         each. The cells view fills the faces of every {n}-cell and pushes the {n}-cells apart.",
        n - 1
    )
}

impl Scene {
    /// The scene of a map: its darts, its points (or a layout of its 1-skeleton, see the
    /// module documentation) and the labels of its cells. O(N n) plus the layout.
    ///
    /// ```
    /// use gmap_ops::export::html::{html_string, HtmlOptions, Scene};
    /// let cube = gmap_ops::build::placed::cube_with_points(3).unwrap();
    /// let scene = Scene::from_map(&cube, None, "a cube");
    /// let page = html_string(&scene, &HtmlOptions::default()).unwrap();
    /// assert!(page.starts_with("<!DOCTYPE html>"));
    /// assert!(!page.contains("http://") && !page.contains("https://"));
    /// ```
    pub fn from_map(map: &DenseMap, labels: Option<&DenseLabels>, title: &str) -> Scene {
        let n = map.dim();
        let vertices = map.cells(0);
        let given: Option<Vec<[f32; 3]>> = if map.has_points() {
            vertices
                .reps
                .iter()
                .map(|&d| map.vertex_point(d).filter(|p| p.iter().all(|c| c.is_finite())))
                .map(|p| p.map(|p| p.map(|c| c as f32)))
                .collect()
        } else {
            None
        };
        let (points, edge_points, placement) = match given {
            Some(p) => (p, false, "the map's points".to_string()),
            None => {
                let edges = if n >= 1 { map.cells(1) } else { map.partition(AlphaSet::of(&[])) };
                let nv = vertices.len();
                let mut links = Vec::with_capacity(2 * edges.len());
                for (e, &d) in edges.reps.iter().enumerate() {
                    let far = if n >= 1 { map.alpha(d, 0) } else { d };
                    links.push((vertices.of[d.index()], (nv + e) as u32));
                    links.push((vertices.of[far.index()], (nv + e) as u32));
                }
                let x = layout::graph_layout(nv + edges.len(), &links);
                let pts = x.iter().map(|p| p.map(|c| c as f32)).collect();
                let why = if map.has_points() { "not every vertex has a finite point; " } else { "no points; " };
                (pts, n >= 1, format!("{why}a layout of the 1-skeleton subdivided once: {}", layout::METHOD))
            }
        };
        let rule = (n > 3).then(|| projection_rule(n));
        let mut scene = Scene {
            title: title.to_string(),
            dim: n,
            points,
            placement,
            rule,
            notes: Vec::new(),
            map: Some(MapPart { alpha: map.flat().to_vec(), edge_points }),
            complex: None,
            counts: map.cell_counts(),
            labels: vec![Vec::new(); n + 1],
            generators: Vec::new(),
        };
        if let Some(l) = labels {
            for (i, per) in l.of.iter().enumerate().take(n + 1) {
                for (c, lab) in per.iter().enumerate() {
                    if !lab.is_empty() && c < scene.counts[i] {
                        scene.labels[i].push((c as u32, lab.clone()));
                    }
                }
            }
        }
        scene
    }

    /// An empty complex scene of dimension `dim`, to be filled with [`Scene::add_point`],
    /// [`Scene::add_cell`] and [`Scene::add_link`]; `placement` says where its points come
    /// from (shown on the page).
    pub fn complex(title: &str, dim: usize, placement: &str) -> Scene {
        Scene {
            title: title.to_string(),
            dim,
            points: Vec::new(),
            placement: placement.to_string(),
            rule: None,
            notes: Vec::new(),
            map: None,
            complex: Some(ComplexPart::default()),
            counts: vec![0; dim + 1],
            labels: vec![Vec::new(); dim + 1],
            generators: Vec::new(),
        }
    }

    /// The scene of a cubical set: one cell per cube (its squares, or its edge or point in
    /// dimension 1 or 0) at its lattice coordinates; in dimension d > 3 the point
    /// `(x_0, …, x_(d-1))` is drawn at `(x_0, x_1, x_2) + Σ_(a ≥ 3) x_a v_a` with
    /// `v_a = 0.45 (cos a, sin a, 0.5)` (stated on the page). Above
    /// [`CUBICAL_ALL_FACES_LIMIT`] cubes only the squares not shared by two cubes of the set
    /// are drawn. O(cubes 2^d d²).
    pub fn from_cubical(set: &CubicalSet, title: &str) -> Scene {
        let d = set.dim();
        let mut s = Scene::complex(title, d, "the cubes' lattice coordinates");
        if d > 3 {
            s.rule = Some(format!(
                "This {d}-dimensional cubical set is drawn in 3-D by an oblique projection: the lattice point \
                 (x0, …, x{}) is drawn at (x0, x1, x2) + Σ_(a≥3) x_a · 0.45 (cos a, sin a, 0.5).",
                d - 1
            ));
        }
        let only_outer = set.cube_count() > CUBICAL_ALL_FACES_LIMIT;
        if only_outer {
            s.notes.push(format!(
                "{} cubes: above {CUBICAL_ALL_FACES_LIMIT}, only the squares that no two cubes share are drawn.",
                set.cube_count()
            ));
        }
        let occupied: rustc_hash::FxHashSet<Vec<i64>> =
            if only_outer { set.cubes().collect() } else { Default::default() };
        let full = vec![1u8; d];
        for cube in set.cubes() {
            let skip = |axis: usize, side: i64| -> bool {
                if !only_outer {
                    return false;
                }
                let mut nb = cube.clone();
                nb[axis] += if side == 0 { -1 } else { 1 };
                occupied.contains(&nb)
            };
            s.push_cube(&cube, &full, true, &skip);
        }
        s
    }

    /// Adds a point, returning its number.
    pub fn add_point(&mut self, p: [f64; 3]) -> u32 {
        self.points.push(p.map(|c| c as f32));
        (self.points.len() - 1) as u32
    }

    /// The point of a lattice point of a cubical scene (added on first use).
    fn lattice_point(&mut self, x: &[i64]) -> u32 {
        if let Some(&k) = self.complex.as_ref().and_then(|c| c.lattice.get(x)) {
            return k;
        }
        let mut p = [0.0f64; 3];
        for (a, &c) in x.iter().enumerate() {
            if a < 3 {
                p[a] += c as f64;
            } else {
                let t = a as f64;
                p[0] += c as f64 * 0.45 * t.cos();
                p[1] += c as f64 * 0.45 * t.sin();
                p[2] += c as f64 * 0.45 * 0.5;
            }
        }
        let k = self.add_point(p);
        if let Some(c) = self.complex.as_mut() {
            c.lattice.insert(x.to_vec(), k);
        }
        k
    }

    /// Adds the cube with minimal vertex `min` and extent (0 or 1 per axis) `extent` as a
    /// cell of dimension `Σ extent`, its squares skipped where `skip(axis, side)` says so.
    fn push_cube(&mut self, min: &[i64], extent: &[u8], shown: bool, skip: &dyn Fn(usize, i64) -> bool) -> u32 {
        let axes: Vec<usize> = (0..extent.len()).filter(|&a| extent[a] != 0).collect();
        let k = axes.len();
        let corner = |s: &mut Scene, bits: &[(usize, i64)]| {
            let mut x = min.to_vec();
            for &(a, b) in bits {
                x[a] += b;
            }
            s.lattice_point(&x)
        };
        let shape = match k {
            0 => Shape::Point(corner(self, &[])),
            1 => Shape::Segment(corner(self, &[(axes[0], 0)]), corner(self, &[(axes[0], 1)])),
            _ => {
                // every square of the cube: two spanning axes, the others at 0 or 1
                let mut polys = Vec::new();
                for (i, &a) in axes.iter().enumerate() {
                    for &b in &axes[i + 1..] {
                        let rest: Vec<usize> = axes.iter().copied().filter(|&c| c != a && c != b).collect();
                        for mask in 0..(1usize << rest.len()) {
                            let fixed: Vec<(usize, i64)> =
                                rest.iter().enumerate().map(|(j, &c)| (c, (mask >> j & 1) as i64)).collect();
                            // a square of a 3-cube lies on one side of the third axis
                            if k == 3 && skip(fixed[0].0, fixed[0].1) {
                                continue;
                            }
                            let mut q = Vec::with_capacity(4);
                            for (da, db) in [(0, 0), (1, 0), (1, 1), (0, 1)] {
                                let mut bits = fixed.clone();
                                bits.push((a, da));
                                bits.push((b, db));
                                q.push(corner(self, &bits));
                            }
                            polys.push(q);
                        }
                    }
                }
                Shape::Polygons(polys)
            }
        };
        self.push_cell(k, shape, shown)
    }

    /// Adds a cube of a cubical scene as a cell (not drawn in the cells view, for
    /// generators): minimal vertex `min`, extent 0 or 1 per axis; returns its number among
    /// the cells of its dimension `Σ extent`. Errors: not a complex scene, or a cube of
    /// another dimension than the scene's axes ([`ExportError::SceneCell`]).
    pub fn add_cube(&mut self, min: &[i64], extent: &[u8]) -> Result<u32, ExportError> {
        if self.complex.is_none() || min.len() != self.dim || extent.len() != self.dim || extent.iter().any(|&e| e > 1)
        {
            return Err(ExportError::SceneCell {
                reason: format!(
                    "a cube ({min:?}, {extent:?}) of a scene of dimension {} (a complex scene, one 0/1 extent per axis)",
                    self.dim
                ),
            });
        }
        Ok(self.push_cube(min, extent, false, &|_, _| false))
    }

    /// Adds a cell of dimension `dim` with a shape; `shown` says whether the cells view
    /// draws it (cells added only for generators are not). Returns its number among the
    /// cells of its dimension. Errors: not a complex scene, a dimension above the scene's,
    /// or a point that does not exist ([`ExportError::SceneCell`]).
    pub fn add_cell(&mut self, dim: usize, shape: Shape, shown: bool) -> Result<u32, ExportError> {
        let np = self.points.len() as u32;
        let bad = |why: String| Err(ExportError::SceneCell { reason: why });
        if self.complex.is_none() {
            return bad("cells are added to complex scenes, not to maps".into());
        }
        if dim > self.dim {
            return bad(format!("a {dim}-cell in a scene of dimension {}", self.dim));
        }
        let pts: Vec<u32> = match &shape {
            Shape::Point(p) => vec![*p],
            Shape::Segment(p, q) => vec![*p, *q],
            Shape::Polygons(ps) => ps.iter().flatten().copied().collect(),
        };
        if let Some(p) = pts.iter().find(|&&p| p >= np) {
            return bad(format!("point {p} of a {dim}-cell, of {np} points"));
        }
        Ok(self.push_cell(dim, shape, shown))
    }

    fn push_cell(&mut self, dim: usize, shape: Shape, shown: bool) -> u32 {
        let c = self.complex.as_mut().expect("a complex scene");
        let global = c.cell_dim.len() as u32;
        c.cell_dim.push(dim as u8);
        c.cell_shown.push(shown as u8);
        match shape {
            Shape::Point(p) => {
                c.dot.push(p);
                c.dot_cell.push(global);
            }
            Shape::Segment(p, q) => {
                c.seg.extend([p, q]);
                c.seg_cell.push(global);
            }
            Shape::Polygons(ps) => {
                for poly in ps {
                    for k in 1..poly.len().saturating_sub(1) {
                        c.tri.extend([poly[0], poly[k], poly[k + 1]]);
                        c.tri_cell.push(global);
                    }
                }
            }
        }
        self.counts[dim] += 1;
        (self.counts[dim] - 1) as u32
    }

    /// Adds a link between two points (drawn as a thin grey line: an entry of an incidence
    /// graph). Errors: a point that does not exist, or not a complex scene.
    pub fn add_link(&mut self, a: u32, b: u32) -> Result<(), ExportError> {
        let np = self.points.len() as u32;
        match self.complex.as_mut() {
            Some(c) if a < np && b < np => {
                c.links.extend([a, b]);
                Ok(())
            }
            _ => Err(ExportError::SceneCell {
                reason: format!("a link {a}–{b} between {np} points of a complex scene"),
            }),
        }
    }

    /// Sets the labels of cell `cell` of dimension `dim`. Errors: no such cell.
    pub fn set_labels(&mut self, dim: usize, cell: u32, labels: Labels) -> Result<(), ExportError> {
        if dim > self.dim || cell as usize >= self.counts[dim] {
            return Err(ExportError::SceneCell { reason: format!("labels of {dim}-cell {cell}, which is not there") });
        }
        let l = &mut self.labels[dim];
        match l.iter_mut().find(|(c, _)| *c == cell) {
            Some(x) => x.1 = labels,
            None => l.push((cell, labels)),
        }
        Ok(())
    }

    /// Adds a highlighted chain. Errors: a dimension above the scene's or a cell that is not
    /// there ([`ExportError::GeneratorCell`]).
    pub fn add_generator(&mut self, g: ViewGenerator) -> Result<(), ExportError> {
        let count = self.counts.get(g.dim).copied();
        if let Some(&cell) = g.cells.iter().find(|&&c| count.is_none_or(|n| c as usize >= n)) {
            return Err(ExportError::GeneratorCell { name: g.name, dim: g.dim, cell, count: count.unwrap_or(0) });
        }
        self.generators.push(g);
        Ok(())
    }

    /// Adds a line of text shown on the page under the scene's description.
    pub fn add_note(&mut self, note: &str) {
        self.notes.push(note.to_string());
    }

    /// The number of cells of each dimension.
    pub fn counts(&self) -> &[usize] {
        &self.counts
    }

    /// The number of darts (0 for a complex).
    pub fn dart_count(&self) -> usize {
        self.map.as_ref().map_or(0, |m| m.alpha.len() / (self.dim + 1))
    }

    /// How the points were obtained, in words.
    pub fn placement(&self) -> &str {
        &self.placement
    }

    /// The names of the labels, in order of first appearance (by dimension, then cell).
    pub fn label_names(&self) -> Vec<String> {
        let mut names: Vec<String> = Vec::new();
        for per in &self.labels {
            for (_, l) in per {
                for (name, _) in l.iter() {
                    if !names.iter().any(|n| n == name) {
                        names.push(name.to_string());
                    }
                }
            }
        }
        names
    }
}

/// `[display text, kind]` of a label value for the page.
fn value_json(v: &LabelValue) -> Value {
    match v {
        LabelValue::Int(i) => json!([i.to_string(), "int"]),
        LabelValue::Real(r) => json!([format!("{r}"), "real"]),
        LabelValue::Text(t) => json!([t, "text"]),
    }
}

/// The involutions as the page reads them: for each dart and each `i`, `alpha_i(d) - d`
/// zigzag-encoded (`2x` for `x >= 0`, `-2x - 1` below) as a LEB128 varint, then base64. Small
/// for maps whose darts are numbered cell by cell (one byte per link when `|alpha_i(d) - d|
/// < 64`); at most five bytes per link.
fn b64_alpha(alpha: &[u32], w: usize) -> String {
    let mut bytes = Vec::with_capacity(alpha.len() + alpha.len() / 4);
    for (k, &e) in alpha.iter().enumerate() {
        let d = (k / w) as i64;
        let x = e as i64 - d;
        let mut z = if x >= 0 { 2 * x as u64 } else { (-2 * x - 1) as u64 };
        loop {
            let b = (z & 127) as u8;
            z >>= 7;
            if z == 0 {
                bytes.push(b);
                break;
            }
            bytes.push(b | 128);
        }
    }
    base64::engine::general_purpose::STANDARD.encode(bytes)
}

fn b64_u32(v: &[u32]) -> String {
    let bytes: Vec<u8> = v.iter().flat_map(|x| x.to_le_bytes()).collect();
    base64::engine::general_purpose::STANDARD.encode(bytes)
}

fn b64_f32(v: &[[f32; 3]]) -> String {
    let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
    base64::engine::general_purpose::STANDARD.encode(bytes)
}

fn b64_u8(v: &[u8]) -> String {
    base64::engine::general_purpose::STANDARD.encode(v)
}

/// Text for HTML element content and double-quoted attribute values (`&`, `<`, `>`, `"`
/// escaped).
pub fn escape_html(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The page of a scene: one self-contained HTML document (see the module documentation).
/// Errors: [`HtmlOptions::color_by`] names no label of the scene ([`ExportError::UnknownLabel`]).
/// O(size of the scene).
pub fn html_string(scene: &Scene, opts: &HtmlOptions) -> Result<String, ExportError> {
    let names = scene.label_names();
    if let Some(c) = &opts.color_by {
        if !names.iter().any(|n| n == c) {
            return Err(ExportError::UnknownLabel { name: c.clone(), known: names });
        }
    }
    // the default label: the first text label of the highest dimension with labels
    let color_by = opts.color_by.clone().or_else(|| {
        scene.labels.iter().rev().find_map(|per| {
            per.iter()
                .find_map(|(_, l)| l.iter().find(|(_, v)| matches!(v, LabelValue::Text(_))).map(|(n, _)| n.to_string()))
        })
    });
    let labels: Vec<Value> = scene
        .labels
        .iter()
        .map(|per| {
            Value::Array(
                per.iter()
                    .map(|(c, l)| json!([c, l.iter().map(|(n, v)| json!([n, value_json(v)])).collect::<Vec<_>>()]))
                    .collect(),
            )
        })
        .collect();
    let darts = scene.dart_count();
    let view = opts.view.unwrap_or(if !scene.generators.is_empty() {
        ViewKind::Homology
    } else if scene.map.is_some() && darts <= opts.dart_limit {
        ViewKind::Darts
    } else {
        ViewKind::Cells
    });
    let view = if scene.map.is_none() && view == ViewKind::Darts { ViewKind::Cells } else { view };
    let meta = json!({
        "title": scene.title,
        "dim": scene.dim,
        "kind": if scene.map.is_some() { "map" } else { "complex" },
        "darts": darts,
        "counts": scene.counts,
        "points": scene.points.len(),
        "placement": scene.placement,
        "rule": scene.rule,
        "notes": scene.notes,
        "edgePoints": scene.map.as_ref().is_some_and(|m| m.edge_points),
        "labels": labels,
        "colorBy": color_by,
        "generators": scene.generators.iter().map(|g| json!({"name": g.name, "dim": g.dim, "cells": g.cells})).collect::<Vec<_>>(),
        "dartLimit": opts.dart_limit,
        "view": view.name(),
    });
    // inside a <script> element: no "</" may appear, so escape every "<"
    let meta = meta.to_string().replace('<', "\\u003c");
    let mut blobs: Vec<(&str, String)> = vec![("points", b64_f32(&scene.points))];
    if let Some(m) = &scene.map {
        blobs.push(("alpha", b64_alpha(&m.alpha, scene.dim + 1)));
    }
    if let Some(c) = &scene.complex {
        blobs.extend([
            ("tri", b64_u32(&c.tri)),
            ("triCell", b64_u32(&c.tri_cell)),
            ("seg", b64_u32(&c.seg)),
            ("segCell", b64_u32(&c.seg_cell)),
            ("dot", b64_u32(&c.dot)),
            ("dotCell", b64_u32(&c.dot_cell)),
            ("cellDim", b64_u8(&c.cell_dim)),
            ("cellShown", b64_u8(&c.cell_shown)),
            ("link", b64_u32(&c.links)),
        ]);
    }
    let size: usize = blobs.iter().map(|(_, b)| b.len()).sum::<usize>() + meta.len() + VIEWER_JS.len() + 4096;
    let mut out = String::with_capacity(size);
    let title = escape_html(&scene.title);
    out.push_str("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n");
    out.push_str(
        "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; \
         style-src 'unsafe-inline'; img-src data: blob:\">\n",
    );
    out.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    out.push_str(&format!("<title>{title} — gmap view</title>\n<style>\n{VIEWER_CSS}</style>\n"));
    // the error catcher comes first, so that an error of the viewer itself is recorded
    out.push_str(
        "<script>window.gmapErrors=[];addEventListener('error',function(e){gmapErrors.push(String(e.message))});\
         addEventListener('securitypolicyviolation',function(e){gmapErrors.push('CSP: '+e.blockedURI)});\
         (function(){var c=console.error;console.error=function(){gmapErrors.push(Array.prototype.join.call(arguments,' '));\
         return c.apply(console,arguments)}})();</script>\n",
    );
    out.push_str("</head><body>\n");
    out.push_str(&format!("<script type=\"application/json\" id=\"gmap-meta\">{meta}</script>\n"));
    for (name, b) in &blobs {
        out.push_str(&format!("<script type=\"application/octet-stream\" id=\"gmap-{name}\">"));
        out.push_str(b);
        out.push_str("</script>\n");
    }
    out.push_str("<script>\n");
    out.push_str(VIEWER_JS);
    out.push_str("</script>\n</body></html>\n");
    Ok(out)
}

/// Writes the page of a scene (see [`html_string`]) through a temporary file.
pub fn write_html(scene: &Scene, opts: &HtmlOptions, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, html_string(scene, opts)?.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build;

    #[test]
    fn a_map_without_points_gets_a_layout_with_a_node_per_edge() {
        let torus = build::schema("a b A B").unwrap();
        let s = Scene::from_map(&torus, None, "torus");
        // one vertex, two edges: three nodes
        assert_eq!(s.points.len(), 3);
        assert!(s.placement.contains("pivot MDS"));
        assert!(s.map.as_ref().unwrap().edge_points);
        assert_eq!(s.counts, vec![1, 2, 1]);
        let cube = crate::build::placed::cube_with_points(3).unwrap();
        let s = Scene::from_map(&cube, None, "cube");
        assert_eq!(s.points.len(), 8);
        assert_eq!(s.placement, "the map's points");
        assert!(s.rule.is_none());
        let s4 = Scene::from_map(&build::cube(4).unwrap(), None, "tesseract");
        assert!(s4.rule.as_ref().unwrap().contains("projection"));
    }

    #[test]
    fn generators_and_labels_are_checked() {
        let cube = crate::build::placed::cube_with_points(2).unwrap();
        let mut s = Scene::from_map(&cube, None, "square");
        assert!(s.add_generator(ViewGenerator { name: "g".into(), dim: 1, cells: vec![0, 3] }).is_ok());
        assert!(matches!(
            s.add_generator(ViewGenerator { name: "h".into(), dim: 1, cells: vec![4] }),
            Err(ExportError::GeneratorCell { cell: 4, count: 4, .. })
        ));
        assert!(matches!(
            s.add_generator(ViewGenerator { name: "h".into(), dim: 3, cells: vec![0] }),
            Err(ExportError::GeneratorCell { dim: 3, .. })
        ));
        assert!(s.set_labels(2, 0, [("name", LabelValue::Text("<b>".into()))].into_iter().collect()).is_ok());
        assert!(s.set_labels(2, 1, Labels::new()).is_err());
        let e = html_string(&s, &HtmlOptions { color_by: Some("colour".into()), ..Default::default() });
        assert!(matches!(e, Err(ExportError::UnknownLabel { ref known, .. }) if known == &["name".to_string()]));
        let page = html_string(&s, &HtmlOptions::default()).unwrap();
        // the text is escaped inside the script element, and chosen as the default colouring
        assert!(page.contains(r#""colorBy":"name""#));
        assert!(page.contains(r"\u003cb>"));
        assert!(!page.contains("<b>"));
    }

    /// Reads back what [`b64_alpha`] wrote, as the page's script does.
    fn decode_alpha(text: &str, w: usize) -> Vec<u32> {
        let bytes = base64::engine::general_purpose::STANDARD.decode(text).unwrap();
        let (mut out, mut p) = (Vec::new(), 0);
        while p < bytes.len() {
            let (mut z, mut shift) = (0u64, 0);
            loop {
                let b = bytes[p];
                p += 1;
                z |= ((b & 127) as u64) << shift;
                shift += 7;
                if b & 128 == 0 {
                    break;
                }
            }
            let x = if z % 2 == 1 { -((z as i64 + 1) / 2) } else { (z / 2) as i64 };
            out.push((out.len() / w) as i64 + x);
        }
        out.into_iter().map(|v| u32::try_from(v).unwrap()).collect()
    }

    #[test]
    fn the_involutions_round_trip_through_their_varints() {
        let grid = crate::build::placed::grid_with_points(&[3, 2, 2], &[false; 3]).unwrap();
        let text = b64_alpha(grid.flat(), 4);
        assert_eq!(decode_alpha(&text, 4), grid.flat());
        // far links take more bytes, never more than five
        let far = [0u32, 4_000_000_000, 2, 3, 4_000_000_000, 0];
        assert_eq!(decode_alpha(&b64_alpha(&far, 2), 2), far);
        let small = b64_alpha(&[1, 0], 1);
        assert_eq!(base64::engine::general_purpose::STANDARD.decode(small).unwrap(), vec![2, 1]);
    }

    #[test]
    fn cubical_scenes_have_a_cell_per_cube_and_cubes_for_generators() {
        let set = crate::import::cubical::parse_cub(b"(0,0,0)\n(1,0,0)\n").unwrap();
        let mut s = Scene::from_cubical(&set, "two cubes");
        assert_eq!(s.counts, vec![0, 0, 0, 2]);
        let c = s.complex.as_ref().unwrap();
        assert_eq!(c.tri.len() / 3, 2 * 6 * 2);
        assert_eq!(s.points.len(), 12);
        assert_eq!(s.add_cube(&[0, 0, 0], &[1, 0, 0]).unwrap(), 0);
        assert_eq!(s.add_cube(&[1, 0, 0], &[1, 0, 0]).unwrap(), 1);
        assert_eq!(s.counts, vec![0, 2, 0, 2]);
        assert!(s.add_cube(&[0, 0], &[1, 0]).is_err());
        let page = html_string(&s, &HtmlOptions::default()).unwrap();
        assert!(page.contains(r#""view":"cells""#));
    }
}
