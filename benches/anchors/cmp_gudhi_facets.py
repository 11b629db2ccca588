#!/usr/bin/env python3
# usage: cmp_gudhi_facets.py GMAP_BINARY DIR...   e.g. cmp_gudhi_facets.py target/release/gmap tests/data/lutz
# End-to-end integer homology by `gmap homology FILE --json` against GUDHI's Z/2 persistence of
# the same simplicial complex (same cells), per .facets file; prints times, ratios, Betti numbers.
import sys, time, os, subprocess, json, gudhi, math, re
G=sys.argv[1]
files=[]
for D in sys.argv[2:]:
    for root,_,fs in os.walk(D):
        files+=[os.path.join(root,f) for f in fs if f.endswith(".facets")]
rows=[]
for p in sorted(files):
    f=os.path.relpath(p, os.path.dirname(p.rstrip('/')))
    head=open(p).read(400)
    facets=[list(map(int,l.split())) for l in open(p) if l.strip() and not l.startswith('#')]
    if not facets or len({len(x) for x in facets})>1 or "NOT a pseudo" in head: continue
    n,k=len(facets[0])-1,len(facets)
    darts=k*math.factorial(n+1)
    if darts>3e7: continue
    best=1e9
    for r in range(2):
        t0=time.perf_counter(); st=gudhi.SimplexTree()
        for fc in facets: st.insert(fc)
        st.compute_persistence(homology_coeff_field=2, persistence_dim_max=True); b=st.betti_numbers()
        best=min(best,time.perf_counter()-t0)
    ours=1e9
    for r in range(2):
        t0=time.perf_counter(); out=subprocess.run([G,"homology",p,"--json"],capture_output=True,text=True,timeout=600); ours=min(ours,time.perf_counter()-t0)
    try: j=json.loads(out.stdout); ob=j.get("betti")
    except Exception: ob=out.stderr[:80]
    rows.append((f,n,k,darts,best,ours,ours/best))
    print(f"{f:40s} d{n} facets {k:7d} darts {darts:9d} gudhi {best*1000:9.1f} ms  ours {ours*1000:9.1f} ms  ours/gudhi {ours/best:7.2f}  {b} {ob}", flush=True)
import statistics
print("geomean ours/gudhi", math.exp(statistics.mean(math.log(r[6]) for r in rows)))
