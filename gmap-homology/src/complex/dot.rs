//! The incidence graph for Graphviz (`.dot`, docs/FORMATS.md §2): one node per region (cell)
//! labelled with its dimension, one edge per defined entry, from the higher region to the
//! lower one, labelled with its weight (the signed incidence number).
//!
//! ```
//! use gmap_homology::arch::ArchComplex;
//! use gmap_homology::dot::write_dot;
//! let x = ArchComplex::try_from_ids(1, &[(0, 0), (1, 1)], &[(1, 0, 0)]).unwrap();
//! let d = write_dot(&x);
//! assert!(d.contains("r0 [label=\"0\"];"));
//! assert!(d.contains("r1 -> r0 [label=\"0\"];"));
//! ```
//!
//! O(R + E).

use std::fmt::Write as _;

use crate::complex::arch::ArchComplex;

/// The Graphviz text of the incidence graph; nodes are named `r<id>`, ranked by dimension
/// (higher dimensions on top).
pub fn write_dot(x: &ArchComplex) -> String {
    let mut s = String::with_capacity(24 * (x.regions().len() + x.entries().len()) + 64);
    s.push_str("digraph incidence {\n  rankdir=TB;\n");
    for k in (0..=x.dim()).rev() {
        let ids = x.regions_of_dim(k);
        if ids.is_empty() {
            continue;
        }
        s.push_str("  { rank=same;");
        for &r in ids {
            let _ = write!(s, " r{}", x.region(r as usize).id);
        }
        s.push_str(" }\n");
    }
    for r in x.regions() {
        let _ = writeln!(s, "  r{} [label=\"{}\"];", r.id, r.dim);
    }
    for (f, t, w) in x.entry_ids() {
        let _ = writeln!(s, "  r{f} -> r{t} [label=\"{w}\"];");
    }
    s.push_str("}\n");
    s
}
