//! CGAL's XML files of generalized maps (`.cgal.xml`), as CGAL 5.5's
//! `save_generalized_map` / `load_generalized_map` write and read them
//! (CGAL/Generalized_map_save_load.h, CGAL/Combinatorial_map_save_load.h):
//!
//! ```text
//! <data>
//!   <darts>
//!     <d><a i="0">2</a><a i="1">4</a></d>     one dart: its non-free alpha links, 1-based
//!   </darts>
//!   <attributes>
//!     <dimension index="0"><type>…</type><type_point>…</type_point>
//!       <a><d>1</d><p><x>0</x><y>0</y><z>0</z></p></a>   a vertex: one of its darts, its point
//!     </dimension>
//!   </attributes>
//! </data>
//! ```
//!
//! CGAL's file does not record the map's dimension: the reader takes the `dimension`
//! attribute of `<darts>` when present (this writer puts it there; CGAL's reader ignores
//! it), else the largest alpha index linked. Points of 0-attributes (2D points get z = 0)
//! are kept, on the dart named; a file holding values (`<v>`) of attributes or darts is
//! refused naming the line, since this reader would drop them. A combinatorial map's file (`<b>` links) is refused, naming it.
//! Errors name the file and the XML line; the dart count is checked against the dart limit
//! and the memory to be had before the alpha table is allocated.

use std::fmt::Write as _;
use std::path::Path;

use gmap_core::ids::Dart;
use gmap_core::DenseMap;

use super::common::read_text;
use super::{default_max_darts, FileError, ImportError};

/// Reads a CGAL XML generalized map, refusing more than `max_darts` darts.
pub fn read_cgal_xml(path: &Path, max_darts: Option<u64>) -> Result<DenseMap, FileError> {
    let text = read_text(path)?;
    parse_cgal_xml(&text, max_darts).map_err(|e| FileError::new(path, e))
}

fn syntax(doc: &roxmltree::Document, node: roxmltree::Node, message: String) -> ImportError {
    ImportError::Syntax { line: doc.text_pos_at(node.range().start).row as usize, message }
}

/// Parses the text of a CGAL XML generalized map. Never panics, whatever the text.
pub fn parse_cgal_xml(text: &str, max_darts: Option<u64>) -> Result<DenseMap, ImportError> {
    if text.trim().is_empty() {
        return Err(ImportError::Format("empty file: a CGAL XML map needs <data><darts>".into()));
    }
    let doc = roxmltree::Document::parse(text).map_err(|e| ImportError::Format(format!("not XML: {e}")))?;
    let data = doc.root_element();
    if !data.has_tag_name("data") {
        return Err(syntax(&doc, data, format!("root element <{}>, expected <data>", data.tag_name().name())));
    }
    let Some(darts) = data.children().find(|n| n.has_tag_name("darts")) else {
        return Err(syntax(&doc, data, "<data> without <darts>".into()));
    };
    if let Some(v) = doc.descendants().find(|n| n.has_tag_name("v")) {
        return Err(syntax(
            &doc,
            v,
            "an attribute or dart value <v>: values are not read, and reading the map without them would drop them"
                .into(),
        ));
    }
    let dart_nodes: Vec<_> = darts.children().filter(|n| n.has_tag_name("d")).collect();
    let count = dart_nodes.len() as u64;
    if count == 0 {
        return Err(syntax(&doc, darts, "<darts> holds no dart: an empty map is not read".into()));
    }
    let limit = max_darts.unwrap_or_else(|| default_max_darts(3));
    if count > limit {
        return Err(ImportError::Format(format!("{count} darts, over the limit of {limit} darts")));
    }
    if count >= u32::MAX as u64 {
        return Err(ImportError::Format(format!("{count} darts: more than a map holds")));
    }
    // links as (dart, index, target), checked before the table is sized
    let mut links: Vec<(u32, usize, u32)> = Vec::new();
    let mut top = 0usize;
    for (k, d) in dart_nodes.iter().enumerate() {
        for a in d.children().filter(|n| n.is_element()) {
            match a.tag_name().name() {
                "a" => {}
                "b" => {
                    return Err(syntax(
                        &doc,
                        a,
                        "a <b> (beta) link: this is a combinatorial map's file, only generalized maps' are read".into(),
                    ))
                }
                _ => continue,
            }
            let i: usize =
                a.attribute("i").and_then(|s| s.trim().parse().ok()).filter(|&i| i < 64).ok_or_else(|| {
                    syntax(&doc, a, format!("dart {}: alpha link without an index i below 64", k + 1))
                })?;
            let t: u64 =
                a.text().and_then(|s| s.trim().parse().ok()).filter(|&t| t >= 1 && t <= count).ok_or_else(|| {
                    syntax(&doc, a, format!("dart {}: alpha_{i} target is not a dart in 1..={count}", k + 1))
                })?;
            top = top.max(i);
            links.push((k as u32, i, (t - 1) as u32));
        }
    }
    let dim = match darts.attribute("dimension") {
        Some(s) => s
            .trim()
            .parse::<usize>()
            .ok()
            .filter(|&n| n >= top && n < 64)
            .ok_or_else(|| syntax(&doc, darts, format!("dimension \"{s}\" is not a number ≥ {top} below 64")))?,
        None => top,
    };
    let w = dim + 1;
    let cells = (count as usize).checked_mul(w).ok_or_else(|| ImportError::Format("too many darts".into()))?;
    gmap_core::resources::check_memory("the alpha table", Some(cells as u64 * 4))?;
    let mut alpha: Vec<u32> = Vec::new();
    if alpha.try_reserve_exact(cells).is_err() {
        return Err(ImportError::OutOfMemory { what: "the alpha table".into(), bytes: cells as u64 * 4 });
    }
    for d in 0..count as u32 {
        alpha.extend(std::iter::repeat_n(d, w));
    }
    for &(d, i, t) in &links {
        alpha[d as usize * w + i] = t;
    }
    let mut map = DenseMap::from_flat_unchecked(dim, alpha).map_err(|e| ImportError::Format(e.to_string()))?;
    map.validate().map_err(|e| ImportError::Format(e.to_string()))?;
    if let Some(attrs) = data.children().find(|n| n.has_tag_name("attributes")) {
        for dimn in attrs.children().filter(|n| n.has_tag_name("dimension")) {
            if dimn.attribute("index").map(str::trim) != Some("0") {
                continue;
            }
            for a in dimn.children().filter(|n| n.has_tag_name("a")) {
                let Some(p) = a.children().find(|n| n.has_tag_name("p")) else { continue };
                let dn = a.children().find(|n| n.has_tag_name("d"));
                let dart: u64 = dn
                    .and_then(|n| n.text())
                    .and_then(|s| s.trim().parse().ok())
                    .filter(|&t| t >= 1 && t <= count)
                    .ok_or_else(|| syntax(&doc, a, format!("vertex attribute without a dart in 1..={count}")))?;
                let mut xyz = [0.0f64; 3];
                for (c, name) in ["x", "y", "z"].iter().enumerate() {
                    match p.children().find(|n| n.has_tag_name(*name)) {
                        Some(n) => {
                            xyz[c] = n
                                .text()
                                .and_then(|s| s.trim().parse::<f64>().ok())
                                .filter(|v| v.is_finite())
                                .ok_or_else(|| syntax(&doc, n, format!("coordinate {name} is not a finite number")))?
                        }
                        None if c == 2 => {}
                        None => return Err(syntax(&doc, p, format!("point without coordinate {name}"))),
                    }
                }
                map.set_point(Dart::new((dart - 1) as u32), Some(xyz));
            }
        }
    }
    Ok(map)
}

