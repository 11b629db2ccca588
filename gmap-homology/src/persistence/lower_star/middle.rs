//! The column reduction of the middle dimension of a 3-D image: the 2-cells' columns over the
//! edges, keyed by rank, only the columns a reduction changed stored.

use super::sweep::Out;
use crate::complex::cubical::grid::face_sign;
use crate::persistence::pairing::Zp;
use crate::prefetch::{filled, prefetch};

/// The boundary of the 2-cell `id = 3 · corner + normal` of a 3-D grid of strides `stride`
/// (the corner's point grid): `+e(c, a) + e(c + e_a, b) - e(c + e_b, a) - e(c, b)` for
/// the other axes `a < b` (the signs of [`face_sign`]: along `a`, its first axis, the faces
/// are the edges along `b`), edges keyed by `edge_key(corner, axis)` (`None`: left out),
/// sorted by key.
#[inline]
pub(super) fn square_boundary<E: Entry>(
    id: u32,
    stride: [usize; 3],
    field: Zp,
    edge_key: impl Fn(usize, usize) -> Option<u64>,
    col: &mut Vec<E>,
) {
    let (low, normal) = (id as usize / 3, id as usize % 3);
    let [a, b] = OTHERS[normal];
    let coef = |j: usize, upper: bool| if face_sign(j, upper) > 0 { 1 } else { field.of(-1) };
    col.clear();
    for (v, axis, coef) in [
        (low, a, coef(1, false)),
        (low + stride[a], b, coef(0, true)),
        (low + stride[b], a, coef(1, true)),
        (low, b, coef(0, false)),
    ] {
        if let Some(k) = edge_key(v, axis) {
            col.push(E::new(k, coef));
        }
    }
    col.sort_unstable_by_key(|e| e.key());
}

/// An entry of a column of the middle dimension: a key `(rank << 32) | edge` and a
/// coefficient, or over Z/2 the key alone (8 bytes instead of 16: the merges and the
/// stored columns read half as much).
pub(super) trait Entry: Copy + Default {
    fn new(key: u64, coef: u32) -> Self;
    fn key(self) -> u64;
    fn coef(self) -> u32;

    /// `out = a + f · b` for entries sorted by key, zeros dropped.
    #[inline]
    fn merge(field: Zp, a: &[Self], f: u32, b: &[Self], out: &mut Vec<Self>) {
        out.clear();
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            let (ka, kb) = (a[i].key(), b[j].key());
            if ka < kb {
                out.push(a[i]);
                i += 1;
            } else if kb < ka {
                out.push(Self::new(kb, field.mul(f, b[j].coef())));
                j += 1;
            } else {
                let c = field.add(a[i].coef(), field.mul(f, b[j].coef()));
                if c != 0 {
                    out.push(Self::new(ka, c));
                }
                i += 1;
                j += 1;
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend(b[j..].iter().map(|x| Self::new(x.key(), field.mul(f, x.coef()))));
    }
}

impl Entry for u64 {
    #[inline(always)]
    fn new(key: u64, _: u32) -> Self {
        key
    }
    #[inline(always)]
    fn key(self) -> u64 {
        self
    }
    #[inline(always)]
    fn coef(self) -> u32 {
        1
    }

    /// Over Z/2 the sum is the symmetric difference.
    #[inline]
    fn merge(_: Zp, a: &[u64], _: u32, b: &[u64], out: &mut Vec<u64>) {
        out.clear();
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            let (x, y) = (a[i], b[j]);
            if x < y {
                out.push(x);
                i += 1;
            } else if y < x {
                out.push(y);
                j += 1;
            } else {
                i += 1;
                j += 1;
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
    }
}

impl Entry for (u64, u32) {
    #[inline(always)]
    fn new(key: u64, coef: u32) -> Self {
        (key, coef)
    }
    #[inline(always)]
    fn key(self) -> u64 {
        self.0
    }
    #[inline(always)]
    fn coef(self) -> u32 {
        self.1
    }
}

/// Columns of at most this many entries are added into a long column in place.
const SHORT: usize = 8;

/// The column reduction of the middle dimension of a 3-D image: the negative 2-cells in
/// filtration order, each column reduced until its pivot (latest edge, the largest key
/// `(rank << 32) | edge`) has no owner. Only the columns changed by a reduction are stored
/// (one after the other in one array); the others are recomputed from the boundary when
/// needed. An edge's owner is one `u32`: [`Middle::FREE`], the place `k < 4` of an
/// unchanged column's 2-cell among the edge's four cofaces ([`coface`]), or `4 + i` for
/// the stored column whose header (its length) is `entries[i]`, so that finding the column
/// to add reads no table and one cache line. A short column (at most [`SHORT`] entries)
/// added into a long one goes in place, each entry found by bisection and moved in (on
/// 128³ random T, 990,597 such additions meet working columns of 716 entries on average);
/// otherwise the part of the working column from the added column's first key up is
/// merged with it, the rest staying in place.
pub(super) struct Middle<E> {
    field: Zp,
    /// the point strides of the grid the edges and 2-cells are named on
    stride: [usize; 3],
    pub(super) owner: Vec<u32>,
    /// the stored columns one after the other, each a header entry (its key the column's
    /// length) followed by the column: finding a stored column reads one cache line
    entries: Vec<E>,
    col: Vec<E>,
    other: Vec<E>,
    scratch: Vec<E>,
}

/// The `k`-th of the four 2-cells containing the edge `e = 3 · point + axis` on a grid of
/// point strides `stride`: spanned by the edge's axis and the other axis `o` (the first of
/// the two others for `k < 2`), lower corner the edge's point minus `(k & 1) · e_o`.
#[inline]
fn coface(e: u32, k: u32, stride: [usize; 3]) -> u32 {
    let (v, axis) = (e as usize / 3, e as usize % 3);
    let others = OTHERS[axis];
    let (o, normal) = if k < 2 { (others[0], others[1]) } else { (others[1], others[0]) };
    (3 * (v - (k as usize & 1) * stride[o]) + normal) as u32
}

/// The place of the 2-cell `id` among the cofaces of its edge `e` ([`coface`]).
#[inline]
fn coface_place(e: u32, id: u32) -> u32 {
    let (v, axis) = (e as usize / 3, e as usize % 3);
    let (low, normal) = (id as usize / 3, id as usize % 3);
    let first = OTHERS[axis][1] == normal;
    2 * u32::from(!first) + u32::from(low != v)
}

/// The two axes other than each axis, in increasing order.
pub(super) const OTHERS: [[usize; 2]; 3] = [[1, 2], [0, 2], [0, 1]];

impl<E: Entry> Middle<E> {
    const FREE: u32 = u32::MAX;

