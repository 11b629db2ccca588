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
    a[:] = 0
    # (centre, squared distance test on the offsets within the bounding half-width)
    objects = []
    c = np.array([300, 300, 300]) * s
    for i in range(5):
        lo, hi = (40 + 30 * i) * s, (48 + 30 * i) * s
        objects.append((c, hi, lambda dx, dy, dz, lo=lo, hi=hi: (dx * dx + dy * dy + dz * dz >= lo * lo)
                        & (dx * dx + dy * dy + dz * dz <= hi * hi)))
    for k in range(7):
        big, small = 45 * s, 12 * s
        # the circle of radius `big` in the plane of axes 0 and 1
        objects.append((np.array([100 + 130 * k, 750, 800]) * s, big + small + 1,
                        lambda dx, dy, dz, big=big, small=small: (np.sqrt(dx * dx + dy * dy) - big) ** 2 + dz * dz
                        <= small * small))
    for j in range(6):
        r = 20 * s
        objects.append((np.array([800, 200 + 100 * j, 300]) * s, r + 1,
                        lambda dx, dy, dz, r=r: dx * dx + dy * dy + dz * dz <= r * r))
    for centre, half, test in objects:
        lo = np.maximum(np.floor(centre - half).astype(int), 0)
        hi = np.minimum(np.ceil(centre + half).astype(int) + 1, size)
        gy, gz = np.meshgrid(np.arange(lo[1], hi[1]), np.arange(lo[2], hi[2]), indexing="ij")
        for x in range(lo[0], hi[0]):
            a[x, lo[1]:hi[1], lo[2]:hi[2]] |= test(x - centre[0], gy - centre[1], gz - centre[2]).astype(np.uint8)
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
