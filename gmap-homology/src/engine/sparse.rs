//! [`SparseMatrix`]: integer matrices in compressed sparse column (CSC) form.
//!
//! A boundary matrix `∂_k : C_k → C_{k-1}` has one column per k-cell (the boundary of that
//! cell) and one row per (k-1)-cell, and is very sparse: a column holds the few faces of one
//! cell. CSC stores, for column `j`, the row indices `row_idx[col_ptr[j]..col_ptr[j + 1]]`
//! and the matching values in `vals`. The invariants, checked by every constructor:
//!
//! * `col_ptr.len() == cols + 1`, `col_ptr[0] == 0`, `col_ptr` non-decreasing and
//!   `col_ptr[cols] == row_idx.len() == vals.len()`;
//! * within a column, row indices are strictly increasing and `< rows`;
//! * no stored value is zero.
//!
//! So every matrix has exactly one representation and equality is structural.

use std::fmt;

use thiserror::Error;

/// Why a set of CSC parts or triplets does not make a valid [`SparseMatrix`].
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum SparseError {
    /// `col_ptr` has the wrong length, does not start at 0, decreases, or does not end at
    /// the number of entries.
    #[error("column pointers are malformed at column {col}")]
    BadColumnPointers {
        /// the first column where the pointers are wrong
        col: usize,
    },
    /// A row index is out of range.
    #[error("entry in column {col} has row {row}, but the matrix has {rows} rows")]
    RowOutOfRange {
        /// the column
        col: usize,
        /// the offending row index
        row: usize,
        /// the number of rows
        rows: usize,
    },
    /// A column index of a triplet is out of range.
    #[error("entry ({row}, {col}) is outside a matrix with {cols} columns")]
    ColOutOfRange {
        /// the row
        row: usize,
        /// the offending column
        col: usize,
        /// the number of columns
        cols: usize,
    },
    /// Row indices of a column are not strictly increasing.
    #[error("rows of column {col} are not strictly increasing at row {row}")]
    Unsorted {
        /// the column
        col: usize,
        /// the row that is not larger than its predecessor
        row: usize,
    },
    /// A stored value is zero.
    #[error("explicit zero stored at ({row}, {col})")]
    ExplicitZero {
        /// the row
        row: usize,
        /// the column
        col: usize,
    },
    /// Summing duplicate triplets overflowed `i64`.
    #[error("entry ({row}, {col}) overflows i64")]
    Overflow {
        /// the row
        row: usize,
        /// the column
        col: usize,
    },
    /// `vals` and `row_idx` have different lengths.
    #[error("{row_idx} row indices but {vals} values")]
    LengthMismatch {
        /// number of row indices
        row_idx: usize,
        /// number of values
        vals: usize,
    },
}

/// A sparse integer matrix in CSC form with validated invariants (see the module docs).
///
/// ```
/// use gmap_homology::SparseMatrix;
/// // the boundary of an edge from vertex 0 to vertex 1: column [-1, +1]
/// let m = SparseMatrix::try_from_triplets(2, 1, &[(0, 0, -1), (1, 0, 1)]).unwrap();
/// assert_eq!(m.get(1, 0), 1);
/// assert_eq!(m.nnz(), 2);
/// assert_eq!(m.to_dense(), vec![vec![-1], vec![1]]);
/// ```
#[derive(Clone, PartialEq, Eq)]
pub struct SparseMatrix {
    rows: usize,
    cols: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<u32>,
    vals: Vec<i64>,
}

/// Appends column `c` to `row_idx`/`vals`: its entries `col` sorted by row (stably, so that
/// equal rows are summed in their given order), duplicates summed, zeros dropped.
fn push_column(
    rows: usize,
    c: usize,
    col: &mut [(u32, i64)],
    row_idx: &mut Vec<u32>,
    vals: &mut Vec<i64>,
) -> Result<(), SparseError> {
    if let Some(&(r, _)) = col.iter().find(|e| e.0 as usize >= rows) {
        return Err(SparseError::RowOutOfRange { col: c, row: r as usize, rows });
    }
    col.sort_by_key(|e| e.0);
    let mut i = 0;
    while i < col.len() {
        let (r, mut v) = col[i];
        i += 1;
        while i < col.len() && col[i].0 == r {
            v = v.checked_add(col[i].1).ok_or(SparseError::Overflow { row: r as usize, col: c })?;
            i += 1;
        }
        if v != 0 {
            row_idx.push(r);
            vals.push(v);
        }
    }
    Ok(())
}

