//! Pure simplicial complexes as G-maps: one dart per flag of each facet.
//!
//! A facet of dimension n with sorted vertices `v_0 < … < v_n` has `(n + 1)!` darts, one per
//! ordering of its vertices (a flag: the first vertex, the edge of the first two, the
//! triangle of the first three, …). For `i < n`, `alpha_i` swaps the vertices at positions
//! `i` and `i + 1` of the ordering; `alpha_n` crosses the ridge spanned by the first `n`
//! vertices into the other facet on that ridge, keeping the order of the ridge's vertices
//! and putting the other facet's remaining vertex last. A ridge on one facet only leaves
//! `alpha_n` free there (the boundary); a ridge on three or more facets cannot be a G-map
//! and is refused (BO §6 uses the same flags for the simplicial counterpart).

use std::hash::BuildHasher;
use std::path::Path;

use rustc_hash::FxBuildHasher;

use gmap_core::io::shorten;
use gmap_core::DenseMap;

use super::common::{available_memory, bytes_per_dart, default_max_darts, FileError, ImportError};
use crate::perm::{factorial, rank, PermTable};

/// A simplicial complex given by its facets, each with its vertices sorted, and the line of
/// the input each facet came from (for error messages). Its dimension n is that of its
/// largest facets; only a pure complex (all facets of dimension n) becomes a G-map, but a
/// mixed one is kept so that [`SimplicialComplex::to_gmap`] can report, in this order, a
/// dart count over the limit, a ridge in three or more n-facets, or the first smaller facet.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SimplicialComplex {
    dim: usize,
    /// `vertices[f * (dim + 1) ..][.. dim + 1]`: the sorted vertices of n-facet `f`
    vertices: Vec<u64>,
    lines: Vec<usize>,
    /// number of facets of every dimension
    total: usize,
    /// the first facet smaller than the largest: (line, number of vertices)
    smaller: Option<(usize, usize)>,
    /// the facets smaller than the largest, sorted, with their lines
    others: Vec<(usize, Vec<u64>)>,
}

impl SimplicialComplex {
    /// A complex from facets given with their line numbers. Checks that no facet repeats a
    /// vertex and that no facet is listed twice (a simplicial complex is a set: a repeated
    /// facet is refused with [`ImportError::RepeatedFacet`], naming both lines, rather than
    /// read as two simplices glued along their whole boundary); facets smaller than the
    /// largest are counted and the first one is remembered (see the type's docs).
    ///
    /// Errors, in this order: [`ImportError::RepeatedVertex`] for the first facet (in the
    /// order given) that repeats a vertex, naming its smallest repeated label;
    /// [`ImportError::RepeatedFacet`] for the smallest repeated facet (lexicographically, as
    /// sorted label lists), naming its two smallest lines; [`ImportError::Empty`] when no
    /// facet has a vertex. O(F n) when the sorted facets come in strictly increasing
    /// lexicographic order (as in the Lutz library); otherwise O(F n + F log F) for a sort
    /// of the facets' 64-bit hashes, and O(F n log F) for a sort of the facets themselves
    /// when two hashes are equal.
    pub fn from_facets_with_lines<I>(facets: I) -> Result<Self, ImportError>
    where
        I: IntoIterator<Item = (usize, Vec<u64>)>,
    {
        let facets = facets.into_iter();
        let mut flat = FlatFacets::default();
        // room for as many facets as the iterator promises, of the size of the first
        let _ = flat.lines.try_reserve(facets.size_hint().0);
        for (line, f) in facets {
            let start = flat.labels.len();
            if start == 0 {
                let _ = flat.labels.try_reserve(flat.lines.capacity().saturating_mul(f.len()));
            }
            flat.labels.extend_from_slice(&f);
            flat.end_facet(start, line);
            if let Some((line, vertex)) = flat.repeat {
                return Err(ImportError::RepeatedVertex { line, vertex });
            }
        }
        flat.finish()
    }

    /// Every facet, of every dimension, with its vertices sorted: the n-facets first, then
    /// the smaller ones in input order.
    pub fn all_facets(&self) -> Vec<&[u64]> {
        self.facets().collect()
    }

