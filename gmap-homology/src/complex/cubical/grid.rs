//! # The doubled grid: one set of coordinates for every cubical cell
//!
//! ## What
//!
//! The cells of a box of `L_0 × … × L_{d-1}` unit cubes (or pixels) are named by the points
//! of a **doubled grid**. Along an axis of `L` cubes the coordinates `0, 1, …, 2L` alternate
//! between the `L + 1` vertex positions (even) and the `L` intervals between them (odd): a
//! point is an elementary cube, odd along the axes it spans, and its dimension is its number
//! of odd coordinates. The cube of minimal vertex `x` is the point `2x + 1`. On a
//! **periodic** axis the two ends are one, so the axis has `2L` points and the upper face of
//! its last interval is the point 0.
//!
//! A [`Grid`] numbers its points by strides, axis 0 fastest ([`Order::FirstFastest`], the
//! bitmaps of cubical sets) or the last axis fastest ([`Order::LastFastest`], numpy's C
//! order, the images of persistence), and gives what every route needs of a cell:
//!
//! * its coordinates ([`Grid::coord`], [`Grid::coords`]) and dimension ([`Grid::dim`]);
//! * its faces, the two neighbours along each odd axis ([`Grid::faces_along`]), and its
//!   cofaces, the one or two neighbours along each even axis ([`Grid::cofaces_along`]);
//! * the **boundary formula**, written here once: along the `j`-th odd axis of a cell
//!   (counted from axis 0) the upper face has the sign `(-1)^j` and the lower one `-(-1)^j`
//!   ([`face_sign`], [`Grid::for_each_face`], [`Grid::faces`]). It gives `∂∂ = 0`: two faces
//!   of a face reached in either order carry opposite signs.
//!
//! How many points (and bytes) the grid of a box will have is known before anything is
//! allocated: [`Placement`] says where the input's items sit (cubes and T-construction
//! pixels on the top cells, `2L + 1` points; V-construction pixels on the vertices,
//! `2L - 1`; a periodic axis, `2L`), and [`point_count`] and [`bytes`] multiply out, `None`
//! past `u64` ([`shown`] writes the axes for a message).
//!
//! ## Why
//!
//! The cubical complex of a set, its slab-by-slab and block routes, the generators' sweep,
//! and the persistence of images (its general route and the Morse complex of its lower
//! stars) all walk this grid. With one primitive their cells have one name, so that the
//! cells one route returns are those another takes, and the signs of every boundary agree.
//! A route whose inner loop runs over a fixed number of axes (the 3-D generators, the
//! pixel route of persistence) keeps its specialised loop but takes its strides from here.
//!
//! ## Complexity
//!
//! A grid holds its points and strides per axis, `O(d)`. A coordinate is a division and a
//! remainder, so a cell's dimension, faces and cofaces cost `O(d)`; nothing is allocated per
//! cell ([`Grid::coords`] and [`Grid::faces`] write into a vector the caller gives or
//! returns one for naming). Every method is inlined: the routes' hot loops compile to the
//! stride arithmetic they would write by hand.
//!
//! ```
//! use gmap_homology::cubical::grid::{Grid, Order, Placement};
//! // a box of 2 × 1 squares: 5 × 3 points, axis 0 fastest
//! let g = Grid::of_box(&[2, 1], Placement::Cubes, Order::FirstFastest).unwrap();
//! assert_eq!((g.points(), g.strides(), g.len()), (&[5, 3][..], &[1, 5][..], 15));
//! // the square of minimal vertex (1, 0) is the point (3, 1)
//! let square = g.point(&[3, 1]);
//! assert_eq!(g.dim(square), 2);
//! let mut faces = Vec::new();
//! g.faces(square, &mut faces);
//! // along axis 0 (j = 0): lower −1, upper +1; along axis 1 (j = 1): lower +1, upper −1
//! let at = |c: [usize; 2]| g.point(&c);
//! assert_eq!(faces, vec![(at([2, 1]), -1), (at([4, 1]), 1), (at([3, 0]), 1), (at([3, 2]), -1)]);
//! ```