impl SparseMatrix {
    /// The `rows × cols` zero matrix. O(cols).
    pub fn zeros(rows: usize, cols: usize) -> Self {
        SparseMatrix { rows, cols, col_ptr: vec![0; cols + 1], row_idx: Vec::new(), vals: Vec::new() }
    }

    /// The `n × n` identity. O(n).
    pub fn identity(n: usize) -> Self {
        SparseMatrix {
            rows: n,
            cols: n,
            col_ptr: (0..=n).collect(),
            row_idx: (0..n as u32).collect(),
            vals: vec![1; n],
        }
    }

    /// A matrix from its CSC parts, checking every invariant. O(rows + nnz).
    pub fn try_from_csc(
        rows: usize,
        cols: usize,
        col_ptr: Vec<usize>,
        row_idx: Vec<u32>,
        vals: Vec<i64>,
    ) -> Result<Self, SparseError> {
        if row_idx.len() != vals.len() {
            return Err(SparseError::LengthMismatch { row_idx: row_idx.len(), vals: vals.len() });
        }
        if col_ptr.len() != cols + 1 || col_ptr[0] != 0 {
            return Err(SparseError::BadColumnPointers { col: 0 });
        }
        for j in 0..cols {
            if col_ptr[j + 1] < col_ptr[j] || col_ptr[j + 1] > row_idx.len() {
                return Err(SparseError::BadColumnPointers { col: j });
            }
            let mut prev: Option<u32> = None;
            for p in col_ptr[j]..col_ptr[j + 1] {
                let r = row_idx[p];
                if r as usize >= rows {
                    return Err(SparseError::RowOutOfRange { col: j, row: r as usize, rows });
                }
                if prev.is_some_and(|q| q >= r) {
                    return Err(SparseError::Unsorted { col: j, row: r as usize });
                }
                if vals[p] == 0 {
                    return Err(SparseError::ExplicitZero { row: r as usize, col: j });
                }
                prev = Some(r);
            }
        }
        if col_ptr[cols] != row_idx.len() {
            return Err(SparseError::BadColumnPointers { col: cols });
        }
        Ok(SparseMatrix { rows, cols, col_ptr, row_idx, vals })
    }

    /// A matrix from CSC parts that hold the invariants by construction (a caller in this
    /// crate that builds them so, e.g. the faces of simplices); checked in debug builds only.
    /// O(1).
    pub(crate) fn from_csc_trusted(
        rows: usize,
        cols: usize,
        col_ptr: Vec<usize>,
        row_idx: Vec<u32>,
        vals: Vec<i64>,
    ) -> Self {
        debug_assert_eq!(
            Self::try_from_csc(rows, cols, col_ptr.clone(), row_idx.clone(), vals.clone()).map(|_| ()),
            Ok(())
        );
        SparseMatrix { rows, cols, col_ptr, row_idx, vals }
    }

    /// A matrix from `(row, col, value)` triplets in any order; duplicates are summed
    /// (with overflow checked) and zero sums dropped. O(nnz log nnz).
    pub fn try_from_triplets(rows: usize, cols: usize, triplets: &[(usize, usize, i64)]) -> Result<Self, SparseError> {
        let mut t: Vec<(usize, usize, i64)> = Vec::with_capacity(triplets.len());
        for &(r, c, v) in triplets {
            if c >= cols {
                return Err(SparseError::ColOutOfRange { row: r, col: c, cols });
            }
            if r >= rows || r > u32::MAX as usize {
                return Err(SparseError::RowOutOfRange { col: c, row: r, rows });
            }
            t.push((c, r, v));
        }
        t.sort_unstable_by_key(|&(c, r, _)| (c, r));
        let mut col_ptr = vec![0usize; cols + 1];
        let mut row_idx: Vec<u32> = Vec::with_capacity(t.len());
        let mut vals: Vec<i64> = Vec::with_capacity(t.len());
        let mut k = 0;
        while k < t.len() {
            let (c, r, mut v) = t[k];
            k += 1;
            while k < t.len() && t[k].0 == c && t[k].1 == r {
                v = v.checked_add(t[k].2).ok_or(SparseError::Overflow { row: r, col: c })?;
                k += 1;
            }
            if v != 0 {
                row_idx.push(r as u32);
                vals.push(v);
                col_ptr[c + 1] += 1;
            }
        }
        for j in 0..cols {
            col_ptr[j + 1] += col_ptr[j];
        }
        Ok(SparseMatrix { rows, cols, col_ptr, row_idx, vals })
    }

