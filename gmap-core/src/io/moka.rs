//! Moka's ascii format `.moka` (docs/FORMATS.md §2).
//!
//! ```text
//! Moka file [ascii]
//! <8 mark-mask integers>
//! <a0> <a1> <a2> <a3> <m0> <m1> <m2> <m3> 0            a dart without a point
//! <a0> <a1> <a2> <a3> <m0> <m1> <m2> <m3> 1 <x> <y> <z>  a dart carrying a point
//! ```
//!
//! Moka is a format of 3G-maps, with no dart count in the header (the number of dart
//! lines is the count). Choices made here:
//! - **reading** gives a map of dimension 3, unless the last mark-mask integer records a
//!   lower dimension (below); the mark masks and the four mark values of each dart must be
//!   non-negative integers and are otherwise ignored; a dart with flag `1` carries its point
//!   (see [`DenseMap::point`]); blank lines are skipped;
//! - **writing** accepts maps of dimension n ≤ 3 and embeds them in dimension 3 with
//!   `alpha_k` the identity for n < k ≤ 3 (every dart k-free, which keeps BO Def. 1); a
//!   map of dimension above 3 is refused with [`WriteError::DimensionTooLarge`]. Marks are
//!   written as zeros, and so are the masks, except that for n < 3 the last mask integer is
//!   [`DIM_TAG`]` + n`: Moka reads such a file as the 3-map (a mask only flips the meaning
//!   of a mark), and this reader restores the dimension n, so a conversion never changes
//!   a map's dimension or homology. A file whose tag records n but where some dart is not
//!   k-free for some k > n is refused. Every dart that carries a point is written with flag
//!   `1` and its coordinates in Rust's shortest round-trip notation, so reading back gives
//!   the same darts, involutions, dimension and points, bit for bit.
//!
//! Reading is O(file size) plus the validation of BO Def. 1.

use std::io::Write as _;
use std::path::Path;

use super::common::{
    bad_number, check_utf8, is_content, push_u32, read_bytes, scan_lines, shorten, validity_to_read_error,
    write_atomically, Num, ReadError, ReadErrorKind, ReadOptions, Scanner, WriteError,
};
use crate::dense::DenseMap;
use crate::ids::{Dart, Point};

/// The first line of a Moka ascii file.
pub const MOKA_HEADER: &str = "Moka file [ascii]";

/// The dimension of Moka maps.
const MOKA_DIM: usize = 3;

/// The last mark-mask integer of a file written from a map of dimension n < 3 is
/// `DIM_TAG + n` (0x7F000000 + n, below 2^31); the reader restores dimension n.
pub const DIM_TAG: u64 = 0x7F00_0000;

/// Reads a `.moka` file as a map of dimension 3 and validates it (BO Def. 1).
pub fn read_moka(path: impl AsRef<Path>) -> Result<DenseMap, ReadError> {
    read_moka_with(path, &ReadOptions::default())
}

/// [`read_moka`] with options (a cap on the number of darts).
pub fn read_moka_with(path: impl AsRef<Path>, opts: &ReadOptions) -> Result<DenseMap, ReadError> {
    let path = path.as_ref();
    if let Some(limit) = opts.max_darts {
        check_line_limit(path, limit)?;
    }
    let bytes = read_bytes(path)?;
    parse_moka_with(&bytes, &path.display().to_string(), opts)
}

/// Refuses a file of more than `limit` dart lines, counting lines as it streams and stopping
/// at the first one over the limit (a file of any size is not loaded to find out it is too
/// big). The first two lines with content are the header and the mark masks.
fn check_line_limit(path: &Path, limit: u64) -> Result<(), ReadError> {
    let name = path.display().to_string();
    let mut content = 0u64;
    let mut over = None;
    scan_lines(path, 1, |number, line| {
        if is_content(line) {
            content += 1;
        }
        if content > limit.saturating_add(2) {
            over = Some(number);
            return false;
        }
        true
    })
    .map_err(|e| ReadError::new(&name, None, ReadErrorKind::Io(e.to_string())))?;
    match over {
        Some(line) => Err(ReadError::new(&name, Some(line), ReadErrorKind::DartLimit { limit, found: limit + 1 })),
        None => Ok(()),
    }
}

