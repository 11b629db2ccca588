#!/usr/bin/env python3
# The GUDHI column of `gmap bench` (embedded in the binary; runnable by hand):
#   bench_gudhi.py FILE.facets...
# For each file, one JSON line on stdout: {"file": F, "ms": T, "betti": [...]} with T the
# wall time in ms of GUDHI's SimplexTree built from the file's facets plus its Z/2
# persistence (file parsing excluded, as in compare_gudhi.py), or {"file": F, "error": E}.
import json, re, sys, time

import gudhi

for p in sys.argv[1:]:
    try:
        facets = []
        with open(p) as f:
            for line in f:
                line = line.split("#", 1)[0].strip()
                if line:
                    facets.append([int(x) for x in re.split(r"[\s,]+", line) if x])
        t0 = time.perf_counter()
        st = gudhi.SimplexTree()
        for fc in facets:
            st.insert(fc)
        st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True)
        b = st.betti_numbers()
        ms = (time.perf_counter() - t0) * 1000.0
        # freed here, untimed: otherwise the next file's time would include freeing this tree
        del st
        print(json.dumps({"file": p, "ms": ms, "betti": b}), flush=True)
    except Exception as e:  # noqa: BLE001 - any failure is that file's error
        print(json.dumps({"file": p, "error": str(e)[:200]}), flush=True)
