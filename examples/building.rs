//! A small building as a labelled 3-map with coordinates: two storeys of four rooms each, the
//! rooms as volumes named by a `name` label, the faces labelled with what they are (`kind`:
//! a wall, a door, the floor between storeys, the stair opening, the slab, the roof) and
//! their `material`. Prints the counts and the homology of the map and of its incidence
//! graph, and writes `building.gmap`, `building.json`, `building.dot` and `building.vtk`
//! (open it in ParaView and colour by `name`, `kind` or `dim`) to a folder.
//!
//! `cargo run --release --example building [FOLDER]` (default: `gmap-building` in the
//! system's temporary folder).
//!
//! The cells come from [`gmap::ops::build::grid`], the 2 × 2 × 2 grid of cubes. Its points
//! are derived from its darts alone: a dart of a cubical grid is a flag (vertex, edge, face,
//! volume), described by its vertex, the order in which its edge, face and volume add the
//! three axes, and the side of the vertex each of them lies on; each involution changes
//! that description in one known way (see [`Flag::step`]), so a walk over the darts from
//! one chosen flag places every vertex.

use std::error::Error;
use std::io::Write;
use std::path::{Path, PathBuf};

use gmap::algebra::arch::ArchComplex;
use gmap::algebra::{dot, gmap_homology, json};
use gmap::core::{to_dense_labels, Dart, DenseMap, LabelValue, LabelledGMap, Labels};
use gmap::ops::{build, export};

/// The x, y and z positions (metres) of the grid lines: two rooms of 4 m by 3.5 m along
/// each horizontal axis, two storeys of 3 m.
const LINES: [[f64; 3]; 3] = [[0.0, 4.0, 8.0], [0.0, 3.5, 7.0], [0.0, 3.0, 6.0]];

/// The room at grid position `[x][y]` on each storey.
const ROOMS: [[[&str; 2]; 2]; 2] =
    [[["hall", "living"], ["kitchen", "study"]], [["landing", "bedroom"], ["bathroom", "office"]]];

/// The pairs of rooms on one storey joined by a door; the other pairs share a wall.
const DOORS: [(&str, &str); 6] = [
    ("hall", "kitchen"),
    ("hall", "living"),
    ("living", "study"),
    ("landing", "bathroom"),
    ("landing", "bedroom"),
    ("bedroom", "office"),
];

/// A dart of the cubical grid as a flag: its vertex (grid coordinates), the axes of its
/// edge, face and volume in the order they are added, and on which side of the vertex each
/// axis is taken (+1 or -1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Flag {
    vertex: [i64; 3],
    axes: [usize; 3],
    side: [i64; 3],
}

impl Flag {
    /// The flag reached by `alpha_i`: `alpha_0` moves the vertex to the other end of the
    /// edge, `alpha_1` and `alpha_2` exchange two consecutive axes (another edge of the
    /// face, another face of the volume), `alpha_3` takes the volume on the other side of
    /// the face.
    fn step(self, i: usize) -> Flag {
        let mut f = self;
        match i {
            0 => {
                let a = f.axes[0];
                f.vertex[a] += f.side[a];
                f.side[a] = -f.side[a];
            }
            1 | 2 => f.axes.swap(i - 1, i),
            _ => {
                let a = f.axes[2];
                f.side[a] = -f.side[a];
            }
        }
        f
    }
}

