#!/usr/bin/env bash
# Builds the Python package into a fresh virtual environment and runs its tests.
#
#   bash python/run-tests.sh            # from anywhere in the repository
#
# Steps: build the `gmap` binary (the tests compare with its --json output; found in the
# target folder `cargo metadata` names, so CARGO_TARGET_DIR is followed), make a new
# venv in a temporary folder, install maturin numpy pytest hypothesis networkx
# dask[distributed] (and gudhi, meshio, vtk, ifcopenshell and topologicpy when pip can get them), `pip install ./python`, run pytest
# on python/tests. Exits non-zero when any step or test fails. GMAP_PYTHON picks the
# interpreter (default python3); GMAP_VENV keeps the venv in a given folder instead.
#
#   bash python/run-tests.sh --where    # prints the path of the gmap binary the tests use
#                                       # (nothing built, nothing installed)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/.." && pwd)"
python="${GMAP_PYTHON:-python3}"

cd "$repo"
# where cargo puts the binary: its target folder (CARGO_TARGET_DIR, CARGO_BUILD_TARGET_DIR,
# a .cargo/config.toml's build.target-dir, or target/ by default), as cargo itself reports it
target_dir="$("$python" -c 'import json, sys; print(json.load(sys.stdin)["target_directory"])' \
    < <(cargo metadata --format-version 1 --no-deps))"
if [ "${1:-}" = "--where" ]; then
    echo "$target_dir/test-release/gmap"
    exit 0
fi
echo "== building the gmap command (for the comparison with the package)"
cargo build --profile test-release --bin gmap --quiet
export GMAP_BIN="$target_dir/test-release/gmap"
[ -x "$GMAP_BIN" ] || { echo "no gmap binary at $GMAP_BIN (cargo's target folder)" >&2; exit 1; }
export GMAP_REQUIRE_CLI=1

venv="${GMAP_VENV:-}"
cleanup=""
if [ -z "$venv" ]; then
    venv="$(mktemp -d "${TMPDIR:-/tmp}/gmap-venv.XXXXXX")"
    cleanup="$venv"
fi
trap '[ -n "$cleanup" ] && rm -rf "$cleanup"' EXIT

echo "== a fresh virtual environment in $venv"
"$python" -m venv "$venv"
pip=("$venv/bin/python" -m pip --disable-pip-version-check -q)
"${pip[@]}" install maturin numpy pytest hypothesis networkx "dask[distributed]"
"${pip[@]}" install gudhi || echo "(gudhi not installed: its comparisons are skipped)"
"${pip[@]}" install meshio || echo "(meshio not installed: the mesh files' comparisons are skipped)"
"${pip[@]}" install vtk || echo "(vtk not installed: VTK's checks of the mesh files are skipped)"
"${pip[@]}" install ifcopenshell || echo "(ifcopenshell not installed: the IFC tests are skipped)"
"${pip[@]}" install topologicpy topologic-core \
    || echo "(topologicpy not installed: the room graphs are checked against its recorded answers only)"

echo "== pip install ./python"
"${pip[@]}" install ./python

echo "== pytest python/tests"
# from the repository root, with the installed package (not the source folder) imported
"$venv/bin/python" -m pytest python/tests -q -p no:cacheprovider "$@"
