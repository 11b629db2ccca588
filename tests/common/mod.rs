//! What the command-line tests share: running the built `gmap` binary and reading its
//! output, and the paths of the test data. Each test crate uses a part of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the `gmap` binary of this build with `args`.
pub fn gmap(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gmap")).args(args).output().expect("run gmap")
}

/// A path as a `&str` argument.
pub fn p(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// The standard error of a run, as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The standard output of a run, as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The folder of the Lutz triangulations (`tests/data/lutz`).
pub fn lutz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lutz")
}

/// A Lutz file by name, as a string argument.
pub fn lutz(name: &str) -> String {
    lutz_dir().join(name).display().to_string()
}
