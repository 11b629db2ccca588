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

use thiserror::Error;

use crate::engine::chain::ChainComplex;
use crate::engine::sparse::SparseMatrix;

/// Why a list of facets gives no chain complex.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
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
    /// (empty vectors when [`face_complex_of`] was asked for no labels)
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

/// An odd constant near `2^64 / φ`: multiplying by it spreads consecutive keys over the
/// high bits (Fibonacci hashing).
const HASH_MULTIPLIER: u64 = 0x9e37_79b9_7f4a_7c15;

/// The numbers of the faces of one size, by key: an open-addressing table (linear probing)
/// of face numbers, the keys themselves held in the caller's vector in numbering order, so a
/// slot is 4 bytes. Kept at most half full.
struct FaceIndex {
    /// a face number per slot, [`FaceIndex::EMPTY`] for none; the length is a power of two
    slots: Vec<u32>,
    /// `64 - log2(slots.len())`: a hash's high bits pick the slot
    shift: u32,
}

impl FaceIndex {
    const EMPTY: u32 = u32::MAX;

    fn new() -> Self {
        FaceIndex { slots: vec![Self::EMPTY; 16], shift: 60 }
    }

    /// Empties the table, sized for about `n` keys (the memory is reused when it suffices).
    fn reset(&mut self, n: usize) {
        let want = (2 * n).next_power_of_two().max(16);
        if want > self.slots.len() {
            self.slots = vec![Self::EMPTY; want];
        } else {
            self.slots.fill(Self::EMPTY);
        }
        self.shift = 64 - self.slots.len().trailing_zeros();
    }

    /// The number of `key` among `keys` (whose entries are exactly the table's), pushing it
    /// as a new face when absent. Expected O(1).
    #[inline]
    fn find_or_insert<K: FaceKey>(&mut self, key: K, keys: &mut Vec<K>) -> u32 {
        let mask = self.slots.len() - 1;
        let mut i = (key.hash64() >> self.shift) as usize;
        loop {
            let s = self.slots[i];
            if s == Self::EMPTY {
                let n = keys.len() as u32;
                self.slots[i] = n;
                keys.push(key);
                if 2 * keys.len() > self.slots.len() {
                    self.grow(keys);
                }
                return n;
            }
            if keys[s as usize] == key {
                return s;
            }
            i = (i + 1) & mask;
        }
    }

    /// Doubles the table and re-enters every key.
    fn grow<K: FaceKey>(&mut self, keys: &[K]) {
        self.slots = vec![Self::EMPTY; 2 * self.slots.len()];
        self.shift -= 1;
        let mask = self.slots.len() - 1;
        for (n, key) in keys.iter().enumerate() {
            let mut i = (key.hash64() >> self.shift) as usize;
            while self.slots[i] != Self::EMPTY {
                i = (i + 1) & mask;
            }
            self.slots[i] = n as u32;
        }
    }
}

/// A face as a hash key: its vertex indices (increasing) packed `bits` per vertex with the
/// first vertex in the high bits (`u64`, `u128`), or the list itself when no integer holds it.
trait FaceKey: Clone + Eq {
    /// A 64-bit hash of the key (its high bits are used).
    fn hash64(&self) -> u64;
    /// The key of `face` (increasing vertex indices).
    fn pack(face: &[u32], bits: u32) -> Self;
    /// Calls `f(p, face)` for each position `p` of the key's `size` vertices (from 0, the
    /// first and smallest vertex), with the key of the face without that vertex.
    fn for_each_face(&self, size: usize, bits: u32, f: impl FnMut(usize, Self));
    /// Writes the vertex indices of the key to `out` (as many as `out` holds), increasing.
    fn unpack_into(&self, bits: u32, out: &mut [u32]);
}

