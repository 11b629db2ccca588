//! The page of `gmap::view` for Python: `obj.view(path)` writes it (or returns it), and
//! `obj._repr_html_()` embeds it in a notebook as an `<iframe srcdoc="…">`. The two methods
//! are defined once, in `gmap/__init__.py`, for the five classes, on [`_page`] and
//! [`_page_frame`].
//!
//! The page is self-contained (its script, styles and data inline), so the iframe needs
//! nothing but the escaped text; a page over [`INLINE_LIMIT`] bytes is not embedded (a
//! notebook keeps its outputs in the `.ipynb` file) and a short note says how to write it to
//! a file instead.

use std::path::PathBuf;

use gmap::{Input, ViewOptions};
use pyo3::prelude::*;

use crate::errors::{Failure, Kind};
use crate::gmapobj::PyGMap;
use crate::objects::{PyArchComplex, PyCubicalSet, PyImage, PySimplicialComplex};

/// The largest page embedded inline by `_repr_html_`, in bytes.
pub const INLINE_LIMIT: usize = 8 << 20;

/// The height of the inline frame, in CSS pixels.
pub const FRAME_HEIGHT: u32 = 600;

/// The page of an input, built with the GIL released.
pub fn page(py: Python<'_>, input: &Input, generators: bool, color_by: Option<String>) -> PyResult<String> {
    let mut o = ViewOptions::default();
    o.generators = generators;
    o.color_by = color_by;
    Ok(py.allow_threads(|| gmap::view(input, &o)).map_err(Failure::from)?)
}

/// The facade input of a package object (a GMap's is a copy of its map with its labels).
fn with_input<T>(x: &Bound<'_, PyAny>, f: impl FnOnce(&Input) -> PyResult<T>) -> PyResult<T> {
    if let Ok(m) = x.downcast::<PyGMap>() {
        let input = crate::gmapobj::read(m)?.input();
        return f(&input);
    }
    if let Ok(s) = x.downcast::<PySimplicialComplex>() {
        return f(&s.get().input);
    }
    if let Ok(c) = x.downcast::<PyCubicalSet>() {
        return f(&c.get().input);
    }
    if let Ok(img) = x.downcast::<PyImage>() {
        return f(&img.get().input);
    }
    if let Ok(a) = x.downcast::<PyArchComplex>() {
        return f(&a.get().input);
    }
    Err(Failure::input(format!("no page for a {}", x.get_type().name()?)).into())
}

/// _page(x, path, generators, color_by): `x.view(...)`: the page written to `path`
/// (returned as a str), or its text when `path` is None.
#[pyfunction]
#[pyo3(signature = (x, path = None, generators = false, color_by = None))]
pub fn _page(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    path: Option<PathBuf>,
    generators: bool,
    color_by: Option<String>,
) -> PyResult<String> {
    let html = with_input(x, |input| page(py, input, generators, color_by))?;
    match path {
        None => Ok(html),
        Some(p) => {
            // written as `gmap view` writes it: a temporary file renamed over the path
            py.allow_threads(|| gmap::core::io::write_atomic(&p, html.as_bytes()))
                .map_err(|e| Failure::new(Kind::Io, format!("{}: {e}", p.display())))?;
            Ok(p.to_string_lossy().into_owned())
        }
    }
}

/// _page_frame(x): `x._repr_html_()`, the notebook's inline view: the page in an iframe,
/// or a note when it is too big.
#[pyfunction]
pub fn _page_frame(py: Python<'_>, x: &Bound<'_, PyAny>) -> PyResult<String> {
    let html = with_input(x, |input| page(py, input, false, None))?;
    Ok(frame(&html))
}

/// The iframe embedding `html`, or the note that replaces a page over [`INLINE_LIMIT`].
pub fn frame(html: &str) -> String {
    if html.len() > INLINE_LIMIT {
        return format!(
            "<p><b>gmap</b>: the page of this input is {:.1} MB, more than the {} MB shown inline; \
             write it to a file with <code>obj.view(\"page.html\")</code> and open that in a browser.</p>",
            html.len() as f64 / 1e6,
            INLINE_LIMIT >> 20
        );
    }
    format!(
        "<iframe srcdoc=\"{}\" style=\"width: 100%; height: {FRAME_HEIGHT}px; border: 1px solid #ccc\" \
         sandbox=\"allow-scripts\" title=\"gmap view\"></iframe>",
        gmap::ops::export::html::escape_html(html)
    )
}
