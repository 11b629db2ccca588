//! Architectural complexes (AC), Euler–Poincaré operators, LAR and TM models, and their file formats.

pub mod arch;
pub mod cubical;
pub mod dot;
pub mod ep;
pub mod graphml;
pub mod json;
pub mod lar;
pub mod simplices;
pub mod tm;
mod unique_keys;
mod wire;
