//! Which route computes an input's homology, as a value: [`plan`] chooses a [`Route`] from
//! the input and the options, [`Route::run`] follows it to a [`Report`]. The command line,
//! the Python package, `gmap bench` and the MPI binary all go through here, so a route is
//! chosen in one place.
//!
//! | input | route | chain complex (module) |
//! |---|---|---|
//! | map | [`Route::Cellular`] (default) | the cells and the border operator under C1/C2 (`chains`) |
//! | map | [`Route::Simplicial`] | the simplicial counterpart: one n-simplex per dart |
//! | simplicial complex | [`Route::Direct`] (default) | every face of every facet a cell |
//! | simplicial complex | [`Route::Gmap`] | the G-map of the facets, then a map route |
//! | cubical set, image, borrowed cubes | [`Route::OnePass`] (dimension ≤ 3, no generators) | none: union-finds and χ ([`crate::cubes`]) |
//! | cubical set, image, borrowed cubes | [`Route::Sweep`] (dimension ≤ 3, generators) | none: union-finds and a sweep |
//! | cubical set, image, borrowed cubes | [`Route::Cubical`] | the cubical complex, whole or slab by slab |
//! | architectural complex | [`Route::Arch`] | the completion by zero of its boundary matrix (AC Def. 3.9) |
//!
//! A simplicial complex goes through its G-map when asked (`via = Gmap`) or when the options
//! need a map (`--method simplicial`, `--simplify`). Simplifying a map is done only when it
//! keeps the groups ([`crate::simplify_if_safe`]). The one-pass route and the sweep hand
//! the cubes to the cubical complex where they cannot finish (a periodic box whose
//! union-finds do not fit in memory, a sweep that stops at a vertex), with a note.

use gmap_homology::{homology_z, homology_zp, Homology};
use gmap_ops::import::{CubicalSet, Level};

use crate::chains::{self, Named};
use crate::cubes::{self, Cubes, CubesRef};
use crate::error::{err, Error, ErrorKind, Result};
use crate::formats::extensions_of;
use crate::input::{Input, Kind};
use crate::options::{check_options, HomologyOptions, Method, Via};
use crate::report::{ArchSpace, Chain, NamedGenerator, Report};

/// A route from an input to its groups.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Route {
    /// a map's cells and the border operator (BO Def. 10), under C1/C2
    Cellular,
    /// a map's simplicial counterpart (BO §6)
    Simplicial,
    /// a simplicial complex: every face of every facet a cell
    Direct,
    /// a simplicial complex through the G-map of its facets, then the map route of `Method`
    Gmap(Method),
    /// cubes of dimension ≤ 3: the groups in one pass over them (periodic: over the torus)
    OnePass,
    /// cubes of dimension ≤ 3 in a box that is not periodic: the groups and a cycle per
    /// summand from union-finds and a sweep of the grid
    Sweep,
    /// cubes: the cubical complex of the closure, whole (`true`) or slab by slab
    Cubical {
        /// built at once rather than slab by slab
        whole: bool,
    },
    /// an architectural complex: the completion by zero of its boundary matrix
    Arch,
}

impl Route {
    /// The route's name, as `gmap bench` prints it: `cellular`, `simplicial`, `direct`,
    /// `gmap`, `one-pass`, `sweep`, `cubical` (whole), `slabs`, `arch`.
    pub fn name(self) -> &'static str {
        match self {
            Route::Cellular => "cellular",
            Route::Simplicial => "simplicial",
            Route::Direct => "direct",
            Route::Gmap(_) => "gmap",
            Route::OnePass => "one-pass",
            Route::Sweep => "sweep",
            Route::Cubical { whole: true } => "cubical",
            Route::Cubical { whole: false } => "slabs",
            Route::Arch => "arch",
        }
    }

    /// Follows the route on `input` (which [`plan`] chose it for) to the groups, with the
    /// generators when asked for.
    pub fn run(self, input: &Input, o: &HomologyOptions) -> Result<Report> {
        let file = input.path().display().to_string();
        let via = check_options(&file, Some(input.input_kind()), o)?;
        let mut report = match input {
            Input::Cubical(set) => run_cubes(self, Cubes::Set(set), o, &file)?,
            Input::Image(img) => run_cubes(self, Cubes::Image(img, level(o)), o, &file)?,
            _ => run_complex(self, input, o, &file)?,
        };
        (report.kind, report.route) = (input.kind(), via);
        Ok(report)
    }
}