/// Parses the bytes of a `.moka` file; `name` is the file name used in errors.
/// Never panics, whatever the bytes.
pub fn parse_moka(bytes: &[u8], name: &str) -> Result<DenseMap, ReadError> {
    parse_moka_with(bytes, name, &ReadOptions::default())
}

/// [`parse_moka`] with options.
pub fn parse_moka_with(bytes: &[u8], name: &str, opts: &ReadOptions) -> Result<DenseMap, ReadError> {
    check_utf8(bytes, name)?;
    let err = |line: usize, kind| ReadError::new(name, Some(line), kind);
    let mut s = Scanner::new(bytes);
    s.skip_empty_lines();
    if s.at_end() {
        return Err(err(s.line, ReadErrorKind::Empty { expected: MOKA_HEADER }));
    }
    let head = s.rest_of_line();
    if head.trim_ascii() != MOKA_HEADER.as_bytes() {
        return Err(err(s.line, ReadErrorKind::BadHeader { expected: MOKA_HEADER, found: shorten(head, 60) }));
    }
    s.next_line();
    s.skip_empty_lines();
    if s.at_end() {
        return Err(err(s.line, ReadErrorKind::Truncated { expected: 0, found: 0 }).mask_line_missing());
    }
    let mask_line = s.line;
    let mut last_mask = 0;
    for k in 0..8 {
        match s.number() {
            Num::Value(v) => last_mask = v,
            Num::Eol => {
                let what = "mark-mask line".to_string();
                return Err(err(s.line, ReadErrorKind::WrongValueCount { what, expected: "8".into(), found: k }));
            }
            Num::Bad(tok) => return Err(err(s.line, bad_number(format!("mark mask {k}"), tok))),
        }
    }
    s.skip_blank();
    if !s.at_eol() {
        let found = 8 + s.count_tokens();
        return Err(err(
            s.line,
            ReadErrorKind::WrongValueCount { what: "mark-mask line".into(), expected: "8".into(), found },
        ));
    }
    s.next_line();
    let data_start = s.pos;
    let data_line = s.line;
    let w = MOKA_DIM + 1;
    let limit = opts.max_darts.unwrap_or(u64::MAX);
    let mut alpha: Vec<u32> = Vec::new();
    if alpha.try_reserve_exact(bytes.len() / 24 * w).is_err() {
        return Err(err(data_line, ReadErrorKind::OutOfMemory { bytes: (bytes.len() / 24 * w * 4) as u64 }));
    }
    let mut points: Vec<(u32, Point)> = Vec::new();
    let mut d: u64 = 0;
    loop {
        s.skip_empty_lines();
        if s.at_end() {
            break;
        }
        if d >= limit {
            return Err(err(s.line, ReadErrorKind::DartLimit { limit, found: d + 1 }));
        }
        if d >= u32::MAX as u64 - 1 {
            return Err(err(s.line, ReadErrorKind::TooManyDarts { found: format!("more than {d}") }));
        }
        let count_err = |s: &mut Scanner, found: usize| {
            let line = s.line;
            let found = found + s.count_tokens();
            err(line, ReadErrorKind::WrongValueCount { what: format!("dart {d}"), expected: "9 or 12".into(), found })
        };
        for i in 0..w {
            match s.number() {
                Num::Value(v) => alpha.push(u32::try_from(v).unwrap_or(u32::MAX)),
                Num::Eol => return Err(count_err(&mut s, i)),
                Num::Bad(tok) => return Err(err(s.line, bad_number(format!("dart {d}, alpha_{i}"), tok))),
            }
        }
        for k in 0..4 {
            match s.number() {
                Num::Value(_) => {}
                Num::Eol => return Err(count_err(&mut s, w + k)),
                Num::Bad(tok) => return Err(err(s.line, bad_number(format!("dart {d}, mark {k}"), tok))),
            }
        }
        match s.token() {
            Some(b"0") => {}
            Some(b"1") => {
                let mut p = [0.0f64; 3];
                for (c, slot) in p.iter_mut().enumerate() {
                    let Some(tok) = s.token() else {
                        return Err(count_err(&mut s, 9 + c));
                    };
                    let v = std::str::from_utf8(tok).ok().and_then(|t| t.parse::<f64>().ok()).filter(|v| v.is_finite());
                    match v {
                        Some(v) => *slot = v,
                        None => {
                            let what = format!("dart {d}, coordinate {}", ["x", "y", "z"][c]);
                            return Err(err(s.line, ReadErrorKind::BadCoordinate { what, token: shorten(tok, 40) }));
                        }
                    }
                }
                points.push((d as u32, p));
            }
            Some(tok) => return Err(err(s.line, ReadErrorKind::BadFlag { dart: d, token: shorten(tok, 40) })),
            None => return Err(count_err(&mut s, 8)),
        }
        s.skip_blank();
        if !s.at_eol() {
            let found = if points.last().is_some_and(|&(x, _)| x as u64 == d) { 12 } else { 9 };
            return Err(count_err(&mut s, found));
        }
        s.next_line();
        d += 1;
    }
    let mut map = DenseMap::from_flat_unchecked(MOKA_DIM, alpha)
        .map_err(|e| validity_to_read_error(e, name, bytes, data_start, data_line))?;
    map.validate().map_err(|e| validity_to_read_error(e, name, bytes, data_start, data_line))?;
    if let Some(n) = last_mask.checked_sub(DIM_TAG).filter(|&n| n < MOKA_DIM as u64) {
        map = lower_dimension(&map, n as usize).map_err(|(d, k)| {
            err(mask_line, ReadErrorKind::RecordedDimension { recorded: n as usize, dart: d as u64, alpha: k })
        })?;
    }
    for (k, p) in points {
        map.set_point(Dart::new(k), Some(p));
    }
    Ok(map)
}

