#!/usr/bin/env python3
"""A benchmark with an analytical answer for the shear profile of slideMPM: a
long Bingham layer (100 m x 1 m, rho' 600, Eq. 1 with n = 1: s_u = s_uo +
mu gdot, mu = s_uo eta/gdot_ref, no remoulding) on a 3.43 deg no-slip base,
released from its geostatic state. Far from its ends the layer is an infinite
one, whose steady flow is the Bingham open-channel profile

    u(z) = (rho g S/mu) (Y z - z^2/2)  for z < Y = H - s_uo/(rho g S),
    u    = rho g S Y^2/(2 mu)           above Y (the plug),

with the shear stress rho g S (H - z), zero at the free surface. The script
reads the particles within 2 m of the layer's middle every 0.5 s from 4 s
to 10 s (the elastic plug rings about its steady state with a period of about
a second), averages 4-7 s and 7-10 s (whether it has settled: the profile
settles in a few rho Y^2/mu = 1.5 s; after about 10 s the collapse of the
layer's ends has thinned its middle), bins them by height, and compares
velocity and shear stress with the profile, for several cells and both ways
the grid can meet the base (fitted: the base a knot line of the B-splines;
levelSet: the base cutting the grid), with APIC and, on the fitted base, the
quadratic transfer; it writes binghamLayer.md and binghamLayer.png beside
itself.

Usage: validation/mpm/binghamLayer.py [--cells 3,5,10] [--configs fitted/apic,levelSet/apic,fitted/quadratic]
       [--work DIR]   (after ./Allwmake)"""
import argparse
import math
import os
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import make_case  # noqa: E402
from runner import run_method  # noqa: E402
from slidefoam_io import particles_on_planar_base  # noqa: E402

import numpy as np  # noqa: E402

THETA = 3.43
RHO = 600.0
G = 9.81
H = 1.0
LENGTH = 100.0
YIELD_DEPTH = 0.5                 # Y: the sheared layer, half the depth
MU = 100.0                        # plastic viscosity [Pa s]
S = math.sin(math.radians(THETA))
S_UO = RHO*G*S*(H - YIELD_DEPTH)
GDOT_REF = 1.0
T_EARLY, T_LATE = 7.0, 10.0       # the averaging windows: [4, 7] and [7, 10] s
ETA = MU*GDOT_REF/S_UO


def exact_velocity(z):
    y = np.minimum(z, YIELD_DEPTH)
    return RHO*G*S/MU*(YIELD_DEPTH*y - 0.5*y*y)


def profile(case, t, cell):
    s, n, u, arr = particles_on_planar_base(case, t, THETA)
    tau = arr["sigma_xz"]
    mid = 0.5*(s.min() + s.max())
    near = np.abs(s - mid) < 2.0
    z = n[near] - n[near].min()
    u, tau = u[near], tau[near]
    # Particles sit at the quarter points of their cells (2 x 2): bins of half a cell hold one row each.
    rows = []
    width = 0.5*cell
    for k in range(int(math.ceil(H/width))):
        m = (z >= k*width) & (z < (k + 1)*width)
        if not m.any():
            continue
        zc = float(z[m].mean())
        rows.append((zc, float(u[m].mean()), float(tau[m].mean())))
    return rows


def mean_profile(case, t0, t1, cell):
    """The profile averaged over the frames written in [t0, t1], row by row."""
    frames = [profile(case, t, cell) for t in np.arange(t0, t1 + 1e-9, 0.5)]
    n = min(len(f) for f in frames)
    return [tuple(float(np.mean([f[k][c] for f in frames])) for c in range(3)) for k in range(n)]


def run(work, cells, base, app="slideMPM", transfer="apic"):
    name = "bingham_h%d_%s_%s" % (cells, base, transfer)
    case = make_case(os.path.join(top, "tutorials", "table1", "case01"), work, name,
                     scene={"length": LENGTH, "height": H, "s_uo": S_UO, "eta": ETA, "n": 1, "gdotRef": GDOT_REF},
                     control={"endTime": T_LATE, "writeInterval": 0.5, "stopAtRest": "no"},
                     dicts={"system/mpmDict": "setting fast;\ncellsPerHeight %d;\nparticlesPerCell 2;\n"
                                              "baseBoundary %s;\ntransfer %s;\nwriteState no;\nprogressInterval 30;\n"
                                              % (cells, base, transfer)})
    summary, _ = run_method(app, case)
    cell = H/cells
    return {"cells": cells, "base": base + ", " + transfer, "early": mean_profile(case, T_EARLY - 3.0, T_EARLY, cell),
            "late": mean_profile(case, T_EARLY, T_LATE, cell),
            "wall": summary["wall_time_s"], "particles": summary["problem_size"]}