    pub(super) fn new(edges: usize, stride: [usize; 3], field: Zp) -> Self {
        Middle {
            field,
            stride,
            owner: filled(edges, Self::FREE),
            entries: Vec::new(),
            col: Vec::new(),
            other: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// Makes the 2-cell `id` the owner of its pivot `e` if `e` has none yet (its column is
    /// then reduced as it is: its boundary) and says whether it did.
    #[inline]
    pub(super) fn take(&mut self, e: u32, id: u32) -> bool {
        let free = self.owner[e as usize] == Self::FREE;
        if free {
            self.owner[e as usize] = coface_place(e, id);
        }
        free
    }

    /// Reduces the column of the 2-cell `id` at rank `death`; `boundary(id, col)` fills
    /// `col` with a 2-cell's boundary, sorted by key. Records the pair it makes. Fails
    /// only if the stored columns would outgrow what an owner can address (`u32::MAX - 4`
    /// entries: 32 GB of them over Z/2).
    #[inline]
    pub(super) fn column(
        &mut self,
        id: u32,
        death: u32,
        out: &mut Out,
        boundary: impl Fn(u32, &mut Vec<E>),
    ) -> Result<(), TooLarge> {
        let field = self.field;
        boundary(id, &mut self.col);
        let mut changed = false;
        while let Some(&top) = self.col.last() {
            let pivot = top.key();
            let e = (pivot & 0xffff_ffff) as u32;
            let o = self.owner[e as usize];
            if o == Self::FREE {
                self.owner[e as usize] = if changed {
                    let at = self.entries.len();
                    if at > (u32::MAX - 4) as usize {
                        return Err(TooLarge);
                    }
                    self.entries.push(E::new(self.col.len() as u64, 0));
                    self.entries.extend_from_slice(&self.col);
                    4 + at as u32
                } else {
                    coface_place(e, id)
                };
                out.push(1, (pivot >> 32) as u32, Some(death));
                return Ok(());
            }
            let pcol: &[E] = if o < 4 {
                boundary(coface(e, o, self.stride), &mut self.other);
                &self.other
            } else {
                let at = (o - 4) as usize + 1;
                &self.entries[at..at + self.entries[at - 1].key() as usize]
            };
            // the next pivot is most likely the working column's or the added column's
            // second latest edge: their owners load while the column is added
            let n = self.col.len();
            for x in [self.col.get(n.wrapping_sub(2)), pcol.get(pcol.len().wrapping_sub(2))].into_iter().flatten() {
                prefetch(&self.owner, (x.key() & 0xffff_ffff) as usize);
            }
            let pc = pcol.last().expect("a pivot column is not zero").coef();
            let fac = field.neg(field.mul(top.coef(), field.inv(pc)));
            if pcol.len() <= SHORT && self.col.len() > 4 * SHORT {
                // a short column into a long one: in place, each entry found by bisection
                for &x in pcol.iter().rev() {
                    let (k, c) = (x.key(), field.mul(fac, x.coef()));
                    match self.col.binary_search_by_key(&k, |e| e.key()) {
                        Ok(i) => match field.add(self.col[i].coef(), c) {
                            0 => {
                                self.col.remove(i);
                            }
                            s => self.col[i] = E::new(k, s),
                        },
                        Err(i) => self.col.insert(i, E::new(k, c)),
                    }
                }
            } else {
                // the entries below the added column's first key stay
                let first = pcol[0].key();
                let lo = self.col.partition_point(|x| x.key() < first);
                E::merge(field, &self.col[lo..], fac, pcol, &mut self.scratch);
                self.col.truncate(lo);
                self.col.extend_from_slice(&self.scratch);
            }
            changed = true;
        }
        unreachable!("a negative 2-cell's column does not reduce to zero");
    }
}

/// The stored columns of [`Middle`] outgrew what an owner can address: the image is left
/// to the general route.
pub(super) struct TooLarge;
