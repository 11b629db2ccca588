//! Opens one file of each kind and prints its characteristics, route and groups, using the
//! facade only: `cargo run --release --example open_any`.
fn main() -> Result<(), gmap::Error> {
    let files = ["labelled_segment.gmap", "lutz/poincare.facets", "cubical/ring.cub", "arch/tetrahedron.json"];
    for file in files {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(file);
        let input = gmap::open(&path)?;
        let info = gmap::info(&input, &gmap::InfoOptions::default())?;
        let report = gmap::homology(&input, &gmap::HomologyOptions::default())?;
        println!("{file}: {} {}, route {}, {}", input.kind(), info.to_json(), report.route_name(), report.groups);
    }
    Ok(())
}
