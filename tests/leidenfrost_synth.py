#!/usr/bin/python3
"""Synthetic height maps with known answers for tests/test_leidenfrost.sh.

  leidenfrost_synth.py OUT.h5 [key=value ...]

A 3D run on a 10 d x 10 d base (t_driv = 1): slabs of w = 0.25 d from z0 = -1 to 201.  Frame k
(time 0.5 k, k < 801) holds a plug of packing fraction 0.62 and height hp (20) above
h_I = h0 + a sin(2 pi t / T) (h0 50, a 10, T 25; a = 0: no oscillation), a gas of fixed volume
(1 d^3 per d^2 of base, so 100/V_bead grains) spread evenly below it, nothing above.  Each
slab holds the mean over its width (a step inside a slab gives the mixed value).
With hole=T, lateral maps of 4 x 4 cells every 2 t.u.: uniform until t = T, then one column
with 0.3 of the mean (a bubble through the plug).
"""
import sys
import h5py
import numpy as np

out = sys.argv[1]
kv = dict(a.split("=", 1) for a in sys.argv[2:])
g = lambda k, d: float(kv.get(k, d))
h0, a, T, hp = g("h0", 50), g("a", 10), g("T", 25), g("hp", 20)
VB = np.pi / 6
z0, w, nb = -1.0, 0.25, 808
edges = z0 + w * np.arange(nb + 1)
t = 0.5 * np.arange(801)


def overlap(lo, hi):
    """fraction of each slab inside [lo, hi)"""
    return np.clip((np.minimum(edges[1:], hi) - np.maximum(edges[:-1], lo)) / w, 0, 1)


phi = []
for x in t:
    hi = h0 + a * np.sin(2 * np.pi * x / T)
    phi.append(0.62 * overlap(hi, hi + hp) + (1.0 / hi) * overlap(0, hi))
phi = np.array(phi)
with h5py.File(out, "w") as f:
    f.create_group("h5md").attrs["version"] = np.array([1, 1], dtype=np.int32)
    p = f.create_group("parameters")
    for k, v in dict(dim=3, n=round((0.62 * hp + 1.0) * 100 / VB), lx=10.0, ly=10.0, t_driv=1.0,
                     e_cb=0.2844, estar=98.9, gamma=60.0).items():
        p.attrs[k] = v
    grp = f.create_group("observables/heights")
    grp.attrs["z0"], grp.attrs["span"] = z0, w * nb
    if "hole" in kv:
        tm = 2.0 * np.arange(400) + 1
        n = np.ones((400, 4, 4)) * 25.6
        n[tm >= g("hole", 0), 1, 2] *= 0.3
        m = f.create_group("observables/maps/number_density")
        m.create_dataset("value", data=n)
        m.create_dataset("time", data=tm)
    for name, val in (("packing_fraction", phi), ("number_density", phi / VB),
                      ("temperature", np.where(phi > 0.5, 0.01, 100.0))):
        s = grp.create_group(name)
        s.create_dataset("value", data=val)
        s.create_dataset("time", data=t)