/// The map of dimension `n` whose `alpha_0..alpha_n` are those of `map`, or the first dart
/// and index k > n where `map` is not k-free.
fn lower_dimension(map: &DenseMap, n: usize) -> Result<DenseMap, (u32, usize)> {
    let mut alpha = Vec::with_capacity(map.dart_count() * (n + 1));
    for d in map.darts() {
        let row = map.row(d);
        if let Some(k) = (n + 1..row.len()).find(|&k| row[k] != d.get()) {
            return Err((d.get(), k));
        }
        alpha.extend_from_slice(&row[..=n]);
    }
    // the rows are those of a valid map restricted to fewer involutions: still valid
    Ok(DenseMap::from_flat_unchecked(n, alpha).expect("a restriction of a valid map"))
}

impl ReadError {
    /// The error for a Moka file that stops after its header.
    fn mask_line_missing(mut self) -> Self {
        self.kind = ReadErrorKind::WrongValueCount { what: "mark-mask line".into(), expected: "8".into(), found: 0 };
        self
    }
}

/// The `.moka` text of a map of dimension at most 3 (embedded in dimension 3), or `None`
/// for a larger dimension. O(N).
pub fn format_moka(map: &DenseMap) -> Option<Vec<u8>> {
    let n = map.dim();
    if n > MOKA_DIM {
        return None;
    }
    let mut out = Vec::with_capacity(64 + map.dart_count() * 24);
    out.extend_from_slice(MOKA_HEADER.as_bytes());
    out.extend_from_slice(b"\n0 0 0 0 0 0 0 ");
    push_u32(&mut out, if n < MOKA_DIM { (DIM_TAG + n as u64) as u32 } else { 0 });
    out.push(b'\n');
    for d in map.darts() {
        let row = map.row(d);
        for &v in row.iter().chain(std::iter::repeat_n(&d.get(), MOKA_DIM - n)) {
            push_u32(&mut out, v);
            out.push(b' ');
        }
        out.extend_from_slice(b"0 0 0 0 ");
        match map.point(d) {
            None => out.extend_from_slice(b"0\n"),
            Some([x, y, z]) => {
                // writing to a Vec cannot fail
                let _ = writeln!(out, "1 {x} {y} {z}");
            }
        }
    }
    Some(out)
}

