#!/usr/bin/python3
"""Synthetic run files with known answers for tests/test_interface.sh (wetgran-interface).

  interface_synth.py KIND OUT.h5 [key=value ...]

Kinds (positions and velocities written as wetgran-run's layout, enough for the tool):
  profile2d   a 2D run with only time-averaged profiles: 100 bins on lx = 100, T_g/E_cb = 50 in
              the gas bins [g0, g1) (default 20, 60; taken periodically), 3 elsewhere
  snap2d      a 2D run with snapshots: lx = 100, particles 16 per d (fluid) or 4 per d (gas in
              [g0, g1 + grow k) in frame k, time 10 k), speeds ~ 1 (fluid) or 10 (gas), frames = 4
  disk3d      a 3D run, box L x L x 8 (L = 60): a disk of radius r (15) centred at (cx, cy)
              (default the corner 0, 0, so it is split over the periodic boundaries) in phase
              'inside' (gas) and the rest in the other phase
  strip3d     a 3D run, box L x L x 8 (L = 96): a fluid strip along x between
              y = c -/+ w/2 + a cos(2 pi x / L) (c 48, w 36, a 6), gas elsewhere; with
              frames = K and tau = T the amplitude of frame k (time 10 k) is a exp(-10 k / T)
  plugwalk    a 2D run with lateral maps (lx = 400, nx = 4000 cells of 0.1 d): a plug of width
              w (100) whose centre moves by sign * a * k^(h) (a 2, h 0.65, sign +1) from c0 (350) over
              frames k = 0 .. frames - 1 (60) at times k * T_driv (so crossing x = 400); dense
              cells: n 5, T_g 3 E_cb; gas: n 0.5, T_g 50 E_cb
  droplets2d  a 2D run with lateral maps (lx = 1000, 1000 cells): frame k holds counts[k]
              (a comma list) equally spaced droplets 20 d wide (n 5, gas 0.5), T_g of every
              cell (c / N)^2 E_cb (c 8): N_f = c (T_g/E_cb)^(-1/2) exactly; times 10 k
  domains3d   a 3D run with lateral maps, 64 x 64 cells on L = 64: frames at t = T_driv * 8^k
              (k < 4) holding 64, 32, 16, 8 crystalline rectangles (T_g 1e-3 E_cb, 6 bridges
              per grain; the fluid 1 E_cb, 4) of 4, 8, 16, 32 cells, one across the periodic
              corner: N_d = 64 (t / T_driv)^(-1/3), area fraction 1/16 in every frame
Every particle field is on a lattice of spacing 'h' (fluid) with speeds from a fixed seed.
"""
import sys
import h5py
import numpy as np

kind, out = sys.argv[1], sys.argv[2]
kv = dict(a.split("=", 1) for a in sys.argv[3:])
g = lambda k, d: float(kv.get(k, d))
rng = np.random.default_rng(int(g("seed", 1)))
E_CB = 0.2844


def header(f, edges, params):
    f.create_group("h5md").attrs["version"] = np.array([1, 1], dtype=np.int32)
    box = f.create_group("particles/all/box")
    box.attrs["dimension"] = len(edges)
    box.create_dataset("edges", data=np.array(edges, dtype=float))
    p = f.create_group("parameters")
    base = dict(e_cb=E_CB, gamma=8.0, estar=10.0, s_crit=0.0711, f_b=4.0, height=edges[-1])
    base.update(params)
    for k, v in base.items():
        p.attrs[k] = v


def snapshots(f, frames):
    """frames: list of (pos N x D, vel N x D); N must be equal in all."""
    n, d = frames[0][0].shape
    pos = np.array([fr[0] for fr in frames])
    vel = np.array([fr[1] for fr in frames])
    t = np.arange(len(frames)) * 10.0
    for name, val in (("position", pos), ("velocity", vel)):
        grp = f.create_group("particles/all/" + name)
        grp.create_dataset("value", data=val)
        grp.create_dataset("time", data=t)
        grp.create_dataset("step", data=np.arange(len(frames)))
    bc = f.create_group("particles/all/bridge_count")
    bc.create_dataset("value", data=np.array([fr[2] for fr in frames], dtype=np.uint8))
    bc.create_dataset("time", data=t)
    f.create_dataset("particles/all/mass", data=np.ones(n))
    f.create_dataset("particles/all/diameter", data=np.ones(n))


