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
//! data line).
//!
//! ## Sections
//!
//! After the dart lines, optional sections carry vertex points and cell labels. Each
//! starts with one header line naming its kind, (for labels) the cell dimension, and its
//! number of lines; each line names one cell by one of its darts:
//!
//! ```text
//! points <count>
//! <dart> <x> <y> [<z>]                      one line per vertex with a point (z = 0 if absent)
//! labels <dim> <count>
//! <dart> <name>=<value> <name>=<value> ...  one line per <dim>-cell with labels
//! ```
//!
//! Coordinates are finite reals. A label value is an integer (`-12`), a real (`1.5`,
//! `2e-3`: a `.` or an exponent) or a text in double quotes with the escapes `\\`, `\"`,
//! `\n`, `\r`, `\t` and `\u{hex}`, so a record is always one line; a name is
//! `[A-Za-z_][A-Za-z0-9_.-]*` or quoted. Sections come in any order, `labels` once per
//! dimension at most in what the writer produces; two lines giving a value to the same cell
//! are refused. A file without sections reads exactly as before they existed.
//!
//! [`read_gmap`] gives a [`DenseMap`] with the points on every dart of their vertex and
//! checks, then drops, the labels; [`read_labelled_gmap`] gives a [`LabelledGMap`] with
//! both. The writers write the points when the map has some, and [`write_labelled_gmap`]
//! the labels of every dimension.
//!
//! Reading is O(file size) plus the validation of BO Def. 1, O(N n²), plus O(N n) per
//! section.

use std::path::Path;

use super::common::{
    bad_number, check_utf8, is_content, push_u32, read_bytes, scan_lines, shorten, validity_to_read_error,
    write_atomic_with, write_atomically, Num, ReadError, ReadErrorKind, ReadOptions, Scanner, WriteError,
};
use crate::alpha::{AlphaSet, MAX_DIM};
use crate::dense::DenseMap;
use crate::edit::DartId;
use crate::ids::{Dart, Point};
use crate::labels::{parse_labels, LabelledGMap, Labels, MAX_LABELLED_DIM};

const HEADER: &str = "gmap <n> <number of darts>";

/// Reads a `.gmap` file (docs/FORMATS.md §2) and validates it (BO Def. 1).
///
/// Errors name the file and line: see [`super::ReadError`].
pub fn read_gmap(path: impl AsRef<Path>) -> Result<DenseMap, ReadError> {
    read_gmap_with(path, &ReadOptions::default())
}

/// [`read_gmap`] with options (a cap on the number of darts).
///
/// The file is read a chunk at a time: beyond the map, the reader holds one chunk of the
/// file and its sections. A file that is not a valid map is then read whole to name the
/// fault.
pub fn read_gmap_with(path: impl AsRef<Path>, opts: &ReadOptions) -> Result<DenseMap, ReadError> {
    let path = path.as_ref();
    if let Some(map) = stream_gmap(path, &path.display().to_string(), opts, CHUNK) {
        return Ok(map);
    }
    let (bytes, name) = gmap_bytes(path, opts)?;
    parse_gmap_with(&bytes, &name, opts)
}

/// The bytes of a `.gmap` file and its name for errors, once the header's dart count is
/// within the caller's limit (checked before the file is read whole).
fn gmap_bytes(path: &Path, opts: &ReadOptions) -> Result<(Vec<u8>, String), ReadError> {
    if let Some(limit) = opts.max_darts {
        check_header_limit(path, limit)?;
    }
    Ok((read_bytes(path)?, path.display().to_string()))
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
    let (mut map, sections) = parse_parts(bytes, name, opts)?;
    sections.check(&map, name, map.dim())?;
    sections.apply_points(&mut map);
    Ok(map)
}

/// The optional sections of a `.gmap` file, as read (each entry with its line).
#[derive(Default)]
struct Sections {
    points: Vec<(u32, Point, usize)>,
    labels: Vec<(usize, u32, Labels, usize)>,
}

impl Sections {
    /// Refuses two lines for one cell, and labels above dimension `max_dim`.
    fn check(&self, map: &DenseMap, name: &str, max_dim: usize) -> Result<(), ReadError> {
        let err = |line: usize, kind| ReadError::new(name, Some(line), kind);
        if !self.points.is_empty() {
            first_per_cell(map, 0, self.points.iter().map(|&(d, _, l)| (d, l)), "points")
                .map_err(|(l, k)| err(l, k))?;
        }
        for dim in 0..=map.dim() {
            let lines = self.labels.iter().filter(|l| l.0 == dim).map(|l| (l.1, l.3));
            first_per_cell(map, dim, lines, &format!("labels {dim}")).map_err(|(l, k)| err(l, k))?;
        }
        if let Some(&(dim, _, _, line)) = self.labels.iter().find(|l| l.0 > max_dim) {
            return Err(err(line, ReadErrorKind::LabelDimension { dim, max: max_dim }));
        }
        Ok(())
    }

