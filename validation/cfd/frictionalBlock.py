#!/usr/bin/env python3
"""What sets slideFoam's runout of Table 1 Case 8 (a 5 m block of s_uo 5 kPa on a frictional base of s_b 1.8 kPa,
5 deg): the slide's downslope momentum budget from its written fields, for the default solver and for the two
halves of cfdDict conservePlugMomentum (PIMPLE restoreCorrectorMomentum; the base's transposeShear runningMean)
alone and together, for the scene without Eq. (1)'s rate effect, and for the base that exerts all of s_b on every
face whose cell holds slide (cfdDict baseStrength wholeFace, slideFoam's only base until session 90), and for base
faces under traces of slide held as the ambient's (cfdDict baseSlideTrace: 1e-3, the solver's default since session
98, and 1e-4) or not (0, the default until then, and the floor under the other variants, as they were run).

Each second of the run: the slide's momentum P = sum(rho alpha U_x V) per metre of width, dP/dt, the length of
base under slide (faces whose moving cell holds alpha > 0.01) and the slide's share of it (sum of alpha times the
face's length: the base exerts s_b on that share by default), and the base force the budget implies, weight along
the slope less dP/dt, over that share. A block sliding on such a base is stopped by its own length: it decelerates
once s_b times its contact passes its weight along the slope (here at 57 m).

Usage: validation/cfd/frictionalBlock.py [--variants default,noSlideTrace,restore,transpose,both,rateFree,wholeFace,
                                          slideTrace] [--cells 10]
                                          [--base-refinement 4] [--processors 2] [--work DIR] [--keep]
(after ./Allwmake; about 2 min a variant on 2 cores at H0/10, 16 min at H0/20; writes frictionalBlock.md beside this
script at Table 1's mesh, H0/10 with H0/40 on the base, else frictionalBlock_H0_<cells>.md)"""
import argparse
import json
import math
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import (cell_geometry, get_entry, make_case, prepare, read_field, run, run_slidefoam,  # noqa: E402
                     set_method_entries, time_dirs, variant_arguments, write_study)
from runner import which  # noqa: E402
from slidefoam_io import read_runout, read_summary  # noqa: E402

CASE = 8
VARIANTS = {
    "default": "the solver's defaults (since session 98 base faces under less than 1e-3 of slide the ambient's, "
               "cfdDict baseSlideTrace 1e-3)",
    "noSlideTrace": "the solver's defaults until session 98: s_b on the slide's share of every base face, down to none "
                    "(cfdDict baseSlideTrace 0)",
    "restore": "PIMPLE restoreCorrectorMomentum yes alone, no slide-trace floor",
    "transpose": "the base's transposeShear runningMean alone, no slide-trace floor",
    "both": "cfdDict conservePlugMomentum yes (both), no slide-trace floor",
    "rateFree": "noSlideTrace, the scene without Eq. (1)'s rate effect (eta 0)",
    "wholeFace": "noSlideTrace, s_b on every face the slide touches (cfdDict baseStrength wholeFace)",
    "slideTrace": "the solver's defaults, base faces under less than 1e-4 of slide the ambient's (cfdDict "
                  "baseSlideTrace 1e-4)",
}
# The studies of sessions 66-93 ran before the base had a trace floor: they keep running without one, so that a run
# repeats its stored row.
NO_FLOOR = ("noSlideTrace", "restore", "transpose", "both", "rateFree", "wholeFace")
# Written every second; these rows go into the table.
REPORT_TIMES = [2, 5, 10, 15, 20, 25, 30, 40, 50]


def scene():
    """theta [rad], s_b [Pa], rho' [kg/m3] of the case's constant/sceneProperties."""
    path = os.path.join(top, "tutorials", "table1", "case%02d" % CASE, "constant", "sceneProperties")
    values = {key: get_entry(path, key) for key in ("angle", "s_b", "density")}
    for key, value in values.items():
        if value is None:
            raise SystemExit("%s: no key '%s'" % (path, key))
    return math.radians(values["angle"]), values["s_b"], values["density"]


def case_name(variant, cells, refinement):
    """The work directory's name of a run: its mesh too, so that a run read back is never another mesh's."""
    return "case08_%s_H0_%d_base%d" % (variant, cells, refinement)