def lattice_2d(lx, ly, h):
    xs = np.arange(h / 2, lx, h)
    ys = np.arange(h / 2, ly, h)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    return X.ravel(), Y.ravel()


def layered(gas_mask, X, Y, z_height, dim, frames):
    """particles at lattice sites (X, Y); gas sites keep every fourth; speeds 10 (gas) or 1."""
    keep = ~gas_mask | (np.arange(len(X)) % 4 == 0)
    X, Y, gas = X[keep], Y[keep], gas_mask[keep]
    n = len(X)
    out = []
    for _ in range(frames):
        scale = np.where(gas, 10.0, 1.0)[:, None]
        if dim == 2:
            pos = np.column_stack([X, rng.uniform(0.5, z_height - 0.5, n)])
        else:
            pos = np.column_stack([X, Y, rng.uniform(0.5, z_height - 0.5, n)])
        vel = rng.normal(size=(n, dim)) * scale
        bridges = np.where(gas, 0, 3)
        out.append((pos, vel, bridges))
    return out


def tdriv(params):
    """wetgran-run's driving period from the header's gamma, estar, e_cb (g = 1)."""
    return 2 * np.pi * np.sqrt(2 * params.get("estar", 10.0) * E_CB) / params.get("gamma", 8.0)


def maps(f, times, dens, bridges, temp):
    """/observables/maps: frames x [ny x] nx arrays; temp in units of E_cb."""
    for name, val in (("number_density", dens), ("bridge_density", bridges),
                      ("temperature", np.asarray(temp) * E_CB)):
        grp = f.create_group("observables/maps/" + name)
        grp.create_dataset("value", data=np.asarray(val, dtype=float))
        grp.create_dataset("time", data=np.asarray(times, dtype=float))
        grp.create_dataset("step", data=np.arange(len(times)))


