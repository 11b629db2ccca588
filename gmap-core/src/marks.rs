//! Marks: reservable boolean attributes on darts.
//!
//! CGAL's maps offer a fixed number of marks (32 by default) and throw when they run
//! out. Here a [`Marks`] pool hands out as many as callers reserve: each mark is a
//! bit vector over dart indices, created on [`Marks::reserve`] and recycled on
//! [`Marks::free`]. A freed mark's bits are cleared before it is handed out again.

use bitvec::vec::BitVec;

/// A handle to a reserved mark. Valid until passed to [`Marks::free`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MarkId(usize);

/// A pool of marks over darts indexed `0..len`.
#[derive(Clone, Debug, Default)]
pub struct Marks {
    len: usize,
    bits: Vec<Option<BitVec>>,
    free: Vec<usize>,
}

impl Marks {
    /// A pool for `len` darts, with no mark reserved.
    pub fn new(len: usize) -> Self {
        Marks { len, bits: Vec::new(), free: Vec::new() }
    }

    /// Number of darts the marks cover.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the pool covers no dart.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Grows (or shrinks) every mark to `len` darts; new darts are unmarked.
    pub fn resize(&mut self, len: usize) {
        self.len = len;
        for b in self.bits.iter_mut().flatten() {
            b.resize(len, false);
        }
    }

    /// Reserves a mark with every dart unmarked. Never fails: there is no fixed cap.
    pub fn reserve(&mut self) -> MarkId {
        if let Some(k) = self.free.pop() {
            let mut b = BitVec::new();
            b.resize(self.len, false);
            self.bits[k] = Some(b);
            MarkId(k)
        } else {
            let mut b = BitVec::new();
            b.resize(self.len, false);
            self.bits.push(Some(b));
            MarkId(self.bits.len() - 1)
        }
    }

    /// Frees a mark. Panics if it was not reserved (a programming error, not input).
    pub fn free(&mut self, m: MarkId) {
        assert!(self.bits[m.0].take().is_some(), "mark {m:?} freed twice");
        self.free.push(m.0);
    }

    /// Number of marks currently reserved.
    pub fn reserved(&self) -> usize {
        self.bits.iter().filter(|b| b.is_some()).count()
    }

    fn get_bits(&self, m: MarkId) -> &BitVec {
        self.bits[m.0].as_ref().expect("mark not reserved")
    }

    fn get_bits_mut(&mut self, m: MarkId) -> &mut BitVec {
        self.bits[m.0].as_mut().expect("mark not reserved")
    }

    /// Whether dart `d` carries mark `m`.
    #[inline]
    pub fn is_marked(&self, m: MarkId, d: usize) -> bool {
        self.get_bits(m)[d]
    }

    /// Sets mark `m` on dart `d`; returns whether it was already set.
    #[inline]
    pub fn mark(&mut self, m: MarkId, d: usize) -> bool {
        let b = self.get_bits_mut(m);
        let was = b[d];
        b.set(d, true);
        was
    }

    /// Clears mark `m` on dart `d`.
    #[inline]
    pub fn unmark(&mut self, m: MarkId, d: usize) {
        self.get_bits_mut(m).set(d, false);
    }

    /// Clears mark `m` on every dart, in bulk.
    pub fn clear(&mut self, m: MarkId) {
        self.get_bits_mut(m).fill(false);
    }

    /// Sets mark `m` on every dart, in bulk.
    pub fn mark_all(&mut self, m: MarkId) {
        self.get_bits_mut(m).fill(true);
    }

    /// Number of darts carrying mark `m`.
    pub fn count(&self, m: MarkId) -> usize {
        self.get_bits(m).count_ones()
    }
}

impl Marks {
    /// Clears every mark's bit at index `d` (used when a dart slot is freed).
    pub fn clear_index(&mut self, d: usize) {
        for b in self.bits.iter_mut().flatten() {
            if d < b.len() {
                b.set(d, false);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn many_marks() {
        let mut p = Marks::new(10);
        let ms: Vec<_> = (0..100).map(|_| p.reserve()).collect();
        for (k, &m) in ms.iter().enumerate() {
            p.mark(m, k % 10);
        }
        assert_eq!(p.reserved(), 100);
        assert!(p.is_marked(ms[13], 3));
        p.free(ms[13]);
        let again = p.reserve();
        assert_eq!(p.count(again), 0);
        p.mark_all(again);
        assert_eq!(p.count(again), 10);
        p.clear(again);
        assert_eq!(p.count(again), 0);
    }
}
