//! [`DenseMap`]: the compact, flat snapshot that analysis runs on.
//!
//! Darts are numbered `0..N` and involutions are stored row by row in one `Vec<u32>`
//! of length `(n + 1) * N`: `alpha[d * (n + 1) + i]` is `alpha_i(d)`. A dart equal to
//! its own image under `alpha_i` is i-free. Every whole-map algorithm (validation,
//! orbit partitions, cell counts, components, orientation, compacted cells) is a
//! linear pass or a marks-based traversal over this array, with an explicit stack:
//! nothing recurses, so maps of millions of darts are safe.

use bitvec::vec::BitVec;

use crate::alpha::{AlphaSet, MAX_DIM};
use crate::error::{BoundaryDefect, CellDefect, DartError, OrientationConflict, ValidityError};
use crate::ids::{CellId, Dart, Point};

/// Marker value of an unassigned entry in a [`Partition`] under construction.
const UNSET: u32 = u32::MAX;

/// A partition of the darts into orbits: `of[d]` is the orbit number of dart `d`,
/// numbered `0..reps.len()` in the order of their smallest dart, and `reps[k]` is
/// the smallest dart of orbit `k`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Partition {
    /// orbit number of each dart
    pub of: Vec<u32>,
    /// smallest dart of each orbit
    pub reps: Vec<Dart>,
}

impl Partition {
    /// Number of orbits.
    pub fn len(&self) -> usize {
        self.reps.len()
    }

    /// The orbit (cell) of dart `d`.
    #[inline]
    pub fn cell_of(&self, d: Dart) -> CellId {
        CellId::new(self.of[d.index()])
    }

    /// The smallest dart of orbit `c`.
    #[inline]
    pub fn rep(&self, c: CellId) -> Dart {
        self.reps[c.index()]
    }

    /// The orbits' numbers, `0..len`.
    pub fn cell_ids(&self) -> impl Iterator<Item = CellId> {
        (0..self.reps.len() as u32).map(CellId::new)
    }

    /// Whether there is no orbit (the map has no dart).
    pub fn is_empty(&self) -> bool {
        self.reps.is_empty()
    }

    /// The darts of each orbit, as a CSR structure: `(offsets, darts)` with the darts of
    /// orbit `k` in `darts[offsets[k]..offsets[k + 1]]`, increasing. O(N).
    pub fn members(&self) -> (Vec<usize>, Vec<u32>) {
        let mut offsets = vec![0usize; self.reps.len() + 1];
        for &k in &self.of {
            offsets[k as usize + 1] += 1;
        }
        for k in 0..self.reps.len() {
            offsets[k + 1] += offsets[k];
        }
        let mut fill = offsets.clone();
        let mut darts = vec![0u32; self.of.len()];
        for (d, &k) in self.of.iter().enumerate() {
            darts[fill[k as usize]] = d as u32;
            fill[k as usize] += 1;
        }
        (offsets, darts)
    }
}

/// A kernel's oriented cells `(cell of each dart, smallest darts, colour words)` of a map of
/// `n` darts as a partition and a bit per dart.
fn oriented_parts((of, reps, words): (Vec<u32>, Vec<Dart>, Vec<usize>), n: usize) -> (Partition, BitVec) {
    let mut pos: BitVec = BitVec::from_vec(words);
    pos.truncate(n);
    (Partition { of, reps }, pos)
}

/// The oriented cells of every dimension of a 3-map, from [`DenseMap::oriented_cells_3d`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OrientedCells3d {
    /// `cells[i]`: the i-cells and the colour of each dart in its compacted i-cell, as
    /// [`DenseMap::oriented_cells`] gives them
    pub cells: Vec<(Partition, BitVec)>,
    /// the Euler characteristic of the boundary surface of each volume (volumes numbered as
    /// in `cells[3]`)
    pub euler: Vec<i64>,
}

/// An n-dimensional generalized map with darts `0..N` in flat arrays (BO Def. 1).
///
/// Build one with [`DenseMap::new`] and [`DenseMap::link`], or from raw rows with
/// [`DenseMap::try_from_flat`]; turn it into an editable [`crate::GMap`] with
/// [`crate::GMap::from_dense`]. Operations that may break the axioms (`link`,
/// `unlink`, `from_flat_unchecked`) say so; [`DenseMap::validate`] checks them.
#[derive(Clone, Debug)]
pub struct DenseMap {
    dim: usize,
    alpha: Vec<u32>,
    /// the index in `table` of each dart's point (`NO_POINT`: none); empty while no dart
    /// has a point. Darts of one vertex share an index when the map is made from a
    /// [`crate::GMap`]: 4 bytes a dart and 24 a vertex, not 32 bytes a dart.
    points: Vec<u32>,
    table: Vec<Point>,
}

