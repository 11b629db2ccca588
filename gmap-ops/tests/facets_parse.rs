//! The `.facets` and `.lex` readers and `SimplicialComplex::from_facets_with_lines` against a
//! plain reference kept here as the oracle: a line split, a `#` split, a split on white space
//! and commas, `str::parse::<u64>`, one `Vec` per facet and a sort of all facets to find a
//! repeated one. On random texts (labels, separators, comments, blank lines, CRLF, bad
//! tokens, repeated vertices and facets, mixed dimensions) both give the same complex or the
//! same error; unit tests pin the edge cases with exact values.

use gmap_ops::import::{ImportError, SimplicialComplex};
use proptest::prelude::*;

/// The reference algorithm. Its `SimplicialComplex` has the fields of the library's, in the
/// same order and under the same names, so the two derived `Debug` texts are equal exactly
/// when every field (dimension, facets, lines, total, first smaller facet, smaller facets)
/// is.
mod oracle {
    use gmap_core::io::shorten;
    use gmap_ops::import::ImportError;

    #[derive(Debug)]
    #[allow(dead_code)] // read through `Debug` only
    pub struct SimplicialComplex {
        dim: usize,
        vertices: Vec<u64>,
        lines: Vec<usize>,
        total: usize,
        smaller: Option<(usize, usize)>,
        others: Vec<(usize, Vec<u64>)>,
    }

    pub fn from_facets_with_lines<I>(facets: I) -> Result<SimplicialComplex, ImportError>
    where
        I: IntoIterator<Item = (usize, Vec<u64>)>,
    {
        let mut all = Vec::new();
        for (line, mut f) in facets {
            f.sort_unstable();
            if let Some(w) = f.windows(2).find(|w| w[0] == w[1]) {
                return Err(ImportError::RepeatedVertex { line, vertex: w[0] });
            }
            all.push((line, f));
        }
        let mut order: Vec<usize> = (0..all.len()).collect();
        order.sort_unstable_by(|&a, &b| all[a].1.cmp(&all[b].1).then(all[a].0.cmp(&all[b].0)));
        if let Some(w) = order.windows(2).find(|w| all[w[0]].1 == all[w[1]].1) {
            return Err(ImportError::RepeatedFacet { first: all[w[0]].0, second: all[w[1]].0 });
        }
        let m = all.iter().map(|(_, f)| f.len()).max().unwrap_or(0);
        if m == 0 {
            return Err(ImportError::Empty);
        }
        let smaller = all.iter().find(|(_, f)| f.len() < m).map(|(l, f)| (*l, f.len()));
        let mut vertices = Vec::new();
        let mut lines = Vec::new();
        let total = all.len();
        let mut others = Vec::new();
        for (line, f) in all {
            if f.len() == m {
                vertices.extend_from_slice(&f);
                lines.push(line);
            } else {
                others.push((line, f));
            }
        }
        Ok(SimplicialComplex { dim: m - 1, vertices, lines, total, smaller, others })
    }

    pub fn parse_facets(text: &str) -> Result<SimplicialComplex, ImportError> {
        let mut facets = Vec::new();
        for (k, raw) in text.lines().enumerate() {
            let line = k + 1;
            let body = raw.split('#').next().unwrap_or("");
            let mut f = Vec::new();
            for tok in body.split(|c: char| c.is_whitespace() || c == ',').filter(|t| !t.is_empty()) {
                let v = tok.parse::<u64>().map_err(|_| ImportError::Syntax {
                    line,
                    message: if tok.bytes().all(|b| b.is_ascii_digit()) {
                        format!("vertex label '{}' is out of range (at most {})", shorten(tok.as_bytes(), 40), u64::MAX)
                    } else {
                        format!("'{}' is not a vertex label (a non-negative integer)", shorten(tok.as_bytes(), 40))
                    },
                })?;
                f.push(v);
            }
            if !f.is_empty() {
                facets.push((line, f));
            }
        }
        from_facets_with_lines(facets)
    }

