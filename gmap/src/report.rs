//! The groups of an input, with the route that computed them and, on request, a
//! representative cycle per summand named in the input's own terms; and their two
//! renderings, the text and the JSON object that `gmap homology` prints (docs/FORMATS.md).

use gmap_homology::Homology;
use serde_json::json;

pub use crate::cell_name::CellName;
use crate::options::{Method, Via};

/// A representative cycle of one summand, in the input's terms.
#[derive(Clone, Debug)]
pub struct NamedGenerator {
    /// the dimension of the summand
    pub dim: usize,
    /// its order: 0 for a free summand (Z, or the field), k for Z/k
    pub order: gmap_homology::Natural,
    /// the cycle: cells with their coefficients
    pub chain: Chain,
    /// its length, for the cycles of a shortest basis (edges counted)
    pub length: Option<f64>,
}

/// The cells of a generator with their coefficients: named one by one, or, for the cubes of
/// a cubical set's one-pass route, as points of the set's doubled grid named when read (that
/// route gives millions of cells: a [`CellName`] each would take several times their memory
/// and most of the time of writing them out).
#[derive(Clone, Debug)]
pub enum Chain {
    /// cells with their names
    Named(Vec<(CellName, i64)>),
    /// points of a doubled grid (cells of the cubes) with their coefficients
    Grid {
        /// `(point, coefficient)`
        cells: Vec<(u64, i64)>,
        /// how a point is named
        grid: std::sync::Arc<CubeGrid>,
    },
}

/// How the points of a cubical set's doubled grid name cubes: `2L + 1` points per axis (axis
/// 0 fastest, a cell odd along the axes it spans), the box's minimal vertex added, the axes
/// given in reverse order when `reversed` (a C-ordered array read in storage order).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubeGrid {
    points: Vec<usize>,
    min: Vec<i64>,
    reversed: bool,
    /// the points per axis as dividers, when the grid's points fit in `u32`
    div: Option<Vec<gmap_core::fastdiv::Divider>>,
}

impl CubeGrid {
    /// The grid of `points` per axis (storage order), the box's minimal vertex `min` (zeros
    /// where shorter), named in reverse axis order if `reversed`.
    pub fn new(points: &[usize], min: &[i64], reversed: bool) -> Self {
        let min = (0..points.len()).map(|a| min.get(a).copied().unwrap_or(0)).collect();
        let fits = points.iter().try_fold(1usize, |v, &n| v.checked_mul(n)).is_some_and(|t| t <= u32::MAX as usize);
        let div = fits.then(|| points.iter().map(|&n| gmap_core::fastdiv::Divider::new(n)).collect()).flatten();
        CubeGrid { points: points.to_vec(), min, reversed, div }
    }

    /// The number of axes.
    pub fn dim(&self) -> usize {
        self.points.len()
    }

    /// `f(a, lo, extent)` for each storage axis `a` of grid point `point`: the cube's minimal
    /// vertex and extent along it.
    #[inline]
    fn for_axes(&self, point: u64, mut f: impl FnMut(usize, i64, u8)) {
        let mut p = point as usize;
        for (a, &n) in self.points.iter().enumerate() {
            let (q, c) = match &self.div {
                Some(div) => {
                    let q = div[a].quotient(p);
                    (q, p - q * n)
                }
                None => (p / n, p % n),
            };
            p = q;
            f(a, self.min[a] + (c / 2) as i64, (c % 2) as u8);
        }
    }

    /// The cube of grid point `point`: its minimal vertex and extent, in naming order.
    pub fn cube(&self, point: u64) -> (smallvec::SmallVec<[i64; 4]>, smallvec::SmallVec<[u8; 4]>) {
        let mut lo = smallvec::SmallVec::<[i64; 4]>::new();
        let mut extent = smallvec::SmallVec::<[u8; 4]>::new();
        self.for_axes(point, |_, l, e| {
            lo.push(l);
            extent.push(e);
        });
        if self.reversed {
            lo.reverse();
            extent.reverse();
        }
        (lo, extent)
    }

    /// Appends the name of grid point `point` as text, as [`CellName::to_text`] writes it
    /// (`[0,1]x2`), without making the name.
    pub fn push_text(&self, point: u64, out: &mut String) {
        const MAX: usize = 8;
        let d = self.points.len();
        if d > MAX {
            let (min, extent) = self.cube(point);
            return push_cube_text(out, &min, &extent);
        }
        let (mut lo, mut ex) = ([0i64; MAX], [0u8; MAX]);
        self.for_axes(point, |a, l, e| {
            lo[a] = l;
            ex[a] = e;
        });
        if self.reversed {
            lo[..d].reverse();
            ex[..d].reverse();
        }
        push_cube_text(out, &lo[..d], &ex[..d]);
    }