    /// Puts each point on every dart of its vertex. O(N n).
    fn apply_points(&self, map: &mut DenseMap) {
        for &(d, p, _) in &self.points {
            for x in map.orbit(Dart::new(d), AlphaSet::cell(0, map.dim())) {
                map.set_point(x, Some(p));
            }
        }
    }
}

/// Checks that no two of `lines` (dart, line) name the same `dim`-cell. O(N n) when there
/// is a line.
fn first_per_cell(
    map: &DenseMap,
    dim: usize,
    lines: impl Iterator<Item = (u32, usize)>,
    what: &str,
) -> Result<(), (usize, ReadErrorKind)> {
    let mut lines = lines.peekable();
    if lines.peek().is_none() {
        return Ok(());
    }
    let cells = map.cells(dim);
    let mut seen: Vec<Option<(u32, usize)>> = vec![None; cells.len()];
    for (d, line) in lines {
        let c = cells.cell_of(Dart::new(d)).index();
        if let Some((other, other_line)) = seen[c] {
            let kind = ReadErrorKind::DuplicateCell {
                what: what.to_string(),
                dart: d as u64,
                other: other as u64,
                other_line,
            };
            return Err((line, kind));
        }
        seen[c] = Some((d, line));
    }
    Ok(())
}

/// Reads the `.gmap` text into the map (validated) and its sections (syntax checked).
fn parse_parts(bytes: &[u8], name: &str, opts: &ReadOptions) -> Result<(DenseMap, Sections), ReadError> {
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
                        dart: Dart::new(d as u32),
                        alpha: i,
                        target: Dart::new(u32::try_from(v).unwrap_or(u32::MAX)),
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
    let sections = read_tail(&mut s, name, dim, darts)?;
    let map = DenseMap::from_flat_unchecked(dim, alpha)
        .map_err(|e| validity_to_read_error(e, name, bytes, data_start, data_line))?;
    map.validate().map_err(|e| validity_to_read_error(e, name, bytes, data_start, data_line))?;
    Ok((map, sections))
}

/// The sections after the dart lines, from `s` (just after the last dart line) to the end;
/// a data line there is one dart too many.
fn read_tail(s: &mut Scanner, name: &str, dim: usize, darts: u64) -> Result<Sections, ReadError> {
    s.skip_empty_lines();
    let mut sections = Sections::default();
    if !s.at_end() {
        let mut peek = Scanner { b: s.b, pos: s.pos, line: s.line };
        peek.skip_blank();
        if peek.b.get(peek.pos).is_some_and(u8::is_ascii_digit) {
            return Err(ReadError::new(name, Some(s.line), ReadErrorKind::ExtraLines { expected: darts }));
        }
        read_sections(s, name, dim, darts, &mut sections)?;
    }
    Ok(sections)
}

/// Bytes read from the file at a time by [`stream_gmap`].
const CHUNK: usize = 1 << 22;