    /// [`SimplicialComplex::all_facets`] without collecting them: the n-facets, then the
    /// smaller ones in input order. The iterator is cheap to clone (a pass over the facets
    /// costs no allocation).
    pub fn facets(&self) -> impl Iterator<Item = &[u64]> + Clone + '_ {
        self.vertices.chunks_exact(self.dim + 1).chain(self.others.iter().map(|(_, f)| f.as_slice()))
    }

    /// The input line of every facet, in the order of [`SimplicialComplex::facets`] (for
    /// [`SimplicialComplex::from_facets`], facet `k` of the input is on line `k + 1`): how
    /// values given in input order are matched to the facets, which put the n-facets first.
    pub fn facet_lines(&self) -> impl Iterator<Item = usize> + '_ {
        self.lines.iter().copied().chain(self.others.iter().map(|(l, _)| *l))
    }

    /// Whether every facet has dimension n (only then is there a G-map).
    pub fn is_pure(&self) -> bool {
        self.smaller.is_none()
    }

    /// A complex from facets, numbered 1, 2, … as if each were on its own line.
    pub fn from_facets<I: IntoIterator<Item = Vec<u64>>>(facets: I) -> Result<Self, ImportError> {
        Self::from_facets_with_lines(facets.into_iter().enumerate().map(|(k, f)| (k + 1, f)))
    }

    /// Parses the `.facets` format (docs/FORMATS.md): one facet per line, vertex labels as
    /// non-negative integers separated by white space or commas, `#` starts a comment,
    /// blank lines skipped. A label is what `str::parse::<u64>` takes: decimal digits with an
    /// optional leading `+`, at most `u64::MAX`. The first token that is not a label is an
    /// [`ImportError::Syntax`] naming its line, even after a facet with a repeated vertex;
    /// the other errors are those of [`SimplicialComplex::from_facets_with_lines`].
    ///
    /// One pass over the bytes into one flat buffer of labels, sized from the first facet
    /// line: O(size of the text), plus the check for a repeated facet when the facets are
    /// not in increasing order (see [`SimplicialComplex::from_facets_with_lines`]).
    pub fn parse_facets(text: &str) -> Result<Self, ImportError> {
        let b = text.as_bytes();
        let mut flat = FlatFacets::default();
        let mut line = 1;
        // where the labels of the current line's facet begin, and where its text begins
        let mut start = 0;
        let mut line_start = 0;
        let mut i = 0;
        while i < b.len() {
            let c = b[i];
            let d = c.wrapping_sub(b'0');
            if d <= 9 {
                // the common case inline: at most 19 digits, then a space (skipped at once), a
                // newline or the end; anything else (more digits, other separators, a bad
                // token) goes to `label_at`
                let (v, end, next) = digits_at(b, i + 1, u64::from(d));
                if end - i <= 19 && (next == b' ' || next == b'\n') {
                    flat.labels.push(v);
                    i = end + usize::from(next == b' ');
                } else {
                    let (v, end) = label_at(text, i).ok_or_else(|| bad_label(text, i, line))?;
                    flat.labels.push(v);
                    i = end;
                }
                continue;
            }
            match c {
                b'\n' => {
                    if flat.labels.len() > start {
                        if flat.len() == 0 {
                            flat.reserve_like_first(b.len() - line_start, i + 1 - line_start);
                        }
                        flat.end_facet(start, line);
                    }
                    line += 1;
                    start = flat.labels.len();
                    i += 1;
                    line_start = i;
                }
                b' ' | b',' | b'\t' | b'\r' | 0x0b | 0x0c => i += 1,
                b'+' => {
                    let (v, end) = label_at(text, i).ok_or_else(|| bad_label(text, i, line))?;
                    flat.labels.push(v);
                    i = end;
                }
                b'#' => i = b[i..].iter().position(|&x| x == b'\n').map_or(b.len(), |p| i + p),
                0x80.. => match text[i..].chars().next() {
                    Some(ch) if ch.is_whitespace() => i += ch.len_utf8(),
                    _ => return Err(bad_label(text, i, line)),
                },
                _ => return Err(bad_label(text, i, line)),
            }
        }
        if flat.labels.len() > start {
            flat.end_facet(start, line);
        }
        flat.finish()
    }

    /// Parses `.facets` text whose facet lines may end with a value after a colon
    /// (`1 2 3 : 0.5`, docs/FORMATS.md): the complex, and one value per facet in the order
    /// of [`SimplicialComplex::facets`], or `None` when no line has a colon. Refuses, naming
    /// the line, a value that is not a number (or is NaN) and, once one facet has a value, a
    /// facet without one. The vertex part goes through [`SimplicialComplex::parse_facets`]
    /// unchanged (the same errors, the same lines). O(size of the text) more than it.
    pub fn parse_valued_facets(text: &str) -> Result<(Self, Option<Vec<f64>>), ImportError> {
        if !text.contains(':') {
            return Ok((Self::parse_facets(text)?, None));
        }
        let mut vertices = String::with_capacity(text.len());
        let mut values: rustc_hash::FxHashMap<usize, f64> = rustc_hash::FxHashMap::default();
        for (i, raw) in text.split('\n').enumerate() {
            let line = i + 1;
            let body = raw.split('#').next().unwrap_or("");
            match body.split_once(':') {
                Some((verts, value)) => {
                    let v: f64 = value.trim().parse().ok().filter(|v: &f64| !v.is_nan()).ok_or_else(|| {
                        ImportError::Syntax { line, message: format!("the value {:?} is not a number", value.trim()) }
                    })?;
                    values.insert(line, v);
                    vertices.push_str(verts);
                }
                None => vertices.push_str(body),
            }
            vertices.push('\n');
        }
        let sc = Self::parse_facets(&vertices)?;
        if values.is_empty() {
            // colons in comments only
            return Ok((sc, None));
        }
        let vals = sc
            .facet_lines()
            .map(|line| {
                values.get(&line).copied().ok_or_else(|| ImportError::Syntax {
                    line,
                    message: "a facet without a value (`: VALUE`) where other facets have one".into(),
                })
            })
            .collect::<Result<Vec<f64>, _>>()?;
        Ok((sc, Some(vals)))
    }

    /// Parses Lutz's `.lex` format: `name=[[1,2,3],[1,2,4],...]`, possibly over several lines
    /// and several complexes per file. Picks the complex called `name`, or the first one.
    /// The line of a facet is the line where its `[` stands.
    pub fn parse_lex(text: &str, name: Option<&str>) -> Result<Self, ImportError> {
        let mut p = LexParser { text, bytes: text.as_bytes(), pos: 0, line: 1 };
        let mut first_name = None;
        let mut flat = FlatFacets::default();
        loop {
            p.skip_ws();
            if p.pos >= p.bytes.len() {
                break;
            }
            let start_line = p.line;
            let start = p.pos;
            while p.pos < p.bytes.len() && p.bytes[p.pos] != b'=' {
                if p.bytes[p.pos] == b'\n' {
                    p.line += 1;
                }
                p.pos += 1;
            }
            if p.pos >= p.bytes.len() {
                return Err(ImportError::Syntax { line: start_line, message: "expected 'name=[[...]]'".into() });
            }
            let this = String::from_utf8_lossy(&p.bytes[start..p.pos]).trim().to_string();
            p.pos += 1;
            p.list(&mut flat)?;
            let wanted = match name {
                Some(n) => n == this,
                None => first_name.is_none(),
            };
            if first_name.is_none() {
                first_name = Some(this);
            }
            if wanted {
                return flat.finish();
            }
            p.skip_ws();
            if p.pos < p.bytes.len() && p.bytes[p.pos] == b',' {
                p.pos += 1;
            }
        }
        match name {
            Some(n) => Err(ImportError::NoSuchName(shorten(n.as_bytes(), 80))),
            None => Err(ImportError::Empty),
        }
    }

    /// The dimension n of the facets.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The number of n-facets (all facets when the complex is pure).
    pub fn facet_count(&self) -> usize {
        self.lines.len()
    }

    /// The number of facets of every dimension.
    pub fn total_facet_count(&self) -> usize {
        self.total
    }

    /// The sorted vertices of n-facet `f`.
    pub fn facet(&self, f: usize) -> &[u64] {
        let m = self.dim + 1;
        &self.vertices[f * m..(f + 1) * m]
    }

    /// The input line of n-facet `f`.
    pub fn line(&self, f: usize) -> usize {
        self.lines[f]
    }

    /// The i-face of dart `d`'s flag in the G-map of [`SimplicialComplex::to_gmap`]: the
    /// labels of the first `i + 1` vertices of the dart's ordering of its facet, sorted.
    /// `None` when there is no such dart or `i > n`. O(n^2).
    pub fn dart_face(&self, d: u64, i: usize) -> Option<Vec<u64>> {
        let m = self.dim + 1;
        let pc = factorial(m)?;
        let (f, mut r) = (usize::try_from(d / pc).ok()?, d % pc);
        if f >= self.facet_count() || i >= m {
            return None;
        }
        // unrank the ordering: digit k is how many later elements are smaller (radix m - k)
        let mut digits = vec![0usize; m];
        for k in (0..m).rev() {
            let radix = (m - k) as u64;
            digits[k] = (r % radix) as usize;
            r /= radix;
        }
        let mut rest: Vec<u64> = self.facet(f).to_vec();
        let mut face: Vec<u64> = (0..=i).map(|k| rest.remove(digits[k])).collect();
        face.sort_unstable();
        Some(face)
    }

    /// The number of darts of the G-map, `facets × (n + 1)!` (all facets counted, as if
    /// the complex were pure), or `None` past `u64`. O(n).
    pub fn dart_count(&self) -> Option<u64> {
        factorial(self.dim + 1).and_then(|p| p.checked_mul(self.total as u64))
    }

    /// Bytes the import takes at most: the involution rows and the tables of orderings of a
    /// facet (`(n + 1)!` of them, shared by all facets, so for a complex of one big facet they
    /// weigh as much as the map), or `None` past `u64`. [`read_facets`] derives its default
    /// limit from it.
    pub fn memory_estimate(&self) -> Option<u64> {
        let m = self.dim as u64 + 1;
        let orderings = factorial(self.dim + 1)?;
        let tables = orderings.checked_mul(table_bytes_per_ordering(self.dim))?;
        self.dart_count()?
            .checked_mul(bytes_per_dart(self.dim))?
            .checked_add(tables)?
            .checked_add(self.total as u64 * m * 36)
    }

    /// The G-map of the complex as the readers make it: refused past `max_darts` darts
    /// (default: [`default_max_darts`] at the complex's dimension, within the memory budget),
    /// the memory estimate checked first (see [`SimplicialComplex::to_gmap`] for the other
    /// refusals).
    pub fn to_gmap_within(&self, max_darts: Option<u64>) -> Result<DenseMap, ImportError> {
        // the true cause first: facets of several dimensions have no G-map at any size
        if let Some((line, found)) = self.smaller {
            return Err(ImportError::MixedDimension { line, expected: self.dim + 1, found });
        }
        let limit = import_limit(self, max_darts)?;
        self.to_gmap(limit)
    }

    /// The G-map of the complex (module docs), refusing more than `max_darts` darts before
    /// allocating it. Every large buffer is reserved fallibly: memory that cannot be had is
    /// an [`ImportError::OutOfMemory`] naming the bytes, not an abort. Errors, in this order:
    /// [`ImportError::MixedDimension`] for the first facet smaller than n, [`ImportError::TooManyDarts`],
    /// [`ImportError::RidgeInManyFacets`] for the first such ridge in sorted order.
    /// O(F n log F) for the ridges and O(F (n+1)! n^2) for the darts.
    pub fn to_gmap(&self, max_darts: u64) -> Result<DenseMap, ImportError> {
        let n = self.dim;
        let m = n + 1;
        let nf = self.facet_count();
        if let Some((line, found)) = self.smaller {
            return Err(ImportError::MixedDimension { line, expected: m, found });
        }
        let darts = self.dart_count();
        let limit = max_darts.min(u32::MAX as u64 - 1);
        match darts {
            Some(d) if d <= limit => {}
            _ => return Err(ImportError::TooManyDarts { facets: self.total, dim: n, darts, limit }),
        }
        let darts = darts.unwrap_or(0) as usize;
        let partner = self.ridge_partners()?;
        let oom = |what: &str, bytes: usize| ImportError::OutOfMemory { what: what.into(), bytes: bytes as u64 };
        let table = PermTable::try_new(m).ok_or_else(|| {
            oom("the orderings of a facet", (factorial(m).unwrap_or(0) * table_bytes_per_ordering(n)) as usize)
        })?;
        let pc = table.len();
        // the crossing table is only needed where two facets share a ridge
        let cross_len = if partner.iter().any(|&x| x != NONE) { m * pc } else { 0 };
        // cross[jg * pc + p]: the ordering reached from ordering p of a facet when crossing the
        // ridge of its first n positions into a facet whose extra vertex is its local vertex jg.
        // The ridge's vertices keep their order, and local numbers shift around the omitted
        // vertex: it depends on p and jg only, not on the facets.
        let mut cross: Vec<u32> = Vec::new();
        cross.try_reserve_exact(cross_len).map_err(|_| oom("the ridge-crossing table", cross_len * 4))?;
        cross.resize(cross_len, 0);
        let mut q = vec![0u8; m];
        for jg in 0..if cross_len == 0 { 0 } else { m } {
            for p in 0..pc {
                let perm = table.perm(p);
                let j = perm[n] as usize;
                for k in 0..n {
                    let a = perm[k] as usize;
                    let r = if a > j { a - 1 } else { a };
                    q[k] = if r >= jg { r + 1 } else { r } as u8;
                }
                q[n] = jg as u8;
                cross[jg * pc + p] = rank(&q) as u32;
            }
        }
        let w = n + 1;
        let mut alpha: Vec<u32> = Vec::new();
        alpha.try_reserve_exact(darts * w).map_err(|_| oom("the involutions", darts * w * 4))?;
        alpha.resize(darts * w, 0);
        for f in 0..nf {
            let base = f * pc;
            for p in 0..pc {
                let d = base + p;
                let row = &mut alpha[d * w..(d + 1) * w];
                for (i, slot) in row.iter_mut().enumerate().take(n) {
                    *slot = (base + table.swap(p, i) as usize) as u32;
                }
                let j = table.perm(p)[n] as usize;
                let other = partner[f * m + j];
                row[n] = if other == NONE {
                    d as u32
                } else {
                    let g = other as usize / m;
                    let jg = other as usize % m;
                    (g * pc + cross[jg * pc + p] as usize) as u32
                };
            }
        }
        let map = DenseMap::from_flat_unchecked(n, alpha)
            .map_err(|e| ImportError::Syntax { line: 0, message: e.to_string() })?;
        Ok(map)
    }

    /// For each (facet, omitted local vertex), the (facet, local vertex) across that ridge,
    /// encoded as `g * m + j'`, or `NONE` on the boundary.
    fn ridge_partners(&self) -> Result<Vec<u32>, ImportError> {
        let n = self.dim;
        let m = n + 1;
        let nf = self.facet_count();
        let total = nf * m;
        let mut partner = vec![NONE; total];
        if n == 0 {
            // the ridge of a vertex is empty: every vertex shares it
            if nf > 2 {
                return Err(ImportError::RidgeInManyFacets { ridge: vec![], lines: self.lines.clone() });
            }
            if nf == 2 {
                partner[0] = 1;
                partner[1] = 0;
            }
            return Ok(partner);
        }
        // fast path: the ridge's labels packed into one u128, sorted with the ridge number
        let max_label = self.vertices.iter().copied().max().unwrap_or(0);
        let bits = 64 - max_label.leading_zeros() as usize;
        if bits.max(1) * n <= 128 {
            let bits = bits.max(1);
            let mut packed: Vec<(u128, u32)> = Vec::with_capacity(total);
            for f in 0..nf {
                let fv = self.facet(f);
                for j in 0..m {
                    let key = fv
                        .iter()
                        .enumerate()
                        .filter(|&(k, _)| k != j)
                        .fold(0u128, |acc, (_, &v)| (acc << bits) | v as u128);
                    packed.push((key, (f * m + j) as u32));
                }
            }
            packed.sort_unstable();
            let mut s = 0;
            while s < total {
                let mut e = s + 1;
                while e < total && packed[e].0 == packed[s].0 {
                    e += 1;
                }
                match e - s {
                    1 => {}
                    2 => {
                        partner[packed[s].1 as usize] = packed[s + 1].1;
                        partner[packed[s + 1].1 as usize] = packed[s].1;
                    }
                    _ => {
                        let r = packed[s].1 as usize;
                        let ridge = self
                            .facet(r / m)
                            .iter()
                            .enumerate()
                            .filter(|&(k, _)| k != r % m)
                            .map(|(_, &v)| v)
                            .collect();
                        let mut lines: Vec<usize> =
                            packed[s..e].iter().map(|&(_, r)| self.lines[r as usize / m]).collect();
                        lines.sort_unstable();
                        return Err(ImportError::RidgeInManyFacets { ridge, lines });
                    }
                }
                s = e;
            }
            return Ok(partner);
        }
        let mut keys = Vec::with_capacity(total * n);
        for f in 0..nf {
            let fv = self.facet(f);
            for j in 0..m {
                keys.extend(fv.iter().enumerate().filter(|&(k, _)| k != j).map(|(_, &v)| v));
            }
        }
        let key = |r: u32| &keys[r as usize * n..(r as usize + 1) * n];
        let mut order: Vec<u32> = (0..total as u32).collect();
        order.sort_unstable_by(|&a, &b| key(a).cmp(key(b)));
        let mut s = 0;
        while s < total {
            let mut e = s + 1;
            while e < total && key(order[e]) == key(order[s]) {
                e += 1;
            }
            match e - s {
                1 => {}
                2 => {
                    partner[order[s] as usize] = order[s + 1];
                    partner[order[s + 1] as usize] = order[s];
                }
                _ => {
                    let mut lines: Vec<usize> = order[s..e].iter().map(|&r| self.lines[r as usize / m]).collect();
                    lines.sort_unstable();
                    return Err(ImportError::RidgeInManyFacets { ridge: key(order[s]).to_vec(), lines });
                }
            }
            s = e;
        }
        Ok(partner)
    }
}

