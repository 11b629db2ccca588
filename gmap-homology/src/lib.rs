//! # gmap-homology: homology on the cells of a generalized map

pub mod ep;
