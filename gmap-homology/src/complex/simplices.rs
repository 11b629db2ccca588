//! Any finite simplicial complex given by its facets, straight to a chain complex: every
//! face of every facet is a cell, simplices are oriented by increasing labels, and
//! `∂[v_0..v_k] = Σ (-1)^i [v_0..v̂_i..v_k]`.
//!
//! Facets may have mixed dimensions, a ridge may lie in any number of facets, a facet of one
//! vertex is an isolated vertex: no manifold condition at all. A d-simplex has `2^(d+1) - 1`
//! faces, so [`face_estimate`] counts them first (checked arithmetic) and
//! [`face_complex`] refuses an input over its limit before enumerating anything.
//!
//! Faces are found by sort-based deduplication per dimension: labels are renumbered
//! `0..V`, a k-face is packed into one `u128` when `(k + 1) ⌈log2 V⌉ <= 128` (else kept as
//! a slice of `u32`), the faces of each dimension are sorted and deduplicated, and each
//! boundary entry is a binary search among the faces one dimension down. Cells come out in
//! lexicographic order of their labels.
//!
//! ```
//! use gmap_homology::{homology_z, simplices::face_complex};
//! // a hollow triangle and an isolated vertex
//! let fc = face_complex(&[vec![1, 2], vec![2, 3], vec![1, 3], vec![7]], u64::MAX).unwrap();
//! assert_eq!(fc.chain.counts(), &[4, 3]);
//! assert_eq!(homology_z(&fc.chain).unwrap().to_string(), "(Z^2, Z)");
//! assert_eq!(fc.labels(1, 1), vec![1, 3]); // edges in lexicographic order: [1,2], [1,3], [2,3]
//! ```

use thiserror::Error;

use crate::engine::chain::ChainComplex;
use crate::engine::sparse::SparseMatrix;

/// Why a list of facets gives no chain complex.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum FaceError {
    /// No facet at all.
    #[error("no facet")]
    Empty,
    /// A facet listing a vertex twice (facet numbered from 0 in the order given).
    #[error("facet {facet} repeats vertex {vertex}")]
    RepeatedVertex {
        /// the facet's index
        facet: usize,
        /// the repeated label
        vertex: u64,
    },
    /// More faces than allowed (or than `u64` counts, `None`).
    #[error("{} faces (counted before removing shared ones), over the limit of {limit}",
        estimate.map_or_else(|| "more than 2^64".to_string(), |e| e.to_string()))]
    TooManyFaces {
        /// `Σ (2^(d_f + 1) - 1)` over the facets
        estimate: Option<u64>,
        /// the limit in force
        limit: u64,
    },
    /// A facet of more vertices than cell indices can number (`u32`).
    #[error("a facet of {0} vertices is too large")]
    FacetTooLarge(usize),
    /// The matrices could not be built (an index past `u32`).
    #[error("{0}")]
    Matrix(String),
}

/// The faces a list of facets spans, counted with repetition (each facet's `2^(d+1) - 1`
/// non-empty faces), or `None` past `u64`. O(F).
pub fn face_estimate<'a, I: IntoIterator<Item = &'a [u64]>>(facets: I) -> Option<u64> {
    let mut total = 0u64;
    for f in facets {
        let m = f.len() as u32;
        let n = if m >= 64 { return None } else { (1u64 << m) - 1 };
        total = total.checked_add(n)?;
    }
    Some(total)
}

/// A simplicial complex as a chain complex, with the labels of every cell.
#[derive(Clone, Debug)]
pub struct FaceComplex {
    /// the chain complex: k-cells are the k-faces, in lexicographic order of labels
    pub chain: ChainComplex,
    /// the vertex labels, sorted: vertex index `i` is label `vertices[i]`
    pub vertices: Vec<u64>,
    /// `faces[k][j * (k + 1)..][..k + 1]`: the vertex indices of k-face `j`, increasing
    pub faces: Vec<Vec<u32>>,
}

impl FaceComplex {
    /// The labels of k-face `j`, increasing.
    pub fn labels(&self, k: usize, j: usize) -> Vec<u64> {
        self.faces[k][j * (k + 1)..(j + 1) * (k + 1)].iter().map(|&v| self.vertices[v as usize]).collect()
    }