    /// The name of grid point `point`.
    pub fn name(&self, point: u64) -> CellName {
        let (min, extent) = self.cube(point);
        CellName::Cube { min, extent }
    }
}

impl Chain {
    /// The number of cells.
    pub fn len(&self) -> usize {
        match self {
            Chain::Named(v) => v.len(),
            Chain::Grid { cells, .. } => cells.len(),
        }
    }

    /// No cells.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The cells with their coefficients, in order (a grid's cells named as they come).
    pub fn iter(&self) -> impl ExactSizeIterator<Item = (CellName, i64)> + '_ {
        (0..self.len()).map(move |i| match self {
            Chain::Named(v) => v[i].clone(),
            Chain::Grid { cells, grid } => (grid.name(cells[i].0), cells[i].1),
        })
    }

    /// The first cell and its coefficient.
    pub fn first(&self) -> Option<(CellName, i64)> {
        self.iter().next()
    }

    /// The coefficients, in order.
    pub fn coefficients(&self) -> Vec<i64> {
        match self {
            Chain::Named(v) => v.iter().map(|x| x.1).collect(),
            Chain::Grid { cells, .. } => cells.iter().map(|x| x.1).collect(),
        }
    }

    /// Reverses the axes of the cubes named (a set whose caller's axes are the reverse of
    /// its storage's); other cells are left as they are.
    pub fn reverse_cube_axes(&mut self) {
        match self {
            Chain::Named(v) => {
                for (cell, _) in v.iter_mut() {
                    if let CellName::Cube { min, extent } = cell {
                        min.reverse();
                        extent.reverse();
                    }
                }
            }
            Chain::Grid { grid, .. } => {
                let g = std::sync::Arc::make_mut(grid);
                g.reversed = !g.reversed;
            }
        }
    }
}

impl From<Vec<(CellName, i64)>> for Chain {
    fn from(v: Vec<(CellName, i64)>) -> Self {
        Chain::Named(v)
    }
}

/// The result of [`crate::homology()`]: the groups, how they were computed, and the generators when
/// asked for.
#[derive(Clone, Debug)]
pub struct Report {
    /// what the input is ([`crate::Input::kind`])
    pub kind: &'static str,
    /// the dimension of the input
    pub dimension: usize,
    /// the method (cellular or simplicial)
    pub method: Method,
    /// the route of a simplicial complex (`None` for other inputs)
    pub route: Option<Via>,
    /// the field's characteristic, `None` over Z
    pub field: Option<u64>,
    /// Betti numbers and torsion
    pub groups: Homology,
    /// a representative cycle per summand, with `generators`
    pub generators: Option<Vec<NamedGenerator>>,
    /// a note on what was done instead of what was asked (`--simplify` skipped, and why)
    pub note: Option<String>,
    /// for an architectural complex: which space the groups are those of
    pub space: Option<ArchSpace>,
}

/// Which space the groups of an architectural complex (`.json`) are those of: the region
/// complex (each region a cell glued along its recorded boundary, the completion by zero of
/// AC Def. 3.9), or with `--topological` the space the regions make (Algorithm 8.16). The
/// two differ where a region is not a ball, which `not_balls` lists.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct ArchSpace {
    /// the groups are the topological ones (`--topological`)
    pub topological: bool,
    /// the regions that are not balls: their names (`region 7
    /// ("kitchen")`), ids and Betti numbers
    pub not_balls: Vec<(String, u64, Vec<usize>)>,
    /// the file's id of each region of `not_balls`: its string id, or its number
    pub not_ball_ids: Vec<serde_json::Value>,
}

