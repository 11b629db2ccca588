//! The options of [`crate::homology`] (the command line's flags) and the rules that check
//! them against one another and against the kind of input, written once for every caller.

use gmap_homology::Prime;

use crate::error::{err, Result};
use crate::formats::extensions_of as exts;
use crate::input::Kind;
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
    /// with `generators` over `Z/2` (`field = Some(2)`): the generators of `H_1` are a
    /// shortest basis, each cycle as short as it can be, lengths counted in edges
    /// (`gmap_homology::curves::basis`); the other dimensions' as without it
    pub shortest: bool,
    /// the most cells with entries per dimension of the reduced complex for which generators
    /// are computed (default: `gmap_homology::generators::GENERATOR_CELL_LIMIT`, 2,000; full
    /// cubical sets of dimension ≤ 3 have their own route, [`crate::cubes::sweep`])
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

/// Refuses a field that is not Z/P for a prime P below 2^31.
pub(crate) fn check_field(field: Option<u64>) -> Result<()> {
    match field {
        Some(p) if Prime::new(p).is_none() => {
            Err(err!(Usage, "--field {p}: the field must be Z/P for a prime P below 2^31"))
        }
        _ => Ok(()),
    }
}

/// Refuses `shortest` without generators or over another field than `Z/2`.
fn check_shortest(file: &str, o: &HomologyOptions) -> Result<()> {
    if !o.shortest {
        return Ok(());
    }
    if !o.generators {
        return Err(err!(Usage, "{file}: a shortest basis is a choice of generators: ask for generators too"));
    }
    if o.field != Some(2) {
        return Err(err!(
            Usage,
            "{file}: the shortest basis of H_1 is computed over Z/2 (its classes modulo 2): add --field 2"
        ));
    }
    Ok(())
}

/// The route a simplicial complex takes, `None` for the other inputs; refuses options that
/// do not fit the input. Direct by default; through the G-map with `via = Gmap`,
/// `method = Simplicial` or `simplify` (which work on maps).
pub(crate) fn simplicial_via(simplicial_input: bool, file: &str, o: &HomologyOptions) -> Result<Option<Via>> {
    let needs_map = o.method == Method::Simplicial || o.simplify;
    let route = match (o.via, simplicial_input) {
        (Some(Via::Direct), false) => {
            return Err(err!(
                Usage,
                "{file}: --via direct applies to simplicial complexes ({})",
                exts(&[Kind::Simplicial])
            ))
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

/// The checks of the options against the kind of input (`None`: a kind not known yet, a
/// file not opened), in the order the command line makes them; the way a simplicial complex
/// is taken. Made before a file is read ([`crate::homology_file`]) and again on the input.
pub(crate) fn check_options(file: &str, kind: Option<Kind>, o: &HomologyOptions) -> Result<Option<Via>> {
    check_field(o.field)?;
    check_shortest(file, o)?;
    let via = simplicial_via(kind == Some(Kind::Simplicial), file, o)?;
    if o.topological && via.is_some() {
        return Err(err!(
            Usage,
            "{file}: --topological applies to architectural complexes ({}), not to simplicial complexes",
            exts(&[Kind::Arch])
        ));
    }
    if o.periodic && !kind.is_some_and(Kind::is_cubical) {
        return Err(err!(
            Usage,
            "{file}: --periodic applies to cubical sets ({})",
            exts(&[Kind::Cubical, Kind::Image])
        ));
    }
    Ok(via)
}
