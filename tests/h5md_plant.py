#!/usr/bin/python3
"""Plant faults in copies of a layout-2 run file, for tests/test_h5md.sh:

    h5md_plant.py FILE DIR FAULT ...     DIR/FAULT.h5: a copy of FILE with that one fault
    h5md_plant.py --list                 the faults

Each fault breaks one rule of tests/h5md_check.py, which must then name that rule.
"""
import os
import shutil
import sys

import h5py
import numpy as np


def vlen(s):
    return np.array(s, dtype=h5py.string_dtype("ascii"))


def drop_version(f):            # H2
    del f["h5md"].attrs["version"]


def drop_author(f):             # H3
    del f["h5md/author"]


def step_rows(f):               # T3: step shorter than value
    g = f["observables/temperature"]
    s = g["step"][()][:-1]
    attrs = dict(g["step"].attrs)
    del g["step"]
    g["step"] = s
    for k, v in attrs.items():
        g["step"].attrs[k] = v


def time_back(f):               # T5 (and W5)
    t = f["observables/kinetic_energy/time"]
    t[2] = t[0] - 1


def step_float(f):              # T1
    g = f["observables/bridges"]
    s = g["step"][()].astype(float)
    attrs = dict(g["step"].attrs)
    del g["step"]
    g["step"] = s
    for k, v in attrs.items():
        g["step"].attrs[k] = v


def boundary_open(f):           # P3
    b = f["particles/all/box"].attrs["boundary"].copy()
    b[0] = b"open"
    f["particles/all/box"].attrs["boundary"] = b


def id_twice(f):                # P6 (and W6)
    i = f["particles/all/id"]
    i[1] = i[0]


def bad_unit(f):                # U3
    f["observables/temperature/value"].attrs["unit"] = vlen("m g d^2")


def fixed_unit(f):              # U2
    f["observables/temperature/value"].attrs["unit"] = np.bytes_("m d+2 tau-2")


def foreign_symbol(f):          # W2
    f["observables/kinetic_energy/value"].attrs["unit"] = vlen("m d+2 s-2")


def drop_layout(f):             # W1 (with --expect-layout 2)
    del f["h5md/creator"].attrs["wetgran_layout"]


def drop_description(f):        # W3
    del f["particles/all/mass"].attrs["description"]


def drop_step_meaning(f):       # W4
    del f["observables"].attrs["step_meaning"]


def own_steps(f):               # W5: each element counting its own samples (layout 1's steps)
    s = f["particles/all/position/step"]
    s[...] = np.arange(len(s))


def text_parameter(f):          # W7
    f["parameters"].attrs["gamma"] = np.bytes_("20")


def wall_moved(f):              # W8
    z = f["observables/walls/lid/value"]
    z[1] = z[1] + 0.01


def bridges_step(f):            # W9
    s = f["bridges/step"]
    s[0] = s[0] + 1


FAULTS = {k: v for k, v in globals().items() if callable(v) and v.__module__ == "__main__" and k != "vlen"}

if __name__ == "__main__":
    if sys.argv[1:] == ["--list"]:
        print("\n".join(FAULTS))
        sys.exit(0)
    src, out = sys.argv[1], sys.argv[2]
    for fault in sys.argv[3:]:
        path = os.path.join(out, fault + ".h5")
        shutil.copyfile(src, path)
        with h5py.File(path, "r+") as f:
            FAULTS[fault](f)