/// The point index of a dart without a point.
const NO_POINT: u32 = u32::MAX;

/// Two maps are equal when they have the same dimension, the same involutions dart by dart
/// and the same point on every dart (a map without points equals one whose points are all
/// `None`).
impl PartialEq for DenseMap {
    fn eq(&self, other: &Self) -> bool {
        self.dim == other.dim
            && self.alpha == other.alpha
            && (0..self.dart_count()).all(|d| self.point(Dart::new(d as u32)) == other.point(Dart::new(d as u32)))
    }
}

impl DenseMap {
    /// A map of dimension `dim` with `darts` darts, all of them free for every involution.
    ///
    /// Panics if `dim > MAX_DIM` or `darts >= u32::MAX`; see [`DenseMap::try_new`].
    pub fn new(dim: usize, darts: usize) -> Self {
        Self::try_new(dim, darts).expect("DenseMap::new")
    }

    /// A map of `darts` free darts, or an error for a dimension or size out of range, or for
    /// memory that cannot be had (reserved fallibly: an error, not an abort).
    pub fn try_new(dim: usize, darts: usize) -> Result<Self, ValidityError> {
        if dim > MAX_DIM {
            return Err(ValidityError::DimensionTooLarge(dim));
        }
        if darts >= u32::MAX as usize {
            return Err(ValidityError::TooManyDarts(darts));
        }
        let w = dim + 1;
        let mut alpha = Vec::new();
        alpha.try_reserve_exact(w * darts).map_err(|_| ValidityError::OutOfMemory { darts })?;
        for d in 0..darts {
            alpha.extend(std::iter::repeat_n(d as u32, w));
        }
        Ok(DenseMap { dim, alpha, points: Vec::new(), table: Vec::new() })
    }

    /// A map from its rows, `alpha[d * (dim + 1) + i] = alpha_i(d)`, validated (BO Def. 1).
    pub fn try_from_flat(dim: usize, alpha: Vec<u32>) -> Result<Self, ValidityError> {
        let m = Self::from_flat_unchecked(dim, alpha)?;
        m.validate()?;
        Ok(m)
    }

    /// A map from its rows without checking the involution axioms (only the sizes: an array
    /// whose length is not a multiple of `dim + 1` is refused with
    /// [`ValidityError::RaggedRows`]).
    /// The result may be invalid; call [`DenseMap::validate`] before relying on it.
    pub fn from_flat_unchecked(dim: usize, alpha: Vec<u32>) -> Result<Self, ValidityError> {
        if dim > MAX_DIM {
            return Err(ValidityError::DimensionTooLarge(dim));
        }
        let w = dim + 1;
        if !alpha.len().is_multiple_of(w) {
            return Err(ValidityError::RaggedRows { len: alpha.len(), width: w });
        }
        let darts = alpha.len() / w;
        if darts >= u32::MAX as usize {
            return Err(ValidityError::TooManyDarts(darts));
        }
        Ok(DenseMap { dim, alpha, points: Vec::new(), table: Vec::new() })
    }

    /// The dimension n.
    #[inline]
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The number of darts N.
    #[inline]
    pub fn dart_count(&self) -> usize {
        self.alpha.len() / (self.dim + 1)
    }

    /// Whether the map has no dart.
    pub fn is_empty(&self) -> bool {
        self.alpha.is_empty()
    }

    /// All darts, in increasing order.
    pub fn darts(&self) -> impl Iterator<Item = Dart> {
        (0..self.dart_count() as u32).map(Dart::new)
    }

    /// The flat involution array (row-major, `dim + 1` entries per dart).
    #[inline]
    pub fn flat(&self) -> &[u32] {
        &self.alpha
    }

    /// The row `alpha_0(d), …, alpha_n(d)` of dart `d`.
    ///
    /// # Panics
    /// If `d` is not a dart of the map.
    #[inline]
    #[track_caller]
    pub fn row(&self, d: Dart) -> &[u32] {
        let w = self.dim + 1;
        if (d.index() + 1) * w > self.alpha.len() {
            self.refuse(DartError::NoSuchDart { dart: d, darts: self.dart_count() });
        }
        &self.alpha[d.index() * w..(d.index() + 1) * w]
    }