/// The CGAL XML text of a map: its darts and alpha links, and one 0-attribute with its
/// point per vertex that has a point ([`DenseMap::vertex_point`]), named by its smallest dart.
pub fn format_cgal_xml(map: &DenseMap) -> String {
    let n = map.dim();
    let mut out = String::with_capacity(64 + map.dart_count() * 40);
    out.push_str("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<data><darts dimension=\"");
    let _ = write!(out, "{n}\">");
    for d in map.darts() {
        out.push_str("<d>");
        for (i, &t) in map.row(d).iter().enumerate() {
            if t != d.get() {
                let _ = write!(out, "<a i=\"{i}\">{}</a>", t as u64 + 1);
            }
        }
        out.push_str("</d>");
    }
    out.push_str("</darts><attributes>");
    // one 0-attribute per vertex with a point, on the vertex's smallest dart
    let mut body = String::new();
    for &d in &map.cells(0).reps {
        if let Some([x, y, z]) = map.vertex_point(d) {
            let _ = write!(body, "<a><d>{}</d><p><x>{x:?}</x><y>{y:?}</y><z>{z:?}</z></p></a>", d.get() as u64 + 1);
        }
    }
    if !body.is_empty() {
        out.push_str("<dimension index=\"0\"><type>v</type><type_point>N4CGAL7Point_3INS_5EpickEEE</type_point>");
        out.push_str(&body);
        out.push_str("</dimension>");
    }
    out.push_str("</attributes></data>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_keeps_darts_links_and_points() {
        let mut m = gmap_core::examples::cylinder();
        m.set_point(Dart::new(0), Some([0.5, -2.0, 1e300]));
        let back = parse_cgal_xml(&format_cgal_xml(&m), None).unwrap();
        assert_eq!(back.dim(), m.dim());
        assert_eq!(back.dart_count(), m.dart_count());
        for d in m.darts() {
            assert_eq!(back.row(d), m.row(d));
        }
        assert_eq!(back.point(Dart::new(0)), Some([0.5, -2.0, 1e300]));
    }

    #[test]
    fn reads_a_cgal_written_edge() {
        // two darts alpha_0-linked, as save_generalized_map writes a 1-map edge
        let t = "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<data><darts><d><a i=\"0\">2</a></d><d><a i=\"0\">1</a></d></darts><attributes/></data>";
        let m = parse_cgal_xml(t, None).unwrap();
        assert_eq!((m.dim(), m.dart_count()), (0, 2));
        assert_eq!(m.row(Dart::new(0)), &[1]);
    }

    #[test]
    fn malformed_files_are_typed_errors() {
        let e = |t: &str| parse_cgal_xml(t, None).unwrap_err().to_string();
        assert!(e("").contains("empty file"));
        assert!(e("<data><darts>").contains("not XML"));
        assert!(e("<data><darts></darts></data>").contains("holds no dart"));
        assert!(e("<map/>").contains("expected <data>"));
        assert!(e("<data><darts><d><a i=\"0\">3</a></d></darts></data>").contains("not a dart in 1..=1"));
        assert!(e("<data><darts><d><b i=\"1\">1</b></d></darts></data>").contains("combinatorial map"));
        // a value CGAL writes for an enabled attribute with information is refused, not dropped
        assert!(e("<data><darts><d><v>7</v></d></darts></data>").contains("values are not read"));
        // alpha_0 not an involution: 1->2 but 2 free
        assert!(!e("<data><darts><d><a i=\"0\">2</a></d><d/></darts></data>").is_empty());
        assert!(parse_cgal_xml("<data><darts><d/><d/></darts></data>", Some(1))
            .unwrap_err()
            .to_string()
            .contains("limit"));
    }
}
