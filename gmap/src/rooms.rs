//! Rooms from walls (`gmap rooms`): the 3-cells of faces given in space — an `.off` polygon
//! soup or a `.json` 2-complex with points — found by LAR's extraction of minimal 2-cycles
//! (`gmap_homology::lar::Faces`), written as a 3-complex whose 3-regions are the rooms (the
//! outer cell left out), in any format `gmap convert` writes an architectural complex to.
//! From a `.json`, the faces keep their ids and labels.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::Path;

use gmap_homology::arch::{ArchComplex, RegionId};
use gmap_homology::lar::{Cells, Faces};

use crate::error::{err, Error, ErrorKind, Result};
use crate::input::{extension, Input};

/// The rooms found in a file's faces.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Rooms {
    /// the 3-complex: vertices, edges, faces and rooms
    pub complex: ArchComplex,
    /// the numbers of vertices, edges and faces
    pub counts: [usize; 3],
    /// each room's name, its number of faces, its volume and the rooms it shares a face with
    pub rooms: Vec<(String, usize, f64, Vec<String>)>,
}

impl Rooms {
    /// The report: counts, then one line per room.
    pub fn to_text(&self) -> String {
        let [v, e, f] = self.counts;
        let mut s = format!("faces {f}, edges {e}, vertices {v}\n");
        let n = self.rooms.len();
        let _ = writeln!(s, "3-cells {}: {n} {} and the outer cell", n + 1, if n == 1 { "room" } else { "rooms" });
        for (name, faces, volume, next) in &self.rooms {
            let next = if next.is_empty() { "no other room".to_string() } else { next.join(", ") };
            let _ = writeln!(s, "{name}: {faces} faces, volume {volume}; next to {next}");
        }
        s
    }
}

/// The faces of a `.json` 2-complex with points: each 2-region's edges chained into loops.
fn json_faces(x: &ArchComplex, file: &str) -> Result<(Faces, Vec<usize>)> {
    let bad = |m: String| err!(Precondition, "{file}: {m}");
    let mut vertex = vec![u32::MAX; x.regions().len()];
    let mut points = Vec::new();
    for &v in x.regions_of_dim(0) {
        let p = x
            .region_point(v as usize)
            .ok_or_else(|| bad(format!("vertex {} has no point", x.region_name(v as usize))))?;
        vertex[v as usize] = points.len() as u32;
        points.push(p);
    }
    let mut faces = Vec::new();
    let mut regions = Vec::new();
    for &f in x.regions_of_dim(2) {
        let f = f as usize;
        // the oriented edges of the face, as (from, to) vertices
        let mut arcs: Vec<(u32, u32)> = Vec::new();
        for e in x.down(f) {
            let ends: Vec<(usize, i64)> = x.down(e.to).iter().map(|d| (d.to, d.weight)).collect();
            let (Some(a), Some(b)) = (ends.iter().find(|d| d.1 < 0), ends.iter().find(|d| d.1 > 0)) else {
                return Err(bad(format!("edge {} of face {} has not two ends", x.region_name(e.to), x.region_name(f))));
            };
            let (a, b) = (vertex[a.0], vertex[b.0]);
            arcs.push(if e.weight > 0 { (a, b) } else { (b, a) });
        }
        let mut loops = Vec::new();
        while let Some((a, b)) = arcs.pop() {
            let mut lp = vec![a];
            let mut at = b;
            while at != a {
                let k = arcs
                    .iter()
                    .position(|&(u, _)| u == at)
                    .ok_or_else(|| bad(format!("the edges of face {} do not close into loops", x.region_name(f))))?;
                lp.push(at);
                at = arcs.swap_remove(k).1;
            }
            loops.push(lp);
        }
        faces.push(loops);
        regions.push(f);
    }
    let faces = Faces::try_new(points, faces).map_err(|e| rooms_error(&e, file, Some((x, &regions))))?;
    Ok((faces, regions))
}

fn rooms_error(e: &gmap_homology::lar::RoomsError, file: &str, names: Option<(&ArchComplex, &[usize])>) -> Error {
    let mut text = e.to_string();
    if let (
        Some((x, regions)),
        gmap_homology::lar::RoomsError::BothSides { face } | gmap_homology::lar::RoomsError::Flat { face },
    ) = (names, e)
    {
        text = text.replacen(&format!("face {face}"), &format!("face {}", x.region_name(regions[*face])), 1);
    }
    Error::new(ErrorKind::Precondition, text).context(format!("{file}: rooms from walls"))
}

