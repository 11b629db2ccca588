//! Which chain complex an input's homology is computed on, and building it.
//!
//! | input | route | chain complex |
//! |---|---|---|
//! | map | `cellular` (default) | the cells and the border operator (BO Def. 10), under C1/C2 |
//! | map | `simplicial` | the simplicial counterpart: one n-simplex per dart (BO §6) |
//! | simplicial complex | `direct` (default) | every face of every facet a cell |
//! | simplicial complex | `gmap` | the G-map of the facets, then a map route |
//! | cubical set | `cubical` | the cubical complex of the closure, free faces collapsed |
//! | architectural complex | `cellular` | the completion by zero of its boundary matrix (AC Def. 3.9) |
//!
//! A simplicial complex goes through its G-map when asked (`via = Gmap`) or when the options
//! need a map (`--method simplicial`, `--simplify`). Simplifying a map is done only when it
//! keeps the groups ([`simplify_if_safe`]).

use gmap_core::DenseMap;
use gmap_homology::arch::ZeroWeightRule;
use gmap_homology::simplices::{face_complex_of, FaceComplex, FaceError};
use gmap_homology::{cellular_complex, simplicial_complex_with_simplices, ChainComplex};
use gmap_ops::import::SimplicialComplex;

use crate::cell_name::CellName;
use crate::error::{err, Error, ErrorKind, Result};
use crate::input::Input;
use crate::progress::Progress;

/// Which chain complex of a map is reduced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// the cellular border operator (BO Def. 10), on the cells themselves
    #[default]
    Cellular,
    /// the simplicial counterpart (BO §6): one n-simplex per dart
    Simplicial,
}

impl Method {
    /// `"cellular"` or `"simplicial"`.
    pub fn name(self) -> &'static str {
        match self {
            Method::Cellular => "cellular",
            Method::Simplicial => "simplicial",
        }
    }
}

/// How a simplicial complex (`.facets`, `.lex`) is taken.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Via {
    /// every face of every facet is a cell (any simplicial complex)
    Direct,
    /// through the G-map of the facets (pure pseudo-manifolds)
    Gmap,
}

impl Via {
    /// `"direct"` or `"gmap"`.
    pub fn name(self) -> &'static str {
        match self {
            Via::Direct => "direct",
            Via::Gmap => "gmap",
        }
    }
}

/// The options of [`crate::homology`], as the command line's flags.
#[derive(Clone, Debug, Default)]
#[non_exhaustive]
pub struct HomologyOptions {
    /// cellular (default) or simplicial
    pub method: Method,
    /// a prime P: compute over Z/P (default: over Z)
    pub field: Option<u64>,
    /// a representative cycle for each summand
    pub generators: bool,
    /// the most cells with entries per dimension of the reduced complex for which generators
    /// are computed (default: `gmap_homology::generators::GENERATOR_CELL_LIMIT`, 2,000; full
    /// cubical sets of dimension ≤ 3 have their own route, `crate::report::cubical_generators`)
    pub max_generator_cells: Option<usize>,
    /// reduce a map by homology-preserving removals and contractions first
    pub simplify: bool,
    /// an architectural complex: Algorithm 8.16 first (topological Betti numbers)
    pub topological: bool,
    /// refuse maps of more darts than this
    pub max_darts: Option<u64>,
    /// the direct route of a simplicial complex: refuse more faces than this (default: what
    /// the memory budget holds)
    pub max_cells: Option<u64>,
    /// a simplicial complex's route (`None`: direct unless the options need the G-map)
    pub via: Option<Via>,
    /// a cubical set's box is a torus (opposite faces identified)
    pub periodic: bool,
    /// a cubical set's box, as its first and last cubes (default: the cubes' bounding box,
    /// or the `box` line of a `.cub`)
    pub cubical_box: Option<(Vec<i64>, Vec<i64>)>,
    /// an image's cubical set: the values `≤ T` (default: the non-zero values)
    pub level: Option<f64>,
    /// where the stages are shown
    pub progress: Progress,
}