const NONE: u32 = u32::MAX;

/// Bytes of the tables kept per ordering of a facet of dimension `dim` (`m = dim + 1`
/// vertices): the ordering itself (`m` bytes), its `m - 1` neighbours by a swap (`u32` each)
/// and the `m` orderings reached across a ridge (`u32` each).
fn table_bytes_per_ordering(dim: usize) -> u64 {
    let m = dim as u64 + 1;
    m + 4 * m.saturating_sub(1) + 4 * m
}

/// The default dart limit of an import: what fits in the memory budget at
/// [`bytes_per_dart`] each, once the tables of orderings are counted (see
/// [`SimplicialComplex::memory_estimate`]), and never more than [`default_max_darts`].
fn default_limit(sc: &SimplicialComplex) -> u64 {
    let cap = default_max_darts(sc.dim());
    let tables = factorial(sc.dim() + 1).and_then(|p| p.checked_mul(table_bytes_per_ordering(sc.dim())));
    match (available_memory(), tables) {
        (Some(avail), Some(t)) => (avail.saturating_sub(t) / bytes_per_dart(sc.dim())).min(cap),
        (Some(_), None) => 0,
        (None, _) => cap,
    }
}

struct LexParser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
    line: usize,
}

impl LexParser<'_> {
    fn skip_ws(&mut self) {
        while self.pos < self.bytes.len() && self.bytes[self.pos].is_ascii_whitespace() {
            if self.bytes[self.pos] == b'\n' {
                self.line += 1;
            }
            self.pos += 1;
        }
    }

    /// Skips white space and the byte `c`, or names what stands there instead.
    #[inline]
    fn expect(&mut self, c: u8) -> Result<(), ImportError> {
        self.skip_ws();
        if self.bytes.get(self.pos) == Some(&c) {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.unexpected(c))
        }
    }

    /// The error of [`LexParser::expect`] (out of its way, which is taken once per facet).
    #[cold]
    fn unexpected(&self, c: u8) -> ImportError {
        let found = self.bytes.get(self.pos).map_or("end of file".to_string(), |&b| format!("'{}'", b as char));
        ImportError::Syntax { line: self.line, message: format!("expected '{}', found {found}", c as char) }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_ws();
        self.bytes.get(self.pos).copied()
    }

    /// `[[1,2,3],[1,2,4]]` → the facets, sorted, into `out` (emptied first), each with the
    /// line of its opening bracket.
    fn list(&mut self, out: &mut FlatFacets) -> Result<(), ImportError> {
        out.clear();
        self.expect(b'[')?;
        if self.peek() == Some(b']') {
            self.pos += 1;
            return Ok(());
        }
        loop {
            self.skip_ws();
            let open = self.pos;
            self.expect(b'[')?;
            let line = self.line;
            let start = out.labels.len();
            loop {
                self.skip_ws();
                let (v, end) = decimal_at(self.text, self.pos);
                if end == self.pos {
                    return Err(ImportError::Syntax { line: self.line, message: "expected a vertex label".into() });
                }
                let v = v.ok_or_else(|| ImportError::Syntax {
                    line: self.line,
                    message: format!("vertex label '{}' is too large", shorten(&self.bytes[self.pos..end], 40)),
                })?;
                self.pos = end;
                out.labels.push(v);
                match self.peek() {
                    Some(b',') => self.pos += 1,
                    Some(b']') => {
                        self.pos += 1;
                        break;
                    }
                    _ => return Err(ImportError::Syntax { line: self.line, message: "expected ',' or ']'".into() }),
                }
            }
            if out.len() == 0 {
                out.reserve_like_first(self.bytes.len() - open, self.pos + 1 - open);
            }
            out.end_facet(start, line);
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b']') => {
                    self.pos += 1;
                    return Ok(());
                }
                _ => return Err(ImportError::Syntax { line: self.line, message: "expected ',' or ']'".into() }),
            }
        }
    }
}

