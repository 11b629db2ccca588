//! Homology of any input the package takes, with the command line's routes, checks and
//! cell names (`gmap homology`, docs/FORMATS.md): the direct route for simplicial complexes,
//! the cellular border operator (or the simplicial counterpart) for G-maps, the cubical
//! complex for cubical sets, the completion by zero for architectural complexes.
//!
//! Nothing here touches Python: the functions run with the GIL released.

use gmap_core::DenseMap;
use gmap_homology::arch::ArchComplex;
use gmap_homology::generators::generators;
use gmap_homology::simplices::{face_complex_of, face_estimate};
use gmap_homology::{cellular_complex, homology_z, homology_zp, is_prime, ChainComplex, Homology, Natural};
use gmap_ops::import::SimplicialComplex;

use crate::errors::{Failure, Kind, Res};

/// Complexes of at most this many faces (counted with repetition) take the direct route
/// without a look at the memory available: their tables take a few megabytes.
const SMALL_FACES: u64 = 1 << 16;

/// Which chain complex of a G-map is reduced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// the cellular border operator, on the cells themselves
    Cellular,
    /// the simplicial counterpart: one n-simplex per dart
    Simplicial,
}

/// How a simplicial complex is taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Via {
    /// every face of every facet a cell
    Direct,
    /// through the G-map of the facets
    Gmap,
}

/// The options of one computation (those of `gmap homology`).
#[derive(Clone, Copy, Debug)]
pub struct Options {
    pub field: Option<u64>,
    pub generators: bool,
    pub method: Method,
    pub via: Option<Via>,
    pub periodic: bool,
}

/// A cubical set given by its bitmap: `bits[x_0 + s_0 (x_1 + …)]` non-zero for a cube
/// (axis 0 fastest). `reversed`: the caller's axes are those of `shape` in reverse order
/// (a C-ordered numpy array), so cube coordinates are given back reversed.
pub struct Cubes<'a> {
    pub shape: &'a [usize],
    pub bits: &'a [u8],
    pub min: &'a [i64],
    pub reversed: bool,
}

/// What a computation runs on.
pub enum Input<'a> {
    /// a G-map; with the simplicial complex it was made from, to name cells by labels
    Map { map: &'a DenseMap, sc: Option<&'a SimplicialComplex> },
    /// a simplicial complex by its facets
    Simplicial(&'a SimplicialComplex),
    /// a full cubical set
    Cubical(Cubes<'a>),
    /// an architectural complex
    Arch(&'a ArchComplex),
}

/// A cell of the input in the input's own terms.
#[derive(Clone, Debug, PartialEq)]
pub enum CellName {
    /// a simplex by its vertex labels, increasing
    Simplex(Vec<u64>),
    /// a G-map cell by one of its darts (and the dart's point; for the simplicial counterpart
    /// the dimensions of the dart's cells spanning the simplex)
    Dart { dart: u32, point: Option<[f64; 3]>, simplex: Option<Vec<u32>> },
    /// a region of an architectural complex
    Region(u64),
    /// an elementary cube: minimal vertex, extent per axis
    Cube { min: Vec<i64>, extent: Vec<u8> },
}

impl CellName {
    /// The command line's JSON of the cell.
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::json;
        match self {
            CellName::Simplex(v) => json!(v),
            CellName::Dart { dart, point, simplex } => {
                let mut v = json!({ "dart": dart });
                if let Some(s) = simplex {
                    v["simplex"] = json!(s);
                }
                if let Some(p) = point {
                    v["point"] = json!(p);
                }
                v
            }
            CellName::Region(id) => json!({ "region": id }),
            CellName::Cube { min, extent } => json!({ "cube": min, "extent": extent }),
        }
    }
}

/// A representative cycle of one summand.
pub struct Gen {
    pub dim: usize,
    pub order: Natural,
    pub cells: Vec<CellName>,
    pub coefficients: Vec<i64>,
}

/// The result of a computation: what `gmap homology --json` prints.
pub struct Report {
    pub dim: usize,
    pub method: Method,
    pub homology: Homology,
    pub route: Option<Via>,
    pub generators: Option<Vec<Gen>>,
}

impl Report {
    /// The command line's `--json` object.
    pub fn to_json(&self) -> serde_json::Value {
        use serde_json::json;
        let h = &self.homology;
        let mut v = json!({
            "dimension": self.dim,
            "method": match self.method { Method::Cellular => "cellular", Method::Simplicial => "simplicial" },
            "coefficients": h.coefficients.to_string(),
            "betti": h.betti,
            "torsion": h.torsion,
            "euler_characteristic": h.euler_characteristic(),
        });
        if let Some(r) = self.route {
            v["route"] = json!(route_name(r));
        }
        if let Some(g) = &self.generators {
            let list: Vec<_> = g
                .iter()
                .map(|x| {
                    json!({
                        "dim": x.dim,
                        "order": x.order,
                        "chain": x.cells.iter().zip(&x.coefficients).map(|(c, k)| json!({
                            "cell": c.to_json(),
                            "coefficient": k,
                        })).collect::<Vec<_>>(),
                    })
                })
                .collect();
            v["generators"] = json!(list);
        }
        v
    }
}

pub fn route_name(r: Via) -> &'static str {
    match r {
        Via::Direct => "direct",
        Via::Gmap => "gmap",
    }
}