    pub fn parse_lex(text: &str, name: Option<&str>) -> Result<SimplicialComplex, ImportError> {
        let mut p = LexParser { bytes: text.as_bytes(), pos: 0, line: 1 };
        let mut first_name = None;
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
            let facets = p.list()?;
            let wanted = match name {
                Some(n) => n == this,
                None => first_name.is_none(),
            };
            if first_name.is_none() {
                first_name = Some(this);
            }
            if wanted {
                return from_facets_with_lines(facets);
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

    struct LexParser<'a> {
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

        fn expect(&mut self, c: u8) -> Result<(), ImportError> {
            self.skip_ws();
            if self.pos < self.bytes.len() && self.bytes[self.pos] == c {
                self.pos += 1;
                Ok(())
            } else {
                let found = self.bytes.get(self.pos).map_or("end of file".to_string(), |&b| format!("'{}'", b as char));
                Err(ImportError::Syntax {
                    line: self.line,
                    message: format!("expected '{}', found {found}", c as char),
                })
            }
        }

        fn peek(&mut self) -> Option<u8> {
            self.skip_ws();
            self.bytes.get(self.pos).copied()
        }

        fn list(&mut self) -> Result<Vec<(usize, Vec<u64>)>, ImportError> {
            self.expect(b'[')?;
            let mut out = Vec::new();
            if self.peek() == Some(b']') {
                self.pos += 1;
                return Ok(out);
            }
            loop {
                self.expect(b'[')?;
                let line = self.line;
                let mut f = Vec::new();
                loop {
                    self.skip_ws();
                    let start = self.pos;
                    while self.pos < self.bytes.len() && self.bytes[self.pos].is_ascii_digit() {
                        self.pos += 1;
                    }
                    if start == self.pos {
                        return Err(ImportError::Syntax { line: self.line, message: "expected a vertex label".into() });
                    }
                    let tok = std::str::from_utf8(&self.bytes[start..self.pos]).unwrap_or("");
                    let v = tok.parse::<u64>().map_err(|_| ImportError::Syntax {
                        line: self.line,
                        message: format!("vertex label '{}' is too large", shorten(tok.as_bytes(), 40)),
                    })?;
                    f.push(v);
                    match self.peek() {
                        Some(b',') => self.pos += 1,
                        Some(b']') => {
                            self.pos += 1;
                            break;
                        }
                        _ => {
                            return Err(ImportError::Syntax { line: self.line, message: "expected ',' or ']'".into() })
                        }
                    }
                }
                out.push((line, f));
                match self.peek() {
                    Some(b',') => self.pos += 1,
                    Some(b']') => {
                        self.pos += 1;
                        return Ok(out);
                    }
                    _ => return Err(ImportError::Syntax { line: self.line, message: "expected ',' or ']'".into() }),
                }
            }
        }
    }
}

/// `Debug` of a result: the complex's every field, or the error's variant and data.
fn shown<T: std::fmt::Debug>(r: &Result<T, ImportError>) -> String {
    format!("{r:?}")
}

fn assert_same_facets(text: &str) {
    let new = SimplicialComplex::parse_facets(text);
    let old = oracle::parse_facets(text);
    assert_eq!(shown(&new), shown(&old), "text {text:?}");
}

/// A label written as `str::parse::<u64>` takes it: mostly plain, sometimes with a `+`
/// sign or leading zeros (enough of them to pass 19 digits).
fn label(v: u64) -> impl Strategy<Value = String> {
    prop_oneof![
        20 => Just(v.to_string()),
        1 => Just(format!("+{v}")),
        1 => (1usize..25).prop_map(move |z| format!("{}{v}", "0".repeat(z))),
    ]
}

/// A token that is not a label, or a label at or just past `u64::MAX`.
fn odd_token() -> impl Strategy<Value = String> {
    prop_oneof![
        (0u64..3).prop_map(|d| (u64::MAX - d).to_string()),
        prop::sample::select(vec![
            "18446744073709551616",
            "99999999999999999999999",
            "x",
            "-1",
            "-0",
            "+",
            "++1",
            "+-1",
            "1x",
            "1.5",
            "1-2",
            "1+2",
            "é",
            "1é",
            "0x1f",
            "٣",
            "\u{1F600}",
            "abcdefghijklmnopqrstuvwxyzéèêë0123456789ABCDEFGHIJ",
        ])
        .prop_map(str::to_string),
    ]
}

/// Between tokens: ASCII and Unicode white space, commas.
fn separator() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop::sample::select(vec![
            " ", " ", " ", " ", "\t", ",", "\r", "\u{b}", "\u{c}", "\u{a0}", "\u{85}", "\u{2028}",
        ]),
        1..3,
    )
    .prop_map(|v| v.concat())
}

