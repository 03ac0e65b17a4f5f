#!/usr/bin/python3
"""H5MD 1.1 conformance checker for wetgran run files (Debian's python3-h5py).

Written from the H5MD 1.1.0 specification (h5md.nongnu.org, releases/h5md-1.1.0) and its
units module 1.0 (modules/units); the W rules are wetgran's own layout 2 (run files from
wetgran-run with the attribute wetgran_layout = 2 on /h5md/creator).  Usage:

    h5md_check.py [--expect-layout N] FILE ...     one line per violation, exit 1 if any
    h5md_check.py --list                            the rules

H, T, P rules apply to every file; U rules when the file declares /h5md/modules/units; W rules
when the file says wetgran_layout >= 2 or --expect-layout 2 is given (then a missing or other
layout is itself a violation, W1).
"""
import re
import signal
import sys

import h5py
import numpy as np

RULES = [
    ("H1", "the root holds a group /h5md"),
    ("H2", "/h5md has attribute version: Integer, shape [2], major version 1"),
    ("H3", "/h5md/author is a group with attribute name (and optional email): scalar fixed-length strings"),
    ("H4", "/h5md/creator is a group with attributes name and version: scalar fixed-length strings"),
    ("H5", "every member of /h5md/modules is a group with attribute version: Integer, shape [2]"),
    ("T1", "a time-dependent element (a group holding value) holds step: Integer, shape [variable] "
           "(explicit) or scalar (fixed, optional scalar Integer attribute offset)"),
    ("T2", "time, if present, is Float or Integer and has the shape of step"),
    ("T3", "value is a dataset of rank >= 1 whose first dimension is the length of step (and time)"),
    ("T4", "explicit step values increase monotonically"),
    ("T5", "explicit time values increase monotonically"),
    ("T6", "a group holding step or time also holds value"),
    ("P1", "every group in /particles holds a group box"),
    ("P2", "box has attribute dimension: scalar Integer >= 1"),
    ("P3", "box has attribute boundary: fixed-length strings, shape [D], each 'periodic' or 'none'"),
    ("P4", "box edges: Float or Integer [D] or [D][D] (or a time-dependent element of those); "
           "absent only if every boundary is 'none'"),
    ("P5", "position, velocity, force, image: value of shape [variable][N][D], D the box dimension, "
           "N the same in every per-particle element of the group"),
    ("P6", "mass (Float), species (Integer or Enumeration), id (Integer, unique), charge: shape [N] "
           "(or [variable][N] when time-dependent)"),
    ("U1", "/h5md/modules/units has attribute system: a scalar string"),
    ("U2", "every unit attribute is a scalar variable-length ASCII string"),
    ("U3", "every unit string is unit factors separated by single spaces: at most one number "
           "(integer or decimal fraction, optional signed power), first; symbols at most once each, "
           "each optionally followed by a non-zero signed integer power"),
    ("W1", "/h5md/creator has attribute wetgran_layout: a scalar Integer equal to 2"),
    ("W2", "the units module has system 'wetgran', a string attribute describing each of d, m, tau, "
           "and every unit uses only these symbols"),
    ("W3", "every dataset carries attributes unit and description (a non-empty string)"),
    ("W4", "/particles/all and /observables carry the string attribute step_meaning, and every step "
           "dataset's description is that string"),
    ("W5", "one clock: in every time-dependent element steps strictly increase; across the file "
           "equal steps are equal times and equal times equal steps; the steps used are 0, 1, ... K-1 "
           "(in a record of wetgran-reduce, group /record: a subset of the run's) and increase with time"),
    ("W6", "/particles/all/id is Integer 0 .. N-1 in order and /particles/all/species Integer [N]"),
    ("W7", "/parameters holds numbers as numbers (no text attribute reads as a number) and seed as "
           "an unsigned 64-bit integer"),
    ("W8", "a box whose last boundary is 'none' has the string attribute z_frame and walls "
           "/observables/walls/{floor,lid} with attributes mean, amplitude, omega, phase and "
           "value = mean + amplitude sin(omega time + phase); a periodic box has no walls"),
    ("W9", "/bridges/step and /bridges/time equal /particles/all/position's step and time; "
           "/bridges/offset has one more row"),
]