    /// Checks that `d` is a dart of the map and `i <= n`.
    #[inline]
    fn check(&self, d: Dart, i: usize) -> Result<(), DartError> {
        if d.index() >= self.dart_count() {
            return Err(DartError::NoSuchDart { dart: d, darts: self.dart_count() });
        }
        if i > self.dim {
            return Err(DartError::BadIndex { dart: d, alpha: i, dim: self.dim });
        }
        Ok(())
    }

    /// The panic of the panicking forms, out of the hot paths.
    #[cold]
    #[inline(never)]
    #[track_caller]
    fn refuse(&self, e: DartError) -> ! {
        panic!("{e}")
    }

    /// `alpha_i(d)`.
    ///
    /// # Panics
    /// If `d` is not a dart of the map or `i > n`; [`DenseMap::try_alpha`] returns the error.
    #[inline]
    #[track_caller]
    pub fn alpha(&self, d: Dart, i: usize) -> Dart {
        let w = self.dim + 1;
        let k = d.index() * w + i;
        if i < w && k < self.alpha.len() {
            Dart::new(self.alpha[k])
        } else {
            self.refuse(self.check(d, i).expect_err("out of range"))
        }
    }

    /// `alpha_i(d)`, or an error naming the dart or the index that does not exist.
    #[inline]
    pub fn try_alpha(&self, d: Dart, i: usize) -> Result<Dart, DartError> {
        self.check(d, i)?;
        Ok(Dart::new(self.alpha[d.index() * (self.dim + 1) + i]))
    }

    /// Whether `d` is i-free (a fixed point of `alpha_i`).
    ///
    /// # Panics
    /// Like [`DenseMap::alpha`].
    #[inline]
    #[track_caller]
    pub fn is_free(&self, d: Dart, i: usize) -> bool {
        self.alpha(d, i) == d
    }

    /// Appends `k` darts free for every involution; returns the first new dart.
    ///
    /// # Panics
    /// If the map would have more than `u32::MAX - 1` darts; [`DenseMap::try_add_darts`]
    /// returns the error.
    #[track_caller]
    pub fn add_darts(&mut self, k: usize) -> Dart {
        match self.try_add_darts(k) {
            Ok(d) => d,
            Err(e) => self.refuse(e),
        }
    }

    /// Appends `k` darts free for every involution and returns the first new dart, or refuses
    /// (changing nothing) when the map would have more than `u32::MAX - 1` darts, the most a
    /// `u32` dart index names (see [`DenseMap::try_new`]), or when the memory cannot be had.
    pub fn try_add_darts(&mut self, k: usize) -> Result<Dart, DartError> {
        let first = self.dart_count();
        let too_many = DartError::TooManyDarts { darts: first, adding: k };
        match first.checked_add(k) {
            Some(t) if t < u32::MAX as usize => {}
            _ => return Err(too_many),
        }
        let w = self.dim + 1;
        let entries = k.checked_mul(w).ok_or_else(|| too_many.clone())?;
        self.alpha.try_reserve(entries).map_err(|_| too_many.clone())?;
        if !self.points.is_empty() {
            self.points.try_reserve(k).map_err(|_| too_many)?;
        }
        for d in first..first + k {
            for _ in 0..w {
                self.alpha.push(d as u32);
            }
        }
        if !self.points.is_empty() {
            self.points.resize(first + k, NO_POINT);
        }
        Ok(Dart::new(first as u32))
    }

    /// Low-level: sets `alpha_i(d) = e` and `alpha_i(e) = d` (first making their former
    /// partners i-free). Keeps `alpha_i` an involution but may break the
    /// `alpha_i alpha_j` condition of BO Def. 1: callers re-validate. `d == e` frees `d`.
    ///
    /// # Panics
    /// If `d` or `e` is not a dart of the map or `i > n` (nothing is changed then);
    /// [`DenseMap::try_link`] returns the error.
    #[track_caller]
    pub fn link(&mut self, d: Dart, e: Dart, i: usize) {
        if let Err(err) = self.try_link(d, e, i) {
            self.refuse(err)
        }
    }

    /// [`DenseMap::link`], or an error (and no change) when a dart or the index does not exist.
    pub fn try_link(&mut self, d: Dart, e: Dart, i: usize) -> Result<(), DartError> {
        self.check(d, i)?;
        self.check(e, i)?;
        self.unlink_unchecked(d, i);
        self.unlink_unchecked(e, i);
        let w = self.dim + 1;
        self.alpha[d.index() * w + i] = e.get();
        self.alpha[e.index() * w + i] = d.get();
        Ok(())
    }

