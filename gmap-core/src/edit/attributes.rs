//! The attributes of a [`GMap`]'s cells: reading, setting and removing the value of a dart's
//! i-cell, by dart or by id, and the merge and split hooks that `sew`, `unsew` and the Euler
//! operators call (the design is in [`crate::attr`]).

use super::*;

impl<A: Attributes> GMap<A> {
    /// Checks that the map has I-cells.
    pub(super) fn has_cells(&self, i: usize) -> Result<(), EditError> {
        if i > self.dim {
            Err(EditError::NoSuchCells { cell: i, dim: self.dim })
        } else {
            Ok(())
        }
    }

    /// The attribute of the I-cell of `d`, if the cell has one. O(1).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_attribute`] returns the error.
    #[track_caller]
    pub fn attribute<const I: usize>(&self, d: DartId) -> Option<&<A as AttributeAt<I>>::Value>
    where
        A: AttributeAt<I>,
    {
        match self.try_attribute::<I>(d) {
            Ok(v) => v,
            Err(e) => refuse(e),
        }
    }

    /// [`GMap::attribute`], or [`EditError::NoSuchDart`] for a stale handle.
    pub fn try_attribute<const I: usize>(&self, d: DartId) -> Result<Option<&<A as AttributeAt<I>>::Value>, EditError>
    where
        A: AttributeAt<I>,
    {
        self.live(d)?;
        Ok(self.attrs.cells().get_at(dart_index(d)))
    }

    /// The attribute of the I-cell of `d`, mutably. O(1).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_attribute_mut`] returns the error.
    #[track_caller]
    pub fn attribute_mut<const I: usize>(&mut self, d: DartId) -> Option<&mut <A as AttributeAt<I>>::Value>
    where
        A: AttributeAt<I>,
    {
        if let Err(e) = self.live(d) {
            refuse(e)
        }
        self.attrs.cells_mut().get_at_mut(dart_index(d))
    }

    /// [`GMap::attribute_mut`], or [`EditError::NoSuchDart`] for a stale handle.
    pub fn try_attribute_mut<const I: usize>(
        &mut self,
        d: DartId,
    ) -> Result<Option<&mut <A as AttributeAt<I>>::Value>, EditError>
    where
        A: AttributeAt<I>,
    {
        self.live(d)?;
        Ok(self.attrs.cells_mut().get_at_mut(dart_index(d)))
    }

    /// The id of the attribute of the I-cell of `d`, if it has one. O(1).
    ///
    /// # Panics
    /// On a stale handle.
    #[track_caller]
    pub fn attribute_id<const I: usize>(&self, d: DartId) -> Option<AttrId>
    where
        A: AttributeAt<I>,
    {
        if let Err(e) = self.live(d) {
            refuse(e)
        }
        self.attrs.cells().id_at(dart_index(d))
    }

    /// The attribute with id `id`, or `None` when it was freed. O(1).
    pub fn attribute_by_id<const I: usize>(&self, id: AttrId) -> Option<&<A as AttributeAt<I>>::Value>
    where
        A: AttributeAt<I>,
    {
        self.attrs.cells().get_id(id)
    }

    /// The attribute with id `id`, mutably, or `None` when it was freed. O(1).
    pub fn attribute_by_id_mut<const I: usize>(&mut self, id: AttrId) -> Option<&mut <A as AttributeAt<I>>::Value>
    where
        A: AttributeAt<I>,
    {
        self.attrs.cells_mut().get_id_mut(id)
    }

    /// A dart of the cell of the attribute `id`, or `None` when it was freed (or when the
    /// darts of its cell were removed without reconciling). O(1).
    pub fn attribute_dart<const I: usize>(&self, id: AttrId) -> Option<DartId>
    where
        A: AttributeAt<I>,
    {
        let cells = self.attrs.cells();
        cells.dart_of(id).filter(|&d| self.contains(d) && cells.id_at(dart_index(d)) == Some(id))
    }

    /// Whether the attribute `id` is held by a live dart (CGAL's `is_attribute_used<I>`):
    /// false once it was freed, merged into another or left by the removal of its darts.
    /// O(1).
    ///
    /// ```
    /// use gmap_core::{Cells, GMap};
    /// let mut g: GMap<((), Cells<u8>)> = GMap::with_attributes(1);
    /// let e = g.make_edge();
    /// let id = g.set_attribute::<1>(e, 7);
    /// assert!(g.is_attribute_used::<1>(id));
    /// g.clear();
    /// assert!(!g.is_attribute_used::<1>(id));
    /// ```
    pub fn is_attribute_used<const I: usize>(&self, id: AttrId) -> bool
    where
        A: AttributeAt<I>,
    {
        self.attribute_dart::<I>(id).is_some()
    }

