#!/usr/bin/python3
"""Series with known Poincare sections for tests/test_poincare.sh (wetgran-poincare).

  poincare_synth.py KIND OUT [key=value ...]

  logistic  a table (time, e_perp): cycles of 40 samples (dt 0.1), each a bump
            0.05 + (x_n - 0.05) sin^2(pi j / 40) peaking at sample 20, x_n+1 = r x_n (1 - x_n)
            (r 2.8, x0 0.2, cycles 30): the sections are x_1, x_2, ... exactly
  noisy     a table: 2 + sin(2 pi t / 10) + N(0, 0.1^2), dt 0.05, t < 1000 (100 periods)
  white     a table: N(0, 1), 5000 samples: no cycle
  ramp      a table: 0.01 i, 2000 samples: no cycle
  h5        a run file (H5MD) holding /observables/e_perp/{time,value} of the logistic kind
"""
import sys
import numpy as np

kind, out = sys.argv[1], sys.argv[2]
kv = dict(a.split("=", 1) for a in sys.argv[3:])
g = lambda k, d: float(kv.get(k, d))
rng = np.random.default_rng(int(g("seed", 7)))


def logistic():
    r, x, n = g("r", 2.8), g("x0", 0.2), int(g("cycles", 30))
    t, v = [], []
    for k in range(n):
        for j in range(40):
            t.append(0.1 * (40 * k + j))
            v.append(0.05 + (x - 0.05) * np.sin(np.pi * j / 40) ** 2)
        x = r * x * (1 - x)
    return np.array(t), np.array(v)


if kind == "logistic":
    t, v = logistic()
elif kind == "noisy":
    t = np.arange(0, 1000, 0.05)
    v = 2 + np.sin(2 * np.pi * t / 10) + 0.1 * rng.standard_normal(t.size)
elif kind == "white":
    t = 0.05 * np.arange(5000)
    v = rng.standard_normal(t.size)
elif kind == "ramp":
    t = 0.05 * np.arange(2000)
    v = 0.01 * np.arange(2000)
elif kind == "h5":
    import h5py
    t, v = logistic()
    with h5py.File(out, "w") as f:
        f.create_group("h5md").attrs["version"] = np.array([1, 1], dtype=np.int32)
        s = f.create_group("observables/e_perp")
        s.create_dataset("time", data=t)
        s.create_dataset("value", data=v)
    sys.exit(0)
else:
    sys.exit("unknown kind " + kind)
with open(out, "w") as f:
    f.write("time\te_perp\n")
    for a, b in zip(t, v):
        f.write("%.6f\t%.12g\n" % (a, b))