    /// Like [`SparseMatrix::try_from_triplets`] for `(row, col, value)` entries with `u32`
    /// indices, by two stable counting sorts (rows, then columns) instead of a comparison
    /// sort: O(nnz + rows + cols). Duplicates are summed (overflow checked), zeros dropped.
    ///
    /// Entries already in column order (columns non-decreasing, as produced column by
    /// column) skip both sorts: each column's few entries are sorted in place.
    pub fn try_from_entries(rows: usize, cols: usize, entries: &[(u32, u32, i64)]) -> Result<Self, SparseError> {
        if entries.windows(2).all(|w| w[0].1 <= w[1].1) {
            return Self::try_from_column_order(rows, cols, entries);
        }
        let mut by_row = vec![0usize; rows + 1];
        let mut by_col = vec![0usize; cols + 1];
        for &(r, c, _) in entries {
            if c as usize >= cols {
                return Err(SparseError::ColOutOfRange { row: r as usize, col: c as usize, cols });
            }
            if r as usize >= rows {
                return Err(SparseError::RowOutOfRange { col: c as usize, row: r as usize, rows });
            }
            by_row[r as usize + 1] += 1;
            by_col[c as usize + 1] += 1;
        }
        for i in 0..rows {
            by_row[i + 1] += by_row[i];
        }
        for j in 0..cols {
            by_col[j + 1] += by_col[j];
        }
        // stable by row
        let mut tmp: Vec<(u32, u32, i64)> = vec![(0, 0, 0); entries.len()];
        for &e in entries {
            let p = &mut by_row[e.0 as usize];
            tmp[*p] = e;
            *p += 1;
        }
        // stable by column: rows ascend within each column
        let mut row_idx = vec![0u32; entries.len()];
        let mut vals = vec![0i64; entries.len()];
        let mut fill = by_col.clone();
        for &(r, c, v) in &tmp {
            let p = &mut fill[c as usize];
            row_idx[*p] = r;
            vals[*p] = v;
            *p += 1;
        }
        drop(tmp);
        // merge duplicates and drop zeros, compacting in place
        let mut col_ptr = vec![0usize; cols + 1];
        let mut out = 0usize;
        for j in 0..cols {
            let mut k = by_col[j];
            let end = by_col[j + 1];
            while k < end {
                let r = row_idx[k];
                let mut v = vals[k];
                k += 1;
                while k < end && row_idx[k] == r {
                    v = v.checked_add(vals[k]).ok_or(SparseError::Overflow { row: r as usize, col: j })?;
                    k += 1;
                }
                if v != 0 {
                    row_idx[out] = r;
                    vals[out] = v;
                    out += 1;
                }
            }
            col_ptr[j + 1] = out;
        }
        row_idx.truncate(out);
        vals.truncate(out);
        Ok(SparseMatrix { rows, cols, col_ptr, row_idx, vals })
    }

    /// [`SparseMatrix::try_from_entries`] for entries whose columns do not decrease.
    fn try_from_column_order(rows: usize, cols: usize, entries: &[(u32, u32, i64)]) -> Result<Self, SparseError> {
        let mut col_ptr = vec![0usize; cols + 1];
        let mut row_idx = Vec::with_capacity(entries.len());
        let mut vals = Vec::with_capacity(entries.len());
        let mut col: Vec<(u32, i64)> = Vec::new();
        let mut k = 0;
        while k < entries.len() {
            let c = entries[k].1;
            if c as usize >= cols {
                return Err(SparseError::ColOutOfRange { row: entries[k].0 as usize, col: c as usize, cols });
            }
            col.clear();
            while k < entries.len() && entries[k].1 == c {
                let (r, _, v) = entries[k];
                col.push((r, v));
                k += 1;
            }
            push_column(rows, c as usize, &mut col, &mut row_idx, &mut vals)?;
            col_ptr[c as usize + 1] = row_idx.len();
        }
        // columns without entries take the pointer of the column before
        for j in 0..cols {
            col_ptr[j + 1] = col_ptr[j + 1].max(col_ptr[j]);
        }
        Ok(SparseMatrix { rows, cols, col_ptr, row_idx, vals })
    }