/// A chain complex with a name for each generator: `name(k, j)` names k-cell `j` in the
/// input's terms.
pub(crate) struct Named<'a> {
    pub(crate) chain: ChainComplex,
    pub(crate) name: Box<dyn Fn(usize, u32) -> CellName + 'a>,
    /// the chain complex is relative to vertices set aside (a cubical set reduced slab by
    /// slab): how its groups become the input's
    pub(crate) relative: Option<gmap_homology::cubical::slabs::Relative>,
}

/// The route a simplicial complex takes, `None` for the other inputs; refuses options that
/// do not fit the input. Direct by default; through the G-map with `via = Gmap`,
/// `method = Simplicial` or `simplify` (which work on maps).
pub(crate) fn simplicial_route(simplicial_input: bool, file: &str, o: &HomologyOptions) -> Result<Option<Via>> {
    let needs_map = o.method == Method::Simplicial || o.simplify;
    let route = match (o.via, simplicial_input) {
        (Some(Via::Direct), false) => {
            return Err(err!(Usage, "{file}: --via direct applies to simplicial complexes (.facets, .lex)"))
        }
        (Some(Via::Direct), true) if needs_map => {
            return Err(err!(Usage, "{file}: --method simplicial and --simplify work on the G-map; use --via gmap"))
        }
        (_, false) => None,
        (Some(v), true) => Some(v),
        (None, true) if needs_map => Some(Via::Gmap),
        (None, true) => Some(Via::Direct),
    };
    Ok(route)
}

/// The file an input was read from, as messages name it.
pub(crate) fn file_of(input: &Input) -> String {
    input.path().display().to_string()
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

/// The cellular chain complex of a map with its cells named, or why the method does not
/// apply (C1, C2, self-bending).
pub(crate) fn cellular<'a>(
    map: &DenseMap,
    file: &str,
    sc: Option<&'a SimplicialComplex>,
    progress: &Progress,
) -> Result<Named<'a>> {
    progress.stage("checking C1 and C2 and building the border operator");
    let c = cellular_complex(map).map_err(|e| {
        Error::from_source(ErrorKind::Precondition, &e)
            .context(format!("{file}: the cellular method does not apply (use --method simplicial)"))
    })?;
    let reps: Vec<Vec<u32>> = c.reps.iter().map(|r| r.iter().map(|d| d.get()).collect()).collect();
    let pts = points(map);
    Ok(Named {
        chain: c.chain,
        name: Box::new(move |k, j| dart_cell(sc, &pts, k, reps[k][j as usize])),
        relative: None,
    })
}

/// Refuses a map whose simplicial counterpart is too big to build (exponential in the
/// dimension): an n-map of N darts has up to `2^(n+1) (N + n + 1)` simplices (building it
/// visits the `2^(n+1)` vertex sets of a flag once per dimension even without darts), and
/// their reduction costs about `n + 1` squared per simplex (the faces of a simplex are
/// many and dense); that product is held to the workspace's work limit
/// ([`gmap_core::resources::DEFAULT_MAX_WORK`]: a one-dart 16-map is built in seconds, a
/// one-dart 17-map is refused, `gmap 30 1` asks for 2^31 simplices); then the memory is
/// checked against the memory limit.
pub fn check_simplicial_size(map: &DenseMap, file: &str) -> Result<()> {
    let n = map.dim() as u32;
    let work = (1u128 << (n + 1)) * (map.dart_count() as u128 + n as u128 + 1);
    let visits = work * (u128::from(n) + 1) * (u128::from(n) + 1);
    if visits > u128::from(gmap_core::resources::DEFAULT_MAX_WORK) {
        return Err(err!(
            Limit,
            "{file}: the simplicial counterpart of a {n}-map of {} darts has up to 2^{} x {} simplices, too many to \
             build (an estimated {visits} steps, over the work limit of {}); the cellular method works on the \
             cells themselves",
            map.dart_count(),
            n + 1,
            map.dart_count().max(1),
            gmap_core::resources::DEFAULT_MAX_WORK
        ));
    }
    // each simplex: its flag (dart and vertex set), its key and its n + 1 boundary entries
    let bytes = work.checked_mul(24 + 12 * (n as u128 + 1)).and_then(|b| u64::try_from(b).ok());
    gmap_core::resources::check_memory("the simplicial counterpart", bytes)
        .map_err(|e| Error::from(e).context(file.to_string()))?;
    Ok(())
}

