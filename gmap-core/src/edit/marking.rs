//! Marks and orientation on a [`GMap`]: reserving and freeing marks, marking darts and
//! orbits, and orienting a component (a mark on one dart of each pair that `alpha_i` joins).

use super::*;

impl<A: Attributes> GMap<A> {
    /// Reserves a mark (no fixed cap). See [`Marks`].
    pub fn reserve_mark(&mut self) -> MarkId {
        self.marks.reserve()
    }

    /// Frees a mark.
    pub fn free_mark(&mut self, m: MarkId) {
        self.marks.free(m)
    }

    /// Marks dart `d`; returns whether it was marked already.
    ///
    /// # Panics
    /// On a stale handle: marks are stored by slot, and the handle of a removed dart must not
    /// mark the dart that reuses its slot. [`GMap::try_mark`] returns the error.
    #[track_caller]
    pub fn mark(&mut self, m: MarkId, d: DartId) -> bool {
        match self.try_mark(m, d) {
            Ok(was) => was,
            Err(e) => refuse(e),
        }
    }

    /// [`GMap::mark`], or [`EditError::NoSuchDart`] (and no change) for a stale handle.
    pub fn try_mark(&mut self, m: MarkId, d: DartId) -> Result<bool, EditError> {
        self.live(d)?;
        let k = self.dart_index(d);
        Ok(self.marks.mark(m, k))
    }

    /// Unmarks dart `d`.
    ///
    /// # Panics
    /// On a stale handle, like [`GMap::mark`].
    #[track_caller]
    pub fn unmark(&mut self, m: MarkId, d: DartId) {
        if let Err(e) = self.live(d) {
            refuse(e)
        }
        let k = self.dart_index(d);
        self.marks.unmark(m, k)
    }

    /// Whether dart `d` is marked.
    ///
    /// # Panics
    /// On a stale handle, like [`GMap::mark`].
    #[track_caller]
    pub fn is_marked(&self, m: MarkId, d: DartId) -> bool {
        if let Err(e) = self.live(d) {
            refuse(e)
        }
        self.marks.is_marked(m, self.dart_index(d))
    }

    /// Unmarks every dart, in bulk.
    pub fn clear_mark(&mut self, m: MarkId) {
        self.marks.clear(m)
    }

    /// Orients the connected component of `d` in mark `m`: marks the class of `d` (the
    /// darts reached from `d` through an even number of involutions that do not fix them)
    /// and unmarks the other class, and returns the size of the marked class. A G-map
    /// stores no orientation: an orientation of an orientable component is the choice of
    /// one of its two classes (BO Def. 7, 8), here recorded as a mark.
    /// [`EditError::NotOrientable`] (and no change) when the component has no 2-colouring,
    /// [`EditError::NoSuchDart`] for a stale handle. O(component size · n).
    pub fn orient(&mut self, m: MarkId, d: DartId) -> Result<usize, EditError> {
        self.live(d)?;
        let mut colour: HashMap<DartId, bool> = HashMap::default();
        colour.insert(d, true);
        let mut queue = vec![d];
        let mut k = 0;
        while k < queue.len() {
            let x = queue[k];
            k += 1;
            let cx = colour[&x];
            for i in 0..=self.dim {
                let y = self.darts.alpha(x, i);
                if y == x {
                    continue;
                }
                match colour.get(&y) {
                    Some(&cy) if cy == cx => return Err(EditError::NotOrientable { dart: x, alpha: i, other: y }),
                    Some(_) => {}
                    None => {
                        colour.insert(y, !cx);
                        queue.push(y);
                    }
                }
            }
        }
        let mut positive = 0;
        for (&x, &c) in &colour {
            let idx = dart_index(x);
            if c {
                self.marks.mark(m, idx);
                positive += 1;
            } else {
                self.marks.unmark(m, idx);
            }
        }
        Ok(positive)
    }

    /// Whether mark `m` is an orientation of the component of `d`: every involution that
    /// moves a dart of it links a marked dart to an unmarked one. The precondition of
    /// [`GMap::reverse_orientation`]. O(component size · n); false for a stale handle.
    pub fn is_orientation(&self, m: MarkId, d: DartId) -> bool {
        self.contains(d)
            && self.orbit_iter(d, AlphaSet::all(self.dim)).all(|x| {
                let mx = self.marks.is_marked(m, dart_index(x));
                (0..=self.dim).all(|i| {
                    let y = self.darts.alpha(x, i);
                    y == x || self.marks.is_marked(m, dart_index(y)) != mx
                })
            })
    }

    /// Reverses the orientation held in mark `m` on the component of `d`: the two classes
    /// swap, so every dart of the component changes mark. The map itself does not change
    /// (a G-map holds both orientations of an orientable object; the mark is the
    /// orientation-dependent data). Precondition: [`GMap::is_orientation`]`(m, d)`, as
    /// [`GMap::orient`] leaves it; otherwise every mark of the component is still toggled.
    /// O(component size · n).
    ///
    /// # Panics
    /// On a stale handle.
    #[track_caller]
    pub fn reverse_orientation(&mut self, m: MarkId, d: DartId) {
        if let Err(e) = self.live(d) {
            refuse(e)
        }
        let comp: Vec<DartId> = self.orbit_iter(d, AlphaSet::all(self.dim)).collect();
        for x in comp {
            let idx = dart_index(x);
            if self.marks.is_marked(m, idx) {
                self.marks.unmark(m, idx);
            } else {
                self.marks.mark(m, idx);
            }
        }
    }

    /// Marks every dart of the orbit `<set>(d)`.
    pub fn mark_orbit(&mut self, m: MarkId, d: DartId, set: AlphaSet) {
        for x in self.orbit(d, set) {
            self.mark(m, x);
        }
    }
}