    /// Low-level: makes `d` and its `alpha_i` partner i-free. May break validity.
    ///
    /// # Panics
    /// If `d` is not a dart of the map or `i > n`; [`DenseMap::try_unlink`] returns the error.
    #[track_caller]
    pub fn unlink(&mut self, d: Dart, i: usize) {
        if let Err(err) = self.try_unlink(d, i) {
            self.refuse(err)
        }
    }

    /// [`DenseMap::unlink`], or an error (and no change) when the dart or the index does not
    /// exist.
    pub fn try_unlink(&mut self, d: Dart, i: usize) -> Result<(), DartError> {
        self.check(d, i)?;
        self.unlink_unchecked(d, i);
        Ok(())
    }

    /// `unlink` for a dart and an index already checked.
    fn unlink_unchecked(&mut self, d: Dart, i: usize) {
        let w = self.dim + 1;
        let e = self.alpha[d.index() * w + i] as usize;
        self.alpha[d.index() * w + i] = d.get();
        if e < self.dart_count() && self.alpha[e * w + i] == d.get() {
            self.alpha[e * w + i] = e as u32;
        }
    }

    /// Whether any dart carries a point.
    pub fn has_points(&self) -> bool {
        self.points.iter().any(|&k| k != NO_POINT)
    }

    /// The point attached to dart `d`, if any.
    pub fn point(&self, d: Dart) -> Option<Point> {
        self.points.get(d.index()).and_then(|&k| self.table.get(k as usize)).copied()
    }

    /// Attaches a point to dart `d` (the position of its 0-cell).
    ///
    /// # Panics
    /// If `d` is not a dart of the map.
    #[track_caller]
    pub fn set_point(&mut self, d: Dart, p: Option<Point>) {
        if d.index() >= self.dart_count() {
            self.refuse(DartError::NoSuchDart { dart: d, darts: self.dart_count() });
        }
        if self.points.is_empty() {
            if p.is_none() {
                return;
            }
            self.points.resize(self.dart_count(), NO_POINT);
        }
        self.points[d.index()] = match p {
            Some(p) => {
                self.table.push(p);
                (self.table.len() - 1) as u32
            }
            None => NO_POINT,
        };
    }

    /// Gives the darts their points from a table: the dart `d` takes `table[index[d]]`
    /// (`u32::MAX`: no point); darts may share an index. Crate-internal: the indices are the
    /// caller's (in range, one per dart).
    pub(crate) fn set_point_table(&mut self, index: Vec<u32>, table: Vec<Point>) {
        debug_assert_eq!(index.len(), self.dart_count());
        self.points = index;
        self.table = table;
    }

    /// The point of the 0-cell of `d`: the first point found on a dart of that vertex.
    pub fn vertex_point(&self, d: Dart) -> Option<Point> {
        if self.points.is_empty() {
            return None;
        }
        self.orbit(d, AlphaSet::cell(0, self.dim)).into_iter().find_map(|x| self.point(x))
    }

    /// Checks all of BO Def. 1: every link in range, every `alpha_i` an involution, and
    /// `alpha_i alpha_j` an involution for `j >= i + 2`. Reports the first violation in
    /// dart order. O(N n^2), on two threads for big maps.
    pub fn validate(&self) -> Result<(), ValidityError> {
        let w = self.dim + 1;
        // the fused check (one pass, two threads on big maps) decides; the detailed pass
        // below only runs to name the first violation
        if crate::kernels::is_valid(&self.alpha, w) {
            return Ok(());
        }
        let n = self.dart_count();
        let a = &self.alpha;
        for d in 0..n {
            let row = &a[d * w..(d + 1) * w];
            for (i, &e) in row.iter().enumerate() {
                if e as usize >= n {
                    return Err(ValidityError::OutOfRange {
                        dart: Dart::new(d as u32),
                        alpha: i,
                        target: Dart::new(e),
                        darts: n,
                    });
                }
                let back = a[e as usize * w + i];
                if back as usize != d {
                    return Err(ValidityError::NotInvolution {
                        dart: Dart::new(d as u32),
                        alpha: i,
                        image: Dart::new(e),
                        back: Dart::new(back),
                    });
                }
            }
        }
        for d in 0..n {
            for i in 0..w {
                for j in i + 2..w {
                    let x = a[d * w + i] as usize;
                    let x = a[x * w + j] as usize;
                    let x = a[x * w + i] as usize;
                    let x = a[x * w + j];
                    if x as usize != d {
                        return Err(ValidityError::NotCommuting {
                            dart: Dart::new(d as u32),
                            i,
                            j,
                            image: Dart::new(x),
                        });
                    }
                }
            }
        }
        Ok(())
    }

