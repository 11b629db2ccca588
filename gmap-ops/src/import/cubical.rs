//! Full cubical sets: CHomP's `.cub` text format and 2D Netpbm bitmaps (`.pbm`, P1 and P4),
//! read into a [`CubicalSet`], a bitmap over the bounding box (docs/FORMATS.md).
//!
//! A set is the union of closed unit cubes `[x_1, x_1 + 1] × … × [x_d, x_d + 1]`, each given
//! by its minimal vertex. [`CubicalSet::gmap`] builds the G-map of the union where that route
//! applies (every cube one d-cell, sewn to its neighbours along shared facets); the cubical
//! chain complex itself is built by `gmap_homology::cubical`.
//!
//! ```
//! use gmap_ops::import::cubical::parse_cub;
//! let s = parse_cub(b"; two squares\n(0,0)\n(1 1)\n").unwrap();
//! assert_eq!((s.dim(), s.shape(), s.cube_count()), (2, &[2usize, 2][..], 2));
//! ```

#![allow(clippy::needless_range_loop)] // axes index several arrays at once

use std::path::Path;

use gmap_core::io::shorten;
use gmap_core::DenseMap;

use super::common::{read_bytes, FileError, ImportError};

/// The largest bounding box accepted, in unit cubes (one byte each in the bitmap), whatever
/// the memory limit: the cells of its closure are numbered with `u32`. Below it, a box is
/// accepted when its estimate fits the memory limit
/// ([`gmap_core::resources::cubical_set_estimate`], checked before the bitmap is allocated).
pub const MAX_BOX_CUBES: u64 = 1 << 30;

/// A full cubical set: the cubes of a box `min + [0, shape)` that belong to the set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CubicalSet {
    min: Vec<i64>,
    shape: Vec<usize>,
    /// one byte a cube (0 or 1), axis 0 fastest
    bits: Vec<u8>,
    count: usize,
}

impl CubicalSet {
    /// A set from its box and bitmap (`bits[x_0 + s_0 (x_1 + s_1 (…))]` non-zero for a cube of
    /// the set). Refuses an empty shape, a zero size, a box over [`MAX_BOX_CUBES`] or a
    /// bitmap of the wrong length.
    pub fn new(min: Vec<i64>, shape: Vec<usize>, bits: Vec<u8>) -> Result<Self, ImportError> {
        if shape.is_empty() || min.len() != shape.len() {
            return Err(ImportError::Format("a cubical set needs dimension at least 1".into()));
        }
        let volume = box_volume(&shape)?;
        if bits.len() as u64 != volume {
            return Err(ImportError::Format(format!("a bitmap of {} bytes for a box of {volume} cubes", bits.len())));
        }
        let mut bits = bits;
        let mut count = 0;
        for b in bits.iter_mut() {
            *b = (*b != 0) as u8;
            count += *b as usize;
        }
        Ok(CubicalSet { min, shape, bits, count })
    }

    /// The same cubes in another box: the cubes from `first` to `last` (inclusive) along
    /// every axis, which must hold every cube of the set (`--periodic` then identifies that
    /// box's opposite faces, not those of the cubes' bounding box). O(box).
    pub fn with_box(&self, first: &[i64], last: &[i64]) -> Result<Self, ImportError> {
        let d = self.dim();
        if first.len() != d || last.len() != d {
            return Err(ImportError::Format(format!(
                "a box of dimension {} for a cubical set of dimension {d}",
                first.len().max(last.len())
            )));
        }
        let mut shape = Vec::with_capacity(d);
        for a in 0..d {
            let (lo, hi) = (self.min[a], self.min[a] + self.shape[a] as i64 - 1);
            if first[a] > lo || last[a] < hi {
                return Err(ImportError::Format(format!(
                    "the box from {first:?} to {last:?} does not hold the cubes: along axis {a} they run from {lo} to {hi}"
                )));
            }
            shape
                .push(usize::try_from(last[a] - first[a] + 1).map_err(|_| ImportError::Format("an empty box".into()))?);
        }
        let volume = box_checked(&shape)? as usize;
        let mut bits = vec![0u8; volume];
        for c in self.cubes() {
            let mut idx = 0usize;
            for a in (0..d).rev() {
                idx = idx * shape[a] + (c[a] - first[a]) as usize;
            }
            bits[idx] = 1;
        }
        CubicalSet::new(first.to_vec(), shape, bits)
    }

