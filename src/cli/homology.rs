//! `gmap homology FILE [--method cellular|simplicial] [--field P] [--json] [--generators]`.

use std::io::IsTerminal;
use std::path::PathBuf;

use anyhow::{bail, Context, Result};
use gmap_core::DenseMap;
use gmap_homology::arch::{ArchComplex, ZeroWeightRule};
use gmap_homology::{
    cellular_complex, homology_z, homology_zp, is_prime, simplicial_complex_with_simplices, ChainComplex, Homology,
};
use serde_json::json;

use gmap_homology::simplices::{face_estimate, FaceComplex};
use gmap_ops::import::SimplicialComplex;

use super::load::{load, Loaded};
use super::{Method, Via};

/// Options of `gmap homology`.
pub struct Options {
    pub file: PathBuf,
    pub method: Method,
    pub field: Option<u64>,
    pub json: bool,
    pub generators: bool,
    pub simplify: bool,
    pub topological: bool,
    pub max_darts: Option<u64>,
    /// the route of a simplicial complex (`None`: direct unless the options need the G-map)
    pub via: Option<Via>,
    /// `--periodic`: a cubical set's box is a torus
    pub periodic: bool,
}

/// When the command started (for the elapsed times of the progress lines).
static START: std::sync::OnceLock<std::time::Instant> = std::sync::OnceLock::new();

/// Prints a stage message on stderr when it is a terminal (docs/FORMATS.md §1: progress only
/// there), with the time elapsed since the start: `gmap homology: [  0.41 s] reducing…`.
fn progress(msg: &str) {
    if std::io::stderr().is_terminal() {
        let t = START.get_or_init(std::time::Instant::now).elapsed().as_secs_f64();
        eprintln!("gmap homology: [{t:7.2} s] {msg}…");
    }
}

/// A cell of the input, in the input's own terms (docs/FORMATS.md, generators).
enum CellName {
    /// a simplex of a simplicial complex: its vertex labels, increasing
    Simplex(Vec<u64>),
    /// a G-map cell by one of its darts; for the simplicial counterpart, the dimensions of
    /// the cells of that dart spanning the simplex
    Dart { dart: u32, point: Option<[f64; 3]>, simplex: Option<Vec<u32>> },
    /// a region of an architectural complex by its id
    Region(u64),
    /// an elementary cube of a cubical set: its minimal vertex and its extent (0 or 1) per
    /// axis
    Cube { min: Vec<i64>, extent: Vec<u8> },
}

impl CellName {
    fn to_json(&self) -> serde_json::Value {
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

    fn to_text(&self) -> String {
        let list = |v: &[u64]| v.iter().map(u64::to_string).collect::<Vec<_>>().join(",");
        match self {
            CellName::Simplex(v) => format!("[{}]", list(v)),
            CellName::Dart { dart, point, simplex } => {
                let mut t = format!("dart {dart}");
                if let Some(s) = simplex {
                    let s: Vec<u64> = s.iter().map(|&x| u64::from(x)).collect();
                    t = format!("simplex {{{}}} of {t}", list(&s));
                }
                if let Some([x, y, z]) = point {
                    t.push_str(&format!(" at ({x}, {y}, {z})"));
                }
                t
            }
            CellName::Region(id) => format!("region {id}"),
            CellName::Cube { min, extent } => min
                .iter()
                .zip(extent)
                .map(|(&lo, &e)| if e == 1 { format!("[{},{}]", lo, lo + 1) } else { lo.to_string() })
                .collect::<Vec<_>>()
                .join("x"),
        }
    }
}

/// A chain complex with a name for each generator (for `--generators`): `name(k, j)` names
/// k-cell `j` in the input's terms.
struct Named<'a> {
    chain: ChainComplex,
    name: Box<dyn Fn(usize, u32) -> CellName + 'a>,
}

/// The points of a map's darts, when it has any (for naming G-map cells).
fn points(map: &DenseMap) -> Option<Vec<Option<[f64; 3]>>> {
    map.has_points().then(|| map.darts().map(|d| map.point(d)).collect())
}

/// The name of the k-cell with dart `d`: by labels when the map came from a simplicial
/// complex (the k-face of the dart's flag), else by dart (and point).
fn dart_cell(sc: Option<&SimplicialComplex>, pts: &Option<Vec<Option<[f64; 3]>>>, k: usize, d: u32) -> CellName {
    if let Some(face) = sc.and_then(|sc| sc.dart_face(u64::from(d), k)) {
        return CellName::Simplex(face);
    }
    CellName::Dart { dart: d, point: pts.as_ref().and_then(|p| p[d as usize]), simplex: None }
}

