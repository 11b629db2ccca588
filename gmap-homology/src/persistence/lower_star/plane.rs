//! 1-D and 2-D images: dimension 0 by union-find on the pixels, dimension 1 on the dual.

use gmap_core::fastdiv::Divider;

use super::sweep::{touch_ahead, Forest, Out, AHEAD};
use crate::prefetch::prefetch;

/// 2-D V-construction (a 1-D image is one row).
pub(super) fn v2(rows: usize, cols: usize, order: &[u32], mut pix: Forest, out: &mut Out) {
    let n = rows * cols;
    // (pixels are fewer than 2^32: `diagram`'s test)
    let Some(by_cols) = Divider::new(cols) else { return };
    // dimension 0: each pixel's edges to earlier neighbours
    for (r, &p) in order.iter().enumerate() {
        touch_ahead(&pix.nodes, order, r, cols, 1);
        let r = r as u32;
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        let mut link = |q: usize| {
            if pix.nodes[q][1] < r {
                if let Some(young) = pix.union(p, q as u32, true) {
                    out.push(0, young, Some(r));
                }
            }
        };
        if j > 0 {
            link(p as usize - 1);
        }
        if j + 1 < cols {
            link(p as usize + 1);
        }
        if i > 0 {
            link(p as usize - cols);
        }
        if i + 1 < rows {
            link(p as usize + cols);
        }
    }
    if rows < 2 || cols < 2 {
        return;
    }
    // dimension 1 on the dual: squares by their lower-left pixel, the outside node `n`; the
    // nodes are the pixels' again (a square's is made before it is read), the ranks copied
    // out first (half the bytes to read)
    let ranks = pix.times(n);
    let rank = |q: usize| ranks[q];
    let mut f = pix;
    let outside = n as u32;
    f.make(outside, u32::MAX);
    let square = |a: usize, b: usize| -> u32 {
        if a < rows - 1 && b < cols - 1 {
            (a * cols + b) as u32
        } else {
            outside
        }
    };
    for (r, &p) in order.iter().enumerate().rev() {
        if r >= AHEAD {
            touch_ahead(&ranks, order, r - AHEAD, cols, 0);
            // the squares at that pixel: rows i - 1 and i of the dual's nodes
            let q = order[r - AHEAD] as usize;
            prefetch(&f.nodes, q.wrapping_sub(cols));
            prefetch(&f.nodes, q);
        }
        let r = r as u32;
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        let early = |a: usize, b: usize| rank(a * cols + b) <= r;
        // the squares whose latest corner is p
        for (a, b) in [(i.wrapping_sub(1), j.wrapping_sub(1)), (i.wrapping_sub(1), j), (i, j.wrapping_sub(1)), (i, j)] {
            if a < rows - 1 && b < cols - 1 && early(a, b) && early(a + 1, b) && early(a, b + 1) && early(a + 1, b + 1)
            {
                f.make((a * cols + b) as u32, r);
            }
        }
        // the edges whose latest end is p join their two cofaces
        let mut edge = |x: u32, y: u32| {
            if let Some(young) = f.union(x, y, false) {
                out.push(1, r, Some(young));
            }
        };
        if j > 0 && rank(p as usize - 1) < r {
            edge(square(i.wrapping_sub(1), j - 1), square(i, j - 1));
        }
        if j + 1 < cols && rank(p as usize + 1) < r {
            edge(square(i.wrapping_sub(1), j), square(i, j));
        }
        if i > 0 && rank(p as usize - cols) < r {
            edge(square(i - 1, j.wrapping_sub(1)), square(i - 1, j));
        }
        if i + 1 < rows && rank(p as usize + cols) < r {
            edge(square(i, j.wrapping_sub(1)), square(i, j));
        }
    }
}

/// 2-D T-construction (a 1-D image is one row): the pixels are the top cells.
pub(super) fn t2(rows: usize, cols: usize, order: &[u32], mut pix: Forest, out: &mut Out) {
    let n = rows * cols;
    let Some(by_cols) = Divider::new(cols) else { return };
    // dimension 0: pixels sharing a vertex
    for (r, &p) in order.iter().enumerate() {
        touch_ahead(&pix.nodes, order, r, cols, 1);
        let r = r as u32;
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        for a in i.saturating_sub(1)..(i + 2).min(rows) {
            for b in j.saturating_sub(1)..(j + 2).min(cols) {
                let q = a * cols + b;
                if pix.nodes[q][1] < r {
                    if let Some(young) = pix.union(p, q as u32, true) {
                        out.push(0, young, Some(r));
                    }
                }
            }
        }
    }
    // dimension 1 on the dual: pixels sharing an edge, the border's edges to the outside;
    // the nodes are the pixels' again, the ranks copied out first
    let ranks = pix.times(n);
    let rank = |q: usize| ranks[q];
    let mut f = pix;
    let outside = n as u32;
    f.make(outside, u32::MAX);
    for (r, &p) in order.iter().enumerate().rev() {
        if r >= AHEAD {
            touch_ahead(&ranks, order, r - AHEAD, cols, 0);
            touch_ahead(&f.nodes, order, r - AHEAD, cols, 0);
        }
        let r = r as u32;
        f.make(p, r);
        let i = by_cols.quotient(p as usize);
        let j = p as usize - i * cols;
        let mut edge = |y: u32| {
            if let Some(young) = f.union(p, y, false) {
                out.push(1, r, Some(young));
            }
        };
        if i == 0 || j == 0 || i + 1 == rows || j + 1 == cols {
            edge(outside);
        }
        for q in [
            (j > 0).then(|| p as usize - 1),
            (j + 1 < cols).then(|| p as usize + 1),
            (i > 0).then(|| p as usize - cols),
            (i + 1 < rows).then(|| p as usize + cols),
        ]
        .into_iter()
        .flatten()
        {
            if rank(q) > r {
                edge(q as u32);
            }
        }
    }
}
