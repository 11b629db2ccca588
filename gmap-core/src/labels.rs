//! Named labels on cells: the attribute with a text form that `.gmap` files carry.
//!
//! A [`Labels`] value is an ordered list of `(name, value)` pairs, each value an integer, a
//! real or a text ([`LabelValue`]). Any cell of any dimension can hold one through a
//! [`Cells<Labels>`](crate::Cells) slot; [`LabelledGMap`] has such a slot on every dimension
//! from 0 to 5 and is what [`crate::io::read_labelled_gmap`] and
//! [`crate::io::write_labelled_gmap`] exchange with `.gmap` files (docs/FORMATS.md, native
//! `.gmap`, sections).
//!
//! ```
//! use gmap_core::{LabelValue, Labels};
//! let mut room = Labels::new();
//! room.set("name", LabelValue::Text("kitchen".into()));
//! room.set("floor", LabelValue::Int(1));
//! room.set("area", LabelValue::Real(12.5));
//! assert_eq!(room.get("floor"), Some(&LabelValue::Int(1)));
//! assert_eq!(room.to_string(), r#"name="kitchen" floor=1 area=12.5"#);
//! ```

use std::fmt;

use crate::attr::Cells;
use crate::dense::DenseMap;
use crate::edit::{DartId, GMap};

/// The value of one label.
#[derive(Clone, Debug, PartialEq)]
pub enum LabelValue {
    /// a signed integer
    Int(i64),
    /// a finite real number
    Real(f64),
    /// a text, any characters
    Text(String),
}

/// An ordered list of named values: the labels of one cell. Names are unique (setting a
/// name again replaces its value in place).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Labels(Vec<(String, LabelValue)>);

impl Labels {
    /// No label.
    pub fn new() -> Self {
        Labels(Vec::new())
    }

    /// The value named `name`. O(number of labels).
    pub fn get(&self, name: &str) -> Option<&LabelValue> {
        self.0.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }

    /// Sets the value named `name`, keeping its place when it exists, else appending it;
    /// returns the old value. O(number of labels).
    pub fn set(&mut self, name: &str, value: LabelValue) -> Option<LabelValue> {
        match self.0.iter_mut().find(|(n, _)| n == name) {
            Some((_, v)) => Some(std::mem::replace(v, value)),
            None => {
                self.0.push((name.to_string(), value));
                None
            }
        }
    }

    /// Removes the value named `name` and returns it.
    pub fn remove(&mut self, name: &str) -> Option<LabelValue> {
        let k = self.0.iter().position(|(n, _)| n == name)?;
        Some(self.0.remove(k).1)
    }

    /// The labels in order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &LabelValue)> {
        self.0.iter().map(|(n, v)| (n.as_str(), v))
    }

    /// Number of labels.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether there is no label.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl<S: Into<String>> FromIterator<(S, LabelValue)> for Labels {
    fn from_iter<I: IntoIterator<Item = (S, LabelValue)>>(iter: I) -> Self {
        let mut l = Labels::new();
        for (n, v) in iter {
            l.set(&n.into(), v);
        }
        l
    }
}

/// A map with [`Labels`] on the cells of every dimension from 0 to 5 (slots above the map's
/// dimension stay empty), and a point per vertex: what `.gmap` files hold in full.
pub type LabelledGMap =
    GMap<(Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>)>;

/// The largest cell dimension a [`LabelledGMap`] labels.
pub const MAX_LABELLED_DIM: usize = 5;

/// The labels of the `dim`-cell of dart `d`, if that cell has a label slot set
/// (`None` above [`MAX_LABELLED_DIM`] or the map's dimension). O(1).
pub fn cell_labels(g: &LabelledGMap, dim: usize, d: DartId) -> Option<&Labels> {
    if dim > g.dim() {
        return None;
    }
    match dim {
        0 => g.attribute::<0>(d),
        1 => g.attribute::<1>(d),
        2 => g.attribute::<2>(d),
        3 => g.attribute::<3>(d),
        4 => g.attribute::<4>(d),
        5 => g.attribute::<5>(d),
        _ => None,
    }
}