/// Reads a well-formed `.gmap` file a chunk at a time, so that nothing but the map (and one
/// chunk, and the sections) is ever held, and from the second chunk on (a quarter of a chunk
/// of whole lines at least) the lines are read by several threads: `None` at the first thing out of the ordinary (a
/// bad header or line, a dart limit or memory estimate exceeded, a map that is not valid, an
/// I/O error), for which the caller parses the whole file to name the fault exactly.
/// Accepts exactly what [`parse_gmap_with`] accepts, and gives the same map. O(file size)
/// plus the validation.
fn stream_gmap(path: &Path, name: &str, opts: &ReadOptions, chunk: usize) -> Option<DenseMap> {
    use std::io::Read as _;
    let mut file = std::fs::File::open(path).ok()?;
    let size = file.metadata().ok()?.len();
    let mut buf: Vec<u8> = Vec::with_capacity(chunk + 64);
    // (dimension, darts) once the header is read; the values; the physical line of the next
    // line; the bytes of the file from the end of the dart lines on
    let mut header: Option<(usize, u64)> = None;
    let mut alpha: Vec<u32> = Vec::new();
    let mut line = 1usize;
    let mut tail: Option<(Vec<u8>, usize)> = None;
    let mut eof = false;
    while !eof {
        // keep the unfinished last line, then read up to a chunk more
        let mut k = buf.len();
        // a line that outgrows the memory left: the whole-file parser names the fault
        buf.try_reserve(chunk).ok()?;
        buf.resize(k + chunk, 0);
        while k < buf.len() {
            match file.read(&mut buf[k..]) {
                Ok(0) => {
                    eof = true;
                    break;
                }
                Ok(r) => k += r,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(_) => return None,
            }
        }
        buf.truncate(k);
        // the complete lines of the buffer (all of it at the end of the file)
        let end = if eof { buf.len() } else { buf.iter().rposition(|&c| c == b'\n').map_or(0, |p| p + 1) };
        if end == 0 && !eof {
            // a line longer than a chunk: read on, up to 64 chunks (no map's line is that
            // long: the whole-file parser, after its memory check, names the fault)
            if buf.len() >= 64 * chunk {
                return None;
            }
            continue;
        }
        let mut pos = 0;
        while pos < end {
            if let Some((t, _)) = &mut tail {
                t.try_reserve(end - pos).ok()?;
                t.extend_from_slice(&buf[pos..end]);
                break;
            }
            let stop = buf[pos..end].iter().position(|&c| c == b'\n').map_or(end, |p| pos + p + 1);
            let text = &buf[pos..stop];
            let content = is_content(text.strip_suffix(b"\n").unwrap_or(text));
            match header {
                Some((dim, darts)) if (alpha.len() as u64) < darts * (dim as u64 + 1) => {
                    if pos == 0 && end >= chunk / 4 {
                        // the whole buffer at once, in pieces on the stages' threads, when
                        // its lines are all dart lines (else line by line below)
                        if let Some(lines) = dart_lines_parallel(&buf[..end], dim + 1, darts, &mut alpha) {
                            line += lines;
                            break;
                        }
                    }
                    dart_line(text, content, dim + 1, darts, &mut alpha)?;
                }
                Some(_) => {
                    tail = Some((buf[pos..end].to_vec(), line));
                    break;
                }
                None => {
                    std::str::from_utf8(text).ok()?;
                    if content {
                        let (dim, darts) = stream_header(text, opts)?;
                        let total = usize::try_from(darts * (dim as u64 + 1)).ok()?;
                        crate::resources::check_memory("the map", Some(total as u64 * 4)).ok()?;
                        let reserve = total.min(usize::try_from(size / 2).ok()? + dim + 1);
                        alpha.try_reserve_exact(reserve).ok()?;
                        header = Some((dim, darts));
                    }
                }
            }
            line += 1;
            pos = stop;
        }
        buf.drain(..end);
    }
    let (dim, darts) = header?;
    if (alpha.len() as u64) < darts * (dim as u64 + 1) {
        return None;
    }
    drop(buf);
    let (bytes, tail_line) = tail.unwrap_or((Vec::new(), line));
    std::str::from_utf8(&bytes).ok()?;
    let mut s = Scanner { b: &bytes, pos: 0, line: tail_line };
    let sections = read_tail(&mut s, name, dim, darts).ok()?;
    let mut map = DenseMap::from_flat_unchecked(dim, alpha).ok()?;
    map.validate().ok()?;
    sections.check(&map, name, dim).ok()?;
    sections.apply_points(&mut map);
    Some(map)
}

/// Reads one line of the dart section onto `alpha`: `w` values below `darts` (nothing for a
/// blank or comment line, `content` false); `None` if the line is anything else.
fn dart_line(text: &[u8], content: bool, w: usize, darts: u64, alpha: &mut Vec<u32>) -> Option<()> {
    if fast_line(text, 0, w, darts, alpha).is_some() {
        return Some(());
    }
    std::str::from_utf8(text).ok()?;
    if content {
        let mut s = Scanner::new(text);
        for _ in 0..w {
            match s.number() {
                Num::Value(v) if v < darts => alpha.push(v as u32),
                _ => return None,
            }
        }
        s.skip_blank();
        if !s.at_eol() {
            return None;
        }
    }
    Some(())
}

