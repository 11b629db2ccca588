//! What the readers and writers of both formats share: options, errors, the byte scanner
//! and the atomic writer.

use std::fmt;
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::error::ValidityError;
pub use crate::text::shorten;

/// Options of the readers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// refuse a map with more darts than this (checked on the header for `.gmap`, as the
    /// darts are read for `.moka`)
    pub max_darts: Option<u64>,
}

/// A failure to read a file: where, and why.
///
/// `Display` gives `FILE:LINE: message`, or `FILE: message` when no line applies (the
/// file could not be opened).
#[derive(Clone, Debug, PartialEq, Error)]
pub struct ReadError {
    /// the file name as given by the caller
    pub file: String,
    /// the physical line (from 1) holding the fault, when one applies
    pub line: Option<usize>,
    /// what is wrong
    pub kind: ReadErrorKind,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(l) => write!(f, "{}:{}: {}", self.file, l, self.kind),
            None => write!(f, "{}: {}", self.file, self.kind),
        }
    }
}

/// What is wrong with an input file.
#[derive(Clone, Debug, PartialEq, Error)]
#[non_exhaustive]
pub enum ReadErrorKind {
    /// The file could not be read.
    #[error("cannot read the file: {0}")]
    Io(String),
    /// The file has no header (it is empty, or holds only comments and blank lines).
    #[error("the file is empty: expected the header `{expected}`")]
    Empty {
        /// the header the format requires
        expected: &'static str,
    },
    /// The bytes are not UTF-8 text.
    #[error("not UTF-8 text: invalid byte at offset {offset}")]
    NotUtf8 {
        /// offset of the first invalid byte in the file
        offset: usize,
    },
    /// The header line is not what the format requires.
    #[error("bad header: expected `{expected}`, found `{found}`")]
    BadHeader {
        /// the header the format requires
        expected: &'static str,
        /// the line found (shortened to 60 characters)
        found: String,
    },
    /// The dimension in the header is above [`crate::MAX_DIM`].
    #[error("dimension {found} is larger than the supported maximum {max}", max = crate::MAX_DIM)]
    DimensionTooLarge {
        /// the dimension as written
        found: String,
    },
    /// The dart count cannot be held: it does not fit a `u32` dart index, or the involution
    /// array would not fit in memory.
    #[error("{found} darts is more than a map can hold (at most {max} darts)", max = u32::MAX - 1)]
    TooManyDarts {
        /// the count as written
        found: String,
    },
    /// The file, or the map it describes, needs more memory than can be had.
    #[error("{bytes} bytes cannot be had to hold the file or its map")]
    OutOfMemory {
        /// the size of the file
        bytes: u64,
    },
    /// The file and its map would take more than the memory limit
    /// ([`crate::resources::max_memory`]): at most three times the file's size (every value
    /// of at least two bytes becomes four).
    #[error(transparent)]
    MemoryLimit(#[from] crate::resources::MemoryLimit),
    /// The map has more darts than the caller allows ([`ReadOptions::max_darts`]).
    #[error("the map has more than {limit} darts (the limit set by the caller): {found}")]
    DartLimit {
        /// the caller's limit
        limit: u64,
        /// the count found or announced
        found: u64,
    },
    /// A token is not a non-negative decimal integer.
    #[error("{what}: `{token}` is not a non-negative integer")]
    NotANumber {
        /// which value (e.g. `dart 3, alpha_1`)
        what: String,
        /// the token (shortened to 40 characters)
        token: String,
    },
    /// A token is an integer too large for its value (above `u64::MAX`).
    #[error("{what}: `{token}` is out of range (at most 18446744073709551615)")]
    OutOfRange {
        /// which value
        what: String,
        /// the token (shortened to 40 characters)
        token: String,
    },
    /// A token is a negative integer.
    #[error("{what}: `{token}` is negative")]
    Negative {
        /// which value
        what: String,
        /// the token
        token: String,
    },
    /// A coordinate is not a finite decimal number.
    #[error("{what}: `{token}` is not a finite number")]
    BadCoordinate {
        /// which value
        what: String,
        /// the token
        token: String,
    },
    /// A Moka embedding flag other than `0` or `1`.
    #[error("dart {dart}: embedding flag `{token}` is neither 0 nor 1")]
    BadFlag {
        /// the dart
        dart: u64,
        /// the token
        token: String,
    },
    /// A line has the wrong number of values.
    #[error("{what}: expected {expected} values, found {found}")]
    WrongValueCount {
        /// which line (e.g. `dart 3`)
        what: String,
        /// how many values the line must have
        expected: String,
        /// how many it has
        found: usize,
    },
    /// The file ends before the announced number of darts.
    #[error("truncated: the header announces {expected} darts but the file ends after {found}")]
    Truncated {
        /// darts announced
        expected: u64,
        /// darts found
        found: u64,
    },
    /// The file holds more dart lines than announced.
    #[error("more dart lines than the {expected} darts the header announces")]
    ExtraLines {
        /// darts announced
        expected: u64,
    },
    /// The darts do not form a G-map (BO Def. 1).
    #[error("not a G-map (BO Def. 1): {0}")]
    Invalid(ValidityError),
    /// A line after the dart lines that starts no known section of `.gmap`.
    #[error("unknown section `{found}`: after the dart lines a `.gmap` file holds only `points <count>` and `labels <dim> <count>` sections")]
    UnknownSection {
        /// the line found (shortened)
        found: String,
    },
    /// A section of `.gmap` ends before the number of lines its header announces.
    #[error("truncated: the `{section}` section announces {expected} lines but the file ends after {found}")]
    SectionTruncated {
        /// the section's header
        section: String,
        /// lines announced
        expected: u64,
        /// lines found
        found: u64,
    },
    /// A section of `.gmap` is followed by more lines than its header announces.
    #[error("more lines than the {expected} the `{section}` section announces")]
    ExtraSectionLines {
        /// the section's header
        section: String,
        /// lines announced
        expected: u64,
    },
    /// A section line names a dart the map does not have.
    #[error("{what}: dart {dart} does not exist (the map has {darts} darts)")]
    SectionDart {
        /// which section
        what: String,
        /// the dart named
        dart: u64,
        /// the number of darts
        darts: u64,
    },
    /// Two lines of a section give a value to the same cell.
    #[error("{what}: dart {dart} is in the same cell as dart {other} of line {other_line}, which already has a value")]
    DuplicateCell {
        /// which section
        what: String,
        /// the dart of this line
        dart: u64,
        /// the dart of the earlier line
        other: u64,
        /// the earlier line
        other_line: usize,
    },
    /// A label line is malformed.
    #[error("{what}: {why}")]
    BadLabels {
        /// which line (e.g. `labels of dart 3`)
        what: String,
        /// what is wrong, at which character
        why: String,
    },
    /// Labels on cells of a dimension the map (or the reader) cannot hold.
    #[error("labels on {dim}-cells cannot be held here: the cells of dimension at most {max} can be labelled")]
    LabelDimension {
        /// the dimension of the section
        dim: usize,
        /// the largest dimension that can be labelled
        max: usize,
    },
    /// A `.moka` file records a dimension n < 3 (its last mark mask) that its darts do not
    /// have: some dart is linked along `alpha_k` for a k > n.
    #[error("the mark masks record dimension {recorded}, but dart {dart} is linked along alpha_{alpha}")]
    RecordedDimension {
        /// the dimension the file records
        recorded: usize,
        /// the first dart not free along `alpha_k`
        dart: u64,
        /// that k
        alpha: usize,
    },
}

impl ReadError {
    pub(super) fn new(file: &str, line: Option<usize>, kind: ReadErrorKind) -> Self {
        ReadError { file: file.to_string(), line, kind }
    }
}

/// A failure to write a file.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum WriteError {
    /// Creating, writing or renaming the file failed.
    #[error("{path}: cannot write the file: {source}")]
    Io {
        /// the destination
        path: PathBuf,
        /// the system error
        source: std::io::Error,
    },
    /// The format cannot hold a map of this dimension (Moka holds dimensions up to 3).
    #[error("{path}: the {format} format holds maps of dimension at most {max}, this one has dimension {dim}")]
    DimensionTooLarge {
        /// the destination
        path: PathBuf,
        /// the format's name
        format: &'static str,
        /// the largest dimension the format holds
        max: usize,
        /// the map's dimension
        dim: usize,
    },
}

