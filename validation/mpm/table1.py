#!/usr/bin/env python3
"""Regenerates the MPM column of Table 1 (Dong, Wang & Cui 2020): runs slideMPM
on tutorials/table1/case01..13 at one or more resolutions and writes, beside
this script, table1.md (paper MPM and DAM runouts, slideMPM's per resolution,
the error against the paper, the detected mechanism, the wall time),
table1.png (bars) and table1.json (the raw results).

Usage: validation/mpm/table1.py [--cells 10,20] [--ppc 4] [--cases 1,2,3] [--fine] [--stored]
                                 [--end-time T] [--continue CASE_DIR --end-time T] [--import ROWS_JSON]
(after ./Allwmake; defaults: cell H0/10 with the paper's 4 x 4 particles, all cases;
--fine adds the runs of FINE, the cases whose reference set-up is finer than the table's, about
28 minutes on 2 cores; --end-time stops the runs at T s instead of the scene's end,
for a scene whose end is out of reach here, e.g. Case 5's 3000 s, about 7 hours; each run's log is
<case>/log.slideMPM in the work directory printed at the start, which is removed at the end; a run stopped by hand
keeps it, and --continue runs it on from its latest restart state: in legs, a run longer than a session)"""
import argparse
import json
import os
import re
import shutil
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from slidefoam_io import front_at as front_of, mechanism_at, read_summary, read_runout  # noqa: E402
from runner import which  # noqa: E402
from paper import paper_table  # noqa: E402
from cfdcase import get_entry, run, set_entry, set_method_entries  # noqa: E402

# Cases whose reference set-up is finer than the table's, at (cells per H0, particles per cell direction):
# Case 11 (S_t = 40) moves by shear bands, and at H0/10-H0/20 a cell is too coarse for more than one
# to form (shearBand.md); H0/40 is the coarsest at which its slide parts into horsts and grabens.
# Case 1, the thinnest deposit, needs the particles: they crowd into the cell on the base, the more so the
# fewer there are, and its runout rises from 268.6 m at 4x4 to 317.4 m at 8x8 at H0/20 (README, open problem 13).
FINE = {1: (20, 8), 11: (40, 2)}
# The remoulding cases, whose mechanism the detector's remoulded-film rule (session 25) can change: a row run
# before it says so.
FILM_SENSITIVE = (10, 11, 12, 13)
OLD_DETECTOR = " (mechanism from the detector before session 25, which parted bodies by empty columns only)"
# Rows run before session 40 had the clay's elasticity in the Jaumann rate of the Cauchy stress.
CAUCHY = " (Cauchy stress rate, before session 40)"


def on_gpu(r):
    """" on CUDA" where row r ran on a GPU (SLIDEFOAM_SLIDEMPM_BINARY): its wall time is not this machine's."""
    if not (r.get("backend") or "").startswith("Cuda"):
        return ""
    # deviceTable1.sh runs several cases at once on the GPU: each one's wall time is then its share's.
    return " on CUDA" + (", %d runs sharing the GPU" % r["lanes"] if r.get("lanes", 1) > 1 else "")


def cauchy_rate(r):
    """Whether row r ran with the Cauchy stress's rate (rows without the key are older than the choice)."""
    return r.get("stressRate", "cauchy") == "cauchy"