NUMBER = re.compile(r"^[0-9]+(\.[0-9]+)?([+-][1-9][0-9]*)?$")
SYMBOL = re.compile(r"^([A-Za-z_]+)([+-][1-9][0-9]*)?$")
WETGRAN_SYMBOLS = ("d", "m", "tau")


def unit_errors(unit):
    """Why unit breaks the units module's grammar ([] if it does not)."""
    if unit == "" or unit != unit.strip() or "  " in unit:
        return ["not factors separated by single spaces: %r" % unit]
    errs, seen = [], set()
    for k, tok in enumerate(unit.split(" ")):
        if NUMBER.match(tok):
            if k > 0:
                errs.append("number %r is not the first factor of %r" % (tok, unit))
            continue
        m = SYMBOL.match(tok)
        if not m:
            errs.append("factor %r of %r is neither a number nor a symbol with a signed power" % (tok, unit))
        elif m.group(1) in seen:
            errs.append("symbol %r occurs twice in %r" % (m.group(1), unit))
        else:
            seen.add(m.group(1))
    return errs


def symbols(unit):
    return [SYMBOL.match(t).group(1) for t in unit.split(" ") if SYMBOL.match(t)]


class Attr:
    """Type facts of one attribute, read through the low-level API."""

    def __init__(self, obj, name):
        aid = h5py.h5a.open(obj.id, name.encode())
        self.tid = aid.get_type()
        self.cls = self.tid.get_class()
        self.shape = aid.shape
        self.value = obj.attrs[name]

    def is_string(self):
        return self.cls == h5py.h5t.STRING

    def is_vlen(self):
        return self.is_string() and self.tid.is_variable_str()

    def is_int(self):
        return self.cls == h5py.h5t.INTEGER

    def text(self):
        v = self.value
        if isinstance(v, np.ndarray) and v.shape == ():
            v = v[()]
        return v.decode("ascii", "replace") if isinstance(v, bytes) else str(v)


def attr(obj, name):
    return Attr(obj, name) if name in obj.attrs else None


def dclass(ds):
    return ds.id.get_type().get_class()


def is_int_ds(ds):
    return dclass(ds) == h5py.h5t.INTEGER


def is_num_ds(ds):
    return dclass(ds) in (h5py.h5t.INTEGER, h5py.h5t.FLOAT)