/// Reads `lines` (complete lines) as dart lines, cut at line ends into one piece per thread
/// of [`crate::parallel`] (run as its tasks), and appends their values to `alpha` in order: the number of lines
/// read, or `None` (with `alpha` untouched) when a line is not a dart line or the lines
/// hold more darts than the `darts` announced, which are read line by line instead.
fn dart_lines_parallel(lines: &[u8], w: usize, darts: u64, alpha: &mut Vec<u32>) -> Option<usize> {
    let threads = crate::parallel::max_threads();
    let mut cuts = vec![0];
    for k in 1..threads {
        let at = (lines.len() * k / threads).max(*cuts.last()?);
        let next = lines[at..].iter().position(|&c| c == b'\n').map_or(lines.len(), |p| at + p + 1);
        cuts.push(next);
    }
    cuts.push(lines.len());
    let pieces: Vec<&[u8]> = cuts.windows(2).map(|c| &lines[c[0]..c[1]]).collect();
    let parsed = crate::parallel::map_parts(pieces, |piece| {
        let mut values = Vec::with_capacity(piece.len() / 4);
        let mut count = 0;
        for text in piece.split_inclusive(|&c| c == b'\n') {
            let content = is_content(text.strip_suffix(b"\n").unwrap_or(text));
            dart_line(text, content, w, darts, &mut values)?;
            count += 1;
        }
        Some((values, count))
    });
    let parsed: Vec<(Vec<u32>, usize)> = parsed.into_iter().collect::<Option<_>>()?;
    let values: usize = parsed.iter().map(|p| p.0.len()).sum();
    if (alpha.len() + values) as u64 > darts * w as u64 {
        return None;
    }
    let mut lines = 0;
    for (v, count) in parsed {
        alpha.extend_from_slice(&v);
        lines += count;
    }
    Some(lines)
}

/// The dimension and dart count of a header line that [`parse_parts`] accepts within `opts`.
fn stream_header(text: &[u8], opts: &ReadOptions) -> Option<(usize, u64)> {
    let mut s = Scanner::new(text);
    if s.token() != Some(b"gmap") {
        return None;
    }
    let (Num::Value(dim), Num::Value(darts)) = (s.number(), s.number()) else { return None };
    if s.token().is_some() || dim > MAX_DIM as u64 || darts >= u32::MAX as u64 {
        return None;
    }
    let total = darts.checked_mul(dim + 1).and_then(|t| usize::try_from(t).ok())?;
    if total > isize::MAX as usize / 4 || opts.max_darts.is_some_and(|limit| darts > limit) {
        return None;
    }
    Some((dim as usize, darts))
}

const POINTS_HEADER: &str = "points <count>";
const LABELS_HEADER: &str = "labels <dim> <count>";

/// Reads the sections after the dart lines, up to the end of the file.
fn read_sections(s: &mut Scanner, name: &str, dim: usize, darts: u64, out: &mut Sections) -> Result<(), ReadError> {
    let err = |line: usize, kind| ReadError::new(name, Some(line), kind);
    let mut previous: Option<(String, u64)> = None;
    while !s.at_end() {
        let header_line = s.line;
        s.skip_blank();
        let found = s.rest_of_line();
        if let (Some((section, expected)), true) = (&previous, found.first().is_some_and(u8::is_ascii_digit)) {
            let kind = ReadErrorKind::ExtraSectionLines { section: section.clone(), expected: *expected };
            return Err(err(header_line, kind));
        }
        let bad = |expected| err(header_line, ReadErrorKind::BadHeader { expected, found: shorten(found, 60) });
        let (expected, cell_dim) = match s.token() {
            Some(b"points") => (POINTS_HEADER, None),
            Some(b"labels") => match s.number() {
                Num::Value(v) if v <= dim as u64 => (LABELS_HEADER, Some(v as usize)),
                Num::Value(v) => {
                    let kind =
                        ReadErrorKind::LabelDimension { dim: usize::try_from(v).unwrap_or(usize::MAX), max: dim };
                    return Err(err(header_line, kind));
                }
                _ => return Err(bad(LABELS_HEADER)),
            },
            _ => return Err(err(header_line, ReadErrorKind::UnknownSection { found: shorten(found, 60) })),
        };
        let count = match s.number() {
            Num::Value(v) => v,
            _ => return Err(bad(expected)),
        };
        if s.token().is_some() {
            return Err(bad(expected));
        }
        let section = shorten(found, 60);
        previous = Some((section.clone(), count));
        s.next_line();
        for k in 0..count {
            s.skip_empty_lines();
            if s.at_end() {
                let kind = ReadErrorKind::SectionTruncated { section, expected: count, found: k };
                return Err(err(s.line, kind));
            }
            let line = s.line;
            let line_start = s.pos;
            let what = if cell_dim.is_some() { "labels" } else { "points" };
            let d = match s.number() {
                Num::Value(v) if v < darts => v as u32,
                Num::Value(v) => {
                    return Err(err(line, ReadErrorKind::SectionDart { what: what.into(), dart: v, darts }));
                }
                Num::Bad(tok) => return Err(err(line, bad_number(format!("{what}: dart"), tok))),
                Num::Eol => return Err(err(line, bad_number(format!("{what}: dart"), b""))),
            };
            match cell_dim {
                None => out.points.push((d, read_point(s, d).map_err(|k| err(line, k))?, line)),
                Some(i) => {
                    let rest = std::str::from_utf8(s.rest_of_line()).unwrap_or_default();
                    // the columns before `rest` are ASCII (blanks and digits): bytes = characters
                    let labels = parse_labels(rest, s.pos - line_start).map_err(|why| {
                        err(line, ReadErrorKind::BadLabels { what: format!("labels of dart {d}"), why })
                    })?;
                    out.labels.push((i, d, labels, line));
                }
            }
            s.next_line();
        }
        s.skip_empty_lines();
    }
    Ok(())
}

