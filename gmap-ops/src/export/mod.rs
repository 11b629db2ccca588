//! Exporters: `.off` polygon meshes (2-maps with points) and `.facets` of the barycentric
//! subdivision (any map). Every writer goes through a temporary file in the target's
//! directory and a rename, so a failure never leaves a partial file behind. The native
//! `.gmap` and Moka formats are written by `gmap_core::io`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use gmap_core::{AlphaSet, Dart, DenseMap};
use thiserror::Error;

/// Why a map could not be exported.
#[derive(Debug, Error)]
pub enum ExportError {
    /// The format holds only maps of one dimension.
    #[error("{format} holds {expected}-maps, this map has dimension {found}")]
    Dimension {
        /// the format
        format: &'static str,
        /// the dimension it needs
        expected: usize,
        /// the map's dimension
        found: usize,
    },
    /// A vertex without a point (`.off` needs coordinates).
    #[error("the vertex of dart {dart} has no point: .off needs coordinates")]
    NoPoint {
        /// a dart of that vertex
        dart: u32,
    },
    /// A face that is not a closed polygon (a 0- or 1-free dart).
    #[error("the face of dart {dart} is not a closed polygon (dart {dart} is {alpha}-free)")]
    OpenFace {
        /// the dart
        dart: u32,
        /// the involution with a fixed point
        alpha: usize,
    },
    /// Writing failed.
    #[error("{path}: {source}")]
    Io {
        /// the file
        path: PathBuf,
        /// the cause
        source: std::io::Error,
    },
}

/// Writes `contents` to `path` with [`gmap_core::io::write_atomic`] (never a partial file).
pub fn write_atomic(path: &Path, contents: &[u8]) -> Result<(), ExportError> {
    gmap_core::io::write_atomic(path, contents).map_err(|source| ExportError::Io { path: path.to_path_buf(), source })
}

/// The OFF text of a 2-map with points: one vertex per 0-cell (numbered by its smallest
/// dart), one polygon per 2-cell listing its corners in cycle order (walking
/// `alpha_0 alpha_1` from the face's smallest dart). Faces must be closed polygons (no 0- or
/// 1-free dart) and every vertex must carry a point. O(N).
pub fn off_string(map: &DenseMap) -> Result<String, ExportError> {
    if map.dim() != 2 {
        return Err(ExportError::Dimension { format: ".off", expected: 2, found: map.dim() });
    }
    for d in map.darts() {
        for i in 0..2 {
            if map.is_free(d, i) {
                return Err(ExportError::OpenFace { dart: d.0, alpha: i });
            }
        }
    }
    let verts = map.cells(0);
    let faces = map.cells(2);
    let mut out = String::new();
    let _ = writeln!(out, "OFF\n{} {} 0", verts.len(), faces.len());
    for &Dart(r) in &verts.reps {
        let p = map.vertex_point(Dart(r)).ok_or(ExportError::NoPoint { dart: r })?;
        let _ = writeln!(out, "{} {} {}", p[0], p[1], p[2]);
    }
    for &Dart(r) in &faces.reps {
        let mut corners = Vec::new();
        let mut d = Dart(r);
        loop {
            corners.push(verts.of[d.index()]);
            d = map.alpha(map.alpha(d, 0), 1);
            if d.0 == r {
                break;
            }
        }
        let _ = write!(out, "{}", corners.len());
        for c in corners {
            let _ = write!(out, " {c}");
        }
        out.push('\n');
    }
    Ok(out)
}

/// Writes a 2-map with points as `.off` (see [`off_string`]).
pub fn write_off(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, off_string(map)?.as_bytes())
}

/// The `.facets` text of the barycentric subdivision: one n-simplex per dart, whose vertices
/// are the dart's 0-cell, 1-cell, …, n-cell, numbered `offset_i + k` for the k-th i-cell
/// (`offset_i` = number of cells of lower dimension), so labels of different dimensions
/// never collide. On a map whose darts are determined by their cells (a regular complex,
/// e.g. anything imported from `.facets`) this is a triangulation of the same space.
/// O(N n).
pub fn barycentric_facets_string(map: &DenseMap) -> String {
    let n = map.dim();
    let parts: Vec<_> = (0..=n).map(|i| map.partition(AlphaSet::cell(i, n))).collect();
    let mut offsets = vec![0u64; n + 1];
    for i in 1..=n {
        offsets[i] = offsets[i - 1] + parts[i - 1].len() as u64;
    }
    let mut out = String::with_capacity(map.dart_count() * (n + 1) * 6);
    let _ = writeln!(
        out,
        "# barycentric subdivision of a {n}-map: one simplex per dart, vertex = (dimension offset) + cell"
    );
    for d in 0..map.dart_count() {
        for i in 0..=n {
            if i > 0 {
                out.push(' ');
            }
            let _ = write!(out, "{}", offsets[i] + parts[i].of[d] as u64);
        }
        out.push('\n');
    }
    out
}

/// Writes the barycentric `.facets` of a map (see [`barycentric_facets_string`]).
pub fn write_barycentric_facets(map: &DenseMap, path: &Path) -> Result<(), ExportError> {
    write_atomic(path, barycentric_facets_string(map).as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build;

    #[test]
    fn off_of_a_square() {
        let sq = build::polygon(4).unwrap();
        let text = off_string(&sq).unwrap();
        assert!(text.starts_with("OFF\n4 1 0\n1 0 0\n"), "{text}");
        assert!(text.ends_with("4 0 1 2 3\n"), "{text}");
        let torus = build::schema("a b A B").unwrap();
        assert!(matches!(off_string(&torus), Err(ExportError::NoPoint { dart: 0 })));
        assert!(matches!(off_string(&build::cube(3).unwrap()), Err(ExportError::Dimension { .. })));
    }

    #[test]
    fn barycentric_of_an_edge() {
        let e = build::simplex(1).unwrap();
        assert_eq!(barycentric_facets_string(&e).lines().skip(1).collect::<Vec<_>>(), vec!["0 2", "1 2"]);
    }

    #[test]
    fn atomic_write_leaves_no_temporary() {
        let dir = std::env::temp_dir().join(format!("gmap-ops-export-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("x.facets");
        write_barycentric_facets(&build::simplex(2).unwrap(), &p).unwrap();
        let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names.len(), 1);
        assert_eq!(std::fs::read_to_string(&p).unwrap().lines().count(), 7);
        assert!(write_atomic(&dir.join("no/such/dir/x"), b"x").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