impl ArchSpace {
    /// The statement for complex `x`. O(Σ closures of the regions).
    pub fn of(x: &gmap_homology::arch::ArchComplex, topological: bool) -> Self {
        let not_balls: Vec<(String, u64, Vec<usize>)> = (0..x.regions().len())
            .filter_map(|r| {
                let betti = x.region_betti(r);
                // an edge on two vertices is a ball (its boundary is two points), whatever
                // the count of boundary components says
                let edge = x.region(r).dim == 1 && !x.has_region_betti(r) && x.down(r).len() == 2;
                let ball = edge || (betti.first() == Some(&1) && betti[1..].iter().all(|&b| b == 0));
                (!ball).then(|| (crate::arch_cells::region_name(x, r), x.region(r).id.0, betti))
            })
            .collect();
        let not_ball_ids = not_balls
            .iter()
            .map(|(_, id, _)| {
                let k = x.index_of(gmap_homology::arch::RegionId(*id));
                k.and_then(|k| x.region_key(k)).map_or_else(|| json!(id), |key| json!(key))
            })
            .collect();
        ArchSpace { topological, not_balls, not_ball_ids }
    }

    /// The lines `gmap homology` prints.
    pub fn to_text(&self) -> String {
        if self.topological {
            return "space: the space the regions make (Algorithm 8.16, --topological)\n".to_string();
        }
        let mut out = "space: the region complex (each region a cell glued along its recorded boundary, AC Def. 3.9)\n"
            .to_string();
        if !self.not_balls.is_empty() {
            let shown: Vec<String> = self
                .not_balls
                .iter()
                .take(3)
                .map(|(name, _, b)| {
                    format!(
                        "{name} (Betti numbers ({}))",
                        b.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")
                    )
                })
                .collect();
            let more = match self.not_balls.len() {
                n if n > 3 => format!(" and {} more", n - 3),
                _ => String::new(),
            };
            let verb = if self.not_balls.len() == 1 { "is" } else { "are" };
            out.push_str(&format!(
                "hint: {}{more} {verb} not a ball; gmap homology --topological gives the groups of the space the regions make\n",
                shown.join(", ")
            ));
        }
        out
    }

    /// The members `gmap homology --json` adds: `"space"` (`"region complex"` or
    /// `"topological"`) and, when a region is not a ball, `"not_balls"` and `"hint"`.
    fn add_json(&self, v: &mut serde_json::Value) {
        v["space"] = json!(if self.topological { "topological" } else { "region complex" });
        if !self.topological && !self.not_balls.is_empty() {
            v["not_balls"] = json!(self
                .not_balls
                .iter()
                .zip(&self.not_ball_ids)
                .map(|((name, n, b), id)| json!({"region": id, "number": n, "name": name, "betti": b}))
                .collect::<Vec<_>>());
            v["hint"] = json!("a region is not a ball: --topological gives the groups of the space the regions make");
        }
    }
}