/// Tokens joined by separators, with a separator before them and after them sometimes, and
/// a comment sometimes.
fn join(tokens: Vec<String>) -> impl Strategy<Value = String> {
    let n = tokens.len();
    (
        prop::collection::vec(separator(), n + 1),
        any::<(bool, bool)>(),
        prop::option::weighted(0.1, prop::sample::select(vec!["#", "# 1 2 x", "#é,#", "#\r"])),
    )
        .prop_map(move |(seps, (lead, trail), comment)| {
            let mut s = if lead { seps[n].clone() } else { String::new() };
            for (k, t) in tokens.iter().enumerate() {
                s.push_str(t);
                if k + 1 < n || trail {
                    s.push_str(&seps[k]);
                }
            }
            s.push_str(comment.unwrap_or(""));
            s
        })
}

/// The labels of a facet line: distinct labels of 0..12 in random order (so that facets
/// repeat now and then), or labels of 0..7 with repetitions, or one odd token among labels.
fn line_tokens() -> impl Strategy<Value = Vec<String>> {
    prop_oneof![
        40 => prop::sample::subsequence((0u64..12).collect::<Vec<_>>(), 1..5)
            .prop_shuffle()
            .prop_flat_map(|vs| vs.into_iter().map(label).collect::<Vec<_>>()),
        1 => prop::collection::vec((0u64..7).prop_flat_map(label), 1..6),
        1 => (prop::collection::vec((0u64..12).prop_map(|v| v.to_string()), 0..4), odd_token(), any::<prop::sample::Index>())
            .prop_map(|(mut ts, odd, at)| {
                let at = at.index(ts.len() + 1);
                ts.insert(at, odd);
                ts
            }),
        4 => Just(Vec::new()),
    ]
}

/// Lines ended by `\n` or `\r\n`, the last one with or without an end, and sometimes a line
/// repeated further down (a repeated facet).
fn text_of(
    lines: Vec<(String, bool)>,
    repeat: Option<(prop::sample::Index, prop::sample::Index)>,
    end: bool,
) -> String {
    let mut lines = lines;
    if let (Some((from, to)), false) = (repeat, lines.is_empty()) {
        let l = lines[from.index(lines.len())].clone();
        lines.insert(to.index(lines.len() + 1), l);
    }
    let mut s = String::new();
    let n = lines.len();
    for (k, (l, crlf)) in lines.into_iter().enumerate() {
        s.push_str(&l);
        if k + 1 < n || end {
            s.push_str(if crlf { "\r\n" } else { "\n" });
        }
    }
    s
}

/// A random text, its facets in random order.
fn text() -> impl Strategy<Value = String> {
    (
        prop::collection::vec((line_tokens().prop_flat_map(join), any::<bool>()), 0..24),
        prop::option::weighted(0.15, any::<(prop::sample::Index, prop::sample::Index)>()),
        any::<bool>(),
    )
        .prop_map(|(lines, repeat, end)| text_of(lines, repeat, end))
}

/// A text whose facets come in increasing order (the order of the Lutz files), of mixed
/// sizes, sometimes with one facet listed again somewhere.
fn sorted_text() -> impl Strategy<Value = String> {
    (
        prop::collection::btree_set(prop::collection::btree_set(0u64..10, 1..5), 1..24),
        prop::option::weighted(0.3, any::<(prop::sample::Index, prop::sample::Index)>()),
        any::<bool>(),
    )
        .prop_flat_map(|(facets, repeat, end)| {
            let mut facets: Vec<Vec<u64>> = facets.into_iter().map(|f| f.into_iter().collect()).collect();
            facets.sort();
            let lines: Vec<_> = facets
                .into_iter()
                .map(|f| {
                    let tokens: Vec<_> = f.into_iter().map(label).collect();
                    (tokens.prop_flat_map(join), any::<bool>())
                })
                .collect();
            (lines, Just(repeat), Just(end))
        })
        .prop_map(|(lines, repeat, end)| text_of(lines, repeat, end))
}

/// Facets for the `.lex` format and `from_facets_with_lines`: small labels, so that
/// vertices and facets repeat, of mixed sizes, at least `min` labels each.
fn facets(min: usize) -> impl Strategy<Value = Vec<Vec<u64>>> {
    prop::collection::vec(
        prop_oneof![
            4 => prop::sample::subsequence((0u64..8).collect::<Vec<_>>(), min..5).prop_shuffle(),
            1 => prop::collection::vec(0u64..8, min..5),
        ],
        0..16,
    )
}

