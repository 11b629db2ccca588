//! The check every mesh writer makes before it writes: its output, read by this crate's
//! reader, gives the same map (isomorphic, checked on the cell counts, the components and
//! the boundary, and dart by dart for maps of at most [`FULL_CHECK_DARTS`] darts) and the
//! same labels on the cells of each dimension (compared as multisets). A write that would
//! change the mesh is refused with what would change.

use gmap_core::{to_dense_labels, AlphaSet, DenseLabels, DenseMap, LabelValue};

use super::error::ExportError;
use crate::import::ImportError;
use crate::mesh::Mesh;

/// The largest map whose read-back is compared dart by dart ([`crate::iso::are_isomorphic`]
/// is quadratic in the worst case); larger maps are compared by their invariants.
pub const FULL_CHECK_DARTS: usize = 20_000;

/// How a format carries labels, for the comparison.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Labelling {
    /// every label as it is
    Exact,
    /// Gmsh: numbers other than the tags as reals, and `gmsh:geometrical` added where the
    /// map has none (every element is on an entity)
    Gmsh,
}

/// The labels of the cells of dimension `i`, as sorted lists, sorted.
fn label_sets(labels: &DenseLabels, i: usize, rule: Labelling, drop_geometrical: bool) -> Vec<Vec<(String, String)>> {
    let mut out: Vec<Vec<(String, String)>> = labels
        .of
        .get(i)
        .map(|v| {
            v.iter()
                .map(|l| {
                    let mut s: Vec<(String, String)> = l
                        .iter()
                        .filter(|(n, _)| !(drop_geometrical && *n == "gmsh:geometrical"))
                        .map(|(n, v)| (n.to_string(), value_key(n, v, rule)))
                        .collect();
                    s.sort();
                    s
                })
                .filter(|s| !s.is_empty())
                .collect()
        })
        .unwrap_or_default();
    out.sort();
    out
}

/// A value as compared: exact, or for Gmsh's data a number as a real.
fn value_key(name: &str, v: &LabelValue, rule: Labelling) -> String {
    let tag = name == "gmsh:geometrical" || name.starts_with("gmsh:physical");
    match (rule, v) {
        (Labelling::Gmsh, LabelValue::Int(i)) if !tag => format!("{:?}", LabelValue::Real(*i as f64)),
        _ => format!("{v:?}"),
    }
}

/// The invariants compared on every map: darts, cells of each dimension, components, and
/// the free darts of each involution.
fn invariants(m: &DenseMap) -> (usize, Vec<usize>, usize, Vec<usize>) {
    let free = (0..=m.dim()).map(|i| m.darts().filter(|&d| m.is_free(d, i)).count()).collect();
    (m.dart_count(), m.cell_counts(), m.count_orbits(AlphaSet::all(m.dim())), free)
}

/// Checks that `parse` (this crate's reader of the text just made in `format`) gives back
/// `map` and `labels` (see the module documentation); refuses with what differs.
pub(crate) fn check(
    map: &DenseMap,
    labels: &DenseLabels,
    format: &'static str,
    rule: Labelling,
    parse: impl FnOnce() -> Result<Mesh, ImportError>,
) -> Result<(), ExportError> {
    let refuse = |what: String| ExportError::MeshWrite { format, reason: format!("its {format} would {what}") };
    let mesh = parse().map_err(|e| refuse(format!("not read back: {e}")))?;
    let limit = (map.dart_count() as u64).saturating_mul(2).max(1024);
    let g = mesh.to_gmap(limit).map_err(|e| refuse(format!("not read back: {e}")))?;
    let (back, back_labels, _) = to_dense_labels(&g);
    let (a, b) = (invariants(map), invariants(&back));
    if a != b {
        return Err(refuse(format!(
            "read back as another map: (darts, cells by dimension, components, free darts by involution) {a:?}, read back {b:?}"
        )));
    }
    if map.dart_count() <= FULL_CHECK_DARTS && !crate::iso::are_isomorphic(map, &back) {
        return Err(refuse("read back as another map with the same numbers of cells".into()));
    }
    let drop = rule == Labelling::Gmsh && !labels.of.iter().flatten().any(|l| l.get("gmsh:geometrical").is_some());
    for i in 0..=map.dim() {
        let (x, y) = (label_sets(labels, i, rule, drop), label_sets(&back_labels, i, rule, drop));
        if x != y {
            let first = x.iter().zip(&y).find(|(p, q)| p != q).map_or_else(
                || format!("{} labelled {i}-cells, read back {}", x.len(), y.len()),
                |(p, q)| format!("a {i}-cell labelled {p:?} reads back as {q:?}"),
            );
            return Err(refuse(format!("read back with other labels: {first}")));
        }
    }
    Ok(())
}