impl Report {
    /// The route's name: `direct` or `gmap` for a simplicial complex, `cubical` for a cubical
    /// set, else the method (`cellular`, `simplicial`).
    pub fn route_name(&self) -> &'static str {
        match (self.route, self.kind) {
            (Some(v), _) => v.name(),
            (None, "cubical set") => "cubical",
            _ => self.method.name(),
        }
    }

    /// The JSON object `gmap homology --json` prints.
    pub fn to_json(&self) -> serde_json::Value {
        let h = &self.groups;
        let mut v = json!({
            "dimension": self.dimension,
            "method": self.method.name(),
            "coefficients": h.coefficients.to_string(),
            "betti": h.betti,
            "torsion": h.torsion,
            "euler_characteristic": h.euler_characteristic(),
        });
        if let Some(r) = self.route {
            v["route"] = json!(r.name());
        }
        if let Some(g) = &self.generators {
            let list: Vec<_> = g
                .iter()
                .map(|x| {
                    let mut g = json!({
                        "dim": x.dim,
                        "order": x.order,
                        "chain": x.chain.iter().map(|(cell, coef)| json!({
                            "cell": cell.to_json(),
                            "coefficient": coef,
                        })).collect::<Vec<_>>(),
                    });
                    if let Some(l) = x.length {
                        g["length"] = json!(l);
                    }
                    g
                })
                .collect();
            v["generators"] = json!(list);
        }
        if let Some(space) = &self.space {
            space.add_json(&mut v);
        }
        v
    }

    /// [`Report::to_json`] as text, the same bytes as its `to_string()`: see
    /// [`Report::write_json`].
    pub fn to_json_string(&self) -> String {
        let mut out = Vec::new();
        // writing into memory does not fail
        let _ = self.write_json(&mut out);
        String::from_utf8(out).unwrap_or_default()
    }

    /// Writes [`Report::to_json`] as text (the same bytes as its `to_string()`), the
    /// generators straight from the report instead of built as JSON values first (a cube's
    /// name as a value is a map of two lists: millions of them take gigabytes), one
    /// generator at a time.
    pub fn write_json(&self, w: &mut impl std::io::Write) -> std::io::Result<()> {
        use std::fmt::Write as _;
        let Some(gens) = &self.generators else { return w.write_all(self.to_json().to_string().as_bytes()) };
        // the report without its generators, a marker in their place (keys are sorted, so
        // the marker sits where the generators belong)
        const MARK: &str = r"\u0000generators\u0000";
        let mut v = self.clone_without_generators().to_json();
        v["generators"] = json!("\u{0}generators\u{0}");
        let text = v.to_string();
        let Some(at) = text.find(&format!("\"{MARK}\"")) else {
            return w.write_all(self.to_json().to_string().as_bytes());
        };
        w.write_all(&text.as_bytes()[..at])?;
        w.write_all(b"[")?;
        let mut out = String::new();
        for (i, g) in gens.iter().enumerate() {
            out.clear();
            if i > 0 {
                out.push(',');
            }
            out.push_str("{\"chain\":[");
            let term = |out: &mut String, j: usize, cell: &CellName, coef: i64| {
                if j > 0 {
                    out.push(',');
                }
                out.push_str("{\"cell\":");
                match cell {
                    CellName::Cube { min, extent } => {
                        out.push_str("{\"cube\":[");
                        push_list(out, min.iter().copied());
                        out.push_str("],\"extent\":[");
                        push_list(out, extent.iter().map(|&e| i64::from(e)));
                        out.push_str("]}");
                    }
                    other => out.push_str(&other.to_json().to_string()),
                }
                out.push_str(",\"coefficient\":");
                out.push_str(itoa::Buffer::new().format(coef));
                out.push('}');
            };
            // named cells borrowed, a grid's named one at a time
            match &g.chain {
                Chain::Named(cells) => {
                    for (j, (cell, coef)) in cells.iter().enumerate() {
                        term(&mut out, j, cell, *coef);
                    }
                }
                Chain::Grid { cells, grid } => {
                    for (j, &(p, coef)) in cells.iter().enumerate() {
                        term(&mut out, j, &grid.name(p), coef);
                    }
                }
            }
            let _ = write!(out, "],\"dim\":{},\"order\":{}}}", g.dim, json!(g.order));
            w.write_all(out.as_bytes())?;
        }
        w.write_all(b"]")?;
        w.write_all(&text.as_bytes()[at + MARK.len() + 2..])
    }

    /// A copy of the report without its generators (cheap: the groups and names only).
    fn clone_without_generators(&self) -> Report {
        Report {
            kind: self.kind,
            dimension: self.dimension,
            method: self.method,
            route: self.route,
            field: self.field,
            groups: self.groups.clone(),
            generators: None,
            note: self.note.clone(),
            space: self.space.clone(),
        }
    }

    /// The text `gmap homology` prints: a header line, one line per group, the Euler
    /// characteristic, then a line per generator.
    pub fn to_text(&self) -> String {
        let mut out = Vec::new();
        // writing into memory does not fail
        let _ = self.write_text(&mut out);
        String::from_utf8(out).unwrap_or_default()
    }

    /// Writes [`Report::to_text`], one generator at a time.
    pub fn write_text(&self, w: &mut impl std::io::Write) -> std::io::Result<()> {
        use std::fmt::Write as _;
        let h = &self.groups;
        let via = self.route.map(|r| format!(", route {}", r.name())).unwrap_or_default();
        let mut out = format!(
            "dimension {}, method {}, coefficients {}{via}\n",
            self.dimension,
            self.method.name(),
            h.coefficients
        );
        for k in 0..h.betti.len() {
            let _ = writeln!(out, "H_{k} = {}", h.group_string(k));
        }
        let _ = writeln!(out, "euler characteristic {}", h.euler_characteristic());
        if let Some(space) = &self.space {
            out.push_str(&space.to_text());
        }
        w.write_all(out.as_bytes())?;
        for x in self.generators.iter().flatten() {
            out.clear();
            let order = match (x.order.to_u64(), self.field) {
                (Some(0), None) => "Z".to_string(),
                (Some(0), Some(p)) => format!("Z/{p}"),
                _ => format!("Z/{}", x.order),
            };
            let _ = write!(out, "generator of H_{} ({order}):", x.dim);
            if let Some(l) = x.length {
                let _ = write!(out, " length {l}:");
            }
            let mut digits = itoa::Buffer::new();
            let mut term = |out: &mut String, coef: i64| {
                out.push_str(if coef >= 0 { " +" } else { " " });
                out.push_str(digits.format(coef));
                out.push(' ');
            };
            match &x.chain {
                // a grid's cubes named as they are written, without a `CellName` each
                Chain::Grid { cells, grid } => {
                    for &(p, coef) in cells {
                        term(&mut out, coef);
                        grid.push_text(p, &mut out);
                    }
                }
                Chain::Named(cells) => {
                    for (cell, coef) in cells {
                        term(&mut out, *coef);
                        match cell {
                            CellName::Cube { min, extent } => push_cube_text(&mut out, min, extent),
                            other => out.push_str(&other.to_text()),
                        }
                    }
                }
            }
            out.push('\n');
            w.write_all(out.as_bytes())?;
        }
        Ok(())
    }
}

