"""max_overlap.py RUN.h5: the largest overlap (r_i + r_j - |r_ij|, in d; <= 0: none) of the
run's last snapshot, periodic axes by the minimum image.  Brute force over all pairs (numpy,
in blocks): for the few thousand grains of a stress cell."""
import sys
import h5py
import numpy as np

with h5py.File(sys.argv[1], "r") as f:
    pos = f["/particles/all/position/value"][-1]
    diam = f["/particles/all/diameter"][()]
    box = f["/particles/all/box/edges"][()]
    bnd = [b.decode().rstrip("\0") if isinstance(b, bytes) else str(b) for b in f["/particles/all/box"].attrs["boundary"]]
periodic = np.array([b == "periodic" for b in bnd])
rad = 0.5 * diam
worst = -np.inf
n = len(pos)
for a in range(0, n, 256):
    d = pos[a:a + 256, None, :] - pos[None, :, :]
    d = np.where(periodic, d - box * np.round(d / box), d)
    dist = np.sqrt((d * d).sum(-1))
    ov = rad[a:a + 256, None] + rad[None, :] - dist
    idx = np.arange(a, min(a + 256, n))
    ov[idx - a, idx] = -np.inf
    worst = max(worst, ov.max())
print("%.3e" % worst)
