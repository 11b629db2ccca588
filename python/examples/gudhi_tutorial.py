"""A GUDHI tutorial-style script: cubical persistence of a sample image, a simplex tree
of a small complex, Betti and persistent Betti numbers. Written for GUDHI; it runs on gmap
by changing its import to ``import gmap.gudhi as gudhi`` (python/tests/test_gudhi_tutorial.py
runs it both ways). Prints its results and leaves them in ``results``."""

import gudhi
import numpy as np

results = {}

# a sample image: two bright blobs on a ramp, with a ring around the first
y, x = np.mgrid[0:40, 0:50]
image = 0.02 * x + np.exp(-((x - 15) ** 2 + (y - 20) ** 2) / 30.0) + np.exp(-((x - 35) ** 2 + (y - 12) ** 2) / 20.0)
ring = np.abs(np.hypot(x - 15, y - 20) - 9) < 1.2
image[ring] += 2.0
image = np.round(image, 3)

cc = gudhi.CubicalComplex(top_dimensional_cells=image)
diagram = cc.persistence()
results["cubical"] = sorted(diagram)
results["cubical_betti"] = cc.betti_numbers()
results["cubical_persistent_betti"] = cc.persistent_betti_numbers(1.0, 2.0)
results["cubical_h1"] = sorted(cc.persistence_intervals_in_dimension(1).tolist())

# the same image, values on the vertices, and superlevel sets by negation
vc = gudhi.CubicalComplex(vertices=-image)
results["vertices"] = sorted(vc.persistence(homology_coeff_field=2, min_persistence=0.01))

# a periodic version
pc = gudhi.PeriodicCubicalComplex(top_dimensional_cells=image[:20, :20], periodic_dimensions=[True, True])
results["periodic"] = sorted(pc.persistence())
results["periodic_betti"] = pc.betti_numbers()

# a simplex tree of a small complex: a hollow tetrahedron's boundary and a tail
st = gudhi.SimplexTree()
for face, value in (([0, 1, 2], 1.0), ([0, 1, 3], 2.0), ([0, 2, 3], 3.0), ([1, 2, 3], 4.0), ([3, 4], 0.5), ([4, 5], 0.7)):
    st.insert(face, filtration=value)
results["num_simplices"] = st.num_simplices()
results["filtration"] = list(st.get_filtration())
results["simplicial"] = sorted(st.persistence(persistence_dim_max=True))
results["simplicial_betti"] = st.betti_numbers()
results["simplicial_persistent_betti"] = st.persistent_betti_numbers(2.0, 3.5)
results["simplicial_h2"] = sorted(st.persistence_intervals_in_dimension(2).tolist())

# a flag complex by expansion
fl = gudhi.SimplexTree()
for e, f in (([0, 1], 0.1), ([1, 2], 0.2), ([0, 2], 0.3), ([2, 3], 0.4), ([3, 0], 0.5), ([1, 3], 0.6)):
    fl.insert(e, f)
fl.expansion(3)
results["flag"] = sorted(fl.persistence())
results["flag_betti"] = fl.betti_numbers()

for k, v in results.items():
    print(k, v if not isinstance(v, list) or len(v) < 8 else f"{len(v)} items")
