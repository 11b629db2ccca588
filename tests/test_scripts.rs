//! The test scripts find what cargo built wherever its target folder is (issue 47):
//! `python/run-tests.sh --where` prints the path of the `gmap` binary the Python tests use,
//! asked of `cargo metadata` (nothing built), so CARGO_TARGET_DIR and
//! CARGO_BUILD_TARGET_DIR (a config's `build.target-dir`) are followed.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `bash python/run-tests.sh --where` with the environment changed by `env` (a value of
/// `None` removes the variable).
fn where_(env: &[(&str, Option<&Path>)]) -> String {
    let mut cmd = Command::new("bash");
    cmd.arg(repo().join("python/run-tests.sh")).arg("--where").current_dir(repo());
    for (k, v) in env {
        match v {
            Some(v) => cmd.env(k, v),
            None => cmd.env_remove(k),
        };
    }
    let o = cmd.output().expect("run bash");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap().trim_end().to_string()
}

#[test]
fn run_tests_finds_the_binary_in_cargos_target_folder() {
    let dir = tempfile::tempdir().unwrap();
    let elsewhere = dir.path().join("elsewhere");
    let found = where_(&[("CARGO_TARGET_DIR", Some(&elsewhere)), ("CARGO_BUILD_TARGET_DIR", None)]);
    assert_eq!(found, elsewhere.join("test-release/gmap").display().to_string());
    // a config's build.target-dir, as its environment variable
    let config = dir.path().join("from-config");
    let found = where_(&[("CARGO_TARGET_DIR", None), ("CARGO_BUILD_TARGET_DIR", Some(&config))]);
    assert_eq!(found, config.join("test-release/gmap").display().to_string());
    // as this test was built: the folder its own binary is in (target/test-release/deps/…)
    let exe = std::env::current_exe().unwrap();
    let target = exe.ancestors().nth(3).unwrap();
    let found = PathBuf::from(where_(&[]));
    assert_eq!(found, target.join("test-release/gmap"), "{}", exe.display());
    // built by this very run under the test-release profile: the binary cargo made
    if exe.ancestors().nth(2).is_some_and(|p| p.ends_with("test-release")) {
        assert_eq!(found, Path::new(env!("CARGO_BIN_EXE_gmap")));
    }
}