    /// The dimension d.
    pub fn dim(&self) -> usize {
        self.shape.len()
    }

    /// The minimal vertex of the box.
    pub fn min(&self) -> &[i64] {
        &self.min
    }

    /// The box's number of cubes along each axis.
    pub fn shape(&self) -> &[usize] {
        &self.shape
    }

    /// One byte a cube of the box, 1 for a cube of the set, axis 0 fastest.
    pub fn bits(&self) -> &[u8] {
        &self.bits
    }

    /// The number of cubes of the set.
    pub fn cube_count(&self) -> usize {
        self.count
    }

    /// The minimal vertices of the cubes of the set in the input's coordinates, axis 0
    /// fastest (the order of [`CubicalSet::bits`]). O(d) per cube, O(box) in all.
    ///
    /// ```
    /// use gmap_ops::import::cubical::parse_cub;
    /// let s = parse_cub(b"(5,-1)\n(4,0)\n").unwrap();
    /// assert_eq!(s.cubes().collect::<Vec<_>>(), vec![vec![5, -1], vec![4, 0]]);
    /// ```
    pub fn cubes(&self) -> impl Iterator<Item = Vec<i64>> + '_ {
        self.bits.iter().enumerate().filter(|(_, &b)| b != 0).map(|(mut i, _)| {
            self.shape
                .iter()
                .zip(&self.min)
                .map(|(&l, &m)| {
                    // within the box: |m| ≤ 2^40 and the offset < 2^30
                    let x = m + (i % l) as i64;
                    i /= l;
                    x
                })
                .collect()
        })
    }

    /// The G-map of the union: the grid of the box ([`crate::build::grid`], axes periodic
    /// with `periodic`) restricted to the cubes of the set, each cube one d-cell sewn to its
    /// neighbours of the set along shared facets, the other facets free. Its cells are those
    /// of the union only where cubes meet along paths of facets (a solid box, a ring, a
    /// shell): two cubes touching at a corner only make two components here. Precondition:
    /// `2^d d! × cubes < 2^32`.
    pub fn gmap(&self, periodic: bool) -> Result<DenseMap, ImportError> {
        let d = self.dim();
        let grid = crate::build::grid(&self.shape, &vec![periodic; d])
            .map_err(|e| ImportError::Format(format!("the grid of the box: {e}")))?;
        let total = grid.dart_count();
        let per = total / self.bits.len();
        let w = d + 1;
        // new index of the first dart of each kept cube
        let mut first = vec![u32::MAX; self.bits.len()];
        let mut next = 0u32;
        for (c, &b) in self.bits.iter().enumerate() {
            if b != 0 {
                first[c] = next;
                next += per as u32;
            }
        }
        let mut alpha = Vec::with_capacity(next as usize * w);
        for (c, &b) in self.bits.iter().enumerate() {
            if b == 0 {
                continue;
            }
            for k in 0..per {
                let old = c * per + k;
                let me = first[c] + k as u32;
                for i in 0..=d {
                    let t = grid.alpha(gmap_core::Dart::new(old as u32), i).index();
                    let (tc, tk) = (t / per, t % per);
                    alpha.push(if first[tc] == u32::MAX { me } else { first[tc] + tk as u32 });
                }
            }
        }
        DenseMap::from_flat_unchecked(d, alpha).map_err(|e| ImportError::Format(e.to_string()))
    }
}

/// Checks the memory a set on a box of `shape` cubes would take (its bitmap and the grid of
/// its chain complex, [`gmap_core::resources::cubical_set_estimate`]) against the memory
/// limit, before anything is allocated; then the box's size ([`box_volume`]).
pub(crate) fn box_checked(shape: &[usize]) -> Result<u64, ImportError> {
    let what = format!(
        "the cubical set on the bounding box {}",
        shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" × ")
    );
    gmap_core::resources::check_memory(&what, gmap_core::resources::cubical_set_estimate(shape))?;
    box_volume(shape)
}

