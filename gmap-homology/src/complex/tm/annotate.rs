//! Views and sections with their annotations: near/far (TM (7:3)) and from/to (TM (7:4)).

use super::{SignedSet, TmError, TmModel};

/// The n-cells on the two sides of an (n-1)-cell, read from `G c` (TM (7:3)). The positive
/// n-cell lies on the far side of each bounding (n-1)-cell it takes positively (TM §III),
/// so `far` is the cell occurring positively in `G c` and `near` the one occurring
/// negatively. In 3D these are the paper's near and far 3-cells of a 2-cell; in 2D, with
/// 2-cells to the left of their positive edges, `far` is the face left of the edge and
/// `near` the face right of it. A side with no cell (a free face of an open model) is
/// `None`; one cell on both sides (a face inside one room folding back on itself) is
/// both.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sides {
    /// the cell on the near side (negative occurrence in `G c`)
    pub near: Option<usize>,
    /// the cell on the far side (positive occurrence in `G c`)
    pub far: Option<usize>,
}

/// The two end 0-cells of a 1-cell, read from `B c` (TM (7:4)): the first 0-cell of the
/// from-to relation is taken negatively, the second positively (TM §III). A missing end is
/// `None`; a loop has the same cell at both ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ends {
    /// the 0-cell the 1-cell goes from (negative occurrence in `B c`)
    pub from: Option<usize>,
    /// the 0-cell the 1-cell goes to (positive occurrence in `B c`)
    pub to: Option<usize>,
}

/// The view of an (n-1)-cell, TM (7:1) `(1 - B)^{-1} c`, annotated with the n-cells on its
/// near and far sides, TM (7:3) (Fig. 2 of the paper, for n = 3).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct View {
    /// the viewed cell
    pub cell: usize,
    /// the cell and its complete boundary, with multiplicities
    pub cells: SignedSet,
    /// the cells on its two sides
    pub sides: Sides,
}

/// The section through a 1-cell, TM (7:2) `(1 - G)^{-1} c`, annotated with the 0-cells it
/// goes from and to, TM (7:4) (Fig. 1 of the paper).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Section {
    /// the cell cut through
    pub cell: usize,
    /// the cell and everything above it, with multiplicities
    pub cells: SignedSet,
    /// its two ends
    pub ends: Ends,
}

/// The cell occurring negatively and the one occurring positively in `s`, each only if
/// it occurs exactly once with that sign; `None` for a sign with no occurrence.
fn pair(model: &TmModel, c: usize, s: &SignedSet) -> Result<(Option<usize>, Option<usize>), TmError> {
    let (plus, minus) = s.totals();
    if plus > 1 || minus > 1 {
        return Err(TmError::NotAPair { id: model.id(c), dim: model.cell_dim(c), plus, minus });
    }
    let neg = s.iter().find(|&(_, _, m)| m > 0).map(|(x, _, _)| x);
    let pos = s.iter().find(|&(_, p, _)| p > 0).map(|(x, _, _)| x);
    Ok((neg, pos))
}

impl TmModel {
    fn require(&self, c: usize, want: usize) -> Result<(), TmError> {
        if c >= self.len() {
            return Err(TmError::NoSuchCell { index: c, len: self.len() });
        }
        if self.cell_dim(c) != want {
            return Err(TmError::WrongDimension { id: self.id(c), dim: self.cell_dim(c), expected: want });
        }
        Ok(())
    }

    /// Whether [`TmModel::try_sides`] would succeed on `c`.
    pub fn has_sides(&self, c: usize) -> bool {
        self.try_sides(c).is_ok()
    }

    /// The n-cells on the near and far sides of the (n-1)-cell `c`, TM (7:3) `G c`.
    ///
    /// Precondition ([`TmModel::has_sides`]): `n >= 1`, `c` is a cell of dimension n - 1,
    /// and `G c` has at most one occurrence of each sign. Errors: [`TmError::Pointless`]
    /// (n = 0), [`TmError::NoSuchCell`], [`TmError::WrongDimension`], [`TmError::NotAPair`]
    /// (three cells on one wall, or two on one side). O(|G c|).
    pub fn try_sides(&self, c: usize) -> Result<Sides, TmError> {
        let want = match self.dim().checked_sub(1) {
            Some(w) => w,
            None => return Err(TmError::Pointless { what: "sides of a cell" }),
        };
        self.require(c, want)?;
        let (near, far) = pair(self, c, self.cobounding(c))?;
        Ok(Sides { near, far })
    }

    /// Whether [`TmModel::try_ends`] would succeed on `c`.
    pub fn has_ends(&self, c: usize) -> bool {
        self.try_ends(c).is_ok()
    }

    /// The 0-cells the 1-cell `c` goes from and to, TM (7:4) `B c`.
    ///
    /// Precondition ([`TmModel::has_ends`]): `c` is a 1-cell and `B c` has at most one
    /// occurrence of each sign. Errors: [`TmError::NoSuchCell`], [`TmError::WrongDimension`],
    /// [`TmError::NotAPair`]. O(|B c|).
    pub fn try_ends(&self, c: usize) -> Result<Ends, TmError> {
        self.require(c, 1)?;
        let (from, to) = pair(self, c, self.bounding(c))?;
        Ok(Ends { from, to })
    }

    /// The annotated view of the (n-1)-cell `c`: (7:1) with the sides of (7:3).
    /// Precondition and errors: those of [`TmModel::try_sides`]. O(size of the view).
    pub fn try_annotated_view(&self, c: usize) -> Result<View, TmError> {
        let sides = self.try_sides(c)?;
        Ok(View { cell: c, cells: self.view(&SignedSet::cell(c)), sides })
    }

    /// The annotated section through the 1-cell `c`: (7:2) with the ends of (7:4).
    /// Precondition and errors: those of [`TmModel::try_ends`]. O(size of the section).
    pub fn try_annotated_section(&self, c: usize) -> Result<Section, TmError> {
        let ends = self.try_ends(c)?;
        Ok(Section { cell: c, cells: self.section(&SignedSet::cell(c)), ends })
    }
}
