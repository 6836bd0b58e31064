#!/usr/bin/env python3
"""Where a weak Table 1 slide's runout picks up its dependence on slideMPM's cell: its centre of mass or its front.

Why: Case 2 (s_uo 500 Pa, eta 0.45, n 0.23) stops at 61.5, 57.7 and 55.4 m with H0/10, H0/20 and H0/40 cells and
4x4 particles (table1.json), and its fronts part from 8 to 15 s, as the slide thins and slows (README, open
problem 5). Session 60's steady layers (rateLayer.md) found the base right within about 2 % of tau_b from 4 cells
through the layer. A runout is the front's travel, which is the centre of mass's travel plus how far the slide
spreads ahead of it; this script says which of the two the cells change, and where along the slide.

The case is run to --end-time with its particles written every second. At each even second it measures, from the
particles, the travel of the slide's centre of mass, of its front (the foremost particle) and of the front of 99 % of
its mass, the rear's (1 % of the mass behind it) and the centre of mass's speed along the base. At --times it cuts
the front --zone metres into 4 m bins and gives each bin's thickness (its mass over rho' and the bin's length) and
plug speed (the mean velocity along the base of its particles in the upper 40 % of that thickness), and the 95th
percentile of its particles' plastic shear strain rate (the rate of its most sheared particles, at the base).

Particle stresses near the base are not used: read from the particles in the lowest 6, 12, 25 or 40 % of the local
thickness, the basal shear stress of the same bin changed by 5-10 % between those choices (session 61), more than
the cells change it. Velocities and masses do not have that problem.

--mpm KEY=VALUE and --scene KEY=VALUE (repeatable) set mpmDict and sceneProperties entries of a variant, --tag
names it. Writes frontZone.md and frontZone.json
beside itself. --import analyses finished run directories case<NN>_h<cells>_p<ppc>_fields[<tag>] instead of running.

Usage: validation/mpm/frontZone.py [--case 2] [--cells 10,20,40] [--ppc 4] [--end-time 20] [--times 8,10,12]
       [--zone 20] [--mpm KEY=VALUE ...] [--scene KEY=VALUE ...] [--tag NAME] [--keep] [--stored] [--import DIR ...]
(after ./Allwmake; on 2 cores Case 2 to 20 s takes about 20 s at H0/10 and 2.5 minutes at H0/20; to 12 s about
8 minutes at H0/40 and 26 minutes at H0/60)"""
import argparse
import json
import os
import re
import shutil
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from table1 import run_case  # noqa: E402
from cfdcase import get_entry  # noqa: E402
from slidefoam_io import particles_on_planar_base, read_pvd  # noqa: E402

import numpy as np  # noqa: E402

BIN = 4.0       # [m] along the base
PLUG = 0.6      # particles above this share of the bin's thickness give its plug speed
TAIL = 0.01     # share of the mass behind the rear and ahead of the front of 99 %


def scene_of(case_dir):
    """The planar base's angle [deg] and the slide's density of a run directory's scene."""
    path = os.path.join(case_dir, "constant", "sceneProperties")
    angle, density = get_entry(path, "angle"), get_entry(path, "density")
    polyline = re.search(r"^\s*profile\s+polyline\s*;", open(path).read(), re.M)
    if angle is None or density is None or polyline:
        raise SystemExit("frontZone.py: %s: a planar base's angle and the slide's density are needed" % path)
    return angle, density


def mass_front(s, m, share):
    """Where `share` of the mass m lies behind, along the base (particle positions s)."""
    order = np.argsort(s)
    cum = np.cumsum(m[order])/m.sum()
    return float(s[order][min(np.searchsorted(cum, share), len(s) - 1)])