fn box_volume(shape: &[usize]) -> Result<u64, ImportError> {
    let mut v: u64 = 1;
    for &s in shape {
        v = v.checked_mul(s as u64).filter(|&v| v <= MAX_BOX_CUBES).ok_or_else(|| {
            ImportError::Format(format!(
                "the bounding box {} holds more than {MAX_BOX_CUBES} unit cubes",
                shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" × ")
            ))
        })?;
    }
    if v == 0 {
        return Err(ImportError::Format("the box is empty".into()));
    }
    Ok(v)
}

/// Reads a `.cub` file (CHomP's cubical sets: one cube a line, `(x, y, z)`).
pub fn read_cub(path: &Path) -> Result<CubicalSet, FileError> {
    let bytes = read_bytes(path)?;
    parse_cub(&bytes).map_err(|e| FileError::new(path, e))
}

/// Reads a `.pbm` bitmap (P1 or P4): each black pixel a closed unit square.
pub fn read_pbm(path: &Path) -> Result<CubicalSet, FileError> {
    let bytes = read_bytes(path)?;
    parse_pbm(&bytes).map_err(|e| FileError::new(path, e))
}

fn syntax(line: usize, message: String) -> ImportError {
    ImportError::Syntax { line, message }
}

/// Parses the text of a `.cub` file: one cube a line as its minimal vertex in parentheses,
/// coordinates separated by commas or spaces (`(3,0,-7)`, `(3 0 -7)`); `;` starts a comment;
/// lines beginning with `dimension` are skipped; a line `box (0,0) (3,0)` gives the box
/// (its first and last cubes, [`CubicalSet::with_box`]) instead of the cubes' bounding box. All cubes have the same dimension; a cube
/// listed twice counts once.
pub fn parse_cub(text: &[u8]) -> Result<CubicalSet, ImportError> {
    let mut given_box: Option<(Vec<i64>, Vec<i64>)> = None;
    let mut coords: Vec<i64> = Vec::new();
    let mut dim = 0usize;
    let mut dim_line = 0usize;
    for (i, raw) in text.split(|&b| b == b'\n').enumerate() {
        let line = i + 1;
        let raw = match raw.iter().position(|&b| b == b';') {
            Some(k) => &raw[..k],
            None => raw,
        };
        let t = raw.trim_ascii();
        if t.is_empty() || t.starts_with(b"dimension") {
            continue;
        }
        if let Some(rest) = t.strip_prefix(b"box") {
            let text = String::from_utf8_lossy(rest);
            given_box = Some(parse_box(&text).map_err(|why| syntax(line, why))?);
            continue;
        }
        let bad = || syntax(line, format!("expected a cube like (0,1,2), found '{}'", shorten(t, 80)));
        if t[0] != b'(' || *t.last().unwrap() != b')' {
            return Err(bad());
        }
        let inner = &t[1..t.len() - 1];
        let before = coords.len();
        for tok in inner.split(|&b| b == b',' || b.is_ascii_whitespace()).filter(|s| !s.is_empty()) {
            let v = std::str::from_utf8(tok)
                .ok()
                .and_then(|s| s.parse::<i64>().ok())
                .ok_or_else(|| syntax(line, format!("'{}' is not an integer coordinate", shorten(tok, 80))))?;
            if v.unsigned_abs() > 1 << 40 {
                return Err(syntax(line, format!("coordinate {v} out of range (at most 2^40 in absolute value)")));
            }
            coords.push(v);
        }
        let n = coords.len() - before;
        if n == 0 {
            return Err(bad());
        }
        if dim == 0 {
            dim = n;
            dim_line = line;
        } else if n != dim {
            return Err(syntax(
                line,
                format!("cube of dimension {n}, but the cube on line {dim_line} has dimension {dim}: mixed dimensions"),
            ));
        }
    }
    if dim == 0 {
        return Err(ImportError::Format("no cube found".into()));
    }
    let mut lo = vec![i64::MAX; dim];
    let mut hi = vec![i64::MIN; dim];
    for c in coords.chunks_exact(dim) {
        for a in 0..dim {
            lo[a] = lo[a].min(c[a]);
            hi[a] = hi[a].max(c[a]);
        }
    }
    let shape: Vec<usize> = (0..dim).map(|a| (hi[a] - lo[a] + 1) as usize).collect();
    let volume = box_checked(&shape)? as usize;
    let mut bits = Vec::new();
    bits.try_reserve_exact(volume)
        .map_err(|_| ImportError::OutOfMemory { what: "the bitmap".into(), bytes: volume as u64 })?;
    bits.resize(volume, 0u8);
    for c in coords.chunks_exact(dim) {
        let mut idx = 0usize;
        for a in (0..dim).rev() {
            idx = idx * shape[a] + (c[a] - lo[a]) as usize;
        }
        bits[idx] = 1;
    }
    let set = CubicalSet::new(lo, shape, bits)?;
    match given_box {
        Some((first, last)) => set.with_box(&first, &last),
        None => Ok(set),
    }
}

