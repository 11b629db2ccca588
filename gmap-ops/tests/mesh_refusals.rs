//! Broken meshes are refused, naming what is missing or what was met (the hostile-input
//! audit of issue 47): a `.msh`, `.vtk` or `.vtu` cut before a section it needs, or holding
//! no cell, is not an empty map; an element block whose entity `$Entities` does not list
//! would lose its physical group; a `.vtu` with a malformed XML declaration, a second
//! `AppendedData` or `CellData`, an unknown encoding or an array without a name.

use std::path::PathBuf;

use gmap_ops::import::read_mesh;

fn data(name: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/mesh")).join(name)
}

fn fixture(name: &str) -> Vec<u8> {
    std::fs::read(data(name)).unwrap()
}

/// The message of reading `bytes` as a file `name`, without the file's name.
fn refusal(name: &str, bytes: &[u8]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join(name);
    std::fs::write(&p, bytes).unwrap();
    match read_mesh(&p, None).unwrap() {
        Ok(g) => panic!("{name} read as a map of {} darts", g.dart_count()),
        Err(e) => {
            let e = e.to_string();
            let prefix = format!("{}: ", p.display());
            assert!(e.starts_with(&prefix), "{e}");
            e[prefix.len()..].to_string()
        }
    }
}

/// `text` up to and including the first occurrence of `end`.
fn cut_after(text: &[u8], end: &str) -> Vec<u8> {
    let at = text.windows(end.len()).position(|w| w == end.as_bytes()).unwrap();
    text[..at + end.len()].to_vec()
}

fn ends_before(section: &str) -> String {
    format!("the file ends before the {section} section it needs")
}

#[test]
fn msh_cut_short_or_empty_is_refused_naming_the_section() {
    let msh = fixture("tet_cube.msh");
    assert_eq!(refusal("m.msh", &cut_after(&msh, "$EndNodes\n")), ends_before("$Elements"));
    assert_eq!(refusal("m.msh", &cut_after(&msh, "$EndMeshFormat\n")), ends_before("$Nodes"));
    assert_eq!(refusal("m.msh", b""), ends_before("$MeshFormat"));
    let none = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n0 0 0 0\n$EndNodes\n$Elements\n0 0 0 0\n$EndElements\n";
    assert_eq!(refusal("m.msh", none.as_bytes()), "$Elements holds no cell: an empty mesh is not read");
}

#[test]
fn msh_element_block_of_an_unlisted_entity_is_refused() {
    // the tetrahedra's block names volume 7, which $Entities does not list
    let text = String::from_utf8(fixture("tet_cube.msh")).unwrap();
    let at = text.find("$Elements").unwrap();
    let block = text[at..].find("\n3 1 4 ").unwrap() + at;
    let broken = format!("{}\n3 7 4 {}", &text[..block], &text[block + "\n3 1 4 ".len()..]);
    let e = refusal("m.msh", broken.as_bytes());
    assert!(
        e.ends_with(
            "an element block of entity 7 (dimension 3), which $Entities does not list: its physical groups are unknown"
        ),
        "{e}"
    );
}

#[test]
fn vtk_header_only_or_without_cells_is_refused() {
    let header = b"# vtk DataFile Version 4.2\nnothing\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    assert_eq!(refusal("m.vtk", header), ends_before("POINTS"));
    let points = b"# vtk DataFile Version 4.2\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 double\n0 0 0\n";
    assert_eq!(refusal("m.vtk", points), ends_before("CELLS"));
    let no_types = [&points[..], b"CELLS 1 2\n1 0\n"].concat();
    assert_eq!(refusal("m.vtk", &no_types), ends_before("CELL_TYPES"));
    let empty = [&points[..], b"CELLS 0 0\nCELL_TYPES 0\n"].concat();
    assert_eq!(refusal("m.vtk", &empty), "CELLS holds no cell: an empty mesh is not read");
}

const GRID_HEAD: &str =
    "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n";

/// One vertex cell, with `cell_data` inside its `CellData`.
fn one_vertex(decl: &str, cell_data: &str) -> String {
    format!(
        "{decl}{GRID_HEAD}<Piece NumberOfPoints=\"1\" NumberOfCells=\"1\">\n\
<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray></Points>\n\
<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0</DataArray>\n\
<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">1</DataArray>\n\
<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">1</DataArray></Cells>\n\
{cell_data}</Piece>\n</UnstructuredGrid>\n</VTKFile>\n"
    )
}