/// The flag of every dart of a 3-map built as a cubical grid, from dart 0 taken as
/// `(origin, axes x y z, all sides +1)`; the vertices are then shifted to start at 0.
/// Fails when two walks give a dart different flags (the map is not a cubical grid).
fn flags(m: &DenseMap) -> Result<Vec<Flag>, String> {
    let mut flag: Vec<Option<Flag>> = vec![None; m.dart_count()];
    flag[0] = Some(Flag { vertex: [0; 3], axes: [0, 1, 2], side: [1; 3] });
    let mut stack = vec![Dart::new(0)];
    while let Some(d) = stack.pop() {
        let f = flag[d.index()].ok_or("a dart on the stack has a flag")?;
        for i in 0..=3 {
            let e = m.alpha(d, i);
            if e == d {
                continue; // a free dart: the boundary of the building
            }
            let g = f.step(i);
            match flag[e.index()] {
                None => {
                    flag[e.index()] = Some(g);
                    stack.push(e);
                }
                Some(h) if h.vertex != g.vertex => {
                    return Err(format!("dart {} is placed at {:?} and at {:?}", e.get(), h.vertex, g.vertex))
                }
                Some(_) => {}
            }
        }
    }
    let flags: Vec<Flag> = flag.into_iter().collect::<Option<_>>().ok_or("the grid is not connected")?;
    let low = lowest(flags.iter().map(|f| f.vertex));
    Ok(flags.into_iter().map(|f| Flag { vertex: [0, 1, 2].map(|a| f.vertex[a] - low[a]), ..f }).collect())
}

/// The lowest corner of the box around grid positions.
fn lowest(positions: impl IntoIterator<Item = [i64; 3]>) -> [i64; 3] {
    positions.into_iter().fold([i64::MAX; 3], |low, p| [0, 1, 2].map(|a| low[a].min(p[a])))
}

fn text(s: &str) -> LabelValue {
    LabelValue::Text(s.to_string())
}

/// The name of the room whose lowest corner is at grid position `c`.
fn room(c: [i64; 3]) -> &'static str {
    ROOMS[c[2] as usize][c[0] as usize][c[1] as usize]
}

/// The labels of a face of the grid, from the grid positions of its four corners: a face
/// normal to `z` is the slab, the roof, or the floor between two rooms one above the other
/// (the stair opening above the hall); a face normal to `x` or `y` is an outer wall, or
/// lies between two rooms of a storey (a door or an inner wall). A face between two rooms
/// names them (`between`).
fn face_labels(corners: &[[i64; 3]]) -> Result<Labels, String> {
    let normal = (0..3)
        .find(|&a| corners.iter().all(|c| c[a] == corners[0][a]))
        .ok_or_else(|| format!("the face {corners:?} is not normal to an axis"))?;
    let at = corners[0][normal];
    let low = lowest(corners.iter().copied());
    let (kind, material, between) = if normal == 2 {
        match at {
            0 => ("slab", "concrete", None),
            2 => ("roof", "tiles", None),
            _ => {
                let (below, above) = (room([low[0], low[1], 0]), room([low[0], low[1], 1]));
                if below == "hall" {
                    ("stair", "oak", Some((below, above)))
                } else {
                    ("floor", "timber", Some((below, above)))
                }
            }
        }
    } else if at == 0 || at == 2 {
        ("wall", "brick", None)
    } else {
        let mut a = low;
        let mut b = low;
        a[normal] = 0;
        b[normal] = 1;
        let (ra, rb) = (room(a), room(b));
        if DOORS.iter().any(|&(p, q)| (p, q) == (ra, rb) || (q, p) == (ra, rb)) {
            ("door", "oak", Some((ra, rb)))
        } else {
            ("wall", "plaster", Some((ra, rb)))
        }
    };
    let mut l = Labels::new();
    l.set("kind", text(kind));
    l.set("material", text(material));
    if let Some((p, q)) = between {
        l.set("between", text(&format!("{p}/{q}")));
    }
    Ok(l)
}

