//! The cells' values of one dimension edited in place: setting and removing a value,
//! forgetting a dart, and the reconciliation after an edit (merge and split hooks), with the
//! check that every dart of a cell reaches the cell's value (the design is in
//! [`crate::attr`]).

use super::*;
use rustc_hash::FxHashMap;
use smallvec::SmallVec;

impl<T: Clone> Cells<T> {
    /// Sets the value of the i-cell of `d`, replacing the cell's value if it has one, and
    /// returns its id. O(1) when the cell has a value, O(cell size · n) otherwise.
    pub(crate) fn set(&mut self, topo: &Topo, i: usize, d: DartId, value: T) -> AttrId {
        self.ensure(topo.bound());
        let k = dart_index(d);
        match self.handle(k) {
            NONE => {
                let h = self.alloc(value, d);
                self.next_epoch(topo.bound());
                let mut cell = std::mem::take(&mut self.scratch);
                cell.clear();
                self.walk(topo, i, d, &mut cell);
                for &x in &cell {
                    let old = self.handles[dart_index(x)];
                    if old != NONE {
                        // a cell whose darts disagree (edited without reconciling): the
                        // new value replaces every old one
                        self.unref(old);
                    }
                    self.handles[dart_index(x)] = h;
                }
                self.entries[h as usize].refs = cell.len() as u32;
                self.scratch = cell;
                self.id(h)
            }
            h => {
                self.entries[h as usize].value = Some(value);
                self.id(h)
            }
        }
    }

    /// Gives a new value to the i-cell whose darts are exactly `cell`, none of them holding a
    /// value (the caller's precondition: a cell just made), without walking it. `bound` is
    /// [`Topo::bound`]. O(|cell|).
    pub(crate) fn set_fresh(&mut self, bound: usize, cell: &[DartId], value: T) -> AttrId {
        self.ensure(bound);
        let h = self.alloc(value, cell[0]);
        for &x in cell {
            self.handles[dart_index(x)] = h;
        }
        self.entries[h as usize].refs = cell.len() as u32;
        self.id(h)
    }

    /// Gives the i-cells their values from an id per dart: the dart of index `k` takes
    /// `values[ids[k]]` (`u32::MAX`, or an id whose value is `None`: no value). `ids` has one
    /// entry per dart index below [`Topo::bound`] (entries of free slots are ignored). The
    /// slot must hold no value yet, and the ids must be constant on each i-cell (the same id
    /// along every `alpha_j`, `j != i`); two i-cells with the same id would share one value,
    /// which is the caller's precondition to rule out. Errors (and no change): a slot holding
    /// values, a length or an id out of range, two neighbours in one cell with different
    /// ids. Returns the number of values set. O(N n), no walk per cell.
    pub(crate) fn set_by_ids(
        &mut self,
        topo: &Topo,
        i: usize,
        ids: &[u32],
        mut values: Vec<Option<T>>,
    ) -> Result<usize, AttributeDefect> {
        let bound = topo.bound();
        let bad = |reason: String| AttributeDefect::BadIds { dim: i, reason };
        if self.live > 0 {
            return Err(bad(format!("{} values are set already", self.live)));
        }
        if ids.len() != bound {
            return Err(bad(format!("{} ids for {bound} dart indices", ids.len())));
        }
        for k in (1..bound).filter(|&k| topo.darts.slot_live(k)) {
            let id = ids[k];
            if id != NONE && id as usize >= values.len() {
                return Err(bad(format!("dart index {k} has the id {id}, past the {} values", values.len())));
            }
            for j in (0..=topo.dim).filter(|&j| j != i) {
                let y = topo.darts.slot_alpha(k as u32, j) as usize;
                if ids[y] != id {
                    return Err(bad(format!(
                        "dart indices {k} and {y} are neighbours by alpha_{j} in one {i}-cell but have the ids {id} and {}",
                        ids[y]
                    )));
                }
            }
        }
        self.ensure(bound);
        self.entries.reserve(values.iter().filter(|v| v.is_some()).count());
        let mut handle_of = vec![NONE; values.len()];
        for k in (1..bound).filter(|&k| topo.darts.slot_live(k)) {
            let id = ids[k];
            if id == NONE {
                continue;
            }
            let mut h = handle_of[id as usize];
            if h == NONE {
                let Some(v) = values[id as usize].take() else { continue };
                h = self.alloc(v, topo.darts.slot_id(k as u32));
                handle_of[id as usize] = h;
            }
            self.handles[k] = h;
            self.entries[h as usize].refs += 1;
        }
        Ok(self.live)
    }

