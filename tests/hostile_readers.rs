//! Every reader the `gmap` command uses, on arbitrary bytes and on mutated valid files (the
//! hostile-input audit): no panic, and every error names the file. The `.gmap`, `.moka`,
//! `.off`, `.facets`, `.lex`, `.cub` and `.pbm` readers have their own proptests in gmap-core
//! and gmap-ops; here the `.json` reader of architectural complexes (gmap-homology) is fuzzed
//! the same way, and the binary is run on a few mutated files of every format.

use std::path::Path;
use std::process::Command;

use proptest::prelude::*;

const JSON: &str = r#"{"dimension": 2, "regions": [{"id": 0, "dim": 1}, {"id": 1, "dim": 1}, {"id": 2, "dim": 2}],
 "incidence": [{"from": 2, "to": 0, "weight": 1}, {"from": 2, "to": 1, "weight": 0}]}"#;

/// Valid files of every input format, by extension.
const SEEDS: [(&str, &str); 8] = [
    ("json", JSON),
    ("gmap", "gmap 2 8\n1 7 5\n0 2 4\n3 1 2\n2 4 3\n5 3 1\n4 6 0\n7 5 6\n6 0 7\n"),
    ("moka", "Moka file [ascii]\n0 0 0 0 0 0 0 0\n1 0 0 0 0 0 0 0 1 0 0 0\n0 1 1 1 0 0 0 0 0\n"),
    ("off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n"),
    ("facets", "1 2 3\n1 2 4\n1 3 4\n2 3 4\n"),
    ("lex", "circle=[[1,2],[2,3],[3,1]]\n"),
    ("cub", "; a ring\n(0,0)\n(1,0)\n(2,0)\n(0,1)\n(2,1)\n(0,-1)\n(1,-1)\n(2,-1)\n"),
    ("pbm", "P1\n3 3\n1 1 1\n1 0 1\n1 1 1\n"),
];

fn mutate(seed: &str, edits: &[(prop::sample::Index, u8, u8)]) -> Vec<u8> {
    let mut bytes = seed.as_bytes().to_vec();
    for (at, byte, kind) in edits {
        if bytes.is_empty() {
            bytes.push(*byte);
            continue;
        }
        let k = at.index(bytes.len());
        match kind {
            0 => bytes[k] = *byte,
            1 => bytes.insert(k, *byte),
            _ => {
                bytes.remove(k);
            }
        }
    }
    bytes
}

fn check_json(bytes: &[u8]) {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("f.json");
    std::fs::write(&p, bytes).unwrap();
    if let Err(e) = gmap_homology::json::read_json_file(&p) {
        let text = e.to_string();
        assert!(text.starts_with(&p.display().to_string()), "{text}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn json_arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        check_json(&bytes);
    }

    #[test]
    fn json_mutated_files_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..6),
    ) {
        check_json(&mutate(JSON, &edits));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// `gmap info` and `gmap homology` on a mutated file of any format: success, or exit
    /// code 1 with one `error:` line naming the file; never a crash.
    #[test]
    fn the_command_on_mutated_files_never_crashes(
        which in 0..SEEDS.len(),
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0u8..3), 1..4),
    ) {
        let (ext, seed) = SEEDS[which];
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join(format!("f.{ext}"));
        std::fs::write(&p, mutate(seed, &edits)).unwrap();
        for sub in ["info", "homology"] {
            let o = Command::new(env!("CARGO_BIN_EXE_gmap"))
                .args([sub, p.to_str().unwrap(), "--max-darts", "100000"])
                .output()
                .unwrap();
            let err = String::from_utf8_lossy(&o.stderr);
            match o.status.code() {
                Some(0) => {}
                Some(1) => {
                    prop_assert!(err.starts_with("error: ") && err.lines().count() == 1, "{}", err);
                    prop_assert!(err.contains(Path::new(&p).file_name().unwrap().to_str().unwrap()), "{}", err);
                }
                c => prop_assert!(false, "{} {}: exit {:?}: {}", sub, ext, c, err),
            }
        }
    }
}
