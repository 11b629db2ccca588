//! CGAL's `gmap_3_dynamic_onmerge` in this library: two hexahedra with a weight (an `f64`,
//! 1 on every face), hooks set at run time that print what they do, a 3-sew along a face
//! (one merge: 1 + 1), a vertex inserted in that face (three splits, each sharing the
//! weight), then the merge hook taken off and one of the new edges removed (a merge that
//! prints nothing). Prints the hooks' lines, and the weights and characteristics after
//! each step, as CGAL's example does (`gmap/tests/data/cgal/gmap_3_dynamic_onmerge.out`).
//!
//! CGAL's split hook shares the weight in proportion to the darts of the two faces; a
//! split hook here sees the two values only, so it halves: the same figures, as every
//! split here cuts a face into two triangles of the same size. The hooks outlive the
//! borrow of `out`, so they write to a shared log that `run` copies out after each step.
//! CGAL lists the weights in the order of its attribute container; this port prints them
//! sorted (the test compares both as sorted lists).
//!
//! `cargo run --release --example cgal_gmap_3_dynamic_onmerge`

use std::error::Error;
use std::io::Write;
use std::sync::{Arc, Mutex};

use gmap::core::{Cells, DartId, GMap};
use gmap::ops::build;
use gmap::ops::euler::ops::{insert_cell_0_in_cell_2, try_remove_cell};

/// A 3-map with an `f64` weight on every face.
type Map = GMap<((), (), Cells<f64>, ())>;

/// The lines the hooks print, waiting to be written out.
type Log = Arc<Mutex<Vec<String>>>;

/// Writes the log's lines to `out` and empties it.
fn flush(log: &Log, out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let lines = std::mem::take(&mut *log.lock().map_err(|_| "the hook log is poisoned")?);
    for line in lines {
        writeln!(out, "{line}")?;
    }
    Ok(())
}

/// The weights, sorted, each followed by `"; "`, then the characteristics.
fn display(g: &Map, out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let mut weights: Vec<f64> = g.attributes::<2>().map(|(_, &w)| w).collect();
    weights.sort_by(f64::total_cmp);
    let line: String = weights.iter().map(|w| format!("{w}; ")).collect();
    writeln!(out, "{line}")?;
    writeln!(out, "{}", g.characteristics())?;
    Ok(())
}

/// Runs the example and writes its ten lines to `out`.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let log: Log = Arc::default();
    let mut g: Map = GMap::with_attributes(3);
    let hexahedron = build::cube(3)?;
    let first = g.try_append(&hexahedron)?[0];
    let second = g.try_append(&hexahedron)?[0];
    let faces: Vec<DartId> = g.one_dart_per_cell(2).collect();
    for f in faces {
        g.try_set_attribute::<2>(f, 1.0)?;
    }
    let split_log = log.clone();
    g.set_on_split::<2>(move |kept, copy| {
        *kept /= 2.0;
        *copy = *kept;
        if let Ok(mut lines) = split_log.lock() {
            lines.push(format!("After on split faces: info of face1={kept}, info of face2={copy}"));
        }
    });
    let merge_log = log.clone();
    g.set_on_merge::<2>(move |kept, other| {
        *kept += other;
        if let Ok(mut lines) = merge_log.lock() {
            lines.push(format!("After on merge faces: info of face1={kept}, info of face2={other}"));
        }
    });

    g.try_sew(first, second, 3)?;
    flush(&log, out)?;
    display(&g, out)?;

    let centre = insert_cell_0_in_cell_2(&mut g, second, None)?;
    flush(&log, out)?;
    display(&g, out)?;

    // without a merge hook the kept weight stays as it is
    g.set_on_merge::<2>(|_, _| {});
    // the new edge at the corner of `second`: its triangle and the last one split off it
    // merge, both weighing 0.25
    try_remove_cell(&mut g, centre, 1)?;
    flush(&log, out)?;
    display(&g, out)?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
