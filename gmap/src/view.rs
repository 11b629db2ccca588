//! One self-contained HTML page to look at an input in a browser: [`view`] builds the
//! scene of any [`Input`] (`gmap_ops::export::html`) and, on request, draws its homology
//! generators in it.
//!
//! * a map: its darts, its points (or a layout of its 1-skeleton) and, for a `.gmap` file,
//!   the labels of its cells;
//! * a simplicial complex (`.facets`, `.lex`): its G-map, laid out the same way; one that
//!   has no G-map (not a pseudo-manifold) by its faces, its vertices laid out from its
//!   1-skeleton;
//! * a cubical set: its cubes at their lattice coordinates;
//! * an architectural complex (`.json`): its regions as points, laid out from the incidence
//!   graph (regions as nodes, entries as links), with their labels.
//!
//! Generators are those of [`crate::homology`] with the cellular method, named in the
//! input's terms ([`CellName`]) and placed in the scene: a dart's cell, a cube, a region.

use gmap_core::DenseMap;
use gmap_ops::export::html::{self, layout, HtmlOptions, Scene, Shape, ViewGenerator};

use crate::error::{err, Result};
use crate::input::{Input, MapInput};
use crate::options::HomologyOptions;
use crate::report::{CellName, NamedGenerator};

/// Options of [`view`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ViewOptions {
    /// compute the homology generators and draw them (the page's homology view)
    pub generators: bool,
    /// the label that colours the cells view (default: the first text label of the highest
    /// dimension with labels)
    pub color_by: Option<String>,
    /// above this many darts the darts view is thinned (default
    /// [`html::DEFAULT_DART_LIMIT`])
    pub dart_limit: Option<usize>,
    /// the page's title (default: the file name)
    pub title: Option<String>,
}

/// The page of an input: one HTML document, nothing fetched when it is viewed (see
/// `gmap_ops::export::html`). Errors: the homology's, with `generators` (a map whose cells
/// fail C1/C2 has no cellular generators), and a `color_by` that names no label
/// ([`crate::ErrorKind::Usage`]).
///
/// ```
/// let input = gmap::open(concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/lutz/poincare.facets"))?;
/// let mut o = gmap::ViewOptions::default();
/// o.generators = true;
/// let page = gmap::view(&input, &o)?;
/// assert!(page.starts_with("<!DOCTYPE html>") && page.contains("H3 #0 (Z)"));
/// # Ok::<(), gmap::Error>(())
/// ```
pub fn view(input: &Input, o: &ViewOptions) -> Result<String> {
    let scene = scene(input, o)?;
    let opts = HtmlOptions {
        color_by: o.color_by.clone(),
        dart_limit: o.dart_limit.unwrap_or(html::DEFAULT_DART_LIMIT),
        view: None,
    };
    html::html_string(&scene, &opts).map_err(|e| match e {
        e @ gmap_ops::export::ExportError::UnknownLabel { .. } => err!(Usage, "{e}"),
        e => e.into(),
    })
}

/// The scene of an input with its generators (see [`view`]).
pub fn scene(input: &Input, o: &ViewOptions) -> Result<Scene> {
    let title = o.title.clone().unwrap_or_else(|| {
        input.path().file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_else(|| input.kind().to_string())
    });
    match input {
        Input::Image(img) => {
            // an image is drawn as its cubical set (the cubes present at the default level)
            let set = img
                .to_cubical_set(gmap_ops::import::Level::Nonzero)
                .map_err(|e| crate::Error::from(gmap_ops::import::FileError::new(img.path(), e)))?;
            let o = ViewOptions { title: Some(title), ..o.clone() };
            scene(&Input::Cubical(crate::Sourced::new(set)), &o)
        }
        // a complex with no G-map (not a pseudo-manifold) is drawn by its faces
        Input::Simplicial(sc) if sc.to_gmap().is_err() => face_scene(input, sc, &title, o),
        Input::Map(_) | Input::Simplicial(_) => map_scene(input, &title, o),
        Input::Cubical(set) => cube_scene(input, set, &title, o),
        Input::Arch(x) => arch_scene(input, x, &title, o),
    }
}