/// Facets read into one flat buffer of labels, each facet sorted, with the line it came
/// from. While every facet has the same number of labels (a pure complex) facet `k` is
/// `labels[k * width..][..width]` and no offsets are kept; from the first facet of another
/// length on, `ends[k]` is where facet `k` ends.
#[derive(Default)]
struct FlatFacets {
    labels: Vec<u64>,
    lines: Vec<usize>,
    /// the number of labels of the first facet
    width: usize,
    /// whether two facets of different lengths have been seen (`ends` is kept only then)
    mixed: bool,
    ends: Vec<usize>,
    /// the first facet that repeats a vertex: its line and its smallest repeated label
    repeat: Option<(usize, u64)>,
    /// where the last facet begins in `labels`
    last: usize,
    /// whether some facet is not lexicographically greater than the one before it (only
    /// then can a facet repeat, and only then does [`FlatFacets::repeated_facet`] sort)
    unordered: bool,
}

impl FlatFacets {
    /// Empties the buffers, keeping their memory.
    fn clear(&mut self) {
        self.labels.clear();
        self.lines.clear();
        self.ends.clear();
        self.mixed = false;
        self.repeat = None;
        self.last = 0;
        self.unordered = false;
    }

    /// The number of facets. O(1).
    fn len(&self) -> usize {
        self.lines.len()
    }

