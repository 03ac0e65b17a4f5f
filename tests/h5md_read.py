#!/usr/bin/python3
"""What a user does in the first hour with a run file and h5py (Debian's python3-h5py):

    h5md_read.py NEW.h5 [OLD.h5]

NEW.h5 is a layout-2 run file of a shaker with snapshots: read positions and the box, a time
series with its unit, a parameter as a number (attrs['gamma'] * 2), and pair the snapshots
with the temperature samples taken at the same instants by step alone.  OLD.h5 (optional) is a
layout-1 file, whose parameters are text: read them through param() below.  Prints one line
per check, "ok ..." or "FAIL ...", and exits 1 on any failure.
"""
import sys

import h5py
import numpy as np

failed = 0


def check(what, cond):
    global failed
    print(("ok    " if cond else "FAIL  ") + what)
    failed += 0 if cond else 1


def param(f, key):
    """A number of /parameters in either layout (layout 1 stored it as text)."""
    v = f["parameters"].attrs[key]
    return float(v.decode() if isinstance(v, bytes) else v)


def layout(f):
    return int(f["h5md/creator"].attrs.get("wetgran_layout", 1))


with h5py.File(sys.argv[1], "r") as f:
    check("layout 2 (wetgran_layout on /h5md/creator)", layout(f) == 2)
    check("H5MD 1.1", list(f["h5md"].attrs["version"]) == [1, 1])
    pos = f["particles/all/position"]
    r = pos["value"][-1]
    box = f["particles/all/box"]
    dim = int(box.attrs["dimension"])
    edges = box["edges"][()]
    bnd = [b.decode() for b in box.attrs["boundary"]]
    n = len(f["particles/all/id"])
    check("positions: %d particles x %d coordinates" % r.shape, r.shape == (n, dim))
    lateral = [k for k in range(dim) if bnd[k] == "periodic"]
    check("positions inside the box along periodic axes %s" % lateral,
          all(np.all((r[:, k] >= 0) & (r[:, k] < edges[k])) for k in lateral))
    # in a shaker, the particles lie between the floor and the lid of their instant
    t_last = pos["time"][-1]
    floor, lid = f["observables/walls/floor"], f["observables/walls/lid"]
    k = int(np.searchsorted(floor["step"][()], pos["step"][-1]))
    zf, zl = floor["value"][k], lid["value"][k]
    rad = f["particles/all/diameter"][()] / 2
    z = r[:, dim - 1]
    check("last snapshot (t = %g): every particle between floor %.4f and lid %.4f" % (t_last, zf, zl),
          floor["time"][k] == t_last and np.all(z - rad >= zf - 1e-9) and np.all(z + rad <= zl + 1e-9))
    temp = f["observables/temperature"]
    unit = temp["value"].attrs["unit"]
    check("temperature unit %r is a str in the units module's grammar (energy: m d+2 tau-2)" % unit,
          unit == "m d+2 tau-2" and f["h5md/modules/units"].attrs["system"] == "wetgran")
    check("time unit 'tau' = sqrt(d/g) is declared", temp["time"].attrs["unit"] == "tau" and
          "sqrt(d/g)" in f["h5md/modules/units"].attrs["tau"].decode())
    gamma = f["parameters"].attrs["gamma"]
    check("attrs['gamma'] * 2 = %r (a number, not text)" % (gamma * 2,),
          isinstance(gamma * 2, (float, np.floating)) and gamma * 2 == 2 * param(f, "gamma"))
    check("seed is an unsigned integer", np.issubdtype(f["parameters"].attrs["seed"].dtype, np.unsignedinteger))
    check("words stay text (container = shaker)", f["parameters"].attrs["container"] == b"shaker")
    # align snapshots with temperature samples by step: same step, same instant
    ps, ts = pos["step"][()], temp["step"][()]
    common, ip, it = np.intersect1d(ps, ts, return_indices=True)
    check("%d snapshots share a step with a temperature sample" % len(common), len(common) >= 2)
    check("and those steps are the same times", np.array_equal(pos["time"][ip], temp["time"][it]))
    # the temperature recomputed from the snapshot's velocities (Eq. 3.2) is the sample's
    v = f["particles/all/velocity/value"][ip[-1]]
    m = f["particles/all/mass"][()]
    vcm = (m[:, None] * v).sum(0) / m.sum()
    tg = (m[:, None] * (v - vcm) ** 2).sum() / (n * dim)
    check("T_g of snapshot step %d from its velocities = the series' %.6g" % (common[-1], temp["value"][it[-1]]),
          abs(tg - temp["value"][it[-1]]) <= 1e-9 * abs(tg))
    check("steps are one clock: the walls are sampled at every step 0..K-1",
          np.array_equal(floor["step"][()], np.arange(len(floor["step"]))) and
          set(ps) | set(ts) <= set(floor["step"][()].tolist()))

if len(sys.argv) > 2:
    with h5py.File(sys.argv[2], "r") as f:
        check("old file is layout 1", layout(f) == 1)
        g = f["parameters"].attrs["gamma"]
        check("its gamma is text %r, read as %g by param()" % (g, param(f, "gamma")),
              isinstance(g, bytes) and param(f, "gamma") > 0)
        check("its positions and temperature read the same way",
              f["particles/all/position/value"].ndim == 3 and f["observables/temperature/value"].ndim == 1)

print("%d failed" % failed)
sys.exit(1 if failed else 0)