/// The simplicial counterpart of a map with its simplices named by dart and vertex set.
pub(crate) fn simplicial(map: &DenseMap, progress: &Progress) -> Named<'static> {
    progress.stage("building the simplicial counterpart");
    let s = simplicial_complex_with_simplices(map);
    let pts = points(map);
    let simplices = s.simplices;
    Named {
        relative: None,
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

/// The direct route's chain complex of a simplicial complex (every face of every facet a
/// cell, `gmap_homology::simplices`), refused past `max_cells` faces (default: what the
/// memory budget holds at its dimension), the error naming `file` and the option that
/// raises the limit; with `labels`, the vertices of every face (to name generators).
pub fn face_complex_within(
    sc: &SimplicialComplex,
    max_cells: Option<u64>,
    file: &str,
    labels: bool,
) -> Result<FaceComplex> {
    let limit = max_cells.unwrap_or_else(|| default_face_limit(sc));
    face_complex_of(sc.facets(), limit, labels).map_err(|e| match e {
        FaceError::TooManyFaces { .. } if max_cells.is_some() => {
            err!(Limit, "{file}: {e}; raise the limit with --max-cells N")
        }
        FaceError::TooManyFaces { .. } => err!(
            Limit,
            "{file}: {e} (the faces the memory budget holds); raise the budget with --max-memory BYTES, or set the limit with --max-cells N"
        ),
        e => Error::from_source(ErrorKind::Limit, &e).context(file.to_string()).flattened(""),
    })
}

/// Complexes of at most this many faces (counted with repetition, a few megabytes of tables)
/// take the direct route without a look at the memory available.
const SMALL_FACES: u64 = 1 << 16;

/// The default face limit: [`gmap_ops::import::default_max_faces`], which reads the memory
/// available (`/proc/meminfo`, about 100 µs), except for a complex of at most
/// [`SMALL_FACES`] faces, which passes at once (a pass over its facets): an in-process call
/// on a small complex costs microseconds.
fn default_face_limit(sc: &SimplicialComplex) -> u64 {
    match gmap_homology::simplices::face_estimate(sc.facets()) {
        Some(e) if e <= SMALL_FACES => SMALL_FACES,
        _ => gmap_ops::import::default_max_faces(sc.dim()),
    }
}

/// The direct route for a simplicial complex: every face of every facet is a cell, no
/// G-map. The faces are counted first and refused past `max_darts`.
pub(crate) fn direct(sc: &SimplicialComplex, o: &HomologyOptions, file: &str) -> Result<Named<'static>> {
    // the estimate is a pass over the facets: made only for a message that shows
    if o.progress.is_visible() {
        o.progress.stage(&format!(
            "enumerating the faces of {} facets (at most {})",
            sc.total_facet_count(),
            gmap_homology::simplices::face_estimate(sc.facets()).map_or_else(|| "2^64".to_string(), |e| e.to_string())
        ));
    }
    let FaceComplex { chain, vertices, faces } = face_complex_within(sc, o.max_cells, file, o.generators)?;
    let name = Box::new(move |k: usize, j: u32| {
        let j = j as usize;
        CellName::Simplex(faces[k][j * (k + 1)..(j + 1) * (k + 1)].iter().map(|&v| vertices[v as usize]).collect())
    });
    Ok(Named { chain, name, relative: None })
}

