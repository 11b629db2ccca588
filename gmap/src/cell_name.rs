//! The name of a cell in the input's own terms: vertex labels, a dart, a region id, a cube.
//! A leaf: the routes make names, the report prints them.

use serde_json::json;
use smallvec::SmallVec;

/// A cell of the input, in the input's own terms.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum CellName {
    /// a simplex of a simplicial complex: its vertex labels, increasing
    Simplex(Vec<u64>),
    /// a G-map cell by one of its darts; for the simplicial counterpart, the dimensions of
    /// the cells of that dart spanning the simplex
    Dart {
        /// the dart
        dart: u32,
        /// the point of the dart's vertex, when the map has points
        point: Option<[f64; 3]>,
        /// the simplex of the counterpart: the dimensions of the dart's cells spanning it
        simplex: Option<Vec<u32>>,
    },
    /// a region of an architectural complex by its id
    Region(u64),
    /// a region of an architectural complex that its file names: its string id (`key`),
    /// its `name` label, or both
    NamedRegion {
        /// the number the region has inside (its id when the file gives a number)
        id: u64,
        /// the string id of the file
        key: Option<String>,
        /// the region's `name` label
        name: Option<String>,
    },
    /// an elementary cube of a cubical set: its minimal vertex and its extent (0 or 1) per
    /// axis (held inline up to dimension 4: the generators of a large image name millions)
    Cube {
        /// the minimal vertex
        min: SmallVec<[i64; 4]>,
        /// 1 along the axes the cube spans, 0 along the others
        extent: SmallVec<[u8; 4]>,
    },
}

impl CellName {
    /// The JSON value of the name (docs/FORMATS.md, generators).
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            CellName::Simplex(v) => json!(v),
            CellName::Dart { dart, point, simplex } => {
                let mut v = json!({ "dart": dart });
                if let Some(s) = simplex {
                    v["simplex"] = json!(s);
                }
                if let Some(p) = point {
                    v["point"] = json!(p);
                }
                v
            }
            CellName::Region(id) => json!({ "region": id }),
            CellName::NamedRegion { id, key, name } => {
                let mut v = match key {
                    Some(k) => json!({ "region": k }),
                    None => json!({ "region": id }),
                };
                if let Some(n) = name {
                    v["name"] = json!(n);
                }
                v
            }
            CellName::Cube { min, extent } => json!({ "cube": min.as_slice(), "extent": extent.as_slice() }),
        }
    }

    /// The text of the name: `[1,2,3]`, `dart 5 at (0, 1, 0)`, `region 7`, `region door`,
    /// `region 12 (kitchen)`, `[0,1]x2`.
    pub fn to_text(&self) -> String {
        let list = |v: &[u64]| v.iter().map(u64::to_string).collect::<Vec<_>>().join(",");
        match self {
            CellName::Simplex(v) => format!("[{}]", list(v)),
            CellName::Dart { dart, point, simplex } => {
                let mut t = format!("dart {dart}");
                if let Some(s) = simplex {
                    let s: Vec<u64> = s.iter().map(|&x| u64::from(x)).collect();
                    t = format!("simplex {{{}}} of {t}", list(&s));
                }
                if let Some([x, y, z]) = point {
                    t.push_str(&format!(" at ({x}, {y}, {z})"));
                }
                t
            }
            CellName::Region(id) => format!("region {id}"),
            CellName::NamedRegion { id, key, name } => {
                let base = key.clone().unwrap_or_else(|| id.to_string());
                match name {
                    Some(n) if *n != base => format!("region {base} ({n})"),
                    _ => format!("region {base}"),
                }
            }
            CellName::Cube { min, extent } => min
                .iter()
                .zip(extent)
                .map(|(&lo, &e)| if e == 1 { format!("[{},{}]", lo, lo + 1) } else { lo.to_string() })
                .collect::<Vec<_>>()
                .join("x"),
        }
    }
}