    /// The labels of facet `k` (`k < len()`). O(1).
    fn facet(&self, k: usize) -> &[u64] {
        if self.mixed {
            let s = if k == 0 { 0 } else { self.ends[k - 1] };
            &self.labels[s..self.ends[k]]
        } else {
            &self.labels[k * self.width..(k + 1) * self.width]
        }
    }

    /// Before the first facet ends, whose `labels` are read from a line of `first` bytes:
    /// reserves room for the facets of `rest` bytes of text (that line included) if their
    /// lines are about as long, and a quarter more, but never more than the text can hold
    /// (a label or a facet line takes two bytes at least). Room never written costs address
    /// space, not memory, whereas growing the buffers copies them and touches both copies;
    /// a wrong guess only means growing. O(1).
    fn reserve_like_first(&mut self, rest: usize, first: usize) {
        let most = rest / 2 + 1;
        let facets = rest / first.max(1);
        let facets = facets.saturating_add(facets / 4 + 1).min(most);
        // a reservation that cannot be had is left to the buffers' growth to report
        let _ = self.lines.try_reserve(facets);
        let _ = self.labels.try_reserve(facets.saturating_mul(self.labels.len()).min(most));
    }

    /// Ends the facet made of `labels[start..]`, read on `line`: sorts it, remembers it if
    /// it is the first to repeat a vertex, and notes whether it comes after the facet
    /// before it. O(n) for sorted labels, O(n log n) otherwise.
    #[inline(always)]
    fn end_facet(&mut self, start: usize, line: usize) {
        if let Some(vertex) = sort_facet(&mut self.labels[start..]) {
            self.repeat.get_or_insert((line, vertex));
        }
        let len = self.labels.len() - start;
        if self.lines.is_empty() {
            self.width = len;
        } else {
            if !self.unordered {
                self.unordered = !increasing(&self.labels[self.last..start], &self.labels[start..]);
            }
            if !self.mixed && len != self.width {
                self.mixed = true;
                self.ends = (1..=self.lines.len()).map(|k| k * self.width).collect();
            }
        }
        if self.mixed {
            self.ends.push(self.labels.len());
        }
        self.last = start;
        self.lines.push(line);
    }

    /// The lines [`ImportError::RepeatedFacet`] names: the two smallest lines of the
    /// smallest facet listed twice, or `None`. O(1) when the facets came in strictly
    /// increasing order (then none repeats). Otherwise a sort of the facets' 64-bit hashes
    /// tells, in O(F n + F log F), whether two facets may be equal; only then are the facets
    /// themselves sorted, with their lines, in O(F n log F), which also settles a mere
    /// collision of hashes.
    fn repeated_facet(&self) -> Option<(usize, usize)> {
        if !self.unordered {
            return None;
        }
        let count = self.len();
        let mut hashes: Vec<u64> = (0..count).map(|k| FxBuildHasher.hash_one(self.facet(k))).collect();
        hashes.sort_unstable();
        if hashes.windows(2).all(|w| w[0] != w[1]) {
            return None;
        }
        let mut order: Vec<usize> = (0..count).collect();
        order.sort_unstable_by(|&a, &b| self.facet(a).cmp(self.facet(b)).then(self.lines[a].cmp(&self.lines[b])));
        order.windows(2).find(|w| self.facet(w[0]) == self.facet(w[1])).map(|w| (self.lines[w[0]], self.lines[w[1]]))
    }

