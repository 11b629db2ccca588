//! Any finite simplicial complex given by its facets, straight to a chain complex: every
//! face of every facet is a cell, simplices are oriented by increasing labels, and
//! `∂[v_0..v_k] = Σ (-1)^i [v_0..v̂_i..v_k]`.
//!
//! Facets may have mixed dimensions, a ridge may lie in any number of facets, a facet of one
//! vertex is an isolated vertex: no manifold condition at all. A d-simplex has `2^(d+1) - 1`
//! faces, so [`face_estimate`] counts them first (checked arithmetic) and
//! [`face_complex`] refuses an input over its limit before enumerating anything.
//!
//! Faces are found by hashing, one dimension at a time from the top down: labels are
//! renumbered `0..V`, a face is packed into one `u64` (or `u128`) when its vertices fit at
//! `⌈log2 V⌉` bits each (else kept as a list of `u32`), and each cell's boundary column comes
//! from dropping each of its vertices in turn and looking the face up in a hash table of the
//! dimension below, which numbers new faces on first sight. So the boundary matrices are
//! built column by column in one pass, with no sort and no search, and only faces of the
//! facets are ever generated. Cells are numbered in that order of discovery: the facets of
//! the top dimension in input order (repeats dropped), then, in each dimension, the faces of
//! the cells above followed by the facets of that dimension not met yet.
//!
//! ```
//! use gmap_homology::{homology_z, simplices::face_complex};
//! // a hollow triangle and an isolated vertex
//! let fc = face_complex(&[vec![1, 2], vec![2, 3], vec![1, 3], vec![7]], u64::MAX).unwrap();
//! assert_eq!(fc.chain.counts(), &[4, 3]);
//! assert_eq!(homology_z(&fc.chain).unwrap().to_string(), "(Z^2, Z)");
//! // the edges in the order found: those of the facets as listed
//! assert_eq!((0..3).map(|j| fc.labels(1, j)).collect::<Vec<_>>(), [[1, 2], [2, 3], [1, 3]]);
//! ```

use rustc_hash::FxHashMap;
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
    /// the chain complex: k-cells are the k-faces, numbered in order of discovery (module docs)
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

/// A face as a hash key: its vertex indices (increasing) packed `bits` per vertex with the
/// first vertex in the high bits (`u64`, `u128`), or the list itself when no integer holds it.
trait FaceKey: Clone + Eq + std::hash::Hash {
    /// The key of `face` (increasing vertex indices).
    fn pack(face: &[u32], bits: u32) -> Self;
    /// The key of the face of `size` vertices without the vertex at position `p` (from 0,
    /// the first and smallest vertex).
    fn without(&self, p: usize, size: usize, bits: u32) -> Self;
    /// Appends the `size` vertex indices of the key to `out`, increasing.
    fn unpack_into(&self, size: usize, bits: u32, out: &mut Vec<u32>);
}

macro_rules! packed_key {
    ($t:ty) => {
        impl FaceKey for $t {
            fn pack(face: &[u32], bits: u32) -> Self {
                face.iter().fold(0, |acc: $t, &v| (acc << bits) | <$t>::from(v))
            }

            fn without(&self, p: usize, size: usize, bits: u32) -> Self {
                // the vertices after position p sit in the low (size - 1 - p) * bits bits
                let low_bits = (size - 1 - p) as u32 * bits;
                let low = *self & <$t>::MAX.checked_shr(<$t>::BITS - low_bits).unwrap_or(0);
                let high = self.checked_shr(low_bits + bits).unwrap_or(0);
                high.checked_shl(low_bits).unwrap_or(0) | low
            }

            fn unpack_into(&self, size: usize, bits: u32, out: &mut Vec<u32>) {
                let mask = <$t>::MAX >> (<$t>::BITS - bits);
                for i in (0..size as u32).rev() {
                    out.push(((*self >> (bits * i)) & mask) as u32);
                }
            }
        }
    };
}
packed_key!(u64);
packed_key!(u128);

impl FaceKey for Box<[u32]> {
    fn pack(face: &[u32], _: u32) -> Self {
        face.into()
    }

    fn without(&self, p: usize, _: usize, _: u32) -> Self {
        self.iter().enumerate().filter(|&(i, _)| i != p).map(|(_, &v)| v).collect()
    }

