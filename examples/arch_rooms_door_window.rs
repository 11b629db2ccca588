//! Two rooms with a door and a window, as an architect writes them in `.json`
//! (`tests/data/arch/rooms_door_window.json`): string ids (`room 1`, `wall`, `door`,
//! `window`, `v0`, `e0`, …), the vertices' points, rooms named by a `name` label, and no
//! incidence sign (the reader chooses them from the points: every face's normal points out
//! of its room). The wall between the rooms holds the door (standing on the floor) and the
//! window (a hole in the wall: the wall is a region with two boundary circles, not a cell).
//!
//! Prints the homology of the region complex and of the space (`--topological`), the TM
//! edit check and the views of the walls (which room is on which side).
//!
//! `cargo run --release --example arch_rooms_door_window`

use std::error::Error;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The model's file in the repository.
pub fn model() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/rooms_door_window.json")
}

/// Writes the report on the model at `file` (also used for the floor with a court).
pub fn report(file: &Path, out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let input = gmap::open(file)?;
    let mut o = gmap::HomologyOptions::default();
    let regions = gmap::homology(&input, &o)?;
    o.topological = true;
    let space = gmap::homology(&input, &o)?;
    writeln!(out, "homology of the region complex: {}", groups(&regions))?;
    writeln!(out, "homology of the space (--topological): {}", groups(&space))?;
    write!(out, "{}", gmap::tm_check(&input)?.to_text())?;
    write!(out, "{}", gmap::tm_views(&input, None)?)?;
    Ok(())
}

/// The groups as `(Z, 0, Z^2)`.
fn groups(r: &gmap::Report) -> String {
    let text = r.to_text();
    let g: Vec<&str> =
        text.lines().filter_map(|l| l.strip_prefix("H_")).filter_map(|l| l.split(" = ").nth(1)).collect();
    format!("({})", g.join(", "))
}

/// The report on the two rooms.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    report(&model(), out)
}

#[allow(dead_code)]
fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