/// Which axis varies fastest along a grid's point numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Order {
    /// axis 0 fastest (cubical sets: `.cub` and bitmap files)
    FirstFastest,
    /// the last axis fastest (numpy's C order: the images of persistence)
    LastFastest,
}

/// Where the `L` items along an axis of the input sit on the doubled grid, which fixes the
/// axis's number of points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Placement {
    /// item `x` is the top cell `2x + 1` of `2L + 1` points (the cubes of a set; the pixels
    /// of the T-construction)
    Cubes,
    /// item `x` is the vertex `2x` of `2L - 1` points (the pixels of the V-construction)
    Vertices,
    /// item `x` is the top cell `2x + 1` of a periodic axis of `2L` points, whose last
    /// interval's upper face is the point 0
    Periodic,
}

impl Placement {
    /// The points of an axis of `l` items, `None` past `usize` (or for no vertex at all).
    #[inline]
    pub const fn points(self, l: usize) -> Option<usize> {
        let Some(twice) = l.checked_mul(2) else { return None };
        match self {
            Placement::Cubes => twice.checked_add(1),
            Placement::Vertices => twice.checked_sub(1),
            Placement::Periodic => Some(twice),
        }
    }

    /// Whether the axes are periodic.
    #[inline]
    pub const fn periodic(self) -> bool {
        matches!(self, Placement::Periodic)
    }
}

/// The points of the doubled grid of a box of `shape` items placed by `placement`, `None`
/// past `u64`. O(d).
pub fn point_count(shape: &[usize], placement: Placement) -> Option<u64> {
    shape.iter().try_fold(1u64, |v, &l| v.checked_mul(placement.points(l)? as u64))
}

/// The bytes of `per_point` bytes a point of that grid, `None` past `u64`. O(d).
pub fn bytes(shape: &[usize], placement: Placement, per_point: u64) -> Option<u64> {
    point_count(shape, placement)?.checked_mul(per_point)
}

/// The points per axis of that grid as `5 × 3 × 7`, for messages (`?` for an axis past
/// `usize`).
pub fn shown(shape: &[usize], placement: Placement) -> String {
    let axis = |&l: &usize| placement.points(l).map_or_else(|| "?".to_string(), |p| p.to_string());
    shape.iter().map(axis).collect::<Vec<_>>().join(" × ")
}

/// The sign of a cell's face along its `j`-th odd axis (counted from axis 0): `(-1)^j` for
/// the upper face, `-(-1)^j` for the lower one. The one boundary formula of every cubical
/// route.
#[inline(always)]
pub const fn face_sign(j: usize, upper: bool) -> i64 {
    let s = if j.is_multiple_of(2) { 1 } else { -1 };
    if upper {
        s
    } else {
        -s
    }
}

/// The coordinates of point `p` of a grid of `points` per axis numbered in `order`. O(d).
pub fn coordinates(points: &[usize], order: Order, p: usize) -> Vec<usize> {
    let mut c = vec![0; points.len()];
    let mut p = p;
    let mut put = |a: usize| {
        c[a] = p % points[a];
        p /= points[a];
    };
    match order {
        Order::FirstFastest => (0..points.len()).for_each(&mut put),
        Order::LastFastest => (0..points.len()).rev().for_each(&mut put),
    }
    c
}

/// A doubled grid: points per axis, their strides, periodic or not. See the
/// [module docs](self).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Grid {
    n: Vec<usize>,
    stride: Vec<usize>,
    order: Order,
    periodic: bool,
    len: usize,
}

impl Grid {
    /// The grid of `points` per axis numbered in `order`; on a `periodic` grid every axis
    /// wraps. `None` if the points are more than `usize` numbers. O(d).
    pub fn new(points: Vec<usize>, periodic: bool, order: Order) -> Option<Grid> {
        let d = points.len();
        let mut stride = vec![1usize; d];
        let mut len = 1usize;
        let mut put = |a: usize| -> Option<()> {
            stride[a] = len;
            len = len.checked_mul(points[a])?;
            Some(())
        };
        match order {
            Order::FirstFastest => (0..d).try_for_each(&mut put)?,
            Order::LastFastest => (0..d).rev().try_for_each(&mut put)?,
        }
        Some(Grid { n: points, stride, order, periodic, len })
    }