    /// The id of the point of the vertex of `d`, if it has one: the vertex attribute of a
    /// linear cell complex (CGAL's `attribute<0>(d)` there). O(1).
    ///
    /// # Panics
    /// On a stale handle.
    #[track_caller]
    pub fn point_attribute(&self, d: DartId) -> Option<AttrId> {
        if let Err(e) = self.live(d) {
            refuse(e)
        }
        self.points.id_at(dart_index(d))
    }

    /// Whether the point `id` (from [`GMap::point_attribute`]) is still the point of a
    /// vertex with live darts (CGAL's `is_attribute_used<0>` on a linear cell complex).
    /// O(1).
    pub fn is_point_used(&self, id: AttrId) -> bool {
        self.points.dart_of(id).is_some_and(|d| self.contains(d) && self.points.id_at(dart_index(d)) == Some(id))
    }

    /// Sets the attribute of the I-cell of `d`, for every dart of the cell, replacing the
    /// cell's value if it has one; returns its id (the same id when a value is replaced).
    /// O(1) when the cell has a value, O(cell size · n) otherwise.
    ///
    /// # Panics
    /// On a stale handle or `I > n`; [`GMap::try_set_attribute`] returns the error.
    #[track_caller]
    pub fn set_attribute<const I: usize>(&mut self, d: DartId, value: <A as AttributeAt<I>>::Value) -> AttrId
    where
        A: AttributeAt<I>,
    {
        match self.try_set_attribute::<I>(d, value) {
            Ok(id) => id,
            Err(e) => refuse(e),
        }
    }

    /// [`GMap::set_attribute`], or an error (and no change) for a stale handle or `I > n`.
    pub fn try_set_attribute<const I: usize>(
        &mut self,
        d: DartId,
        value: <A as AttributeAt<I>>::Value,
    ) -> Result<AttrId, EditError>
    where
        A: AttributeAt<I>,
    {
        self.has_cells(I)?;
        self.live(d)?;
        let topo = Topo { dim: self.dim, darts: &self.darts };
        Ok(self.attrs.cells_mut().set(&topo, I, d, value))
    }

    /// Removes the attribute of the I-cell of `d` (from every dart of the cell) and returns
    /// it. O(cell size · n).
    ///
    /// # Panics
    /// On a stale handle; [`GMap::try_remove_attribute`] returns the error.
    #[track_caller]
    pub fn remove_attribute<const I: usize>(&mut self, d: DartId) -> Option<<A as AttributeAt<I>>::Value>
    where
        A: AttributeAt<I>,
    {
        match self.try_remove_attribute::<I>(d) {
            Ok(v) => v,
            Err(e) => refuse(e),
        }
    }

    /// [`GMap::remove_attribute`], or [`EditError::NoSuchDart`] (and no change) for a stale
    /// handle.
    pub fn try_remove_attribute<const I: usize>(
        &mut self,
        d: DartId,
    ) -> Result<Option<<A as AttributeAt<I>>::Value>, EditError>
    where
        A: AttributeAt<I>,
    {
        self.live(d)?;
        if I > self.dim {
            return Ok(None);
        }
        let topo = Topo { dim: self.dim, darts: &self.darts };
        Ok(self.attrs.cells_mut().remove(&topo, I, d))
    }

    /// The attributes of the I-cells, with their ids, lazily (one per cell that has one; use
    /// [`GMap::attribute_dart`] for a dart of each). O(capacity of the slot) in total.
    pub fn attributes<const I: usize>(&self) -> impl Iterator<Item = (AttrId, &<A as AttributeAt<I>>::Value)> + '_
    where
        A: AttributeAt<I>,
    {
        self.attrs.cells().iter()
    }

    /// Number of I-cells with an attribute. O(1).
    pub fn attribute_count<const I: usize>(&self) -> usize
    where
        A: AttributeAt<I>,
    {
        self.attrs.cells().len()
    }

    /// Sets the function called when two I-cells that both carry an attribute become one:
    /// `f(kept, other)`, `kept` the attribute that stays (the first dart's, for a sew) and
    /// `other` the one that disappears. Without it the kept value stays as it is.
    /// The hook is shared by clones of the map.
    pub fn set_on_merge<const I: usize>(
        &mut self,
        f: impl Fn(&mut <A as AttributeAt<I>>::Value, <A as AttributeAt<I>>::Value) + Send + Sync + 'static,
    ) where
        A: AttributeAt<I>,
    {
        self.attrs.cells_mut().set_on_merge(std::sync::Arc::new(f));
    }

    /// Sets the function called when an I-cell that carries an attribute becomes two:
    /// `f(kept, copy)`, `copy` a clone of `kept` that goes to the new cell. Without it the
    /// copy stays a plain clone. The hook is shared by clones of the map.
    pub fn set_on_split<const I: usize>(
        &mut self,
        f: impl Fn(&mut <A as AttributeAt<I>>::Value, &mut <A as AttributeAt<I>>::Value) + Send + Sync + 'static,
    ) where
        A: AttributeAt<I>,
    {
        self.attrs.cells_mut().set_on_split(std::sync::Arc::new(f));
    }
}
