//! The format registry: one row per file format, and everything that depends on a format
//! reads it from here — [`crate::open`] (the reader and the kind of [`Input`] it makes),
//! [`crate::homology_file`]'s checks made before a file is read, the images
//! [`crate::persistence_file`] takes, [`crate::save()`] (the writer and what it keeps), the
//! command line's help text ([`extensions_of`]) and the Python package's `open` and `save`
//! (the class of each kind, [`Kind::python_class`]).
//!
//! A new format is one reader (`crate::read`) or writer (`crate::write`) and one row of
//! [`FORMATS`].
//!
//! | extension | reads | writes | keeps |
//! |---|---|---|---|
//! | `.gmap` | map | any input through its G-map | points, labels |
//! | `.cgal.xml` | map (CGAL's generalized maps) | a map with its vertex points | points |
//! | `.moka` | map | a map of dimension ≤ 3 | points |
//! | `.off` | map | a 2-map with points (`--boundary`: a 3-map's boundary) | points |
//! | `.vtk` | map (unstructured grid) | a map of dimension ≤ 3 with points, a full cubical set as voxels | points, labels |
//! | `.vtu` | map | a map of dimension ≤ 3 with points | points, labels |
//! | `.msh` | map | a map of dimension ≤ 3 with points, cells Gmsh has | points, labels |
//! | `.facets` | simplicial complex | a simplicial complex's facets; any other input through its G-map (the barycentric subdivision) | – |
//! | `.lex[#name]` | simplicial complex | – | – |
//! | `.json` | architectural complex | any input's incidence graph | points, labels |
//! | `.cub` | cubical set | a full cubical set's cubes | – |
//! | `.cel`, `.pbm` | cubical set | – | – |
//! | `.npy`, `.complex` | image (memory-mapped) | an image | – |
//! | `.pgm`, `.png` | image (grey values) | – | – |
//! | `.txt` | image (Perseus cubical; a periodic one refused) | – | – |
//! | `.lar.json` | – | a map's LAR matrices | – |
//! | `.dot`, `.graphml` | – | any input's incidence graph | labels |

use std::path::Path;

use crate::error::{err, Error, Result};
use crate::input::{extension, Input, Kind, OpenOptions};
use crate::{read, write};

/// How a format is read: into an input of a kind, or refused with the reason (a format
/// written only, as a view or an export).
#[derive(Clone, Copy)]
pub(crate) enum Reader {
    /// the reader and the kind of input it makes
    Reads(Kind, read::ReadFn),
    /// written only: why a file of this format is not read
    WrittenOnly(&'static str),
}

/// How a format is written.
#[derive(Clone, Copy)]
pub(crate) enum Writer {
    /// not written
    None,
    /// a map format: the writer of a map, of a map with its labels and points (`None`: the
    /// plain writer, labels dropped), of a full cubical set's cubes as they are (`None`:
    /// through the G-map of its cubes), and of a simplicial complex's facets as they are
    /// (`None`: through its G-map)
    Map {
        map: write::MapFn,
        labelled: Option<write::LabelledFn>,
        cubes: Option<write::CubesFn>,
        facets: Option<write::FacetsFn>,
    },
    /// a full cubical set's cubes, as they are
    Cubes(write::CubesFn),
    /// the incidence graph of any input (regions and entries)
    Graph(write::GraphFn),
    /// an image as it is
    Image(write::ImageFn),
}

/// One file format.
#[derive(Clone, Copy)]
pub struct Format {
    /// the extension, lower-case, without its dot (`lar.json` for LAR's files)
    pub extension: &'static str,
    /// what the format is, in a few words
    pub description: &'static str,
    /// whether a file of the format carries the labels of cells or regions through a write
    pub keeps_labels: bool,
    /// whether it carries the points of vertices through a write
    pub keeps_points: bool,
    pub(crate) reader: Reader,
    pub(crate) writer: Writer,
}

impl std::fmt::Debug for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Format")
            .field("extension", &self.extension)
            .field("reads", &self.reads())
            .field("writes", &self.is_written())
            .finish()
    }
}

impl Format {
    /// The kind of input a file of this format opens as (`None`: the format is written only).
    pub fn reads(&self) -> Option<Kind> {
        match self.reader {
            Reader::Reads(kind, _) => Some(kind),
            Reader::WrittenOnly(_) => None,
        }
    }

    /// Whether [`crate::save()`] writes this format.
    pub fn is_written(&self) -> bool {
        !matches!(self.writer, Writer::None)
    }