fn cellular<'a>(map: &DenseMap, file: &str, sc: Option<&'a SimplicialComplex>) -> Result<Named<'a>> {
    progress("checking C1 and C2 and building the border operator");
    let c = cellular_complex(map)
        .with_context(|| format!("{file}: the cellular method does not apply (use --method simplicial)"))?;
    let reps: Vec<Vec<u32>> = c.reps.iter().map(|r| r.iter().map(|d| d.get()).collect()).collect();
    let pts = points(map);
    Ok(Named { chain: c.chain, name: Box::new(move |k, j| dart_cell(sc, &pts, k, reps[k][j as usize])) })
}

/// Refuses a map whose simplicial counterpart is too big to build (exponential in the
/// dimension): an n-map of N darts has up to `2^(n+1) (N + n + 1)` simplices (building it
/// visits the `2^(n+1)` vertex sets of a flag once per dimension even without darts), and
/// their reduction costs about `n + 1` squared per simplex (the faces of a simplex are
/// many and dense); that product is held to the workspace's work limit
/// ([`gmap_core::resources::DEFAULT_MAX_WORK`]: a one-dart 16-map is built in seconds, a
/// one-dart 17-map is refused, `gmap 30 1` asks for 2^31 simplices); then the memory is
/// checked against the memory limit.
pub(super) fn check_simplicial_size(map: &DenseMap, file: &str) -> Result<()> {
    let n = map.dim() as u32;
    let work = (1u128 << (n + 1)) * (map.dart_count() as u128 + n as u128 + 1);
    let visits = work * (u128::from(n) + 1) * (u128::from(n) + 1);
    if visits > u128::from(gmap_core::resources::DEFAULT_MAX_WORK) {
        bail!(
            "{file}: the simplicial counterpart of a {n}-map of {} darts has up to 2^{} x {} simplices, too many to \
             build (an estimated {visits} steps, over the work limit of {}); the cellular method works on the \
             cells themselves",
            map.dart_count(),
            n + 1,
            map.dart_count().max(1),
            gmap_core::resources::DEFAULT_MAX_WORK
        );
    }
    // each simplex: its flag (dart and vertex set), its key and its n + 1 boundary entries
    let bytes = work.checked_mul(24 + 12 * (n as u128 + 1)).and_then(|b| u64::try_from(b).ok());
    gmap_core::resources::check_memory("the simplicial counterpart", bytes).with_context(|| file.to_string())?;
    Ok(())
}

fn simplicial(map: &DenseMap) -> Named<'static> {
    progress("building the simplicial counterpart");
    let s = simplicial_complex_with_simplices(map);
    let pts = points(map);
    let simplices = s.simplices;
    Named {
        chain: s.chain,
        name: Box::new(move |k, j| {
            let x = &simplices[k][j as usize];
            CellName::Dart {
                dart: x.dart.get(),
                point: pts.as_ref().and_then(|p| p[x.dart.index()]),
                simplex: Some((0..32).filter(|i| x.labels & (1 << i) != 0).collect()),
            }
        }),
    }
}

/// The direct route for a simplicial complex: every face of every facet is a cell
/// (`gmap_homology::simplices`), no G-map. The faces are counted first and refused past
/// `--max-darts` (default: what the available memory holds).
fn direct(sc: &SimplicialComplex, o: &Options, file: &str) -> Result<(usize, Named<'static>)> {
    // the estimate is a pass over the facets: made only for a message that shows
    if std::io::stderr().is_terminal() {
        progress(&format!(
            "enumerating the faces of {} facets (at most {})",
            sc.total_facet_count(),
            face_estimate(sc.facets()).map_or_else(|| "2^64".to_string(), |e| e.to_string())
        ));
    }
    let fc = super::load::face_complex_within(sc, o.max_darts, file, o.generators)?;
    let FaceComplex { chain, vertices, faces } = fc;
    let dim = chain.dim();
    let name = Box::new(move |k: usize, j: u32| {
        let j = j as usize;
        CellName::Simplex(faces[k][j * (k + 1)..(j + 1) * (k + 1)].iter().map(|&v| vertices[v as usize]).collect())
    });
    Ok((dim, Named { chain, name }))
}

/// The chain complex of an architectural complex (`.json`): the completion by zero of its
/// partial boundary matrix (AC Def. 3.9), after Algorithm 8.16 with `--topological`.
fn complex(x: ArchComplex, o: &Options, file: &str) -> Result<Named<'static>> {
    if o.method == Method::Simplicial {
        bail!("{file}: an architectural complex has no simplicial counterpart; use --method cellular");
    }
    let x = if o.topological {
        let t = x.topological(ZeroWeightRule::Closed).with_context(|| format!("{file}: Algorithm 8.16"))?;
        for op in &t.operators {
            progress(&format!("Algorithm 8.16: {op}"));
        }
        t.complex
    } else {
        x
    };
    let ids: Vec<Vec<u64>> =
        (0..=x.dim()).map(|k| x.regions_of_dim(k).iter().map(|&r| x.region(r as usize).id.0).collect()).collect();
    Ok(Named { chain: x.chain_complex(), name: Box::new(move |k, j| CellName::Region(ids[k][j as usize])) })
}

