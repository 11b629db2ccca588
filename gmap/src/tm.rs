//! The architect's checks on a model (`gmap tm check`, `gmap tm views`): Corbett's
//! topological models (TM, `gmap_homology::tm`, docs/TM.md) of an architectural complex
//! (`.json`) or of a G-map, with every cell named as the file names it.
//!
//! [`tm_check`] runs the topological edit check (TM §XI, (7:5), (7:6)) and lists every
//! defect; a model whose only defects are its free (n-1)-cells (the outer walls, floors and
//! roofs of a building given room by room) is closed by the exterior n-cell
//! ([`gmap_homology::tm::TmModel::try_close_with_exterior`]) and checked again.
//! [`tm_views`] lists the view of each (n-1)-cell (TM (7:1)) with the n-cells on its near
//! and far sides (TM (7:3)): for a wall, the rooms on either side; with a cell named, that
//! cell's view (or, for a 1-cell, its section (7:2) with its from and to ends (7:4)) cell
//! by cell. Both are linear in the size of the model (the edit check: O(Σ |B²c| + |G²c|)).

use std::fmt::Write as _;
use std::path::Path;

use gmap_homology::arch::Shape;
use gmap_homology::json;
use gmap_homology::tm::{SignedSet, TmDefect, TmModel};

use crate::error::{err, Error, ErrorKind, Result};
use crate::input::Input;

/// A model and the names of its cells.
struct Named {
    model: TmModel,
    names: Vec<String>,
    /// the keys a user may give for each cell (its name, its string id, its number)
    keys: Vec<Vec<String>>,
}

fn named(input: &Input) -> Result<Named> {
    let file = input.path().display().to_string();
    match input {
        Input::Arch(x) => {
            let names = (0..x.regions().len()).map(|k| x.region_name(k)).collect();
            let keys = (0..x.regions().len())
                .map(|k| {
                    let mut v = vec![x.region(k).id.to_string(), x.region_name(k)];
                    v.extend(x.region_key(k).map(str::to_string));
                    v.extend(x.name_label(k).map(str::to_string));
                    v
                })
                .collect();
            Ok(Named { model: TmModel::from_arch(x), names, keys })
        }
        Input::Map(m) => {
            let model = TmModel::from_map(m.map())
                .map_err(|e| Error::from_source(ErrorKind::Precondition, e).context(format!("{file}: TM model")))?;
            let names = (0..model.len()).map(|c| format!("{}-cell {}", model.cell_dim(c), model.id(c))).collect();
            let keys = (0..model.len()).map(|c| vec![model.id(c).to_string()]).collect();
            Ok(Named { model, names, keys })
        }
        other => Err(err!(
            Unsupported,
            "{file}: a TM model is made from an architectural complex (.json) or a G-map, not from a {}",
            other.kind()
        )),
    }
}

/// What [`tm_check`] found.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct TmCheck {
    /// the model's dimension n
    pub dim: usize,
    /// the number of cells of each dimension `0..=n`
    pub counts: Vec<usize>,
    /// the defects of the model as given, one line each, cells by name
    pub defects: Vec<String>,
    /// when the model is open (free (n-1)-cells only): the defects left once the exterior
    /// n-cell closes it
    pub closed: Option<Vec<String>>,
    /// the metrical edit (TM §X) of a model with points: its tolerance and every failed
    /// continuity or non-intersection condition, cells by name; `None` without points
    pub metric: Option<(f64, Vec<String>)>,
}

impl TmCheck {
    /// Whether the model passes the edit check, as given or once closed by its exterior.
    pub fn passes(&self) -> bool {
        let metric = self.metric.as_ref().is_none_or(|m| m.1.is_empty());
        metric && (self.defects.is_empty() || self.closed.as_ref().is_some_and(Vec::is_empty))
    }

