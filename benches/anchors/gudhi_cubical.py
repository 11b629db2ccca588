#!/usr/bin/env python3
# usage: gudhi_cubical.py [K]   (default 40)
# Anchor: GUDHI's Z/2 homology of the periodic K^3 cubical complex (the 3-torus as K^3 cubes),
# the cellular counterpart of gmap's periodic grid; three runs, each printing its times.
import time, sys, numpy as np, gudhi
n=int(sys.argv[1]) if len(sys.argv)>1 else 40
for rep in range(3):
    t0=time.perf_counter()
    cc=gudhi.PeriodicCubicalComplex(top_dimensional_cells=np.zeros((n,n,n)), periodic_dimensions=[True,True,True])
    t1=time.perf_counter()
    cc.compute_persistence(homology_coeff_field=2)
    b=cc.betti_numbers()
    t2=time.perf_counter()
    print(f"GUDHI PeriodicCubical {n}^3: build {t1-t0:.3f}s persistence+betti {t2-t1:.3f}s betti {b}", flush=True)
