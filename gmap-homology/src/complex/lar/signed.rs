//! Signed boundary and coboundary matrices from the characteristic matrices, with LAR's
//! *conventional orientation* (LAR, "Conventional orientation"):
//!
//! * every vertex is positive;
//! * an edge `{a, b}` with `a < b` runs from `a` to `b`: `∂e = b - a`;
//! * a p-cell, `2 <= p`, is oriented from the first facet of its canonical representation:
//!   its facets (by the count rule, [`Lar::unsigned_boundary`]) sorted by index, the
//!   lowest-numbered one gets `+1` and the others the signs that make the boundary of the
//!   boundary cancel ("coherent orientation");
//! * with coordinates, a top cell may instead take the sign of its oriented measure:
//!   [`Lar::signed_boundary_planar`] orients every face of a plane 2-complex
//!   counter-clockwise (positive area), [`Lar::signed_boundary_solid`] orients every 3-cell
//!   of a 3-complex in space so that its boundary 2-cycle encloses a positive volume
//!   (outward normals by the right-hand rule).
//!
//! The signed coboundary is the transpose of the signed boundary. Both conventions give
//! `∂_{p-1} ∂_p = 0`, and the homology of the resulting chain complex is the cellular
//! homology of the complex; on a G-map whose cells are determined by their vertex sets it
//! is our border operator up to the sign of each cell.

use super::{Lar, LarError};
use crate::engine::chain::ChainComplex;
use crate::engine::sparse::SparseMatrix;

impl Lar {
    /// `[∂_1], …, [∂_n]` with the first-facet convention (module docs). Rows of `∂_p` are
    /// (p-1)-cells, columns p-cells; every entry is `±1`.
    ///
    /// Precondition ([`Lar::is_orientable`]): every edge has two vertices, no two p-cells
    /// have the same vertex set ([`Lar::check_distinct`]), and the facets of
    /// every p-cell (`p >= 2`) form one connected closed orientable (p-1)-cycle: each
    /// (p-2)-cell of its boundary lies on exactly two of its facets. Errors name the cell:
    /// [`LarError::EdgeVertices`], [`LarError::SameVertices`], [`LarError::NoFacet`], [`LarError::OpenBoundary`],
    /// [`LarError::DisconnectedBoundary`], [`LarError::NonOrientable`].
    /// O(Σ_p (cost of the count rule + nnz(∂_p) · facet size · log)).
    ///
    /// ```
    /// use gmap_homology::lar::{characteristic_matrix, Lar};
    /// // a triangle: edges {0,1}, {1,2}, {0,2}; one face
    /// let lar = Lar::from_cells(3, vec![
    ///     characteristic_matrix(3, &[vec![0, 1], vec![1, 2], vec![0, 2]]).unwrap(),
    ///     characteristic_matrix(3, &[vec![0, 1, 2]]).unwrap(),
    /// ]).unwrap();
    /// let d = lar.signed_boundaries().unwrap();
    /// // edges run from the lower vertex to the higher
    /// assert_eq!(d[0].to_dense(), vec![vec![-1, 0, -1], vec![1, -1, 0], vec![0, 1, 1]]);
    /// // the face follows its first edge {0,1}: 0 -> 1 -> 2 -> 0
    /// assert_eq!(d[1].to_dense(), vec![vec![1], vec![1], vec![-1]]);
    /// ```
    pub fn signed_boundaries(&self) -> Result<Vec<SparseMatrix>, LarError> {
        let mut out: Vec<SparseMatrix> = Vec::with_capacity(self.dim());
        for p in 1..=self.dim() {
            let d = match out.last() {
                None => self.signed_edges()?,
                Some(lower) => {
                    self.check_distinct(p)?;
                    orient_cells(p, &self.unsigned_boundary(p)?, lower)?
                }
            };
            if p == 1 {
                self.check_distinct(1)?;
            }
            out.push(d);
        }
        Ok(out)
    }

    /// `[∂_p]` with the first-facet convention, `1 <= p <= n`; see
    /// [`Lar::signed_boundaries`] (it computes `∂_1 … ∂_p`).
    pub fn signed_boundary(&self, p: usize) -> Result<SparseMatrix, LarError> {
        if p == 0 || p > self.dim() {
            return Err(LarError::NoSuchDimension { p, n: self.dim() });
        }
        let mut all = Lar { vertices: self.vertices, cells: self.cells[..p].to_vec() }.signed_boundaries()?;
        Ok(all.swap_remove(p - 1))
    }

    /// The signed coboundary `[δ_p] = [∂_{p+1}]^T : C_p → C_{p+1}`, `0 <= p < n`: rows
    /// (p+1)-cells, columns p-cells. Same precondition as [`Lar::signed_boundaries`].
    pub fn signed_coboundary(&self, p: usize) -> Result<SparseMatrix, LarError> {
        Ok(self.signed_boundary(p + 1)?.transpose())
    }

    /// Whether [`Lar::signed_boundaries`] succeeds: the precondition of every signed
    /// operator here.
    pub fn is_orientable(&self) -> bool {
        self.signed_boundaries().is_ok()
    }