/// The chain complex of an architectural complex (`.json`): the completion by zero of its
/// partial boundary matrix (AC Def. 3.9), after Algorithm 8.16 with `topological`.
pub(crate) fn arch(x: &gmap_homology::arch::ArchComplex, o: &HomologyOptions, file: &str) -> Result<Named<'static>> {
    if o.method == Method::Simplicial {
        return Err(err!(
            Precondition,
            "{file}: an architectural complex has no simplicial counterpart; use --method cellular"
        ));
    }
    let original = x;
    let topological;
    let x = if o.topological {
        let t = x.topological(ZeroWeightRule::Closed).map_err(|e| {
            Error::new(ErrorKind::Precondition, e.named(&x.region_names()).to_string())
                .context(format!("{file}: Algorithm 8.16"))
        })?;
        for op in &t.operators {
            o.progress.stage(&format!("Algorithm 8.16: {op}"));
        }
        topological = t.complex;
        &topological
    } else {
        x
    };
    // the file's names: a region Algorithm 8.16 added has none and goes by its number
    let named = |r: usize| {
        let id = x.region(r).id;
        let k = original.index_of(id).filter(|&i| original.region(i).dim == x.region(r).dim);
        let key = k.and_then(|i| original.region_key(i)).map(str::to_string);
        let name = k.and_then(|i| original.name_label(i)).map(str::to_string);
        if key.is_none() && name.is_none() {
            CellName::Region(id.0)
        } else {
            CellName::NamedRegion { id: id.0, key, name }
        }
    };
    let names: Vec<Vec<CellName>> =
        (0..=x.dim()).map(|k| x.regions_of_dim(k).iter().map(|&r| named(r as usize)).collect()).collect();
    Ok(Named { chain: x.chain_complex(), name: Box::new(move |k, j| names[k][j as usize].clone()), relative: None })
}

/// The groups of a cubical set of dimension ≤ 3 in one pass over its cubes
/// (`gmap_homology::cubical::pass`, or `gmap_homology::cubical::torus` for a periodic box),
/// where no cubical complex is needed: no generators, the cellular method. `None` where the
/// cubical complex is needed (and for a periodic box whose union-finds would not fit in
/// memory). `fill(start, out)` writes the presence bytes of the cubes
/// `start..start + out.len()` (axis 0 fastest); `file` names the input in messages. Public
/// for callers that hold the cubes elsewhere (the Python package reads a numpy array in
/// place).
pub fn cubical_one_pass(
    shape: &[usize],
    fill: impl Fn(usize, &mut [u8]) + Sync,
    o: &HomologyOptions,
    file: &str,
) -> Result<Option<gmap_homology::Homology>> {
    if shape.len() > 3 || o.generators || o.method != Method::Cellular || o.simplify || o.topological {
        return Ok(None);
    }
    let limit =
        |e: gmap_homology::cubical::CubicalError| Error::from_source(ErrorKind::Limit, &e).context(file.to_string());
    let d = shape.len();
    let (betti, torsion): (Vec<u64>, Vec<Vec<u64>>) = if o.periodic {
        // union-finds over the whole box: where they do not fit, the cubical complex (slab by
        // slab, its memory growing with the reduced complex) may still
        let what = "the periodic one-pass route";
        if gmap_core::resources::check_memory(what, gmap_homology::cubical::torus::bytes_needed(shape)).is_err() {
            o.progress.note("the periodic one-pass route does not fit in memory: the cubical complex instead");
            return Ok(None);
        }
        o.progress.stage("one pass over the cubes of the torus: components of the set, of its complement and their windings, Euler characteristic");
        let r = gmap_homology::cubical::torus::betti_one_pass_periodic(shape, fill).map_err(limit)?;
        (r.betti, r.torsion)
    } else {
        o.progress.stage("one pass over the cubes: components of the set and of its complement, Euler characteristic");
        let r = gmap_homology::cubical::pass::betti_one_pass(shape, fill).map_err(limit)?;
        (r.betti, vec![Vec::new(); d + 1])
    };
    let to_usize = |b: u64| usize::try_from(b).unwrap_or(usize::MAX);
    Ok(Some(match o.field {
        None => gmap_homology::Homology {
            coefficients: gmap_homology::homology::Coefficients::Integers,
            betti: betti.into_iter().map(to_usize).collect(),
            torsion: torsion.into_iter().map(|t| t.into_iter().map(Into::into).collect()).collect(),
        },
        // universal coefficients: a factor divisible by p adds a Z/p to H_k and one to H_{k+1}
        Some(p) => {
            let hits: Vec<usize> = torsion.iter().map(|t| t.iter().filter(|&&s| s % p == 0).count()).collect();
            let betti = (0..=d).map(|k| to_usize(betti[k]) + hits[k] + if k > 0 { hits[k - 1] } else { 0 }).collect();
            gmap_homology::Homology {
                coefficients: gmap_homology::homology::Coefficients::Field(p),
                betti,
                torsion: vec![Vec::new(); d + 1],
            }
        }
    }))
}