    /// Whether the output is an incidence graph (`.json`, `.dot`, `.graphml`).
    pub fn is_graph(&self) -> bool {
        matches!(self.writer, Writer::Graph(_))
    }

    /// Whether a file of this format is a grey-value image ([`Kind::Image`]).
    pub fn is_image(&self) -> bool {
        self.reads() == Some(Kind::Image)
    }
}

/// Every format, in the order the help text lists them.
pub static FORMATS: &[Format] = &[
    Format {
        extension: "gmap",
        description: "native G-map text with points and cell labels",
        keeps_labels: true,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::gmap),
        writer: Writer::Map { map: write::gmap, labelled: Some(write::labelled_gmap), cubes: None, facets: None },
    },
    Format {
        extension: "cgal.xml",
        description: "CGAL's XML generalized maps (save_generalized_map) with vertex points",
        keeps_labels: false,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::cgal_xml),
        writer: Writer::Map { map: write::cgal_xml, labelled: None, cubes: None, facets: None },
    },
    Format {
        extension: "moka",
        description: "Moka's ascii 3G-maps with points",
        keeps_labels: false,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::moka),
        writer: Writer::Map { map: write::moka, labelled: None, cubes: None, facets: None },
    },
    Format {
        extension: "off",
        description: "polygon meshes",
        keeps_labels: false,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::off),
        writer: Writer::Map { map: write::off, labelled: None, cubes: None, facets: None },
    },
    Format {
        extension: "vtk",
        description: "legacy VTK unstructured grids, data as labels",
        keeps_labels: true,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::mesh),
        writer: Writer::Map {
            map: write::vtk,
            labelled: Some(write::labelled_vtk),
            cubes: Some(write::voxels_vtk),
            facets: None,
        },
    },
    Format {
        extension: "vtu",
        description: "XML VTK unstructured grids, data as labels",
        keeps_labels: true,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::mesh),
        writer: Writer::Map { map: write::vtu, labelled: Some(write::labelled_vtu), cubes: None, facets: None },
    },
    Format {
        extension: "msh",
        description: "Gmsh meshes, physical groups and data as labels",
        keeps_labels: true,
        keeps_points: true,
        reader: Reader::Reads(Kind::Map, read::mesh),
        writer: Writer::Map { map: write::msh, labelled: Some(write::labelled_msh), cubes: None, facets: None },
    },
    Format {
        extension: "facets",
        description: "simplicial complexes, one facet per line",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Simplicial, read::facets),
        writer: Writer::Map { map: write::facets, labelled: None, cubes: None, facets: Some(write::complex_facets) },
    },
    Format {
        extension: "lex",
        description: "Lutz's lists of facets, several complexes per file (FILE.lex#name)",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Simplicial, read::lex),
        writer: Writer::None,
    },
    Format {
        extension: "json",
        description: "architectural complexes and incidence graphs",
        keeps_labels: true,
        keeps_points: true,
        reader: Reader::Reads(Kind::Arch, read::json),
        writer: Writer::Graph(write::json_graph),
    },
    Format {
        extension: "cub",
        description: "CHomP's cubical sets and cells",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Cubical, read::cub),
        writer: Writer::Cubes(write::cub),
    },
    Format {
        extension: "cel",
        description: "CHomP's cubical cell complexes",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Cubical, read::cub),
        writer: Writer::None,
    },
    Format {
        extension: "pbm",
        description: "Netpbm bitmaps, black pixels as unit squares",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Cubical, read::pbm),
        writer: Writer::None,
    },
    Format {
        extension: "npy",
        description: "numpy arrays as grey-value images",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Image, read::image),
        writer: Writer::Image(write::npy),
    },
    Format {
        extension: "complex",
        description: "DIPHA's image files",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Image, read::image),
        writer: Writer::Image(write::dipha),
    },
    Format {
        extension: "pgm",
        description: "Netpbm grey images",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Image, read::raster),
        writer: Writer::None,
    },
    Format {
        extension: "png",
        description: "PNG grey images",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Image, read::raster),
        writer: Writer::None,
    },
    Format {
        extension: "txt",
        description: "Perseus cubical complexes (GUDHI's perseus_file): top-cell values, one a line",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::Reads(Kind::Image, read::perseus),
        writer: Writer::None,
    },
    Format {
        extension: "lar.json",
        description: "LAR's characteristic matrices",
        keeps_labels: false,
        keeps_points: false,
        reader: Reader::WrittenOnly("is written only, as an export: read the file it came from"),
        writer: Writer::Map { map: write::lar, labelled: None, cubes: None, facets: None },
    },
    Format {
        extension: "dot",
        description: "incidence graphs for Graphviz",
        keeps_labels: true,
        keeps_points: false,
        reader: Reader::WrittenOnly("is written only, as a view (read the .gmap it came from)"),
        writer: Writer::Graph(write::dot_graph),
    },
    Format {
        extension: "graphml",
        description: "incidence graphs for networkx and Gephi",
        keeps_labels: true,
        keeps_points: false,
        reader: Reader::WrittenOnly("is written only, as a view (read the file it came from)"),
        writer: Writer::Graph(write::graphml_graph),
    },
];