/// A chain complex with a name for each cell.
type Namer<'a> = Box<dyn Fn(usize, u32) -> CellName + 'a>;

fn points(map: &DenseMap) -> Option<Vec<Option<[f64; 3]>>> {
    map.has_points().then(|| map.darts().map(|d| map.point(d)).collect())
}

fn dart_cell(sc: Option<&SimplicialComplex>, pts: &Option<Vec<Option<[f64; 3]>>>, k: usize, d: u32) -> CellName {
    if let Some(face) = sc.and_then(|sc| sc.dart_face(u64::from(d), k)) {
        return CellName::Simplex(face);
    }
    CellName::Dart { dart: d, point: pts.as_ref().and_then(|p| p[d as usize]), simplex: None }
}

/// Refuses a map whose simplicial counterpart is too big to build (the command line's
/// check: `2^(n+1) (N + n + 1)` simplices, `(n + 1)^2` work each, held to the work limit,
/// then their memory to the memory limit).
fn check_simplicial_size(map: &DenseMap) -> Res<()> {
    let n = map.dim() as u32;
    let work = (1u128 << (n + 1)) * (map.dart_count() as u128 + n as u128 + 1);
    let visits = work * (u128::from(n) + 1) * (u128::from(n) + 1);
    if visits > u128::from(gmap_core::resources::DEFAULT_MAX_WORK) {
        return Err(Failure::new(
            Kind::Limit,
            format!(
                "the simplicial counterpart of a {n}-map of {} darts has up to 2^{} x {} simplices, too many to \
                 build (an estimated {visits} steps, over the work limit of {}); the cellular method works on the \
                 cells themselves",
                map.dart_count(),
                n + 1,
                map.dart_count().max(1),
                gmap_core::resources::DEFAULT_MAX_WORK
            ),
        ));
    }
    let bytes = work.checked_mul(24 + 12 * (n as u128 + 1)).and_then(|b| u64::try_from(b).ok());
    gmap_core::resources::check_memory("the simplicial counterpart", bytes)?;
    Ok(())
}

/// The G-map of a simplicial complex (pure pseudo-manifolds), within the default dart
/// limit and the memory limit.
pub fn gmap_of(sc: &SimplicialComplex) -> Res<DenseMap> {
    // past the largest dart index no memory helps: the dart count is the refusal
    let cap = u32::MAX as u64 - 1;
    if sc.dart_count().is_none_or(|d| d > cap) {
        return Ok(sc.to_gmap(cap)?);
    }
    gmap_core::resources::check_memory("the G-map of the facets", sc.memory_estimate())?;
    let limit = gmap_ops::import::default_max_darts(sc.dim());
    Ok(sc.to_gmap(limit)?)
}

fn map_chain<'a>(
    map: &'a DenseMap,
    sc: Option<&'a SimplicialComplex>,
    o: &Options,
    name: &str,
) -> Res<(ChainComplex, Namer<'a>)> {
    let pts = points(map);
    match o.method {
        Method::Cellular => {
            let c = cellular_complex(map).map_err(|e| {
                let f: Failure = e.into();
                Failure::new(
                    f.kind,
                    format!("{name}: the cellular method does not apply (use --method simplicial): {}", f.message),
                )
            })?;
            let reps: Vec<Vec<u32>> = c.reps.iter().map(|r| r.iter().map(|d| d.index() as u32).collect()).collect();
            Ok((c.chain, Box::new(move |k, j| dart_cell(sc, &pts, k, reps[k][j as usize]))))
        }
        Method::Simplicial => {
            check_simplicial_size(map).map_err(|f| f.in_file(name))?;
            let s = gmap_homology::simplicial_complex_with_simplices(map);
            let simplices = s.simplices;
            Ok((
                s.chain,
                Box::new(move |k, j| {
                    let x = &simplices[k][j as usize];
                    CellName::Dart {
                        dart: x.dart.index() as u32,
                        point: pts.as_ref().and_then(|p| p[x.dart.index()]),
                        simplex: Some((0..32).filter(|i| x.labels & (1 << i) != 0).collect()),
                    }
                }),
            ))
        }
    }
}