macro_rules! packed_key {
    ($t:ty) => {
        impl FaceKey for $t {
            fn hash64(&self) -> u64 {
                // fold to 64 bits, then a multiplicative hash whose high bits mix all of them
                let x = *self as u128;
                ((x >> 64) as u64 ^ x as u64).wrapping_mul(HASH_MULTIPLIER)
            }

            fn pack(face: &[u32], bits: u32) -> Self {
                face.iter().fold(0, |acc: $t, &v| (acc << bits) | <$t>::from(v))
            }

            fn for_each_face(&self, size: usize, bits: u32, mut f: impl FnMut(usize, Self)) {
                // dropping the vertex at p keeps the bits below its field and moves those
                // above it down by one field: `(key & low) | ((key >> bits) & !low)`, where
                // `low` covers the (size - 1 - p) fields after p
                let shifted = *self >> bits;
                let mut low = <$t>::MAX.checked_shr(<$t>::BITS - (size as u32 - 1) * bits).unwrap_or(0);
                for p in 0..size {
                    f(p, (*self & low) | (shifted & !low));
                    low >>= bits;
                }
            }

            fn unpack_into(&self, bits: u32, out: &mut [u32]) {
                let mask = <$t>::MAX >> (<$t>::BITS - bits);
                let mut key = *self;
                for slot in out.iter_mut().rev() {
                    *slot = (key & mask) as u32;
                    key = key.checked_shr(bits).unwrap_or(0);
                }
            }
        }
    };
}
packed_key!(u64);
packed_key!(u128);

impl FaceKey for Box<[u32]> {
    fn hash64(&self) -> u64 {
        self.iter().fold(0u64, |h, &v| (h.rotate_left(5) ^ u64::from(v)).wrapping_mul(HASH_MULTIPLIER))
    }

    fn pack(face: &[u32], _: u32) -> Self {
        face.into()
    }

    fn for_each_face(&self, size: usize, _: u32, mut f: impl FnMut(usize, Self)) {
        for p in 0..size {
            f(p, self.iter().enumerate().filter(|&(i, _)| i != p).map(|(_, &v)| v).collect());
        }
    }

    fn unpack_into(&self, _: u32, out: &mut [u32]) {
        out.copy_from_slice(self);
    }
}

/// Refuses `n` faces of `size` vertices when face numbers (`u32`, one value kept for "none")
/// might not hold them.
fn fits_u32(n: usize, size: usize) -> Result<(), FaceError> {
    if n < u32::MAX as usize {
        Ok(())
    } else {
        Err(FaceError::Matrix(format!("up to {n} faces of {size} vertices, past u32 indices")))
    }
}