    /// A matrix built column by column, without a list of entries: `fill(j, col)` pushes the
    /// entries `(row, value)` of column `j` onto the empty `col`, in any order (duplicates
    /// are summed, overflow checked, zeros dropped). The columns are cut into contiguous
    /// ranges filled on the threads of [`gmap_core::parallel`], then joined; `nnz_hint`, an
    /// estimate of the number of entries, sizes each range's arrays up front (an estimate
    /// above the truth reserves address space only; growing the arrays would copy them and
    /// leave the old copies to the allocator). Besides the matrix, one column at a time per
    /// thread. O(nnz log(column length) + cols).
    ///
    /// ```
    /// use gmap_homology::SparseMatrix;
    /// // column j holds +1 in row j and -1 in row j + 1 (mod 3), given in any order
    /// let m = SparseMatrix::try_from_column_fn(3, 3, 6, |j, col| {
    ///     col.push((((j + 1) % 3) as u32, -1));
    ///     col.push((j as u32, 1));
    /// })
    /// .unwrap();
    /// assert_eq!(m.get(0, 2), -1);
    /// assert_eq!(m.get(2, 2), 1);
    /// assert!(SparseMatrix::try_from_column_fn(2, 1, 1, |_, col| col.push((2, 1))).is_err());
    /// ```
    pub fn try_from_column_fn<F>(rows: usize, cols: usize, nnz_hint: usize, fill: F) -> Result<Self, SparseError>
    where
        F: Fn(usize, &mut Vec<(u32, i64)>) + Sync,
    {
        let ranges = gmap_core::parallel::split_ranges(cols, gmap_core::parallel::threads_for(cols, cols));
        let parts = gmap_core::parallel::map_parts(ranges, |range| {
            let mut ends = Vec::with_capacity(range.len());
            let hint = (nnz_hint as u128 * range.len() as u128 / cols.max(1) as u128) as usize + 16;
            let (mut row_idx, mut vals) = (Vec::with_capacity(hint), Vec::with_capacity(hint));
            let mut col = Vec::new();
            for j in range {
                col.clear();
                fill(j, &mut col);
                push_column(rows, j, &mut col, &mut row_idx, &mut vals)?;
                ends.push(row_idx.len());
            }
            Ok::<_, SparseError>((ends, row_idx, vals))
        });
        let parts = parts.into_iter().collect::<Result<Vec<_>, _>>()?;
        let nnz = parts.iter().map(|p| p.1.len()).sum();
        let mut col_ptr = Vec::with_capacity(cols + 1);
        col_ptr.push(0);
        let (mut row_idx, mut vals) = (Vec::with_capacity(nnz), Vec::with_capacity(nnz));
        // each part is dropped once copied
        for (ends, r, v) in parts {
            let base = row_idx.len();
            col_ptr.extend(ends.iter().map(|e| base + e));
            row_idx.extend_from_slice(&r);
            vals.extend_from_slice(&v);
        }
        Ok(SparseMatrix { rows, cols, col_ptr, row_idx, vals })
    }

    /// A matrix from sorted columns, each a list of `(row, value)` with strictly increasing
    /// rows and non-zero values (checked). O(rows + nnz).
    pub fn try_from_columns(rows: usize, columns: &[Vec<(u32, i64)>]) -> Result<Self, SparseError> {
        let mut col_ptr = Vec::with_capacity(columns.len() + 1);
        col_ptr.push(0);
        let nnz = columns.iter().map(Vec::len).sum();
        let mut row_idx = Vec::with_capacity(nnz);
        let mut vals = Vec::with_capacity(nnz);
        for c in columns {
            for &(r, v) in c {
                row_idx.push(r);
                vals.push(v);
            }
            col_ptr.push(row_idx.len());
        }
        Self::try_from_csc(rows, columns.len(), col_ptr, row_idx, vals)
    }