    /// The complex of the facets read, or the first error in the order of
    /// [`SimplicialComplex::from_facets_with_lines`]. A pure complex keeps the buffers
    /// as they are; a mixed one moves its smaller facets apart. O(F n) plus
    /// [`FlatFacets::repeated_facet`].
    fn finish(self) -> Result<SimplicialComplex, ImportError> {
        if let Some((line, vertex)) = self.repeat {
            return Err(ImportError::RepeatedVertex { line, vertex });
        }
        if let Some((first, second)) = self.repeated_facet() {
            return Err(ImportError::RepeatedFacet { first, second });
        }
        let total = self.len();
        let m = if self.mixed { (0..total).map(|k| self.facet(k).len()).max().unwrap_or(0) } else { self.width };
        if total == 0 || m == 0 {
            return Err(ImportError::Empty);
        }
        if !self.mixed {
            let FlatFacets { labels, lines, .. } = self;
            return Ok(SimplicialComplex {
                dim: m - 1,
                vertices: labels,
                lines,
                total,
                smaller: None,
                others: Vec::new(),
            });
        }
        let mut vertices = Vec::new();
        let mut lines = Vec::new();
        let mut others = Vec::new();
        for (k, &line) in self.lines.iter().enumerate() {
            let f = self.facet(k);
            if f.len() == m {
                vertices.extend_from_slice(f);
                lines.push(line);
            } else {
                others.push((line, f.to_vec()));
            }
        }
        let smaller = others.first().map(|(line, f): &(usize, Vec<u64>)| (*line, f.len()));
        Ok(SimplicialComplex { dim: m - 1, vertices, lines, total, smaller, others })
    }
}

/// Whether facet `b` comes strictly after facet `a` in lexicographic order. O(n).
#[inline(always)]
fn increasing(a: &[u64], b: &[u64]) -> bool {
    match a.iter().zip(b).find(|(x, y)| x != y) {
        Some((x, y)) => x < y,
        None => a.len() < b.len(),
    }
}

/// Sorts the labels of a facet and returns its smallest repeated label, if any. O(n) for
/// labels already in strictly increasing order, O(n log n) otherwise.
#[inline]
fn sort_facet(f: &mut [u64]) -> Option<u64> {
    if f.windows(2).all(|w| w[0] < w[1]) {
        return None;
    }
    f.sort_unstable();
    f.windows(2).find(|w| w[0] == w[1]).map(|w| w[0])
}

/// The end of the decimal digits of `b` from byte `start` on (`start` itself when there
/// is none), the value of `v` followed by these digits, modulo 2^64 (exact for up to 19
/// digits in all: 10^19 < 2^64), and the byte after the digits (`b'\n'` at the end of `b`,
/// which ends a line as well). O(digits).
#[inline(always)]
fn digits_at(b: &[u8], start: usize, mut v: u64) -> (u64, usize, u8) {
    let mut end = start;
    while let Some(&c) = b.get(end) {
        let d = c.wrapping_sub(b'0');
        if d > 9 {
            return (v, end, c);
        }
        v = v.wrapping_mul(10).wrapping_add(u64::from(d));
        end += 1;
    }
    (v, end, b'\n')
}

/// The value of the decimal digits of `text` from byte `start` on (`None` past
/// `u64::MAX`, with any number of leading zeros) and the byte after the last digit (`start`
/// itself when there is none). O(digits).
#[inline(always)]
fn decimal_at(text: &str, start: usize) -> (Option<u64>, usize) {
    let (v, end, _) = digits_at(text.as_bytes(), start, 0);
    if end - start > 19 {
        return (long_decimal(&text[start..end]), end);
    }
    (Some(v), end)
}

/// The value of 20 digits or more, `None` past `u64::MAX` (the rare case of
/// [`decimal_at`], kept out of its loop).
#[cold]
fn long_decimal(digits: &str) -> Option<u64> {
    digits.parse().ok()
}

/// The vertex label of a `.facets` text at byte `i` and the byte after it: what
/// `str::parse::<u64>` takes (an optional `+`, then digits, at most `u64::MAX`), ended by a
/// separator (white space, a comma), a `#` or the end of the text. `None` when the token at
/// `i` is not one. O(length of the label).
fn label_at(text: &str, i: usize) -> Option<(u64, usize)> {
    let b = text.as_bytes();
    let digits = i + usize::from(b[i] == b'+');
    let (v, end) = decimal_at(text, digits);
    let ends_token = match b.get(end) {
        None => true,
        Some(&c) if c < 0x80 => matches!(c, b' ' | b',' | b'#' | b'\t'..=b'\r'),
        Some(_) => text[end..].chars().next().is_some_and(char::is_whitespace),
    };
    if end == digits || !ends_token {
        return None;
    }
    v.map(|v| (v, end))
}

/// The error for the token of a `.facets` text starting at byte `i` on `line`, which is not
/// a vertex label: the token runs to the next white space, comma or `#`, and is shown cut
/// to 40 characters.
fn bad_label(text: &str, i: usize, line: usize) -> ImportError {
    let rest = &text[i..];
    let token = rest.find(|c: char| c.is_whitespace() || c == ',' || c == '#').map_or(rest, |e| &rest[..e]);
    let shown = shorten(token.as_bytes(), 40);
    let message = if !token.is_empty() && token.bytes().all(|b| b.is_ascii_digit()) {
        format!("vertex label '{shown}' is out of range (at most {})", u64::MAX)
    } else {
        format!("'{shown}' is not a vertex label (a non-negative integer)")
    };
    ImportError::Syntax { line, message }
}

/// The dart limit of an import: `max_darts`, or the default ([`default_limit`]). Unless the
/// complex is over an explicit `max_darts` or has more darts than a map can index (both
/// reported by [`SimplicialComplex::to_gmap`]),
/// its [`SimplicialComplex::memory_estimate`] is first checked against the memory limit
/// ([`gmap_core::resources::check_memory`]), so a refusal names the bytes and the limit.
fn import_limit(sc: &SimplicialComplex, max_darts: Option<u64>) -> Result<u64, ImportError> {
    // past the largest dart index no memory helps: the dart count is the refusal
    let cap = u32::MAX as u64 - 1;
    match max_darts {
        Some(limit) if sc.dart_count().is_none_or(|d| d > limit) => Ok(limit),
        None if sc.dart_count().is_none_or(|d| d > cap) => Ok(cap),
        _ => {
            gmap_core::resources::check_memory("the G-map of the facets", sc.memory_estimate())?;
            Ok(max_darts.unwrap_or_else(|| default_limit(sc)))
        }
    }
}

