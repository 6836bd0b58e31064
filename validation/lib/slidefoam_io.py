"""Readers for SlideFoam's output contract: runout.dat, summary.json and the
VTK XML PolyData (.vtp, appended raw binary) written by slideDAM and slideMPM."""
import json
import os
import re
import struct

import numpy as np


def read_runout(path):
    """runout.dat as a dict of numpy arrays keyed by column name."""
    names = ["time", "front", "rear", "frontVelocity", "maxVelocity", "maxThickness", "mass", "kineticEnergy"]
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def unresolved(row):
    """True where no cell of a slideFoam run is nearly full of slide at the end (alpha max below 0.9): the slide is
    thinner than its cells on the base (Table 1 Case 4 at H0/10: a layer 0.1-0.2 m thick in cells 0.25 m high), and
    a front read where alpha crosses 0.5 on the base is not the slide's."""
    return row.get("alpha_max", 1.0) < 0.9


def base_cells(row):
    """n of the H0/n cells on the base of a slideFoam run (validation/cfd/table1.json's row)."""
    return row["cells"]*(row.get("refinement") or 1)


# The log each method's failure would be in, in the order its Allrun runs them.
LOGS = {"slideDAM": ["log.slideDAM"], "slideMPM": ["log.slideMPM"],
        "slideFoam": ["log.slideFoamCase", "log.blockMesh", "log.decomposePar", "log.slideFoam", "log.reconstructPar"]}


def failure_reason(case, method):
    """The first error line of the method's logs in a case, or None where it did not run at all."""
    ran = False
    for log in LOGS[method]:
        path = os.path.join(case, log)
        if not os.path.isfile(path):
            continue
        ran = True
        lines = open(path, errors="replace").read().splitlines()
        for i, line in enumerate(lines):
            low = line.lower()
            # Not OpenFOAM's "time step continuity errors" lines: only what stops a run.
            if "fatal" in low or "blow-up" in low or "error:" in low or "failed" in low:
                detail = " ".join(l.strip() for l in lines[i:i + 3] if l.strip())
                return "%s: %s" % (log, detail[:400])
    return "ran, but wrote no summary.json (stopped before the end?)" if ran else None


def read_summary(path):
    with open(path) as f:
        return json.load(f)


def mechanism_at(summary, t):
    """The mechanism a summary's mechanism_history gives at time t (the last write at or before t), or None."""
    for row in reversed(summary.get("mechanism_history", [])):
        if row[0] <= t + 1e-9:
            return row[1]
    return None


def front_at(history, t):
    """Front travel at time t from [[time, front], ...] (linear between the logged times), None after its end."""
    if not history or t > history[-1][0] + 1e-9:
        return None
    for (t0, f0), (t1, f1) in zip(history, history[1:]):
        if t0 <= t <= t1:
            return f0 + (f1 - f0)*(t - t0)/(t1 - t0) if t1 > t0 else f1
    return history[-1][1]


def read_vtp(path):
    """Points (n x 3) and point arrays {name: array} of a SlideFoam .vtp file."""
    with open(path, "rb") as f:
        raw = f.read()
    start = raw.index(b"<AppendedData")
    start = raw.index(b"_", start) + 1
    header = raw[:start].decode("ascii", "replace")
    arrays = {}
    points = None
    for m in re.finditer(r'<DataArray type="(\w+)"(?: Name="([^"]*)")?(?: NumberOfComponents="(\d+)")?'
                         r' format="appended" offset="(\d+)"', header):
        typ, name, nc, off = m.group(1), m.group(2), int(m.group(3) or 1), int(m.group(4))
        nbytes = struct.unpack("<Q", raw[start + off:start + off + 8])[0]
        dtype = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4"}[typ]
        a = np.frombuffer(raw[start + off + 8:start + off + 8 + nbytes], dtype=dtype)
        if nc > 1:
            a = a.reshape(-1, nc)
        if name == "Points":
            points = a
        elif name not in ("connectivity", "offsets"):
            arrays[name] = a
    return points, arrays


def read_pvd(path):
    """[(time, vtp path)] of a .pvd collection."""
    base = os.path.dirname(path)
    with open(path) as f:
        text = f.read()
    return [(float(t), os.path.join(base, p)) for t, p in re.findall(r'timestep="([^"]+)".*?file="([^"]+)"', text)]


def particles_on_planar_base(case, t, theta_deg):
    """slideMPM's particles of the frame written nearest to time t, in the frame of a planar base of angle
    theta_deg: (distance along the base downslope, height above the base line through the origin, velocity along
    the base, the particle arrays)."""
    import math
    frames = read_pvd(os.path.join(case, "postProcessing", "slideMPM", "particles.pvd"))
    pts, arr = read_vtp(min(frames, key=lambda f: abs(f[0] - t))[1])
    c, s = math.cos(math.radians(theta_deg)), math.sin(math.radians(theta_deg))
    return (pts[:, 0]*c - pts[:, 2]*s, pts[:, 0]*s + pts[:, 2]*c,
            arr["velocity"][:, 0]*c - arr["velocity"][:, 2]*s, arr)