    /// The top dimension (that of the largest facets).
    pub fn dim(&self) -> usize {
        self.chain.dim()
    }
}

/// Sorted, deduplicated k-faces of one dimension with a way to find a face's index.
enum Faces {
    /// faces of at most 64 bits packed: keys as in `Packed`, and `start[v]..start[v + 1]`
    /// the range of the faces whose first vertex is `v` (a search looks only there)
    Small { keys: Vec<u64>, bits: u32, start: Vec<u32> },
    /// packed keys, `bits` per vertex, first vertex in the high bits
    Packed { keys: Vec<u128>, bits: u32 },
    /// flat vertex lists (stride k + 1), sorted lexicographically
    Flat { flat: Vec<u32>, stride: usize },
}

impl Faces {
    fn len(&self) -> usize {
        match self {
            Faces::Small { keys, .. } => keys.len(),
            Faces::Packed { keys, .. } => keys.len(),
            Faces::Flat { flat, stride } => flat.len() / stride,
        }
    }

    fn find(&self, face: &[u32]) -> Option<usize> {
        match self {
            Faces::Small { keys, bits, start } => {
                let v = face[0] as usize;
                let lo = start[v] as usize;
                let range = &keys[lo..start[v + 1] as usize];
                range.binary_search(&(pack(face, *bits) as u64)).ok().map(|k| lo + k)
            }
            Faces::Packed { keys, bits } => keys.binary_search(&pack(face, *bits)).ok(),
            Faces::Flat { flat, stride } => {
                let (mut lo, mut hi) = (0, flat.len() / stride);
                while lo < hi {
                    let mid = (lo + hi) / 2;
                    match flat[mid * stride..(mid + 1) * stride].cmp(face) {
                        std::cmp::Ordering::Less => lo = mid + 1,
                        std::cmp::Ordering::Greater => hi = mid,
                        std::cmp::Ordering::Equal => return Some(mid),
                    }
                }
                None
            }
        }
    }

    /// The flat vertex lists.
    fn to_flat(&self, stride: usize) -> Vec<u32> {
        match self {
            Faces::Flat { flat, .. } => flat.clone(),
            Faces::Small { keys, bits, .. } => unpack(keys.iter().map(|&k| u128::from(k)), *bits, stride),
            Faces::Packed { keys, bits } => unpack(keys.iter().copied(), *bits, stride),
        }
    }
}

/// The vertex lists of packed keys of `stride` vertices, `bits` each.
fn unpack(keys: impl ExactSizeIterator<Item = u128>, bits: u32, stride: usize) -> Vec<u32> {
    let mask = (1u128 << bits) - 1;
    let mut out = Vec::with_capacity(keys.len() * stride);
    for key in keys {
        for i in (0..stride).rev() {
            out.push(((key >> (bits * i as u32)) & mask) as u32);
        }
    }
    out
}

fn pack(face: &[u32], bits: u32) -> u128 {
    face.iter().fold(0u128, |acc, &v| (acc << bits) | v as u128)
}

/// Calls `f` on every `size`-subset of `vs` (increasing, in lexicographic order).
fn subsets(vs: &[u32], size: usize, buf: &mut Vec<u32>, f: &mut impl FnMut(&[u32])) {
    let n = vs.len();
    if size == 0 || size > n {
        return;
    }
    let mut idx: Vec<usize> = (0..size).collect();
    loop {
        buf.clear();
        buf.extend(idx.iter().map(|&i| vs[i]));
        f(buf);
        // the rightmost position that can still move right
        let mut i = size;
        while i > 0 && idx[i - 1] == i - 1 + n - size {
            i -= 1;
        }
        if i == 0 {
            return;
        }
        idx[i - 1] += 1;
        for j in i..size {
            idx[j] = idx[j - 1] + 1;
        }
    }
}