    /// The chain complex `C_0 ← C_1 ← … ← C_n` of the signed boundaries, `∂∂ = 0` checked.
    /// Feed it to [`crate::homology_z`] for the homology groups.
    pub fn chain_complex(&self) -> Result<ChainComplex, LarError> {
        let d = self.signed_boundaries()?;
        let mut counts = vec![self.vertices];
        counts.extend(self.cells.iter().map(SparseMatrix::rows));
        Ok(ChainComplex::try_new(counts, d)?)
    }

    /// `[∂_2]` of a 2-complex in the plane with every face counter-clockwise: the face's
    /// first-facet orientation, turned over where its boundary 1-cycle encloses a negative
    /// area (twice the area is `Σ_e s_e (x_a y_b - x_b y_a)` over its edges `e = (a, b)`
    /// with sign `s_e`, exact in `i128`). `points[v]` is vertex `v`.
    ///
    /// Precondition: that of [`Lar::signed_boundaries`], `dim() == 2`, one point per vertex,
    /// no face of zero area ([`LarError::ZeroMeasure`]). O(cost of `∂_1, ∂_2`).
    pub fn signed_boundary_planar(&self, points: &[[i32; 2]]) -> Result<SparseMatrix, LarError> {
        self.check_top(2, points.len())?;
        let d = self.signed_boundaries()?;
        let edge_area = |e: usize| {
            let (a, b) = ends(&d[0], e);
            let (p, q) = (points[a], points[b]);
            i128::from(p[0]) * i128::from(q[1]) - i128::from(q[0]) * i128::from(p[1])
        };
        flip_by_measure(2, &d[1], |f| {
            let (rows, vals) = d[1].col(f);
            rows.iter()
                .zip(vals)
                .try_fold(0i128, |acc, (&e, &s)| acc.checked_add(i128::from(s) * edge_area(e as usize)))
        })
    }

    /// `[∂_3]` of a 3-complex in space with every 3-cell's boundary enclosing a positive
    /// volume (outward normals by the right-hand rule): the first-facet orientation, turned
    /// over where six times the volume, `Σ_f s_f Σ_e t_e det(q_f, a, b)` over the faces `f`
    /// of the cell (sign `s_f`), the edges `e = (a, b)` of each face (sign `t_e` in `∂_2`) and
    /// a vertex `q_f` of the face, is negative (exact in `i128`). `points[v]` is vertex `v`.
    ///
    /// Precondition: that of [`Lar::signed_boundaries`], `dim() == 3`, one point per vertex,
    /// no 3-cell of zero volume. O(cost of `∂_1 … ∂_3`).
    pub fn signed_boundary_solid(&self, points: &[[i32; 3]]) -> Result<SparseMatrix, LarError> {
        self.check_top(3, points.len())?;
        let d = self.signed_boundaries()?;
        let pt = |v: usize| points[v].map(i128::from);
        // six times the signed volume of the cone from the origin over face f
        let cone = |f: usize| -> Option<i128> {
            let (edges, signs) = d[1].col(f);
            let q = pt(ends(&d[0], edges[0] as usize).0);
            edges.iter().zip(signs).try_fold(0i128, |acc, (&e, &t)| {
                let (a, b) = ends(&d[0], e as usize);
                acc.checked_add(i128::from(t) * det3(q, pt(a), pt(b))?)
            })
        };
        flip_by_measure(3, &d[2], |c| {
            let (faces, signs) = d[2].col(c);
            faces.iter().zip(signs).try_fold(0i128, |acc, (&f, &s)| acc.checked_add(i128::from(s) * cone(f as usize)?))
        })
    }

    /// Checks `dim() == n` and one point per vertex.
    fn check_top(&self, n: usize, points: usize) -> Result<(), LarError> {
        if self.dim() != n {
            return Err(LarError::NoSuchDimension { p: n, n: self.dim() });
        }
        if points != self.vertices {
            return Err(LarError::PointCount { points, vertices: self.vertices });
        }
        Ok(())
    }

    /// Whether the p-cells have pairwise distinct vertex sets: the condition for the count
    /// rule to see a complex faithfully ([`LarError::SameVertices`] names two cells that
    /// share theirs). O(nnz(M_p) log).
    pub fn check_distinct(&self, p: usize) -> Result<(), LarError> {
        if p == 0 || p > self.dim() {
            return Err(LarError::NoSuchDimension { p, n: self.dim() });
        }
        let t = self.cells[p - 1].transpose();
        let mut sets: Vec<(&[u32], usize)> = (0..t.cols()).map(|j| (t.col(j).0, j)).collect();
        sets.sort_unstable();
        match sets.windows(2).find(|w| w[0].0 == w[1].0) {
            Some(w) => Err(LarError::SameVertices { dim: p, first: w[0].1, second: w[1].1 }),
            None => Ok(()),
        }
    }