/// Builds the labelled building: the grid, a point per vertex, a name, storey and floor
/// area per room, a kind and material per face.
pub fn building() -> Result<LabelledGMap, Box<dyn Error>> {
    let mut m = build::grid(&[2, 2, 2], &[false; 3])?;
    let flags = flags(&m)?;
    if flags.iter().any(|f| f.vertex.iter().any(|&v| !(0..=2).contains(&v))) {
        return Err("the grid is not 2 × 2 × 2".into());
    }
    for (k, f) in flags.iter().enumerate() {
        let p = [0, 1, 2].map(|a| LINES[a][f.vertex[a] as usize]);
        m.set_point(Dart::new(k as u32), Some(p));
    }
    let (mut g, ids) = LabelledGMap::from_dense_with_attributes(&m);
    let volumes = m.cells(3);
    for &r in &volumes.reps {
        let cell = (0..m.dart_count()).filter(|&k| volumes.of[k] == volumes.of[r.index()]);
        let low = lowest(cell.map(|k| flags[k].vertex));
        let (x, y, z) = (low[0] as usize, low[1] as usize, low[2] as usize);
        let area = (LINES[0][x + 1] - LINES[0][x]) * (LINES[1][y + 1] - LINES[1][y]);
        let labels: Labels =
            [("name", text(room(low))), ("storey", LabelValue::Int(z as i64)), ("area", LabelValue::Real(area))]
                .into_iter()
                .collect();
        g.try_set_attribute::<3>(ids[r.index()], labels)?;
    }
    let faces = m.cells(2);
    let mut corners: Vec<Vec<[i64; 3]>> = vec![Vec::new(); faces.len()];
    for (k, f) in flags.iter().enumerate() {
        corners[faces.of[k] as usize].push(f.vertex);
    }
    for (c, &r) in faces.reps.iter().enumerate() {
        g.try_set_attribute::<2>(ids[r.index()], face_labels(&corners[c])?)?;
    }
    Ok(g)
}

/// Builds the building, prints its summary to `out` and writes the four files to `dir`.
pub fn run(dir: &Path, out: &mut dyn Write) -> Result<(), Box<dyn Error>> {
    let g = building()?;
    let c = g.characteristics();
    writeln!(out, "{c}")?;
    let h = gmap_homology(&g)?;
    writeln!(out, "homology of the map: {h}")?;
    let x = ArchComplex::from_labelled_map(&g)?;
    let counts: Vec<String> = x.region_counts().iter().map(|n| n.to_string()).collect();
    writeln!(
        out,
        "incidence graph: {} regions ({}), {} entries",
        x.regions().len(),
        counts.join(", "),
        x.entries().len()
    )?;
    writeln!(out, "homology of the incidence graph: {}", x.homology_z()?)?;
    let mut rooms = Vec::new();
    let mut doors = Vec::new();
    for (k, r) in x.regions().iter().enumerate() {
        let l = x.region_labels(k);
        match (r.dim, l.get("name"), l.get("kind"), l.get("between")) {
            (3, Some(LabelValue::Text(n)), _, _) => rooms.push(format!("{n} ({l})")),
            (2, _, Some(LabelValue::Text(kind)), Some(LabelValue::Text(b))) if kind == "door" || kind == "stair" => {
                doors.push(format!("{kind} {b}"))
            }
            _ => {}
        }
    }
    doors.sort();
    writeln!(out, "rooms: {}", rooms.len())?;
    for r in &rooms {
        writeln!(out, "  {r}")?;
    }
    writeln!(out, "openings: {}", doors.join(", "))?;
    std::fs::create_dir_all(dir)?;
    let file = |ext: &str| dir.join(format!("building.{ext}"));
    gmap::core::io::write_labelled_gmap(&g, file("gmap"))?;
    gmap::core::io::write_atomic(&file("json"), json::write_json(&x).as_bytes())?;
    gmap::core::io::write_atomic(&file("dot"), dot::write_dot(&x).as_bytes())?;
    let (m, labels, _) = to_dense_labels(&g);
    export::write_vtk_with_labels(&m, &labels, &file("vtk"))?;
    writeln!(out, "wrote building.gmap, building.json, building.dot, building.vtk")?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir =
        std::env::args_os().nth(1).map(PathBuf::from).unwrap_or_else(|| std::env::temp_dir().join("gmap-building"));
    run(&dir, &mut std::io::stdout().lock())?;
    println!("in {}", dir.display());
    Ok(())
}