/// The layers of the slowest axis per slab of the slab-by-slab cubical complex: rows of
/// about 32 MiB in all (two per layer), at least one layer and at most 64.
pub(crate) fn slab_layers(shape: &[usize]) -> usize {
    let row: usize = shape[..shape.len().saturating_sub(1)].iter().fold(1usize, |v, &l| v.saturating_mul(2 * l + 1));
    ((32usize << 20) / row.max(1) / 2).clamp(1, 64)
}

fn check_cubical_options(o: &HomologyOptions, file: &str) -> Result<()> {
    if o.method == Method::Simplicial {
        return Err(err!(
            Precondition,
            "{file}: a cubical set has no simplicial counterpart here; use --method cellular"
        ));
    }
    if o.simplify || o.topological {
        return Err(err!(Usage, "{file}: --simplify and --topological do not apply to cubical sets"));
    }
    Ok(())
}

/// The largest doubled grid whose whole cubical complex is built at once (about 1 GiB at
/// [`gmap_core::resources::CUBICAL_BYTES_PER_POINT`]); larger ones go slab by slab.
pub(crate) const WHOLE_GRID_POINTS: u64 = 1 << 27;

/// Whether the whole cubical complex of a box of `shape` is built at once (faster: dense
/// collapses over one array) rather than slab by slab (memory of a slab and the survivors).
pub(crate) fn whole_grid_fits(shape: &[usize], periodic: bool) -> bool {
    gmap_core::resources::cubical_grid_points(shape, periodic).is_some_and(|p| p <= WHOLE_GRID_POINTS)
}

/// The chain complex of a cubical set with its cells named by their minimal vertex and
/// extent in the input's coordinates: the whole complex after collapses of free faces up to
/// [`WHOLE_GRID_POINTS`], else built and reduced slab by slab
/// (`gmap_homology::cubical::slabs`; collapses only with generators, so that its cycles are
/// the set's).
pub(crate) fn cubical(set: &gmap_ops::import::CubicalSet, o: &HomologyOptions, file: &str) -> Result<Named<'static>> {
    check_cubical_options(o, file)?;
    // a cell complex's lower cells are marked on the whole grid
    let (c, relative) = if whole_grid_fits(set.shape(), o.periodic) || !set.is_full() {
        o.progress.stage("building the cubical complex");
        let cells = set.lower_cells_in_box();
        gmap_homology::cubical::cubical_cell_complex_with(set.shape(), set.bits(), &cells, o.periodic, true)
            .map(|c| (c, None))
    } else {
        o.progress.stage("building and reducing the cubical complex slab by slab");
        let bits = set.bits();
        let fill = |s: usize, out: &mut [u8]| out.copy_from_slice(&bits[s..s + out.len()]);
        gmap_homology::cubical::slabs::cubical_complex_slabs(
            set.shape(),
            fill,
            o.periodic,
            slab_layers(set.shape()),
            o.generators,
        )
        .map(|c| (c.complex, Some(c.relative)))
    }
    .map_err(|e| Error::from_source(ErrorKind::Limit, &e).context(file.to_string()))?;
    Ok(named_cubes(c, set.min(), o.generators, relative))
}