def frame(case_dir, t, angle):
    """Centre of mass, its speed, front, front of 99 % of the mass and rear (along the base, m) at the frame nearest t,
    and the particles."""
    s, z, u, arr = particles_on_planar_base(case_dir, t, angle)
    m = arr["mass"]
    M = m.sum()
    return {"com": float((m*s).sum()/M), "comSpeed": float((m*u).sum()/M), "front": float(s.max()),
            "front99": mass_front(s, m, 1.0 - TAIL),
            "rear": mass_front(s, m, TAIL)}, (s, z, u, m, arr["plasticShearStrainRate"])


def zone(particles, zone_length, density):
    """[(distance of the bin's middle behind the front, thickness, plug speed, the 95th percentile of its particles'
    plastic shear strain rate)] over the front zone_length m."""
    s, z, u, m, rate = particles
    front = s.max()
    rows = []
    for lo in np.arange(front - BIN, front - zone_length - 1e-9, -BIN):
        k = (s >= lo) & (s < lo + BIN)
        if k.sum() < 8:
            continue
        h = float(m[k].sum()/(density*BIN))
        top = z[k] > PLUG*h
        if top.any():
            rows.append((float(front - (lo + 0.5*BIN)), h, float(u[k][top].mean()),
                         float(np.percentile(rate[k], 95))))
    return rows


def analyse(d, case, cells, ppc, tag, times, zone_length):
    frames = read_pvd(os.path.join(d, "postProcessing", "slideMPM", "particles.pvd"))
    written = sorted({round(t) for t, _ in frames if abs(t - round(t)) < 1e-6 and round(t) % 2 == 0})
    angle, density = scene_of(d)
    start, _ = frame(d, 0.0, angle)
    history, bins = [], {}
    for t in written:
        f, particles = frame(d, t, angle)
        history.append([t] + [f[k] - start[k] if k != "comSpeed" else f[k]
                              for k in ("com", "comSpeed", "front", "front99", "rear")])
        if any(abs(t - x) < 1e-6 for x in times):
            bins["%g" % t] = zone(particles, zone_length, density)
    return {"case": case, "cells": cells, "ppc": ppc, "tag": tag, "history": history, "bins": bins}


