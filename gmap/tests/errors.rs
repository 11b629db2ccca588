//! The facade's error: the library's typed error as its source, the offending item, I/O
//! failures told apart, and a message that names its file once.

use std::path::Path;

use gmap::{Error, ErrorKind, Item};

#[test]
fn the_library_error_is_the_source() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.gmap");
    std::fs::write(&path, "gmap 1 2\n1 0\n5 1\n").unwrap();
    let e = gmap::open(&path).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Parse);
    let read = e.source_as::<gmap_core::io::ReadError>().expect("the reader's error");
    assert_eq!(read.line, e.line());
    assert!(!e.is_io());
    let missing = gmap::open(dir.path().join("missing.gmap")).unwrap_err();
    assert!(missing.is_io(), "{missing:?}");
}

#[test]
fn a_failed_condition_names_its_cell() {
    // a segment whose two darts are 0-free: its edge has an open boundary (C1)
    let mut m = gmap_core::DenseMap::new(1, 2);
    m.link(gmap_core::Dart::new(0), gmap_core::Dart::new(1), 1);
    let e: Error = gmap_homology::check_preconditions(&m).unwrap_err().into();
    assert_eq!(e.kind(), ErrorKind::Precondition);
    assert!(matches!(e.item(), Some(Item::Cell { dim: 1, .. })), "{:?} {e}", e.item());
    assert!(e.source_as::<gmap_homology::PreconditionError>().is_some());
}

#[test]
fn a_message_names_its_file_once() {
    let e = Error::new(ErrorKind::Usage, "x").about_file(Path::new("a.npy"));
    assert_eq!(e.to_string(), "a.npy: x");
    assert_eq!(e.about_file(Path::new("a.npy")).to_string(), "a.npy: x");
}
