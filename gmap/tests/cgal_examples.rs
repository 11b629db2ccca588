//! The workspace's `examples/cgal_*.rs` ports (written with this crate only) against the
//! outputs of CGAL's own programs, recorded in `gmap/tests/data/cgal/` (see its README for how they were obtained and which lines list items
//! in an order that is an artefact of CGAL's containers).
//!
//! Each example exposes `run(out)`, which writes what its `main` prints; the test includes
//! the example's source as a module and compares what `run` writes with the recorded file,
//! line by line: exactly, or as sorted lists of `; `-separated items on the lines listed.

use std::io::Write;
use std::path::Path;

type Run = fn(&mut dyn Write) -> Result<(), Box<dyn std::error::Error>>;

/// The items of a list line, sorted: the text after the first `: ` (or the whole line), cut
/// at `;`, trimmed, empty items dropped.
fn sorted_items(line: &str) -> (String, Vec<String>) {
    let (head, list) = match line.find(": ") {
        Some(k) => (line[..k + 2].to_string(), &line[k + 2..]),
        None => (String::new(), line),
    };
    let mut items: Vec<String> = list.split(';').map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect();
    items.sort();
    (head, items)
}

/// Runs the port and compares its output with `gmap/tests/data/cgal/NAME.out`, from the recorded
/// line `skip` on (CGAL lines before it come from a part the port does not reproduce).
/// `unordered` lists the 1-based lines (of the recorded file) compared as sorted items.
fn check(name: &str, run: Run, skip: usize, unordered: &[usize]) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cgal").join(format!("{name}.out"));
    let expected = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut out = Vec::new();
    run(&mut out).unwrap_or_else(|e| panic!("{name}: {e}"));
    let got = String::from_utf8(out).expect("utf-8 output");
    let want: Vec<&str> = expected.lines().skip(skip).collect();
    let have: Vec<&str> = got.lines().collect();
    assert_eq!(have.len(), want.len(), "{name}: line count\n--- ours\n{got}--- CGAL's\n{expected}");
    for (k, (h, w)) in have.iter().zip(&want).enumerate() {
        let line = k + 1 + skip;
        if unordered.contains(&line) {
            assert_eq!(sorted_items(h), sorted_items(w), "{name}, line {line} as sorted items");
        } else {
            assert_eq!(h, w, "{name}, line {line}");
        }
    }
}

#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_2_moebius.rs"]
mod gmap_2_moebius;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_3_dynamic_onmerge.rs"]
mod gmap_3_dynamic_onmerge;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_3_insert.rs"]
mod gmap_3_insert;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_3_marks.rs"]
mod gmap_3_marks;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_3_operations.rs"]
mod gmap_3_operations;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_3_simple_example.rs"]
mod gmap_3_simple_example;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_3_with_colored_facets.rs"]
mod gmap_3_with_colored_facets;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_4_simple_example.rs"]
mod gmap_4_simple_example;
#[allow(dead_code)]
#[path = "../../examples/cgal_gmap_linear_cell_complex_3.rs"]
mod gmap_linear_cell_complex_3;
#[allow(dead_code)]
#[path = "../../examples/cgal_linear_cell_complex_3_operations.rs"]
mod linear_cell_complex_3_operations;
#[allow(dead_code)]
#[path = "../../examples/cgal_linear_cell_complex_4.rs"]
mod linear_cell_complex_4;

/// Every port: CGAL's program name, the port's `run`, and `skip` and `unordered` as in
/// [`check`].
const PORTS: &[(&str, Run, usize, &[usize])] = &[
    ("gmap_2_moebius", gmap_2_moebius::run, 0, &[]),
    ("gmap_3_simple_example", gmap_3_simple_example::run, 0, &[]),
    ("gmap_4_simple_example", gmap_4_simple_example::run, 0, &[]),
    ("gmap_3_marks", gmap_3_marks::run, 0, &[]),
    ("gmap_3_operations", gmap_3_operations::run, 0, &[]),
    ("gmap_3_insert", gmap_3_insert::run, 0, &[]),
    ("linear_cell_complex_4", linear_cell_complex_4::run, 0, &[]),
    ("gmap_3_with_colored_facets", gmap_3_with_colored_facets::run, 0, &[1, 2]),
    ("gmap_3_dynamic_onmerge", gmap_3_dynamic_onmerge::run, 0, &[2, 7, 9]),
    ("gmap_linear_cell_complex_3", gmap_linear_cell_complex_3::run, 0, &[1, 2, 3, 4, 5, 6, 7]),
    ("linear_cell_complex_3_operations", linear_cell_complex_3_operations::run, 1, &[]),
];

#[test]
fn every_port_prints_what_cgal_prints() {
    for &(name, run, skip, unordered) in PORTS {
        check(name, run, skip, unordered);
    }
}

#[test]
fn sorted_items_ignore_order_and_keep_the_head() {
    assert_eq!(sorted_items("Volume 1 : 1 0 0; -1 0 0; "), sorted_items("Volume 1 : -1 0 0; 1 0 0;"));
    assert_ne!(sorted_items("Volume 1 : 1 0 0; "), sorted_items("Volume 2 : 1 0 0; "));
    assert_ne!(sorted_items("2; 7; "), sorted_items("2; 7; 7; "));
}
