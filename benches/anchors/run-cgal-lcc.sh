#!/usr/bin/env bash
# Build CGAL's Linear_cell_complex grid harness (Debian's libcgal-dev) and run it.
# usage: run-cgal-lcc.sh [K] [reps] [variant]   prints one JSON line per variant (see cgal_lcc_grid.cpp)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
k=${1:-40}; reps=${2:-3}
[ -f /usr/include/CGAL/Linear_cell_complex_for_generalized_map.h ] || { apt-get update -qq && apt-get install -y -qq libcgal-dev >/dev/null; }
bin="${TMPDIR:-/tmp}/cgal_lcc_grid"
# (re)build when the binary is missing or older than its source
[ "$bin" -nt "$here/cgal_lcc_grid.cpp" ] || g++ -O3 -DNDEBUG -DCGAL_NDEBUG -std=c++17 "$here/cgal_lcc_grid.cpp" -o "$bin" -lgmp -lmpfr
exec "$bin" "$k" "$reps" ${3:+"$3"}