/// Reads a whole file, mapping failure to a [`ReadError`] without a line. The buffer is
/// reserved fallibly: a file larger than the memory to be had is an error naming its size,
/// not an abort.
pub(super) fn read_bytes(path: &Path) -> Result<Vec<u8>, ReadError> {
    use std::io::Read as _;
    let io_err =
        |e: std::io::Error| ReadError::new(&path.display().to_string(), None, ReadErrorKind::Io(e.to_string()));
    let mut f = fs::File::open(path).map_err(io_err)?;
    let size = f.metadata().map(|m| m.len()).unwrap_or(0);
    crate::resources::check_memory("the file and its map", size.checked_mul(3))
        .map_err(|e| ReadError::new(&path.display().to_string(), None, ReadErrorKind::MemoryLimit(e)))?;
    let mut bytes = Vec::new();
    let want = usize::try_from(size).unwrap_or(usize::MAX);
    if bytes.try_reserve_exact(want).is_err() {
        return Err(ReadError::new(&path.display().to_string(), None, ReadErrorKind::OutOfMemory { bytes: size }));
    }
    f.read_to_end(&mut bytes).map_err(io_err)?;
    Ok(bytes)
}

/// Calls `f` on each line of the file at `path` (its number from 1 and at most its first
/// `keep` bytes after its leading blanks, without the newline), streaming: never more than a buffer and `keep` bytes
/// in memory, whatever the file. Stops when `f` returns `false`. Used to check a size limit
/// before the whole file is read.
pub(super) fn scan_lines(path: &Path, keep: usize, mut f: impl FnMut(usize, &[u8]) -> bool) -> std::io::Result<()> {
    use std::io::Read as _;
    let mut file = fs::File::open(path)?;
    let mut buf = vec![0u8; 1 << 16];
    let mut line = Vec::with_capacity(keep);
    let mut number = 1;
    loop {
        let k = match file.read(&mut buf) {
            Ok(0) => break,
            Ok(k) => k,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        for &c in &buf[..k] {
            if c == b'\n' {
                if !f(number, &line) {
                    return Ok(());
                }
                line.clear();
                number += 1;
            } else if line.len() < keep && !(line.is_empty() && matches!(c, b' ' | b'\t' | b'\r')) {
                // leading blanks are not kept: the first byte kept tells a comment line
                line.push(c);
            }
        }
    }
    if !line.is_empty() {
        f(number, &line);
    }
    Ok(())
}

/// Whether a line holds data: not blank and not a comment (first non-blank byte `#`), as
/// [`Scanner::skip_empty_lines`] decides.
pub(super) fn is_content(line: &[u8]) -> bool {
    match line.iter().find(|c| !matches!(c, b' ' | b'\t' | b'\r')) {
        None | Some(b'#') => false,
        Some(_) => true,
    }
}

/// Writes `bytes` to `path` so that readers of `path` see either the old file or the whole
/// new one, never a part: the one file writer of the workspace, used by every format.
///
/// The bytes go to a temporary file created exclusively (`O_EXCL`, a random name: a planted
/// symbolic link is never followed) in the destination's own folder, are flushed to disk,
/// and the file is renamed over `path`. The result has the permissions of the file it
/// replaces, or `0644` for a new file. On any failure the temporary file is removed and
/// `path` is left as it was.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomic_with(path, |w| w.write_all(bytes))
}