/// The chain complex of an image's cubical set (the values at `level`) over
/// [`WHOLE_GRID_POINTS`], read from the image one layer at a time in its memory order and
/// reduced slab by slab: no bitmap of the whole image. Without generators (whose names need
/// the input's axis order: [`cubical`]).
pub(crate) fn cubical_image(
    img: &gmap_ops::import::Image,
    level: gmap_ops::import::Level,
    o: &HomologyOptions,
    file: &str,
) -> Result<Named<'static>> {
    check_cubical_options(o, file)?;
    o.progress.stage("reading the image and reducing its cubical complex slab by slab");
    let shape = img.memory_shape();
    let c = gmap_homology::cubical::slabs::cubical_complex_slabs(
        &shape,
        |s, out| img.presence(level, s, out),
        o.periodic,
        slab_layers(&shape),
        false,
    )
    .map_err(|e| Error::from_source(ErrorKind::Limit, &e).context(file.to_string()))?;
    Ok(named_cubes(c.complex, &[], false, Some(c.relative)))
}

/// Names the cells of a cubical complex by minimal vertex (`min` the box's) and extent, when
/// `generators` asks for names.
fn named_cubes(
    c: gmap_homology::cubical::CubicalComplex,
    min: &[i64],
    generators: bool,
    relative: Option<gmap_homology::cubical::slabs::Relative>,
) -> Named<'static> {
    let names: Vec<Vec<(Vec<i64>, Vec<u8>)>> = if generators {
        let name = |k: usize, i: usize| {
            let coords = c.coordinates(k, i);
            let lo = coords.iter().enumerate().map(|(a, &x)| min.get(a).copied().unwrap_or(0) + (x / 2) as i64);
            (lo.collect(), coords.iter().map(|&x| (x % 2) as u8).collect())
        };
        (0..c.cells.len()).map(|k| (0..c.cells[k].len()).map(|i| name(k, i)).collect()).collect()
    } else {
        vec![Vec::new(); c.cells.len()]
    };
    let name = Box::new(move |k: usize, j: u32| {
        let (min, extent) = &names[k][j as usize];
        CellName::Cube { min: min.as_slice().into(), extent: extent.as_slice().into() }
    });
    Named { chain: c.chain, name, relative }
}

/// The map reduced by removals and contractions of cells, or the map itself where the
/// reduction could change the groups, with the reason. Removals and contractions keep the
/// homology only when the cells are homology balls (conditions C1 and C2, docs/DESIGN.md):
/// where they fail (a segment with open ends, a map of loose darts), simplifying would merge
/// components and lose classes, so it is skipped. As a guard, a reduction that changes the
/// number of components is dropped too. Either way the groups are those of `map`.
pub fn simplify_if_safe(map: DenseMap, progress: &Progress) -> (DenseMap, Option<String>) {
    progress.stage("checking C1 and C2 before simplifying");
    if let Err(e) = gmap_homology::check_preconditions(&map) {
        return (map, Some(format!("--simplify skipped: the cells are not all homology balls ({e})")));
    }
    progress.stage("simplifying by removals and contractions of cells");
    let small = gmap_ops::euler::simplify(&map).0;
    if small.component_count() != map.component_count() {
        return (map, Some("--simplify skipped: the reduction changed the number of components".to_string()));
    }
    (small, None)
}