/// A `.lex` text of complexes named `a`, `b`, … with random white space (and so random
/// lines) between the brackets and labels.
fn lex_text(complexes: &[Vec<Vec<u64>>], gaps: &[u8]) -> String {
    let mut gap = gaps.iter().cycle().map(|g| match g % 6 {
        0..=2 => "",
        3 => " ",
        4 => "\n",
        _ => "\r\n\t",
    });
    let mut s = String::new();
    for (k, c) in complexes.iter().enumerate() {
        s.push_str(gap.next().unwrap_or(""));
        s.push((b'a' + k as u8) as char);
        s.push_str("=[");
        for (i, f) in c.iter().enumerate() {
            if i > 0 {
                s.push(',');
            }
            s.push_str(gap.next().unwrap_or(""));
            s.push('[');
            for (j, v) in f.iter().enumerate() {
                if j > 0 {
                    s.push(',');
                }
                s.push_str(gap.next().unwrap_or(""));
                s.push_str(&v.to_string());
            }
            s.push(']');
        }
        s.push(']');
        if k + 1 < complexes.len() {
            s.push_str(",\n");
        }
    }
    s
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Random `.facets` texts: the same complex or the same error as the reference.
    #[test]
    fn facets_texts_agree_with_the_reference(t in text()) {
        let new = SimplicialComplex::parse_facets(&t);
        let old = oracle::parse_facets(&t);
        prop_assert_eq!(shown(&new), shown(&old), "text {:?}", t);
    }

    /// Texts of facets in increasing order, where no sort is needed unless a facet repeats.
    #[test]
    fn sorted_facets_texts_agree_with_the_reference(t in sorted_text()) {
        let new = SimplicialComplex::parse_facets(&t);
        let old = oracle::parse_facets(&t);
        prop_assert_eq!(shown(&new), shown(&old), "text {:?}", t);
    }

    /// Random facets with arbitrary line numbers (not increasing, repeated, empty facets).
    #[test]
    fn facets_with_lines_agree_with_the_reference(
        fs in facets(0),
        lines in prop::collection::vec(0usize..40, 16),
    ) {
        let input: Vec<(usize, Vec<u64>)> = lines.into_iter().zip(fs).collect();
        let new = SimplicialComplex::from_facets_with_lines(input.clone());
        let old = oracle::from_facets_with_lines(input);
        prop_assert_eq!(shown(&new), shown(&old));
    }

    /// Random `.lex` texts of one to three complexes, picked by name or the first, and the
    /// same texts with one byte changed.
    #[test]
    fn lex_texts_agree_with_the_reference(
        complexes in prop::collection::vec(facets(1), 1..4),
        gaps in prop::collection::vec(any::<u8>(), 1..64),
        pick in 0u8..5,
        mutation in prop::option::weighted(0.3, (any::<prop::sample::Index>(), prop::sample::select(b"[],= 9x\n".to_vec()))),
    ) {
        let mut t = lex_text(&complexes, &gaps);
        if let Some((at, byte)) = mutation {
            let at = at.index(t.len());
            t.replace_range(at..at + 1, &(byte as char).to_string());
        }
        let name = match pick {
            0 => None,
            1 => Some("a"),
            2 => Some("b"),
            3 => Some("c"),
            _ => Some("zz"),
        };
        let new = SimplicialComplex::parse_lex(&t, name);
        let old = oracle::parse_lex(&t, name);
        prop_assert_eq!(shown(&new), shown(&old), "text {:?} name {:?}", t, name);
    }
}

fn syntax(text: &str) -> (usize, String) {
    match SimplicialComplex::parse_facets(text) {
        Err(ImportError::Syntax { line, message }) => (line, message),
        r => panic!("{text:?}: {r:?}"),
    }
}

#[test]
fn labels_are_what_str_parse_takes() {
    let sc = SimplicialComplex::parse_facets("+5 0007 18446744073709551615 000000000000000000000000042\n").unwrap();
    assert_eq!(sc.facet(0), &[5, 7, 42, u64::MAX][..]);
    assert_eq!(
        syntax("1 2\n3 18446744073709551616\n"),
        (2, "vertex label '18446744073709551616' is out of range (at most 18446744073709551615)".into())
    );
    assert_eq!(syntax("1 -0"), (1, "'-0' is not a vertex label (a non-negative integer)".into()));
    assert_eq!(syntax("+ 1"), (1, "'+' is not a vertex label (a non-negative integer)".into()));
    assert_eq!(syntax("1 ++1"), (1, "'++1' is not a vertex label (a non-negative integer)".into()));
    assert_eq!(syntax("\n\n 12x,3"), (3, "'12x' is not a vertex label (a non-negative integer)".into()));
    assert_eq!(syntax("1 1é#2"), (1, "'1é' is not a vertex label (a non-negative integer)".into()));
    // a bad token is shown cut to 40 characters
    let long = format!("{}é{}", "a".repeat(39), "b".repeat(10));
    assert_eq!(
        syntax(&format!("1 2 {long} 3")),
        (1, format!("'{}é…' is not a vertex label (a non-negative integer)", "a".repeat(39)))
    );
}