    /// Number of rows.
    #[inline]
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    #[inline]
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Number of stored (non-zero) entries.
    #[inline]
    pub fn nnz(&self) -> usize {
        self.vals.len()
    }

    /// The column pointers (length `cols + 1`).
    #[inline]
    pub fn col_ptr(&self) -> &[usize] {
        &self.col_ptr
    }

    /// The row indices of column `j` (strictly increasing) and their values. O(1).
    #[inline]
    pub fn col(&self, j: usize) -> (&[u32], &[i64]) {
        let (a, b) = (self.col_ptr[j], self.col_ptr[j + 1]);
        (&self.row_idx[a..b], &self.vals[a..b])
    }

    /// The entry at `(i, j)` (0 if not stored). O(log of the column length).
    #[inline]
    pub fn get(&self, i: usize, j: usize) -> i64 {
        let (r, v) = self.col(j);
        match r.binary_search(&(i as u32)) {
            Ok(p) => v[p],
            Err(_) => 0,
        }
    }

    /// Iterates over the stored entries `(row, col, value)` column by column.
    pub fn iter(&self) -> impl Iterator<Item = (usize, usize, i64)> + '_ {
        (0..self.cols).flat_map(move |j| {
            let (r, v) = self.col(j);
            r.iter().zip(v).map(move |(&i, &x)| (i as usize, j, x))
        })
    }

    /// The transpose, still in CSC form (so its columns are this matrix's rows). O(rows + cols + nnz).
    pub fn transpose(&self) -> SparseMatrix {
        let mut col_ptr = vec![0usize; self.rows + 1];
        for &r in &self.row_idx {
            col_ptr[r as usize + 1] += 1;
        }
        for i in 0..self.rows {
            col_ptr[i + 1] += col_ptr[i];
        }
        let mut fill = col_ptr.clone();
        let mut row_idx = vec![0u32; self.nnz()];
        let mut vals = vec![0i64; self.nnz()];
        for j in 0..self.cols {
            let (r, v) = self.col(j);
            for (&i, &x) in r.iter().zip(v) {
                let p = fill[i as usize];
                row_idx[p] = j as u32;
                vals[p] = x;
                fill[i as usize] += 1;
            }
        }
        SparseMatrix { rows: self.cols, cols: self.rows, col_ptr, row_idx, vals }
    }

    /// The product `self * other`, or `None` on a dimension mismatch or an `i64` overflow.
    /// O(sum over columns of other of the work to merge the touched columns of self).
    pub fn checked_mul(&self, other: &SparseMatrix) -> Option<SparseMatrix> {
        if self.cols != other.rows {
            return None;
        }
        let mut acc = vec![0i64; self.rows];
        let mut touched: Vec<u32> = Vec::new();
        let mut columns: Vec<Vec<(u32, i64)>> = Vec::with_capacity(other.cols);
        for j in 0..other.cols {
            let (ri, rv) = other.col(j);
            for (&k, &y) in ri.iter().zip(rv) {
                let (si, sv) = self.col(k as usize);
                for (&i, &x) in si.iter().zip(sv) {
                    let slot = &mut acc[i as usize];
                    if *slot == 0 {
                        touched.push(i);
                    }
                    *slot = slot.checked_add(x.checked_mul(y)?)?;
                }
            }
            touched.sort_unstable();
            touched.dedup();
            let mut c = Vec::new();
            for &i in &touched {
                let v = std::mem::take(&mut acc[i as usize]);
                if v != 0 {
                    c.push((i, v));
                }
            }
            touched.clear();
            columns.push(c);
        }
        SparseMatrix::try_from_columns(self.rows, &columns).ok()
    }

    /// Whether every entry is zero.
    pub fn is_zero(&self) -> bool {
        self.vals.is_empty()
    }

    /// The dense form, row by row. O(rows × cols): for tests and small matrices.
    pub fn to_dense(&self) -> Vec<Vec<i64>> {
        let mut d = vec![vec![0i64; self.cols]; self.rows];
        for (i, j, x) in self.iter() {
            d[i][j] = x;
        }
        d
    }
}