/// [`write_atomic`] for contents too large to hold in memory: `write` streams them into the
/// temporary file (buffered), which then replaces `path` as in [`write_atomic`].
pub fn write_atomic_with(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let mut tmp = tempfile::Builder::new().prefix(&format!(".{name}.")).suffix(".tmp").tempfile_in(dir)?;
    {
        let mut w = std::io::BufWriter::with_capacity(1 << 20, tmp.as_file_mut());
        write(&mut w)?;
        w.flush()?;
    }
    let perms = match fs::metadata(path) {
        Ok(m) if m.is_file() => Some(m.permissions()),
        _ => default_permissions(),
    };
    if let Some(p) = perms {
        tmp.as_file().set_permissions(p)?;
    }
    tmp.as_file().sync_all()?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

/// `0644` on Unix; elsewhere the temporary file keeps what the system gave it.
pub(super) fn default_permissions() -> Option<fs::Permissions> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        Some(fs::Permissions::from_mode(0o644))
    }
    #[cfg(not(unix))]
    {
        None
    }
}

/// [`write_atomic`] with the error as a [`WriteError`] naming the file.
pub(super) fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), WriteError> {
    write_atomic(path, bytes).map_err(|source| WriteError::Io { path: path.to_path_buf(), source })
}

/// Appends the decimal digits of `v` to `out`.
#[inline]
pub(super) fn push_u32(out: &mut Vec<u8>, mut v: u32) {
    let mut buf = [0u8; 10];
    let mut k = buf.len();
    loop {
        k -= 1;
        buf[k] = b'0' + (v % 10) as u8;
        v /= 10;
        if v == 0 {
            break;
        }
    }
    out.extend_from_slice(&buf[k..]);
}

/// Checks that the bytes are UTF-8; on failure, names the line of the first bad byte.
pub(super) fn check_utf8(bytes: &[u8], file: &str) -> Result<(), ReadError> {
    if let Err(e) = std::str::from_utf8(bytes) {
        let offset = e.valid_up_to();
        let line = 1 + bytes[..offset].iter().filter(|&&b| b == b'\n').count();
        return Err(ReadError::new(file, Some(line), ReadErrorKind::NotUtf8 { offset }));
    }
    Ok(())
}