def run_case(c, cells, ppc, work, scene=None, numerics=None, tag="", end_time=None):
    """slideMPM on Table 1 Case c at cell H0/cells with ppc x ppc particles; `scene` sets entries of the
    case's constant/sceneProperties (a sensitivity run, e.g. {"eta": 0}), `numerics` more of its mpmDict,
    `tag` names its run directory, `end_time` stops it before the scene's end (the row says so)."""
    src = os.path.join(top, "tutorials", "table1", "case%02d" % c)
    d = os.path.join(work, "case%02d_h%d_p%d%s" % (c, cells, ppc, tag))
    shutil.copytree(src, d, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    for k, v in (scene or {}).items():
        set_entry(os.path.join(d, "constant", "sceneProperties"), k, v)
    # The tutorial's mpmDict with the resolution of this run (its other entries, e.g. a shearBandThickness, kept).
    set_method_entries(d, "mpmDict", {"setting": "fast", "cellsPerHeight": cells, "particlesPerCell": ppc,
                                      "writeFields": "no", "progressInterval": 30,
                                      # One restart state kept: at H0/20 with 4x4 Case 4 writes 97 MB a second.
                                      "purgeState": 1, **(numerics or {})})
    if end_time is not None:
        set_entry(os.path.join(d, "system", "controlDict"), "endTime", "%g" % end_time)
    print("case %2d H0/%d %dx%d: %s/log.slideMPM" % (c, cells, ppc, ppc, d), flush=True)
    if run(d, which("slideMPM"), "-case", ".", log="log.slideMPM", check=False) != 0:
        return {"case": c, "cells": cells, "ppc": ppc, "failed": open(os.path.join(d, "log.slideMPM")).read()[-800:],
                "stressRate": (numerics or {}).get("stressRate", "kirchhoff")}
    res = case_result(c, cells, ppc, d)
    if end_time is not None:
        res["endTimeCut"] = end_time
    return res


def case_result(c, cells, ppc, d):
    """The row of table1.json from a finished slideMPM run in case directory d."""
    s = read_summary(os.path.join(d, "postProcessing", "slideMPM", "summary.json"))
    r = read_runout(os.path.join(d, "postProcessing", "slideMPM", "runout.dat"))
    return {"case": c, "cells": cells, "ppc": ppc, "runout": s["runout_m"], "endTime": s["end_time_s"],
            "atRest": s["at_rest"], "wall": s["wall_time_s"], "particles": s["problem_size"],
            "backend": s.get("backend"),
            "mechanism": s["mechanism"], "shearBand": s.get("shear_band"), "mech10": mechanism_at(s, 10.0),
            "mech30": mechanism_at(s, 30.0),
            "baseContact": s.get("base_contact", "withinCell"),
            "baseRowMassScaling": s.get("base_row_mass_scaling"),
            "particleShifting": s.get("particle_shifting", 0.0),
            "stressRate": s.get("stress_rate", "cauchy"),
            # The energy budget's remainder (gravity's work neither kinetic, elastic, plastic nor the boundary's),
            # as a share of gravity's work: what the discretisation lost.
            "numericalDissipation": s.get("numerical_dissipation_fraction"),
            # Absent: the mechanism came from the detector before session 25, which parted bodies by empty columns
            # only (a no-slip base keeps a remoulded film between bodies that slid apart).
            "breakawayFilm": s.get("breakaway_film_height_m"),
            # The front's resolution (slideMPM since session 62): the fewest cells through its moving foremost H0,
            # and the share of the runout it ran under three (frontResolution.md).
            "frontMinCells": s.get("front_min_cells_moving"),
            "frontUnderResolvedShare": s.get("front_travel_under_resolved_fraction"),
            # The front of the slide's body (slideMPM since session 63), which particles thrown ahead of a fast,
            # thin sheet do not set (sheetFlow.md).
            "massFront": s.get("front_of_99_percent_mass_m"),
            "maxThickness": s.get("max_thickness_m"), "frontVelocity": float(r["frontVelocity"][-1]),
            "maxVelocity": float(r["maxVelocity"][-1]),
            "history": [[float(a), float(b), float(v)] for a, b, v in zip(r["time"], r["front"], r["frontVelocity"])]}


def front_at(history, times):
    """The front at each of `times` from a row's history ([time, front, front speed] per write), None past the
    run's end; keyed "%g" as the rows store it."""
    return {"%g" % t: front_of([h[:2] for h in history], t) for t in times}


def legs_run(d):
    """The legs run in case directory d, read from their logs (log.slideMPM, log.slideMPM.from<t> of --continue):
    [start, last time printed, wall time until then], in order."""
    legs = []
    for name in os.listdir(d):
        m = re.match(r"^log\.slideMPM(?:\.from([0-9.eE+-]+))?$", name)
        rows = re.findall(r"^Time = ([0-9.eE+-]+) .*ExecutionTime = ([0-9.eE+-]+) s",
                          open(os.path.join(d, name)).read(), re.M) if m else []
        if rows:
            legs.append([float(m.group(1) or 0.0), float(rows[-1][0]), float(rows[-1][1])])
    return sorted(legs)


def continue_case(d, end_time):
    """Runs a case directory of an earlier table1.py run (one stopped by hand keeps its work directory) on from
    its latest restart state to end_time, and returns its table1.json row; its wall time is the sum of the legs'
    logs, each counted to its last progress line, the work after the latest state that a stopped leg lost included."""
    m = re.match(r"^case(\d+)_h(\d+)_p(\d+)$", os.path.basename(os.path.normpath(d)))
    if not m:
        raise SystemExit("--continue: %s is not a case directory of table1.py (caseNN_hN_pN)" % d)
    c, cells, ppc = (int(g) for g in m.groups())
    states = [float(t) for t in os.listdir(d) if re.match(r"^[0-9.eE+-]+$", t)
              and os.path.exists(os.path.join(d, t, "slideMPM.state"))]
    if not states:
        raise SystemExit("--continue: %s holds no restart state (<time>/slideMPM.state)" % d)
    if end_time <= max(states):
        raise SystemExit("--continue: %s has run to %g s; give a later --end-time" % (d, max(states)))
    control = os.path.join(d, "system", "controlDict")
    set_entry(control, "startFrom", "latestTime")
    set_entry(control, "endTime", "%g" % end_time)
    log = "log.slideMPM.from%g" % max(states)
    print("case %2d H0/%d %dx%d: on from %g s to %g s, %s" % (c, cells, ppc, ppc, max(states), end_time,
                                                             os.path.join(d, log)), flush=True)
    if run(d, which("slideMPM"), "-case", ".", log=log, check=False) != 0:
        raise SystemExit("--continue: slideMPM failed in %s:\n%s" % (d, open(os.path.join(d, log)).read()[-800:]))
    res = case_result(c, cells, ppc, d)
    legs = legs_run(d)
    if not legs or legs[0][0] > 0.0:
        print("--continue: no log of the leg from 0 s in %s: the wall time counts the later legs only" % d)
    res.update(wall=sum(leg[2] for leg in legs), legs=legs)
    scene_end = get_entry(os.path.join(top, "tutorials", "table1", "case%02d" % c, "system", "controlDict"),
                          "endTime")
    if end_time < scene_end:
        res["endTimeCut"] = end_time
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", default="10")
    ap.add_argument("--ppc", type=int, default=4)
    ap.add_argument("--cases", default=",".join(str(c) for c in range(1, 14)))
    ap.add_argument("--fine", action="store_true", help="also run the cases of FINE at their finer cell")
    ap.add_argument("--stored", action="store_true", help="rewrite table1.md/png from table1.json without running")
    ap.add_argument("--end-time", type=float, default=None,
                    help="stop the runs at this time instead of the scene's end (the table says so)")
    ap.add_argument("--import", dest="imported", metavar="ROWS_JSON",
                    help="store the rows of runs made elsewhere (deviceTable1.sh's rows.json on a GPU) and rewrite "
                         "the table, as --stored does")
    ap.add_argument("--continue", dest="cont", metavar="CASE_DIR",
                    help="run a kept case directory of an earlier run on from its latest state to --end-time, "
                         "and store its row")
    args = ap.parse_args()
    if args.cont and args.end_time is None:
        raise SystemExit("--continue needs --end-time")
    cells = [int(x) for x in args.cells.split(",")]
    cases = [int(x) for x in args.cases.split(",")]
    paper = paper_table()
    work = tempfile.mkdtemp(prefix="slideMPM_table1_")
    results = [continue_case(args.cont, args.end_time)] if args.cont else []
    if args.imported:
        # A failed row (a run that broke there) is kept as what it is; cut-off runs never reach rows.json.
        results = json.load(open(args.imported))
        args.stored = True
    for c in ([] if args.stored or args.cont else cases):
        for h in cells:
            res = run_case(c, h, args.ppc, work, end_time=args.end_time)
            results.append(res)
            print("case %2d H0/%d: %s" % (c, h, "FAILED" if "failed" in res else
                  "%.1f m (%s, %s), %.0f s" % (res["runout"], res["mechanism"],
                                               "at rest" if res["atRest"] else "moving at t = %g s" % res["endTime"],
                                               res["wall"])), flush=True)
    for c in ([] if args.stored or args.cont or not args.fine else [c for c in cases if c in FINE]):
        res = run_case(c, FINE[c][0], FINE[c][1], work)
        results.append(res)
        print("case %2d H0/%d %dx%d: %s" % (c, FINE[c][0], FINE[c][1], FINE[c][1], res.get("runout", "FAILED")),
              flush=True)
    # Results of other cases or resolutions from earlier runs are kept: a run of a few
    # cases updates the table instead of replacing it.
    path = os.path.join(here, "table1.json")
    kept = [r for r in (json.load(open(path)) if os.path.isfile(path) else [])
            if not any(r["case"] == n["case"] and r["cells"] == n["cells"] and r["ppc"] == n["ppc"] for n in results)]
    results = sorted(kept + results, key=lambda r: (r["case"], r["cells"], r["ppc"]))
    cases = sorted({r["case"] for r in results if r["ppc"] == args.ppc and r["cells"] in cells})
    with open(path, "w") as f:
        json.dump(results, f, indent=1)

    lines = ["# Table 1, MPM column: slideMPM against Dong, Wang & Cui (2020)", "",
             "Regenerated by `validation/mpm/table1.py --cells %s --ppc %d`. Runout = travel of the front (m); "
             "error against the paper's MPM (DAM where the paper gives no MPM value). "
             "Cell H0/n with %dx%d particles per cell. The front is the foremost particle; beside it the front of 99 %% "
             "of the mass (summary.json's front_of_99_percent_mass_m, from the initial front like the runout), which "
             "a film or a spray of 1 %% of the slide cannot set (sheetFlow.md; \"-\": a run made before slideMPM "
             "gave it, session 63)." % (args.cells, args.ppc, args.ppc, args.ppc), ""]
    head = "| case | paper mechanism | paper MPM | paper DAM |"
    sep = "|---|---|---|---|"
    for h in cells:
        head += " H0/%d runout | error | front of 99 %% of the mass | mechanism | wall |" % h
        sep += "---|---|---|---|---|"
    lines += [head, sep]
    for c in cases:
        mech, vals = paper[c]
        row = "| %d | %s | %s | %s |" % (c, mech, vals.get("MPM", ""), vals.get("DAM", ""))
        for h in cells:
            found = [r for r in results if r["case"] == c and r["cells"] == h and r["ppc"] == args.ppc]
            if not found:
                row += " - | | | | |"
                continue
            res = found[0]
            if "failed" in res:
                # The run's own reason: the first line of slideMPM's FATAL ERROR, where it gave one.
                why = res["failed"].split("FATAL ERROR:")[-1].strip().split("\n")[0] \
                    if "FATAL ERROR:" in res["failed"] else ""
                row += " failed%s%s | | | | |" % ((": " + why.split(" (")[0]) if why else "",
                                                CAUCHY if cauchy_rate(res) else "")
                continue
            ref = vals.get("MPM", vals.get("DAM"))
            err = "%+.0f %%" % (100.0*(res["runout"]/ref - 1.0)) if ref else ""
            state = "" if res["atRest"] else " (moving, t = %g s%s)" % (
                res["endTime"], ", stopped before the scene's end (`--end-time`)" if "endTimeCut" in res else "")
            extra = ""
            if c == 9:
                extra = "; %.1f m/s, H %.1f m at 20 s" % (res["frontVelocity"], res["maxThickness"])
            if c == 11:
                extra = "; 10 s: %s, 30 s: %s" % (res["mech10"], res["mech30"])
            if c == 12:
                extra = "; shear band %s" % res["shearBand"]
            if res.get("breakawayFilm") is None and c in FILM_SENSITIVE:
                extra += OLD_DETECTOR
            if cauchy_rate(res):
                extra += CAUCHY
            mass_front = "%.1f" % res["massFront"] if res.get("massFront") is not None else "-"
            row += " %.1f%s | %s | %s | %s%s | %.0f s%s |" % (res["runout"], state, err, mass_front, res["mechanism"],
                                                            extra, res["wall"], on_gpu(res))
        lines.append(row)
    # The stored runs at FINE's cell or finer (the paper's H0/60 among them) are shown too.
    fine = [(c, r) for c in cases if c in FINE for r in results
            if r["case"] == c and r["cells"] >= FINE[c][0] and r["ppc"] == FINE[c][1] and "runout" in r]
    if fine:
        lines += ["", "Cases whose reference set-up is finer than the table's (`--fine`):", ""]
        for c, r in fine:
            lines.append("- Case %d at H0/%d, %dx%d particles: %.1f m%s; mechanism %s; 10 s: %s, 30 s: %s; "
                         "shear band %s; %.0f s%s%s" % (
                             c, r["cells"], r["ppc"], r["ppc"], r["runout"],
                             "" if r["atRest"] else " (moving, t = %g s)" % r["endTime"], r["mechanism"],
                             r["mech10"], r["mech30"], r["shearBand"], r["wall"], on_gpu(r),
                             (OLD_DETECTOR if r.get("breakawayFilm") is None else "")
                             + (CAUCHY if cauchy_rate(r) else "")))
    # Every stored cell of a case with these particles, coarse to fine: the convergence in the cell, and the
    # paper's own set-up (H0/60, 4x4) where it was run.
    conv = []
    for c in cases:
        runs = [r for r in results if r["case"] == c and r["ppc"] == args.ppc and "runout" in r]
        if len(runs) < 2:
            continue
        ref = paper[c][1].get("MPM")
        conv.append("- Case %d: " % c + ", ".join(
            "H0/%d %.1f m%s%s%s" % (r["cells"], r["runout"],
                                    " (%+.0f %%)" % (100.0*(r["runout"]/ref - 1.0)) if ref else "",
                                    "" if r["atRest"] else " moving at %g s" % r["endTime"],
                                    " (Cauchy rate)" if cauchy_rate(r) else "")
            for r in sorted(runs, key=lambda r: r["cells"])))
    if conv:
        lines += ["", "Every stored cell with %dx%d particles, coarse to fine (H0/60 is the paper's set-up; error "
                  "against the paper's MPM):" % (args.ppc, args.ppc), ""] + conv
    # Every stored particles-per-cell of a case at one cell: the convergence in the particles, which the cell's
    # does not show (README, open problem 13).
    per = []
    for c in cases:
        for h in sorted({r["cells"] for r in results if r["case"] == c}):
            runs = [r for r in results if r["case"] == c and r["cells"] == h and "runout" in r]
            if len(runs) < 2:
                continue
            ref = paper[c][1].get("MPM")
            per.append("- Case %d at H0/%d: " % (c, h) + ", ".join(
                "%dx%d %.1f m%s%s" % (r["ppc"], r["ppc"], r["runout"],
                                      " (%+.0f %%)" % (100.0*(r["runout"]/ref - 1.0)) if ref else "",
                                      "" if r["atRest"] else " moving at %g s" % r["endTime"])
                for r in sorted(runs, key=lambda r: r["ppc"])))
    if per:
        lines += ["", "Every stored particles per cell at one cell (error against the paper's MPM):", ""] + per
    with open(os.path.join(here, "table1.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    shown = [c for c in cases if paper[c][1].get("MPM")]
    if shown:
        x = np.arange(len(shown))
        w = 0.8/(1 + len(cells))
        fig, ax = plt.subplots(figsize=(10, 4))
        ax.bar(x, [paper[c][1]["MPM"] for c in shown], w, label="paper MPM")
        for k, h in enumerate(cells):
            vals = []
            for c in shown:
                found = [r for r in results if r["case"] == c and r["cells"] == h and r["ppc"] == args.ppc]
                vals.append(found[0].get("runout", np.nan) if found else np.nan)
            ax.bar(x + (k + 1)*w, vals, w, label="slideMPM H0/%d" % h)
        ax.set_xticks(x + 0.5*w*len(cells))
        ax.set_xticklabels(["Case %d" % c for c in shown])
        ax.set_yscale("log")
        ax.set_ylabel("runout [m]")
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(here, "table1.png"), dpi=120)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