    fn unpack_into(&self, _: usize, _: u32, out: &mut Vec<u32>) {
        out.extend_from_slice(self);
    }
}

/// The chain complex and the faces (flat, as in [`FaceComplex`]) of facets given as increasing vertex indices, `top` the
/// largest facet size (module docs). One pass per dimension, from the top down: the cells of
/// size `s` are the faces found from the cells of size `s + 1` followed by the facets of size
/// `s` not seen yet; dropping each vertex of each of them in turn gives its boundary column
/// and numbers the new faces of size `s - 1` on first sight.
fn enumerate<K: FaceKey>(
    local: &[Vec<u32>],
    top: usize,
    bits: u32,
) -> Result<(ChainComplex, Vec<Vec<u32>>), FaceError> {
    let mut by_size: Vec<Vec<&[u32]>> = vec![Vec::new(); top + 1];
    for g in local {
        by_size[g.len()].push(g);
    }
    let mut index: FxHashMap<K, u32> = FxHashMap::default();
    index.reserve(by_size[top].len());
    let mut keys: Vec<K> = Vec::new();
    let mut columns = Vec::with_capacity(top - 1);
    let mut flat: Vec<Vec<u32>> = vec![Vec::new(); top];
    let mut counts = vec![0; top];
    let mut column: Vec<(u32, i64)> = Vec::with_capacity(top);
    for size in (1..=top).rev() {
        for g in &by_size[size] {
            let key = K::pack(g, bits);
            if !index.contains_key(&key) {
                index.insert(key.clone(), keys.len() as u32);
                keys.push(key);
            }
        }
        let cells = std::mem::take(&mut keys);
        counts[size - 1] = cells.len();
        let out = &mut flat[size - 1];
        out.reserve(cells.len() * size);
        for key in &cells {
            key.unpack_into(size, bits, out);
        }
        if size == 1 {
            break;
        }
        // the faces one size down, numbered on first sight
        let mut below: FxHashMap<K, u32> = FxHashMap::default();
        below.reserve(cells.len() * size / 2);
        keys.reserve(cells.len() * size / 2);
        let mut col_ptr = Vec::with_capacity(cells.len() + 1);
        let mut row_idx = Vec::with_capacity(cells.len() * size);
        let mut vals = Vec::with_capacity(cells.len() * size);
        col_ptr.push(0);
        for key in &cells {
            column.clear();
            for p in 0..size {
                let face = key.without(p, size, bits);
                let next = keys.len() as u32;
                let row = *below.entry(face).or_insert_with_key(|f| {
                    keys.push(f.clone());
                    next
                });
                column.push((row, if p % 2 == 0 { 1 } else { -1 }));
            }
            column.sort_unstable_by_key(|&(r, _)| r);
            row_idx.extend(column.iter().map(|&(r, _)| r));
            vals.extend(column.iter().map(|&(_, v)| v));
            col_ptr.push(row_idx.len());
        }
        if keys.len() > u32::MAX as usize {
            return Err(FaceError::Matrix(format!("{} faces of {} vertices, past u32 indices", keys.len(), size - 1)));
        }
        // the rows are known once the facets of size `size - 1` join, at the next step
        columns.push((cells.len(), col_ptr, row_idx, vals));
        index = below;
    }
    let mut boundaries = Vec::with_capacity(top - 1);
    for (k, (cols, col_ptr, row_idx, vals)) in columns.into_iter().rev().enumerate() {
        let m = SparseMatrix::try_from_csc(counts[k], cols, col_ptr, row_idx, vals)
            .map_err(|e| FaceError::Matrix(e.to_string()))?;
        boundaries.push(m);
    }
    let chain = ChainComplex::try_new_unchecked_dd(counts, boundaries).map_err(|e| FaceError::Matrix(e.to_string()))?;
    Ok((chain, flat))
}

