"""Writes the large test images of docs/PERFORMANCE.md as .npy files, a slab at a time
(memory stays at a few hundred MB whatever the size).

    python3 benches/anchors/make_images.py random OUT.npy SIZE DIM DENSITY [SEED]
    python3 benches/anchors/make_images.py structured OUT.npy SIZE

`random`: a uint8 array of SIZE^DIM values, each 1 with probability DENSITY.
`structured`: a uint8 SIZE^3 array holding 5 nested spherical shells (H2 = Z^5), 7 solid tori
(H1 = Z^7) and 6 solid balls, all apart: H0 = Z^18, H1 = Z^7, H2 = Z^5 (SIZE >= 256; the
objects scale with SIZE / 1024).
"""
import sys
import numpy as np


def random_image(out, size, dim, density, seed):
    shape = (size,) * dim
    a = np.lib.format.open_memmap(out, mode="w+", dtype=np.uint8, shape=shape)
    rng = np.random.default_rng(seed)
    step = max(1, (1 << 24) // (size ** (dim - 1)))
    for i in range(0, size, step):
        j = min(size, i + step)
        a[i:j] = rng.random((j - i,) + shape[1:], dtype=np.float32) < density
    a.flush()


def structured(out, size):
    s = size / 1024.0
    a = np.lib.format.open_memmap(out, mode="w+", dtype=np.uint8, shape=(size, size, size))
    shells_c = np.array([300, 300, 300]) * s
    radii = [((40 + 30 * i) * s, (48 + 30 * i) * s) for i in range(5)]
    tori = [(np.array([100 + 130 * k, 750, 800]) * s, 45 * s, 12 * s) for k in range(7)]
    balls = [(np.array([800, 200 + 100 * j, 300]) * s, 20 * s) for j in range(6)]
    y, z = np.meshgrid(np.arange(size, dtype=np.float32), np.arange(size, dtype=np.float32), indexing="ij")
    for x in range(size):
        layer = np.zeros((size, size), dtype=bool)
        r2 = (x - shells_c[0]) ** 2 + (y - shells_c[1]) ** 2 + (z - shells_c[2]) ** 2
        for lo, hi in radii:
            layer |= (r2 >= lo * lo) & (r2 <= hi * hi)
        for c, big, small in tori:
            # the circle of radius `big` around c in the plane z = c_z
            rho = np.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2)
            layer |= (rho - big) ** 2 + (z - c[2]) ** 2 <= small * small
        for c, r in balls:
            layer |= (x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2 <= r * r
        a[x] = layer
    a.flush()


if __name__ == "__main__":
    kind, out = sys.argv[1], sys.argv[2]
    size = int(sys.argv[3])
    if kind == "random":
        dim, density = int(sys.argv[4]), float(sys.argv[5])
        seed = int(sys.argv[6]) if len(sys.argv) > 6 else 1
        random_image(out, size, dim, density, seed)
    elif kind == "structured":
        structured(out, size)
    else:
        sys.exit(f"unknown kind {kind}")