    /// The report, one line per defect.
    pub fn to_text(&self) -> String {
        let counts: Vec<String> = self.counts.iter().map(usize::to_string).collect();
        let mut s = if counts.is_empty() {
            "TM model: none (the file is not a complex)\n".to_string()
        } else {
            format!("TM model of dimension {}, cells (0..n) {}\n", self.dim, counts.join(" "))
        };
        let _ = writeln!(s, "defects: {}", self.defects.len());
        for d in &self.defects {
            let _ = writeln!(s, "  {d}");
        }
        match &self.closed {
            Some(c) if c.is_empty() => {
                let _ = writeln!(
                    s,
                    "closed by the exterior {}-cell: no defect (the defects above are its free faces)",
                    self.dim
                );
            }
            Some(c) => {
                let _ = writeln!(
                    s,
                    "closed by the exterior {}-cell: {} defect{}",
                    self.dim,
                    c.len(),
                    if c.len() == 1 { "" } else { "s" }
                );
                for d in c {
                    let _ = writeln!(s, "  {d}");
                }
            }
            None => {}
        }
        if let Some((tol, m)) = &self.metric {
            match m.len() {
                0 => {
                    let _ = writeln!(s, "metrical edit (TM X, tolerance {tol:e}): no defect");
                }
                k => {
                    let _ = writeln!(
                        s,
                        "metrical edit (TM X, tolerance {tol:e}): {k} defect{}",
                        if k == 1 { "" } else { "s" }
                    );
                }
            }
            for d in m {
                let _ = writeln!(s, "  {d}");
            }
        }
        s.push_str(if self.passes() { "passes the edit check\n" } else { "fails the edit check\n" });
        s
    }
}

/// How the n-cells on a cell take it: `+1`, `-1`, `+2/-1`.
fn taken(plus: u64, minus: u64) -> String {
    match (plus, minus) {
        (p, 0) => format!("+{p}"),
        (0, m) => format!("-{m}"),
        (p, m) => format!("+{p}/-{m}"),
    }
}

/// A defect with the cells named.
fn describe(d: &TmDefect, t: &TmModel, names: &dyn Fn(usize) -> String) -> String {
    let name = |id: u64| t.index_of(id).map_or_else(|| id.to_string(), names);
    match *d {
        TmDefect::BoundaryNotCircuit { cell, dim, at, plus, minus } => format!(
            "(7:5) the boundary of {dim}-cell {} is not a circuit: {} occurs +{plus}/-{minus} times in its boundary",
            name(cell),
            name(at)
        ),
        TmDefect::CoboundaryNotCocircuit { cell, dim, at, plus, minus } if at == cell && plus + minus == 1 => {
            format!(
                "(7:6) the coboundary of {dim}-cell {} is not a cocircuit: it lies on one {}-cell only (taken {}), a free face",
                name(cell),
                dim + 1,
                taken(plus, minus)
            )
        }
        TmDefect::CoboundaryNotCocircuit { cell, dim, at, plus, minus } if at == cell => format!(
            "(7:6) the coboundary of {dim}-cell {} is not a cocircuit: the {}-cells on it take it {}, not once each way",
            name(cell),
            dim + 1,
            taken(plus, minus)
        ),
        TmDefect::CoboundaryNotCocircuit { cell, dim, at, plus, minus } => format!(
            "(7:6) the coboundary of {dim}-cell {} is not a cocircuit: {} occurs {} times in the coboundary of its coboundary",
            name(cell),
            name(at),
            taken(plus, minus)
        ),
        ref other => other.to_string(),
    }
}