    /// Whether [`DenseMap::validate`] succeeds (CGAL's `is_valid`).
    pub fn is_valid(&self) -> bool {
        self.validate().is_ok()
    }

    /// The darts of the i-cell of `d` (BO Def. 2), in breadth-first order from `d`.
    /// O(cell size × n).
    pub fn cell_darts(&self, d: Dart, i: usize) -> Vec<Dart> {
        self.orbit(d, AlphaSet::cell(i, self.dim))
    }

    /// The darts of the orbit `<set>(d)`, in traversal order starting with `d`.
    /// O(size of the orbit) time, O(N) bits of scratch.
    pub fn orbit(&self, d: Dart, set: AlphaSet) -> Vec<Dart> {
        let mut seen: BitVec = BitVec::repeat(false, self.dart_count());
        self.orbit_with(d, set, &mut seen)
    }

    /// Like [`DenseMap::orbit`], reusing a caller's visited bits: darts of the orbit are set
    /// in `seen` (which must be at least N long) and are left set on return.
    pub fn orbit_with(&self, d: Dart, set: AlphaSet, seen: &mut BitVec) -> Vec<Dart> {
        let idx: Vec<usize> = set.iter().filter(|&i| i <= self.dim).collect();
        let w = self.dim + 1;
        let mut out = vec![d];
        seen.set(d.index(), true);
        let mut k = 0;
        while k < out.len() {
            let x = out[k].index();
            k += 1;
            for &i in &idx {
                let y = self.alpha[x * w + i];
                if !seen[y as usize] {
                    seen.set(y as usize, true);
                    out.push(Dart::new(y));
                }
            }
        }
        out
    }

    /// Partitions the darts into `<set>`-orbits, numbered in order of smallest dart. A
    /// union-find over one sequential scan of the links (most of them close by in memory)
    /// for dimensions up to 7, a traversal above. O(N |set| α(N)).
    pub fn partition(&self, set: AlphaSet) -> Partition {
        let w = self.dim + 1;
        let mask = set.bits() & AlphaSet::all(self.dim).bits();
        if let Some((of, reps)) = crate::kernels::partition(&self.alpha, w, mask) {
            return Partition { of, reps };
        }
        let idx: Vec<usize> = set.iter().filter(|&i| i <= self.dim).collect();
        let n = self.dart_count();
        let a = &self.alpha;
        let mut of = vec![UNSET; n];
        let mut reps = Vec::new();
        let mut stack: Vec<u32> = Vec::new();
        for d in 0..n {
            if of[d] != UNSET {
                continue;
            }
            let id = reps.len() as u32;
            reps.push(Dart::new(d as u32));
            of[d] = id;
            stack.push(d as u32);
            while let Some(x) = stack.pop() {
                let row = &a[x as usize * w..x as usize * w + w];
                for &i in &idx {
                    let y = row[i];
                    // SAFETY-free indexing: `y < n` holds for a valid map; an invalid one panics
                    // here with an index error, so callers validate first.
                    if of[y as usize] == UNSET {
                        of[y as usize] = id;
                        stack.push(y);
                    }
                }
            }
        }
        Partition { of, reps }
    }

    /// The i-cells (BO Def. 2): orbits of every involution but `alpha_i`.
    pub fn cells(&self, i: usize) -> Partition {
        assert!(i <= self.dim, "cell dimension {i} > map dimension {}", self.dim);
        self.partition(AlphaSet::cell(i, self.dim))
    }

    /// Number of i-cells.
    pub fn cell_count(&self, i: usize) -> usize {
        self.count_orbits(AlphaSet::cell(i, self.dim))
    }

    /// Number of `<set>`-orbits, without keeping the partition. O(N |set|) time, N bits
    /// of scratch.
    pub fn count_orbits(&self, set: AlphaSet) -> usize {
        crate::kernels::count_orbits(&self.alpha, self.dim + 1, set.bits() & AlphaSet::all(self.dim).bits())
    }

    /// Numbers of cells of every dimension `0..=n`. O(N n^2), on two threads for big maps.
    pub fn cell_counts(&self) -> Vec<usize> {
        let masks: Vec<u32> = (0..=self.dim).map(|i| AlphaSet::cell(i, self.dim).bits()).collect();
        crate::kernels::count_orbits_many(&self.alpha, self.dim + 1, &masks)
    }

    /// The numbers of cells of every dimension and the number of connected components,
    /// computed together (on two threads for big maps). O(N n^2).
    pub fn cell_counts_and_components(&self) -> (Vec<usize>, usize) {
        crate::kernels::counts_and_components(&self.alpha, self.dim + 1)
    }