    /// Drops one use of a handle, freeing it when no dart uses it.
    fn unref(&mut self, h: u32) {
        if let Some(e) = self.entries.get_mut(h as usize) {
            if e.value.is_some() {
                e.refs = e.refs.saturating_sub(1);
                if e.refs == 0 {
                    self.release(h);
                }
            }
        }
    }

    /// Removes the value of the i-cell of `d` and returns it. O(cell size · n).
    pub(crate) fn remove(&mut self, topo: &Topo, i: usize, d: DartId) -> Option<T> {
        let h = self.handle(dart_index(d));
        if h == NONE {
            return None;
        }
        self.next_epoch(topo.bound());
        let mut cell = std::mem::take(&mut self.scratch);
        cell.clear();
        self.walk(topo, i, d, &mut cell);
        for &x in &cell {
            let k = dart_index(x);
            if self.handles[k] == h {
                self.handles[k] = NONE;
            }
        }
        self.scratch = cell;
        self.release(h)
    }

    /// Forgets dart `d` (about to be removed): drops its use of its value, and moves the
    /// value's recorded dart to a neighbour of `d` in the same cell when `d` was it.
    pub(crate) fn drop_dart(&mut self, topo: &Topo, i: usize, d: DartId) {
        let k = dart_index(d);
        let h = self.handle(k);
        if h == NONE {
            return;
        }
        self.handles[k] = NONE;
        if self.entries[h as usize].dart == d {
            let other = (0..=topo.dim)
                .filter(|&j| j != i)
                .map(|j| topo.alpha(d, j))
                .find(|&y| y != d && self.handle(dart_index(y)) == h);
            if let Some(y) = other {
                self.entries[h as usize].dart = y;
            }
        }
        self.unref(h);
    }

    /// The consistency routine of the [module docs](self) for dimension `i`.
    pub(crate) fn reconcile(&mut self, topo: &Topo, i: usize, touched: &[DartId]) {
        if !self.active() {
            return;
        }
        self.ensure(topo.bound());
        self.next_epoch(topo.bound());
        let mut darts = std::mem::take(&mut self.scratch);
        darts.clear();
        let mut starts: SmallVec<[usize; 16]> = SmallVec::new();
        for &t in touched {
            if topo.live(t) {
                let before = darts.len();
                self.walk(topo, i, t, &mut darts);
                if darts.len() > before {
                    starts.push(before);
                }
            }
        }
        starts.push(darts.len());
        let cells = starts.len() - 1;
        // the distinct live handles of each walked cell, in the order met
        let mut held: Vec<SmallVec<[u32; 2]>> = Vec::with_capacity(cells);
        for c in 0..cells {
            let mut hs: SmallVec<[u32; 2]> = SmallVec::new();
            for &x in &darts[starts[c]..starts[c + 1]] {
                let h = self.handles[dart_index(x)];
                if h != NONE && self.entries[h as usize].value.is_some() && !hs.contains(&h) {
                    hs.push(h);
                }
            }
            held.push(hs);
        }
        // 1. splits: a handle held by several cells stays with the first, the others get copies
        let mut owner: FxHashMap<u32, usize> = FxHashMap::default();
        for (c, hs) in held.iter_mut().enumerate() {
            for h in hs.iter_mut() {
                match owner.get(h) {
                    Some(&first) if first != c => {
                        let mut copy = self.entries[*h as usize].value.clone().expect("live handle");
                        if let Some(f) = self.on_split.clone() {
                            let kept = self.entries[*h as usize].value.as_mut().expect("live handle");
                            f(kept, &mut copy);
                        }
                        *h = self.alloc(copy, darts[starts[c]]);
                    }
                    Some(_) => {}
                    None => {
                        owner.insert(*h, c);
                    }
                }
            }
        }
        // relabel every walked dart with its cell's first handle, counting uses exactly
        for (c, hs) in held.iter().enumerate() {
            let keep = hs.first().copied().unwrap_or(NONE);
            for &x in &darts[starts[c]..starts[c + 1]] {
                let k = dart_index(x);
                let old = self.handles[k];
                if old != keep {
                    if old != NONE {
                        if let Some(e) = self.entries.get_mut(old as usize) {
                            e.refs = e.refs.saturating_sub(1);
                        }
                    }
                    if keep != NONE {
                        self.entries[keep as usize].refs += 1;
                    }
                    self.handles[k] = keep;
                }
            }
            if keep != NONE {
                self.entries[keep as usize].dart = darts[starts[c]];
            }
        }
        // 2. merges: the other handles of a cell fold into its first
        for hs in &held {
            for &other in hs.iter().skip(1) {
                let v = if self.entries[other as usize].refs == 0 {
                    self.release(other).expect("live handle")
                } else {
                    self.entries[other as usize].value.clone().expect("live handle")
                };
                let kept = self.entries[hs[0] as usize].value.as_mut().expect("live handle");
                if let Some(f) = &self.on_merge {
                    f(kept, v);
                }
            }
        }
        self.scratch = darts;
    }

