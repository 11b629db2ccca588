//! The native `.gmap` format (docs/FORMATS.md §2).
//!
//! ```text
//! # comment lines start with '#'
//! gmap <n> <number of darts>
//! <alpha_0> <alpha_1> ... <alpha_n>      one line per dart, darts numbered from 0
//! ```
//!
//! A value equal to the dart's own number is a fixed point. Values are separated by
//! spaces or tabs; lines may end with `\r\n`. The reader also skips blank lines and
//! comment lines after the header (they are not data lines: dart `k` is still the `k`-th
//! data line). The format holds no points: a map written to `.gmap` loses its embedding
//! (use `.moka` to keep it).
//!
//! Reading is O(file size) plus the validation of BO Def. 1, O(N n²).

use std::path::Path;

use super::{
    bad_number, check_utf8, is_content, push_u32, read_bytes, scan_lines, shorten, validity_to_read_error,
    write_atomically, Num, ReadError, ReadErrorKind, ReadOptions, Scanner, WriteError,
};
use crate::alpha::MAX_DIM;
use crate::dense::{Dart, DenseMap};

const HEADER: &str = "gmap <n> <number of darts>";

/// Reads a `.gmap` file (docs/FORMATS.md §2) and validates it (BO Def. 1).
///
/// Errors name the file and line: see [`super::ReadError`].
pub fn read_gmap(path: impl AsRef<Path>) -> Result<DenseMap, ReadError> {
    read_gmap_with(path, &ReadOptions::default())
}

/// [`read_gmap`] with options (a cap on the number of darts).
pub fn read_gmap_with(path: impl AsRef<Path>, opts: &ReadOptions) -> Result<DenseMap, ReadError> {
    let path = path.as_ref();
    if let Some(limit) = opts.max_darts {
        check_header_limit(path, limit)?;
    }
    let bytes = read_bytes(path)?;
    parse_gmap_with(&bytes, &path.display().to_string(), opts)
}

/// Refuses a file whose header announces more than `limit` darts, reading only up to the
/// header (a file of any size is not loaded to find out it is too big).
fn check_header_limit(path: &Path, limit: u64) -> Result<(), ReadError> {
    let name = path.display().to_string();
    let mut found = None;
    scan_lines(path, 256, |number, line| {
        if !is_content(line) {
            return true;
        }
        let mut t = line.split(|c| matches!(c, b' ' | b'\t' | b'\r')).filter(|t| !t.is_empty());
        if t.next() == Some(b"gmap") {
            let _dim = t.next();
            let darts = t.next().and_then(|d| std::str::from_utf8(d).ok()).and_then(|d| d.parse::<u64>().ok());
            if let Some(d) = darts.filter(|&d| d > limit) {
                found = Some((number, d));
            }
        }
        false
    })
    .map_err(|e| ReadError::new(&name, None, ReadErrorKind::Io(e.to_string())))?;
    match found {
        Some((line, darts)) => Err(ReadError::new(&name, Some(line), ReadErrorKind::DartLimit { limit, found: darts })),
        None => Ok(()),
    }
}

/// Parses the bytes of a `.gmap` file; `name` is the file name used in errors.
/// Never panics, whatever the bytes.
pub fn parse_gmap(bytes: &[u8], name: &str) -> Result<DenseMap, ReadError> {
    parse_gmap_with(bytes, name, &ReadOptions::default())
}

