//! Hostile inputs for the `.gmap` and `.moka` readers (the hostile-input audit): a size
//! limit is applied before the file is read whole, and no byte string makes a reader panic;
//! every error names the file.

use std::io::Write as _;

use gmap_core::io::{format_gmap, format_moka, parse_gmap, parse_moka, read_gmap_with, read_moka_with, ReadOptions};
use proptest::prelude::*;

/// A file of `head` followed by `tail` bytes of zeros that take no disk space (a sparse
/// file): reading it whole would need `tail` bytes of memory.
fn sparse_file(dir: &tempfile::TempDir, name: &str, head: &[u8], tail: u64) -> std::path::PathBuf {
    let p = dir.path().join(name);
    let mut f = std::fs::File::create(&p).unwrap();
    f.write_all(head).unwrap();
    f.set_len(head.len() as u64 + tail).unwrap();
    p
}

#[test]
fn gmap_header_over_the_limit_is_refused_before_reading_the_file() {
    let dir = tempfile::tempdir().unwrap();
    // 64 GiB after the header: the limit must be checked on the header alone
    let p = sparse_file(&dir, "big.gmap", b"# comment\ngmap 1 5\n1 0\n", 64 << 30);
    let opts = ReadOptions { max_darts: Some(2) };
    let e = read_gmap_with(&p, &opts).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("{}:2: the map has more than 2 darts (the limit set by the caller): 5", p.display())
    );
}

#[test]
fn moka_lines_over_the_limit_are_refused_before_reading_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let head = b"Moka file [ascii]\n0 0 0 0 0 0 0 0\n0 0 0 0 0 0 0 0 0\n\n# c\n1 1 1 1 0 0 0 0 0\n2 2 2 2 0 0 0 0 0\n";
    let p = sparse_file(&dir, "big.moka", head, 64 << 30);
    let opts = ReadOptions { max_darts: Some(2) };
    let e = read_moka_with(&p, &opts).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("{}:7: the map has more than 2 darts (the limit set by the caller): 3", p.display())
    );
    // within the limit, the same reader reads
    let q = dir.path().join("small.moka");
    std::fs::write(&q, &head[..head.len() - 18]).unwrap();
    assert_eq!(read_moka_with(&q, &opts).unwrap().dart_count(), 2);
}

/// Valid files to mutate.
fn seeds() -> Vec<(Vec<u8>, Vec<u8>)> {
    use gmap_core::examples;
    [examples::fig1_curve(), examples::fig1_surface(), examples::cylinder(), examples::klein_bottle()]
        .iter()
        .map(|m| (format_gmap(m), format_moka(&m.embedded(3).unwrap()).unwrap()))
        .collect()
}

/// Checks that parsing never panics and that an error names the file.
fn check_both(bytes: &[u8]) {
    if let Err(e) = parse_gmap(bytes, "fuzz.gmap") {
        assert!(e.to_string().starts_with("fuzz.gmap:"), "{e}");
        assert!(e.to_string().chars().count() < 400, "{e}");
    }
    if let Err(e) = parse_moka(bytes, "fuzz.moka") {
        assert!(e.to_string().starts_with("fuzz.moka:"), "{e}");
        assert!(e.to_string().chars().count() < 400, "{e}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        check_both(&bytes);
    }

    #[test]
    fn mutated_valid_files_never_panic(
        which in 0usize..4,
        moka in any::<bool>(),
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..8),
    ) {
        let (g, m) = &seeds()[which];
        let mut bytes = if moka { m.clone() } else { g.clone() };
        for (at, byte, kind) in edits {
            if bytes.is_empty() {
                bytes.push(byte);
                continue;
            }
            let k = at.index(bytes.len());
            match kind {
                0 => bytes[k] = byte,
                1 => bytes.insert(k, byte),
                _ => {
                    bytes.remove(k);
                }
            }
        }
        check_both(&bytes);
    }
}

#[test]
fn a_huge_token_is_quoted_short() {
    let mut text = b"gmap 1 1\n0 ".to_vec();
    text.extend(std::iter::repeat_n(b'x', 1 << 20));
    let e = parse_gmap(&text, "f.gmap").unwrap_err().to_string();
    assert!(e.len() < 200, "{} bytes", e.len());
    let mut text = b"Moka file [ascii]\n0 0 0 0 0 0 0 0\n0 0 0 0 0 0 0 0 1 0 0 ".to_vec();
    text.extend(std::iter::repeat_n(b'7', 1 << 20));
    text.extend_from_slice(b"x\n");
    let e = parse_moka(&text, "f.moka").unwrap_err().to_string();
    assert!(e.len() < 200, "{} bytes", e.len());
}