def run_variant(variant, work, cells, refinement, processors):
    d = make_case(os.path.join(top, "tutorials", "table1", "case%02d" % CASE), work,
                  case_name(variant, cells, refinement),
                  scene={"eta": 0} if variant == "rateFree" else None)
    # Room for the default's 112 m: the DAM-sized mesh (1.3 x 47 m) is left at 31 s.
    cfd = {"setting": "fast", "cellsPerHeight": cells, "baseRefinement": refinement, "processors": processors,
           "reach": "200"}
    if variant in ("both", "restore"):
        cfd["conservePlugMomentum"] = "yes"
    # The halves apart: conservePlugMomentum's restore without its default transposeShear, or the mean alone.
    if variant == "restore":
        cfd["transposeShear"] = "nearKinks"
    if variant == "transpose":
        cfd["transposeShear"] = "runningMean"
    if variant == "wholeFace":
        cfd["baseStrength"] = "wholeFace"
    if variant == "slideTrace":
        cfd["baseSlideTrace"] = "1e-4"
    if variant in NO_FLOOR:
        cfd["baseSlideTrace"] = "0"
    set_method_entries(d, "cfdDict", cfd)
    run(d, which("slideDAM"), "-case", ".")
    prepare(d)
    run_slidefoam(d, processors)
    # Every time: slideDAM's state files already fill the first seconds' directories, which -newTimes skips.
    run(d, "reconstructPar")
    return d


def budget(d, theta, s_b, rho):
    """The slide's area and weight along the slope, the contact that stalls it, and per written whole second its
    momentum P, dP/dt (backward), contact length [m] and the base force [N/m] and stress [Pa] the budget implies."""
    V, Cx, Cy = cell_geometry(d)
    base = np.abs(Cy - Cy.min()) < 1e-6 * max(1.0, abs(Cy.min()))
    order = np.argsort(Cx[base])
    width = np.gradient(Cx[base][order])
    # The 2D mesh's depth, from a base cell's volume: V = width x height x depth, height twice its centre's.
    depth = V[base][order][0] / (width[0] * 2 * Cy.min())
    a0 = np.clip(read_field(d, "0", "alpha.slide"), 0, 1)
    area = np.sum(a0 * V) / depth
    weight = rho * area * 9.81 * math.sin(theta)
    rows = []
    for t in time_dirs(d):
        if float(t) != round(float(t)) or not os.path.exists(os.path.join(d, t, "U")):
            continue
        a = np.clip(read_field(d, t, "alpha.slide"), 0, 1)
        U = read_field(d, t, "U")
        if U.ndim == 1:
            U = np.tile(U, (len(a), 1))
        P = np.sum(rho * a * U[:, 0] * V) / depth
        moving = np.abs(U[base][order][:, 0]) > 1e-3
        touching = (a[base][order] > 0.01) & moving
        rows.append([float(t), P, np.sum(width * touching), np.sum(width * a[base][order] * moving)])
    out = []
    for (t0, P0, _, S0), (t1, P1, L1, S1) in zip(rows, rows[1:]):
        dPdt = (P1 - P0) / (t1 - t0)
        out.append({"t": t1, "P": P1, "dPdt": dPdt, "contact": L1, "share": S1, "base_force": weight - dPdt,
                    "base_stress": (weight - dPdt) / (0.5 * (S0 + S1)) if S0 + S1 > 0 else None})
    return {"area": area, "weight": weight, "stall_contact": weight / s_b, "rows": out}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", type=int, default=10)
    ap.add_argument("--base-refinement", type=int, default=4)
    ap.add_argument("--processors", type=int, default=2)
    ap.add_argument("--keep", action="store_true",
                    help="keep the other variants of the mesh's stored report (its .json) in the report")
    args, variants, work = variant_arguments(ap, VARIANTS, "frictionalBlock", "a variant already run there on the "
                                             "same mesh (its summary.json present) is read, not rerun")
    theta, s_b, rho = scene()
    results = {}
    stored = os.path.join(here, report_name(args) + ".json")
    if args.keep and os.path.exists(stored):
        for v, r in json.load(open(stored)).items():
            # JSON's keys are strings: the report's times back to numbers.
            results[v] = dict(r, front={int(t): x for t, x in r["front"].items()},
                              speed={int(t): x for t, x in r["speed"].items()})
    for v in variants:
        d = os.path.join(work, case_name(v, args.cells, args.base_refinement))
        summary = os.path.join(d, "postProcessing", "slideFoam", "summary.json")
        if not os.path.exists(summary):
            print("Case 8, %s: running slideFoam (H0/%d, H0/%d on the base, %d ranks)"
                  % (v, args.cells, args.cells * args.base_refinement, args.processors), flush=True)
            d = run_variant(v, work, args.cells, args.base_refinement, args.processors)
        s = read_summary(summary)
        r = read_runout(os.path.join(d, "postProcessing", "slideFoam", "runout.dat"))
        b = budget(d, theta, s_b, rho)
        at = {t: int(np.argmin(np.abs(r["time"] - t))) for t in REPORT_TIMES}
        results[v] = dict(b, runout=s["runout_m"], at_rest=s["at_rest"], end=s["end_time_s"], wall=s["wall_time_s"],
                          front={t: float(r["front"][i]) for t, i in at.items()},
                          speed={t: float(r["frontVelocity"][i]) for t, i in at.items()},
                          thickness=float(r["maxThickness"][-1]))
        print("%-9s runout %.1f m at %g s, wall %.0f s" % (v, s["runout_m"], s["end_time_s"], s["wall_time_s"]),
              flush=True)
    write_report({v: results[v] for v in VARIANTS if v in results}, s_b, args)