/// The labels of the cells of a dense map: `of[i][c]` are those of the `i`-cell numbered
/// `c` in [`DenseMap::cells`]`(i)` (empty when the cell has none).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DenseLabels {
    /// per dimension, per cell number
    pub of: Vec<Vec<Labels>>,
}

impl DenseLabels {
    /// The labels of `i`-cell `c`; empty for a dimension or cell it does not hold.
    pub fn get(&self, i: usize, c: usize) -> &Labels {
        static NONE: Labels = Labels(Vec::new());
        self.of.get(i).and_then(|v| v.get(c)).unwrap_or(&NONE)
    }

    /// Whether no cell has a label.
    pub fn is_empty(&self) -> bool {
        self.of.iter().all(|v| v.iter().all(Labels::is_empty))
    }
}

/// Freezes a labelled map ([`GMap::to_dense_map`]) and numbers its labels like the dense map's
/// cells: `(dense map, labels, handle of each dense dart)`. O(N n²) (one cell partition
/// per dimension).
pub fn to_dense_labels(g: &LabelledGMap) -> (DenseMap, DenseLabels, Vec<DartId>) {
    let (dense, ids) = g.to_dense_with_ids();
    let mut of = Vec::with_capacity(dense.dim() + 1);
    for i in 0..=dense.dim().min(MAX_LABELLED_DIM) {
        let cells = dense.cells(i);
        of.push(cells.reps.iter().map(|&r| cell_labels(g, i, ids[r.index()]).cloned().unwrap_or_default()).collect());
    }
    (dense, DenseLabels { of }, ids)
}

/// The labels of the cells of each dimension `0..=min(n, 5)` that carry some, each cell in
/// the order of its first dart ([`GMap::darts`]): the order of [`to_dense_labels`], without
/// its dense copy of the map or its partitions (one pass over the darts a dimension, a bit a
/// value). For counts of names (`gmap info`).
pub fn labels_by_dimension(g: &LabelledGMap) -> Vec<Vec<&Labels>> {
    fn one<const I: usize>(g: &LabelledGMap) -> Vec<&Labels>
    where
        (Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>, Cells<Labels>):
            crate::attr::AttributeAt<I, Value = Labels>,
    {
        let mut seen: Vec<bool> = Vec::new();
        let mut out = Vec::new();
        if g.attribute_count::<I>() == 0 {
            return out;
        }
        for d in g.darts() {
            if let Some(id) = g.attribute_id::<I>(d) {
                let k = id.index();
                if seen.len() <= k {
                    seen.resize((k + 1).max(2 * seen.len()), false);
                }
                if !seen[k] {
                    seen[k] = true;
                    out.extend(g.attribute_by_id::<I>(id));
                }
            }
        }
        out
    }
    let f: [fn(&LabelledGMap) -> Vec<&Labels>; 6] = [one::<0>, one::<1>, one::<2>, one::<3>, one::<4>, one::<5>];
    f.iter().take(g.dim().min(MAX_LABELLED_DIM) + 1).map(|f| f(g)).collect()
}

/// Whether `name` can be written bare: `[A-Za-z_][A-Za-z0-9_.-]*`.
pub(crate) fn is_bare_name(name: &str) -> bool {
    let mut c = name.chars();
    matches!(c.next(), Some(x) if x.is_ascii_alphabetic() || x == '_')
        && c.all(|x| x.is_ascii_alphanumeric() || matches!(x, '_' | '.' | '-'))
}

/// Writes `s` in double quotes, escaping `\`, `"` and every control character, so that the
/// result is one line.
pub(crate) fn write_quoted(f: &mut impl fmt::Write, s: &str) -> fmt::Result {
    f.write_char('"')?;
    for c in s.chars() {
        match c {
            '"' => f.write_str("\\\"")?,
            '\\' => f.write_str("\\\\")?,
            '\n' => f.write_str("\\n")?,
            '\r' => f.write_str("\\r")?,
            '\t' => f.write_str("\\t")?,
            c if c.is_control() => write!(f, "\\u{{{:x}}}", c as u32)?,
            c => f.write_char(c)?,
        }
    }
    f.write_char('"')
}