/// Appends a cube's name as [`CellName::to_text`] writes it: `[0,1]x2`.
fn push_cube_text(out: &mut String, min: &[i64], extent: &[u8]) {
    let mut digits = itoa::Buffer::new();
    for (a, (&lo, &e)) in min.iter().zip(extent).enumerate() {
        if a > 0 {
            out.push('x');
        }
        if e == 1 {
            out.push('[');
            out.push_str(digits.format(lo));
            out.push(',');
            out.push_str(digits.format(lo + 1));
            out.push(']');
        } else {
            out.push_str(digits.format(lo));
        }
    }
}

/// Appends integers separated by commas.
fn push_list(out: &mut String, values: impl Iterator<Item = i64>) {
    let mut digits = itoa::Buffer::new();
    for (i, x) in values.enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str(digits.format(x));
    }
}

impl Report {
    /// The report whose [`Report::to_json`] is `v` (how a result crosses a process boundary:
    /// the Python package's pickles, a Dask worker's answer), `None` when `v` is not such an
    /// object. Kept: the groups, the dimension, method, route and field, the generators'
    /// cells (named, a cubical route's grid included), an architectural complex's space;
    /// the note and the names of the regions that are not balls are not in the JSON
    /// (`to_text` names those regions `region ID`). The kind is read from what the JSON
    /// holds: a route for a simplicial complex, a space for an architectural complex, else
    /// the cells of the generators (cubes, regions), else a map.
    pub fn from_json(v: &serde_json::Value) -> Option<Report> {
        use crate::input::Kind;
        let (groups, field) = groups_from_json(v)?;
        let method = match v.get("method")?.as_str()? {
            "cellular" => Method::Cellular,
            "simplicial" => Method::Simplicial,
            _ => return None,
        };
        let route = match v.get("route").map(|r| r.as_str()) {
            None => None,
            Some(Some("direct")) => Some(Via::Direct),
            Some(Some("gmap")) => Some(Via::Gmap),
            Some(_) => return None,
        };
        let generators = match v.get("generators") {
            None => None,
            Some(g) => Some(g.as_array()?.iter().map(generator_from_json).collect::<Option<Vec<_>>>()?),
        };
        let space = match v.get("space") {
            None => None,
            Some(s) => Some(space_from_json(s, v.get("not_balls"))?),
        };
        let first_cell = generators.as_ref().and_then(|g| g.iter().find_map(|x| x.chain.first()));
        let kind = match (route, &space, first_cell) {
            (Some(_), _, _) => Kind::Simplicial,
            (None, Some(_), _) => Kind::Arch,
            (None, None, Some((CellName::Cube { .. }, _))) => Kind::Cubical,
            (None, None, Some((CellName::Region(_) | CellName::NamedRegion { .. }, _))) => Kind::Arch,
            _ => Kind::Map,
        };
        let dimension = json_usize(v.get("dimension")?)?;
        Some(Report { kind: kind.name(), dimension, method, route, field, groups, generators, note: None, space })
    }
}

/// A count in a JSON object.
fn json_usize(x: &serde_json::Value) -> Option<usize> {
    x.as_u64().and_then(|b| usize::try_from(b).ok())
}