/// Reads a `.facets` file into a G-map, refusing more than `max_darts` darts (default:
/// [`default_max_darts`]) or more than the memory limit before allocating.
pub fn read_facets(path: &Path, max_darts: Option<u64>) -> Result<DenseMap, FileError> {
    let text = super::common::read_text(path)?;
    let sc = SimplicialComplex::parse_facets(&text).map_err(|e| FileError::new(path, e))?;
    sc.to_gmap_within(max_darts).map_err(|e| FileError::new(path, e))
}

/// Reads a `.facets` file as a simplicial complex, without making a G-map of it (any
/// finite simplicial complex: mixed dimensions, ridges in any number of facets).
pub fn read_facets_complex(path: &Path) -> Result<SimplicialComplex, FileError> {
    let text = super::common::read_text(path)?;
    SimplicialComplex::parse_facets(&text).map_err(|e| FileError::new(path, e))
}

/// Reads a `.facets` file whose facets may carry values
/// ([`SimplicialComplex::parse_valued_facets`]).
pub fn read_valued_facets(path: &Path) -> Result<(SimplicialComplex, Option<Vec<f64>>), FileError> {
    let text = super::common::read_text(path)?;
    SimplicialComplex::parse_valued_facets(&text).map_err(|e| FileError::new(path, e))
}

/// Reads the complex `name` (or the first) of a `.lex` file, without making a G-map of it.
pub fn read_lex_complex(path: &Path, name: Option<&str>) -> Result<SimplicialComplex, FileError> {
    let text = super::common::read_text(path)?;
    SimplicialComplex::parse_lex(&text, name).map_err(|e| FileError::new(path, e))
}

/// Reads a `.lex` file (the complex `name`, or the first one) into a G-map; see
/// [`read_facets`] for the limit.
pub fn read_lex(path: &Path, name: Option<&str>, max_darts: Option<u64>) -> Result<DenseMap, FileError> {
    let text = super::common::read_text(path)?;
    let sc = SimplicialComplex::parse_lex(&text, name).map_err(|e| FileError::new(path, e))?;
    sc.to_gmap_within(max_darts).map_err(|e| FileError::new(path, e))
}

/// Parses a vertex-values file (docs/FORMATS.md, "Vertex values"): one vertex per line,
/// its label and its value separated by white space, a comma or a colon (`3 0.5`,
/// `3: 0.5`), `#` starts a comment, blank lines skipped. The pairs in file order. Refuses,
/// naming the line, a line without exactly a label and a value, a label that is not a
/// non-negative integer, a value that is not a number (or is NaN), and a label given twice
/// (naming both lines). O(size of the text).
pub fn parse_vertex_values(text: &str) -> Result<Vec<(u64, f64)>, ImportError> {
    let mut out = Vec::new();
    let mut seen: rustc_hash::FxHashMap<u64, usize> = rustc_hash::FxHashMap::default();
    for (i, raw) in text.split('\n').enumerate() {
        let line = i + 1;
        let body = raw.split('#').next().unwrap_or("");
        let tokens: Vec<&str> =
            body.split(|c: char| c.is_whitespace() || c == ',' || c == ':').filter(|t| !t.is_empty()).collect();
        match tokens[..] {
            [] => continue,
            [label, value] => {
                let label: u64 = label.parse().map_err(|_| ImportError::Syntax {
                    line,
                    message: format!("the vertex label {label:?} is not a non-negative integer"),
                })?;
                let value: f64 = value.parse().ok().filter(|v: &f64| !v.is_nan()).ok_or_else(|| {
                    ImportError::Syntax { line, message: format!("the value {value:?} is not a number") }
                })?;
                if let Some(first) = seen.insert(label, line) {
                    return Err(ImportError::Syntax {
                        line,
                        message: format!("vertex {label} has a value on line {first} already"),
                    });
                }
                out.push((label, value));
            }
            _ => {
                return Err(ImportError::Syntax {
                    line,
                    message: format!("expected a vertex label and a value, found {} tokens", tokens.len()),
                })
            }
        }
    }
    Ok(out)
}