def compare(r):
    """Adds the surface velocities, the RMS profile error and the top row's shear stress to a run's result."""
    z = np.array([p[0] for p in r["late"]])
    r["surfaceLate"] = r["late"][-1][1]
    r["surfaceEarly"] = r["early"][-1][1]
    r["rms"] = float(np.sqrt(np.mean((np.array([p[1] for p in r["late"]]) - exact_velocity(z))**2)))
    r["tauTop"] = r["late"][-1][2]
    r["tauTopExact"] = RHO*G*S*(H - r["late"][-1][0])
    return r


PLUG_VELOCITY = float(exact_velocity(np.array(H)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", default="3,5,10")
    ap.add_argument("--configs", default="fitted/apic,levelSet/apic,fitted/quadratic")
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="binghamLayer_")
    plug = PLUG_VELOCITY
    results = []
    for c, base, tr in ((int(v), *b.split("/")) for v in args.cells.split(",") for b in args.configs.split(",")):
        r = compare(run(work, c, base, transfer=tr))
        results.append(r)
        print("H/%d, %s base, %s: surface velocity %.3f (to %g s), %.3f (to %g s) m/s against %.3f; RMS profile error %.3f m/s; "
              "shear stress in the top row %.1f Pa (exact %.1f); %.1f s"
              % (c, base, tr, r["surfaceEarly"], T_EARLY, r["surfaceLate"], T_LATE, plug, r["rms"], r["tauTop"], r["tauTopExact"], r["wall"]),
              flush=True)

    lines = ["# A Bingham layer on a no-slip slope (written by binghamLayer.py)", "",
             "%g m x %g m layer, rho' %g kg/m3, %.2f deg, s_uo %.1f Pa, plastic viscosity %g Pa s (eta %.4f, n 1, "
             "gdot_ref 1/s), 2 x 2 particles per cell, released from its geostatic state. Particles within 2 m of "
             "the middle, binned by height, against the steady Bingham profile (sheared layer Y = %.2f m under a "
             "plug at %.3f m/s, shear stress rho g S (H - z))."
             % (LENGTH, H, RHO, THETA, S_UO, MU, ETA, YIELD_DEPTH, plug), "",
             "| cell | base, transfer | particles | surface velocity, mean over %g-%g s / %g-%g s [m/s] | against the plug | RMS profile error, %g-%g s "
             "[m/s] | shear stress, top row [Pa] (exact) | wall [s] |" % (T_EARLY - 3, T_EARLY, T_EARLY, T_LATE, T_EARLY, T_LATE),
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in results:
        lines.append("| H/%d | %s | %d | %.3f / %.3f | %+.1f %% | %.3f | %.1f (%.1f) | %.1f |"
                     % (r["cells"], r["base"], r["particles"], r["surfaceEarly"], r["surfaceLate"], 100*(r["surfaceLate"]/plug - 1), r["rms"],
                        r["tauTop"], r["tauTopExact"], r["wall"]))
    lines += ["", "Profiles, mean over %g-%g s (height of the row [m]: velocity [m/s], shear stress [Pa]; exact in brackets):" % (T_EARLY, T_LATE), ""]
    for r in results:
        lines.append("- H/%d, %s: " % (r["cells"], r["base"]) + "; ".join(
            "%.3f: %.3f (%.3f), %.0f (%.0f)" % (z, u, exact_velocity(z), tau, RHO*G*S*(H - z))
            for z, u, tau in r["late"]))
    with open(os.path.join(here, "binghamLayer.md"), "w") as f:
        f.write("\n".join(lines) + "\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 4), sharey=True)
    zz = np.linspace(0.0, H, 200)
    a1.plot(exact_velocity(zz), zz, "k-", label="steady Bingham profile")
    a2.plot(RHO*G*S*(H - zz), zz, "k-", label="rho g S (H - z)")
    a2.axvline(S_UO, color="0.6", ls=":", label="s_uo")
    for r in results:
        z = [p[0] for p in r["late"]]
        style = {"fitted, apic": "o-", "levelSet, apic": "x--"}.get(r["base"], "s:")
        a1.plot([p[1] for p in r["late"]], z, style, ms=3, label="H/%d, %s, %g-%g s" % (r["cells"], r["base"], T_EARLY, T_LATE))
        a2.plot([p[2] for p in r["late"]], z, style, ms=3, label="H/%d, %s" % (r["cells"], r["base"]))
    a1.set_xlabel("velocity along the slope [m/s]")
    a1.set_ylabel("height above the base [m]")
    a2.set_xlabel("shear stress sigma_xz [Pa]")
    a1.legend(fontsize=8)
    a2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "binghamLayer.png"), dpi=110)


if __name__ == "__main__":
    main()
