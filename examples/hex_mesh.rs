//! A hexahedral mesh read from `.vtu` (meshio's default output: base64, zlib) into a labelled
//! 3-map, its cells, components and homology printed, then written as legacy `.vtk` with its
//! data as cell data (hexahedra stay VTK hexahedra):
//! `cargo run --release --example hex_mesh -- [IN.vtu] [OUT.vtk]` (default: the hollow block
//! of tests/data/mesh, written to `hex_mesh.vtk`).
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let input = args
        .next()
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/mesh/hex_hollow.vtu"));
    let output = PathBuf::from(args.next().unwrap_or_else(|| "hex_mesh.vtk".into()));

    // the cells sewn face to face, the data as labels
    let mesh = gmap::ops::import::read_vtu(&input, None)?;
    let (map, labels, _) = gmap::core::to_dense_labels(&mesh);
    println!("{}", gmap::core::Characteristics::of(&map));
    let labelled = labels.of.iter().map(|v| v.iter().filter(|l| !l.is_empty()).count()).collect::<Vec<_>>();
    println!("labelled cells per dimension: {labelled:?}");

    // its homology over Z by the cellular method
    let complex = gmap::algebra::cellular_complex(&map)?;
    println!("{}", gmap::algebra::homology_z(&complex.chain)?);

    gmap::ops::export::write_vtk_with_labels(&map, &labels, &output)?;
    println!("wrote {}", output.display());
    Ok(())
}