#[test]
fn separators_comments_and_line_ends() {
    let text = "# header 1 2 x\n\n1,2\t3\r\n\u{b}4\u{a0}5\u{c}6\u{2028}# 9 9\r\n  7 8#9\n9 10 11";
    let sc = SimplicialComplex::parse_facets(text).unwrap();
    assert_eq!((sc.dim(), sc.facet_count(), sc.total_facet_count()), (2, 3, 4));
    assert_eq!(sc.all_facets(), vec![&[1u64, 2, 3][..], &[4, 5, 6], &[9, 10, 11], &[7, 8]]);
    assert_eq!((sc.line(0), sc.line(1), sc.line(2)), (3, 4, 6));
    assert!(!sc.is_pure());
}

#[test]
fn errors_come_in_the_reference_order() {
    // a bad token anywhere is reported before a repeated vertex on an earlier line
    assert_eq!(syntax("1 1 2\n3 4 5\n6 y\n").0, 3);
    // the first facet repeating a vertex, naming its smallest repeated label
    let e = SimplicialComplex::parse_facets("1 2 3\n3 3 1 1\n2 2\n").unwrap_err();
    assert!(matches!(e, ImportError::RepeatedVertex { line: 2, vertex: 1 }), "{e:?}");
    // the smallest repeated facet, with its two smallest lines
    let e = SimplicialComplex::parse_facets("1 2 3\n3 2 1\n0 1\n1 0\n1 2 3\n1,0\n").unwrap_err();
    assert!(matches!(e, ImportError::RepeatedFacet { first: 3, second: 4 }), "{e:?}");
    let e = SimplicialComplex::from_facets_with_lines(vec![(9, vec![2, 1]), (4, vec![1, 2]), (7, vec![2, 1])]);
    assert!(matches!(e, Err(ImportError::RepeatedFacet { first: 4, second: 7 })), "{e:?}");
    for empty in ["", "\n\n", "# only a comment\r\n", " , \t\n"] {
        assert!(matches!(SimplicialComplex::parse_facets(empty), Err(ImportError::Empty)), "{empty:?}");
    }
    assert!(matches!(
        SimplicialComplex::from_facets(vec![vec![], vec![]]),
        Err(ImportError::RepeatedFacet { first: 1, second: 2 })
    ));
    assert!(matches!(SimplicialComplex::from_facets(vec![vec![]]), Err(ImportError::Empty)));
}

#[test]
fn facets_in_any_order_and_of_mixed_sizes() {
    // out of order: the repeated-facet check sorts, the facets keep the input order
    assert_same_facets("4 5 6\n1 2 3\n3 4\n1 2 4\n2\n");
    let sc = SimplicialComplex::parse_facets("4 5 6\n1 2 3\n3 4\n1 2 4\n2\n").unwrap();
    assert_eq!(sc.all_facets(), vec![&[4u64, 5, 6][..], &[1, 2, 3], &[1, 2, 4], &[3, 4], &[2]]);
    // a smaller facet first, then larger ones
    let sc = SimplicialComplex::parse_facets("7\n1 2\n3 4\n").unwrap();
    assert_eq!((sc.dim(), sc.facet_count(), sc.total_facet_count()), (1, 2, 3));
    assert_eq!(sc.all_facets(), vec![&[1u64, 2][..], &[3, 4], &[7]]);
    let sc = SimplicialComplex::from_facets(vec![vec![], vec![3, 1]]).unwrap();
    assert_eq!(sc.all_facets(), vec![&[1u64, 3][..], &[]]);
}

#[test]
fn every_lutz_file_reads_as_the_reference_reads_it() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/data/lutz");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "facets") {
            assert_same_facets(&std::fs::read_to_string(&path).unwrap());
            n += 1;
        }
    }
    assert_eq!(n, 44);
}