/// Reads a vertex-values file ([`parse_vertex_values`]).
pub fn read_vertex_values(path: &Path) -> Result<Vec<(u64, f64)>, FileError> {
    let text = super::common::read_text(path)?;
    parse_vertex_values(&text).map_err(|e| FileError::new(path, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertex_values_keep_order_and_refuse_bad_lines() {
        let v = parse_vertex_values("# heights\n3 0.5\n1: -2 # low\n\n2,1e3\n").unwrap();
        assert_eq!(v, vec![(3, 0.5), (1, -2.0), (2, 1000.0)]);
        assert_eq!(parse_vertex_values("").unwrap(), vec![]);
        let e = |t: &str| parse_vertex_values(t).unwrap_err().to_string();
        assert_eq!(e("1 0\n2 1\n1 3\n"), "line 3: vertex 1 has a value on line 1 already");
        assert_eq!(e("1 0\n-2 1\n"), "line 2: the vertex label \"-2\" is not a non-negative integer");
        assert_eq!(e("1 NaN\n"), "line 1: the value \"NaN\" is not a number");
        assert_eq!(e("1 x\n"), "line 1: the value \"x\" is not a number");
        assert_eq!(e("1\n"), "line 1: expected a vertex label and a value, found 1 tokens");
        assert_eq!(e("1 2 3\n"), "line 1: expected a vertex label and a value, found 3 tokens");
        assert_eq!(parse_vertex_values("5 inf\n").unwrap(), vec![(5, f64::INFINITY)]);
    }

    #[test]
    fn valued_facets_keep_lines_and_refuse_gaps() {
        let (sc, v) = SimplicialComplex::parse_valued_facets("# c\n1 2 3 : 0.5\n2 3 4: -1e2 # x\n\n5 6 : 7\n").unwrap();
        assert_eq!(sc.all_facets(), vec![&[1, 2, 3][..], &[2, 3, 4][..], &[5, 6][..]]);
        assert_eq!(v, Some(vec![0.5, -100.0, 7.0]));
        let (_, v) = SimplicialComplex::parse_valued_facets("1 2\n").unwrap();
        assert_eq!(v, None);
        let (_, v) = SimplicialComplex::parse_valued_facets("# a: comment\n1 2\n").unwrap();
        assert_eq!(v, None);
        let e = SimplicialComplex::parse_valued_facets("1 2 : 1\n2 3\n").unwrap_err().to_string();
        assert!(e.starts_with("line 2:"), "{e}");
        let e = SimplicialComplex::parse_valued_facets("1 2 : x\n").unwrap_err().to_string();
        assert!(e.starts_with("line 1:") && e.contains("\"x\""), "{e}");
        let e = SimplicialComplex::parse_valued_facets("1 2 : 1\n1 z : 2\n").unwrap_err().to_string();
        assert!(e.starts_with("line 2:"), "{e}");
    }

    #[test]
    fn triangle_boundary_and_tetrahedron_surface() {
        let tri = SimplicialComplex::from_facets(vec![vec![0, 1, 2]]).unwrap();
        let m = tri.to_gmap(1000).unwrap();
        m.validate().unwrap();
        assert_eq!(m.cell_counts(), vec![3, 3, 1]);
        let s2 = SimplicialComplex::parse_facets("1 2 3\n1,2,4\n# c\n1 3 4\n2 3 4 # end\n").unwrap();
        let m = s2.to_gmap(1000).unwrap();
        m.validate().unwrap();
        assert_eq!(m.dart_count(), 24);
        assert_eq!(m.cell_counts(), vec![4, 6, 4]);
        assert!(m.has_complete_boundaries());
        assert!(m.is_orientable());
    }

    #[test]
    fn errors_name_line_and_ridge() {
        let sc = SimplicialComplex::parse_facets("1 2\n1 2 3\n1 3\n").unwrap();
        assert!(!sc.is_pure());
        assert_eq!((sc.facet_count(), sc.total_facet_count(), sc.dart_count()), (1, 3, Some(18)));
        let e = sc.to_gmap(100).unwrap_err();
        assert!(matches!(e, ImportError::MixedDimension { line: 1, expected: 3, found: 2 }));
        let e = SimplicialComplex::parse_facets("1 2 3\n\n4 4 5\n").unwrap_err();
        assert!(matches!(e, ImportError::RepeatedVertex { line: 3, vertex: 4 }));
        let e = SimplicialComplex::parse_facets("1 2 x\n").unwrap_err();
        assert!(matches!(e, ImportError::Syntax { line: 1, .. }));
        let sc = SimplicialComplex::parse_facets("1 2 3\n1 2 4\n1 2 5\n").unwrap();
        match sc.to_gmap(1000).unwrap_err() {
            ImportError::RidgeInManyFacets { ridge, lines } => {
                assert_eq!(ridge, vec![1, 2]);
                assert_eq!(lines, vec![1, 2, 3]);
            }
            e => panic!("{e}"),
        }
        let e = sc.to_gmap(17).unwrap_err();
        assert!(matches!(e, ImportError::TooManyDarts { darts: Some(18), limit: 17, .. }));
        assert!(matches!(SimplicialComplex::parse_facets("# nothing\n"), Err(ImportError::Empty)));
    }

    #[test]
    fn large_labels_take_the_general_path() {
        // 3 labels of 62 bits do not pack into 128 bits: ridges are compared as slices
        let big = 1u64 << 61;
        let f = |a: u64, b: u64, c: u64, d: u64| vec![big + a, big + b, big + c, big + d];
        let s3 = SimplicialComplex::from_facets(vec![
            f(1, 2, 3, 4),
            f(1, 2, 3, 5),
            f(1, 2, 4, 5),
            f(1, 3, 4, 5),
            f(2, 3, 4, 5),
        ])
        .unwrap();
        let m = s3.to_gmap(10_000).unwrap();
        m.validate().unwrap();
        assert_eq!(m.cell_counts(), vec![5, 10, 10, 5]);
        let bad = SimplicialComplex::from_facets(vec![f(1, 2, 3, 4), f(1, 2, 3, 5), f(1, 2, 3, 6)]).unwrap();
        match bad.to_gmap(10_000).unwrap_err() {
            ImportError::RidgeInManyFacets { ridge, lines } => {
                assert_eq!(ridge, vec![big + 1, big + 2, big + 3]);
                assert_eq!(lines, vec![1, 2, 3]);
            }
            e => panic!("{e}"),
        }
    }

    #[test]
    fn dart_faces_follow_the_orderings() {
        let sc = SimplicialComplex::parse_facets("1 2 3\n7 5 6\n").unwrap();
        // dart 0 is ordering (0 1 2) of facet [1 2 3]; dart 1 is (0 2 1); dart 6 + 5 is (2 1 0) of [5 6 7]
        assert_eq!(sc.dart_face(0, 0), Some(vec![1]));
        assert_eq!(sc.dart_face(1, 1), Some(vec![1, 3]));
        assert_eq!(sc.dart_face(11, 0), Some(vec![7]));
        assert_eq!(sc.dart_face(11, 1), Some(vec![6, 7]));
        assert_eq!(sc.dart_face(11, 2), Some(vec![5, 6, 7]));
        assert_eq!(sc.dart_face(12, 0), None);
        let mixed = SimplicialComplex::parse_facets("1 2 3\n4 5\n6\n").unwrap();
        assert_eq!(mixed.all_facets(), vec![&[1u64, 2, 3][..], &[4, 5][..], &[6][..]]);
    }

    #[test]
    fn lex_picks_by_name() {
        let text = "first=[[1,2],[2,3],\n[3,1]]\nsecond=[[1,2,3],\n[1,2,4],[1,3,4],[2,3,4]]\n";
        let a = SimplicialComplex::parse_lex(text, None).unwrap();
        assert_eq!((a.dim(), a.facet_count()), (1, 3));
        let b = SimplicialComplex::parse_lex(text, Some("second")).unwrap();
        assert_eq!((b.dim(), b.facet_count(), b.line(1)), (2, 4, 4));
        assert!(matches!(SimplicialComplex::parse_lex(text, Some("x")), Err(ImportError::NoSuchName(_))));
        assert!(matches!(SimplicialComplex::parse_lex("a=[[1,2],", None), Err(ImportError::Syntax { .. })));
        let c = a.to_gmap(100).unwrap();
        assert_eq!(c.cell_counts(), vec![3, 3]);
    }
}