/// The chain complex of all faces of the given facets (module docs). Each facet's labels may
/// come in any order; a facet repeating a label is refused, and so is an input whose
/// [`face_estimate`] exceeds `limit` (before anything is enumerated). Facets listed twice or
/// contained in others are harmless. O(E log E) for E faces counted with repetition.
pub fn face_complex<F: AsRef<[u64]>>(facets: &[F], limit: u64) -> Result<FaceComplex, FaceError> {
    if facets.is_empty() {
        return Err(FaceError::Empty);
    }
    let estimate = face_estimate(facets.iter().map(AsRef::as_ref));
    match estimate {
        Some(e) if e <= limit => {}
        _ => return Err(FaceError::TooManyFaces { estimate, limit }),
    }
    // renumber the labels 0..V
    let mut vertices: Vec<u64> = facets.iter().flat_map(|f| f.as_ref().iter().copied()).collect();
    vertices.sort_unstable();
    vertices.dedup();
    let mut local: Vec<Vec<u32>> = Vec::with_capacity(facets.len());
    let mut top = 0;
    for (i, f) in facets.iter().enumerate() {
        let mut g: Vec<u32> =
            f.as_ref().iter().map(|v| vertices.binary_search(v).expect("label collected above") as u32).collect();
        g.sort_unstable();
        if let Some(w) = g.windows(2).find(|w| w[0] == w[1]) {
            return Err(FaceError::RepeatedVertex { facet: i, vertex: vertices[w[0] as usize] });
        }
        if g.len() > 64 {
            return Err(FaceError::FacetTooLarge(g.len()));
        }
        top = top.max(g.len());
        local.push(g);
    }
    if top == 0 {
        return Err(FaceError::Empty);
    }
    let bits = (32 - (vertices.len().saturating_sub(1) as u32).leading_zeros()).max(1);
    let mut faces: Vec<Faces> = Vec::with_capacity(top);
    let mut buf = Vec::new();
    for size in 1..=top {
        let f = if bits as usize * size <= 64 {
            let mut keys: Vec<u64> = Vec::new();
            for g in &local {
                subsets(g, size, &mut buf, &mut |s| keys.push(pack(s, bits) as u64));
            }
            keys.sort_unstable();
            keys.dedup();
            // the first vertex is the top `bits` of the key's `bits * size`
            let shift = bits * (size as u32 - 1);
            let mut start = vec![0u32; vertices.len() + 1];
            for &key in &keys {
                start[(key >> shift) as usize + 1] += 1;
            }
            for v in 0..vertices.len() {
                start[v + 1] += start[v];
            }
            Faces::Small { keys, bits, start }
        } else if bits as usize * size <= 128 {
            let mut keys = Vec::new();
            for g in &local {
                subsets(g, size, &mut buf, &mut |s| keys.push(pack(s, bits)));
            }
            keys.sort_unstable();
            keys.dedup();
            Faces::Packed { keys, bits }
        } else {
            let mut all: Vec<u32> = Vec::new();
            for g in &local {
                subsets(g, size, &mut buf, &mut |s| all.extend_from_slice(s));
            }
            let mut order: Vec<usize> = (0..all.len() / size).collect();
            order.sort_unstable_by(|&a, &b| all[a * size..(a + 1) * size].cmp(&all[b * size..(b + 1) * size]));
            order.dedup_by(|a, b| all[*a * size..(*a + 1) * size] == all[*b * size..(*b + 1) * size]);
            let mut flat = Vec::with_capacity(order.len() * size);
            for j in order {
                flat.extend_from_slice(&all[j * size..(j + 1) * size]);
            }
            Faces::Flat { flat, stride: size }
        };
        faces.push(f);
    }
    let counts: Vec<usize> = faces.iter().map(Faces::len).collect();
    let flat: Vec<Vec<u32>> = faces.iter().enumerate().map(|(k, f)| f.to_flat(k + 1)).collect();
    let mut boundaries = Vec::with_capacity(top - 1);
    let mut face = Vec::new();
    for k in 1..top {
        let mut entries: Vec<(u32, u32, i64)> = Vec::with_capacity(counts[k] * (k + 1));
        for (j, s) in flat[k].chunks_exact(k + 1).enumerate() {
            for i in 0..=k {
                face.clear();
                face.extend(s.iter().enumerate().filter(|&(x, _)| x != i).map(|(_, &v)| v));
                let row = faces[k - 1].find(&face).expect("every face of a face was enumerated");
                entries.push((row as u32, j as u32, if i % 2 == 0 { 1 } else { -1 }));
            }
        }
        let m = SparseMatrix::try_from_entries(counts[k - 1], counts[k], &entries)
            .map_err(|e| FaceError::Matrix(e.to_string()))?;
        boundaries.push(m);
    }
    let chain = ChainComplex::try_new_unchecked_dd(counts, boundaries).map_err(|e| FaceError::Matrix(e.to_string()))?;
    Ok(FaceComplex { chain, vertices, faces: flat })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::homology::{homology_z, homology_zp};

    /// A triangulated mod-k Moore space: a disk (a fan of triangles around a centre, in an
    /// annulus of two rings of 3k vertices) whose boundary wraps a triangle k times.
    pub(crate) fn moore(k: u64) -> Vec<Vec<u64>> {
        // boundary ring: 3k vertices b_i mapped to triangle vertex i mod 3; inner ring of 3k
        // vertices c_i; centre z. Triangles: (b_i, b_{i+1}, c_i), (b_{i+1}, c_i, c_{i+1}),
        // (c_i, c_{i+1}, z); b_i is label i mod 3 — the edge b_i b_{i+1} runs round the
        // triangle 0 1 2 k times.
        let n = 3 * k;
        let b = |i: u64| i % 3;
        let c = |i: u64| 3 + (i % n);
        let z = 3 + n;
        let mut out = Vec::new();
        for i in 0..n {
            out.push(vec![b(i), b(i + 1), c(i)]);
            out.push(vec![b(i + 1), c(i), c(i + 1)]);
            out.push(vec![c(i), c(i + 1), z]);
        }
        out
    }

    #[test]
    fn moore_spaces_have_torsion() {
        for k in [2u64, 3, 12] {
            let fc = face_complex(&moore(k), u64::MAX).unwrap();
            fc.chain.check_dd().unwrap();
            let h = homology_z(&fc.chain).unwrap();
            assert_eq!(h.betti, vec![1, 0, 0], "k = {k}");
            assert_eq!(h.torsion, vec![vec![], vec![k], vec![]], "k = {k}");
            let h3 = homology_zp(&fc.chain, 3).unwrap();
            let want = if k % 3 == 0 { vec![1, 1, 1] } else { vec![1, 0, 0] };
            assert_eq!(h3.betti, want, "k = {k} over Z/3");
        }
    }

    #[test]
    fn mixed_dimensions_isolated_vertices_and_books() {
        // three triangles on one edge (a book), a dangling edge, an isolated vertex
        let f = vec![vec![1, 2, 3], vec![1, 2, 4], vec![2, 1, 5], vec![5, 6], vec![9]];
        let fc = face_complex(&f, 1000).unwrap();
        fc.chain.check_dd().unwrap();
        assert_eq!(fc.chain.counts(), &[7, 8, 3]);
        assert_eq!(homology_z(&fc.chain).unwrap().to_string(), "(Z^2, 0, 0)");
        assert_eq!(fc.labels(2, 2), vec![1, 2, 5]);
        assert_eq!(face_complex(&[vec![1, 2, 2]], 100).unwrap_err(), FaceError::RepeatedVertex { facet: 0, vertex: 2 });
        assert_eq!(
            face_complex(&[vec![1, 2, 3]], 6).unwrap_err(),
            FaceError::TooManyFaces { estimate: Some(7), limit: 6 }
        );
        assert_eq!(face_estimate([&[0u64; 64][..]]), None);
    }

    #[test]
    fn wide_labels_take_the_flat_path() {
        // the boundary of a 12-simplex on labels far apart: a sphere S^11
        let big: Vec<u64> = (0..13).map(|i| i * 1_000_003).collect();
        let facets: Vec<Vec<u64>> = (0..13).map(|j| big.iter().copied().filter(|&v| v != big[j]).collect()).collect();
        let fc = face_complex(&facets, u64::MAX).unwrap();
        fc.chain.check_dd().unwrap();
        let h = homology_z(&fc.chain).unwrap();
        let mut want = vec![0; 12];
        want[0] = 1;
        want[11] = 1;
        assert_eq!(h.betti, want);
        // 2^9 vertices of 9 bits each: faces of 15 vertices take 135 bits, the flat path
        let mut many: Vec<Vec<u64>> = (0..512).map(|v| vec![v]).collect();
        many.push((0..15).collect());
        let fc = face_complex(&many, u64::MAX).unwrap();
        fc.chain.check_dd().unwrap();
        let h = homology_z(&fc.chain).unwrap();
        assert_eq!(h.betti[0], 512 - 15 + 1);
        assert!(h.betti[1..].iter().all(|&b| b == 0));
    }
}
