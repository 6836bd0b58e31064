#!/usr/bin/python3
"""The DAM applicability map, rebuilt from runs (the paper's conclusion: the DAM is
feasible for s_uo >= 0.05 kPa and S_t <= 3 with eta = 0.45, n = 0.23).

Runs slideDAM (fast, 800 columns) and slideMPM (cell H0/n, the tutorials' 4x4 particles) on Table 1
Case 13's slide, which is Case 2's with remoulding (40 x 5 m, rho' 600, 3.43 deg no-slip,
eta 0.45, n 0.23, gdot_ref 0.06, xi95 10) over a grid of strengths s_uo and sensitivities S_t = 1/delta_rem,
takes slideMPM as the reference (it resolves the shear band the DAM averages
away), and marks where the two runouts agree within the tolerance. Writes map.md,
map.png and map.json here, and etc/damApplicability, which slideDAM reads to warn
when a scene lies outside the region where it agreed.

Usage: validation/applicability/map.py [--suo 150,500,2000] [--st 1,3,10] [--cells 5] [--ppc 4]
                                       [--tolerance 0.15] [--end 300] [--check S_UO:ST,...]
                                       [--check-cells 10,20] [--stored]
(about 40 min on 2 cores with the defaults: slideMPM at H0/5 with 4x4 particles, the
front compared at rest or at 300 s; 2x2 takes a quarter of it, H0/10 about 8 times longer)
"""
import argparse
import json
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
from cfdcase import make_case  # noqa: E402
from runner import TOP, run_method  # noqa: E402


def run(s_uo, st, cells, ppc, end, work):
    # Case 13 is Case 2's slide with remoulding (xi95 10): only s_uo and delta_rem change.
    d = make_case(os.path.join(TOP, "tutorials", "table1", "case13"), work, "suo%g_st%g" % (s_uo, st),
                  scene={"s_uo": "%g" % s_uo, "deltaRem": "%g" % (1.0/st)},
                  # Both methods are compared at the same time: at rest, or the front at endTime.
                  control={"endTime": "%g" % end, "writeInterval": 5, "purgeWrite": 1},
                  # The tutorial's method dictionaries (Case 13's mpmDict counts xi per H0/60 shear band) at
                  # this resolution.
                  dam={"setting": "fast", "columns": 800, "writeFields": "no"},
                  mpm={"setting": "fast", "cellsPerHeight": cells, "particlesPerCell": ppc, "writeFields": "no",
                       "progressInterval": 60})
    out = {}
    for app in ("slideDAM", "slideMPM"):
        s = run_method(app, d)[0]
        out[app] = {"runout": s["runout_m"], "atRest": s["at_rest"], "end": s["end_time_s"],
                    "mechanism": s["mechanism"], "wall": s["wall_time_s"]}
    return out


def verdict(point, tolerance):
    """The DAM's runout against the finest slideMPM run at this point: the grid's, or a finer check's."""
    mpm, label = point["mpm"], None
    for c in sorted(point.get("checks", []), key=lambda c: c["cells"]):
        mpm, label = c["mpm"], "H0/%d" % c["cells"]
    diff = (point["dam"]["runout"] - mpm["runout"])/mpm["runout"] if mpm["runout"] > 0 else float("inf")
    return mpm, label, diff, abs(diff) <= tolerance


