#!/usr/bin/env bash
# Runs every command of a `gmap` binary over tests/data (and files derived from it by the same
# binary's `convert`) and writes each output, stderr and exit code under OUT, so that two
# builds can be compared byte for byte: `diff -r OUT1 OUT2`.
#   scripts/cli-snapshot.sh BINARY OUT
# Times and memory are the only things that differ between runs: `bench` rows keep their groups and cells,
# with the millisecond and peak-memory columns removed.
set -u
bin=$(realpath "$1"); out=$(realpath -m "$2")
cd "$(dirname "$0")/.."
# derived files live at one fixed place, so that the messages naming them agree between runs
derived=${TMPDIR:-/tmp}/gmap-cli-snapshot
rm -rf "$out" "$derived"; mkdir -p "$out" "$derived"
run() { # name, args...
  local name=$1; shift
  "$bin" "$@" >"$out/$name.out" 2>"$out/$name.err"; echo $? >"$out/$name.rc"
}
inputs=$(find tests/data -type f \( -name '*.facets' -o -name '*.gmap' -o -name '*.cub' -o -name '*.pbm' -o -name '*.json' \) | sort)
# derived inputs: every format the binary writes, from a surface, a 3-manifold and the labelled file
for src in tests/data/lutz/poincare.facets tests/data/lutz/dunce_hat.facets tests/data/labelled_segment.gmap; do
  b=$(basename "$src" | tr . _)
  for ext in gmap moka off facets vtk json lar.json dot; do
    run "convert_${b}_$ext" convert "$src" "$derived/$b.$ext"
  done
done
run demo demo
for f in $inputs $(find "$derived" -type f | sort); do
  n=$(echo "${f#$derived/}" | tr / _)
  run "info_$n" info "$f"
  run "infojson_$n" info "$f" --json
  run "hom_$n" homology "$f"
  run "homjson_$n" homology "$f" --json
  run "homgen_$n" homology "$f" --generators
  run "homgenjson_$n" homology "$f" --json --generators
  run "homf3_$n" homology "$f" --field 3
  run "homsimp_$n" homology "$f" --method simplicial --max-darts 200000
  run "homsimplify_$n" homology "$f" --simplify
  run "homvia_$n" homology "$f" --via gmap
  run "homdirect_$n" homology "$f" --via direct
  run "homtopo_$n" homology "$f" --topological
  run "homper_$n" homology "$f" --periodic
  run "infoper_$n" info "$f" --periodic
  run "hommax_$n" homology "$f" --max-darts 10
done
# bench: the rows without their times (and without the GUDHI column of older builds)
bench_inputs="tests/data/lutz/poincare.facets tests/data/lutz/dunce_hat.facets tests/data/cubical"
run bench bench $bench_inputs --json --no-gudhi
[ "$(cat "$out/bench.rc")" = 2 ] && run bench bench $bench_inputs --json
python3 -c '
import json, sys
rows = json.load(open(sys.argv[1]))["rows"]
for r in rows:
    for k in ("times_ms", "gudhi_ms", "ratio", "peak_rss_bytes"):
        r.pop(k, None)
    print(json.dumps(r, sort_keys=True))
' "$out/bench.out" >"$out/bench.masked" && rm "$out/bench.out" "$out/bench.err"
run missing info no/such/file.gmap
run noext homology README
cp -r "$derived" "$out/derived"
