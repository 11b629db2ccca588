//! What the sweeps over the pixels share: the diagram they fill (its values read a few pairs
//! late), their union-find, and the rows they read ahead of the step that needs them.

use crate::persistence::Diagram;
use crate::prefetch::{filled, prefetch};

/// The diagram being filled, with the values in rank order. A pair's values are read
/// [`LAG`] pairs after it is pushed, their cache lines asked for at the push: a birth
/// is a rank from anywhere in the image, and reading its value at once would stall the
/// sweep on a cache miss per pair.
pub(super) struct Out<'a> {
    diagram: Diagram,
    sv: &'a [f64],
    sign: f64,
    /// the pairs pushed and not yet read: `(dim, birth, death)`, `u32::MAX` for no death
    /// (no rank is `u32::MAX`: `diagram` takes images of fewer pixels)
    pending: [(u8, u32, u32); LAG],
    next: usize,
}

/// How many pairs [`Out`] holds before reading their values.
const LAG: usize = 16;

impl<'a> Out<'a> {
    pub(super) fn new(diagram: Diagram, sv: &'a [f64], sign: f64) -> Self {
        Out { diagram, sv, sign, pending: [(0, 0, 0); LAG], next: 0 }
    }

    /// A pair between ranks (`None`: essential).
    #[inline]
    pub(super) fn push(&mut self, dim: usize, birth: u32, death: Option<u32>) {
        if death == Some(birth) {
            return; // one rank, one value: most pairs, found without reading the values
        }
        prefetch(self.sv, birth as usize);
        let slot = self.next % LAG;
        if self.next >= LAG {
            self.read(self.pending[slot]);
        }
        // dimensions are at most 3
        self.pending[slot] = (dim as u8, birth, death.unwrap_or(u32::MAX));
        self.next += 1;
    }

    /// Enters a pending pair in the diagram, unless its values are equal.
    #[inline]
    pub(super) fn read(&mut self, (dim, birth, death): (u8, u32, u32)) {
        let b = self.sv[birth as usize];
        let e = if death == u32::MAX { f64::INFINITY } else { self.sv[death as usize] };
        if b != e {
            self.diagram.push(dim as usize, b, e, self.sign, None);
        }
    }

    /// The diagram, every pending pair read.
    pub(super) fn finish(mut self) -> Diagram {
        let first = self.next.saturating_sub(LAG);
        for k in first..self.next {
            self.read(self.pending[k % LAG]);
        }
        self.diagram
    }
}

/// Union-find nodes `[parent, time]`: the root's time names its component (the elder rule
/// compares times), paths are halved.
pub(super) struct Forest {
    pub(super) nodes: Vec<[u32; 2]>,
}

impl Forest {
    pub(super) fn new(n: usize) -> Self {
        Forest { nodes: filled(n, [0, 0]) }
    }

    /// The times of the first `n` nodes (for the ranks once the nodes are reused), on huge
    /// pages like the nodes.
    pub(super) fn times(&self, n: usize) -> Vec<u32> {
        let mut t = filled(n, 0u32);
        for (t, node) in t.iter_mut().zip(&self.nodes) {
            *t = node[1];
        }
        t
    }

    #[inline]
    pub(super) fn make(&mut self, x: u32, time: u32) {
        self.nodes[x as usize] = [x, time];
    }

    #[inline]
    pub(super) fn find(&mut self, mut x: u32) -> u32 {
        loop {
            let p = self.nodes[x as usize][0];
            if p == x {
                return x;
            }
            let g = self.nodes[p as usize][0];
            if g == p {
                return p;
            }
            self.nodes[x as usize][0] = g;
            x = g;
        }
    }

    /// Joins the components of `x` and `y`; the one whose root time is `keep`-er (smaller
    /// with `keep_small`) stays root. Returns the lost root's time, `None` if already one.
    #[inline]
    pub(super) fn union(&mut self, x: u32, y: u32, keep_small: bool) -> Option<u32> {
        let (a, b) = (self.find(x), self.find(y));
        if a == b {
            return None;
        }
        let (ta, tb) = (self.nodes[a as usize][1], self.nodes[b as usize][1]);
        let a_stays = if keep_small { ta < tb } else { ta > tb };
        let (stay, lose, t) = if a_stays { (a, b, tb) } else { (b, a, ta) };
        self.nodes[lose as usize][0] = stay;
        Some(t)
    }
}

/// How many pixels ahead of the sweep their rows are read in (see [`touch_ahead`]).
pub(super) const AHEAD: usize = 12;

/// Reads the entry (node or rank) of the pixel `AHEAD` steps after `r` in the sweep's
/// direction (`dir` 1: forward, 0: `r` is that pixel's step already) and the entries of the
/// rows above and below:
/// the loads start early and overlap with the current step's work, so the step that needs
/// them finds them in cache (the sweep visits pixels in value order, all over the image).
#[inline]
pub(super) fn touch_ahead<T>(nodes: &[T], order: &[u32], r: usize, cols: usize, dir: usize) {
    let Some(&q) = order.get(r + dir * AHEAD) else { return };
    let q = q as usize;
    prefetch(nodes, q);
    prefetch(nodes, q.wrapping_sub(cols));
    prefetch(nodes, q + cols);
}

/// Reads `data` at `at + i · steps[0] + j · steps[1]` for the `(i, j)` of `rows` (rows of
/// a 3-D array around a point) so that their cache lines load while the current step
/// works: the sweeps visit the voxels in value order, all over the array. Only the rows the
/// step will read: more hints than the processor has loads in flight hold it up.
#[inline]
pub(super) fn touch_rows<T>(data: &[T], at: usize, steps: [usize; 2], rows: &[(isize, isize)]) {
    for &(i, j) in rows {
        prefetch(data, at.wrapping_add_signed(i * steps[0] as isize + j * steps[1] as isize));
    }
}

/// The nine rows around a point.
pub(super) const BLOCK: [(isize, isize); 9] =
    [(-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 0), (0, 1), (1, -1), (1, 0), (1, 1)];

/// A point's row and the four next to it (its six neighbours).
pub(super) const CROSS: [(isize, isize); 5] = [(0, 0), (-1, 0), (1, 0), (0, -1), (0, 1)];

/// The rows of the points below a point along the first two axes (V: lower corners of the
/// cubes and 2-cells at a point).
pub(super) const LOWER: [(isize, isize); 4] = [(-1, -1), (-1, 0), (0, -1), (0, 0)];

/// The rows of the points above (T: the corners of a voxel of lower corner the point).
pub(super) const UPPER: [(isize, isize); 4] = [(0, 0), (0, 1), (1, 0), (1, 1)];
