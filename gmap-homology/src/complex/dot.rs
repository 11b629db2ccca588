//! The incidence graph for Graphviz (`.dot`, docs/FORMATS.md §2): one node per region (cell)
//! labelled with its dimension, one edge per defined entry, from the higher region to the
//! lower one, labelled with its weight (the signed incidence number). A region with labels
//! ([`ArchComplex::region_labels`]) shows its `name` label on a line above its dimension
//! (`label="kitchen\n3"`) and carries every other label as a quoted node attribute
//! (`"material"="brick"`, numbers in their `.gmap` text form).
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

use gmap_core::LabelValue;

use crate::complex::arch::ArchComplex;

/// Writes `t` as a Graphviz quoted string (`"` and `\` escaped, line breaks as `\n`);
/// shared by every DOT writer.
pub fn quote(s: &mut String, t: &str) {
    s.push('"');
    for c in t.chars() {
        match c {
            '"' => s.push_str("\\\""),
            '\\' => s.push_str("\\\\"),
            '\n' => s.push_str("\\n"),
            '\r' => {}
            c => s.push(c),
        }
    }
    s.push('"');
}

/// The Graphviz text of the incidence graph; nodes are named `r<id>` (the region's number),
/// ranked by dimension (higher dimensions on top), labelled by their `name` label or else
/// their string id, and carry the string id as the attribute `"id"`.
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
    for (k, r) in x.regions().iter().enumerate() {
        let labels = x.region_labels(k);
        let _ = write!(s, "  r{} [label=", r.id);
        // the name, when there is one, on a line above the dimension
        match (labels.get("name"), x.region_key(k)) {
            (Some(LabelValue::Text(t)), _) => quote(&mut s, &format!("{t}\n{}", r.dim)),
            (Some(v), _) => quote(&mut s, &format!("{v}\n{}", r.dim)),
            (None, Some(key)) => quote(&mut s, &format!("{key}\n{}", r.dim)),
            (None, None) => {
                let _ = write!(s, "\"{}\"", r.dim);
            }
        }
        // the file's string id, which the node's name r<number> stands for
        if let Some(key) = x.region_key(k) {
            s.push_str(", \"id\"=");
            quote(&mut s, key);
        }
        for (name, v) in labels.iter().filter(|(n, _)| *n != "name") {
            s.push_str(", ");
            quote(&mut s, name);
            s.push('=');
            match v {
                LabelValue::Text(t) => quote(&mut s, t),
                v => quote(&mut s, &v.to_string()),
            }
        }
        s.push_str("];\n");
    }
    for (f, t, w) in x.entry_ids() {
        let _ = writeln!(s, "  r{f} -> r{t} [label=\"{w}\"];");
    }
    s.push_str("}\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::complex::arch::RegionId;
    use gmap_core::Labels;

    #[test]
    fn named_regions_show_their_name_and_carry_the_other_labels() {
        let x = ArchComplex::try_from_ids(1, &[(0, 0), (1, 1), (2, 0)], &[(1, 0, 0)]).unwrap();
        let l: Labels = [
            ("kind", LabelValue::Text("door".into())),
            ("name", LabelValue::Text("front \"door\"\\\n".into())),
            ("width", LabelValue::Real(0.9)),
        ]
        .into_iter()
        .collect();
        let x = x.with_region_labels(RegionId(1), l).unwrap();
        let numbered: Labels = [("name", LabelValue::Int(7))].into_iter().collect();
        let x = x.with_region_labels(RegionId(2), numbered).unwrap();
        let d = write_dot(&x);
        assert!(d.contains("  r0 [label=\"0\"];\n"), "{d}");
        assert!(
            d.contains("  r1 [label=\"front \\\"door\\\"\\\\\\n\\n1\", \"kind\"=\"door\", \"width\"=\"0.9\"];\n"),
            "{d}"
        );
        assert!(d.contains("  r2 [label=\"7\\n0\"];\n"), "{d}");
    }
}
