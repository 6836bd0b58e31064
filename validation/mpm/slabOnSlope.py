#!/usr/bin/env python3
"""A benchmark with an analytical answer for the slide-base interface of slideMPM:
a long slab (40 m x 1 m, rho' 600, rate-independent s_uo, no remoulding) on a
3.43 deg no-slip base, released from its geostatic state. With the basal
driving stress R = rho g H sin(theta)/s_uo above 1, a rigid-plastic slab slides
as a plug over a yielded basal layer with

    a = g sin(theta) (1 - 1/R),

and with R < 1 it stays. The script measures the acceleration of the plug
(the top 30 % of the particles within 2 m of the slab's middle) between 2 s and
4 s, after the release has rung out, for several cells, transfers and both
ways the grid can meet the base (fitted: the base a knot line of the
B-splines; levelSet: the base cutting the grid), and writes slabOnSlope.md
beside itself.

Usage: validation/mpm/slabOnSlope.py [--cells 5,10,20] [--work DIR]   (after ./Allwmake)"""
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


def plug_velocity(case, t):
    s, n, u, _ = particles_on_planar_base(case, t, THETA)
    mid = 0.5*(s.min() + s.max())
    near = np.abs(s - mid) < 2.0
    plug = near & (n - n[near].min() > 0.7*(n[near].max() - n[near].min()))
    return float(u[plug].mean())


def run(work, R, cells, transfer, base):
    s_uo = RHO*G*H*math.sin(math.radians(THETA))/R
    name = "R%.2f_h%d_%s_%s" % (R, cells, transfer, base)
    case = make_case(os.path.join(top, "tutorials", "table1", "case01"), work, name,
                     scene={"length": 40, "height": H, "s_uo": s_uo, "eta": 0},
                     control={"endTime": 4, "writeInterval": 0.5, "stopAtRest": "no"},
                     dicts={"system/mpmDict": "setting fast;\ncellsPerHeight %d;\nparticlesPerCell 2;\n"
                                              "transfer %s;\nbaseBoundary %s;\nwriteState no;\nprogressInterval 30;\n"
                                              % (cells, transfer, base)})
    summary, _ = run_method("slideMPM", case)
    u2, u4 = plug_velocity(case, 2.0), plug_velocity(case, 4.0)
    return {"R": R, "cells": cells, "transfer": transfer, "base": base, "u2": u2, "u4": u4, "a": (u4 - u2)/2.0,
            "wall": summary["wall_time_s"]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", default="5,10,20")
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="slabOnSlope_")
    cells = [int(c) for c in args.cells.split(",")]
    runs = ([(1.5, c, "apic", "fitted") for c in cells] + [(1.5, c, "apic", "levelSet") for c in cells]
            + [(1.5, 10, "quadratic", "fitted"), (1.5, 10, "pic", "fitted"), (0.8, 10, "apic", "fitted")])
    gs = G*math.sin(math.radians(THETA))
    rows = []
    for R, c, tr, base in runs:
        r = run(work, R, c, tr, base)
        exact = gs*(1.0 - 1.0/R) if R > 1.0 else 0.0
        r["exact"] = exact
        rows.append(r)
        print("R %.2f  cell H/%-3d %-9s %-8s  plug velocity %.3f -> %.3f m/s  a = %.4f m/s2  (rigid-plastic %.4f)  %.1f s"
              % (R, c, tr, base, r["u2"], r["u4"], r["a"], exact, r["wall"]), flush=True)
    with open(os.path.join(here, "slabOnSlope.md"), "w") as f:
        f.write("# Slab on a no-slip slope (written by slabOnSlope.py)\n\n"
                "40 m x 1 m slab, rho' 600 kg/m3, 3.43 deg, rate-independent s_uo = rho g H sin(theta)/R, "
                "2 x 2 particles per cell. Plug acceleration between 2 s and 4 s against the rigid-plastic "
                "a = g sin(theta) (1 - 1/R).\n\n"
                "| R | cell | transfer | base | plug velocity at 2 s, 4 s [m/s] | a [m/s2] | rigid-plastic | wall [s] |\n"
                "| --- | --- | --- | --- | --- | --- | --- | --- |\n")
        for r in rows:
            f.write("| %.2f | H/%d | %s | %s | %.3f, %.3f | %.4f | %.4f | %.1f |\n"
                    % (r["R"], r["cells"], r["transfer"].upper(), r["base"], r["u2"], r["u4"], r["a"], r["exact"], r["wall"]))


if __name__ == "__main__":
    main()
