//! Persistent homology through the facade: [`persistence`] on an opened [`Input`] (a G-map
//! with a numeric label per cell, a cubical set as a 0/1 image) and [`persistence_file`],
//! which also reads what only persistence uses: grey images (`.npy`, DIPHA's `.complex`,
//! `.pgm`, `.png`) and `.facets` files with a value per facet. The engine is
//! `gmap_homology::persistence`; this module picks the reader and the filtration.

use std::path::Path;

use gmap_homology::persistence::{
    cubical_persistence, plot, Construction, CubicalOptions, Diagram, FilteredComplex, SimplexValues,
};
use gmap_ops::import::image::{Image, Order};

use crate::input::extension;
use crate::{Error, ErrorKind, Input, Result};

/// What `gmap persistence` computes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PersistenceOptions {
    /// coefficients `Z/p` (default 2)
    pub field: u32,
    /// for images: T (values on top cells, GUDHI's default) or V (on vertices, CubicalRipser's)
    pub construction: Construction,
    /// for images: superlevel sets
    pub superlevel: bool,
    /// for images: identify the opposite faces of the box
    pub periodic: bool,
    /// a representative cycle per pair
    pub cycles: bool,
    /// for a `.gmap`: the numeric label giving each cell its value (default `value`)
    pub label: String,
}

impl Default for PersistenceOptions {
    fn default() -> Self {
        PersistenceOptions {
            field: 2,
            construction: Construction::T,
            superlevel: false,
            periodic: false,
            cycles: false,
            label: "value".into(),
        }
    }
}

/// A diagram with the 2-D image it came from, if it did (to draw cycles over).
#[derive(Clone, Debug)]
pub struct Persistence {
    /// the diagram
    pub diagram: Diagram,
    /// `(rows, cols, values)` of a 2-D image input
    pub image: Option<(usize, usize, Vec<f64>)>,
    /// whether the image's pixels are vertices (V-construction)
    pub vertex_centred: bool,
}

fn compute(e: gmap_homology::persistence::PersistenceError) -> Error {
    Error::from_source(ErrorKind::Compute, &e)
}

/// The engine's options for an image (`gmap_homology::persistence::cubical_persistence`);
/// public for callers that hold the values themselves (the Python package's numpy arrays).
pub fn cubical_options(o: &PersistenceOptions) -> CubicalOptions {
    CubicalOptions {
        construction: o.construction,
        superlevel: o.superlevel,
        periodic: o.periodic,
        field: o.field,
        cycles: o.cycles,
    }
}

/// The diagram of an opened input: a G-map by the label `opts.label` of its cells (a
/// `.gmap` file), a cubical set as the image with 0 on its cubes and 1 elsewhere. A
/// simplicial complex carries no values once opened: [`persistence_file`] reads them.
pub fn persistence(input: &Input, opts: &PersistenceOptions) -> Result<Diagram> {
    match input {
        Input::Map(m) => {
            let g = m.labelled().ok_or_else(|| {
                Error::new(ErrorKind::Unsupported, "a map carries values only as labels in a .gmap file")
                    .with_path(m.path())
            })??;
            let f = FilteredComplex::from_labelled_gmap(g, &opts.label).map_err(|e| compute(e).with_path(m.path()))?;
            f.diagram(opts.field, opts.cycles).map_err(compute)
        }
        Input::Cubical(c) => {
            c.require_full("the image of 0 on the cubes and 1 elsewhere")
                .map_err(|e| Error::new(ErrorKind::Unsupported, e.to_string()).with_path(c.path()))?;
            // the set's cubes, axis 0 fastest, as a C-order array of the reversed shape
            let mut shape = c.shape().to_vec();
            shape.reverse();
            let values: Vec<f64> = c.bits().iter().map(|&b| if b != 0 { 0.0 } else { 1.0 }).collect();
            cubical_persistence(&shape, &values, &cubical_options(opts)).map_err(compute)
        }
        Input::Image(img) => {
            let values: Vec<f64> = (0..img.len()).map(|i| img.value(i)).collect();
            let mut shape = img.shape().to_vec();
            if img.order() == Order::Fortran {
                shape.reverse();
            }
            cubical_persistence(&shape, &values, &cubical_options(opts)).map_err(compute)
        }
        Input::Simplicial(s) => Err(Error::new(
            ErrorKind::Unsupported,
            "a simplicial complex needs values: a .facets file with `: VALUE` after each facet",
        )
        .with_path(s.path())),
        Input::Arch(a) => {
            Err(Error::new(ErrorKind::Unsupported, "persistence of an architectural complex").with_path(a.path()))
        }
    }
}

