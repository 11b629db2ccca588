//! Homotopy tests of paths on a surface (CGAL's `Curves_on_surface_topology` tests), by
//! [`gmap_homology::curves::homotopy`]: [`Paths`] preprocesses a 2-map once, then answers
//! `is_contractible`, `are_freely_homotopic`, `are_homotopic_with_fixed_endpoints` and
//! `is_homotopic_to_simple_cycle` for paths given as darts or as vertices.
//!
//! A path by darts gives, for each step, a dart of its edge at the vertex it leaves
//! (CGAL's paths of darts); by vertices, the vertices passed, numbered as the map numbers
//! its vertices (by their smallest darts, in increasing order), each step along the one
//! edge joining them. A sequence that is not a path is refused naming its step.
//!
//! ```
//! use gmap::homotopy::{PathSpec, Paths};
//! let torus = gmap::ops::build::grid(&[4, 3], &[true, true]).unwrap();
//! let input = gmap::Input::Map(gmap::MapInput::new(torus));
//! let paths = Paths::new(&input).unwrap();
//! // the shortest loop round the torus is not contractible and is a simple cycle; run
//! // twice, it is not simple
//! let c = gmap::curves::edge_width(&input).unwrap().unwrap();
//! let once = PathSpec::Darts(c.darts.clone());
//! assert!(!paths.is_contractible(&once).unwrap());
//! assert!(paths.is_homotopic_to_simple_cycle(&once).unwrap());
//! let twice = PathSpec::Darts([c.darts.clone(), c.darts].concat());
//! assert!(!paths.is_homotopic_to_simple_cycle(&twice).unwrap());
//! assert!(!paths.are_freely_homotopic(&once, &twice).unwrap());
//! ```

use gmap_core::{Dart, DenseMap};
use gmap_homology::curves::homotopy::{Homotopy, SurfaceKind, SurfacePath};
use gmap_homology::curves::CurveError;

use crate::error::Result;
use crate::input::Input;

/// A path as the user gives it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PathSpec {
    /// for each step, a dart of its edge at the vertex it leaves
    Darts(Vec<u64>),
    /// the vertices passed (vertex numbers), consecutive ones joined by exactly one edge
    Vertices(Vec<u64>),
}

/// A 2-map preprocessed for homotopy tests.
#[derive(Clone, Debug)]
pub struct Paths {
    map: DenseMap,
    h: Homotopy,
}

impl Paths {
    /// The preprocessing of the surface of `input` (a 2-map, or the G-map of a simplicial
    /// complex): a connected surface, closed or with boundary, orientable or not. O(N).
    pub fn new(input: &Input) -> Result<Self> {
        let map = input.to_map()?.into_owned();
        let h = Homotopy::new(&map)?;
        Ok(Paths { map, h })
    }

    /// What the surface is (orientable, boundary, Euler characteristic).
    pub fn kind(&self) -> SurfaceKind {
        self.h.kind()
    }

    /// The dart sequence of the path through `vertices` (see [`PathSpec::Vertices`]).
    pub fn vertices_path(&self, vertices: &[u64]) -> Result<Vec<u64>> {
        Ok(self.path(&PathSpec::Vertices(vertices.to_vec()))?.darts.iter().map(|d| u64::from(d.get())).collect())
    }

    fn path(&self, p: &PathSpec) -> Result<SurfacePath> {
        let small = |x: u64, step: usize| {
            u32::try_from(x).map_err(|_| CurveError::NotAPath {
                step,
                dart: u32::MAX,
                reason: "is not a dart of the map",
            })
        };
        Ok(match p {
            PathSpec::Darts(d) => {
                let darts = d
                    .iter()
                    .enumerate()
                    .map(|(k, &x)| small(x, k).map(Dart::new))
                    .collect::<std::result::Result<Vec<_>, _>>()?;
                self.h.path(&darts)?
            }
            PathSpec::Vertices(v) => {
                let nv = self.map.cell_count(0);
                let vs = v
                    .iter()
                    .map(|&x| u32::try_from(x).map_err(|_| CurveError::NoSuchVertex { vertex: u32::MAX, vertices: nv }))
                    .collect::<std::result::Result<Vec<_>, _>>()?;
                self.h.path_through_vertices(&self.map, &vs)?
            }
        })
    }

    /// Whether the closed path `p` is contractible.
    pub fn is_contractible(&self, p: &PathSpec) -> Result<bool> {
        Ok(self.h.is_contractible(&self.path(p)?)?)
    }

    /// Whether the closed paths `p` and `q` are freely homotopic (refused, with the reason,
    /// where this implementation cannot decide: see docs/CURVES.md).
    pub fn are_freely_homotopic(&self, p: &PathSpec, q: &PathSpec) -> Result<bool> {
        Ok(self.h.are_freely_homotopic(&self.path(p)?, &self.path(q)?)?)
    }

    /// Whether `p` and `q` (the same ends) are homotopic with their ends fixed.
    pub fn are_homotopic_with_fixed_endpoints(&self, p: &PathSpec, q: &PathSpec) -> Result<bool> {
        Ok(self.h.are_homotopic_with_fixed_endpoints(&self.path(p)?, &self.path(q)?)?)
    }

    /// Whether the closed path `p` is homotopic to a simple closed curve (refused where
    /// this implementation cannot decide).
    pub fn is_homotopic_to_simple_cycle(&self, p: &PathSpec) -> Result<bool> {
        Ok(self.h.is_homotopic_to_simple_cycle(&self.path(p)?)?)
    }
}