    /// The doubled grid of a box of `shape` items placed by `placement`. `None` past
    /// `usize`. O(d).
    pub fn of_box(shape: &[usize], placement: Placement, order: Order) -> Option<Grid> {
        let points = shape.iter().map(|&l| placement.points(l)).collect::<Option<Vec<_>>>()?;
        Grid::new(points, placement.periodic(), order)
    }

    /// The number of axes.
    #[inline]
    pub fn axes(&self) -> usize {
        self.n.len()
    }

    /// Points per axis.
    #[inline]
    pub fn points(&self) -> &[usize] {
        &self.n
    }

    /// The stride of each axis in the point numbers.
    #[inline]
    pub fn strides(&self) -> &[usize] {
        &self.stride
    }

    /// The number of points.
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the grid has no point (an axis of none).
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether every axis wraps.
    #[inline]
    pub fn is_periodic(&self) -> bool {
        self.periodic
    }

    /// The coordinate of point `p` along axis `a`.
    #[inline]
    pub fn coord(&self, p: usize, a: usize) -> usize {
        (p / self.stride[a]) % self.n[a]
    }

    /// The coordinates of point `p`.
    pub fn coords(&self, p: usize) -> Vec<usize> {
        coordinates(&self.n, self.order, p)
    }

    /// The point at coordinates `c` (each below its axis's points).
    #[inline]
    pub fn point(&self, c: &[usize]) -> usize {
        c.iter().zip(&self.stride).map(|(c, s)| c * s).sum()
    }

    /// The dimension of the cell at `p`: its number of odd coordinates.
    #[inline]
    pub fn dim(&self, p: usize) -> usize {
        (0..self.n.len()).filter(|&a| self.coord(p, a) & 1 == 1).count()
    }

    /// The two faces of `p` along axis `a`, on which `p` has the odd coordinate `c`:
    /// `(lower, upper)`. The upper face of the last interval of a periodic axis is at 0; on
    /// a periodic axis of one cube the two faces are one point.
    #[inline]
    pub fn faces_along(&self, p: usize, a: usize, c: usize) -> (usize, usize) {
        let s = self.stride[a];
        let up = if c + 1 == self.n[a] { p - c * s } else { p + s };
        (p - s, up)
    }

    /// The cofaces of `p` along axis `a`, on which `p` has the even coordinate `c`:
    /// `[lower, upper]`, `None` past a side of a grid that is not periodic. On a periodic
    /// axis of one cube the two are one point.
    #[inline]
    pub fn cofaces_along(&self, p: usize, a: usize, c: usize) -> [Option<usize>; 2] {
        let (s, n) = (self.stride[a], self.n[a]);
        let lo = if c > 0 {
            Some(p - s)
        } else if self.periodic {
            Some(p + (n - 1) * s)
        } else {
            None
        };
        let hi = if c + 1 < n {
            Some(p + s)
        } else if self.periodic {
            Some(p - c * s)
        } else {
            None
        };
        [lo, hi]
    }

    /// Calls `f(lower, upper, sign)` for each odd axis of `p`, in axis order: its two faces
    /// there ([`Grid::faces_along`]) and the sign of the upper one ([`face_sign`]; the lower
    /// one has the opposite). The boundary of `p` is the sum over the calls of
    /// `sign · (upper − lower)`.
    #[inline]
    pub fn for_each_face(&self, p: usize, mut f: impl FnMut(usize, usize, i64)) {
        let mut j = 0;
        for a in 0..self.n.len() {
            let c = self.coord(p, a);
            if c & 1 == 1 {
                let (lo, up) = self.faces_along(p, a, c);
                f(lo, up, face_sign(j, true));
                j += 1;
            }
        }
    }

    /// The signed faces of `p` into `out` (cleared first): along each odd axis in order, the
    /// lower face then the upper one, with the signs of [`face_sign`]. Two faces that are one
    /// point (a periodic axis of one cube) are both listed; their entries cancel.
    #[inline]
    pub fn faces(&self, p: usize, out: &mut Vec<(usize, i64)>) {
        out.clear();
        self.for_each_face(p, |lo, up, s| {
            out.push((lo, -s));
            out.push((up, s));
        });
    }