fn compute(c: &ChainComplex, field: Option<u64>) -> Result<Homology> {
    progress(&format!(
        "reducing {} cells ({} matrix entries): collapses, coreductions, then elimination",
        c.counts().iter().sum::<usize>(),
        (1..c.counts().len()).map(|k| c.boundary(k).nnz()).sum::<usize>()
    ));
    Ok(match field {
        Some(p) => homology_zp(c, p)?,
        None => homology_z(c)?,
    })
}

/// The map reduced by `--simplify`, or the map itself where the reduction could change the
/// groups. Removals and contractions keep the homology only when the cells are homology
/// balls (conditions C1 and C2, docs/DESIGN.md): where they fail (a segment with open ends, a
/// map of loose darts), simplifying would merge components and lose classes, so it is skipped,
/// with the reason on stderr when stderr is a terminal. As a guard, a reduction that changes
/// the number of components is dropped too. Either way the groups are those without
/// `--simplify`.
pub fn simplified(map: DenseMap) -> DenseMap {
    progress("checking C1 and C2 before simplifying");
    if let Err(e) = gmap_homology::check_preconditions(&map) {
        note(&format!("--simplify skipped: the cells are not all homology balls ({e})"));
        return map;
    }
    progress("simplifying by removals and contractions of cells");
    let small = gmap_ops::euler::simplify(&map).0;
    if small.component_count() != map.component_count() {
        note("--simplify skipped: the reduction changed the number of components");
        return map;
    }
    small
}

/// A note on stderr when it is a terminal (nothing otherwise: the output stays the same).
fn note(msg: &str) {
    if std::io::stderr().is_terminal() {
        eprintln!("gmap homology: {msg}");
    }
}

/// Which route a simplicial complex (`.facets`, `.lex`) takes: `None` for other inputs.
/// Direct by default; through the G-map with `--via gmap`, `--method simplicial` (the
/// G-map's simplicial counterpart) or `--simplify` (which works on maps).
fn simplicial_route(o: &Options) -> Result<Option<Via>> {
    let simplicial_input = matches!(super::load::extension(&o.file).as_str(), "facets" | "lex");
    let file = o.file.display();
    match (o.via, simplicial_input) {
        (Some(Via::Direct), false) => bail!("{file}: --via direct applies to simplicial complexes (.facets, .lex)"),
        (Some(Via::Direct), true) if o.method == Method::Simplicial || o.simplify => {
            bail!("{file}: --method simplicial and --simplify work on the G-map; use --via gmap")
        }
        (_, false) => Ok(None),
        (Some(v), true) => Ok(Some(v)),
        (None, true) if o.method == Method::Simplicial || o.simplify => Ok(Some(Via::Gmap)),
        (None, true) => Ok(Some(Via::Direct)),
    }
}

