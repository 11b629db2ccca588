//! Boundary-incomplete stratified objects (EO).