/// Every route that applies to an input of this kind, in the order `gmap bench` runs them:
/// a simplicial complex's direct route then its G-map's two; a map's cellular and
/// simplicial routes; cubes' one pass (cubes only, dimension ≤ 3, a box that is not
/// periodic), then their cubical complex slab by slab and whole (a set with cells of its
/// own: whole only); an architectural complex's one route.
pub fn candidates(input: &Input, periodic: bool) -> Vec<Route> {
    let cubes = |c: Cubes<'_>| {
        let mut out = Vec::new();
        if c.is_full() {
            if c.shape().len() <= 3 && !periodic {
                out.push(Route::OnePass);
            }
            out.push(Route::Cubical { whole: false });
        }
        out.push(Route::Cubical { whole: true });
        out
    };
    match input {
        Input::Simplicial(_) => vec![Route::Direct, Route::Gmap(Method::Cellular), Route::Gmap(Method::Simplicial)],
        Input::Map(_) => vec![Route::Cellular, Route::Simplicial],
        Input::Cubical(set) => cubes(Cubes::Set(set)),
        Input::Image(img) => cubes(Cubes::Image(img, Level::Nonzero)),
        Input::Arch(_) => vec![Route::Arch],
    }
}

/// The cubes of an image: the values `≤ level` (default: the non-zero values).
fn level(o: &HomologyOptions) -> Level {
    o.level.map_or(Level::Nonzero, Level::AtMost)
}

/// The route [`crate::homology`] takes for `input` with `o`; refuses options that do not fit
/// the input with the reason ([`ErrorKind::Usage`]).
pub fn plan(input: &Input, o: &HomologyOptions) -> Result<Route> {
    let file = input.path().display().to_string();
    let via = check_options(&file, Some(input.input_kind()), o)?;
    if o.level.is_some() && !matches!(input, Input::Image(_)) {
        return Err(err!(Usage, "{file}: --level applies to images ({})", extensions_of(&[Kind::Image])));
    }
    Ok(match input {
        Input::Cubical(set) => plan_cubes(Cubes::Set(set), o),
        Input::Image(img) => plan_cubes(Cubes::Image(img, level(o)), o),
        Input::Simplicial(_) => match via {
            Some(Via::Direct) => Route::Direct,
            _ => Route::Gmap(o.method),
        },
        Input::Map(_) if o.topological => {
            return Err(err!(
                Usage,
                "{file}: --topological applies to architectural complexes ({}), not to G-maps",
                extensions_of(&[Kind::Arch])
            ))
        }
        Input::Map(_) => match o.method {
            Method::Cellular => Route::Cellular,
            Method::Simplicial => Route::Simplicial,
        },
        Input::Arch(_) if o.simplify => {
            return Err(err!(
                Usage,
                "{file}: --simplify applies to G-maps, not to architectural complexes ({})",
                extensions_of(&[Kind::Arch])
            ))
        }
        Input::Arch(_) => Route::Arch,
    })
}

/// The route of cubes: one pass or the sweep where they apply (dimension ≤ 3, the cellular
/// method, cubes only), else the cubical complex, whole when it fits.
fn plan_cubes(cubes: Cubes<'_>, o: &HomologyOptions) -> Route {
    let shape = cubes.shape();
    let plain = o.method == Method::Cellular && !o.simplify && !o.topological && cubes.is_full() && shape.len() <= 3;
    if o.shortest {
        // the shortest basis needs the absolute complex, built whole
        return Route::Cubical { whole: true };
    }
    match (plain, o.generators) {
        (true, false) => Route::OnePass,
        (true, true) if !o.periodic => Route::Sweep,
        _ => Route::Cubical { whole: !cubes.is_full() || cubes::whole_grid_fits(&shape, o.periodic) },
    }
}

/// A report of groups computed by a route, before [`Route::run`] sets the input's kind and
/// route.
fn route_report(
    dimension: usize,
    o: &HomologyOptions,
    groups: Homology,
    generators: Option<Vec<NamedGenerator>>,
) -> Report {
    Report {
        kind: Kind::Cubical.name(),
        dimension,
        method: o.method,
        route: None,
        field: o.field,
        groups,
        generators,
        note: None,
        space: None,
    }
}