    /// Euler characteristic: the alternating sum of the cell counts.
    pub fn euler_characteristic(&self) -> i64 {
        self.cell_counts().iter().enumerate().map(|(i, &c)| if i % 2 == 0 { c as i64 } else { -(c as i64) }).sum()
    }

    /// The connected components: orbits of all involutions.
    pub fn components(&self) -> Partition {
        self.partition(AlphaSet::all(self.dim))
    }

    /// Number of connected components.
    pub fn component_count(&self) -> usize {
        self.count_orbits(AlphaSet::all(self.dim))
    }

    /// Orientation classes (BO Def. 7, 8): a bit per dart, set for the positive class,
    /// where the smallest dart of each component is positive and `alpha_i` changes the
    /// class of every dart it does not fix. Fails with the first conflict found.
    pub fn orientation(&self) -> Result<BitVec, OrientationConflict> {
        let col = crate::kernels::orientation(&self.alpha, self.dim + 1)?;
        Ok(col.iter().map(|&c| c == 1).collect())
    }

    /// Whether the map is orientable (BO Def. 7). O(N n).
    pub fn is_orientable(&self) -> bool {
        crate::kernels::is_orientable(&self.alpha, self.dim + 1)
    }

    /// Checks BO Def. 6 (cells with complete boundary): no fixed point of `alpha_i` for
    /// `i < n` (the first free dart, in dart order, is named), and no self-bending
    /// ([`DenseMap::check_no_self_bending`]). O(N n^2).
    pub fn check_complete_boundaries(&self) -> Result<(), BoundaryDefect> {
        let n = self.dim;
        for d in self.darts() {
            for i in 0..n {
                if self.is_free(d, i) {
                    return Err(BoundaryDefect::Free { dart: d, alpha: i });
                }
            }
        }
        self.check_no_self_bending()
    }

    /// Checks the second part of BO Def. 6: no self-bending, that is, for every dart `d`
    /// and every `i`, the orbits `<alpha_{i+1}..alpha_n>(d)` and `<alpha_0..alpha_{i-1}>(d)`
    /// meet in `d` alone. Where they meet in a second dart, the i-cell of `d` is folded
    /// onto itself (a square face of a volume sewn to itself by a half-turn, an edge sewn
    /// to itself reversed); the error names the lowest such `i`, the smallest dart `d` with
    /// a second dart in both orbits, that second dart (the smallest one), and the i-cell.
    ///
    /// Only `1 <= i <= n - 1` can fail (for `i = 0` and `i = n` one orbit is `{d}`). Where
    /// one of the two orbits is a single involution's (`i = 1`: `{d, alpha_0(d)}`;
    /// `i = n - 1`: `{d, alpha_n(d)}`), one partition decides; otherwise the darts are
    /// grouped by their `<alpha_{i+1}..alpha_n>`-orbit and two darts of a group must lie
    /// in different `<alpha_0..alpha_{i-1}>`-orbits. O(N n^2) (the partitions); no sort.
    ///
    /// ```
    /// use gmap_core::{Dart, DenseMap};
    /// // a square (8 darts, alpha_0 and alpha_1 alternating) as the face of a 3-map,
    /// // sewn to itself by alpha_3 with a half-turn: dart d meets dart d + 4
    /// let mut m = DenseMap::new(3, 8);
    /// for d in (0..8).step_by(2) {
    ///     m.link(Dart::new(d), Dart::new(d + 1), 0);
    ///     m.link(Dart::new(d + 1), Dart::new((d + 2) % 8), 1);
    /// }
    /// assert!(m.check_no_self_bending().is_ok());
    /// for d in 0..4 {
    ///     m.link(Dart::new(d), Dart::new(d + 4), 3);
    /// }
    /// assert!(m.validate().is_ok());
    /// let e = m.check_no_self_bending().unwrap_err();
    /// assert!(e.to_string().starts_with("the 2-cell of dart 0 is folded onto itself"), "{e}");
    /// ```
    pub fn check_no_self_bending(&self) -> Result<(), BoundaryDefect> {
        let n = self.dim;
        let count = self.dart_count();
        for i in 1..n {
            // the smallest dart with a second dart in both orbits, and that second dart
            let mut found: Option<(u32, u32)> = None;
            if i == 1 || i == n - 1 {
                // one side is `{d, alpha_j(d)}`: the pair meets again iff `alpha_j(d) != d`
                // lies in the other side's orbit of `d`
                let (j, other) = if i == 1 { (0, AlphaSet::above(1, n)) } else { (n, AlphaSet::below(n - 1)) };
                let p = self.partition(other);
                for d in 0..count {
                    let e = self.alpha[d * (n + 1) + j] as usize;
                    if e != d && p.of[d] == p.of[e] {
                        found = Some((d.min(e) as u32, d.max(e) as u32));
                        break;
                    }
                }
            } else {
                let up = self.partition(AlphaSet::above(i, n));
                let down = self.partition(AlphaSet::below(i));
                // darts grouped by up-orbit (a counting sort, dart order kept in each group)
                let mut start = vec![0u32; up.len() + 1];
                for &u in &up.of {
                    start[u as usize + 1] += 1;
                }
                for k in 0..up.len() {
                    start[k + 1] += start[k];
                }
                let mut next = start.clone();
                let mut order = vec![0u32; count];
                for (d, &u) in up.of.iter().enumerate() {
                    order[next[u as usize] as usize] = d as u32;
                    next[u as usize] += 1;
                }
                // first[down orbit] = (group, first dart of the group in that orbit)
                let mut first = vec![(u32::MAX, 0u32); down.len()];
                for g in 0..up.len() {
                    for &d in &order[start[g] as usize..start[g + 1] as usize] {
                        let slot = &mut first[down.of[d as usize] as usize];
                        if slot.0 == g as u32 {
                            if found.is_none_or(|f| (slot.1, d) < f) {
                                found = Some((slot.1, d));
                            }
                        } else {
                            *slot = (g as u32, d);
                        }
                    }
                }
            }
            if let Some((d, other)) = found {
                let cell = self.orbit(Dart::new(d), AlphaSet::cell(i, n)).into_iter().min().unwrap_or(Dart::new(d));
                return Err(BoundaryDefect::SelfBending { dart: Dart::new(d), i, other: Dart::new(other), cell });
            }
        }
        Ok(())
    }