/// The chain complex of all faces of the given facets (module docs). Each facet's labels may
/// come in any order; a facet repeating a label is refused, and so is an input whose
/// [`face_estimate`] exceeds `limit` (before anything is enumerated). Facets listed twice or
/// contained in others are harmless. Expected O(E · d) for E faces counted with repetition
/// and facets of at most d + 1 vertices (one hash look-up per boundary entry).
pub fn face_complex<F: AsRef<[u64]>>(facets: &[F], limit: u64) -> Result<FaceComplex, FaceError> {
    if facets.is_empty() {
        return Err(FaceError::Empty);
    }
    let estimate = face_estimate(facets.iter().map(AsRef::as_ref));
    match estimate {
        Some(e) if e <= limit => {}
        _ => return Err(FaceError::TooManyFaces { estimate, limit }),
    }
    // renumber the labels 0..V: by a table when the labels are small (the usual 1..V), else
    // by binary search among the sorted labels
    let entries: usize = facets.iter().map(|f| f.as_ref().len()).sum();
    let largest = facets.iter().flat_map(|f| f.as_ref().iter().copied()).max().unwrap_or(0);
    let (vertices, table) = if largest < 2 * entries as u64 + 1024 {
        // mark the labels present, then number them in increasing order: no sort
        let mut table = vec![u32::MAX; largest as usize + 1];
        for f in facets {
            for &v in f.as_ref() {
                table[v as usize] = 0;
            }
        }
        let mut vertices = Vec::new();
        for (v, slot) in table.iter_mut().enumerate() {
            if *slot == 0 {
                *slot = vertices.len() as u32;
                vertices.push(v as u64);
            }
        }
        (vertices, Some(table))
    } else {
        let mut vertices: Vec<u64> = facets.iter().flat_map(|f| f.as_ref().iter().copied()).collect();
        vertices.sort_unstable();
        vertices.dedup();
        (vertices, None)
    };
    let index_of = |v: &u64| match &table {
        Some(t) => t[*v as usize],
        None => vertices.binary_search(v).expect("label collected above") as u32,
    };
    let mut local: Vec<Vec<u32>> = Vec::with_capacity(facets.len());
    let mut top = 0;
    for (i, f) in facets.iter().enumerate() {
        let mut g: Vec<u32> = f.as_ref().iter().map(index_of).collect();
        if !g.is_sorted() {
            g.sort_unstable();
        }
        if let Some(w) = g.windows(2).find(|w| w[0] == w[1]) {
            return Err(FaceError::RepeatedVertex { facet: i, vertex: vertices[w[0] as usize] });
        }
        if g.len() > 64 {
            return Err(FaceError::FacetTooLarge(g.len()));
        }
        top = top.max(g.len());
        local.push(g);
    }
    let bits = (32 - (vertices.len().saturating_sub(1) as u32).leading_zeros()).max(1);
    let (chain, faces) = if bits as usize * top <= 64 {
        enumerate::<u64>(&local, top, bits)?
    } else if bits as usize * top <= 128 {
        enumerate::<u128>(&local, top, bits)?
    } else {
        enumerate::<Box<[u32]>>(&local, top, bits)?
    };
    Ok(FaceComplex { chain, vertices, faces })
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
    fn packed_keys_drop_each_vertex_at_full_width() {
        // 8 vertices of 8 bits fill a u64; 16 of 8 bits fill a u128: dropping the first
        // vertex shifts by the whole width
        let face: Vec<u32> = (0..8).map(|i| 200 + i).collect();
        let wide: Vec<u32> = (0..16).map(|i| 100 + 9 * i).collect();
        for p in 0..8 {
            let want: Vec<u32> = face.iter().enumerate().filter(|&(i, _)| i != p).map(|(_, &v)| v).collect();
            let mut got = Vec::new();
            <u64 as FaceKey>::pack(&face, 8).without(p, 8, 8).unpack_into(7, 8, &mut got);
            assert_eq!(got, want, "u64, p = {p}");
        }
        for p in 0..16 {
            let want: Vec<u32> = wide.iter().enumerate().filter(|&(i, _)| i != p).map(|(_, &v)| v).collect();
            let mut got = Vec::new();
            <u128 as FaceKey>::pack(&wide, 8).without(p, 16, 8).unpack_into(15, 8, &mut got);
            assert_eq!(got, want, "u128, p = {p}");
            let mut flat = Vec::new();
            <Box<[u32]> as FaceKey>::pack(&wide, 8).without(p, 16, 8).unpack_into(15, 8, &mut flat);
            assert_eq!(flat, want, "list, p = {p}");
        }
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