/// A cursor over the bytes of a text file that tracks the physical line number.
pub(super) struct Scanner<'a> {
    pub(super) b: &'a [u8],
    pub(super) pos: usize,
    /// physical line of `pos`, from 1
    pub(super) line: usize,
}

/// The outcome of reading one unsigned integer token.
pub(super) enum Num<'a> {
    /// a value (saturated at `u64::MAX` if it overflows)
    Value(u64),
    /// the end of the line: no token
    Eol,
    /// a token that is not an unsigned integer (negative or not a number)
    Bad(&'a [u8]),
}

impl<'a> Scanner<'a> {
    pub(super) fn new(b: &'a [u8]) -> Self {
        Scanner { b, pos: 0, line: 1 }
    }

    pub(super) fn at_end(&self) -> bool {
        self.pos >= self.b.len()
    }

    /// Skips spaces, tabs and carriage returns (not newlines).
    #[inline]
    pub(super) fn skip_blank(&mut self) {
        while let Some(&c) = self.b.get(self.pos) {
            if c == b' ' || c == b'\t' || c == b'\r' {
                self.pos += 1;
            } else {
                break;
            }
        }
    }

    /// Whether the cursor is at the end of a line (after blanks are skipped by the caller).
    #[inline]
    pub(super) fn at_eol(&self) -> bool {
        self.pos >= self.b.len() || self.b[self.pos] == b'\n'
    }

    /// Moves past the end of the current line.
    pub(super) fn next_line(&mut self) {
        while self.pos < self.b.len() {
            let c = self.b[self.pos];
            self.pos += 1;
            if c == b'\n' {
                self.line += 1;
                return;
            }
        }
    }

    /// Skips blank lines and lines whose first non-blank byte is `#`; stops at the start of
    /// the next line with content, or at the end.
    pub(super) fn skip_empty_lines(&mut self) {
        loop {
            let start = self.pos;
            self.skip_blank();
            if self.at_end() {
                return;
            }
            let c = self.b[self.pos];
            if c == b'\n' || c == b'#' {
                self.next_line();
            } else {
                self.pos = start;
                return;
            }
        }
    }

    /// The next whitespace-delimited token on this line, if any.
    pub(super) fn token(&mut self) -> Option<&'a [u8]> {
        self.skip_blank();
        if self.at_eol() {
            return None;
        }
        let start = self.pos;
        while self.pos < self.b.len() && !matches!(self.b[self.pos], b' ' | b'\t' | b'\r' | b'\n') {
            self.pos += 1;
        }
        Some(&self.b[start..self.pos])
    }

    /// The rest of the current line, without its end.
    pub(super) fn rest_of_line(&self) -> &'a [u8] {
        let end = self.b[self.pos..].iter().position(|&c| c == b'\n').map_or(self.b.len(), |k| self.pos + k);
        &self.b[self.pos..end]
    }

    /// Counts the tokens left on this line (moves the cursor to its end).
    pub(super) fn count_tokens(&mut self) -> usize {
        let mut k = 0;
        while self.token().is_some() {
            k += 1;
        }
        k
    }

    /// Reads an unsigned decimal integer token: the hot loop of both readers.
    #[inline]
    pub(super) fn number(&mut self) -> Num<'a> {
        self.skip_blank();
        let start = self.pos;
        let mut v: u64 = 0;
        while let Some(&c) = self.b.get(self.pos) {
            let digit = c.wrapping_sub(b'0');
            if digit > 9 {
                break;
            }
            v = v.saturating_mul(10).saturating_add(digit as u64);
            self.pos += 1;
        }
        if self.pos == start {
            if self.at_eol() {
                return Num::Eol;
            }
        } else if self.at_eol() || matches!(self.b[self.pos], b' ' | b'\t' | b'\r') {
            return Num::Value(v);
        }
        self.pos = start;
        let tok = self.token().unwrap_or(&[]);
        Num::Bad(tok)
    }
}

/// The error for a bad integer token.
pub(super) fn bad_number(what: String, tok: &[u8]) -> ReadErrorKind {
    let negative = tok.len() > 1 && tok[0] == b'-' && tok[1..].iter().all(u8::is_ascii_digit);
    let token = shorten(tok, 40);
    if negative {
        ReadErrorKind::Negative { what, token }
    } else if !tok.is_empty() && tok.iter().all(u8::is_ascii_digit) {
        ReadErrorKind::OutOfRange { what, token }
    } else {
        ReadErrorKind::NotANumber { what, token }
    }
}