    /// Whether no cell is folded onto itself (BO Def. 6, part 2); see
    /// [`DenseMap::check_no_self_bending`].
    pub fn has_no_self_bending(&self) -> bool {
        self.check_no_self_bending().is_ok()
    }

    /// Whether the map has cells with complete boundaries (BO Def. 6).
    pub fn has_complete_boundaries(&self) -> bool {
        self.check_complete_boundaries().is_ok()
    }

    /// Orients every i-cell as a compacted cell (condition C1, docs/DESIGN.md): a bit per dart,
    /// set for the positive class, such that `alpha_k` flips the class for `k < i` and
    /// `alpha_j` keeps it for `j > i`; the smallest dart of each i-cell is positive.
    /// Fails, naming the cell, where a dart is k-free for some `k < i` or the colouring
    /// conflicts (a non-orientable or folded cell).
    pub fn cell_orientation(&self, i: usize) -> Result<BitVec, CellDefect> {
        self.oriented_cells(i).map(|(_, positive)| positive)
    }

    /// The i-cells and their orientation as compacted cells, from one traversal: the
    /// partition numbers the cells as [`DenseMap::cells`] does, and the bits are those of
    /// [`DenseMap::cell_orientation`]. Fails like `cell_orientation`. O(N n).
    pub fn oriented_cells(&self, i: usize) -> Result<(Partition, BitVec), CellDefect> {
        assert!(i <= self.dim, "cell dimension {i} > map dimension {}", self.dim);
        let n = self.dart_count();
        crate::kernels::oriented_cells(&self.alpha, self.dim + 1, i).map(|cells| oriented_parts(cells, n))
    }

    /// The oriented cells of every dimension of a 3-map and the Euler characteristic of the
    /// boundary surface of each volume, in one O(N) pass per dimension that walks each cell
    /// along its rings (faces: two `<alpha_0, alpha_1>`-rings; edges: an
    /// `<alpha_2, alpha_3>`-orbit and its `alpha_0`-image; vertices: corners joined by
    /// `alpha_3`) instead of following every involution from every dart. Entry `i` equals
    /// [`DenseMap::oriented_cells`]`(i)`; `euler[v]` is, for volume `v`, its corners minus its
    /// edge sides plus its face sides (2 exactly when C2 holds for it, given C1).
    ///
    /// `None` when the map is not of dimension 3 or some cell is not of these shapes: a dart
    /// free for `alpha_0`, `alpha_1` or `alpha_2`, a folded face or edge, a non-orientable
    /// volume. Then C1 fails somewhere, and [`DenseMap::oriented_cells`] names the cell.
    /// Maps of at least 65,536 darts share the four dimensions among threads
    /// ([`crate::parallel`]).
    pub fn oriented_cells_3d(&self) -> Option<OrientedCells3d> {
        if self.dim != 3 {
            return None;
        }
        let rows: &[[u32; 4]] = self.alpha.as_chunks::<4>().0;
        let (cells, euler) = crate::cells3::oriented_cells_3(rows)?;
        let cells = cells.into_iter().map(|c| oriented_parts(c, rows.len())).collect();
        Some(OrientedCells3d { cells, euler })
    }