/// The groups of a report's JSON object and its field (`None` over Z).
fn groups_from_json(v: &serde_json::Value) -> Option<(Homology, Option<u64>)> {
    use gmap_homology::{Coefficients, Natural};
    // a number of any length (arbitrary precision): its digits
    let nat = |x: &serde_json::Value| -> Option<Natural> { x.as_number()?.to_string().parse().ok() };
    let (coefficients, field) = match v.get("coefficients")?.as_str()? {
        "Z" => (Coefficients::Integers, None),
        s => {
            let p: u64 = s.strip_prefix("Z/")?.parse().ok()?;
            (Coefficients::Field(p), Some(p))
        }
    };
    let betti = v.get("betti")?.as_array()?.iter().map(json_usize).collect::<Option<Vec<_>>>()?;
    let torsion = v
        .get("torsion")?
        .as_array()?
        .iter()
        .map(|t| t.as_array().and_then(|t| t.iter().map(nat).collect::<Option<Vec<_>>>()))
        .collect::<Option<Vec<_>>>()?;
    (torsion.len() == betti.len()).then_some((Homology { coefficients, betti, torsion }, field))
}

/// An architectural complex's space from a report's `"space"` and `"not_balls"` members.
fn space_from_json(space: &serde_json::Value, not_balls: Option<&serde_json::Value>) -> Option<ArchSpace> {
    let topological = match space.as_str()? {
        "topological" => true,
        "region complex" => false,
        _ => return None,
    };
    let not_balls = match not_balls {
        None => Vec::new(),
        Some(list) => list
            .as_array()?
            .iter()
            .map(|r| {
                let key = r.get("region")?.clone();
                let id = r.get("number").and_then(|n| n.as_u64()).or_else(|| key.as_u64())?;
                let name =
                    r.get("name").and_then(|n| n.as_str()).map_or_else(|| format!("region {id}"), str::to_string);
                let betti = r.get("betti")?.as_array()?.iter().map(json_usize).collect::<Option<Vec<_>>>()?;
                Some(((name, id, betti), key))
            })
            .collect::<Option<Vec<_>>>()?,
    };
    let (not_balls, not_ball_ids) = not_balls.into_iter().unzip();
    Some(ArchSpace { topological, not_balls, not_ball_ids })
}

/// A generator read back from its JSON object (`{"dim", "order", "chain"}`).
fn generator_from_json(x: &serde_json::Value) -> Option<NamedGenerator> {
    let chain = x
        .get("chain")?
        .as_array()?
        .iter()
        .map(|e| Some((cell_from_json(e.get("cell")?)?, e.get("coefficient")?.as_i64()?)))
        .collect::<Option<Vec<_>>>()?;
    Some(NamedGenerator {
        dim: usize::try_from(x.get("dim")?.as_u64()?).ok()?,
        order: x.get("order")?.as_number()?.to_string().parse().ok()?,
        chain: Chain::Named(chain),
        length: x.get("length").and_then(serde_json::Value::as_f64),
    })
}

/// A cell's name read back from [`CellName::to_json`].
fn cell_from_json(c: &serde_json::Value) -> Option<CellName> {
    if let Some(a) = c.as_array() {
        return Some(CellName::Simplex(a.iter().map(serde_json::Value::as_u64).collect::<Option<Vec<_>>>()?));
    }
    if let Some(r) = c.get("region") {
        let name = match c.get("name") {
            None => None,
            Some(n) => Some(n.as_str()?.to_string()),
        };
        return Some(match (r.as_u64(), r.as_str(), name) {
            (Some(id), _, None) => CellName::Region(id),
            (Some(id), _, name) => CellName::NamedRegion { id, key: None, name },
            (None, Some(key), name) => CellName::NamedRegion { id: 0, key: Some(key.to_string()), name },
            (None, None, _) => return None,
        });
    }
    if let Some(cube) = c.get("cube") {
        let min = cube.as_array()?.iter().map(serde_json::Value::as_i64).collect::<Option<smallvec::SmallVec<_>>>()?;
        let extent = c
            .get("extent")?
            .as_array()?
            .iter()
            .map(|x| x.as_u64().and_then(|e| u8::try_from(e).ok()).filter(|&e| e <= 1))
            .collect::<Option<smallvec::SmallVec<_>>>()?;
        return (min.len() == extent.len()).then_some(CellName::Cube { min, extent });
    }
    let dart = u32::try_from(c.get("dart")?.as_u64()?).ok()?;
    let simplex = match c.get("simplex") {
        None => None,
        Some(s) => Some(
            s.as_array()?.iter().map(|x| x.as_u64().and_then(|x| u32::try_from(x).ok())).collect::<Option<Vec<_>>>()?,
        ),
    };
    let point = match c.get("point") {
        None => None,
        Some(p) => match p.as_array()?.as_slice() {
            [x, y, z] => Some([x.as_f64()?, y.as_f64()?, z.as_f64()?]),
            _ => return None,
        },
    };
    Some(CellName::Dart { dart, point, simplex })
}