/// The homology of `input` with the options `o`; `name` (a file name, or a description of
/// the object) opens the messages, as the file does on the command line.
pub fn homology(input: &Input<'_>, o: &Options, name: &str) -> Res<Report> {
    if let Some(p) = o.field {
        if !is_prime(p) || p >= 1 << 31 {
            return Err(Failure::input(format!("--field {p}: the field must be Z/P for a prime P below 2^31")));
        }
    }
    if o.periodic && !matches!(input, Input::Cubical(_)) {
        return Err(Failure::input(format!("{name}: --periodic applies to cubical sets (.cub, .pbm)")));
    }
    let route = match input {
        Input::Simplicial(_) => match (o.via, o.method) {
            (Some(Via::Direct), Method::Simplicial) => {
                return Err(Failure::input(format!(
                    "{name}: --method simplicial and --simplify work on the G-map; use --via gmap"
                )))
            }
            (Some(v), _) => Some(v),
            (None, Method::Simplicial) => Some(Via::Gmap),
            (None, Method::Cellular) => Some(Via::Direct),
        },
        _ if o.via == Some(Via::Direct) => {
            return Err(Failure::input(format!(
                "{name}: --via direct applies to simplicial complexes (.facets, .lex)"
            )))
        }
        _ => None,
    };
    let owned_map;
    let (dim, chain, namer): (usize, ChainComplex, Namer<'_>) = match input {
        Input::Simplicial(sc) if route == Some(Via::Direct) => {
            // below SMALL_FACES faces (a few MB at most) the memory budget, which reads
            // /proc/meminfo, is not consulted: a call on a small complex costs microseconds
            let small = face_estimate(sc.facets()).is_some_and(|e| e <= SMALL_FACES);
            let limit = if small { SMALL_FACES } else { gmap_ops::import::default_max_faces(sc.dim()) };
            let fc = face_complex_of(sc.facets(), limit, o.generators).map_err(|e| Failure::from(e).in_file(name))?;
            let gmap_homology::simplices::FaceComplex { chain, vertices, faces } = fc;
            let namer: Namer<'_> = Box::new(move |k: usize, j: u32| {
                let j = j as usize;
                CellName::Simplex(faces[k][j * (k + 1)..(j + 1) * (k + 1)].iter().map(|&v| vertices[v as usize]).collect())
            });
            (chain.dim(), chain, namer)
        }
        Input::Simplicial(sc) => {
            owned_map = gmap_of(sc).map_err(|f| f.in_file(name))?;
            let (chain, namer) = map_chain(&owned_map, Some(sc), o, name)?;
            (owned_map.dim(), chain, namer)
        }
        Input::Map { map, sc } => {
            let (chain, namer) = map_chain(map, *sc, o, name)?;
            (map.dim(), chain, namer)
        }
        Input::Cubical(c) => {
            if o.method == Method::Simplicial {
                return Err(Failure::input(format!(
                    "{name}: a cubical set has no simplicial counterpart here; use --method cellular"
                )));
            }
            let cc = gmap_homology::cubical::cubical_complex_with(c.shape, c.bits, o.periodic, true)
                .map_err(|e| Failure::from(e).in_file(name))?;
            let min = c.min.to_vec();
            let reversed = c.reversed;
            let gmap_homology::cubical::CubicalComplex { chain, cells, grid } = cc;
            let namer: Namer<'_> = Box::new(move |k: usize, j: u32| {
                let mut p = cells[k][j as usize] as usize;
                let mut lo = Vec::with_capacity(grid.len());
                let mut extent = Vec::with_capacity(grid.len());
                for (a, &n) in grid.iter().enumerate() {
                    let x = p % n;
                    p /= n;
                    lo.push(min.get(a).copied().unwrap_or(0) + (x / 2) as i64);
                    extent.push((x % 2) as u8);
                }
                if reversed {
                    lo.reverse();
                    extent.reverse();
                }
                CellName::Cube { min: lo, extent }
            });
            (c.shape.len(), chain, namer)
        }
        Input::Arch(x) => {
            if o.method == Method::Simplicial {
                return Err(Failure::input(format!(
                    "{name}: an architectural complex has no simplicial counterpart; use --method cellular"
                )));
            }
            let ids: Vec<Vec<u64>> = (0..=x.dim())
                .map(|k| x.regions_of_dim(k).iter().map(|&r| x.region(r as usize).id.0).collect())
                .collect();
            (x.dim(), x.chain_complex(), Box::new(move |k, j| CellName::Region(ids[k][j as usize])))
        }
    };
    let h = match o.field {
        Some(p) => homology_zp(&chain, p),
        None => homology_z(&chain),
    }
    .map_err(|e| Failure::from(e).in_file(name))?;
    let gens = if o.generators {
        let g = generators(&chain, o.field).map_err(|e| Failure::from(e).in_file(name))?;
        Some(
            g.into_iter()
                .map(|x| Gen {
                    dim: x.dim,
                    cells: x.chain.iter().map(|&(c, _)| namer(x.dim, c)).collect(),
                    coefficients: x.chain.iter().map(|&(_, k)| k).collect(),
                    order: x.order,
                })
                .collect(),
        )
    } else {
        None
    };
    Ok(Report { dim, method: o.method, homology: h, route, generators: gens })
}