/// The format of `path` by its extension (case does not matter; `.lar.json` before
/// `.json`, `FILE.lex#name` as `.lex`), `None` for an extension no row has.
pub fn format_of(path: &Path) -> Option<&'static Format> {
    let lower = path.to_string_lossy().to_lowercase();
    let ext = extension(path);
    FORMATS
        .iter()
        .filter(|f| f.extension.contains('.'))
        .find(|f| lower.ends_with(&format!(".{}", f.extension)))
        .or_else(|| FORMATS.iter().find(|f| f.extension == ext))
}

/// The extensions [`crate::open`] reads, in the registry's order.
pub fn input_extensions() -> impl Iterator<Item = &'static str> {
    FORMATS.iter().filter(|f| f.reads().is_some()).map(|f| f.extension)
}

/// The extensions [`crate::save()`] writes, in the registry's order.
pub fn output_extensions() -> impl Iterator<Item = &'static str> {
    FORMATS.iter().filter(|f| f.is_written()).map(|f| f.extension)
}

/// The extensions that open as one of `kinds`, as messages and the help text list them:
/// `.cub, .cel, .pbm`.
pub fn extensions_of(kinds: &[Kind]) -> String {
    let listed: Vec<String> = FORMATS
        .iter()
        .filter(|f| f.reads().is_some_and(|k| kinds.contains(&k)))
        .map(|f| format!(".{}", f.extension))
        .collect();
    listed.join(", ")
}

/// Every extension [`crate::open`] reads, as the help text lists them (`.lex[#name]`: one
/// complex of a `.lex` file).
pub fn input_help() -> String {
    extensions_of(&Kind::ALL).replace(".lex", ".lex[#name]")
}

/// The outputs of `gmap convert`, as its help text lists them: the map and image formats,
/// then the incidence graphs.
pub fn output_help() -> String {
    let written = |graph: bool| -> Vec<String> {
        FORMATS
            .iter()
            .filter(|f| f.is_written() && f.is_graph() == graph)
            .map(|f| format!(".{}", f.extension))
            .collect()
    };
    format!("{}, or the incidence graph as {}", written(false).join(", "), written(true).join(", "))
}

/// The kind of input `path` opens as, by its extension, without reading it (`None`: an
/// extension that is not read).
pub fn kind_of(path: &Path) -> Option<Kind> {
    format_of(path).and_then(Format::reads)
}

/// Reads `path` with the reader of its format; refuses a format that is written only and an
/// extension no format has, with the extensions read.
pub(crate) fn read(path: &Path, opts: &OpenOptions) -> Result<Input> {
    match format_of(path).map(|f| (f, f.reader)) {
        Some((_, Reader::Reads(_, read))) => read(path, opts),
        Some((f, Reader::WrittenOnly(why))) => Err(written_only(path, f, why)),
        None => Err(unknown_input(path)),
    }
}

fn written_only(path: &Path, f: &Format, why: &str) -> Error {
    let what = match f.extension {
        "lar.json" => ".lar.json (LAR)".to_string(),
        ext => format!("unsupported input format '.{ext}': it"),
    };
    err!(Unsupported, "{}: {what} {why}", path.display()).naming_path(path)
}

/// The refusal of a path whose extension names no format read; an IFC file is pointed to
/// the Python package, which reads it through IfcOpenShell.
pub(crate) fn unknown_input(path: &Path) -> Error {
    match extension(path).as_str() {
        "ifc" => err!(
            Unsupported,
            "{}: IFC is read through the Python package and IfcOpenShell: pip install './python[ifc]' (from the gmap repository), then in Python gmap.ifc.open(path) gives its architectural complex (rooms, walls, doors, windows), which .save(\"model.json\") writes for the command line",
            path.display()
        ),
        "" => err!(
            Unsupported,
            "{}: the file name has no extension, which names the format: one of .{}",
            path.display(),
            input_extensions().collect::<Vec<_>>().join(", .")
        ),
        other => err!(
            Unsupported,
            "{}: unsupported input format '.{}'",
            path.display(),
            gmap_core::io::shorten(other.as_bytes(), 40)
        ),
    }
    .naming_path(path)
}