/// The generators of `input` by the cellular method, named in its terms.
fn generators_of(input: &Input) -> Result<Vec<NamedGenerator>> {
    let h = HomologyOptions { generators: true, ..Default::default() };
    Ok(crate::homology(input, &h)?.generators.unwrap_or_default())
}

/// The scene of a map (or of a simplicial complex's G-map): its darts, and the labels of a
/// labelled file's cells.
fn map_scene(input: &Input, title: &str, o: &ViewOptions) -> Result<Scene> {
    // the labels number the cells of the labelled file's own map: that map is drawn
    let labelled = match input {
        Input::Map(m) => m.dense_labels().transpose()?,
        _ => None,
    };
    let (map, labels) = match labelled {
        Some((m, l)) => (m, Some(l)),
        None => (input.to_map()?.into_owned(), None),
    };
    let mut scene = Scene::from_map(&map, labels.as_ref(), title);
    if o.generators {
        // the generators of the drawn map itself, so that their darts are its darts
        let gens = generators_of(&Input::Map(MapInput::new(map.clone())))?;
        add_map_generators(&mut scene, &map, &gens)?;
    }
    Ok(scene)
}

/// The scene of a cubical set: its cubes at their lattice coordinates.
fn cube_scene(input: &Input, set: &gmap_ops::import::CubicalSet, title: &str, o: &ViewOptions) -> Result<Scene> {
    set.require_full("the page, which draws cubes,")
        .map_err(|e| err!(Unsupported, "{}: {e}", input.path().display()).with_path(input.path()))?;
    let mut scene = Scene::from_cubical(set, title);
    if o.generators {
        let gens = generators_of(input)?;
        for (g, name) in gens.iter().zip(generator_names(&gens)) {
            let mut cells = Vec::with_capacity(g.chain.len());
            for (c, _) in g.chain.iter() {
                if let CellName::Cube { min, extent } = c {
                    cells.push(scene.add_cube(&min, &extent)?);
                }
            }
            scene.add_generator(ViewGenerator { name, dim: g.dim, cells })?;
        }
    }
    Ok(scene)
}

/// The scene of an architectural complex: its regions as points, laid out from the
/// incidence graph (regions as nodes, entries as links), with their labels.
fn arch_scene(input: &Input, x: &gmap_homology::arch::ArchComplex, title: &str, o: &ViewOptions) -> Result<Scene> {
    let n = x.regions().len();
    let links: Vec<(u32, u32)> = x.entries().iter().map(|e| (e.from as u32, e.to as u32)).collect();
    let placement = format!("a layout of the incidence graph (regions as nodes, entries as links): {}", layout::METHOD);
    let mut scene = Scene::complex(title, x.dim(), &placement);
    let pos = layout::graph_layout(n, &links);
    let point: Vec<u32> = pos.iter().map(|&p| scene.add_point(p)).collect();
    // cells by dimension, in the order of `regions_of_dim`, so that a region's cell number
    // is its rank in its dimension
    for k in 0..=x.dim() {
        for &r in x.regions_of_dim(k) {
            let c = scene.add_cell(k, Shape::Point(point[r as usize]), true)?;
            let labels = x.region_labels(r as usize);
            if !labels.is_empty() {
                scene.set_labels(k, c, labels.clone())?;
            }
        }
    }
    for &(a, b) in &links {
        scene.add_link(point[a as usize], point[b as usize])?;
    }
    scene.add_note("An architectural complex: each region is a point, each entry of its boundary matrix a grey line.");
    if o.generators {
        let gens = generators_of(input)?;
        for (g, name) in gens.iter().zip(generator_names(&gens)) {
            let mut cells = Vec::with_capacity(g.chain.len());
            for (c, _) in g.chain.iter() {
                if let CellName::Region(id) | CellName::NamedRegion { id, .. } = c {
                    let r = x.index_of(id.into()).ok_or_else(|| err!(Compute, "generator region {id} is unknown"))?;
                    cells.push(x.rank_in_dim(r) as u32);
                }
            }
            scene.add_generator(ViewGenerator { name, dim: g.dim, cells })?;
        }
    }
    Ok(scene)
}