/// A report read back from its JSON object ([`Report::to_json`]): how a result crosses a
/// process boundary (pickling). `None` when the object is not such a report.
pub fn report_from_json(v: &serde_json::Value) -> Option<Report> {
    use gmap_homology::Coefficients;
    let nat = |x: &serde_json::Value| -> Option<Natural> { x.to_string().parse().ok() };
    let coefficients = match v["coefficients"].as_str()? {
        "Z" => Coefficients::Integers,
        s => Coefficients::Field(s.strip_prefix("Z/")?.parse().ok()?),
    };
    let betti = v["betti"].as_array()?.iter().map(|b| b.as_u64().map(|b| b as usize)).collect::<Option<Vec<_>>>()?;
    let torsion = v["torsion"]
        .as_array()?
        .iter()
        .map(|t| t.as_array().and_then(|t| t.iter().map(nat).collect::<Option<Vec<_>>>()))
        .collect::<Option<Vec<_>>>()?;
    let method = match v["method"].as_str()? {
        "simplicial" => Method::Simplicial,
        _ => Method::Cellular,
    };
    let route = match v.get("route").and_then(|r| r.as_str()) {
        Some("direct") => Some(Via::Direct),
        Some("gmap") => Some(Via::Gmap),
        _ => None,
    };
    let cell = |c: &serde_json::Value| -> Option<CellName> {
        if let Some(a) = c.as_array() {
            return Some(CellName::Simplex(a.iter().map(|x| x.as_u64()).collect::<Option<Vec<_>>>()?));
        }
        if let Some(r) = c.get("region") {
            return Some(CellName::Region(r.as_u64()?));
        }
        if let Some(cube) = c.get("cube") {
            let min = cube.as_array()?.iter().map(|x| x.as_i64()).collect::<Option<Vec<_>>>()?;
            let extent =
                c["extent"].as_array()?.iter().map(|x| x.as_u64().map(|e| e as u8)).collect::<Option<Vec<_>>>()?;
            return Some(CellName::Cube { min, extent });
        }
        let dart = c.get("dart")?.as_u64()? as u32;
        let simplex = match c.get("simplex") {
            Some(s) => Some(s.as_array()?.iter().map(|x| x.as_u64().map(|x| x as u32)).collect::<Option<Vec<_>>>()?),
            None => None,
        };
        let point = match c.get("point") {
            Some(p) => {
                let p = p.as_array()?;
                Some([p.first()?.as_f64()?, p.get(1)?.as_f64()?, p.get(2)?.as_f64()?])
            }
            None => None,
        };
        Some(CellName::Dart { dart, point, simplex })
    };
    let generators = match v.get("generators") {
        Some(g) => Some(
            g.as_array()?
                .iter()
                .map(|x| {
                    let chain = x["chain"].as_array()?;
                    Some(Gen {
                        dim: x["dim"].as_u64()? as usize,
                        order: nat(&x["order"])?,
                        cells: chain.iter().map(|e| cell(&e["cell"])).collect::<Option<Vec<_>>>()?,
                        coefficients: chain.iter().map(|e| e["coefficient"].as_i64()).collect::<Option<Vec<_>>>()?,
                    })
                })
                .collect::<Option<Vec<_>>>()?,
        ),
        None => None,
    };
    Some(Report {
        dim: v["dimension"].as_u64()? as usize,
        method,
        homology: Homology { coefficients, betti, torsion },
        route,
        generators,
    })
}
