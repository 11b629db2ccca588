//! The incidence graph as GraphML (`.graphml`, docs/FORMATS.md), the XML graph format that
//! networkx (`read_graphml`), Gephi, yEd and igraph read: one node per region (cell), one
//! directed edge per defined entry, from the higher region to the lower one.
//!
//! A node's GraphML id is `r<id>` (the region's number; an XML name token) and it carries
//! `id` (the region's id in the file: its string id, or its number) and `dim` (its dimension);
//! every edge carries `weight` (the signed incidence number). Each label name of the regions ([`ArchComplex::region_labels`]) is a node key
//! of its own, typed by its values: `long` when every value given is an integer, `double`
//! when every value is a number, else `string` (numbers then in their `.gmap` text form);
//! a region without the label has no value for it. Text is XML-escaped; characters XML 1.0
//! cannot hold (controls other than tab and line breaks) are written as U+FFFD.
//!
//! ```
//! use gmap_homology::arch::ArchComplex;
//! use gmap_homology::graphml::write_graphml;
//! let x = ArchComplex::try_from_ids(1, &[(0, 0), (1, 1)], &[(1, 0, -1)]).unwrap();
//! let g = write_graphml(&x);
//! assert!(g.contains(r#"<node id="r0"><data key="id">0</data><data key="dim">0</data></node>"#));
//! assert!(g.contains(r#"<edge source="r1" target="r0"><data key="weight">-1</data></edge>"#));
//! ```
//!
//! O(R + E + the labels).

use std::fmt::Write as _;

use gmap_core::LabelValue;

use crate::complex::arch::ArchComplex;

/// Writes `t` escaped for XML text and attribute values (characters XML 1.0 cannot hold
/// as U+FFFD); shared by every GraphML writer.
pub fn escape(s: &mut String, t: &str) {
    for c in t.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            '\t' | '\n' | '\r' => s.push(c),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => s.push('\u{FFFD}'),
            c => s.push(c),
        }
    }
}

/// The GraphML type of a label name: the narrowest that holds every value it takes.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum KeyType {
    Long,
    Double,
    Text,
}

impl KeyType {
    fn of(v: &LabelValue) -> Self {
        match v {
            LabelValue::Int(_) => KeyType::Long,
            LabelValue::Real(_) => KeyType::Double,
            LabelValue::Text(_) => KeyType::Text,
        }
    }

    fn name(self) -> &'static str {
        match self {
            KeyType::Long => "long",
            KeyType::Double => "double",
            KeyType::Text => "string",
        }
    }
}

/// The GraphML text of the incidence graph (module docs).
pub fn write_graphml(x: &ArchComplex) -> String {
    // the label names in order of first appearance, each with its type
    let mut keys: Vec<(String, KeyType)> = Vec::new();
    for k in 0..x.regions().len() {
        for (name, v) in x.region_labels(k).iter() {
            let t = KeyType::of(v);
            match keys.iter_mut().find(|(n, _)| n == name) {
                Some((_, kt)) => *kt = (*kt).max(t),
                None => keys.push((name.to_string(), t)),
            }
        }
    }
    let mut s = String::with_capacity(64 * (x.regions().len() + x.entries().len()) + 512);
    s.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    s.push_str("<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" xsi:schemaLocation=\"http://graphml.graphdrawing.org/xmlns http://graphml.graphdrawing.org/xmlns/1.0/graphml.xsd\">\n");
    s.push_str("  <key id=\"id\" for=\"node\" attr.name=\"id\" attr.type=\"string\"/>\n");
    s.push_str("  <key id=\"dim\" for=\"node\" attr.name=\"dim\" attr.type=\"int\"/>\n");
    for (k, (name, t)) in keys.iter().enumerate() {
        let _ = write!(s, "  <key id=\"l{k}\" for=\"node\" attr.name=\"");
        escape(&mut s, name);
        let _ = writeln!(s, "\" attr.type=\"{}\"/>", t.name());
    }
    s.push_str("  <key id=\"weight\" for=\"edge\" attr.name=\"weight\" attr.type=\"long\"/>\n");
    s.push_str("  <graph id=\"incidence\" edgedefault=\"directed\">\n");
    for (k, r) in x.regions().iter().enumerate() {
        let _ = write!(s, "    <node id=\"r{}\"><data key=\"id\">", r.id);
        match x.region_key(k) {
            Some(key) => escape(&mut s, key),
            None => {
                let _ = write!(s, "{}", r.id);
            }
        }
        let _ = write!(s, "</data><data key=\"dim\">{}</data>", r.dim);
        for (name, v) in x.region_labels(k).iter() {
            let key = keys.iter().position(|(n, _)| n == name).expect("collected above");
            let _ = write!(s, "<data key=\"l{key}\">");
            match v {
                LabelValue::Text(t) => escape(&mut s, t),
                LabelValue::Real(f) if keys[key].1 == KeyType::Double => {
                    let _ = write!(s, "{f:?}");
                }
                LabelValue::Int(i) if keys[key].1 == KeyType::Double => {
                    let _ = write!(s, "{:?}", *i as f64);
                }
                v => escape(&mut s, &v.to_string()),
            }
            s.push_str("</data>");
        }
        s.push_str("</node>\n");
    }
    for (f, t, w) in x.entry_ids() {
        let _ = writeln!(s, "    <edge source=\"r{f}\" target=\"r{t}\"><data key=\"weight\">{w}</data></edge>");
    }
    s.push_str("  </graph>\n</graphml>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::complex::arch::RegionId;
    use gmap_core::Labels;

    #[test]
    fn labels_become_typed_keys_and_text_is_escaped() {
        let x = ArchComplex::try_from_ids(1, &[(0, 0), (1, 1), (2, 0)], &[(1, 0, 1), (1, 2, -1)]).unwrap();
        let l: Labels = [("name", LabelValue::Text("a <b> & \"c\"\u{1}".into())), ("area", LabelValue::Real(2.5))]
            .into_iter()
            .collect();
        let x = x.with_region_labels(RegionId(1), l).unwrap();
        let l: Labels = [("area", LabelValue::Int(3)), ("storey", LabelValue::Int(-1))].into_iter().collect();
        let x = x.with_region_labels(RegionId(2), l).unwrap();
        let g = write_graphml(&x);
        assert!(g.contains(r#"<key id="l0" for="node" attr.name="name" attr.type="string"/>"#), "{g}");
        assert!(g.contains(r#"<key id="l1" for="node" attr.name="area" attr.type="double"/>"#), "{g}");
        assert!(g.contains(r#"<key id="l2" for="node" attr.name="storey" attr.type="long"/>"#), "{g}");
        assert!(
            g.contains("<data key=\"l0\">a &lt;b&gt; &amp; &quot;c&quot;\u{FFFD}</data><data key=\"l1\">2.5</data>"),
            "{g}"
        );
        assert!(g.contains(r#"<data key="l1">3.0</data><data key="l2">-1</data>"#), "{g}");
        assert!(g.contains(r#"<edge source="r1" target="r2"><data key="weight">-1</data></edge>"#), "{g}");
    }
}