impl fmt::Display for LabelValue {
    /// `42`, `1.5` (a real always shows a `.` or an exponent), `"text"` (quoted, escaped).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LabelValue::Int(v) => write!(f, "{v}"),
            LabelValue::Real(v) => write!(f, "{v:?}"),
            LabelValue::Text(s) => write_quoted(f, s),
        }
    }
}

impl fmt::Display for Labels {
    /// `name=value` pairs separated by one space; a name that is not an identifier is
    /// quoted like a text.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, (n, v)) in self.0.iter().enumerate() {
            if k > 0 {
                f.write_str(" ")?;
            }
            if is_bare_name(n) {
                f.write_str(n)?;
            } else {
                write_quoted(f, n)?;
            }
            write!(f, "={v}")?;
        }
        Ok(())
    }
}

/// An error at a column: `(Some(column), message)`.
macro_rules! at {
    ($fmt:literal, $col:expr) => {
        (Some($col), format!($fmt))
    };
}

/// Parses the text of [`Labels`]'s `Display` (what follows the dart on a label line).
/// Errors say what is wrong at which column: the character's place in `text` (from 1)
/// plus `offset` (the characters of the line before `text`).
pub(crate) fn parse_labels(text: &str, offset: usize) -> Result<Labels, String> {
    parse_labels_at(text).map_err(|(col, why)| match col {
        Some(c) => format!("column {}: {why}", c + offset),
        None => why,
    })
}

/// [`parse_labels`] with errors as (column in `text` from 1, what).
fn parse_labels_at(text: &str) -> Result<Labels, (Option<usize>, String)> {
    let b: Vec<char> = text.chars().collect();
    let mut k = 0;
    let mut out = Labels::new();
    let skip = |k: &mut usize| {
        while *k < b.len() && matches!(b[*k], ' ' | '\t' | '\r') {
            *k += 1;
        }
    };
    loop {
        skip(&mut k);
        if k >= b.len() {
            return Ok(out);
        }
        let name = if b[k] == '"' {
            quoted(&b, &mut k)?
        } else {
            let start = k;
            while k < b.len() && b[k] != '=' && !matches!(b[k], ' ' | '\t' | '\r') {
                k += 1;
            }
            let name: String = b[start..k].iter().collect();
            if !is_bare_name(&name) {
                return Err(at!(
                    "`{name}` is not a label name (letters, digits, `_`, `.`, `-`, or a quoted text)",
                    start + 1
                ));
            }
            name
        };
        if b.get(k) != Some(&'=') {
            return Err(at!("expected `=` after the label name `{name}`", k + 1));
        }
        k += 1;
        let value = if b.get(k) == Some(&'"') {
            LabelValue::Text(quoted(&b, &mut k)?)
        } else {
            let start = k;
            while k < b.len() && !matches!(b[k], ' ' | '\t' | '\r') {
                k += 1;
            }
            let tok: String = b[start..k].iter().collect();
            number(&tok).map_err(|why| (Some(start + 1), format!("label `{name}`: {why}")))?
        };
        if out.get(&name).is_some() {
            return Err((None, format!("label `{name}` appears twice")));
        }
        out.set(&name, value);
        if k < b.len() && !matches!(b[k], ' ' | '\t' | '\r') {
            return Err(at!("expected a space after the value of `{name}`", k + 1));
        }
    }
}