/// Parses a box given as its first and last cubes, `(0,0) (3,0)` (the `box` line of a
/// `.cub` file, `--box`): the two corners, each a cube like the file's.
pub fn parse_box(text: &str) -> Result<(Vec<i64>, Vec<i64>), String> {
    let corners: Vec<Vec<i64>> = text
        .split(')')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| {
            let inner = s
                .strip_prefix('(')
                .ok_or_else(|| format!("expected a box like (0,0) (3,0), found '{}'", text.trim()))?;
            inner
                .split(|c: char| c == ',' || c.is_whitespace())
                .filter(|t| !t.is_empty())
                .map(|t| t.parse::<i64>().map_err(|_| format!("'{t}' is not an integer coordinate")))
                .collect()
        })
        .collect::<Result<_, _>>()?;
    match <[Vec<i64>; 2]>::try_from(corners) {
        Ok([first, last]) if first.len() == last.len() && !first.is_empty() => Ok((first, last)),
        _ => Err(format!("expected a box as its first and last cubes, like (0,0) (3,0), found '{}'", text.trim())),
    }
}

/// Parses a Netpbm bitmap: `P1` (ASCII `0`/`1`, whitespace optional between pixels) or `P4`
/// (packed rows, each padded to a whole byte, most significant bit first), `#` comments in
/// the header. A black pixel (1) in column `x` of row `r` (from the top) is the square with
/// minimal vertex `(x, h - 1 - r)`; the box is the whole image.
pub fn parse_pbm(bytes: &[u8]) -> Result<CubicalSet, ImportError> {
    let fmt = |m: String| ImportError::Format(m);
    let magic = bytes.get(..2).unwrap_or(bytes);
    let binary = match magic {
        b"P1" => false,
        b"P4" => true,
        _ => return Err(fmt(format!("not a PBM bitmap: magic '{}', expected P1 or P4", shorten(magic, 80)))),
    };
    let mut pos = 2;
    let mut header = [0usize; 2];
    for (k, slot) in header.iter_mut().enumerate() {
        let what = ["width", "height"][k];
        // whitespace and comments
        loop {
            match bytes.get(pos) {
                Some(b) if b.is_ascii_whitespace() => pos += 1,
                Some(b'#') => {
                    while bytes.get(pos).is_some_and(|&b| b != b'\n') {
                        pos += 1;
                    }
                }
                _ => break,
            }
        }
        let start = pos;
        while bytes.get(pos).is_some_and(|b| b.is_ascii_digit()) {
            pos += 1;
        }
        let tok = &bytes[start..pos];
        let end = bytes[pos..].iter().position(|b| b.is_ascii_whitespace()).map_or(bytes.len(), |k| pos + k);
        if tok.is_empty() || (pos < bytes.len() && !bytes[pos].is_ascii_whitespace() && bytes[pos] != b'#') {
            return Err(fmt(format!("bad {what} '{}' in the PBM header", shorten(&bytes[start..end], 80))));
        }
        *slot = std::str::from_utf8(tok)
            .ok()
            .and_then(|s| s.parse::<usize>().ok())
            .filter(|&v| v > 0)
            .ok_or_else(|| fmt(format!("bad {what} '{}' in the PBM header", shorten(tok, 80))))?;
    }
    let [w, h] = header;
    let volume = box_checked(&[w, h])? as usize;
    let mut bits = Vec::new();
    bits.try_reserve_exact(volume)
        .map_err(|_| ImportError::OutOfMemory { what: "the bitmap".into(), bytes: volume as u64 })?;
    bits.resize(volume, 0u8);
    if binary {
        // exactly one whitespace byte after the height
        if !bytes.get(pos).is_some_and(|b| b.is_ascii_whitespace()) {
            return Err(fmt("no whitespace after the PBM header".into()));
        }
        pos += 1;
        let row_bytes = w.div_ceil(8);
        let need = row_bytes * h;
        let data = &bytes[pos..];
        if data.len() < need {
            return Err(fmt(format!("P4 data too short: {} bytes for {w} × {h} pixels, expected {need}", data.len())));
        }
        for r in 0..h {
            let row = &data[r * row_bytes..(r + 1) * row_bytes];
            let y = h - 1 - r;
            for x in 0..w {
                bits[y * w + x] = (row[x / 8] >> (7 - x % 8)) & 1;
            }
        }
    } else {
        let mut k = 0usize;
        let mut p = pos;
        while k < volume {
            match bytes.get(p) {
                None => {
                    return Err(fmt(format!("P1 data too short: {k} pixels for {w} × {h}")));
                }
                Some(b) if b.is_ascii_whitespace() => {}
                Some(b'#') => {
                    while bytes.get(p).is_some_and(|&b| b != b'\n') {
                        p += 1;
                    }
                    continue;
                }
                Some(&b @ (b'0' | b'1')) => {
                    let (r, x) = (k / w, k % w);
                    bits[(h - 1 - r) * w + x] = b - b'0';
                    k += 1;
                }
                Some(_) => {
                    let end = (p + 8).min(bytes.len());
                    return Err(fmt(format!("bad P1 pixel '{}', expected 0 or 1", shorten(&bytes[p..end], 80))));
                }
            }
            p += 1;
        }
    }
    CubicalSet::new(vec![0, 0], vec![w, h], bits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cub_comments_negative_duplicates() {
        let s = parse_cub(b"dimension 2\n; c\n(-1, -2) ; x\n(-1 -2)\n(0,-1)\r\n").unwrap();
        assert_eq!(s.min(), &[-1, -2]);
        assert_eq!(s.shape(), &[2, 2]);
        assert_eq!(s.cube_count(), 2);
        assert_eq!(s.bits(), &[1, 0, 0, 1]);
    }

    #[test]
    fn cub_refusals() {
        assert!(matches!(parse_cub(b"(0,0)\n(1,2,3)\n"), Err(ImportError::Syntax { line: 2, .. })));
        assert!(matches!(parse_cub(b"(0,x)\n"), Err(ImportError::Syntax { line: 1, .. })));
        assert!(matches!(parse_cub(b"0,1\n"), Err(ImportError::Syntax { line: 1, .. })));
        assert!(matches!(parse_cub(b"()\n"), Err(ImportError::Syntax { line: 1, .. })));
        assert!(matches!(parse_cub(b"; nothing\n"), Err(ImportError::Format(_))));
        // a box of 2001^3 cubes: estimated from the box, over any memory limit of this machine
        match parse_cub(b"(0,0,0)\n(2000,2000,2000)\n") {
            Err(ImportError::MemoryLimit(e)) => assert_eq!(e.estimate, Some(2001u64.pow(3) + 9 * 4003u64.pow(3))),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn pbm_p1_p4_agree() {
        let p1 = parse_pbm(b"P1\n# c\n3 2\n1 0 1\n011\n").unwrap();
        let p4 = parse_pbm(b"P4 3 2\n\xa0\x60").unwrap();
        assert_eq!(p1, p4);
        assert_eq!(p1.cube_count(), 4);
        assert!(parse_pbm(b"P4 3 2\n\xa0").is_err());
        assert!(parse_pbm(b"P1 3 2 1 0 1").is_err());
        assert!(parse_pbm(b"P2 3 2").is_err());
        assert!(parse_pbm(b"P1 3x 2").is_err());
    }

    #[test]
    fn gmap_of_a_ring() {
        let s = parse_cub(b"(0,0)\n(1,0)\n(2,0)\n(0,1)\n(2,1)\n(0,2)\n(1,2)\n(2,2)\n").unwrap();
        let m = s.gmap(false).unwrap();
        m.validate().unwrap();
        assert_eq!(m.euler_characteristic(), 0);
    }
}