/// Writes `map` (dimension at most 3) to any writer in the `.moka` format.
pub fn write_moka_to(map: &DenseMap, out: &mut impl std::io::Write) -> Result<(), WriteError> {
    let bytes = format_moka(map).ok_or_else(|| too_large(map, Path::new("<stream>")))?;
    out.write_all(&bytes).map_err(|source| WriteError::Io { path: "<stream>".into(), source })
}

/// Writes `map` (dimension at most 3) to `path` in the `.moka` format, through a temporary
/// file renamed over `path`. A larger dimension is refused before anything is written.
pub fn write_moka(map: &DenseMap, path: impl AsRef<Path>) -> Result<(), WriteError> {
    let path = path.as_ref();
    let bytes = format_moka(map).ok_or_else(|| too_large(map, path))?;
    write_atomically(path, &bytes)
}

fn too_large(map: &DenseMap, path: &Path) -> WriteError {
    WriteError::DimensionTooLarge { path: path.to_path_buf(), format: "Moka", max: MOKA_DIM, dim: map.dim() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::examples;

    fn msg(bytes: &[u8]) -> String {
        parse_moka(bytes, "f.moka").unwrap_err().to_string()
    }

    #[test]
    fn round_trip_with_points() {
        let mut m = examples::cylinder();
        m.set_point(Dart::new(0), Some([0.1, -2.5e-300, 1e300]));
        m.set_point(Dart::new(5), Some([-0.0, 3.0, f64::MIN_POSITIVE]));
        let text = format_moka(&m).unwrap();
        assert!(text.starts_with(b"Moka file [ascii]\n0 0 0 0 0 0 0 2130706434\n1 7 5 0 0 0 0 0 1 0.1 "));
        let back = parse_moka(&text, "x").unwrap();
        assert_eq!(back, m);
        assert_eq!(back.point(Dart::new(5)).unwrap()[0].to_bits(), (-0.0f64).to_bits());
        assert_eq!(back.point(Dart::new(1)), None);
        assert!(format_moka(&DenseMap::new(4, 1)).is_none());
    }

    #[test]
    fn reads_tabs_and_marks() {
        let text = b"Moka file [ascii]\r\n128 0 0 0 0 0 0 0\n0\t0\t0\t0\t128\t0\t0\t0\t1\t-5\t0.5\t2\n";
        let m = parse_moka(text, "x").unwrap();
        assert_eq!(m.dim(), 3);
        assert_eq!(m.flat(), &[0, 0, 0, 0]);
        assert_eq!(m.point(Dart::new(0)), Some([-5.0, 0.5, 2.0]));
    }

    #[test]
    fn every_kind_of_bad_input() {
        let h = "Moka file [ascii]\n0 0 0 0 0 0 0 0\n";
        let with = |rest: &str| msg(format!("{h}{rest}").as_bytes());
        assert_eq!(msg(b""), "f.moka:1: the file is empty: expected the header `Moka file [ascii]`");
        assert_eq!(
            msg(b"Moka file [binary]\n"),
            "f.moka:1: bad header: expected `Moka file [ascii]`, found `Moka file [binary]`"
        );
        assert_eq!(msg(b"Moka file [ascii]\n"), "f.moka:2: mark-mask line: expected 8 values, found 0");
        assert_eq!(msg(b"Moka file [ascii]\n0 0 0\n"), "f.moka:2: mark-mask line: expected 8 values, found 3");
        assert_eq!(
            msg(b"Moka file [ascii]\n0 0 0 0 0 0 0 0 0\n"),
            "f.moka:2: mark-mask line: expected 8 values, found 9"
        );
        assert_eq!(msg(b"Moka file [ascii]\n0 0 -1 0 0 0 0 0\n"), "f.moka:2: mark mask 2: `-1` is negative");
        assert_eq!(parse_moka(h.as_bytes(), "x").unwrap(), DenseMap::new(3, 0));
        assert_eq!(with("0 0 0 0 0 0 0 0\n"), "f.moka:3: dart 0: expected 9 or 12 values, found 8");
        assert_eq!(with("0 0 0 0 0 0 0 0 0 7\n"), "f.moka:3: dart 0: expected 9 or 12 values, found 10");
        assert_eq!(with("0 0 0 0 0 0 0 0 1 1 2\n"), "f.moka:3: dart 0: expected 9 or 12 values, found 11");
        assert_eq!(with("0 0 0 0 0 0 0 0 1 1 2 3 4\n"), "f.moka:3: dart 0: expected 9 or 12 values, found 13");
        assert_eq!(with("0 0 0 0 0 0 0 0 2\n"), "f.moka:3: dart 0: embedding flag `2` is neither 0 nor 1");
        assert_eq!(with("0 0 0 0 0 0 0 0 1 1 nan 3\n"), "f.moka:3: dart 0, coordinate y: `nan` is not a finite number");
        assert_eq!(with("0 0 0 -1 0 0 0 0 0\n"), "f.moka:3: dart 0, alpha_3: `-1` is negative");
        assert_eq!(with("0 0 0 0 0 x 0 0 0\n"), "f.moka:3: dart 0, mark 1: `x` is not a non-negative integer");
        assert_eq!(
            with("0 0 0 0 0 0 0 0 0\n1 1 1 5 0 0 0 0 0\n"),
            "f.moka:4: not a G-map (BO Def. 1): dart 1 is linked along alpha_3 to dart 5, which does not exist (the map has 2 darts)"
        );
        assert_eq!(
            with("1 0 0 0 0 0 0 0 0\n1 1 1 1 0 0 0 0 0\n"),
            "f.moka:3: not a G-map (BO Def. 1): dart 0 is linked along alpha_0 to dart 1, which is linked back to dart 1 instead"
        );
        assert_eq!(
            msg(b"Moka file [ascii]\n0 0 0 0 0 0 0 0\n0 0 0 0 0 0 0 0 \xc3\x28\n"),
            "f.moka:3: not UTF-8 text: invalid byte at offset 50"
        );
        let opts = ReadOptions { max_darts: Some(1) };
        let two = format!("{h}0 0 0 0 0 0 0 0 0\n1 1 1 1 0 0 0 0 0\n");
        let e = parse_moka_with(two.as_bytes(), "f", &opts).unwrap_err();
        assert_eq!(e.to_string(), "f:4: the map has more than 1 darts (the limit set by the caller): 2");
    }

    #[test]
    fn write_refuses_dimension_four() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("x.moka");
        let e = write_moka(&DenseMap::new(4, 2), &p).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("{}: the Moka format holds maps of dimension at most 3, this one has dimension 4", p.display())
        );
        assert!(!p.exists());
        let m = examples::fig1_surface();
        write_moka(&m, &p).unwrap();
        assert_eq!(read_moka(&p).unwrap(), m);
    }

    #[test]
    fn lower_dimensions_are_restored() {
        for n in 0..=3 {
            let mut m = DenseMap::new(n, 4);
            if n >= 1 {
                m.link(Dart::new(0), Dart::new(1), n);
            }
            m.link(Dart::new(2), Dart::new(3), 0);
            m.set_point(Dart::new(2), Some([1.0, 2.0, 3.0]));
            let text = format_moka(&m).unwrap();
            let back = parse_moka(&text, "x").unwrap();
            assert_eq!(back, m, "dimension {n}");
            assert_eq!(back.point(Dart::new(2)), Some([1.0, 2.0, 3.0]));
        }
        // the tag of dimension 1 on a map linked along alpha_2
        let text = format!("Moka file [ascii]\n0 0 0 0 0 0 0 {}\n0 0 1 0 0 0 0 0 0\n1 1 0 1 0 0 0 0 0\n", DIM_TAG + 1);
        assert_eq!(
            msg(text.as_bytes()),
            "f.moka:2: the mark masks record dimension 1, but dart 0 is linked along alpha_2"
        );
        // a tag of 3 or more is an ordinary mask
        let text = format!("Moka file [ascii]\n0 0 0 0 0 0 0 {}\n0 0 0 0 0 0 0 0 0\n", DIM_TAG + 3);
        assert_eq!(parse_moka(text.as_bytes(), "x").unwrap().dim(), 3);
        let empty = format_moka(&DenseMap::new(2, 0)).unwrap();
        assert_eq!(parse_moka(&empty, "x").unwrap(), DenseMap::new(2, 0));
    }
}