/// An integer (`-?[0-9]+`, fitting `i64`) or a finite real.
fn number(tok: &str) -> Result<LabelValue, String> {
    let digits = tok.strip_prefix('-').unwrap_or(tok);
    if tok.is_empty() {
        return Err("the value is missing".into());
    }
    if !digits.is_empty() && digits.bytes().all(|c| c.is_ascii_digit()) {
        return tok.parse::<i64>().map(LabelValue::Int).map_err(|_| format!("`{tok}` does not fit a 64-bit integer"));
    }
    match tok.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(LabelValue::Real(v)),
        _ => Err(format!(
            "`{}` is neither an integer, a finite real nor a quoted text",
            crate::text::shorten(tok.as_bytes(), 40)
        )),
    }
}

/// Reads a quoted text starting at `b[*k] == '"'`, leaving `*k` after the closing quote.
fn quoted(b: &[char], k: &mut usize) -> Result<String, (Option<usize>, String)> {
    let open = *k;
    *k += 1;
    let mut s = String::new();
    while *k < b.len() {
        let c = b[*k];
        *k += 1;
        match c {
            '"' => return Ok(s),
            '\\' => {
                let e = b.get(*k).copied();
                *k += 1;
                match e {
                    Some('"') => s.push('"'),
                    Some('\\') => s.push('\\'),
                    Some('n') => s.push('\n'),
                    Some('r') => s.push('\r'),
                    Some('t') => s.push('\t'),
                    Some('u') if b.get(*k) == Some(&'{') => {
                        let start = *k + 1;
                        let end = (start..b.len())
                            .find(|&j| b[j] == '}')
                            .ok_or_else(|| at!("unterminated `\\u{{…}}` escape", start - 2))?;
                        let hex: String = b[start..end].iter().collect();
                        let c = u32::from_str_radix(&hex, 16)
                            .ok()
                            .and_then(char::from_u32)
                            .ok_or_else(|| at!("`\\u{{{hex}}}` is not a character", start - 2))?;
                        s.push(c);
                        *k = end + 1;
                    }
                    _ => return Err(at!("unknown escape (use \\\\, \\\", \\n, \\r, \\t or \\u{{hex}})", *k - 1)),
                }
            }
            c => s.push(c),
        }
    }
    Err(at!("the quoted text is not closed", open + 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_labels0(text: &str) -> Result<Labels, String> {
        parse_labels(text, 0)
    }

    #[test]
    fn text_round_trip_with_awkward_strings() {
        let l: Labels = [
            ("name", LabelValue::Text("a \"quoted\" word,\nnew line\tand \\ back\u{1}".into())),
            ("n", LabelValue::Int(-42)),
            ("x", LabelValue::Real(1.0)),
            ("big", LabelValue::Real(1e300)),
            ("with space", LabelValue::Text(String::new())),
        ]
        .into_iter()
        .collect();
        let text = l.to_string();
        assert!(!text.contains('\n'));
        assert_eq!(
            text,
            r#"name="a \"quoted\" word,\nnew line\tand \\ back\u{1}" n=-42 x=1.0 big=1e300 "with space"="""#
        );
        assert_eq!(parse_labels0(&text).unwrap(), l);
        assert_eq!(parse_labels0("").unwrap(), Labels::new());
    }

    #[test]
    fn malformed_labels_are_refused_with_the_place() {
        assert_eq!(
            parse_labels0("1a=2").unwrap_err(),
            "column 1: `1a` is not a label name (letters, digits, `_`, `.`, `-`, or a quoted text)"
        );
        assert_eq!(parse_labels0("a 2").unwrap_err(), "column 2: expected `=` after the label name `a`");
        assert_eq!(parse_labels0("a=").unwrap_err(), "column 3: label `a`: the value is missing");
        assert_eq!(parse_labels0("a=\"x").unwrap_err(), "column 3: the quoted text is not closed");
        assert_eq!(
            parse_labels0("a=\"\\q\"").unwrap_err(),
            "column 4: unknown escape (use \\\\, \\\", \\n, \\r, \\t or \\u{hex})"
        );
        assert_eq!(parse_labels0("a=1 a=2").unwrap_err(), "label `a` appears twice");
        assert_eq!(
            parse_labels0("a=inf").unwrap_err(),
            "column 3: label `a`: `inf` is neither an integer, a finite real nor a quoted text"
        );
        assert_eq!(
            parse_labels0("a=99999999999999999999").unwrap_err(),
            "column 3: label `a`: `99999999999999999999` does not fit a 64-bit integer"
        );
        assert_eq!(parse_labels0("a=\"x\"b=1").unwrap_err(), "column 6: expected a space after the value of `a`");
        assert_eq!(parse_labels0("a=\"\\u{110000}\"").unwrap_err(), "column 4: `\\u{110000}` is not a character");
    }

    #[test]
    fn set_get_remove_keep_order() {
        let mut l = Labels::new();
        assert!(l.is_empty());
        l.set("b", LabelValue::Int(1));
        l.set("a", LabelValue::Int(2));
        assert_eq!(l.set("b", LabelValue::Int(3)), Some(LabelValue::Int(1)));
        assert_eq!(l.iter().map(|(n, _)| n).collect::<Vec<_>>(), vec!["b", "a"]);
        assert_eq!(l.remove("b"), Some(LabelValue::Int(3)));
        assert_eq!(l.len(), 1);
    }

    #[test]
    fn dense_labels_are_numbered_like_the_dense_cells() {
        let (mut g, ids) = LabelledGMap::from_dense_with_attributes(&crate::examples::torus());
        let named = |n: &str| -> Labels { [("name", LabelValue::Text(n.into()))].into_iter().collect() };
        g.set_attribute::<2>(ids[5], named("face"));
        g.set_attribute::<0>(ids[7], named("vertex"));
        let (dense, labels, back) = to_dense_labels(&g);
        assert_eq!(dense.cell_counts(), crate::examples::torus().cell_counts());
        for i in 0..=2 {
            let cells = dense.cells(i);
            assert_eq!(labels.of[i].len(), cells.len());
            for (k, &h) in back.iter().enumerate() {
                let want = match (i, g.attribute::<2>(h), g.attribute::<0>(h)) {
                    (2, Some(l), _) | (0, _, Some(l)) => l.clone(),
                    _ => Labels::new(),
                };
                assert_eq!(labels.get(i, cells.of[k] as usize), &want, "dimension {i}, dart {k}");
            }
        }
        assert_eq!(labels.of[2].iter().filter(|l| !l.is_empty()).count(), 1);
        assert_eq!(labels.of[0].iter().filter(|l| !l.is_empty()).count(), 1);
        assert!(labels.get(3, 0).is_empty() && labels.get(0, 1000).is_empty());
        assert!(!labels.is_empty() && DenseLabels::default().is_empty());
        assert_eq!(cell_labels(&g, 3, ids[0]), None);
    }

    #[test]
    fn labels_by_dimension_are_those_of_to_dense_labels_in_their_order() {
        let (mut g, ids) = LabelledGMap::from_dense_with_attributes(&crate::examples::torus());
        let named = |n: &str| -> Labels { [("name", LabelValue::Text(n.into()))].into_iter().collect() };
        // set out of dart order: the order is the cells' first darts', not the setting's
        let edges = crate::examples::torus().cells(1);
        let other = (0..ids.len()).rev().find(|&k| edges.of[k] != edges.of[0]).expect("two edges");
        g.set_attribute::<1>(ids[other], named("late"));
        g.set_attribute::<1>(ids[0], named("first"));
        g.set_attribute::<2>(ids[3], named("face"));
        let (_, labels, _) = to_dense_labels(&g);
        let by_dim = labels_by_dimension(&g);
        assert_eq!(by_dim.len(), 3);
        for (i, got) in by_dim.iter().enumerate() {
            let want: Vec<&Labels> = labels.of[i].iter().filter(|l| !l.is_empty()).collect();
            assert_eq!(*got, want, "dimension {i}");
        }
        assert_eq!(by_dim[1].len(), 2);
        assert_eq!(by_dim[1][0].get("name"), Some(&LabelValue::Text("first".into())));
        assert!(by_dim[0].is_empty());
    }
}
