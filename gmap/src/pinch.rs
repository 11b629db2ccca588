//! The rule of a write that would change the space. A G-map sews its top cells along shared
//! facets only, so where the pieces of a simplicial complex (its facets) or of a cubical set
//! (its cubes) around a cell share no facet there — two triangles meeting at a vertex only,
//! two squares at a corner — the G-map pulls the cell apart into one cell per group: another
//! space. [`crate::save()`] refuses such an output naming the cell and the formats that keep
//! the input as it is; with `lossy` it writes it and says what changes. The command line
//! (`gmap convert`) and the Python package (`save(lossy=)`) both go through here.

use std::collections::HashMap;
use std::path::Path;

use gmap_core::DenseMap;
use gmap_ops::import::SimplicialComplex;

use crate::error::{err, Item, Result};
use crate::formats::{Writer, FORMATS};
use crate::input::Input;

/// A cell the G-map of an input pulls apart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Pinch {
    /// the cell in the input's terms: `the vertex 2`, `the edge {1, 2}`, `the cell 1x1`
    pub cell: String,
    /// the cell as an error's item (a simplex by its vertex labels)
    pub item: Option<Item>,
    /// the number of groups of pieces around it: the cells it becomes
    pub groups: usize,
    /// what the pieces are: `facets`, `cubes`
    pub pieces: &'static str,
    /// what the map sews them along: `ridge`, `facet`
    pub shared: &'static str,
}

impl Pinch {
    /// What the G-map does to the cell: `the facets around the vertex 0 fall into 2 groups
    /// that share no ridge there, and a G-map sews facets along ridges only, so the vertex 0
    /// becomes 2 cells`.
    fn what_changes(&self) -> String {
        let Pinch { cell, groups, pieces, shared, .. } = self;
        format!(
            "the {pieces} around {cell} fall into {groups} groups that share no {shared} there, and a G-map sews {pieces} along {shared}s only, so {cell} becomes {groups} cells"
        )
    }
}

/// The refusal of a homology route through the G-map of a simplicial complex that `m`
/// pulls apart at a cell (`--via gmap`, `--method simplicial`, `--simplify`): the groups of
/// the map are another space's, so none is given; the direct route computes the complex's.
/// `None` when `m` keeps every face of `sc` one cell. The rule of [`simplicial`], as
/// [`check`] applies it to a write.
pub(crate) fn check_route(sc: &SimplicialComplex, m: &DenseMap, file: &str) -> Result<()> {
    let Some(p) = simplicial(sc, m) else { return Ok(()) };
    Err(err!(
        Precondition,
        "{file}: the G-map of this complex is another space: {}; its groups are not the complex's, --via direct computes those (--method simplicial and --simplify work on the G-map)",
        p.what_changes()
    )
    .with_item(p.item))
}

/// The name of a face of a simplicial complex by its vertex labels.
fn face_name(face: &[u64]) -> String {
    let labels: Vec<String> = face.iter().map(u64::to_string).collect();
    match face.len() {
        1 => format!("the vertex {}", labels[0]),
        2 => format!("the edge {{{}}}", labels.join(", ")),
        k => format!("the {}-simplex {{{}}}", k - 1, labels.join(", ")),
    }
}

/// The first face of `sc` (the highest dimension first, then in the order of the map's
/// cells) that its G-map `m` ([`SimplicialComplex::to_gmap`]) splits into several cells: a
/// face of dimension at most n − 2 whose facets are not joined around it by ridges holding
/// it. The highest first: two tetrahedra sharing an edge are pinched along the edge (its
/// vertices only follow).
/// `None` when every face is one cell of the map: then the map is the complex's own cell
/// structure, the same space. O(N n) per dimension.
pub(crate) fn simplicial(sc: &SimplicialComplex, m: &DenseMap) -> Option<Pinch> {
    for i in (0..m.dim().saturating_sub(1)).rev() {
        let mut count: HashMap<Vec<u64>, usize> = HashMap::new();
        let mut order = Vec::new();
        for d in m.cells(i).reps {
            let face = sc.dart_face(d.index() as u64, i)?;
            let c = count.entry(face.clone()).or_insert(0);
            if *c == 0 {
                order.push(face);
            }
            *c += 1;
        }
        if let Some(face) = order.into_iter().find(|f| count[f] > 1) {
            let groups = count[&face];
            return Some(Pinch {
                cell: face_name(&face),
                item: Some(Item::Simplex(face)),
                groups,
                pieces: "facets",
                shared: "ridge",
            });
        }
    }
    None
}

/// The extensions of the formats that write `input` as it is, not through a G-map: a
/// simplicial complex's `.facets`, a full cubical set's cubes (`.cub`) and voxels (`.vtk`),
/// and every incidence graph. From the registry ([`FORMATS`]).
pub(crate) fn keeping(input: &Input) -> Vec<&'static str> {
    FORMATS
        .iter()
        .filter(|f| {
            matches!(
                (f.writer, input),
                (Writer::Graph(_), _)
                    | (Writer::Map { facets: Some(_), .. }, Input::Simplicial(_))
                    | (Writer::Map { cubes: Some(_), .. } | Writer::Cubes(_), Input::Cubical(_))
            )
        })
        .map(|f| f.extension)
        .collect()
}

/// The rule: no pinch, nothing to say; a pinch without `lossy` is refused (nothing written)
/// naming the cell, what the output would do to it and the formats that keep the input;
/// with `lossy`, the sentence saying what the output changes. `hint` ends the refusal.
pub(crate) fn check(p: Option<Pinch>, input: &Input, output: &Path, lossy: bool, hint: &str) -> Result<Option<String>> {
    let Some(p) = p else { return Ok(None) };
    let source = match input.path().as_os_str().is_empty() {
        true => format!("the {}", input.kind()),
        false => input.path().display().to_string(),
    };
    let change = format!("{} is another space than {source}: {}", output.display(), p.what_changes());
    if lossy {
        return Ok(Some(change));
    }
    let keep: Vec<String> = keeping(input).iter().map(|e| format!(".{e}")).collect();
    Err(err!(Unsupported, "{change} (nothing written); {} keep it; {hint}", keep.join(", "))
        .with_path(output)
        .with_item(p.item))
}