/// Follows a cubical route. Generators of an image are named on its cubical set (the
/// caller's axes), made first.
fn run_cubes(route: Route, cubes: Cubes<'_>, o: &HomologyOptions, file: &str) -> Result<Report> {
    let d = cubes.shape().len();
    if let (Cubes::Image(img, level), true) = (cubes, o.generators) {
        o.progress.stage("the image's cubical set");
        let set: CubicalSet = cubes::image_set(img, level, file)?;
        let whole = cubes::whole_grid_fits(set.shape(), o.periodic);
        let route = if route == Route::Sweep { route } else { Route::Cubical { whole } };
        return run_cubes(route, Cubes::Set(&set), o, file);
    }
    match route {
        Route::OnePass => {
            if let Some(groups) = cubes::one_pass(&cubes.shape(), |s, out| cubes.fill(s, out), o, file)? {
                return Ok(route_report(d, o, groups, None));
            }
        }
        Route::Sweep => {
            let found = match cubes {
                Cubes::Set(set) => cubes::sweep(set.shape(), set.bits(), set.min(), false, o, file)?,
                Cubes::Borrowed(b) => cubes::sweep(b.storage_shape(), b.bytes(), &[], b.is_reversed(), o, file)?,
                Cubes::Image(..) => None,
            };
            if let Some((groups, generators)) = found {
                return Ok(route_report(d, o, groups, Some(generators)));
            }
        }
        _ => {}
    }
    let whole = match route {
        Route::Cubical { whole } => whole,
        _ => !cubes.is_full() || cubes::whole_grid_fits(&cubes.shape(), o.periodic),
    };
    let named = cubes::complex(cubes, whole, o, file)?;
    let mut report = finish(&named, d, o, file)?;
    if cubes.reversed() {
        for g in report.generators.iter_mut().flatten() {
            g.chain.reverse_cube_axes();
        }
    }
    Ok(report)
}

/// Follows the route of a map, a simplicial complex or an architectural complex.
fn run_complex(route: Route, input: &Input, o: &HomologyOptions, file: &str) -> Result<Report> {
    let mut note = None;
    let (dim, named) = match (route, input) {
        (Route::Direct, Input::Simplicial(sc)) => (sc.dim(), chains::direct(sc, o, file)?),
        (Route::Gmap(method), Input::Simplicial(sc)) => {
            let map = sc.to_gmap_within(o.max_darts)?;
            // a map that pulls a face apart is another space: its groups are not the complex's
            crate::pinch::check_route(sc, &map, file)?;
            let (map, names) = if o.simplify {
                let (m, n) = chains::simplify_if_safe(map, &o.progress);
                note = n;
                (m, None)
            } else {
                (map, o.generators.then_some(sc.get()))
            };
            (map.dim(), map_chains(&map, method, o, file, names)?)
        }
        (Route::Cellular | Route::Simplicial, Input::Map(m)) => {
            let method = if route == Route::Simplicial { Method::Simplicial } else { Method::Cellular };
            if o.simplify {
                let (map, n) = chains::simplify_if_safe(m.map().clone(), &o.progress);
                note = n;
                (map.dim(), map_chains(&map, method, o, file, None)?)
            } else {
                // a map made from a complex's facets names its cells by the complex's labels
                (m.map().dim(), map_chains(m.map(), method, o, file, m.complex())?)
            }
        }
        (Route::Arch, Input::Arch(x)) => (x.dim(), chains::arch(x, o, file)?),
        (route, input) => {
            return Err(err!(Usage, "{file}: the route {} does not apply to a {}", route.name(), input.kind()))
        }
    };
    if let Some(n) = &note {
        o.progress.note(&format!("gmap homology: {n}"));
    }
    let mut report = finish(&named, dim, o, file)?;
    report.note = note;
    if let Input::Arch(x) = input {
        report.space = Some(ArchSpace::of(x, o.topological));
    }
    Ok(report)
}

/// The chain complex of a map by `method`.
fn map_chains<'a>(
    map: &gmap_core::DenseMap,
    method: Method,
    o: &HomologyOptions,
    file: &str,
    sc: Option<&'a gmap_ops::import::SimplicialComplex>,
) -> Result<Named<'a>> {
    match method {
        Method::Cellular => chains::cellular(map, file, sc, &o.progress),
        Method::Simplicial => {
            chains::check_simplicial_size(map, file)?;
            Ok(chains::simplicial(map, &o.progress))
        }
    }
}

/// The groups of a named chain complex and, when asked for, a cycle per summand named in
/// the input's terms (those of `H_1` a shortest basis with `shortest`).
fn finish(named: &Named<'_>, dimension: usize, o: &HomologyOptions, file: &str) -> Result<Report> {
    let groups = reduce(named, o).map_err(|e| e.context(file.to_string()))?;
    let generators = if o.generators {
        o.progress.stage("computing generators and lifting them to the input's cells");
        let limit = o.max_generator_cells.unwrap_or(gmap_homology::generators::GENERATOR_CELL_LIMIT);
        let g = gmap_homology::generators::generators_within(&named.chain, o.field, limit).map_err(|e| match e {
            gmap_homology::HomologyError::GeneratorsTooLarge { .. } => {
                err!(Limit, "{file}: {e}; the groups are computed without --generators, or raise the limit with --max-generator-cells N (the cost grows as its cube)")
            }
            e => Error::from(e).context(file.to_string()),
        })?;
        let mut g: Vec<NamedGenerator> = g.into_iter().map(|x| name_generator(named, x)).collect();
        if o.shortest {
            let h1 = shortest_h1(named, o, file)?;
            let at = g.iter().position(|x| x.dim == 1).unwrap_or(g.len());
            g.retain(|x| x.dim != 1);
            g.splice(at.min(g.len())..at.min(g.len()), h1);
        }
        Some(g)
    } else {
        None
    };
    Ok(route_report(dimension, o, groups, generators))
}