/// The format `output` is written in, or the refusal: an extension no format has, or a
/// format that is read only.
pub(crate) fn output_format(output: &Path) -> Result<&'static Format> {
    match format_of(output) {
        Some(f) if f.is_written() => Ok(f),
        _ => Err(err!(
            Unsupported,
            "{}: unsupported output format '.{}'",
            output.display(),
            gmap_core::io::shorten(extension(output).as_bytes(), 40)
        )),
    }
}

/// An input from the text of a file of the format `extension` held in memory (no file:
/// messages name none), read as the file would be, with the facade's kinds of error: a
/// `.gmap` map with its points and labels, an architectural complex's `.json`. How the
/// Python package makes `GMap.from_text` and `ArchComplex(text)` and unpickles them; the
/// other formats are read from files only.
pub fn parse_text(extension: &str, text: &str) -> Result<Input> {
    match extension {
        "gmap" => Ok(Input::labelled_map_from(
            gmap_core::io::parse_labelled_gmap(text.as_bytes(), "<text>")?,
            crate::input::Source::default(),
        )),
        "json" => {
            let x =
                gmap_homology::json::read_json(text).map_err(|e| Error::from_source(read::json_error_kind(&e), e))?;
            Ok(Input::Arch(crate::Sourced::new(x)))
        }
        other => Err(err!(Unsupported, "a '.{other}' is read from a file only; text is read as .gmap or .json")),
    }
}

/// The text [`crate::save()`] writes for `input` in the format `extension` (the text
/// [`parse_text`] reads back): a map's `.gmap` (with its points and labels), an
/// architectural complex's `.json`.
pub fn to_text(input: &Input, extension: &str) -> Result<String> {
    match (extension, input) {
        ("gmap", Input::Map(m)) => {
            let bytes = match m.labelled() {
                Some(g) => gmap_core::io::format_labelled_gmap(g?),
                None => {
                    gmap_core::io::format_labelled_gmap(&gmap_core::LabelledGMap::from_dense_with_attributes(m.map()).0)
                }
            };
            Ok(String::from_utf8_lossy(&bytes).into_owned())
        }
        ("json", Input::Arch(x)) => Ok(crate::write::json_graph(x)),
        (ext, input) => Err(err!(
            Unsupported,
            "the text of a {} as '.{ext}': text is written for a map as .gmap, an architectural complex as .json",
            input.kind()
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_extension_has_one_row() {
        let mut seen = std::collections::HashSet::new();
        for f in FORMATS {
            assert!(seen.insert(f.extension), "two rows for .{}", f.extension);
            assert!(f.reads().is_some() || f.is_written(), ".{} is neither read nor written", f.extension);
        }
    }

    #[test]
    fn lar_json_is_not_json() {
        assert_eq!(format_of(Path::new("a/B.LAR.JSON")).unwrap().extension, "lar.json");
        assert_eq!(format_of(Path::new("b.json")).unwrap().extension, "json");
        assert_eq!(kind_of(Path::new("x.lex#name")), Some(Kind::Simplicial));
        assert_eq!(kind_of(Path::new("x.dot")), None);
        assert!(format_of(Path::new("x.unknown")).is_none());
    }

    #[test]
    fn text_reads_back() {
        let gmap_text = "gmap 1 2\n1 0\n0 1\npoints 2\n0 0.0 0.0 0.0\n1 2.5 0.0 -1.0\nlabels 1 1\n0 name=\"beam\"\n";
        let m = parse_text("gmap", gmap_text).unwrap();
        assert_eq!(to_text(&m, "gmap").unwrap(), gmap_text);
        let bad = parse_text("gmap", "gmap 1 2\n1 7\n").unwrap_err();
        assert_eq!(bad.kind(), crate::ErrorKind::Parse);
        assert!(parse_text("json", "{").is_err());
        assert!(parse_text("off", "OFF").is_err());
        assert!(to_text(&m, "json").is_err());
    }

    #[test]
    fn help_lists_every_kind() {
        assert_eq!(extensions_of(&[Kind::Cubical, Kind::Image]), ".cub, .cel, .pbm, .npy, .complex, .pgm, .png, .txt");
        assert!(input_help().contains(".lex[#name]"));
        assert!(output_help().ends_with("or the incidence graph as .json, .dot, .graphml"));
    }
}