/// The physical line (from 1) of the `k`-th data line (from 0) counted from byte offset
/// `start` (on line `start_line`), skipping blank and comment lines. Used on error paths.
pub(super) fn line_of_data(bytes: &[u8], start: usize, start_line: usize, k: usize) -> usize {
    let mut s = Scanner { b: bytes, pos: start, line: start_line };
    let mut seen = 0;
    loop {
        s.skip_empty_lines();
        if s.at_end() || seen == k {
            return s.line;
        }
        seen += 1;
        s.next_line();
    }
}

/// Converts a [`ValidityError`] of a freshly read map into a [`ReadError`] on the line of
/// the offending dart.
pub(super) fn validity_to_read_error(
    e: ValidityError,
    file: &str,
    bytes: &[u8],
    data_start: usize,
    data_line: usize,
) -> ReadError {
    let dart = match &e {
        ValidityError::OutOfRange { dart, .. }
        | ValidityError::NotInvolution { dart, .. }
        | ValidityError::NotCommuting { dart, .. } => Some(dart.index()),
        ValidityError::DimensionTooLarge(_)
        | ValidityError::TooManyDarts(_)
        | ValidityError::RaggedRows { .. }
        | ValidityError::OutOfMemory { .. } => None,
    };
    let line = dart.map(|d| line_of_data(bytes, data_start, data_line, d));
    ReadError::new(file, line, ReadErrorKind::Invalid(e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(unix)]
    #[test]
    pub(super) fn atomic_writer_keeps_modes_and_refuses_planted_links() {
        use std::os::unix::fs::{symlink, PermissionsExt};
        let dir = tempfile::tempdir().unwrap();
        let mode = |p: &Path| fs::metadata(p).unwrap().permissions().mode() & 0o777;
        // a new file is 0644
        let new = dir.path().join("new.gmap");
        write_atomic(&new, b"a").unwrap();
        assert_eq!(mode(&new), 0o644);
        // an existing 0664 file keeps its mode
        let old = dir.path().join("old.gmap");
        fs::write(&old, b"x").unwrap();
        fs::set_permissions(&old, fs::Permissions::from_mode(0o664)).unwrap();
        write_atomic(&old, b"yz").unwrap();
        assert_eq!((mode(&old), fs::read(&old).unwrap()), (0o664, b"yz".to_vec()));
        // a symlink planted under the old fixed temporary name is not followed
        let victim = dir.path().join("victim");
        fs::write(&victim, b"keep").unwrap();
        symlink(&victim, dir.path().join(format!(".out.json.{}.tmp", std::process::id()))).unwrap();
        write_atomic(&dir.path().join("out.json"), b"{}").unwrap();
        assert_eq!(fs::read(&victim).unwrap(), b"keep");
        // a failure leaves no temporary file behind
        assert!(write_atomic(&dir.path().join("no/such/dir/x"), b"x").is_err());
        let names: Vec<String> =
            fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        assert_eq!(names.iter().filter(|n| n.ends_with(".tmp") && !n.contains(".out.json.")).count(), 0, "{names:?}");
    }

    #[test]
    pub(super) fn scanner_numbers() {
        let mut s = Scanner::new(b"12 -3 x9 4x 18446744073709551616\n7");
        assert!(matches!(s.number(), Num::Value(12)));
        assert!(matches!(s.number(), Num::Bad(b"-3")));
        assert!(matches!(s.number(), Num::Bad(b"x9")));
        assert!(matches!(s.number(), Num::Bad(b"4x")));
        assert!(matches!(s.number(), Num::Value(u64::MAX)));
        assert!(matches!(s.number(), Num::Eol));
        s.next_line();
        assert_eq!(s.line, 2);
        assert!(matches!(s.number(), Num::Value(7)));
        assert!(matches!(s.number(), Num::Eol));
    }

    #[test]
    pub(super) fn data_lines_skip_comments() {
        let b = b"h\n1\n\n# c\n2\n3\n";
        assert_eq!(line_of_data(b, 2, 2, 0), 2);
        assert_eq!(line_of_data(b, 2, 2, 1), 5);
        assert_eq!(line_of_data(b, 2, 2, 2), 6);
        assert_eq!(line_of_data(b, 2, 2, 3), 7);
    }

    #[test]
    pub(super) fn shorten_and_push() {
        assert_eq!(shorten("é".repeat(50).as_bytes(), 3), "ééé…");
        let mut v = Vec::new();
        push_u32(&mut v, 0);
        v.push(b' ');
        push_u32(&mut v, u32::MAX);
        assert_eq!(v, b"0 4294967295");
    }
}