/// [`parse_gmap`] with options.
pub fn parse_gmap_with(bytes: &[u8], name: &str, opts: &ReadOptions) -> Result<DenseMap, ReadError> {
    check_utf8(bytes, name)?;
    let err = |line: usize, kind| ReadError::new(name, Some(line), kind);
    let mut s = Scanner::new(bytes);
    s.skip_empty_lines();
    if s.at_end() {
        return Err(err(s.line, ReadErrorKind::Empty { expected: HEADER }));
    }
    // header
    let header_line = s.line;
    let bad_header = |s: &Scanner| {
        err(header_line, ReadErrorKind::BadHeader { expected: HEADER, found: shorten(s.rest_of_line(), 60) })
    };
    let line_start = Scanner { b: bytes, pos: s.pos, line: s.line };
    if s.token() != Some(b"gmap") {
        return Err(bad_header(&line_start));
    }
    let dim = match s.number() {
        Num::Value(v) if v <= MAX_DIM as u64 => v as usize,
        Num::Value(_) => {
            let mut t = Scanner { b: bytes, pos: line_start.pos, line: header_line };
            t.token();
            let found = shorten(t.token().unwrap_or(&[]), 40);
            return Err(err(header_line, ReadErrorKind::DimensionTooLarge { found }));
        }
        Num::Eol => return Err(bad_header(&line_start)),
        Num::Bad(tok) => return Err(err(header_line, bad_number("header dimension".into(), tok))),
    };
    let darts = match s.number() {
        Num::Value(v) => v,
        Num::Eol => return Err(bad_header(&line_start)),
        Num::Bad(tok) => return Err(err(header_line, bad_number("header dart count".into(), tok))),
    };
    if s.token().is_some() {
        return Err(bad_header(&line_start));
    }
    let w = dim + 1;
    let total =
        darts.checked_mul(w as u64).and_then(|t| usize::try_from(t).ok()).filter(|&t| t <= isize::MAX as usize / 4);
    let total = match total {
        Some(t) if darts < u32::MAX as u64 => t,
        _ => return Err(err(header_line, ReadErrorKind::TooManyDarts { found: darts.to_string() })),
    };
    if let Some(limit) = opts.max_darts {
        if darts > limit {
            return Err(err(header_line, ReadErrorKind::DartLimit { limit, found: darts }));
        }
    }
    s.next_line();
    let data_start = s.pos;
    let data_line = s.line;
    // every value takes at least two bytes: never reserve more than the file can fill
    let mut alpha: Vec<u32> = Vec::new();
    let reserve = total.min(bytes.len() / 2 + w);
    if alpha.try_reserve_exact(reserve).is_err() {
        return Err(err(header_line, ReadErrorKind::OutOfMemory { bytes: reserve as u64 * 4 }));
    }
    for d in 0..darts {
        // fast path: a line of exactly `w` in-range values separated by single spaces
        if let Some(end) = fast_line(bytes, s.pos, w, darts, &mut alpha) {
            s.pos = end;
            s.line += 1;
            continue;
        }
        s.skip_empty_lines();
        if s.at_end() {
            return Err(err(s.line, ReadErrorKind::Truncated { expected: darts, found: d }));
        }
        for i in 0..w {
            match s.number() {
                Num::Value(v) if v < darts => alpha.push(v as u32),
                Num::Value(v) => {
                    let e = crate::ValidityError::OutOfRange {
                        dart: Dart(d as u32),
                        alpha: i,
                        target: Dart(u32::try_from(v).unwrap_or(u32::MAX)),
                        darts: darts as usize,
                    };
                    return Err(err(s.line, ReadErrorKind::Invalid(e)));
                }
                Num::Eol => {
                    let what = format!("dart {d}");
                    return Err(err(
                        s.line,
                        ReadErrorKind::WrongValueCount { what, expected: w.to_string(), found: i },
                    ));
                }
                Num::Bad(tok) => return Err(err(s.line, bad_number(format!("dart {d}, alpha_{i}"), tok))),
            }
        }
        s.skip_blank();
        if !s.at_eol() {
            let found = w + s.count_tokens();
            let what = format!("dart {d}");
            return Err(err(s.line, ReadErrorKind::WrongValueCount { what, expected: w.to_string(), found }));
        }
        s.next_line();
    }
    s.skip_empty_lines();
    if !s.at_end() {
        return Err(err(s.line, ReadErrorKind::ExtraLines { expected: darts }));
    }
    let map = DenseMap::from_flat_unchecked(dim, alpha)
        .map_err(|e| validity_to_read_error(e, name, bytes, data_start, data_line))?;
    map.validate().map_err(|e| validity_to_read_error(e, name, bytes, data_start, data_line))?;
    Ok(map)
}

/// Parses a plain data line at `pos`: `w` decimal values below `darts` (at most 10 digits
/// each) separated by single spaces and ended by `\n`. Pushes the values and returns the
/// offset after the line, or returns `None` having pushed nothing, for the general path to
/// handle the line (and report any error). This is the loop that loads big files.
#[inline]
fn fast_line(b: &[u8], pos: usize, w: usize, darts: u64, out: &mut Vec<u32>) -> Option<usize> {
    let mark = out.len();
    let mut p = pos;
    for i in 0..w {
        let start = p;
        let mut v: u64 = 0;
        while let Some(&c) = b.get(p) {
            let digit = c.wrapping_sub(b'0');
            if digit > 9 {
                break;
            }
            v = v * 10 + digit as u64;
            p += 1;
            if p - start > 10 {
                out.truncate(mark);
                return None;
            }
        }
        let sep = if i + 1 < w { b' ' } else { b'\n' };
        if p == start || v >= darts || b.get(p) != Some(&sep) {
            out.truncate(mark);
            return None;
        }
        out.push(v as u32);
        p += 1;
    }
    Some(p)
}

