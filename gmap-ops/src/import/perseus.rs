//! Perseus's text formats, `#` lines and blank lines skipped:
//! - cubical, as GUDHI reads it (`perseus_file`): one number a line; the dimension `d`,
//!   then `d` sizes (the first axis fastest; a negative size makes its axis periodic), then
//!   one value per top-dimensional cell in that order (Fortran order over the sizes).
//!   Nothing but comments may follow.
//! - simplicial (Perseus's `nmfsimtop`): a first line `1`, then one simplex a line: its
//!   dimension `k`, its `k + 1` vertex labels and its birth value.
//!
//! [`is_simplicial`] tells them apart: a simplicial file's second line has several numbers.

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
    let mut last = line;
    for k in 0..d {
        let (line, s) = lines.next().ok_or_else(|| syntax(last, format!("the file ends after {k} of {d} sizes")))?;
        last = line;
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
        .ok_or_else(|| syntax(last, format!("the sizes {sizes:?} overflow a cell count")))?;
    // a value takes two bytes of text at least: room for what the text can hold, no more
    let mut values = Vec::new();
    let room = n.min(text.len() / 2);
    values.try_reserve_exact(room).map_err(|_| syntax(last, format!("cannot hold {room} values")))?;
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

/// Whether Perseus text is simplicial (`nmfsimtop`: its second line has several numbers)
/// rather than cubical (one number a line).
pub fn is_simplicial(text: &str) -> bool {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with('#'));
    lines.next();
    lines.next().is_some_and(|l| l.split_whitespace().count() > 1)
}

/// Parses a Perseus simplicial file (`nmfsimtop`): the simplices (vertex labels as given)
/// and their birth values, in file order. Refuses, naming the line: a first line other
/// than `1`, a line whose count of labels is not its dimension plus one, a label that is
/// not a non-negative integer, a birth that is not a number (or is NaN). No simplex is
/// [`ImportError::Empty`].
pub fn parse_perseus_simplicial(text: &str) -> Result<(Vec<Vec<u64>>, Vec<f64>), ImportError> {
    let mut lines =
        text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (line, head) = lines.next().ok_or(ImportError::Empty)?;
    if head != "1" {
        return Err(syntax(line, format!("a Perseus simplicial file begins with the line 1, not {head:?}")));
    }
    let (mut simplices, mut values) = (Vec::new(), Vec::new());
    for (line, l) in lines {
        let t: Vec<&str> = l.split_whitespace().collect();
        let k: usize = t[0].parse().map_err(|_| syntax(line, format!("the dimension {:?} is not an integer", t[0])))?;
        // compared without forming k + 3, which overflows for k near usize::MAX
        if t.len().checked_sub(3) != Some(k) {
            return Err(syntax(
                line,
                format!(
                    "a {k}-simplex is its dimension, {} labels and a birth: {} numbers, not {}",
                    k as u128 + 1,
                    k as u128 + 3,
                    t.len()
                ),
            ));
        }
        let labels = t[1..=k + 1]
            .iter()
            .map(|x| {
                x.parse::<u64>()
                    .map_err(|_| syntax(line, format!("the vertex label {x:?} is not a non-negative integer")))
            })
            .collect::<Result<Vec<u64>, _>>()?;
        let v: f64 = t[k + 2]
            .parse()
            .ok()
            .filter(|v: &f64| !v.is_nan())
            .ok_or_else(|| syntax(line, format!("the birth {:?} is not a number", t[k + 2])))?;
        simplices.push(labels);
        values.push(v);
    }
    if simplices.is_empty() {
        return Err(ImportError::Empty);
    }
    Ok((simplices, values))
}

/// Reads a Perseus cubical file ([`parse_perseus_cubical`]).
pub fn read_perseus_cubical(path: &std::path::Path) -> Result<PerseusCubical, FileError> {
    let text = super::common::read_text(path)?;
    parse_perseus_cubical(&text).map_err(|e| FileError::new(path, e))
}

/// Reads a Perseus file of either kind ([`is_simplicial`] tells which).
pub fn read_perseus(path: &std::path::Path) -> Result<Perseus, FileError> {
    let text = super::common::read_text(path)?;
    let parsed = if is_simplicial(&text) {
        parse_perseus_simplicial(&text).map(|(s, v)| Perseus::Simplicial(s, v))
    } else {
        parse_perseus_cubical(&text).map(Perseus::Cubical)
    };
    parsed.map_err(|e| FileError::new(path, e))
}

/// A Perseus file, cubical or simplicial.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Perseus {
    /// top cells with values ([`parse_perseus_cubical`])
    Cubical(PerseusCubical),
    /// simplices with their birth values, in file order ([`parse_perseus_simplicial`])
    Simplicial(Vec<Vec<u64>>, Vec<f64>),
}

#[cfg(test)]
mod tests;
