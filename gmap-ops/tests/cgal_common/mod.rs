//! The checks of the CGAL test-suite port: CGAL's `check_number_of_cells_*` (the map is
//! valid, then its cells of every dimension and its components are as CGAL asserts), with
//! the CGAL file and line of each step in the failure message, and a count of the steps.

#![allow(dead_code)]

use gmap_core::{Attributes, GMap};

/// The steps of one CGAL test header, counted as they pass.
pub struct Steps {
    file: &'static str,
    passed: usize,
}

impl Steps {
    /// No step yet of `file`.
    pub fn new(file: &'static str) -> Self {
        Steps { file, passed: 0 }
    }

    /// One boolean assertion of CGAL's header (an isomorphism, a shape test, a degree).
    #[track_caller]
    pub fn assert(&mut self, line: u32, ok: bool, what: &str) {
        assert!(ok, "{}:{line}: {what} fails", self.file);
        self.passed += 1;
    }

    /// One equality of CGAL's header.
    #[track_caller]
    pub fn equal<T: PartialEq + std::fmt::Debug>(&mut self, line: u32, got: T, want: T, what: &str) {
        assert_eq!(got, want, "{}:{line}: {what}", self.file);
        self.passed += 1;
    }

    /// The number of steps that passed.
    pub fn done(&self) -> usize {
        self.passed
    }
}

/// CGAL's `check_number_of_cells_n`: the map is valid (BO Def. 1, attributes and points
/// consistent), and `want` lists its i-cells for every i, then its components.
#[track_caller]
pub fn check<A: Attributes>(s: &mut Steps, line: u32, g: &GMap<A>, want: &[usize]) {
    if let Err(e) = g.validate() {
        panic!("{}:{line}: the map is not valid: {e}", s.file);
    }
    let mut got = g.cell_counts();
    got.push(g.component_count());
    assert_eq!(got, want, "{}:{line}: cells of every dimension, then components", s.file);
    s.passed += 1;
}

/// CGAL's `is_isomorphic_to` without attributes.
pub fn isomorphic<A: Attributes, B: Attributes>(a: &GMap<A>, b: &GMap<B>) -> bool {
    gmap_ops::iso::are_isomorphic(&a.to_dense_map(), &b.to_dense_map())
}