/// The scene of any simplicial complex, by its faces: its vertices laid out from its
/// 1-skeleton, every face a cell (an edge a segment, a triangle a polygon, a higher simplex
/// its triangles), numbered as the direct route numbers them, so that its generators are
/// drawn on them.
fn face_scene(input: &Input, sc: &gmap_ops::import::SimplicialComplex, title: &str, o: &ViewOptions) -> Result<Scene> {
    let file = input.path().display().to_string();
    let fc = crate::face_complex_within(sc, None, &file, true)?;
    let face = |k: usize, j: usize| &fc.faces[k][j * (k + 1)..(j + 1) * (k + 1)];
    let n = fc.faces.first().map_or(0, |v| v.len());
    let edges: Vec<(u32, u32)> =
        (0..fc.faces.get(1).map_or(0, |f| f.len() / 2)).map(|j| (face(1, j)[0], face(1, j)[1])).collect();
    let placement = format!("a layout of the 1-skeleton (vertices as nodes, edges as links): {}", layout::METHOD);
    let mut scene = Scene::complex(title, sc.dim(), &placement);
    let point: Vec<u32> = layout::graph_layout(n, &edges).into_iter().map(|p| scene.add_point(p)).collect();
    let mut number: Vec<std::collections::HashMap<Vec<u64>, u32>> = Vec::new();
    for k in 0..fc.faces.len() {
        let mut of_dim = std::collections::HashMap::new();
        for j in 0..fc.faces[k].len() / (k + 1) {
            let v: Vec<u32> = face(k, j).iter().map(|&i| point[i as usize]).collect();
            let shape = match k {
                0 => Shape::Point(v[0]),
                1 => Shape::Segment(v[0], v[1]),
                _ => Shape::Polygons(triangles(&v)),
            };
            let c = scene.add_cell(k, shape, true)?;
            of_dim.insert(face(k, j).iter().map(|&i| fc.vertices[i as usize]).collect(), c);
        }
        number.push(of_dim);
    }
    scene.add_note("A simplicial complex that is not a pseudo-manifold (it has no G-map): drawn by its faces.");
    if o.generators {
        let gens = generators_of(input)?;
        for (g, name) in gens.iter().zip(generator_names(&gens)) {
            let mut cells = Vec::with_capacity(g.chain.len());
            for (c, _) in g.chain.iter() {
                let found = match &c {
                    CellName::Simplex(v) => number.get(g.dim).and_then(|m| m.get(v)),
                    _ => None,
                };
                cells.push(*found.ok_or_else(|| err!(Compute, "a generator names {}, not a face", c.to_text()))?);
            }
            scene.add_generator(ViewGenerator { name, dim: g.dim, cells })?;
        }
    }
    Ok(scene)
}

/// The triangles of a simplex of 3 or more points (the simplex itself for a triangle).
fn triangles(v: &[u32]) -> Vec<Vec<u32>> {
    let mut out = Vec::new();
    for a in 0..v.len() {
        for b in a + 1..v.len() {
            for c in b + 1..v.len() {
                out.push(vec![v[a], v[b], v[c]]);
            }
        }
    }
    out
}

/// The names shown in the page's list: `H1 #0 (Z)`, the summand's dimension, its rank
/// among the generators of that dimension, its order.
fn generator_names(gens: &[NamedGenerator]) -> Vec<String> {
    let mut per_dim = std::collections::HashMap::new();
    gens.iter()
        .map(|g| {
            let k = per_dim.entry(g.dim).or_insert(0usize);
            *k += 1;
            let order = if g.order.to_u64() == Some(0) { "Z".to_string() } else { format!("Z/{}", g.order) };
            format!("H{} #{} ({order})", g.dim, *k - 1)
        })
        .collect()
}

/// Adds the generators of a map, named by darts, as cells of the map.
fn add_map_generators(scene: &mut Scene, map: &DenseMap, gens: &[NamedGenerator]) -> Result<()> {
    for (g, name) in gens.iter().zip(generator_names(gens)) {
        let cells_of = map.cells(g.dim);
        let mut cells = Vec::with_capacity(g.chain.len());
        for (c, _) in g.chain.iter() {
            match c {
                CellName::Dart { dart, simplex: None, .. } if (dart as usize) < map.dart_count() => {
                    cells.push(cells_of.of[dart as usize]);
                }
                other => return Err(err!(Compute, "a generator names {}, not a cell of the map", other.to_text())),
            }
        }
        scene.add_generator(ViewGenerator { name, dim: g.dim, cells })?;
    }
    Ok(())
}