/// Reads `x y [z]` of the point of dart `d`, to the end of the line.
fn read_point(s: &mut Scanner, d: u32) -> Result<Point, ReadErrorKind> {
    let what = format!("point of dart {d}");
    let mut p = [0.0; 3];
    let mut k = 0;
    while let Some(tok) = s.token() {
        if k == 3 {
            return Err(ReadErrorKind::WrongValueCount {
                what,
                expected: "2 or 3".into(),
                found: 4 + s.count_tokens(),
            });
        }
        let v = std::str::from_utf8(tok).ok().and_then(|t| t.parse::<f64>().ok()).filter(|v| v.is_finite());
        match v {
            Some(v) => p[k] = v,
            None => return Err(ReadErrorKind::BadCoordinate { what, token: shorten(tok, 40) }),
        }
        k += 1;
    }
    if k < 2 {
        return Err(ReadErrorKind::WrongValueCount { what, expected: "2 or 3".into(), found: k });
    }
    Ok(p)
}

/// Reads a `.gmap` file with its sections into a [`LabelledGMap`]: the points on their
/// vertices, the labels on their cells (dimensions up to
/// [`MAX_LABELLED_DIM`](crate::labels::MAX_LABELLED_DIM)). Errors name the file and line.
pub fn read_labelled_gmap(path: impl AsRef<Path>) -> Result<LabelledGMap, ReadError> {
    read_labelled_gmap_with(path, &ReadOptions::default())
}

/// [`read_labelled_gmap`] with options.
pub fn read_labelled_gmap_with(path: impl AsRef<Path>, opts: &ReadOptions) -> Result<LabelledGMap, ReadError> {
    let (bytes, name) = gmap_bytes(path.as_ref(), opts)?;
    parse_labelled_gmap_with(&bytes, &name, opts)
}

/// Parses the bytes of a `.gmap` file into a [`LabelledGMap`]; `name` is the file name used
/// in errors. Never panics, whatever the bytes.
pub fn parse_labelled_gmap(bytes: &[u8], name: &str) -> Result<LabelledGMap, ReadError> {
    parse_labelled_gmap_with(bytes, name, &ReadOptions::default())
}

/// [`parse_labelled_gmap`] with options.
pub fn parse_labelled_gmap_with(bytes: &[u8], name: &str, opts: &ReadOptions) -> Result<LabelledGMap, ReadError> {
    let (mut map, sections) = parse_parts(bytes, name, opts)?;
    sections.check(&map, name, map.dim().min(MAX_LABELLED_DIM))?;
    sections.apply_points(&mut map);
    let (mut g, ids) = LabelledGMap::from_dense_with_attributes(&map);
    for (dim, d, labels, _) in &sections.labels {
        set_labels(&mut g, *dim, ids[*d as usize], labels.clone());
    }
    Ok(g)
}

/// Sets the labels of the `dim`-cell of `d` (`dim <= MAX_LABELLED_DIM` and `dim <= n`,
/// checked by the caller).
fn set_labels(g: &mut LabelledGMap, dim: usize, d: DartId, l: Labels) {
    let _ = match dim {
        0 => g.try_set_attribute::<0>(d, l),
        1 => g.try_set_attribute::<1>(d, l),
        2 => g.try_set_attribute::<2>(d, l),
        3 => g.try_set_attribute::<3>(d, l),
        4 => g.try_set_attribute::<4>(d, l),
        _ => g.try_set_attribute::<5>(d, l),
    };
}

/// The `.gmap` text of a [`LabelledGMap`]: the darts in storage order, the points, then a
/// `labels` section per dimension that has labels (each cell named by its first dart in
/// storage order). O(N n).
pub fn format_labelled_gmap(g: &LabelledGMap) -> Vec<u8> {
    use std::fmt::Write as _;
    let (dense, ids) = g.to_dense_with_ids();
    let mut out = format_gmap(&dense);
    let mut index: slotmap::SecondaryMap<DartId, u32> = slotmap::SecondaryMap::with_capacity(ids.len());
    for (k, &d) in ids.iter().enumerate() {
        index.insert(d, k as u32);
    }
    for dim in 0..=g.dim().min(MAX_LABELLED_DIM) {
        let mut lines = String::new();
        let mut count = 0;
        for d in g.one_dart_per_cell(dim) {
            if let Some(l) = crate::labels::cell_labels(g, dim, d) {
                count += 1;
                let _ =
                    if l.is_empty() { writeln!(lines, "{}", index[d]) } else { writeln!(lines, "{} {l}", index[d]) };
            }
        }
        if count > 0 {
            out.extend_from_slice(format!("labels {dim} {count}\n").as_bytes());
            out.extend_from_slice(lines.as_bytes());
        }
    }
    out
}

