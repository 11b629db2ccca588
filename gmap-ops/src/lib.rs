//! # gmap-ops: making and changing generalized maps