with h5py.File(out, "w") as f:
    if kind == "plugwalk":
        header(f, [400.0, 9.0], {})
        nx, w, c0 = 4000, g("w", 100), g("c0", 350)
        x = (np.arange(nx) + 0.5) * 0.1
        frames = int(g("frames", 60))
        centre = [c0 + g("sign", 1) * g("a", 2) * k ** g("h", 0.65) for k in range(frames)]
        dense = np.array([np.abs((x - c + 200) % 400 - 200) < w / 2 for c in centre])
        maps(f, np.arange(frames) * tdriv({}), np.where(dense, 5.0, 0.5), np.where(dense, 3.0, 0.0),
             np.where(dense, 3.0, 50.0))
    elif kind == "droplets2d":
        header(f, [1000.0, 9.0], {})
        counts = [int(c) for c in kv.get("counts", "2,4,8,8,8,7,6,5,4,3,2,2,2,4,4,4").split(",")]
        x = np.arange(1000) + 0.5
        c = g("c", 8)
        dens, temp = [], []
        for n in counts:
            centres = (np.arange(n) + 0.5) * 1000 / n
            d = np.min(np.abs((x[:, None] - centres[None, :] + 500) % 1000 - 500), axis=1) < 10
            dens.append(np.where(d, 5.0, 0.5))
            temp.append(np.full(1000, (c / n) ** 2))
        maps(f, np.arange(len(counts)) * 10.0, dens, np.array(dens) - 0.5, temp)
    elif kind == "domains3d":
        header(f, [64.0, 64.0, 8.0], {})
        # (h, w, spacing along y, along x) per frame
        sizes = [(2, 2, 8, 8), (2, 4, 16, 8), (4, 4, 16, 16), (4, 8, 32, 16)]
        dens, temp = [], []
        for h, w, spy, spx in sizes:
            t = np.ones((64, 64))
            for y0 in range(-1, 63, spy):  # the first row starts at -1: across the corner
                for x0 in range(-1, 63, spx):
                    for yy in range(y0, y0 + h):
                        for xx in range(x0, x0 + w):
                            t[yy % 64, xx % 64] = 1e-3
            temp.append(t)
            dens.append(np.full((64, 64), 3.0))
        # coordination 2 n_cb / n: 6 in the crystal, 4 in the fluid
        maps(f, [tdriv({}) * 8 ** k for k in range(4)], dens,
             np.where(np.array(temp) < 0.01, 9.0, 6.0), temp)
    elif kind == "profile2d":
        header(f, [100.0, 9.0], {"estar": g("estar", 10)})
        x = np.arange(100) + 0.5
        g0, g1 = g("g0", 20), g("g1", 60)
        gas = ((x - g0) % 100) < ((g1 - g0) % 100)
        pr = f.create_group("observables/profiles")
        pr.attrs["e_cb"] = E_CB
        pr.create_dataset("x", data=x)
        pr.create_dataset("number_density", data=np.where(gas, 1.0, 4.0))
        pr.create_dataset("bridge_density", data=np.where(gas, 0.01, 5.0))
        pr.create_dataset("temperature", data=np.where(gas, 50.0, 3.0) * E_CB)
    elif kind == "snap2d":
        header(f, [100.0, 9.0], {})
        g0, g1, grow = g("g0", 30), g("g1", 70), g("grow", 0)
        X, _ = lattice_2d(100.0, 1.0, 0.25)
        frames = []
        for k in range(int(g("frames", 4))):
            gas = ((X - g0) % 100) < ((g1 + grow * k - g0) % 100)
            frames += layered(gas, X, X * 0, 9.0, 2, 1)
        # equal particle numbers in every frame: the gas keeps every fourth site, so pad
        n = max(len(fr[0]) for fr in frames)
        snapshots(f, [(np.vstack([p, p[:n - len(p)]]), np.vstack([v, v[:n - len(p)]]),
                       np.concatenate([b, b[:n - len(p)]])) for p, v, b in frames])
    elif kind == "disk3d":
        L = g("L", 60)
        header(f, [L, L, 8.0], {})
        X, Y = lattice_2d(L, L, 0.5)
        cx, cy, r = g("cx", 0), g("cy", 0), g("r", 15)
        dx = (X - cx + L / 2) % L - L / 2
        dy = (Y - cy + L / 2) % L - L / 2
        inside = dx * dx + dy * dy < r * r
        gas = inside if kv.get("inside", "gas") == "gas" else ~inside
        snapshots(f, layered(gas, X, Y, 8.0, 3, int(g("frames", 2))))
    elif kind == "strip3d":
        L = g("L", 96)
        header(f, [L, L, 8.0], {})
        X, Y = lattice_2d(L, L, 0.5)
        c, w, a, tau = g("c", 48), g("w", 36), g("a", 6), g("tau", 0)
        frames = []
        for k in range(int(g("frames", 2))):
            amp = a * np.exp(-10.0 * k / tau) if tau > 0 else a
            edge = c + amp * np.cos(2 * np.pi * X / L)
            d = (Y - edge + L / 2) % L - L / 2
            gas = np.abs(d) >= w / 2
            frames += layered(gas, X, Y, 8.0, 3, 1)
        # the frames have different particle numbers: pad with gas particles far apart
        n = max(len(fr[0]) for fr in frames)
        padded = []
        for pos, vel, br in frames:
            m = n - len(pos)
            if m:
                gi = np.flatnonzero(br == 0)[:m]
                pos = np.vstack([pos, pos[gi] + [0.1, 0.1, 0]])
                vel = np.vstack([vel, vel[gi]])
                br = np.concatenate([br, br[gi]])
            padded.append((pos % [L, L, 100], vel, br))
        snapshots(f, padded)
    else:
        sys.exit("interface_synth.py: unknown kind " + kind)