/// Writes a [`LabelledGMap`] to `path` in the `.gmap` format with its sections, through a
/// temporary file renamed over `path`.
pub fn write_labelled_gmap(g: &LabelledGMap, path: impl AsRef<Path>) -> Result<(), WriteError> {
    write_atomically(path.as_ref(), &format_labelled_gmap(g))
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

/// The `.gmap` text of a map (no comment line): the dart lines, then a `points` section when
/// some dart has a point (one line per vertex, from its first dart with a point). O(N n).
pub fn format_gmap(map: &DenseMap) -> Vec<u8> {
    let mut out = Vec::with_capacity(32 + map.flat().len() * 8);
    // a Vec takes every write
    let _ = write_gmap_to(map, &mut out);
    out
}

/// The size of the pieces [`write_gmap_to`] formats before handing them to the writer.
const WRITE_PIECE: usize = 1 << 20;

/// Writes `map` to any writer in the `.gmap` format, formatted a piece of about a MiB at a
/// time (a map of any size is not held twice).
pub fn write_gmap_to(map: &DenseMap, out: &mut impl std::io::Write) -> std::io::Result<()> {
    let w = map.dim() + 1;
    let mut buf = Vec::with_capacity(WRITE_PIECE + 128);
    buf.extend_from_slice(format!("gmap {} {}\n", map.dim(), map.dart_count()).as_bytes());
    for row in map.flat().chunks_exact(w) {
        for (i, &v) in row.iter().enumerate() {
            if i > 0 {
                buf.push(b' ');
            }
            push_u32(&mut buf, v);
        }
        buf.push(b'\n');
        if buf.len() >= WRITE_PIECE {
            out.write_all(&buf)?;
            buf.clear();
        }
    }
    if map.has_points() {
        let vertices = map.cells(0);
        let mut first: Vec<Option<(u32, Point)>> = vec![None; vertices.len()];
        for d in map.darts() {
            let c = vertices.cell_of(d).index();
            if first[c].is_none() {
                first[c] = map.point(d).map(|p| (d.get(), p));
            }
        }
        let lines: Vec<(u32, Point)> = first.into_iter().flatten().collect();
        buf.extend_from_slice(format!("points {}\n", lines.len()).as_bytes());
        for (d, p) in lines {
            buf.extend_from_slice(format!("{d} {:?} {:?} {:?}\n", p[0], p[1], p[2]).as_bytes());
            if buf.len() >= WRITE_PIECE {
                out.write_all(&buf)?;
                buf.clear();
            }
        }
    }
    out.write_all(&buf)
}

/// Writes `map` to `path` in the `.gmap` format, through a temporary file in the same
/// directory renamed over `path` (no partial file on failure), streamed: beyond the map,
/// a piece of about a MiB is held.
pub fn write_gmap(map: &DenseMap, path: impl AsRef<Path>) -> Result<(), WriteError> {
    let path = path.as_ref();
    write_atomic_with(path, |mut w| write_gmap_to(map, &mut w))
        .map_err(|source| WriteError::Io { path: path.to_path_buf(), source })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::examples;

    fn msg(bytes: &[u8]) -> String {
        parse_gmap(bytes, "f.gmap").unwrap_err().to_string()
    }

    #[test]
    fn a_map_written_in_pieces_is_the_formatted_map() {
        // 200,000 free darts: about 5 MB of text, several pieces
        let m = DenseMap::new(3, 200_000);
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("big.gmap");
        write_gmap(&m, &p).unwrap();
        let written = std::fs::read(&p).unwrap();
        assert!(written.len() > 4 * WRITE_PIECE);
        assert_eq!(written, format_gmap(&m));
        assert_eq!(read_gmap(&p).unwrap(), m);
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

    /// The chunked reader gives the map the whole-file parser gives, whatever the chunk
    /// boundaries, and gives up (for the whole-file parser to name the fault) exactly where
    /// that one fails; `read_gmap` reports the same either way.
    #[test]
    fn streaming_equals_whole_file() {
        let mut files: Vec<Vec<u8>> = [examples::fig1_surface(), examples::cylinder(), examples::klein_bottle()]
            .iter()
            .map(format_gmap)
            .collect();
        let mut pointed = examples::torus();
        for d in 0..pointed.dart_count() as u32 {
            pointed.set_point(Dart::new(d), Some([f64::from(d % 3), 1.5, 0.0]));
        }
        let pointed = parse_gmap(&format_gmap(&pointed), "x").unwrap();
        files.push(format_gmap(&pointed));
        // many lines, a comment among them: the pieces read in parallel
        let mut big = DenseMap::new(1, 2000);
        for d in (0..2000).step_by(2) {
            big.link(Dart::new(d), Dart::new(d + 1), 0);
        }
        let text = format_gmap(&big);
        let middle = text.len() / 2 + text[text.len() / 2..].iter().position(|&c| c == b'\n').unwrap() + 1;
        files.push([&text[..middle], b"  # a comment\n\n", &text[middle..]].concat());
        files.push([&text[..middle], b"0 x\n", &text[middle..]].concat());
        for text in [
            &b"# a comment\n\n  # another\r\ngmap 1 2\r\n1\t1\r\n\n# mid\n0 0  \r\n\n"[..],
            b"gmap 1 2\n1 1\n0 0",
            b"gmap 3 0\n",
            b"gmap 1 2\n1 1\n0 0\nlabels 0 1\n0 name=\"a\"\n",
            b"",
            b"map 1 2\n",
            b"gmap 1 2 3\n",
            b"gmap 2 4000000000\n0 0 0\n",
            b"gmap 1 3\n0 0\n1 1\n",
            b"gmap 1 1\n0 0\n0 0\n",
            b"gmap 1 2\n0 0\n1\n",
            b"gmap 1 2\n0 0\n1 2\n",
            b"gmap 1 2\n0 0\n1 \xff\n",
            b"gmap 1 2\n0 0\n# \xff\n1 1\n",
            b"gmap 1 3\n1 0\n2 1\n1 2\n",
            b"gmap 1 2\n1 1\n0 0\npoints 1\n0 1 2\n",
            b"gmap 1 2\n1 1\n0 0\npoints 2\n0 1 2\n1 1 2\n",
        ] {
            files.push(text.to_vec());
        }
        let dir = tempfile::tempdir().unwrap();
        for (k, bytes) in files.iter().enumerate() {
            let path = dir.path().join(format!("{k}.gmap"));
            std::fs::write(&path, bytes).unwrap();
            let name = path.display().to_string();
            let whole = parse_gmap_with(bytes, &name, &ReadOptions::default());
            for chunk in [CHUNK, 4096, 64, 7, 3, 2, 1] {
                let streamed = stream_gmap(&path, &name, &ReadOptions::default(), chunk);
                assert_eq!(streamed.as_ref(), whole.as_ref().ok(), "file {k}, chunk {chunk}");
            }
            assert_eq!(read_gmap(&path), whole, "file {k}");
        }
        // a dart limit below the header's count: refused by the whole-file path's message
        let path = dir.path().join("0.gmap");
        let opts = ReadOptions { max_darts: Some(3) };
        assert!(stream_gmap(&path, "x", &opts, CHUNK).is_none());
        assert!(read_gmap_with(&path, &opts).unwrap_err().to_string().contains("3"));
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

#[cfg(test)]
mod section_tests {
    use super::*;
    use crate::labels::LabelValue;
    use crate::{examples, GMap};

    fn msg(bytes: &[u8]) -> String {
        parse_labelled_gmap(bytes, "f.gmap").unwrap_err().to_string()
    }

    /// A segment (1-map, 2 darts) with sections.
    const SEGMENT: &str = "gmap 1 2\n1 0\n0 1\n";

    #[test]
    fn points_and_labels_read_and_write_back() {
        let text = format!(
            "{SEGMENT}points 2\n0 0 0 0\n1 1.5 -2\n# a comment between sections\nlabels 1 1\n1 name=\"a \\\"b\\\"\\nc\" n=3 x=0.25\nlabels 0 1\n0\n"
        );
        let g = parse_labelled_gmap(text.as_bytes(), "s.gmap").unwrap();
        let d: Vec<_> = g.darts().collect();
        assert_eq!(g.point(d[0]), Some([0.0, 0.0, 0.0]));
        assert_eq!(g.point(d[1]), Some([1.5, -2.0, 0.0]));
        let edge = g.attribute::<1>(d[0]).unwrap();
        assert_eq!(edge.get("name"), Some(&LabelValue::Text("a \"b\"\nc".into())));
        assert_eq!(edge.get("n"), Some(&LabelValue::Int(3)));
        assert_eq!(edge.get("x"), Some(&LabelValue::Real(0.25)));
        assert_eq!(g.attribute::<0>(d[0]), Some(&Labels::new()));
        assert_eq!(g.attribute::<0>(d[1]), None);
        let out = String::from_utf8(format_labelled_gmap(&g)).unwrap();
        assert_eq!(
            out,
            "gmap 1 2\n1 0\n0 1\npoints 2\n0 0.0 0.0 0.0\n1 1.5 -2.0 0.0\nlabels 0 1\n0\nlabels 1 1\n0 name=\"a \\\"b\\\"\\nc\" n=3 x=0.25\n"
        );
        let back = parse_labelled_gmap(out.as_bytes(), "s.gmap").unwrap();
        assert_eq!(format_labelled_gmap(&back), out.as_bytes());
        // the dense reader keeps the points on every dart of the vertex, drops the labels
        let dense = parse_gmap(text.as_bytes(), "s.gmap").unwrap();
        assert_eq!(dense.point(Dart::new(1)), Some([1.5, -2.0, 0.0]));
        assert_eq!(parse_gmap(&format_gmap(&dense), "x").unwrap(), dense);
    }

    #[test]
    fn a_map_with_points_on_every_vertex_round_trips() {
        let (mut g, ids) = GMap::from_dense(&examples::cylinder());
        for (k, &d) in ids.iter().enumerate() {
            if g.point(d).is_none() {
                g.set_point(d, Some([k as f64, 0.1 * k as f64, -3.0]));
            }
        }
        let dense = g.to_dense_map();
        let text = format_gmap(&dense);
        assert_eq!(parse_gmap(&text, "c.gmap").unwrap(), dense);
    }

    #[test]
    fn malformed_sections_name_the_line() {
        let m = |rest: &str| msg(format!("{SEGMENT}{rest}").as_bytes());
        assert_eq!(m("  0 0\n"), "f.gmap:4: more dart lines than the 2 darts the header announces");
        assert_eq!(m("colors 1\n"), "f.gmap:4: unknown section `colors 1`: after the dart lines a `.gmap` file holds only `points <count>` and `labels <dim> <count>` sections");
        assert_eq!(m("points\n"), "f.gmap:4: bad header: expected `points <count>`, found `points`");
        assert_eq!(m("points 1 2\n"), "f.gmap:4: bad header: expected `points <count>`, found `points 1 2`");
        assert_eq!(m("labels x 1\n"), "f.gmap:4: bad header: expected `labels <dim> <count>`, found `labels x 1`");
        assert_eq!(
            m("labels 2 1\n0\n"),
            "f.gmap:4: labels on 2-cells cannot be held here: the cells of dimension at most 1 can be labelled"
        );
        assert_eq!(
            m("points 2\n0 0 0\n"),
            "f.gmap:6: truncated: the `points 2` section announces 2 lines but the file ends after 1"
        );
        assert_eq!(m("points 1\n2 0 0\n"), "f.gmap:5: points: dart 2 does not exist (the map has 2 darts)");
        assert_eq!(m("points 1\n-1 0 0\n"), "f.gmap:5: points: dart: `-1` is negative");
        assert_eq!(m("points 1\n0 0\n"), "f.gmap:5: point of dart 0: expected 2 or 3 values, found 1");
        assert_eq!(m("points 1\n0 0 0 0 0\n"), "f.gmap:5: point of dart 0: expected 2 or 3 values, found 4");
        assert_eq!(m("points 1\n0 0 nan\n"), "f.gmap:5: point of dart 0: `nan` is not a finite number");
        assert_eq!(
            m("labels 1 2\n0 a=1\n1 a=2\n"),
            "f.gmap:6: labels 1: dart 1 is in the same cell as dart 0 of line 5, which already has a value"
        );
        assert_eq!(m("labels 1 1\n0 a=\"x\n"), "f.gmap:5: labels of dart 0: column 5: the quoted text is not closed");
        assert_eq!(m("points 1\n0 0 0\n9 9\n"), "f.gmap:6: more lines than the 1 the `points 1` section announces");
        // the dense reader checks the sections too
        assert!(parse_gmap(format!("{SEGMENT}points 1\n0 0 x\n").as_bytes(), "f").is_err());
    }

    #[test]
    fn labels_above_the_labelled_dimensions_are_refused() {
        let mut text = b"gmap 6 1\n0 0 0 0 0 0 0\nlabels 6 1\n0 a=1\n".to_vec();
        assert_eq!(
            msg(&text),
            "f.gmap:4: labels on 6-cells cannot be held here: the cells of dimension at most 5 can be labelled"
        );
        // the dense reader takes them (and drops them)
        assert!(parse_gmap(&text, "f").is_ok());
        text = b"gmap 6 1\n0 0 0 0 0 0 0\nlabels 5 1\n0 a=1\n".to_vec();
        assert!(parse_labelled_gmap(&text, "f").is_ok());
    }
}