/// Reads `path` and computes its diagram: images by content (`.npy`, `.complex`, `.pgm`,
/// `.png`), `.facets` with values, anything else through [`crate::open`] and
/// [`persistence`].
pub fn persistence_file(path: &Path, opts: &PersistenceOptions) -> Result<Persistence> {
    let ext = extension(path);
    let image = match ext.as_str() {
        "npy" | "complex" => Some(Image::read(path)),
        "pgm" | "png" => Some(gmap_ops::import::raster::read_raster(path)),
        _ => None,
    };
    if let Some(img) = image {
        let img = img.map_err(|e| Error::from_source(ErrorKind::Parse, &e).with_path(path))?;
        let values: Vec<f64> = (0..img.len()).map(|i| img.value(i)).collect();
        let mut shape = img.shape().to_vec();
        if img.order() == Order::Fortran {
            shape.reverse();
        }
        let diagram =
            cubical_persistence(&shape, &values, &cubical_options(opts)).map_err(|e| compute(e).with_path(path))?;
        let image = (shape.len() == 2 && img.order() == Order::C).then(|| (shape[0], shape[1], values));
        return Ok(Persistence { diagram, image, vertex_centred: opts.construction == Construction::V });
    }
    if ext == "facets" {
        let (sc, values) = gmap_ops::import::simplicial::read_valued_facets(path)
            .map_err(|e| Error::from_source(ErrorKind::Parse, &e).with_path(path))?;
        let values = values.ok_or_else(|| {
            Error::new(ErrorKind::Unsupported, "no values: write `: VALUE` after each facet").with_path(path)
        })?;
        let facets: Vec<Vec<u64>> = sc.facets().map(<[u64]>::to_vec).collect();
        let f = FilteredComplex::from_simplices(&facets, SimplexValues::PerSimplex(&values))
            .map_err(|e| compute(e).with_path(path))?;
        let diagram = f.diagram(opts.field, opts.cycles).map_err(compute)?;
        return Ok(Persistence { diagram, image: None, vertex_centred: false });
    }
    let input = crate::open(path)?;
    Ok(Persistence { diagram: persistence(&input, opts)?, image: None, vertex_centred: false })
}

/// A picture format, by the output's extension.
enum PictureFormat {
    Svg,
    Png,
}

fn picture_format(out: &Path) -> Result<PictureFormat> {
    match extension(out).as_str() {
        "svg" => Ok(PictureFormat::Svg),
        "png" => Ok(PictureFormat::Png),
        _ => Err(Error::new(ErrorKind::Unsupported, "plots are written as .svg or .png").with_path(out)),
    }
}

/// A raster as PNG bytes (8-bit RGB).
pub fn png_bytes(r: &plot::Raster) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    let mut enc = png::Encoder::new(&mut bytes, r.width, r.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut w = enc.write_header().map_err(|e| Error::from_source(ErrorKind::Write, &e))?;
    w.write_image_data(&r.rgb).map_err(|e| Error::from_source(ErrorKind::Write, &e))?;
    w.finish().map_err(|e| Error::from_source(ErrorKind::Write, &e))?;
    Ok(bytes)
}

fn write_picture(out: &Path, svg: impl FnOnce() -> String, raster: impl FnOnce() -> plot::Raster) -> Result<()> {
    let bytes = match picture_format(out)? {
        PictureFormat::Svg => svg().into_bytes(),
        PictureFormat::Png => png_bytes(&raster()).map_err(|e| e.with_path(out))?,
    };
    gmap_core::io::write_atomic(out, &bytes).map_err(|e| Error::from_source(ErrorKind::Write, &e).with_path(out))
}

/// Writes the diagram as a picture to `out`, SVG or PNG by its extension (other
/// extensions are refused); with `barcode`, the barcode. The PNG has the SVG's marks
/// without its text.
pub fn plot_file(p: &Persistence, out: &Path, barcode: bool) -> Result<()> {
    if barcode {
        write_picture(out, || plot::barcode_svg(&p.diagram, 600), || plot::barcode_raster(&p.diagram, 600))
    } else {
        write_picture(out, || plot::diagram_svg(&p.diagram, 500), || plot::diagram_raster(&p.diagram, 500))
    }
}

/// Writes the 2-D image with the cycle of pair `k` drawn over it, SVG or PNG by the
/// extension of `out`.
pub fn plot_cycle_file(p: &Persistence, k: usize, out: &Path) -> Result<()> {
    let (rows, cols, values) =
        p.image.as_ref().ok_or_else(|| Error::new(ErrorKind::Usage, "cycles are drawn over 2-D images only"))?;
    let chain = p.diagram.cycles.get(k).ok_or_else(|| {
        Error::new(
            ErrorKind::Usage,
            format!("no cycle for pair {k} ({} pairs; cycles asked for?)", p.diagram.pairs.len()),
        )
    })?;
    let scale = (800 / (*rows).max(*cols)).clamp(1, 20) as u32;
    write_picture(
        out,
        || plot::image_with_chain_svg(*rows, *cols, values, chain, p.vertex_centred, scale),
        || plot::image_with_chain_raster(*rows, *cols, values, chain, p.vertex_centred, scale),
    )
}