class Checker:
    def __init__(self, path, expect_layout):
        self.path = path
        self.expect = expect_layout
        self.out = []
        self.elements = []  # (path, step array, time array or None) of explicit elements

    def bad(self, rule, where, msg):
        self.out.append("%s: %s %s: %s" % (self.path, rule, where, msg))

    # ---- H ----
    def check_h5md(self, f):
        if "h5md" not in f or not isinstance(f["h5md"], h5py.Group):
            self.bad("H1", "/h5md", "missing")
            return
        h = f["h5md"]
        a = attr(h, "version")
        if a is None:
            self.bad("H2", "/h5md", "no attribute version")
        elif not a.is_int() or a.shape != (2,):
            self.bad("H2", "/h5md", "version is not Integer[2] (shape %s)" % (a.shape,))
        elif int(a.value[0]) != 1:
            self.bad("H2", "/h5md", "major version %d, not 1" % a.value[0])
        for grp, names, rule in (("author", ("name",), "H3"), ("creator", ("name", "version"), "H4")):
            if grp not in h or not isinstance(h[grp], h5py.Group):
                self.bad(rule, "/h5md/" + grp, "missing group")
                continue
            for n in names + (("email",) if grp == "author" else ()):
                a = attr(h[grp], n)
                if a is None:
                    if n != "email":
                        self.bad(rule, "/h5md/" + grp, "no attribute %s" % n)
                elif not a.is_string() or a.is_vlen() or a.shape != ():
                    self.bad(rule, "/h5md/" + grp, "attribute %s is not a scalar fixed-length string" % n)
        if "modules" in h:
            for name, m in h["modules"].items():
                a = attr(m, "version") if isinstance(m, h5py.Group) else None
                if not isinstance(m, h5py.Group):
                    self.bad("H5", "/h5md/modules/" + name, "not a group")
                elif a is None or not a.is_int() or a.shape != (2,):
                    self.bad("H5", "/h5md/modules/" + name, "no version Integer[2]")

    # ---- T ----
    def check_element(self, g):
        p = g.name
        if "value" not in g:
            self.bad("T6", p, "step or time without value")
            return
        v = g["value"]
        if not isinstance(v, h5py.Dataset) or len(v.shape) < 1:
            self.bad("T3", p + "/value", "not a dataset of rank >= 1")
            return
        s = g.get("step")
        if not isinstance(s, h5py.Dataset) or not is_int_ds(s) or len(s.shape) > 1:
            self.bad("T1", p + "/step", "missing, not Integer, or neither [variable] nor scalar")
            return
        t = g.get("time")
        if t is not None and (not isinstance(t, h5py.Dataset) or not is_num_ds(t) or t.shape != s.shape):
            self.bad("T2", p + "/time", "not Float or Integer of step's shape %s" % (s.shape,))
            t = None
        if s.shape == ():  # fixed step storage
            off = attr(s, "offset")
            if off is not None and (not off.is_int() or off.shape != ()):
                self.bad("T1", p + "/step", "offset is not a scalar Integer")
            return
        steps = s[()]
        if v.shape[0] != len(steps):
            self.bad("T3", p, "value has %d rows, step %d" % (v.shape[0], len(steps)))
        if np.any(np.diff(steps) < 0):
            k = int(np.argmax(np.diff(steps) < 0))
            self.bad("T4", p + "/step", "decreases at row %d (%d -> %d)" % (k + 1, steps[k], steps[k + 1]))
        times = None
        if t is not None:
            times = t[()]
            if len(times) != len(steps):
                self.bad("T3", p, "time has %d rows, step %d" % (len(times), len(steps)))
                times = None
            elif np.any(np.diff(times) < 0) or np.any(np.isnan(times)):
                k = int(np.argmax(~(np.diff(times) >= 0)))
                self.bad("T5", p + "/time", "does not increase at row %d (%r -> %r)"
                         % (k + 1, times[k], times[min(k + 1, len(times) - 1)]))
        self.elements.append((p, steps, times))

    def walk_elements(self, g):
        """Time-dependent elements below g (groups holding value, step or time)."""
        for name, o in g.items():
            if isinstance(o, h5py.Group):
                if "value" in o or "step" in o or "time" in o:
                    self.check_element(o)
                elif name != "box":
                    self.walk_elements(o)

    # ---- P ----
    def check_particles(self, f):
        if "particles" not in f:
            return
        for name, g in f["particles"].items():
            p = g.name
            if not isinstance(g, h5py.Group):
                continue
            if "box" not in g or not isinstance(g["box"], h5py.Group):
                self.bad("P1", p, "no box group")
                continue
            box = g["box"]
            a = attr(box, "dimension")
            D = None
            if a is None or not a.is_int() or a.shape != () or int(a.value) < 1:
                self.bad("P2", box.name, "dimension missing or not a scalar Integer >= 1")
            else:
                D = int(a.value)
            a = attr(box, "boundary")
            bnd = None
            if a is None or not a.is_string() or a.is_vlen() or len(a.shape) != 1 or \
                    (D is not None and a.shape[0] != D):
                self.bad("P3", box.name, "boundary missing, not fixed-length strings or not of shape [%s]" % D)
            else:
                bnd = [x.decode() if isinstance(x, bytes) else str(x) for x in a.value]
                for k, b in enumerate(bnd):
                    if b not in ("periodic", "none"):
                        self.bad("P3", box.name, "boundary[%d] = %r is neither 'periodic' nor 'none'" % (k, b))
            e = box.get("edges")
            if e is None:
                if bnd is not None and any(b != "none" for b in bnd):
                    self.bad("P4", box.name, "no edges though a boundary is periodic")
            elif D is not None:
                shape = e.shape if isinstance(e, h5py.Dataset) else \
                    (e["value"].shape[1:] if "value" in e else None)
                ok = isinstance(e, h5py.Dataset) and is_num_ds(e) or isinstance(e, h5py.Group)
                if not ok or shape not in ((D,), (D, D)):
                    self.bad("P4", box.name + "/edges", "shape %s is neither [%d] nor [%d][%d]" % (shape, D, D, D))
            N = None
            for el in ("position", "velocity", "force", "image"):
                o = g.get(el)
                if not isinstance(o, h5py.Group) or not isinstance(o.get("value"), h5py.Dataset):
                    continue
                sh = o["value"].shape
                if len(sh) != 3 or (D is not None and sh[2] != D):
                    self.bad("P5", o.name + "/value", "shape %s is not [variable][N][%s]" % (sh, D))
                    continue
                if N is None:
                    N = sh[1]
                elif sh[1] != N:
                    self.bad("P5", o.name + "/value", "%d particles, position has %d" % (sh[1], N))
            for el in ("mass", "species", "id", "charge"):
                o = g.get(el)
                if o is None:
                    continue
                ds = o if isinstance(o, h5py.Dataset) else o.get("value")
                if not isinstance(ds, h5py.Dataset):
                    self.bad("P6", o.name, "neither a dataset nor an element with value")
                    continue
                n = ds.shape[0] if isinstance(o, h5py.Dataset) and len(ds.shape) == 1 else \
                    (ds.shape[1] if len(ds.shape) == 2 and not isinstance(o, h5py.Dataset) else None)
                if n is None or (N is not None and n != N):
                    self.bad("P6", ds.name, "shape %s is not [N] (N = %s)" % (ds.shape, N))
                cls = dclass(ds)
                if el == "mass" and cls != h5py.h5t.FLOAT:
                    self.bad("P6", ds.name, "mass is not Float")
                if el == "species" and cls not in (h5py.h5t.INTEGER, h5py.h5t.ENUM):
                    self.bad("P6", ds.name, "species is neither Integer nor Enumeration")
                if el == "id":
                    if cls != h5py.h5t.INTEGER:
                        self.bad("P6", ds.name, "id is not Integer")
                    elif isinstance(o, h5py.Dataset) and len(np.unique(ds[()])) != ds.shape[0]:
                        self.bad("P6", ds.name, "id values are not unique")

    # ---- U ----
    def check_units(self, f, datasets):
        m = f.get("h5md/modules/units")
        if m is None:
            return False
        a = attr(m, "system")
        if a is None or not a.is_string() or a.shape != ():
            self.bad("U1", m.name, "no scalar string attribute system")
        for ds in datasets:
            a = attr(ds, "unit")
            if a is None:
                continue
            if not a.is_vlen() or a.shape != () or a.tid.get_cset() != h5py.h5t.CSET_ASCII:
                self.bad("U2", ds.name, "unit is not a scalar variable-length ASCII string")
            for e in unit_errors(a.text()):
                self.bad("U3", ds.name, e)
        return True

    # ---- W ----
    def check_wetgran(self, f, datasets):
        cr = f.get("h5md/creator")
        a = attr(cr, "wetgran_layout") if cr is not None else None
        if a is None or not a.is_int() or a.shape != () or int(a.value) != 2:
            self.bad("W1", "/h5md/creator", "wetgran_layout is %s, not a scalar Integer 2"
                     % ("missing" if a is None else repr(a.value)))
        m = f.get("h5md/modules/units")
        if m is None:
            self.bad("W2", "/h5md/modules/units", "units module not declared")
        else:
            a = attr(m, "system")
            if a is None or a.text() != "wetgran":
                self.bad("W2", m.name, "system is not 'wetgran'")
            for s in WETGRAN_SYMBOLS:
                a = attr(m, s)
                if a is None or not a.is_string() or not a.text().strip():
                    self.bad("W2", m.name, "symbol %s not described" % s)
        for ds in datasets:
            u, d = attr(ds, "unit"), attr(ds, "description")
            if u is None or d is None or not d.is_string() or not d.text().strip():
                self.bad("W3", ds.name, "unit or description missing")
            if u is not None and u.is_string() and not unit_errors(u.text()):
                for s in symbols(u.text()):
                    if s not in WETGRAN_SYMBOLS:
                        self.bad("W2", ds.name, "unit %r uses symbol %r outside d, m, tau" % (u.text(), s))
        meaning = None
        for g in ("particles/all", "observables"):
            a = attr(f[g], "step_meaning") if g in f else None
            if a is None or not a.is_string() or not a.text().strip():
                self.bad("W4", "/" + g, "no step_meaning string")
            else:
                if meaning is not None and a.text() != meaning:
                    self.bad("W4", "/" + g, "step_meaning differs from /particles/all's")
                meaning = meaning or a.text()
        # one clock
        step_time = {}
        time_step = {}
        for p, steps, times in self.elements:
            if meaning is not None:
                d = attr(f[p + "/step"], "description")
                if d is None or d.text() != meaning:
                    self.bad("W4", p + "/step", "description is not the step_meaning")
            if len(steps) > 1 and np.any(np.diff(steps) <= 0):
                self.bad("W5", p + "/step", "steps do not strictly increase")
            if times is None:
                self.bad("W5", p, "no time dataset")
                continue
            for s, t in zip(steps.tolist(), times.tolist()):
                if step_time.setdefault(s, (t, p))[0] != t:
                    self.bad("W5", p, "step %d is t = %r here but t = %r in %s" % (s, t, *step_time[s]))
                    break
                if time_step.setdefault(t, (s, p))[0] != s:
                    self.bad("W5", p, "t = %r is step %d here but step %d in %s" % (t, s, *time_step[t]))
                    break
        if step_time:
            ks = sorted(step_time)
            # a record (wetgran-reduce, group /record) keeps the run's steps of the instants it keeps
            if ks != list(range(len(ks))) and "record" not in f:
                missing = sorted(set(range(ks[-1] + 1)) - set(ks))[:3]
                self.bad("W5", "/", "steps are not 0 .. K-1 (min %d, max %d, unused e.g. %s)" % (ks[0], ks[-1], missing))
            ts = [step_time[k][0] for k in ks]
            if any(b <= a for a, b in zip(ts, ts[1:])):
                self.bad("W5", "/", "times do not increase with step")
        # id, species
        pa = f.get("particles/all")
        if pa is not None:
            # N from the snapshots, or (a record without them) from the per-particle masses
            n = pa["position/value"].shape[1] if "position/value" in pa else \
                (pa["mass"].shape[0] if isinstance(pa.get("mass"), h5py.Dataset) else None)
            i = pa.get("id")
            if not isinstance(i, h5py.Dataset) or not is_int_ds(i) or n is None or \
                    not np.array_equal(i[()], np.arange(n)):
                self.bad("W6", "/particles/all/id", "missing or not 0 .. N-1")
            s = pa.get("species")
            if not isinstance(s, h5py.Dataset) or not is_int_ds(s) or s.shape != (n,):
                self.bad("W6", "/particles/all/species", "missing or not Integer [N]")
        # parameters
        par = f.get("parameters")
        if par is not None:
            for k in par.attrs:
                a = Attr(par, k)
                if a.is_string():
                    try:
                        float(a.text())
                        self.bad("W7", "/parameters", "%s = %r is a number stored as text" % (k, a.text()))
                    except ValueError:
                        pass
            a = attr(par, "seed")
            if a is not None and (not a.is_int() or a.tid.get_sign() != h5py.h5t.SGN_NONE or a.tid.get_size() != 8):
                self.bad("W7", "/parameters", "seed is not an unsigned 64-bit integer")
        # walls
        box = f.get("particles/all/box")
        if box is not None and "boundary" in box.attrs:
            last = box.attrs["boundary"][-1]
            last = last.decode() if isinstance(last, bytes) else str(last)
            walls = f.get("observables/walls")
            if last == "none":
                if attr(box, "z_frame") is None:
                    self.bad("W8", box.name, "no z_frame attribute")
                for w in ("floor", "lid"):
                    g = walls.get(w) if walls is not None else None
                    if g is None or "value" not in g or "time" not in g:
                        self.bad("W8", "/observables/walls/" + w, "missing")
                        continue
                    try:
                        c, A, om, ph = (float(g.attrs[k]) for k in ("mean", "amplitude", "omega", "phase"))
                    except KeyError as e:
                        self.bad("W8", g.name, "no attribute %s" % e)
                        continue
                    t, z = g["time"][()], g["value"][()]
                    want = c + A * np.sin(om * t + ph) if A != 0 and om > 0 else np.full_like(t, c)
                    err = np.abs(z - want)
                    if len(err) and err.max() > 1e-9 * (1 + abs(c) + A):
                        k = int(np.argmax(err))
                        self.bad("W8", g.name, "value %r at t = %r, the wall law gives %r" % (z[k], t[k], want[k]))
            elif walls is not None:
                self.bad("W8", walls.name, "walls in a box periodic along every axis")
        # bridges
        b, pos = f.get("bridges"), f.get("particles/all/position")
        if b is not None and pos is not None:
            for k in ("step", "time"):
                if k not in b or not np.array_equal(b[k][()], pos[k][()]):
                    self.bad("W9", "/bridges/" + k, "missing or not position's %s" % k)
            if "offset" in b and b["offset"].shape != (pos["step"].shape[0] + 1,):
                self.bad("W9", "/bridges/offset", "%s rows, not snapshots + 1" % (b["offset"].shape,))

    def run(self):
        try:
            f = h5py.File(self.path, "r")
        except OSError as e:
            self.out.append("%s: cannot open: %s" % (self.path, e))
            return self.out
        with f:
            datasets = []
            f.visititems(lambda n, o: datasets.append(o) if isinstance(o, h5py.Dataset) else None)
            self.check_h5md(f)
            for g in ("particles", "observables"):
                if g in f:
                    self.walk_elements(f[g])
            self.check_particles(f)
            self.check_units(f, datasets)
            cr = f.get("h5md/creator")
            layout = attr(cr, "wetgran_layout") if cr is not None else None
            layout = int(layout.value) if layout is not None and layout.is_int() else 1
            if self.expect >= 2 or layout >= 2:
                self.check_wetgran(f, datasets)
        return self.out


def main(argv):
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # quiet when piped into head or grep -q
    if "--list" in argv:
        for r, text in RULES:
            print("%s  %s" % (r, text))
        return 0
    expect, files = 0, []
    it = iter(argv)
    for a in it:
        if a == "--expect-layout":
            expect = int(next(it, "0"))
        elif a.startswith("-"):
            print("h5md_check.py: unknown option %s (see --list)" % a, file=sys.stderr)
            return 2
        else:
            files.append(a)
    if not files:
        print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
        return 2
    n = 0
    for p in files:
        out = Checker(p, expect).run()
        for line in out:
            print(line)
        n += len(out)
    return 1 if n else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