    /// The consistency routine for dimension `i` after a sew of index `s != i` that linked
    /// the darts of each pair of `pairs` by `alpha_s`, on a map whose i-cells were consistent
    /// before. Gives the result of [`Cells::reconcile`] on the darts of the pairs (first
    /// sides, then second sides), with the same hook calls in the same order, but uses the
    /// known pairing: a sew only merges cells, and every old cell of a merged cell holds a
    /// dart of the pairs, so the handles on the pairs tell which cells merge without walking
    /// them. When each merged cell joins at most two cells that both carry an attribute,
    /// only the darts of the cell whose value disappears are relabelled; other cases (a
    /// cell without attribute meeting one with, three or more cells becoming one) go to
    /// [`Cells::reconcile`]. O(p²) for p pairs plus O(r · n) for the r darts relabelled.
    pub(crate) fn reconcile_sewn(&mut self, topo: &Topo, i: usize, pairs: &[(DartId, DartId)]) {
        if !self.active() {
            return;
        }
        self.ensure(topo.bound());
        match self.sew_merges(pairs) {
            Some(merges) => {
                for (kept, other, from) in merges {
                    self.fold(topo, i, kept, other, from);
                }
            }
            None => {
                let touched: Vec<DartId> = pairs.iter().map(|p| p.0).chain(pairs.iter().map(|p| p.1)).collect();
                self.reconcile(topo, i, &touched);
            }
        }
    }

    /// Whether `h` names a live value.
    #[inline]
    fn is_live(&self, h: u32) -> bool {
        h != NONE && self.alive.get(h as usize / 64).is_some_and(|w| w & (1 << (h % 64)) != 0)
    }

    /// The merges a sew of `pairs` causes, as `(kept, other, a dart holding other)` in the
    /// order [`Cells::reconcile`] runs their hooks, or `None` when the sew is not the simple
    /// case of [`Cells::reconcile_sewn`].
    ///
    /// Every paired dart holding a live handle, the handles are the nodes of a graph whose
    /// edges are the pairs with different handles; a connected set of nodes is one merged
    /// cell. The general routine keeps the handle of the first paired dart (first sides
    /// come first) of each merged cell and runs the hooks cell by cell in that order. The
    /// simple case: every merged cell joins two cells, the kept one holding the first side
    /// of the pair that joins them, and the merges come in the order of their first pairs.
    fn sew_merges(&self, pairs: &[(DartId, DartId)]) -> Option<SmallVec<[(u32, u32, DartId); 4]>> {
        // the handles of the first sides in order of first appearance: a merged cell's
        // first paired dart is always a first side (its partner is in the same cell)
        let mut order: SmallVec<[u32; 16]> = SmallVec::new();
        for &(a, _) in pairs {
            let h = self.handle(dart_index(a));
            if !self.is_live(h) {
                return None;
            }
            if !order.contains(&h) {
                order.push(h);
            }
        }
        let rank = |h: u32| order.iter().position(|&x| x == h).unwrap_or(usize::MAX);
        let mut merges: SmallVec<[(u32, u32, DartId); 4]> = SmallVec::new();
        for &(a, b) in pairs {
            let (ha, hb) = (self.handle(dart_index(a)), self.handle(dart_index(b)));
            if !self.is_live(hb) {
                return None;
            }
            if ha == hb || merges.iter().any(|m| (m.0, m.1) == (ha, hb)) {
                continue;
            }
            let simple = rank(ha) < rank(hb)
                && merges.iter().all(|m| m.0 != ha && m.1 != ha && m.0 != hb && m.1 != hb)
                && merges.last().is_none_or(|m| rank(m.0) < rank(ha));
            if !simple {
                // the second side's value kept, three or more cells becoming one, or hooks
                // out of the order of the pairs
                return None;
            }
            merges.push((ha, hb, b));
        }
        Some(merges)
    }