/// The topological edit check of the input's TM model (module docs). Refuses inputs that
/// are not an architectural complex or a G-map.
pub fn tm_check(input: &Input) -> Result<TmCheck> {
    let n = named(input)?;
    let t = &n.model;
    let dim = t.dim();
    let counts = (0..=dim).map(|k| t.regions_of_dim(k).len()).collect();
    let defects = t.edit_defects();
    let name = |c: usize| n.names[c].clone();
    let text: Vec<String> = defects.iter().map(|d| describe(d, t, &name)).collect();
    // only free faces: a coboundary defect of an (n-1)-cell with one n-cell on it
    let open = dim >= 1
        && !defects.is_empty()
        && defects.iter().all(|d| matches!(d, TmDefect::CoboundaryNotCocircuit { dim: k, .. } if k + 1 == dim));
    let closed = if open {
        let id = (0..t.len()).map(|c| t.id(c)).max().map_or(0, |m| m.saturating_add(1));
        match t.try_close_with_exterior(id) {
            Ok((c, e)) => {
                let name = |k: usize| if k == e { "the exterior".to_string() } else { n.names[k].clone() };
                Some(c.edit_defects().iter().map(|d| describe(d, &c, &name)).collect())
            }
            Err(_) => None,
        }
    } else {
        None
    };
    let metric = match input {
        Input::Arch(x) if (0..x.regions().len()).any(|k| x.region_point(k).is_some()) => {
            let shape = Shape::of(x);
            let names = x.region_names();
            Some((shape.tolerance(), shape.defects().iter().map(|d| d.named(&names).to_string()).collect()))
        }
        Input::Map(m) if m.map().has_points() => map_metric(m.map(), &n.names),
        _ => None,
    };
    Ok(TmCheck { dim, counts, defects: text, closed, metric })
}

/// The metrical edit (TM §X) of a G-map with points: its cells numbered as the TM model
/// numbers them (the 0-cells first, each dimension in the order of `DenseMap::cells`), each
/// 0-cell at the point of its vertex, the cells adjacent in consecutive dimensions, the
/// defects named as the topological ones (`2-cell 7`). `None` when the cells' incidences
/// cannot be counted (the topological check says why). O(Shape's check) after the cells.
fn map_metric(map: &gmap_core::DenseMap, names: &[String]) -> Option<(f64, Vec<String>)> {
    use gmap_homology::arch::{Region, RegionId, RegionNames};
    let n = map.dim();
    let counts = map.cell_counts();
    let mut offset = vec![0u64; n + 2];
    for k in 0..=n {
        offset[k + 1] = offset[k] + counts[k] as u64;
    }
    let regions: Vec<Region> = (0..=n)
        .flat_map(|k| {
            let start = offset[k];
            (0..counts[k] as u64).map(move |j| Region { id: RegionId(start + j), dim: k })
        })
        .collect();
    let incidences = gmap_homology::arch::all_cell_incidences(map).ok()?;
    let entries: Vec<(RegionId, RegionId)> = incidences
        .iter()
        .enumerate()
        .flat_map(|(k, list)| {
            let (up, low) = (offset[k + 1], offset[k]);
            list.iter().map(move |c| (RegionId(up + c.upper as u64), RegionId(low + c.lower as u64)))
        })
        .collect();
    let vertices = map.cells(0);
    let points: std::collections::HashMap<RegionId, [f64; 3]> = vertices
        .cell_ids()
        .filter_map(|v| map.vertex_point(vertices.rep(v)).map(|p| (RegionId(u64::from(u32::from(v))), p)))
        .collect();
    let shape = Shape::new(&regions, entries.into_iter(), &points);
    let mut region_names = RegionNames::new();
    for (k, name) in names.iter().enumerate() {
        region_names.insert(RegionId(k as u64), name.clone());
    }
    Some((shape.tolerance(), shape.defects().iter().map(|d| d.named(&region_names).to_string()).collect()))
}

/// [`tm_check`] of the file at `path`. A `.json` complex whose points do not conform is
/// read all the same and its metrical defects listed (the reader refuses it); one that
/// cannot be read as a complex at all has that as its one topological defect.
pub fn tm_check_file(path: impl AsRef<Path>) -> Result<TmCheck> {
    let path = path.as_ref();
    if path.extension().and_then(|e| e.to_str()) != Some("json") || !path.is_file() {
        return tm_check(&crate::open(path)?);
    }
    let text = std::fs::read_to_string(path).map_err(|e| err!(Parse, "{}: cannot read: {e}", path.display()))?;
    let parse = |e: json::JsonError| Error::from_source(ErrorKind::Parse, e).context(path.display().to_string());
    let (found, names, tol) = json::json_metric_defects(&text).map_err(parse)?;
    let metric = (!names.is_empty() || !found.is_empty())
        .then(|| (tol, found.iter().map(|d| d.named(&names).to_string()).collect()));
    match json::read_json_with(&text, &json::JsonOptions::accepting_nonconforming()) {
        Ok((x, _)) => {
            let input = Input::Arch(crate::Sourced::new(x));
            let mut c = tm_check(&input)?;
            c.metric = c.metric.map(|m| (m.0, metric.map_or(m.1, |x| x.1)));
            Ok(c)
        }
        Err(e) => Ok(TmCheck {
            dim: 0,
            counts: Vec::new(),
            defects: vec![format!("the file is not a complex: {e}")],
            closed: None,
            metric,
        }),
    }
}