pub fn run(o: &Options) -> Result<()> {
    if let Some(p) = o.field {
        if !is_prime(p) || p >= 1 << 31 {
            bail!("--field {p}: the field must be Z/P for a prime P below 2^31");
        }
    }
    START.get_or_init(std::time::Instant::now);
    let file = o.file.display().to_string();
    let route = simplicial_route(o)?;
    if o.topological && route.is_some() {
        bail!("{file}: --topological applies to architectural complexes (.json), not to simplicial complexes");
    }
    progress(&format!("reading {file}"));
    // the complex itself: for the direct route, and to name the G-map's cells by labels
    if o.periodic && !matches!(super::load::extension(&o.file).as_str(), "cub" | "pbm") {
        bail!("{file}: --periodic applies to cubical sets (.cub, .pbm)");
    }
    let sc = if route == Some(Via::Direct) || (route == Some(Via::Gmap) && o.generators) {
        super::load::load_simplicial(&o.file)?
    } else {
        None
    };
    let (dim, named) = if route == Some(Via::Direct) {
        direct(sc.as_ref().expect("a simplicial input"), o, &file)?
    } else {
        match load(&o.file, o.max_darts)? {
            Loaded::Cubical(set) => {
                progress("building the cubical complex");
                let (chain, names) = super::cubical::complex(&set, o, &file)?;
                let name = Box::new(move |k: usize, j: u32| {
                    let (min, extent) = names[k][j as usize].clone();
                    CellName::Cube { min, extent }
                });
                (set.dim(), Named { chain, name })
            }
            Loaded::Map(map) => {
                if o.topological {
                    bail!("{file}: --topological applies to architectural complexes (.json), not to G-maps");
                }
                let map = if o.simplify { simplified(map) } else { map };
                // labels name the cells only while darts are those of the import
                let sc = if o.simplify { None } else { sc.as_ref() };
                let named = match o.method {
                    Method::Cellular => cellular(&map, &file, sc)?,
                    Method::Simplicial => {
                        check_simplicial_size(&map, &file)?;
                        simplicial(&map)
                    }
                };
                (map.dim(), named)
            }
            Loaded::Complex(x) => {
                if o.simplify {
                    bail!("{file}: --simplify applies to G-maps, not to architectural complexes (.json)");
                }
                (x.dim(), complex(x, o, &file)?)
            }
        }
    };
    let h = compute(&named.chain, o.field).with_context(|| file.clone())?;
    let method = match o.method {
        Method::Cellular => "cellular",
        Method::Simplicial => "simplicial",
    };
    let gens = if o.generators {
        progress("computing generators and lifting them to the input's cells");
        Some(gmap_homology::generators::generators(&named.chain, o.field).with_context(|| file.clone())?)
    } else {
        None
    };
    if o.json {
        let mut v = json!({
            "dimension": dim,
            "method": method,
            "coefficients": h.coefficients.to_string(),
            "betti": h.betti,
            "torsion": h.torsion,
            "euler_characteristic": h.euler_characteristic(),
        });
        if let Some(r) = route {
            v["route"] = json!(match r {
                Via::Direct => "direct",
                Via::Gmap => "gmap",
            });
        }
        if let Some(g) = &gens {
            let list: Vec<_> = g
                .iter()
                .map(|x| {
                    json!({
                        "dim": x.dim,
                        "order": x.order,
                        "chain": x.chain.iter().map(|&(cell, coef)| json!({
                            "cell": (named.name)(x.dim, cell).to_json(),
                            "coefficient": coef,
                        })).collect::<Vec<_>>(),
                    })
                })
                .collect();
            v["generators"] = json!(list);
        }
        outln!("{v}")?;
    } else {
        let via = match route {
            Some(Via::Direct) => ", route direct",
            Some(Via::Gmap) => ", route gmap",
            None => "",
        };
        outln!("dimension {dim}, method {method}, coefficients {}{via}", h.coefficients)?;
        for k in 0..h.betti.len() {
            outln!("H_{k} = {}", h.group_string(k))?;
        }
        outln!("euler characteristic {}", h.euler_characteristic())?;
        if let Some(g) = &gens {
            for x in g {
                let order = match (x.order.to_u64(), o.field) {
                    (Some(0), None) => "Z".to_string(),
                    (Some(0), Some(p)) => format!("Z/{p}"),
                    _ => format!("Z/{}", x.order),
                };
                let terms: Vec<String> = x
                    .chain
                    .iter()
                    .map(|&(cell, coef)| format!("{coef:+} {}", (named.name)(x.dim, cell).to_text()))
                    .collect();
                outln!("generator of H_{} ({order}): {}", x.dim, terms.join(" "))?;
            }
        }
    }
    Ok(())
}

/// The `homology` column of `gmap demo`: integer homology written as `(Z, Z + Z/2, 0)`, by
/// the cellular method where C1 and C2 hold, else by the simplicial one (marked `*`).
pub fn demo_homology(m: &DenseMap) -> String {
    let cell = cellular_complex(m).ok().map(|c| homology_z(&c.chain));
    match cell {
        Some(Ok(h)) => h.to_string(),
        Some(Err(e)) => format!("error: {e}"),
        None => match homology_z(&gmap_homology::simplicial_complex(m)) {
            Ok(h) => format!("{h}*"),
            Err(e) => format!("error: {e}"),
        },
    }
}

/// The `cellular = simplicial` column of `gmap demo`: `yes`, `NO`, or `n/a` with the
/// condition that keeps the cellular method from applying.
pub fn demo_agreement(m: &DenseMap) -> String {
    let s = homology_z(&gmap_homology::simplicial_complex(m));
    match cellular_complex(m) {
        Err(gmap_homology::PreconditionError::C1(_)) => "n/a (C1)".to_string(),
        Err(gmap_homology::PreconditionError::C2 { .. }) => "n/a (C2)".to_string(),
        Err(gmap_homology::PreconditionError::SelfBending(_)) => "n/a (self-bending)".to_string(),
        Err(e) => format!("n/a ({e})"),
        Ok(c) => match (homology_z(&c.chain), s) {
            (Ok(a), Ok(b)) if a == b => "yes".to_string(),
            _ => "NO".to_string(),
        },
    }
}