    /// Folds the cell holding `other` (reached from its dart `from`) into the value `kept`:
    /// relabels its darts, moves the counts, frees `other` once no dart holds it and runs the
    /// merge hook on (kept, other). The darts holding `other` are connected by links that
    /// a sew leaves in place, so the walk from `from` through them finds them all. O(r · n)
    /// for the r darts relabelled.
    fn fold(&mut self, topo: &Topo, i: usize, kept: u32, other: u32, from: DartId) {
        // by slot number: the walk reads the rows of links and the handles only
        let mut stack: SmallVec<[u32; 64]> = SmallVec::new();
        let start = dart_index(from);
        self.handles[start] = kept;
        stack.push(start as u32);
        let mut moved: u32 = 1;
        while let Some(x) = stack.pop() {
            for j in (0..=topo.dim).filter(|&j| j != i) {
                let y = topo.darts.slot_alpha(x, j);
                let k = y as usize;
                if self.handles[k] == other {
                    self.handles[k] = kept;
                    moved += 1;
                    stack.push(y);
                }
            }
        }
        self.entries[kept as usize].refs += moved;
        let e = &mut self.entries[other as usize];
        e.refs = e.refs.saturating_sub(moved);
        let v =
            if e.refs == 0 { self.release(other).expect("live handle") } else { e.value.clone().expect("live handle") };
        let kept = self.entries[kept as usize].value.as_mut().expect("live handle");
        if let Some(f) = &self.on_merge {
            f(kept, v);
        }
    }

    /// Checks the invariant of dimension `i` on every live dart: neighbours in the cell hold
    /// the same handle, handles name live values, counts match, no value is held by two
    /// cells. O(N n).
    pub(crate) fn check(&self, topo: &Topo, i: usize, darts: &[DartId]) -> Result<(), AttributeDefect> {
        if !self.active() {
            return Ok(());
        }
        let mut counts = vec![0u32; self.entries.len()];
        for &d in darts {
            let h = self.handle(dart_index(d));
            if h != NONE {
                if self.entries.get(h as usize).is_none_or(|e| e.value.is_none()) {
                    return Err(AttributeDefect::Dangling { dim: i, dart: d });
                }
                counts[h as usize] += 1;
            }
            for j in (0..=topo.dim).filter(|&j| j != i) {
                let y = topo.alpha(d, j);
                if self.handle(dart_index(y)) != h {
                    return Err(AttributeDefect::Disagree {
                        dim: i,
                        dart: d,
                        other: y,
                        dart_attr: self.id_at(dart_index(d)),
                        other_attr: self.id_at(dart_index(y)),
                    });
                }
            }
        }
        for (k, e) in self.entries.iter().enumerate() {
            if e.value.is_some() && e.refs != counts[k] {
                return Err(AttributeDefect::Count {
                    dim: i,
                    attr: self.id(k as u32),
                    stored: e.refs,
                    found: counts[k],
                });
            }
        }
        // one cell per value (the cells are uniform by now): the first dart met holding a
        // value claims it for its cell; a dart of another cell holding it is a defect
        let mut visited = bitvec::vec::BitVec::<usize>::repeat(false, topo.bound());
        let mut owner: Vec<Option<DartId>> = vec![None; self.entries.len()];
        let mut stack = Vec::new();
        for &d in darts {
            let h = self.handle(dart_index(d));
            if h == NONE || visited[dart_index(d)] {
                continue;
            }
            if let Some(other) = owner[h as usize] {
                return Err(AttributeDefect::Shared { dim: i, attr: self.id(h), dart: d, other });
            }
            owner[h as usize] = Some(d);
            visited.set(dart_index(d), true);
            stack.push(d);
            while let Some(x) = stack.pop() {
                for j in (0..=topo.dim).filter(|&j| j != i) {
                    let y = topo.alpha(x, j);
                    if !visited[dart_index(y)] {
                        visited.set(dart_index(y), true);
                        stack.push(y);
                    }
                }
            }
        }
        Ok(())
    }
}
