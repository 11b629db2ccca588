//! Inputs shared by the benches, all found or made inside the checkout: the Lutz files of
//! `tests/data/lutz` and cube grids written by the library itself into the target folder.

#![allow(dead_code)] // each bench uses only some of these

use std::path::{Path, PathBuf};

/// The workspace root (the root package's manifest folder).
pub fn workspace() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A script of `benches/anchors/`.
pub fn anchor(script: &str) -> PathBuf {
    workspace().join("benches/anchors").join(script)
}

/// The folder of the Lutz files: `$GMAP_LUTZ`, else the workspace's `tests/data/lutz`.
pub fn lutz_dir() -> PathBuf {
    std::env::var_os("GMAP_LUTZ").map(PathBuf::from).unwrap_or_else(|| workspace().join("tests/data/lutz"))
}

/// Where generated inputs go: `bench-data` under `$CARGO_TARGET_DIR` when it is set, else
/// under the workspace's `target` folder.
pub fn bench_data_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from).unwrap_or_else(|| workspace().join("target"));
    target.join("bench-data")
}

/// The `.gmap` file of the `k^d` cube grid (every axis periodic when `periodic`): the path in
/// `$env_var` when set, else `bench-data/grid{k}.gmap` (`grid{k}p.gmap` when periodic). A
/// missing file is made with [`gmap_ops::build::grid`] and written with
/// [`gmap_core::io::write_gmap`] (which writes through a temporary file, so an interrupted
/// run leaves no half-written grid). `None`, with the reason printed, when that fails.
pub fn grid_file(env_var: &str, d: usize, k: usize, periodic: bool) -> Option<PathBuf> {
    let path = match std::env::var_os(env_var) {
        Some(p) => PathBuf::from(p),
        None => bench_data_dir().join(format!("grid{k}{}.gmap", if periodic { "p" } else { "" })),
    };
    if path.exists() {
        return Some(path);
    }
    eprintln!("bench: writing the {k}^{d} grid (periodic: {periodic}) to {}", path.display());
    let map = match gmap_ops::build::grid(&vec![k; d], &vec![periodic; d]) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("bench: cannot build the grid: {e}");
            return None;
        }
    };
    if let Some(dir) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("bench: cannot create {}: {e}", dir.display());
            return None;
        }
    }
    if let Err(e) = gmap_core::io::write_gmap(&map, &path) {
        eprintln!("bench: {e}");
        return None;
    }
    Some(path)
}
