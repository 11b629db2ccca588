//! Perseus's cubical text format, as GUDHI reads it (`perseus_file`): one number a line,
//! `#` lines and blank lines skipped; the dimension `d`, then `d` sizes (the first axis
//! fastest; a negative size makes its axis periodic), then one value per top-dimensional
//! cell in that order (Fortran order over the sizes). Nothing but comments may follow.

use super::common::{FileError, ImportError};

/// The most axes a Perseus file may have here (the images' limit).
pub const MAX_AXES: usize = super::image::MAX_DIM;

/// A Perseus cubical file: the sizes (first axis fastest), which axes wrap, and the
/// values of the top-dimensional cells in Fortran order.
#[derive(Clone, Debug, PartialEq)]
pub struct PerseusCubical {
    /// the number of top cells along each axis
    pub sizes: Vec<usize>,
    /// whether each axis is periodic (its size was negative)
    pub periodic: Vec<bool>,
    /// the value of each top cell, the first axis fastest
    pub values: Vec<f64>,
}

fn syntax(line: usize, message: String) -> ImportError {
    ImportError::Syntax { line, message }
}

/// Parses a Perseus cubical file's text. Refuses, naming the line: a dimension that is
/// not 1 to [`MAX_AXES`], a size that is not a non-zero integer, a value that is not a
/// number (or is NaN), a file that ends before the last value (saying how many were read),
/// and a line other than a comment after it. An empty file is [`ImportError::Empty`].
pub fn parse_perseus_cubical(text: &str) -> Result<PerseusCubical, ImportError> {
    let mut lines =
        text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let first = |l: &str| l.split_whitespace().next().unwrap_or("").to_string();
    let (line, d) = lines.next().ok_or(ImportError::Empty)?;
    let d: usize = first(d)
        .parse()
        .ok()
        .filter(|d| (1..=MAX_AXES).contains(d))
        .ok_or_else(|| syntax(line, format!("the dimension {d:?} is not an integer from 1 to {MAX_AXES}")))?;
    let (mut sizes, mut periodic) = (Vec::with_capacity(d), Vec::with_capacity(d));
    for k in 0..d {
        let (line, s) = lines.next().ok_or_else(|| syntax(line, format!("the file ends after {k} of {d} sizes")))?;
        let s: i64 = first(s)
            .parse()
            .ok()
            .filter(|&s: &i64| s != 0)
            .ok_or_else(|| syntax(line, format!("the size {s:?} is not a non-zero integer")))?;
        sizes.push(usize::try_from(s.unsigned_abs()).map_err(|_| syntax(line, format!("the size {s} is too large")))?);
        periodic.push(s < 0);
    }
    let n = sizes
        .iter()
        .try_fold(1usize, |p, &s| p.checked_mul(s))
        .ok_or_else(|| syntax(line, format!("the sizes {sizes:?} overflow a cell count")))?;
    let mut values = Vec::new();
    values.try_reserve_exact(n).map_err(|_| syntax(line, format!("cannot hold {n} values")))?;
    let mut last = line;
    while values.len() < n {
        let (line, v) = lines.next().ok_or_else(|| {
            syntax(last, format!("the file ends after {} of {n} values of a {sizes:?} complex", values.len()))
        })?;
        let v: f64 = first(v)
            .parse()
            .ok()
            .filter(|v: &f64| !v.is_nan())
            .ok_or_else(|| syntax(line, format!("the value {v:?} is not a number")))?;
        values.push(v);
        last = line;
    }
    if let Some((line, l)) = lines.next() {
        return Err(syntax(line, format!("more lines after the {n} values: {l:?}")));
    }
    Ok(PerseusCubical { sizes, periodic, values })
}

/// Reads a Perseus cubical file ([`parse_perseus_cubical`]).
pub fn read_perseus_cubical(path: &std::path::Path) -> Result<PerseusCubical, FileError> {
    let text = super::common::read_text(path)?;
    parse_perseus_cubical(&text).map_err(|e| FileError::new(path, e))
}

#[cfg(test)]
mod tests;