/// The chain complex and the faces (flat, as in [`FaceComplex`]) of facets grouped by size
/// (`groups[s]`: the facets of `s` vertices, `s` increasing vertex indices each, end to end),
/// `top` the largest size (module docs). One pass per dimension, from the top down: the cells
/// of size `s` are the faces found from the cells of size `s + 1` followed by the facets of
/// size `s` not seen yet; dropping each vertex of each of them in turn gives its boundary
/// column and numbers the new faces of size `s - 1` on first sight.
fn enumerate<K: FaceKey>(
    groups: &[Vec<u32>],
    top: usize,
    bits: u32,
    labels: bool,
) -> Result<(ChainComplex, Vec<Vec<u32>>), FaceError> {
    // the faces of the current size by key (to join the facets of that size), and a second
    // table for the faces one size down: the two swap at each step, so their memory is reused
    let mut index = FaceIndex::new();
    let mut below = FaceIndex::new();
    // the cells of the current size and the faces found one size down, in order: they swap too
    let mut cells: Vec<K> = Vec::new();
    let mut keys: Vec<K> = Vec::new();
    let mut columns = Vec::with_capacity(top - 1);
    let mut flat: Vec<Vec<u32>> = vec![Vec::new(); top];
    let mut counts = vec![0; top];
    // cofaces per face, to size the table of the faces one size down: a ridge of the top
    // cells lies in two of them inside a pseudo-manifold and in one on its boundary; lower
    // faces have more cofaces, so the ratio a step finds overestimates the next step's faces
    // (the table grows if an estimate falls short)
    let mut share = (3.0, 2.0);
    for size in (1..=top).rev() {
        let joining = groups[size].len() / size;
        if joining > 0 {
            fits_u32(keys.len() + joining, size)?;
            if size == top {
                index.reset(joining);
            }
            for g in groups[size].chunks_exact(size) {
                index.find_or_insert(K::pack(g, bits), &mut keys);
            }
        }
        std::mem::swap(&mut cells, &mut keys);
        keys.clear();
        counts[size - 1] = cells.len();
        if labels {
            let out = &mut flat[size - 1];
            out.resize(cells.len() * size, 0);
            for (key, slot) in cells.iter().zip(out.chunks_exact_mut(size)) {
                key.unpack_into(bits, slot);
            }
        }
        if size == 1 {
            break;
        }
        // the faces one size down, numbered on first sight
        let expected = ((cells.len() * size) as f64 * share.1 / share.0) as usize;
        fits_u32(cells.len() * size, size - 1)?;
        below.reset(expected);
        keys.reserve(expected);
        // each column holds exactly `size` entries: the faces of a simplex are distinct
        let col_ptr: Vec<usize> = (0..=cells.len()).map(|j| j * size).collect();
        let mut row_idx = vec![0u32; cells.len() * size];
        let mut vals = vec![0i64; cells.len() * size];
        for ((key, rows), signs) in cells.iter().zip(row_idx.chunks_exact_mut(size)).zip(vals.chunks_exact_mut(size)) {
            key.for_each_face(size, bits, |p, face| {
                let row = below.find_or_insert(face, &mut keys);
                // insertion into the sorted column
                let mut at = p;
                while at > 0 && rows[at - 1] > row {
                    rows[at] = rows[at - 1];
                    signs[at] = signs[at - 1];
                    at -= 1;
                }
                rows[at] = row;
                signs[at] = if p % 2 == 0 { 1 } else { -1 };
            });
        }
        // cofaces per face at this step, as a fraction (entries, faces)
        share = ((cells.len() * size) as f64, keys.len().max(1) as f64);
        // the rows are known once the facets of size `size - 1` join, at the next step
        columns.push((cells.len(), col_ptr, row_idx, vals));
        std::mem::swap(&mut index, &mut below);
    }
    let mut boundaries = Vec::with_capacity(top - 1);
    for (k, (cols, col_ptr, row_idx, vals)) in columns.into_iter().rev().enumerate() {
        // rows strictly increasing per column (distinct faces, sorted), below the number of
        // faces found, values ±1
        boundaries.push(SparseMatrix::from_csc_trusted(counts[k], cols, col_ptr, row_idx, vals));
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
    face_complex_of(facets.iter().map(AsRef::as_ref), limit, true)
}

/// [`face_complex`] of facets given by an iterator, which is walked a few times (so a
/// complex that holds its facets end to end needs no list of them). Same errors; a facet's
/// number is its position in the iteration. Without `labels`, [`FaceComplex::faces`] is left
/// empty (one vector per dimension): what only needs the groups saves writing the vertices
/// of every face.
pub fn face_complex_of<'a, I>(facets: I, limit: u64, labels: bool) -> Result<FaceComplex, FaceError>
where
    I: Iterator<Item = &'a [u64]> + Clone,
{
    let estimate = face_estimate(facets.clone());
    if facets.clone().next().is_none() {
        return Err(FaceError::Empty);
    }
    match estimate {
        Some(e) if e <= limit => {}
        _ => return Err(FaceError::TooManyFaces { estimate, limit }),
    }
    // renumber the labels 0..V: by a table when the labels are small (the usual 1..V), else
    // by binary search among the sorted labels
    let (mut entries, mut largest) = (0usize, 0u64);
    for f in facets.clone() {
        entries += f.len();
        largest = f.iter().copied().fold(largest, u64::max);
    }
    let (vertices, table) = if largest < 2 * entries as u64 + 1024 {
        // mark the labels present, then number them in increasing order: no sort
        let mut table = vec![u32::MAX; largest as usize + 1];
        for f in facets.clone() {
            for &v in f {
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
        let mut vertices: Vec<u64> = facets.clone().flat_map(|f| f.iter().copied()).collect();
        vertices.sort_unstable();
        vertices.dedup();
        (vertices, None)
    };
    let index_of = |v: &u64| match &table {
        Some(t) => t[*v as usize],
        None => vertices.binary_search(v).expect("label collected above") as u32,
    };
    // the facets grouped by size, as increasing vertex indices end to end
    let mut sizes = vec![0usize; 2];
    for f in facets.clone() {
        let m = f.len();
        if m >= sizes.len() {
            sizes.resize(m + 1, 0);
        }
        sizes[m] += m;
    }
    let mut groups: Vec<Vec<u32>> = sizes.iter().map(|&n| Vec::with_capacity(n)).collect();
    let mut top = 0;
    for (i, f) in facets.enumerate() {
        let g = &mut groups[f.len()];
        let start = g.len();
        g.extend(f.iter().map(index_of));
        let g = &mut g[start..];
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
    }
    if top == 0 {
        // only empty facets: no face at all
        return Err(FaceError::Empty);
    }
    let bits = (32 - (vertices.len().saturating_sub(1) as u32).leading_zeros()).max(1);
    let (chain, faces) = if bits as usize * top <= 64 {
        enumerate::<u64>(&groups, top, bits, labels)?
    } else if bits as usize * top <= 128 {
        enumerate::<u128>(&groups, top, bits, labels)?
    } else {
        enumerate::<Box<[u32]>>(&groups, top, bits, labels)?
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
        // the same chain complex without the labels
        let bare = face_complex_of(f.iter().map(Vec::as_slice), 1000, false).unwrap();
        assert_eq!(bare.chain.boundaries(), fc.chain.boundaries());
        assert!(bare.faces.iter().all(Vec::is_empty) && bare.faces.len() == 3);
        assert_eq!(face_complex(&[vec![1, 2, 2]], 100).unwrap_err(), FaceError::RepeatedVertex { facet: 0, vertex: 2 });
        assert_eq!(
            face_complex(&[vec![1, 2, 3]], 6).unwrap_err(),
            FaceError::TooManyFaces { estimate: Some(7), limit: 6 }
        );
        assert_eq!(face_estimate([&[0u64; 64][..]]), None);
    }

    /// The key of `face` without its vertex at position `p`, through `for_each_face`.
    fn face_at<K: FaceKey>(face: &[u32], p: usize, bits: u32) -> K {
        let mut out = None;
        K::pack(face, bits).for_each_face(face.len(), bits, |q, f| {
            if q == p {
                out = Some(f);
            }
        });
        out.unwrap()
    }

    #[test]
    fn packed_keys_drop_each_vertex_at_full_width() {
        // 8 vertices of 8 bits fill a u64; 16 of 8 bits fill a u128: dropping the first
        // vertex shifts by the whole width
        let face: Vec<u32> = (0..8).map(|i| 200 + i).collect();
        let wide: Vec<u32> = (0..16).map(|i| 100 + 9 * i).collect();
        for p in 0..8 {
            let want: Vec<u32> = face.iter().enumerate().filter(|&(i, _)| i != p).map(|(_, &v)| v).collect();
            let mut got = vec![0; 7];
            face_at::<u64>(&face, p, 8).unpack_into(8, &mut got);
            assert_eq!(got, want, "u64, p = {p}");
        }
        for p in 0..16 {
            let want: Vec<u32> = wide.iter().enumerate().filter(|&(i, _)| i != p).map(|(_, &v)| v).collect();
            let mut got = vec![0; 15];
            face_at::<u128>(&wide, p, 8).unpack_into(8, &mut got);
            assert_eq!(got, want, "u128, p = {p}");
            let mut flat = vec![0; 15];
            face_at::<Box<[u32]>>(&wide, p, 8).unpack_into(8, &mut flat);
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