/// The `.gmap` text of a map (no comment line; points are not written). O(N n).
pub fn format_gmap(map: &DenseMap) -> Vec<u8> {
    let w = map.dim() + 1;
    let mut out = Vec::with_capacity(32 + map.flat().len() * 8);
    out.extend_from_slice(format!("gmap {} {}\n", map.dim(), map.dart_count()).as_bytes());
    for row in map.flat().chunks_exact(w) {
        for (i, &v) in row.iter().enumerate() {
            if i > 0 {
                out.push(b' ');
            }
            push_u32(&mut out, v);
        }
        out.push(b'\n');
    }
    out
}

/// Writes `map` to any writer in the `.gmap` format.
pub fn write_gmap_to(map: &DenseMap, out: &mut impl std::io::Write) -> std::io::Result<()> {
    out.write_all(&format_gmap(map))
}

/// Writes `map` to `path` in the `.gmap` format, through a temporary file in the same
/// directory renamed over `path` (no partial file on failure).
pub fn write_gmap(map: &DenseMap, path: impl AsRef<Path>) -> Result<(), WriteError> {
    write_atomically(path.as_ref(), &format_gmap(map))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::examples;

    fn msg(bytes: &[u8]) -> String {
        parse_gmap(bytes, "f.gmap").unwrap_err().to_string()
    }

    #[test]
    fn round_trip_examples() {
        for m in [examples::fig1_curve(), examples::fig1_surface(), examples::cylinder(), examples::klein_bottle()] {
            assert_eq!(parse_gmap(&format_gmap(&m), "x").unwrap(), m);
        }
        let empty = DenseMap::new(3, 0);
        assert_eq!(format_gmap(&empty), b"gmap 3 0\n");
        assert_eq!(parse_gmap(b"gmap 3 0\n", "x").unwrap(), empty);
    }

    #[test]
    fn comments_blank_lines_crlf() {
        let m = parse_gmap(b"# a comment\n\n  # another\r\ngmap 1 2\r\n1\t1\r\n\n# mid\n0 0  \r\n\n", "x").unwrap();
        assert_eq!(m.flat(), &[1, 1, 0, 0]);
    }

    #[test]
    fn every_kind_of_bad_input() {
        assert_eq!(msg(b""), "f.gmap:1: the file is empty: expected the header `gmap <n> <number of darts>`");
        assert_eq!(msg(b"# only\n\n"), "f.gmap:3: the file is empty: expected the header `gmap <n> <number of darts>`");
        assert_eq!(msg(b"map 1 2\n"), "f.gmap:1: bad header: expected `gmap <n> <number of darts>`, found `map 1 2`");
        assert_eq!(msg(b"gmap 1\n"), "f.gmap:1: bad header: expected `gmap <n> <number of darts>`, found `gmap 1`");
        assert_eq!(
            msg(b"gmap 1 2 3\n"),
            "f.gmap:1: bad header: expected `gmap <n> <number of darts>`, found `gmap 1 2 3`"
        );
        assert_eq!(msg(b"gmap x 2\n"), "f.gmap:1: header dimension: `x` is not a non-negative integer");
        assert_eq!(msg(b"gmap -1 2\n"), "f.gmap:1: header dimension: `-1` is negative");
        assert_eq!(msg(b"gmap 1000000 2\n"), "f.gmap:1: dimension 1000000 is larger than the supported maximum 30");
        assert_eq!(
            msg(b"gmap 99999999999999999999999 2\n"),
            "f.gmap:1: dimension 99999999999999999999999 is larger than the supported maximum 30"
        );
        assert_eq!(
            msg(b"gmap 30 18446744073709551615\n"),
            "f.gmap:1: 18446744073709551615 darts is more than a map can hold (at most 4294967294 darts)"
        );
        assert_eq!(
            msg(b"gmap 1 4294967295\n"),
            "f.gmap:1: 4294967295 darts is more than a map can hold (at most 4294967294 darts)"
        );
        // a huge count with a tiny file: refused as truncated, without a huge allocation
        assert_eq!(
            msg(b"gmap 2 4000000000\n0 0 0\n"),
            "f.gmap:3: truncated: the header announces 4000000000 darts but the file ends after 1"
        );
        assert_eq!(
            msg(b"gmap 1 3\n0 0\n1 1\n"),
            "f.gmap:4: truncated: the header announces 3 darts but the file ends after 2"
        );
        assert_eq!(msg(b"gmap 1 1\n0 0\n0 0\n"), "f.gmap:3: more dart lines than the 1 darts the header announces");
        assert_eq!(msg(b"gmap 1 2\n0 0\n1\n"), "f.gmap:3: dart 1: expected 2 values, found 1");
        assert_eq!(msg(b"gmap 1 2\n0 0 0 0\n1 1\n"), "f.gmap:2: dart 0: expected 2 values, found 4");
        assert_eq!(
            msg(b"gmap 1 2\n0 0\n1 2\n"),
            "f.gmap:3: not a G-map (BO Def. 1): dart 1 is linked along alpha_1 to dart 2, which does not exist (the map has 2 darts)"
        );
        assert_eq!(
            msg(b"gmap 1 2\n0 0\n1 99999999999\n"),
            "f.gmap:3: not a G-map (BO Def. 1): dart 1 is linked along alpha_1 to dart 4294967295, which does not exist (the map has 2 darts)"
        );
        assert_eq!(msg(b"gmap 1 2\n0 0\n1 -1\n"), "f.gmap:3: dart 1, alpha_1: `-1` is negative");
        assert_eq!(msg(b"gmap 1 2\n0 0\n1 1.5\n"), "f.gmap:3: dart 1, alpha_1: `1.5` is not a non-negative integer");
        assert_eq!(msg(b"gmap 1 2\n0 0\n1 abc\n"), "f.gmap:3: dart 1, alpha_1: `abc` is not a non-negative integer");
        assert_eq!(msg(b"gmap 1 2\n0 0\n1 \xff\n"), "f.gmap:3: not UTF-8 text: invalid byte at offset 15");
        assert_eq!(
            msg(b"gmap 1 3\n1 0\n2 1\n1 2\n"),
            "f.gmap:2: not a G-map (BO Def. 1): dart 0 is linked along alpha_0 to dart 1, which is linked back to dart 2 instead"
        );
        // alpha_0 alpha_2 not an involution: a0 = (0 1)(2 3), a2 = (1 2), 0 and 3 2-free
        assert_eq!(
            msg(b"gmap 2 4\n1 0 0\n0 1 2\n3 2 1\n2 3 3\n"),
            "f.gmap:2: not a G-map (BO Def. 1): the links alpha_0 and alpha_2 do not commute at dart 0: alpha_0, alpha_2, alpha_0, alpha_2 from it lead to dart 3, not back to it"
        );
        // the offending dart's line counts data lines only
        assert_eq!(
            msg(b"gmap 1 2\n# c\n0 0\n\n1 0\n"),
            "f.gmap:5: not a G-map (BO Def. 1): dart 1 is linked along alpha_1 to dart 0, which is linked back to dart 0 instead"
        );
    }

    #[test]
    fn dart_limit() {
        let opts = ReadOptions { max_darts: Some(1) };
        let e = parse_gmap_with(b"gmap 1 2\n1 0\n0 1\n", "f", &opts).unwrap_err();
        assert_eq!(e.to_string(), "f:1: the map has more than 1 darts (the limit set by the caller): 2");
    }

    #[test]
    fn write_and_read_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("k.gmap");
        let m = examples::klein_bottle();
        write_gmap(&m, &p).unwrap();
        assert_eq!(read_gmap(&p).unwrap(), m);
        let missing = dir.path().join("none.gmap");
        let e = read_gmap(&missing).unwrap_err();
        assert_eq!(e.line, None);
        assert!(e.to_string().starts_with(&format!("{}: cannot read the file: ", missing.display())));
        let e = write_gmap(&m, dir.path().join("no/such/dir/x.gmap")).unwrap_err();
        assert!(matches!(e, WriteError::Io { .. }));
    }
}