def write_md(store):
    runs = sorted(store["runs"], key=lambda r: (r["case"], r["tag"], r["ppc"], r["cells"]))
    name = lambda r: "H0/%d %dx%d%s" % (r["cells"], r["ppc"], r["ppc"], (" " + r["tag"]) if r["tag"] else "")
    lines = ["# Where a weak slide's runout depends on slideMPM's cell: its centre of mass or its front", "",
             "Regenerated by `validation/mpm/frontZone.py` (its docstring says what it measures). Travel along the "
             "base since release [m]: the centre of mass (com), the foremost particle (front), the front of 99 % of "
             "the mass (f99) and the rear of 99 % (rear, negative: upslope); spread = front - com."]
    for case in sorted({r["case"] for r in runs}):
        rs = [r for r in runs if r["case"] == case]
        times = sorted({h[0] for r in rs for h in r["history"]})
        lines += ["", "**Case %d**" % case, "",
                  "| t [s] | " + " | ".join("%s: com / com speed [m/s] / front / f99 / rear / spread" % name(r)
                                            for r in rs) + " |",
                  "|---|" + "---|"*len(rs)]
        for t in times:
            cells = []
            for r in rs:
                h = [x for x in r["history"] if x[0] == t]
                cells.append("%.2f / %.2f / %.2f / %.2f / %.2f / %.2f" % (h[0][1], h[0][2], h[0][3], h[0][4],
                                                                          h[0][5], h[0][3] - h[0][1])
                             if h else "-")
            lines.append("| %g | %s |" % (t, " | ".join(cells)))
        for t in sorted({t for r in rs for t in r["bins"]}, key=float):
            lines += ["", "Case %d at %s s, the front's bins: thickness [m] / plug speed [m/s] / the 95th percentile of "
                      "the plastic shear strain rate [1/s] (not stored for the first variants' runs)" % (case, t), "",
                      "| behind the front [m] | " + " | ".join(name(r) for r in rs) + " |", "|---|" + "---|"*len(rs)]
            dist = sorted({b[0] for r in rs for b in r["bins"].get(t, [])})
            for x in dist:
                row = []
                for r in rs:
                    b = [b for b in r["bins"].get(t, []) if b[0] == x]
                    row.append(("%.2f / %.2f / " % (b[0][1], b[0][2]) + ("%.1f" % b[0][3] if len(b[0]) > 3 else "-"))
                               if b else "-")
                lines.append("| %g | %s |" % (x, " | ".join(row)))
    with open(os.path.join(here, "frontZone.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % os.path.join(here, "frontZone.md"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", type=int, default=2)
    ap.add_argument("--cells", default="10,20,40")
    ap.add_argument("--ppc", type=int, default=4)
    ap.add_argument("--end-time", type=float, default=20.0)
    ap.add_argument("--times", default="8,10,12")
    ap.add_argument("--zone", type=float, default=20.0)
    ap.add_argument("--mpm", action="append", default=[], help="KEY=VALUE of the variant's mpmDict")
    ap.add_argument("--scene", action="append", default=[], help="KEY=VALUE of the variant's sceneProperties")
    ap.add_argument("--tag", default="")
    ap.add_argument("--keep", action="store_true", help="keep the run directories (fields: 1.3 GB at H0/40)")
    ap.add_argument("--stored", action="store_true")
    ap.add_argument("--import", dest="imports", nargs="*", default=[])
    args = ap.parse_args()
    times = [float(x) for x in args.times.split(",")]
    def entries(option, pairs):
        out = {}
        for kv in pairs:
            if "=" not in kv:
                raise SystemExit("frontZone.py: --%s %s: not KEY=VALUE" % (option, kv))
            k, v = kv.split("=", 1)
            out[k] = v
        return out
    numerics = dict(writeFields="yes", **entries("mpm", args.mpm))
    scene = entries("scene", args.scene)
    if (args.mpm or args.scene) and not args.tag:
        raise SystemExit("frontZone.py: --mpm and --scene need --tag, the variant's name in frontZone.md")
    path = os.path.join(here, "frontZone.json")
    store = json.load(open(path)) if os.path.isfile(path) else {"runs": []}
    if not args.stored:
        new = []
        if args.imports:
            for d in args.imports:
                m = re.match(r"case(\d+)_h(\d+)_p(\d+)_fields(\w*)$", os.path.basename(os.path.normpath(d)))
                if not m:
                    raise SystemExit("frontZone.py: --import %s: not a run directory "
                                     "case<NN>_h<cells>_p<ppc>_fields[<tag>]" % d)
                new.append(analyse(d, int(m.group(1)), int(m.group(2)), int(m.group(3)), m.group(4), times,
                                   args.zone))
        else:
            work = tempfile.mkdtemp(prefix="slideMPM_frontZone_")
            for n in [int(x) for x in args.cells.split(",")]:
                res = run_case(args.case, n, args.ppc, work, scene=scene, numerics=numerics,
                               tag="_fields" + args.tag, end_time=args.end_time)
                if "failed" in res:
                    raise SystemExit("frontZone.py: case %d H0/%d failed:\n%s" % (args.case, n, res["failed"]))
                d = os.path.join(work, "case%02d_h%d_p%d_fields%s" % (args.case, n, args.ppc, args.tag))
                new.append(analyse(d, args.case, n, args.ppc, args.tag, times, args.zone))
                print("case %d H0/%d%s: analysed %s" % (args.case, n, args.tag, d), flush=True)
                if not args.keep:
                    shutil.rmtree(d, ignore_errors=True)
            if not args.keep:
                shutil.rmtree(work, ignore_errors=True)
        keys = {(r["case"], r["cells"], r["ppc"], r["tag"]) for r in new}
        store["runs"] = [r for r in store["runs"] if (r["case"], r["cells"], r["ppc"], r["tag"]) not in keys] + new
        with open(path, "w") as f:
            json.dump(store, f, indent=1)
    write_md(store)


if __name__ == "__main__":
    main()
