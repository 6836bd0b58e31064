#!/usr/bin/python3
"""Profiles and morphologies at the paper's snapshot times (its Figs. 7-9): Table 1
Case 2 at 10 s, Case 9 at 20 s, Case 11 at 10 s and 30 s. Runs slideDAM (fast,
800 columns) and slideMPM (cell H0/10, the tutorials' 4x4 particles; Case 11 at
H0/40 with 2x2, the coarsest cell at which its shear bands part the slide into
horsts and grabens, ../mpm/shearBand.md) with field output to the last snapshot
time, reads their .pvd series and writes snapshots.png and snapshots.json here.
~20 min on 2 cores.

slideFoam is not drawn: the paper gives CFD for Cases 1-3 only, and these
snapshots (Cases 2, 9, 11) compare the DAM's profile with the MPM's particles.
"""
import json
import math
import os
import re
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
from cfdcase import make_case  # noqa: E402
from runner import TOP, run_method  # noqa: E402
from slidefoam_io import read_pvd, read_summary, read_vtp  # noqa: E402
sys.path.insert(0, os.path.join(HERE, "..", "mpm"))
from table1 import FINE  # noqa: E402

SNAPSHOTS = [(2, 10.0), (9, 20.0), (11, 10.0), (11, 30.0)]


def along_slope(points, angle_deg):
    """(s, h): distance along a planar base through the origin and height above it."""
    a = math.radians(angle_deg)
    x, z = points[:, 0], points[:, 2]
    return x*math.cos(a) - z*math.sin(a), x*math.sin(a) + z*math.cos(a)


def scene_value(case_dir, key):
    text = open(os.path.join(case_dir, "constant", "sceneProperties")).read()
    return float(re.search(r"^\s*%s\s+([0-9.eE+-]+);" % key, text, re.M).group(1))


def base_angle(case_dir):
    return scene_value(case_dir, "angle")


def mpm_resolution(case):
    """slideMPM's (cells per H0, particles per cell direction): the tutorials' H0/10, 4x4, or the finer cell
    that the case's mechanism needs (Table 1's FINE)."""
    return FINE.get(case, (10, 4))


def mpm_label(case):
    cells, ppc = mpm_resolution(case)
    return "H0/%d, %dx%d" % (cells, ppc, ppc)


def run(case, end, work):
    d = make_case(os.path.join(TOP, "tutorials", "table1", "case%02d" % case), work, "case%02d" % case,
                  control={"endTime": "%g" % end, "stopAtRest": "no", "writeInterval": 1},
                  dam={"setting": "fast", "columns": 800, "writeFields": "yes"},
                  mpm={"setting": "fast", "cellsPerHeight": mpm_resolution(case)[0],
                       "particlesPerCell": mpm_resolution(case)[1], "writeFields": "yes", "progressInterval": 30})
    for app in ("slideDAM", "slideMPM"):
        run_method(app, d)
    return d


def at_time(pvd, t):
    series = read_pvd(pvd)
    return min(series, key=lambda e: abs(e[0] - t))


def main():
    work = tempfile.mkdtemp(prefix="slideFoam_snapshots_")
    ends = {}
    for c, t in SNAPSHOTS:
        ends[c] = max(ends.get(c, 0.0), t)
    dirs = {}
    for c, end in ends.items():
        print("running Case %d to %g s" % (c, end), flush=True)
        dirs[c] = run(c, end, work)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(SNAPSHOTS), 1, figsize=(11, 2.6*len(SNAPSHOTS)))
    record = []
    for ax, (c, t) in zip(axes, SNAPSHOTS):
        d = dirs[c]
        angle = base_angle(d)
        td, dam_file = at_time(os.path.join(d, "postProcessing", "slideDAM", "profile.pvd"), t)
        tm, mpm_file = at_time(os.path.join(d, "postProcessing", "slideMPM", "particles.pvd"), t)
        _, dam = read_vtp(dam_file)
        pts, mpm = read_vtp(mpm_file)
        s, h = along_slope(pts, angle)
        xi = mpm["xi"]
        # A remoulding slide's xi runs to hundreds where it has flowed: the colours stop at xi95, so that
        # intact and remoulded material stand apart.
        xi95 = scene_value(d, "xi95") if scene_value(d, "deltaRem") < 1.0 else None
        sc = ax.scatter(s, h, c=xi, s=1.5, cmap="viridis", vmin=0.0,
                        vmax=xi95 if xi95 else max(1.0, float(xi.max())))
        ax.plot(dam["s"], dam["thickness"], color="tab:red", lw=1.2, label="slideDAM surface")
        ax.set_title("Case %d at t = %g s (slideDAM %g s, slideMPM %g s at %s)" % (c, t, td, tm, mpm_label(c)),
                     fontsize=9)
        ax.set_ylabel("height [m]")
        ax.legend(fontsize=7, loc="upper right")
        fig.colorbar(sc, ax=ax, label="MPM xi" + (" (to xi95)" if xi95 else ""), pad=0.01)
        mech = [m for tt, m in read_summary(os.path.join(d, "postProcessing", "slideMPM",
                                                          "summary.json"))["mechanism_history"] if abs(tt - t) < 1e-6]
        record.append({"case": c, "time": t,
                       "dam": {"front_s": float(dam["s"].max()), "maxThickness": float(dam["thickness"].max()),
                               "frontVelocity": float(dam["U"][-1])},
                       "mpm": {"front_s": float(s.max()), "maxThickness": float(h.max()),
                               "maxVelocity": float(abs(mpm["velocity"][:, 0]).max()), "maxXi": float(xi.max()),
                               "mechanism": mech[0] if mech else None}})
    axes[-1].set_xlabel("distance along the base [m]")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "snapshots.png"), dpi=100)

    lines = ["Regenerated by `snapshots/snapshots.py` (slideDAM fast, 800 columns; slideMPM H0/10, 4x4, Case 11 "
             "H0/40, 2x2, the coarsest cell at which its shear bands part the slide (`mpm/shearBand.md`); particles "
             "coloured by their accumulated plastic shear strain xi, up to xi95 where the slide remoulds; the DAM's surface "
             "in red; vertical scale "
             "exaggerated).", "", "| case | t [s] | DAM front s [m] | MPM front s [m] | DAM max thickness [m] | "
             "MPM max height [m] | MPM max xi | MPM mechanism at t | MPM cell |", "|---|---|---|---|---|---|---|---|---|"]
    for r in record:
        lines.append("| %d | %g | %.1f | %.1f | %.2f | %.2f | %.1f | %s | %s |" % (
            r["case"], r["time"], r["dam"]["front_s"], r["mpm"]["front_s"], r["dam"]["maxThickness"],
            r["mpm"]["maxThickness"], r["mpm"]["maxXi"], r["mpm"]["mechanism"], mpm_label(r["case"])))
    with open(os.path.join(HERE, "snapshots.json"), "w") as f:
        json.dump({"summary": "\n".join(lines), "snapshots": record}, f, indent=1)
    shutil.rmtree(work, ignore_errors=True)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