    /// The oriented i-cells of a 3-map for each `i` of `dims` (entry `k` for `dims[k]`), as
    /// [`DenseMap::oriented_cells_3d`] walks them, without the other dimensions: a caller
    /// that needs two dimensions at a time holds two partitions, not four. `None` when the
    /// map is not of dimension 3, a dimension is above 3, or a cell of these dimensions is
    /// not of the shapes of the ring walks. The dimensions are tasks of [`crate::parallel`].
    /// O(N α(N)) per dimension.
    ///
    /// ```
    /// let m = gmap_core::examples::torus().embedded(3).unwrap();
    /// let all = m.oriented_cells_3d().unwrap();
    /// let two = m.oriented_cells_3d_of(&[3, 1]).unwrap();
    /// assert_eq!(two, vec![all.cells[3].clone(), all.cells[1].clone()]);
    /// assert!(gmap_core::DenseMap::new(2, 0).oriented_cells_3d_of(&[0]).is_none(), "not a 3-map");
    /// ```
    pub fn oriented_cells_3d_of(&self, dims: &[usize]) -> Option<Vec<(Partition, BitVec)>> {
        if self.dim != 3 || dims.iter().any(|&i| i > 3) {
            return None;
        }
        let rows: &[[u32; 4]] = self.alpha.as_chunks::<4>().0;
        let cells = crate::cells3::oriented_cells_3_of(rows, dims)?;
        Some(cells.into_iter().map(|c| oriented_parts(c, rows.len())).collect())
    }

    /// Checks C1 for every dimension; returns the first failing cell.
    pub fn check_cells_orientable(&self) -> Result<(), CellDefect> {
        for i in 0..=self.dim {
            self.cell_orientation(i)?;
        }
        Ok(())
    }

    /// The dual map: `alpha'_i = alpha_{n-i}` on the same darts. Points are dropped
    /// (the dual's vertices are the primal's n-cells). Dual of dual is the identity.
    pub fn dual(&self) -> DenseMap {
        let w = self.dim + 1;
        let mut alpha = Vec::with_capacity(self.alpha.len());
        for row in self.alpha.chunks_exact(w) {
            alpha.extend(row.iter().rev());
        }
        DenseMap { dim: self.dim, alpha, points: Vec::new(), table: Vec::new() }
    }

    /// The same map seen in dimension `dim >= self.dim()`: every new involution
    /// `alpha_k`, `k > self.dim()`, is the identity (all darts k-free), which keeps BO Def. 1.
    /// Points are kept. `None` if `dim` is smaller than the map's dimension or above
    /// [`MAX_DIM`]. O(N dim).
    pub fn embedded(&self, dim: usize) -> Option<DenseMap> {
        if dim < self.dim || dim > MAX_DIM {
            return None;
        }
        let w = self.dim + 1;
        let mut alpha = Vec::with_capacity(self.dart_count() * (dim + 1));
        for (d, row) in self.alpha.chunks_exact(w).enumerate() {
            alpha.extend_from_slice(row);
            alpha.extend(std::iter::repeat_n(d as u32, dim - self.dim));
        }
        Some(DenseMap { dim, alpha, points: self.points.clone(), table: self.table.clone() })
    }

    /// Renumbers the darts: dart `d` becomes `perm[d]`. `perm` must be a permutation of `0..N`.
    pub fn permuted(&self, perm: &[u32]) -> DenseMap {
        let w = self.dim + 1;
        let n = self.dart_count();
        assert_eq!(perm.len(), n);
        let mut alpha = vec![0u32; self.alpha.len()];
        for d in 0..n {
            let nd = perm[d] as usize;
            for i in 0..w {
                alpha[nd * w + i] = perm[self.alpha[d * w + i] as usize];
            }
        }
        let mut points = Vec::new();
        if !self.points.is_empty() {
            points = vec![NO_POINT; n];
            for d in 0..n {
                points[perm[d] as usize] = self.points[d];
            }
        }
        DenseMap { dim: self.dim, alpha, points, table: self.table.clone() }
    }
}