    /// The number of an all-even (`odd == false`) or all-odd point among the points of that
    /// kind, in the grid's order: a vertex's or a top cell's number.
    #[inline]
    pub fn compact(&self, p: usize, odd: bool) -> usize {
        let count = |a: usize| if odd { self.n[a] / 2 } else { self.n[a].div_ceil(2) };
        let mut r = 0;
        let mut step = |a: usize| r = r * count(a) + self.coord(p, a) / 2;
        match self.order {
            Order::FirstFastest => (0..self.n.len()).rev().for_each(&mut step),
            Order::LastFastest => (0..self.n.len()).for_each(&mut step),
        }
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strides_follow_the_order() {
        let g = Grid::new(vec![3, 5, 2], false, Order::FirstFastest).unwrap();
        assert_eq!((g.strides(), g.len()), (&[1, 3, 15][..], 30));
        let h = Grid::new(vec![3, 5, 2], false, Order::LastFastest).unwrap();
        assert_eq!((h.strides(), h.len()), (&[10, 2, 1][..], 30));
        for p in 0..30 {
            assert_eq!(g.point(&g.coords(p)), p);
            assert_eq!(h.point(&h.coords(p)), p);
        }
        assert!(Grid::new(vec![usize::MAX, 2], false, Order::FirstFastest).is_none());
    }

    #[test]
    fn placements_and_estimates() {
        assert_eq!(Placement::Cubes.points(4), Some(9));
        assert_eq!(Placement::Vertices.points(4), Some(7));
        assert_eq!(Placement::Periodic.points(4), Some(8));
        assert_eq!(Placement::Vertices.points(0), None);
        assert_eq!(point_count(&[2, 3], Placement::Cubes), Some(35));
        assert_eq!(bytes(&[2, 3], Placement::Periodic, 9), Some(9 * 24));
        assert_eq!(point_count(&[1 << 40, 1 << 40], Placement::Cubes), None);
    }

    #[test]
    fn the_boundary_of_a_boundary_is_zero() {
        for (periodic, placement) in [(false, Placement::Cubes), (true, Placement::Periodic)] {
            let g = Grid::of_box(&[2, 3, 2], placement, Order::LastFastest).unwrap();
            assert_eq!(g.is_periodic(), periodic);
            let (mut f1, mut f2) = (Vec::new(), Vec::new());
            for p in 0..g.len() {
                let mut sum = std::collections::BTreeMap::new();
                g.faces(p, &mut f1);
                for &(q, s) in &f1 {
                    g.faces(q, &mut f2);
                    for &(r, t) in &f2 {
                        *sum.entry(r).or_insert(0) += s * t;
                    }
                }
                assert!(sum.values().all(|&v| v == 0), "∂∂ of point {p}");
                assert_eq!(f1.len(), 2 * g.dim(p));
            }
        }
    }

    #[test]
    fn faces_and_cofaces_wrap_on_a_periodic_grid() {
        let g = Grid::of_box(&[3], Placement::Periodic, Order::FirstFastest).unwrap();
        assert_eq!(g.faces_along(5, 0, 5), (4, 0));
        assert_eq!(g.cofaces_along(0, 0, 0), [Some(5), Some(1)]);
        let h = Grid::of_box(&[3], Placement::Cubes, Order::FirstFastest).unwrap();
        assert_eq!(h.cofaces_along(0, 0, 0), [None, Some(1)]);
        assert_eq!(h.cofaces_along(6, 0, 6), [Some(5), None]);
    }

    #[test]
    fn compact_numbers_vertices_and_top_cells_in_order() {
        for order in [Order::FirstFastest, Order::LastFastest] {
            let g = Grid::of_box(&[3, 2], Placement::Cubes, order).unwrap();
            let (mut even, mut odd) = (Vec::new(), Vec::new());
            for p in 0..g.len() {
                match g.dim(p) {
                    0 => even.push(g.compact(p, false)),
                    2 => odd.push(g.compact(p, true)),
                    _ => {}
                }
            }
            assert_eq!(even, (0..12).collect::<Vec<_>>());
            assert_eq!(odd, (0..6).collect::<Vec<_>>());
        }
    }
}