#[test]
fn vtu_without_piece_or_cells_is_refused() {
    let none = format!("<?xml version=\"1.0\"?>\n{GRID_HEAD}</UnstructuredGrid>\n</VTKFile>\n");
    assert_eq!(refusal("m.vtu", none.as_bytes()), ends_before("<Piece>"));
    let empty = format!(
        "{GRID_HEAD}<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"></Piece>\n</UnstructuredGrid>\n</VTKFile>\n"
    );
    assert_eq!(refusal("m.vtu", empty.as_bytes()), "<Piece> holds no cell: an empty mesh is not read");
}

#[test]
fn vtu_well_formed_reads() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("m.vtu");
    let good = "<CellData><DataArray type=\"Int32\" Name=\"k\" format=\"ascii\">3</DataArray></CellData>\n";
    for decl in ["", "<?xml version=\"1.0\"?>\n", "<?xml version='1.0' encoding='UTF-8' standalone=\"yes\" ?>\n"] {
        std::fs::write(&p, one_vertex(decl, good)).unwrap();
        let g = read_mesh(&p, None).unwrap().unwrap_or_else(|e| panic!("{decl}: {e}"));
        assert_eq!(g.dart_count(), 1, "{decl}");
    }
}

#[test]
fn vtu_malformed_declarations_are_refused() {
    let good = "<CellData><DataArray type=\"Int32\" Name=\"k\" format=\"ascii\">3</DataArray></CellData>\n";
    for (decl, message) in [
        ("<?xml version=\"1.0\"\n", "XML declaration: not closed by '?>'"),
        ("<?xml versio=\"1.0\"?>\n", "XML declaration: versio=\"1.0\" is not a version 1.x, an encoding UTF-8 and standalone yes or no, in that order"),
        ("<?xml version=\"2.0\"?>\n", "XML declaration: version=\"2.0\" is not a version 1.x, an encoding UTF-8 and standalone yes or no, in that order"),
        ("<?xml version=1.0?>\n", "XML declaration: version: the value is not quoted"),
        ("<?xml encoding=\"UTF-8\" version=\"1.0\"?>\n", "XML declaration: encoding=\"UTF-8\" is not a version 1.x, an encoding UTF-8 and standalone yes or no, in that order"),
        ("<?xml version=\"1.0\"encoding=\"UTF-8\"?>\n", "XML declaration: no space after version"),
        ("<?xml?>\n", "XML declaration: '<?xml' is not followed by a space"),
        ("\n<?xml version=\"1.0\"?>\n", "an XML declaration after the start of the file"),
    ] {
        let e = refusal("m.vtu", one_vertex(decl, good).as_bytes());
        assert!(e.ends_with(message), "{decl:?}: {e}");
    }
}

#[test]
fn vtu_duplicated_sections_and_unnamed_arrays_are_refused() {
    let data = "<CellData><DataArray type=\"Int32\" Name=\"k\" format=\"ascii\">3</DataArray></CellData>\n";
    let e = refusal("m.vtu", one_vertex("", &format!("{data}{data}")).as_bytes());
    assert_eq!(e, "line 9: a second CellData element in Piece: it has one");
    let unnamed = "<CellData><DataArray type=\"Int32\" format=\"ascii\">3</DataArray></CellData>\n";
    let e = refusal("m.vtu", one_vertex("", unnamed).as_bytes());
    assert_eq!(e, "line 8: a DataArray of CellData without a Name: labels are named");
    let empty_name = "<CellData><DataArray type=\"Int32\" Name=\"\" format=\"ascii\">3</DataArray></CellData>\n";
    let e = refusal("m.vtu", one_vertex("", empty_name).as_bytes());
    assert_eq!(e, "line 8: a DataArray of CellData without a Name: labels are named");
    // the fuzzing's find: an attribute `Namce` for `Name`
    let e = refusal("m.vtu", &fixture("fuzz/vtu_empty_name.vtu"));
    assert_eq!(e, "line 7: a DataArray of CellData without a Name: labels are named");
}

#[test]
fn vtu_appended_data_twice_or_of_an_unknown_encoding_is_refused() {
    let ring = fixture("ring_raw.vtu");
    let at = ring.windows(14).position(|w| w == b"<AppendedData ").unwrap();
    let twice = [&ring[..at], b"<AppendedData encoding=\"raw\">_</AppendedData>\n", &ring[at..]].concat();
    let e = refusal("m.vtu", &twice);
    assert!(e.ends_with("a second AppendedData element: a file has one"), "{e}");
    let needle = b"encoding=\"raw\"";
    let at = ring.windows(needle.len()).position(|w| w == needle).unwrap();
    let bogus = [&ring[..at], b"encoding=\"base18446744073709551615\"", &ring[at + needle.len()..]].concat();
    let e = refusal("m.vtu", &bogus);
    assert!(e.ends_with("AppendedData encoding 'base18446744073709551615' is not read (raw, base64)"), "{e}");
}