    /// `[∂_1]`: edge `{a, b}`, `a < b`, has `-1` at `a` and `+1` at `b`.
    fn signed_edges(&self) -> Result<SparseMatrix, LarError> {
        let ev = self.cells[0].transpose();
        let mut columns = Vec::with_capacity(ev.cols());
        for e in 0..ev.cols() {
            match ev.col(e).0 {
                &[a, b] => columns.push(vec![(a, -1), (b, 1)]),
                other => return Err(LarError::EdgeVertices { edge: e, count: other.len() }),
            }
        }
        Ok(SparseMatrix::try_from_columns(self.vertices, &columns).expect("two distinct sorted vertices per edge"))
    }
}

/// The two ends `(a, b)`, `a < b`, of edge `e` in a signed `∂_1`.
fn ends(d1: &SparseMatrix, e: usize) -> (usize, usize) {
    let (r, _) = d1.col(e);
    (r[0] as usize, r[1] as usize)
}

/// `det(a, b, c)` of three integer vectors, checked.
fn det3(a: [i128; 3], b: [i128; 3], c: [i128; 3]) -> Option<i128> {
    let minor = |i: usize, j: usize| b[i].checked_mul(c[j])?.checked_sub(b[j].checked_mul(c[i])?);
    a[0].checked_mul(minor(1, 2)?)?
        .checked_sub(a[1].checked_mul(minor(0, 2)?)?)?
        .checked_add(a[2].checked_mul(minor(0, 1)?)?)
}

/// `d` with column `j` negated where `measure(j) < 0`; a zero measure is an error, an
/// overflow (`None`) too.
fn flip_by_measure(
    dim: usize,
    d: &SparseMatrix,
    measure: impl Fn(usize) -> Option<i128>,
) -> Result<SparseMatrix, LarError> {
    let mut columns = Vec::with_capacity(d.cols());
    for j in 0..d.cols() {
        let m = measure(j).ok_or(LarError::Overflow)?;
        if m == 0 {
            return Err(LarError::ZeroMeasure { dim, cell: j });
        }
        let s = m.signum() as i64;
        let (rows, vals) = d.col(j);
        columns.push(rows.iter().zip(vals).map(|(&r, &v)| (r, s * v)).collect());
    }
    Ok(SparseMatrix::try_from_columns(d.rows(), &columns).expect("a matrix with some columns negated"))
}

/// The signed `∂_p` (`p >= 2`) from the unsigned one and the signed `∂_{p-1}`: each cell's
/// facets are signed by a breadth-first walk from its first facet (sign `+1`) across the
/// (p-2)-cells they share, so that each shared (p-2)-cell cancels. O(Σ_j F_j R log(F_j R))
/// for F_j facets of cell j with at most R (p-2)-cells each.
fn orient_cells(p: usize, unsigned: &SparseMatrix, lower: &SparseMatrix) -> Result<SparseMatrix, LarError> {
    let mut columns = Vec::with_capacity(unsigned.cols());
    for cell in 0..unsigned.cols() {
        let facets = unsigned.col(cell).0;
        if facets.is_empty() {
            return Err(LarError::NoFacet { dim: p, cell });
        }
        // (ridge, facet position, sign of the ridge in the facet's boundary)
        let mut touch: Vec<(u32, usize, i64)> = Vec::new();
        for (k, &f) in facets.iter().enumerate() {
            let (r, v) = lower.col(f as usize);
            touch.extend(r.iter().zip(v).map(|(&r, &v)| (r, k, v)));
        }
        touch.sort_unstable();
        // neighbours across each ridge: (other facet, ratio of the two signs, ridge)
        let mut adj: Vec<Vec<(usize, i64, u32)>> = vec![Vec::new(); facets.len()];
        for group in touch.chunk_by(|x, y| x.0 == y.0) {
            let ridge = group[0].0;
            if group.len() != 2 {
                return Err(LarError::OpenBoundary { dim: p, cell, ridge: ridge as usize, count: group.len() });
            }
            let ((_, a, sa), (_, b, sb)) = (group[0], group[1]);
            // s_a sa + s_b sb = 0 and sa, sb are ±1, so s_b = -s_a sa sb
            adj[a].push((b, -sa * sb, ridge));
            adj[b].push((a, -sa * sb, ridge));
        }
        let mut sign = vec![0i64; facets.len()];
        sign[0] = 1;
        let mut stack = vec![0usize];
        while let Some(a) = stack.pop() {
            for &(b, ratio, ridge) in &adj[a] {
                let want = sign[a] * ratio;
                if sign[b] == 0 {
                    sign[b] = want;
                    stack.push(b);
                } else if sign[b] != want {
                    return Err(LarError::NonOrientable { dim: p, cell, ridge: ridge as usize });
                }
            }
        }
        if let Some(k) = sign.iter().position(|&s| s == 0) {
            return Err(LarError::DisconnectedBoundary { dim: p, cell, facet: facets[k] as usize });
        }
        columns.push(facets.iter().zip(&sign).map(|(&f, &s)| (f, s)).collect());
    }
    Ok(SparseMatrix::try_from_columns(unsigned.rows(), &columns).expect("the unsigned boundary's pattern"))
}