/// The signed occurrences of a cell, `+1`, `-1`, `+1/-1`.
fn signs(p: u64, m: u64) -> String {
    match (p, m) {
        (p, 0) => format!("+{p}"),
        (0, m) => format!("-{m}"),
        (p, m) => format!("+{p}/-{m}"),
    }
}

/// The views of a model's (n-1)-cells (TM (7:1), (7:3)), or one cell's view or section
/// cell by cell (module docs). `cell` is a name, a string id or a number of the file.
pub fn tm_views(input: &Input, cell: Option<&str>) -> Result<String> {
    let n = named(input)?;
    let t = &n.model;
    let file = input.path().display().to_string();
    let dim = t.dim();
    let side = |c: Option<usize>| c.map_or_else(|| "nothing".to_string(), |c| n.names[c].clone());
    let mut s = String::new();
    let Some(key) = cell else {
        if dim == 0 {
            return Err(err!(Precondition, "{file}: a model of dimension 0 has no views"));
        }
        let _ = writeln!(s, "views of the {}-cells (TM 7:1) and the {dim}-cells on their sides (TM 7:3):", dim - 1);
        for &c in t.regions_of_dim(dim - 1) {
            let view = t.view(&SignedSet::cell(c));
            let mut per_dim = vec![0usize; dim];
            for (x, _, _) in view.iter() {
                per_dim[t.cell_dim(x)] += 1;
            }
            let parts: Vec<String> = (0..dim - 1).rev().map(|k| format!("{} {k}-cells", per_dim[k])).collect();
            let sides = match t.try_sides(c) {
                Ok(sd) => format!("near {}, far {}", side(sd.near), side(sd.far)),
                Err(e) => format!("no near and far: {e}"),
            };
            let _ = writeln!(s, "  {}: {sides}; boundary {}", n.names[c], parts.join(", "));
        }
        return Ok(s);
    };
    let c = (0..t.len())
        .find(|&c| n.keys[c].iter().any(|k| k == key))
        .ok_or_else(|| err!(Usage, "{file}: no cell is called '{key}'"))?;
    let k = t.cell_dim(c);
    let (what, set) = if k == 1 && dim != 2 {
        ("section (TM 7:2)", t.section(&SignedSet::cell(c)))
    } else {
        ("view (TM 7:1)", t.view(&SignedSet::cell(c)))
    };
    let _ = writeln!(s, "{what} of {k}-cell {}: {} cells", n.names[c], set.len());
    if k + 1 == dim {
        if let Ok(sd) = t.try_sides(c) {
            let _ = writeln!(s, "near {}, far {} (TM 7:3)", side(sd.near), side(sd.far));
        }
    }
    if k == 1 {
        if let Ok(e) = t.try_ends(c) {
            let _ = writeln!(s, "from {} to {} (TM 7:4)", side(e.from), side(e.to));
        }
    }
    let mut rows: Vec<(usize, String, String)> =
        set.iter().map(|(x, p, m)| (t.cell_dim(x), n.names[x].clone(), signs(p, m))).collect();
    rows.sort_by(|a, b| b.0.cmp(&a.0).then_with(|| a.1.cmp(&b.1)));
    for (d, name, sg) in rows {
        let _ = writeln!(s, "  {d}-cell {name} {sg}");
    }
    Ok(s)
}

/// [`tm_views`] of the file at `path`.
pub fn tm_views_file(path: impl AsRef<Path>, cell: Option<&str>) -> Result<String> {
    tm_views(&crate::open(path.as_ref())?, cell)
}