def report_name(args):
    """Table 1's mesh writes frictionalBlock.md, another mesh frictionalBlock_H0_<cells>.md."""
    return "frictionalBlock" + ("" if (args.cells, args.base_refinement) == (10, 4) else "_H0_%d" % args.cells)


def write_report(results, s_b, args):
    lines = ["# Table 1 Case 8 in slideFoam: the block's momentum budget",
             "",
             "Written by `validation/cfd/frictionalBlock.py --cells %d --base-refinement %d --processors %d`. A 5 m "
             "block of s_uo 5 kPa on a frictional base of s_b = %.0f Pa; its weight along the slope is matched by "
             "s_b under a contact of %.1f m. Contact: the base faces whose cell holds slide (alpha > 0.01) and moves; "
             "share: the slide's share of them (the sum of alpha times the face's length), on which the base "
             "exerts s_b by default; base force: weight along the slope less dP/dt; base stress: that over the share."
             % (args.cells, args.base_refinement, args.processors, s_b,
                next(iter(results.values()))["stall_contact"]),
             "",
             "| variant | runout [m] | end | max thickness at the end [m] | wall [s] |",
             "|---|---|---|---|---|"]
    for v, r in results.items():
        lines.append("| %s | %.1f | %s | %.2f | %.0f |" % (VARIANTS[v], r["runout"],
                     ("at rest by %g s" % r["end"]) if r["at_rest"] else ("%g s, not at rest" % r["end"]),
                     r["thickness"], r["wall"]))
    lines += ["", "| t [s] | " + " | ".join("%s: front [m], speed [m/s], contact [m], share [m], base stress [Pa]" % v
                                              for v in results) + " |",
              "|---|" + "---|" * len(results)]
    for t in REPORT_TIMES:
        cells = []
        for v, r in results.items():
            row = [x for x in r["rows"] if abs(x["t"] - t) < 1e-9]
            if not row:
                cells.append("-")
                continue
            x = row[0]
            if r["speed"][t] < 0.05:
                # Stopped: the stuck faces hold what they need, the stress over the creeping ones means nothing.
                cells.append("%.1f, %.2f, stopped" % (r["front"][t], r["speed"][t]))
            else:
                cells.append("%.1f, %.2f, %.1f, %.1f, %.0f" % (r["front"][t], r["speed"][t], x["contact"],
                                                               x["share"], x["base_stress"]))
        lines.append("| %g | " % t + " | ".join(cells) + " |")
    write_study(here, report_name(args), lines, results)


if __name__ == "__main__":
    main()
