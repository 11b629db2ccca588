"""Writes the small images of gmap-ops/tests/image.rs with numpy itself (run from this folder).

One 4 x 3 x 2 array `a` (values 0..5, some zero) saved in every dtype, both orders and both
byte orders, in format versions 1.0, 2.0 and 3.0; its non-zero cubes as `a.cub`; the same
values as a DIPHA image written the way DIPHA's save_image_data.m writes it.
"""
import struct
import numpy as np

a = (np.arange(24).reshape(4, 3, 2) * 7) % 6
with open("a.cub", "w") as f:
    for idx in zip(*np.nonzero(a)):
        f.write("(" + ",".join(str(int(i)) for i in idx) + ")\n")
for dt in ["?", "i1", "u1", "<i2", ">i2", "<u2", "<i4", ">i4", "<u4", "<i8", ">i8", "<u8", "<f4", ">f4", "<f8", ">f8"]:
    name = dt.replace("<", "le").replace(">", "be").replace("?", "bool")
    np.save(f"a_{name}_c.npy", a.astype(dt))
    np.save(f"a_{name}_f.npy", np.asfortranarray(a.astype(dt)))
for v in [(2, 0), (3, 0)]:
    with open(f"a_v{v[0]}.npy", "wb") as f:
        np.lib.format.write_array(f, a.astype("<i4"), version=v)
with open("a.complex", "wb") as f:
    f.write(struct.pack("<5q", 8067171840, 1, a.size, 3, 4) + struct.pack("<2q", 3, 2))
    f.write(np.asfortranarray(a.astype("<f8")).tobytes(order="F"))
np.save("line.npy", np.array([1, 0, 1, 1], dtype="u1"))