/// A shortest basis of `H_1` over `Z/2` with every edge of length 1, named, with their
/// lengths.
fn shortest_h1(named: &Named<'_>, o: &HomologyOptions, file: &str) -> Result<Vec<NamedGenerator>> {
    if named.relative.is_some() {
        return Err(err!(
            Precondition,
            "{file}: the shortest basis needs the whole complex, not one relative to vertices set aside"
        ));
    }
    o.progress.stage("a shortest basis of H_1: shortest-path trees from every vertex, then the greedy basis");
    let edges = named.chain.counts().get(1).copied().unwrap_or(0);
    let basis = gmap_homology::curves::shortest_basis(&named.chain, &vec![1.0; edges])
        .map_err(|e| Error::from(e).context(file.to_string()))?;
    let gens = basis
        .into_iter()
        .map(|c| {
            let mut edges = c.edges;
            edges.sort_unstable();
            edges.dedup();
            let chain = edges.iter().map(|&e| ((named.name)(1, e), 1)).collect();
            NamedGenerator { dim: 1, order: 0u64.into(), chain: Chain::Named(chain), length: Some(c.length) }
        })
        .collect();
    Ok(gens)
}

/// Reduces the chain complex (over Z or Z/p) and gives the groups of the input (a complex
/// relative to vertices set aside made absolute).
fn reduce(named: &Named<'_>, o: &HomologyOptions) -> Result<Homology> {
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
        Some(r) => r.absolute(h).map_err(|e| Error::from_source(ErrorKind::Limit, e)),
        None => Ok(h),
    }
}

fn name_generator(named: &Named<'_>, x: gmap_homology::generators::Generator) -> NamedGenerator {
    NamedGenerator {
        dim: x.dim,
        order: x.order.clone(),
        chain: Chain::Named(x.chain.iter().map(|&(cell, coef)| ((named.name)(x.dim, cell), coef)).collect()),
        length: None,
    }
}

/// The homology of an input, by the route the command line takes ([`plan`], then
/// [`Route::run`]): the cellular border operator of a map (or its simplicial counterpart),
/// the direct face complex or the G-map of a simplicial complex, the cubical routes of a
/// cubical set or image, the completed boundary matrix of an architectural complex. Over Z
/// with torsion, or over Z/p.
///
/// Options that do not fit the input are refused with the reason ([`ErrorKind::Usage`]),
/// so are routes whose conditions fail ([`ErrorKind::Precondition`]) and work over the
/// limits ([`ErrorKind::Limit`]).
pub fn homology(input: &Input, o: &HomologyOptions) -> Result<Report> {
    if let Some((first, last)) = &o.cubical_box {
        let file = input.path().display().to_string();
        let Input::Cubical(set) = input else {
            return Err(err!(Usage, "{file}: --box applies to cubical sets ({})", extensions_of(&[Kind::Cubical])));
        };
        let boxed = set.with_box(first, last).map_err(|e| err!(Usage, "{file}: --box: {e}"))?;
        let mut inner = o.clone();
        inner.cubical_box = None;
        return homology(&Input::Cubical(set.with_value(boxed)), &inner);
    }
    plan(input, o)?.run(input, o)
}

/// [`homology`] of the file at `path`: the options are checked against the file's kind (by
/// the format registry) before it is read, then the file is opened with `o.max_darts`.
pub fn homology_file(path: impl AsRef<std::path::Path>, o: &HomologyOptions) -> Result<Report> {
    let path = path.as_ref();
    check_options(&path.display().to_string(), crate::formats::kind_of(path), o)?;
    o.progress.stage(&format!("reading {}", path.display()));
    let input = crate::open_with(path, &crate::OpenOptions::max_darts(o.max_darts))?;
    homology(&input, o)
}

/// The homology of cubes borrowed from memory (a numpy array read in place), by the cubical
/// routes a cubical set takes; the cells of generators named in the caller's axis order.
pub fn homology_cubes(cubes: &CubesRef<'_>, o: &HomologyOptions) -> Result<Report> {
    let file = "the array";
    check_options(file, Some(Kind::Cubical), o)?;
    if o.level.is_some() || o.cubical_box.is_some() {
        return Err(err!(Usage, "{file}: --level and --box apply to files"));
    }
    let source = Cubes::Borrowed(cubes);
    run_cubes(plan_cubes(source, o), source, o, file)
}
