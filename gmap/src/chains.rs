//! The chain complexes of the routes of maps, simplicial complexes and architectural
//! complexes, each with a name for every cell in the input's terms ([`Named`]):
//!
//! | input | chain complex | builder |
//! |---|---|---|
//! | map | the cells and the border operator (BO Def. 10), under C1/C2 | [`cellular`] |
//! | map | the simplicial counterpart: one n-simplex per dart (BO §6) | [`simplicial`] |
//! | simplicial complex | every face of every facet a cell | [`direct`] |
//! | architectural complex | the completion by zero of its boundary matrix (AC Def. 3.9) | [`arch`] |
//!
//! The cubical routes are in [`crate::cubes`]; [`crate::route`] chooses among them all.

use gmap_core::DenseMap;
use gmap_homology::arch::ZeroWeightRule;
use gmap_homology::simplices::{face_complex_of, FaceComplex, FaceError};
use gmap_homology::{cellular_complex, simplicial_complex_with_simplices, ChainComplex};
use gmap_ops::import::SimplicialComplex;

use crate::cell_name::CellName;
use crate::error::{err, Error, ErrorKind, Result};
use crate::options::{HomologyOptions, Method};
use crate::progress::Progress;

/// A chain complex with a name for each generator: `name(k, j)` names k-cell `j` in the
/// input's terms.
pub(crate) struct Named<'a> {
    pub(crate) chain: ChainComplex,
    pub(crate) name: Box<dyn Fn(usize, u32) -> CellName + 'a>,
    /// the chain complex is relative to vertices set aside (a cubical set reduced slab by
    /// slab): how its groups become the input's
    pub(crate) relative: Option<gmap_homology::cubical::slabs::Relative>,
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
    // the failed condition's cell as the error's item (From<PreconditionError>)
    let c = cellular_complex(map).map_err(|e| {
        Error::from(e).context(format!("{file}: the cellular method does not apply (use --method simplicial)"))
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
        e => Error::from_source(ErrorKind::Limit, e).context(file.to_string()).flattened(""),
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