def parse_points(text):
    return [tuple(float(v) for v in item.split(":")) for item in text.split(",") if item]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--suo", default="150,500,2000", help="s_uo values [Pa]")
    ap.add_argument("--st", default="1,3,10", help="sensitivities S_t")
    ap.add_argument("--cells", type=int, default=5)
    ap.add_argument("--ppc", type=int, default=4, help="particles per cell and direction (the tutorials' 4)")
    ap.add_argument("--tolerance", type=float, default=0.15)
    ap.add_argument("--end", type=float, default=300.0, help="end time [s] (runs stop earlier at rest)")
    ap.add_argument("--check", default="", help="grid points S_UO:ST[,...] whose slideMPM reference is rerun at the "
                                                "finer cells of --check-cells (the verdict then takes the finest)")
    ap.add_argument("--check-cells", default="10,20", help="cells per H0 of the checks")
    ap.add_argument("--stored", action="store_true",
                    help="keep the grid of map.json (run only the --check points not stored) and rewrite the outputs")
    args = ap.parse_args()
    suos = [float(x) for x in args.suo.split(",")]
    sts = [float(x) for x in args.st.split(",")]
    checkCells = [int(x) for x in args.check_cells.split(",") if x]
    work = tempfile.mkdtemp(prefix="slideFoam_map_")
    if args.stored:
        stored = json.load(open(os.path.join(HERE, "map.json")))
        grid = stored["grid"]
        args.cells, args.ppc, args.tolerance = stored["cells"], stored["ppc"], stored["tolerance"]
        args.end = stored.get("end", args.end)
        suos = sorted({g["s_uo"] for g in grid})
        sts = sorted({g["S_t"] for g in grid})
    else:
        grid = []
        for s_uo in suos:
            for st in sts:
                r = run(s_uo, st, args.cells, args.ppc, args.end, work)
                grid.append({"s_uo": s_uo, "S_t": st, "dam": r["slideDAM"], "mpm": r["slideMPM"]})
                print("s_uo %g Pa, S_t %g: DAM %.1f m, MPM %.1f m" % (s_uo, st, r["slideDAM"]["runout"],
                                                                      r["slideMPM"]["runout"]), flush=True)
    # The reference's own convergence where the verdict matters: slideMPM again at finer cells (same particles
    # per cell, same per-band remoulding); slideDAM does not depend on them.
    for s_uo, st in parse_points(args.check):
        point = [g for g in grid if g["s_uo"] == s_uo and g["S_t"] == st][0]
        done = {c["cells"] for c in point.get("checks", [])}
        for cells in checkCells:
            if cells in done:
                continue
            r = run(s_uo, st, cells, args.ppc, args.end, work)
            point.setdefault("checks", []).append({"cells": cells, "ppc": args.ppc, "mpm": r["slideMPM"]})
            print("check s_uo %g Pa, S_t %g at H0/%d: MPM %.1f m" % (s_uo, st, cells, r["slideMPM"]["runout"]),
                  flush=True)
    for g in grid:
        mpm, label, g["difference"], g["agrees"] = verdict(g, args.tolerance)
    shutil.rmtree(work, ignore_errors=True)

    lines = ["Regenerated by `applicability/map.py --suo %s --st %s --cells %d --ppc %d --tolerance %g --end %g%s`: Table 1 "
             "Case 2's slide, with remoulding from Case 13's scene (eta 0.45, n 0.23, 3.43 deg no-slip) with s_uo "
             "and S_t varied; slideDAM (fast) against "
             "slideMPM (H0/%d, %dx%d, remoulding counted per shear band of H0/60 as in Case 13's mpmDict) as the reference, fronts compared at rest or at %g s. Agreement: |DAM - MPM| <= "
             "%.0f %% of MPM. The paper's conclusion: s_uo >= 50 Pa and S_t <= 3." % (
                 ",".join("%g" % x for x in suos), ",".join("%g" % x for x in sts), args.cells, args.ppc,
                 args.tolerance, args.end,
                 (" --check %s --check-cells %s" % (
                     ",".join("%g:%g" % (g["s_uo"], g["S_t"]) for g in grid if g.get("checks")),
                     ",".join(sorted({"%d" % c["cells"] for g in grid for c in g.get("checks", [])}, key=int))))
                 if any(g.get("checks") for g in grid) else "",
                 args.cells, args.ppc, args.ppc, args.end, 100*args.tolerance),
             "",
             "| s_uo [Pa] | " + " | ".join("S_t = %g" % st for st in sts) + " |", "|---|" + "---|"*len(sts)]
    for s_uo in suos:
        cells = []
        for st in sts:
            g = [x for x in grid if x["s_uo"] == s_uo and x["S_t"] == st][0]
            mpm, label, diff, agrees = verdict(g, args.tolerance)
            cells.append("DAM %.0f / MPM %.0f%s (%+.0f %%)%s" % (g["dam"]["runout"], mpm["runout"],
                                                                 " at %s" % label if label else "", 100*diff,
                                                                 "" if agrees else " **x**"))
        lines.append("| %g | " % s_uo + " | ".join(cells) + " |")
    checked = [g for g in grid if g.get("checks")]
    if checked:
        lines += ["", "The reference's convergence in the cell (slideMPM, %dx%d particles; \"moving\": still faster "
                  "than restVelocity at %g s):" % (args.ppc, args.ppc, args.end), "",
                  "| s_uo [Pa] | S_t | cell | slideMPM runout [m] | wall [s] | DAM against it |", "|---|---|---|---|---|---|"]
        for g in checked:
            for cells, mpm in [(args.cells, g["mpm"])] + [(c["cells"], c["mpm"]) for c in
                                                          sorted(g["checks"], key=lambda c: c["cells"])]:
                lines.append("| %g | %g | H0/%d | %.1f%s | %.0f | %+.0f %% |" % (
                    g["s_uo"], g["S_t"], cells, mpm["runout"], "" if mpm["atRest"] else " (moving)", mpm["wall"],
                    100*(g["dam"]["runout"] - mpm["runout"])/mpm["runout"]))
    summary = "\n".join(lines)
    with open(os.path.join(HERE, "map.md"), "w") as f:
        f.write(summary + "\n")
    with open(os.path.join(HERE, "map.json"), "w") as f:
        json.dump({"summary": summary, "tolerance": args.tolerance, "cells": args.cells, "ppc": args.ppc,
                   "end": args.end, "grid": grid}, f, indent=1)

    # The map slideDAM reads (src/scene/damApplicability.C): the grid and where it agreed.
    with open(os.path.join(TOP, "etc", "damApplicability"), "w") as f:
        f.write("/*--------------------------------*- C++ -*----------------------------------*\\\n"
                "  Where slideDAM agreed with slideMPM: written by validation/applicability/map.py.\n"
                "\\*---------------------------------------------------------------------------*/\n"
                "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
                "    object      damApplicability;\n}\n\n")
        f.write("tolerance   %g;      // |DAM - MPM| / MPM\n" % args.tolerance)
        f.write("eta         0.45;\nn           0.23;\n")
        f.write("s_uo        (%s);   // [Pa]\n" % " ".join("%g" % x for x in suos))
        f.write("sensitivity (%s);\n" % " ".join("%g" % x for x in sts))
        f.write("// One row per s_uo, one column per sensitivity: 1 where the runouts agreed.\n")
        f.write("agrees      (%s);\n" % " ".join(
            "(%s)" % " ".join("1" if [x for x in grid if x["s_uo"] == s and x["S_t"] == t][0]["agrees"] else "0"
                              for t in sts) for s in suos))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig, ax = plt.subplots(figsize=(6, 4.5))
    diff = np.array([[[x for x in grid if x["s_uo"] == s and x["S_t"] == t][0]["difference"] for t in sts]
                     for s in suos])
    im = ax.pcolormesh(np.arange(len(sts) + 1), np.arange(len(suos) + 1), 100*np.abs(diff), cmap="RdYlGn_r",
                       vmin=0, vmax=100)
    for i in range(len(suos)):
        for j in range(len(sts)):
            ax.text(j + 0.5, i + 0.5, "%+.0f %%" % (100*diff[i, j]), ha="center", va="center", fontsize=9)
    ax.set_xticks(np.arange(len(sts)) + 0.5)
    ax.set_xticklabels(["%g" % t for t in sts])
    ax.set_yticks(np.arange(len(suos)) + 0.5)
    ax.set_yticklabels(["%g" % s for s in suos])
    ax.set(xlabel="sensitivity S_t", ylabel="s_uo [Pa]", title="slideDAM against slideMPM: runout difference")
    fig.colorbar(im, label="|DAM - MPM| / MPM [%]")
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "map.png"), dpi=110)
    print(summary)


if __name__ == "__main__":
    main()
