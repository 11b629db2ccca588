//! A G-map's cells and their signed incidences (BO Def. 9, 10), the conditions C1/C2 under which they give the homology, and the simplicial counterpart (BO §6).

pub mod border;
pub mod checked;
pub mod incidence;
pub mod oriented;
pub mod precond;
pub mod simplicial;
