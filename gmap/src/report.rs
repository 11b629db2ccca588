//! The groups of an input, with the route that computed them and, on request, a
//! representative cycle per summand named in the input's own terms; and their two
//! renderings, the text and the JSON object that `gmap homology` prints (docs/FORMATS.md).

use gmap_homology::generators::Generator;
use gmap_homology::{homology_z, homology_zp, is_prime, Homology};
use serde_json::json;

pub use crate::cell_name::CellName;
use crate::error::{err, Error, ErrorKind, Result};
use crate::input::Input;
use crate::route::{self, HomologyOptions, Method, Named, Via};

/// A representative cycle of one summand, in the input's terms.
#[derive(Clone, Debug)]
pub struct NamedGenerator {
    /// the dimension of the summand
    pub dim: usize,
    /// its order: 0 for a free summand (Z, or the field), k for Z/k
    pub order: gmap_homology::Natural,
    /// the cycle: cells with their coefficients
    pub chain: Chain,
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

/// The result of [`homology`]: the groups, how they were computed, and the generators when
/// asked for.
#[derive(Clone, Debug)]
pub struct Report {
    /// what the input is ([`Input::kind`])
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
    /// the regions that are not balls: their names ([`crate::arch_cells`]'s `region 7
    /// ("kitchen")`), ids and Betti numbers
    pub not_balls: Vec<(String, u64, Vec<usize>)>,
}

impl ArchSpace {
    /// The statement for complex `x`. O(Σ closures of the regions).
    pub fn of(x: &gmap_homology::arch::ArchComplex, topological: bool) -> Self {
        let not_balls = (0..x.regions().len())
            .filter_map(|r| {
                let betti = x.region_betti(r);
                // an edge on two vertices is a ball (its boundary is two points), whatever
                // the count of boundary components says
                let edge = x.region(r).dim == 1 && !x.has_region_betti(r) && x.down(r).len() == 2;
                let ball = edge || (betti.first() == Some(&1) && betti[1..].iter().all(|&b| b == 0));
                (!ball).then(|| (crate::arch_cells::region_name(x, r), x.region(r).id.0, betti))
            })
            .collect();
        ArchSpace { topological, not_balls }
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
            v["not_balls"] =
                json!(self.not_balls.iter().map(|(_, id, b)| json!({"region": id, "betti": b})).collect::<Vec<_>>());
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
                    json!({
                        "dim": x.dim,
                        "order": x.order,
                        "chain": x.chain.iter().map(|(cell, coef)| json!({
                            "cell": cell.to_json(),
                            "coefficient": coef,
                        })).collect::<Vec<_>>(),
                    })
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

/// Refuses a field that is not Z/P for a prime P below 2^31.
pub(crate) fn check_field(field: Option<u64>) -> Result<()> {
    match field {
        Some(p) if !is_prime(p) || p >= 1 << 31 => {
            Err(err!(Usage, "--field {p}: the field must be Z/P for a prime P below 2^31"))
        }
        _ => Ok(()),
    }
}

/// The homology of an input, by the route the command line takes (docs/DESIGN.md): the
/// cellular border operator of a map (or its simplicial counterpart), the direct face complex
/// or the G-map of a simplicial complex, the cubical complex of a cubical set, the completed
/// boundary matrix of an architectural complex. Over Z with torsion, or over Z/p.
///
/// Options that do not fit the input are refused with the reason ([`crate::ErrorKind::Usage`]),
/// so are routes whose conditions fail ([`crate::ErrorKind::Precondition`]) and work over the
/// limits ([`crate::ErrorKind::Limit`]).
pub fn homology(input: &Input, o: &HomologyOptions) -> Result<Report> {
    let file = route::file_of(input);
    if let Some((first, last)) = &o.cubical_box {
        let Input::Cubical(set) = input else {
            return Err(err!(Usage, "{file}: --box applies to cubical sets (.cub, .cel, .pbm)"));
        };
        let boxed = set.with_box(first, last).map_err(|e| err!(Usage, "{file}: --box: {e}"))?;
        let mut inner = o.clone();
        inner.cubical_box = None;
        return homology(&Input::Cubical(set.with_value(boxed)), &inner);
    }
    let cubical = matches!(input, Input::Cubical(_) | Input::Image(_));
    let route = check_options(&file, matches!(input, Input::Simplicial(_)), cubical, o)?;
    if o.level.is_some() && !matches!(input, Input::Image(_)) {
        return Err(err!(Usage, "{file}: --level applies to images (.npy, .complex)"));
    }
    // dimension ≤ 3: the groups in one pass over the cubes, no cubical complex
    let one_pass = match input {
        Input::Cubical(set) if set.is_full() => {
            let bits = set.bits();
            route::cubical_one_pass(set.shape(), |s, out| out.copy_from_slice(&bits[s..s + out.len()]), o, &file)?
        }
        Input::Image(img) => {
            let level = o.level.map_or(gmap_ops::import::Level::Nonzero, gmap_ops::import::Level::AtMost);
            // the layout's own axis order (the axes reversed for C order): the same groups
            route::cubical_one_pass(&img.memory_shape(), |s, out| img.presence(level, s, out), o, &file)?
        }
        _ => None,
    };
    if let Some(groups) = one_pass {
        let (kind, dimension) = (input.kind(), input.dim());
        return Ok(Report {
            kind,
            dimension,
            method: o.method,
            route,
            field: o.field,
            groups,
            generators: None,
            note: None,
            space: None,
        });
    }
    // dimension ≤ 3 with generators: read off union-finds and a sweep, no chain complex
    let with_generators = match input {
        Input::Cubical(set) if set.is_full() => {
            cubical_generators(set.shape(), set.bits(), set.min(), false, o, &file)?
        }
        Input::Image(img) if o.generators && img.memory_shape().len() <= 3 && !o.periodic => {
            let level = o.level.map_or(gmap_ops::import::Level::Nonzero, gmap_ops::import::Level::AtMost);
            o.progress.stage("the image's cubical set");
            let set = img
                .to_cubical_set(level)
                .map_err(|e| Error::from_source(ErrorKind::Limit, &e).context(file.clone()))?;
            cubical_generators(set.shape(), set.bits(), set.min(), false, o, &file)?
        }
        _ => None,
    };
    if let Some((groups, generators)) = with_generators {
        return Ok(Report {
            kind: input.kind(),
            dimension: input.dim(),
            method: o.method,
            route,
            field: o.field,
            groups,
            generators: Some(generators),
            note: None,
            space: None,
        });
    }
    let image_set;
    let mut note = None;
    // the complex names the G-map's cells by labels while the darts are those of the import
    let owned_map;
    let (dim, named) = match input {
        Input::Simplicial(sc) if route == Some(Via::Direct) => (sc.dim(), route::direct(sc, o, &file)?),
        Input::Simplicial(sc) => {
            owned_map = sc.to_gmap_within(o.max_darts)?;
            let (map, sc_names) = if o.simplify {
                let (m, n) = route::simplify_if_safe(owned_map, &o.progress);
                note = n;
                (m, None)
            } else {
                (owned_map, o.generators.then_some(sc.get()))
            };
            (map.dim(), map_route(&map, o, &file, sc_names)?)
        }
        Input::Map(m) => {
            if o.topological {
                return Err(err!(
                    Usage,
                    "{file}: --topological applies to architectural complexes (.json), not to G-maps"
                ));
            }
            if o.simplify {
                let (map, n) = route::simplify_if_safe(m.map().clone(), &o.progress);
                note = n;
                (map.dim(), map_route(&map, o, &file, None)?)
            } else {
                (m.map().dim(), map_route(m.map(), o, &file, None)?)
            }
        }
        Input::Cubical(set) => (set.dim(), route::cubical(set, o, &file)?),
        Input::Image(img) if !o.generators && !route::whole_grid_fits(&img.memory_shape(), o.periodic) => {
            let level = o.level.map_or(gmap_ops::import::Level::Nonzero, gmap_ops::import::Level::AtMost);
            (img.memory_shape().len(), route::cubical_image(img, level, o, &file)?)
        }
        Input::Image(img) => {
            let level = o.level.map_or(gmap_ops::import::Level::Nonzero, gmap_ops::import::Level::AtMost);
            o.progress.stage("the image's cubical set");
            image_set = img
                .to_cubical_set(level)
                .map_err(|e| Error::from_source(ErrorKind::Limit, &e).context(file.clone()))?;
            (image_set.dim(), route::cubical(&image_set, o, &file)?)
        }
        Input::Arch(x) => {
            if o.simplify {
                return Err(err!(
                    Usage,
                    "{file}: --simplify applies to G-maps, not to architectural complexes (.json)"
                ));
            }
            (x.dim(), route::arch(x, o, &file)?)
        }
    };
    if let Some(n) = &note {
        o.progress.note(&format!("gmap homology: {n}"));
    }
    let groups = compute(&named, o).map_err(|e| e.context(file.clone()))?;
    let generators = if o.generators {
        o.progress.stage("computing generators and lifting them to the input's cells");
        let limit = o.max_generator_cells.unwrap_or(gmap_homology::generators::GENERATOR_CELL_LIMIT);
        let g = gmap_homology::generators::generators_within(&named.chain, o.field, limit).map_err(|e| match e {
            gmap_homology::HomologyError::GeneratorsTooLarge { .. } => {
                err!(Limit, "{file}: {e}; the groups are computed without --generators, or raise the limit with --max-generator-cells N (the cost grows as its cube)")
            }
            e => Error::from(e).context(file.clone()),
        })?;
        Some(g.into_iter().map(|x| name_generator(&named, x)).collect())
    } else {
        None
    };
    let space = match input {
        Input::Arch(x) => Some(ArchSpace::of(x, o.topological)),
        _ => None,
    };
    Ok(Report {
        kind: input.kind(),
        dimension: dim,
        method: o.method,
        route,
        field: o.field,
        groups,
        generators,
        note,
        space,
    })
}

/// The groups and a basis of cycles of a full cubical set of dimension ≤ 3 in a box that is
/// not periodic, from union-finds and a sweep over the grid (`gmap_homology::cubical::gens`:
/// a vertex per component, the boundary of each hole or cavity, in 3-D the fundamental
/// cycles of the sweep's forest), in time linear in the cells plus the cycles' length:
/// `shape` and `bits` as for `gmap_homology::cubical::gens`, the cells named by minimal vertex
/// (offset by `min`, the box's minimal vertex) and extent, their axes reversed with
/// `reversed` (a C-ordered array). Over Z/p the same cycles, their coefficients taken in
/// `0..p`. `None` where this route does not apply (no generators asked for, another
/// dimension, a periodic box, the simplicial method) or hands the set on (a 3-D sweep that
/// stops at a vertex, said in a note); the cycles then come from the cubical complex. Public
/// for callers that hold the cubes elsewhere (the Python package).
pub fn cubical_generators(
    shape: &[usize],
    bits: &[u8],
    min: &[i64],
    reversed: bool,
    o: &HomologyOptions,
    file: &str,
) -> Result<Option<(gmap_homology::Homology, Vec<NamedGenerator>)>> {
    if !o.generators
        || shape.len() > 3
        || o.periodic
        || o.method != route::Method::Cellular
        || o.simplify
        || o.topological
    {
        return Ok(None);
    }
    check_field(o.field)?;
    o.progress
        .stage("one pass over the cells: components, the complement's components, the loops of a spanning forest");
    let g = match gmap_homology::cubical::gens::cubical_generators(shape, bits) {
        Ok(g) => g,
        Err(gmap_homology::cubical::CubicalError::NotReduced(why)) => {
            o.progress.note(&format!("{why}: the cubical complex instead"));
            return Ok(None);
        }
        Err(e) => return Err(Error::from_source(ErrorKind::Limit, &e).context(file.to_string())),
    };
    let d = shape.len();
    let betti: Vec<usize> = g.betti.iter().map(|&b| usize::try_from(b).unwrap_or(usize::MAX)).collect();
    let groups = gmap_homology::Homology {
        coefficients: match o.field {
            None => gmap_homology::homology::Coefficients::Integers,
            Some(p) => gmap_homology::homology::Coefficients::Field(p),
        },
        betti,
        torsion: vec![Vec::new(); d + 1],
    };
    let coefficient = |c: i64| match o.field {
        Some(p) => c.rem_euclid(p as i64),
        None => c,
    };
    let grid = std::sync::Arc::new(CubeGrid::new(&g.grid, min, reversed));
    let generators = g
        .generators
        .into_iter()
        .map(|z| {
            let mut cells = z.chain;
            if o.field.is_some() {
                for x in cells.iter_mut() {
                    x.1 = coefficient(x.1);
                }
            }
            NamedGenerator {
                dim: z.dim,
                order: gmap_homology::Natural::from(0u64),
                chain: Chain::Grid { cells, grid: grid.clone() },
            }
        })
        .collect();
    Ok(Some((groups, generators)))
}

/// [`homology`] of the file at `path`: the options are checked against the file's kind (by
/// its extension) before it is read, then the file is opened with `o.max_darts`.
pub fn homology_file(path: impl AsRef<std::path::Path>, o: &HomologyOptions) -> Result<Report> {
    let path = path.as_ref();
    let ext = crate::input::extension(path);
    check_options(
        &path.display().to_string(),
        matches!(ext.as_str(), "facets" | "lex"),
        matches!(ext.as_str(), "cub" | "cel" | "pbm" | "npy" | "complex"),
        o,
    )?;
    o.progress.stage(&format!("reading {}", path.display()));
    let input = crate::input::open_with(path, &crate::input::OpenOptions::max_darts(o.max_darts))?;
    homology(&input, o)
}

/// The checks of the options against the kind of input, in the order the command line
/// makes them; the route of a simplicial complex.
fn check_options(file: &str, simplicial: bool, cubical: bool, o: &HomologyOptions) -> Result<Option<Via>> {
    check_field(o.field)?;
    let route = route::simplicial_route(simplicial, file, o)?;
    if o.topological && route.is_some() {
        return Err(err!(
            Usage,
            "{file}: --topological applies to architectural complexes (.json), not to simplicial complexes"
        ));
    }
    if o.periodic && !cubical {
        return Err(err!(Usage, "{file}: --periodic applies to cubical sets (.cub, .cel, .pbm, .npy, .complex)"));
    }
    Ok(route)
}

/// The chain complex of a map by the method asked for.
fn map_route<'a>(
    map: &gmap_core::DenseMap,
    o: &HomologyOptions,
    file: &str,
    sc: Option<&'a gmap_ops::import::SimplicialComplex>,
) -> Result<Named<'a>> {
    match o.method {
        Method::Cellular => route::cellular(map, file, sc, &o.progress),
        Method::Simplicial => {
            route::check_simplicial_size(map, file)?;
            Ok(route::simplicial(map, &o.progress))
        }
    }
}

fn compute(named: &Named<'_>, o: &HomologyOptions) -> Result<Homology> {
    let c = &named.chain;
    if o.progress.is_visible() {
        o.progress.stage(&format!(
            "reducing {} cells ({} matrix entries): collapses, coreductions, then elimination",
            c.counts().iter().sum::<usize>(),
            (1..c.counts().len()).map(|k| c.boundary(k).nnz()).sum::<usize>()
        ));
    }
    let h = match o.field {
        Some(p) => homology_zp(c, p)?,
        None => homology_z(c)?,
    };
    match &named.relative {
        Some(r) => r.absolute(h).map_err(|e| Error::from_source(ErrorKind::Limit, &e)),
        None => Ok(h),
    }
}

fn name_generator(named: &Named<'_>, x: Generator) -> NamedGenerator {
    NamedGenerator {
        dim: x.dim,
        order: x.order.clone(),
        chain: Chain::Named(x.chain.iter().map(|&(cell, coef)| ((named.name)(x.dim, cell), coef)).collect()),
    }
}
