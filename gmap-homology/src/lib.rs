//! # gmap-homology: homology on the cells of a generalized map