/// The rooms of the faces in the file at `path` (`.off` or `.json`; module docs).
pub fn rooms_of(path: &Path) -> Result<Rooms> {
    let file = path.display().to_string();
    let (faces, source) = match extension(path).as_str() {
        "off" => {
            let text =
                std::fs::read_to_string(path).map_err(|e| err!(Parse, "{file}: cannot read: {e}").with_path(path))?;
            let mesh = gmap_ops::import::PolygonMesh::parse(&text)
                .map_err(|e| Error::from_source(ErrorKind::Parse, e).context(file.clone()).with_path(path))?;
            let polys = mesh.polygons.into_iter().map(|p| vec![p]).collect();
            (Faces::try_new(mesh.points, polys).map_err(|e| rooms_error(&e, &file, None))?, None)
        }
        _ => match crate::open(path)? {
            Input::Arch(x) => {
                let (faces, regions) = json_faces(&x, &file)?;
                (faces, Some((x, regions)))
            }
            other => {
                return Err(err!(
                Unsupported,
                "{file}: rooms are found in faces with points, an .off polygon soup or a .json 2-complex, not in a {}",
                other.kind()
            ))
            }
        },
    };
    let names = source.as_ref().map(|(x, r)| (&**x, r.as_slice()));
    let cells = faces.cells().map_err(|e| rooms_error(&e, &file, names))?;
    let mut complex = cells.to_arch(&faces).map_err(|e| Error::from_source(ErrorKind::Compute, e))?;
    let counts = [faces.points().len(), faces.edges().len(), faces.len()];
    // the faces of a .json keep their ids and labels
    if let Some((x, regions)) = &source {
        for (f, &r) in regions.iter().enumerate() {
            let id = RegionId((counts[0] + counts[1] + f) as u64);
            let key = x.region_key(r).map_or_else(|| x.region(r).id.to_string(), str::to_string);
            complex = complex
                .with_region_key(id, key)
                .and_then(|c| c.with_region_labels(id, x.region_labels(r).clone()))
                .map_err(|e| Error::from_source(ErrorKind::Compute, e))?;
        }
    }
    if let Some((x, regions)) = &source {
        complex =
            keep_names(complex, x, regions, &cells, counts).map_err(|e| Error::from_source(ErrorKind::Compute, e))?;
    }
    let rooms = describe(&cells, &complex, counts);
    Ok(Rooms { complex, counts, rooms })
}

/// The rooms found keep the id and labels of the input's 3-region with the same faces, and
/// the vertices the ids of the input's vertices (`regions`: the input region of each face).
fn keep_names(
    mut complex: ArchComplex,
    x: &ArchComplex,
    regions: &[usize],
    cells: &Cells,
    [nv, ne, nf]: [usize; 3],
) -> std::result::Result<ArchComplex, gmap_homology::arch::ArchError> {
    for (i, &v) in x.regions_of_dim(0).iter().enumerate() {
        if let Some(key) = x.region_key(v as usize) {
            complex = complex.with_region_key(RegionId(i as u64), key.to_string())?;
        }
    }
    let given: Vec<(BTreeSet<usize>, usize)> =
        x.regions_of_dim(3).iter().map(|&q| (x.down(q as usize).iter().map(|e| e.to).collect(), q as usize)).collect();
    for (r, room) in cells.rooms().enumerate() {
        let faces: BTreeSet<usize> = room.iter().map(|&(f, _)| regions[f]).collect();
        let Some(&(_, q)) = given.iter().find(|g| g.0 == faces) else { continue };
        let id = RegionId((nv + ne + nf + r) as u64);
        let key = x.region_key(q).map_or_else(|| x.region(q).id.to_string(), str::to_string);
        complex = complex.with_region_key(id, key)?.with_region_labels(id, x.region_labels(q).clone())?;
    }
    Ok(complex)
}

fn describe(cells: &Cells, x: &ArchComplex, [nv, ne, nf]: [usize; 3]) -> Vec<(String, usize, f64, Vec<String>)> {
    let rooms: Vec<&[(usize, i64)]> = cells.rooms().collect();
    let volumes: Vec<f64> =
        (0..cells.cells.len()).filter(|&k| k != cells.outer).map(|k| cells.volumes6[k] / 6.0).collect();
    let name = |r: usize| x.region_name(nv + ne + nf + r);
    (0..rooms.len())
        .map(|r| {
            let mine: BTreeSet<usize> = rooms[r].iter().map(|&(f, _)| f).collect();
            let next: Vec<String> = (0..rooms.len())
                .filter(|&q| q != r && rooms[q].iter().any(|(f, _)| mine.contains(f)))
                .map(name)
                .collect();
            (name(r), rooms[r].len(), volumes[r], next)
        })
        .collect()
}

/// [`rooms_of`] `input`, written to `output` (`.json`, `.dot`, or a map format through the
/// flag construction, as `gmap convert` writes an architectural complex).
pub fn rooms_file(input: impl AsRef<Path>, output: impl AsRef<Path>, max_darts: Option<u64>) -> Result<Rooms> {
    let rooms = rooms_of(input.as_ref())?;
    crate::save::save_arch(&rooms.complex, output.as_ref(), max_darts)?;
    Ok(rooms)
}
