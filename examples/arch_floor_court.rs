//! A floor with a court, as an architect writes it in `.json`
//! (`tests/data/arch/floor_court.json`): one 2-region `floor` (named `ground floor`) whose
//! boundary is two circles, the outer walls and the court's, with string ids, points and
//! no incidence sign (the outer circle runs anticlockwise seen from above, the court's
//! clockwise). The region is an annulus, not a cell: the region complex has two components,
//! the space (`--topological`, AC Algorithm 8.16) is the annulus, (Z, Z, 0).
//!
//! Prints the homology of both, the TM edit check and the views of the edges.
//!
//! `cargo run --release --example arch_floor_court`

use std::error::Error;
use std::io::Write;
use std::path::Path;

#[allow(dead_code)]
#[path = "arch_rooms_door_window.rs"]
pub mod rooms;

/// The report on the floor.
pub fn run(out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    rooms::report(&Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/arch/floor_court.json"), out)
}

fn main() -> Result<(), Box<dyn Error>> {
    run(&mut std::io::stdout().lock())
}