impl fmt::Debug for SparseMatrix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "SparseMatrix {}x{} [", self.rows, self.cols)?;
        for (k, (i, j, x)) in self.iter().enumerate() {
            if k > 0 {
                write!(f, ", ")?;
            }
            write!(f, "({i},{j})={x}")?;
        }
        write!(f, "]")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triplets_sum_and_drop_zeros() {
        let m = SparseMatrix::try_from_triplets(2, 2, &[(0, 1, 2), (0, 1, -2), (1, 0, 3), (1, 0, 4)]).unwrap();
        assert_eq!(m.nnz(), 1);
        assert_eq!(m.get(1, 0), 7);
        assert_eq!(m.get(0, 1), 0);
    }

    #[test]
    fn invariants_checked() {
        assert_eq!(
            SparseMatrix::try_from_csc(2, 1, vec![0, 2], vec![1, 0], vec![1, 1]),
            Err(SparseError::Unsorted { col: 0, row: 0 })
        );
        assert_eq!(
            SparseMatrix::try_from_csc(2, 1, vec![0, 1], vec![0], vec![0]),
            Err(SparseError::ExplicitZero { row: 0, col: 0 })
        );
        assert_eq!(
            SparseMatrix::try_from_csc(2, 1, vec![0, 1], vec![5], vec![1]),
            Err(SparseError::RowOutOfRange { col: 0, row: 5, rows: 2 })
        );
        assert_eq!(
            SparseMatrix::try_from_triplets(1, 1, &[(0, 0, i64::MAX), (0, 0, 1)]),
            Err(SparseError::Overflow { row: 0, col: 0 })
        );
    }

    /// Entries in column order take the in-place path; it builds the matrix of the
    /// counting sorts (which a shuffled order of the same entries goes through).
    #[test]
    fn column_ordered_entries_agree_with_the_counting_sorts() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |m: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % m
        };
        for case in 0..200 {
            let (rows, cols) = (1 + next(9) as u32, 1 + next(9) as u32);
            let mut e: Vec<(u32, u32, i64)> = (0..next(40))
                .map(|_| (next(rows as u64) as u32, next(cols as u64) as u32, next(5) as i64 - 2))
                .collect();
            e.sort_by_key(|x| x.1);
            let ordered = SparseMatrix::try_from_entries(rows as usize, cols as usize, &e).unwrap();
            // an order with a decreasing column forces the counting sorts
            e.reverse();
            let shuffled = if e.windows(2).all(|w| w[0].1 <= w[1].1) {
                SparseMatrix::try_from_triplets(
                    rows as usize,
                    cols as usize,
                    &e.iter().map(|&(r, c, v)| (r as usize, c as usize, v)).collect::<Vec<_>>(),
                )
                .unwrap()
            } else {
                SparseMatrix::try_from_entries(rows as usize, cols as usize, &e).unwrap()
            };
            assert_eq!(ordered, shuffled, "case {case}");
        }
        assert_eq!(
            SparseMatrix::try_from_entries(2, 2, &[(0, 0, 1), (0, 1, i64::MAX), (0, 1, 1)]),
            Err(SparseError::Overflow { row: 0, col: 1 })
        );
        assert_eq!(
            SparseMatrix::try_from_entries(2, 2, &[(0, 0, 1), (3, 1, 1)]),
            Err(SparseError::RowOutOfRange { col: 1, row: 3, rows: 2 })
        );
    }

    #[test]
    fn product_and_transpose() {
        // boundary of a triangle: d1 (3 vertices x 3 edges), d2 (3 edges x 1 face)
        let d1 = SparseMatrix::try_from_triplets(
            3,
            3,
            &[(0, 0, -1), (1, 0, 1), (1, 1, -1), (2, 1, 1), (0, 2, -1), (2, 2, 1)],
        )
        .unwrap();
        let d2 = SparseMatrix::try_from_triplets(3, 1, &[(0, 0, 1), (1, 0, 1), (2, 0, -1)]).unwrap();
        assert!(d1.checked_mul(&d2).unwrap().is_zero());
        let t = d1.transpose();
        assert_eq!(t.get(0, 1), 1);
        assert_eq!(t.transpose(), d1);
    }
}
