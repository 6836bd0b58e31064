#!/usr/bin/env python3
"""Table 1 Case 5 in slideMPM: a very weak slide (s_uo 50 Pa on 10 deg) that becomes a fast sheet a cell thick, and
what of it the MPM resolves.

Why: the basal driving stress of Case 5's 5 m slide is 5.1 kPa against s_uo = 50 Pa, so it runs as a nearly inviscid
sheet down the slope: slideDAM's front reaches 55 m/s by 30 s and 7.5 km at rest (the paper's DAM 4.4 km; the paper
gives no MPM or CFD for it). Its critical thickness s_uo/(rho' g sin(theta)) is 5 cm, a tenth of Table 1's H0/10
cell. slideMPM's Table 1 row stopped on a blow-up at 66 s before session 40; run with today's code to 80 s, its
front (the foremost particle) jumped between 3 and 104 m/s from write to write. This script says what that front
is made of.

The case is run to --end-time with its particles written every second. At each of --times it measures along the
base, from the particles: the travel of the front (the foremost particle, what runout.dat calls the front), of the
front of 99.9 % and of 99 % of the mass, and of the centre of mass; the share of the mass that has left the sheet
(particles higher above the base than three times their 5 m bin's thickness and than two cells: material no longer
in contact with the flow below it, but still tied to it through the grid's nodes); the highest particle; and from
energy.dat the share of gravity's work that the discretisation lost (neither kinetic, elastic, plastic nor the
boundary's). slideDAM's front at the same time is read from ../dam/table1.json (its stored Table 1 run).

--mpm KEY=VALUE (repeatable) sets mpmDict entries of a variant and --tag names it. Writes sheetFlow.md and
sheetFlow.json beside itself, and for Table 1's set-up (H0/10, 4x4, no --mpm) sheetFlow.png: the sheet's head at 10
and 20 s, its particles coloured by their velocity normal to and along the base; --stored rewrites the md from the
json.

Usage: validation/mpm/sheetFlow.py [--cells 10] [--ppc 4] [--end-time 40] [--times 10,20,30,40]
       [--mpm KEY=VALUE ...] [--tag NAME] [--keep] [--stored]
(after ./Allwmake; on 2 cores Case 5 at H0/10 with 4x4 particles takes about 3 minutes to 40 s, 14 minutes to 80 s)"""
import argparse
import json
import os
import shutil
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from frontZone import mass_front, scene_of  # noqa: E402
from table1 import run_case  # noqa: E402
from slidefoam_io import front_at, particles_on_planar_base  # noqa: E402

import numpy as np  # noqa: E402

CASE = 5
BIN = 5.0          # [m] along the base: the bins whose thickness a particle is set against
LEFT_SHEET = 3.0   # a particle higher than this times its bin's thickness (and two cells) has left the sheet


def measure(d, t, angle, density, cell):
    """The row of one written time t of run directory d."""
    s, z, u, arr = particles_on_planar_base(d, t, angle)
    m = arr["mass"]
    b = np.floor((s - s.min())/BIN).astype(int)
    thickness = (np.bincount(b, weights=m)/(density*BIN))[b]
    left = z > np.maximum(LEFT_SHEET*thickness, 2.0*cell)
    return {"t": t, "front": float(s.max()), "front999": mass_front(s, m, 0.999), "front99": mass_front(s, m, 0.99),
            "com": float((m*s).sum()/m.sum()), "leftSheet": float(m[left].sum()/m.sum()),
            "highest": float(z.max()), "particles": int(len(s))}


def figure(d, angle, path, times=(10.0, 20.0), length=(60.0, 100.0)):
    """The head of the sheet at each of `times` (its foremost `length` metres): the particles coloured by their
    velocity normal to the base, and by their velocity along it."""
    import math
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    c, sn = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    fig, axs = plt.subplots(len(times), 2, figsize=(16, 3.2*len(times)), squeeze=False)
    for row, t, ahead in zip(axs, times, length):
        s, z, u, arr = particles_on_planar_base(d, t, angle)
        vn = arr["velocity"][:, 0]*sn + arr["velocity"][:, 2]*c
        k = s > s.max() - ahead
        for ax, val, label, lim in ((row[0], vn, "velocity normal to the base [m/s]", (-1.5, 1.5)),
                                    (row[1], u, "velocity along the base [m/s]", (0.0, 40.0))):
            sc = ax.scatter(s[k], z[k], c=val[k], s=2, cmap="coolwarm" if lim[0] < 0 else "jet",
                            vmin=lim[0], vmax=lim[1])
            ax.set_title("t = %g s" % t)
            ax.set_xlabel("along the base [m]")
            ax.set_ylabel("above the base [m]")
            fig.colorbar(sc, ax=ax, label=label)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def energy_share(d, t):
    """numerical/gravityWork of energy.dat at the row nearest t."""
    rows = np.loadtxt(os.path.join(d, "postProcessing", "slideMPM", "energy.dat"), comments="#", ndmin=2)
    return float(rows[np.argmin(np.abs(rows[:, 0] - t)), -1])


def analyse(d, cells, ppc, tag, times, mpm):
    angle, density = scene_of(d)
    cell = 5.0/cells        # Table 1's H0 = 5 m
    start = measure(d, 0.0, angle, density, cell)
    rows = []
    for t in times:
        r = measure(d, t, angle, density, cell)
        for k in ("front", "front999", "front99", "com"):
            r[k] -= start[k]
        r["numericalShare"] = energy_share(d, t)
        rows.append(r)
    return {"cells": cells, "ppc": ppc, "tag": tag, "mpm": mpm, "rows": rows}


def dam_fronts(times):
    rows = [r for r in json.load(open(os.path.join(top, "validation", "dam", "table1.json"))) if r["case"] == CASE]
    if not rows:
        return {}
    return {t: front_at([h[:2] for h in rows[0]["history"]], t) for t in times}


def write_md(store):
    lines = ["# Table 1 Case 5 in slideMPM: the fast sheet (written by sheetFlow.py)", "",
             "Case 5 (s_uo 50 Pa, eta 0.35, n 0.15, 10 deg, no-slip), run with its particles written every second. "
             "Travel along the base [m] of the front (the foremost particle: runout.dat's front), of the front of "
             "99.9 % and 99 % of the mass, and of the centre of mass; slideDAM's front (its stored Table 1 run, "
             "`../dam/table1.json`); the share of the mass that has left the sheet (higher above the base than "
             "three times its 5 m bin's thickness and than two cells); the highest particle above the base; and the "
             "share of gravity's work the discretisation lost (energy.dat). The script's docstring says why.", "",
             "![Case 5's head at 10 and 20 s, Table 1's set-up](sheetFlow.png)", ""]
    # Table 1's set-up first, then its variants, then other cells.
    for run in sorted(store["runs"], key=lambda r: (r["cells"], r["ppc"], bool(r["mpm"]), r["tag"])):
        table1 = (run["cells"], run["ppc"]) == (10, 4) and not run["mpm"]
        lines += ["## H0/%d, %dx%d particles%s%s, %.0f s of wall time" % (
                      run["cells"], run["ppc"], run["ppc"],
                      "".join(", %s %s" % kv for kv in run["mpm"].items()), " (Table 1's set-up)" if table1 else "",
                      run["wall"]), "",
                  "| t [s] | front | front of 99.9 % | front of 99 % | centre of mass | slideDAM front | "
                  "left the sheet | highest particle [m] | numerical share of gravity's work | particles |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        dam = dam_fronts([r["t"] for r in run["rows"]])
        for r in run["rows"]:
            d = dam.get(r["t"])
            lines.append("| %g | %.1f | %.1f | %.1f | %.1f | %s | %.2f %% | %.2f | %.1f %% | %d |" % (
                r["t"], r["front"], r["front999"], r["front99"], r["com"], "%.1f" % d if d is not None else "-",
                100.0*r["leftSheet"], r["highest"], 100.0*r["numericalShare"], r["particles"]))
        lines.append("")
    with open(os.path.join(here, "sheetFlow.md"), "w") as f:
        f.write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", type=int, default=10)
    ap.add_argument("--ppc", type=int, default=4)
    ap.add_argument("--end-time", type=float, default=40.0)
    ap.add_argument("--times", default="10,20,30,40")
    ap.add_argument("--mpm", action="append", default=[], help="KEY=VALUE of the variant's mpmDict")
    ap.add_argument("--tag", default="")
    ap.add_argument("--keep", action="store_true", help="keep the run directory")
    ap.add_argument("--stored", action="store_true", help="rewrite sheetFlow.md from sheetFlow.json")
    args = ap.parse_args()
    times = [float(x) for x in args.times.split(",")]
    if max(times) > args.end_time:
        raise SystemExit("sheetFlow.py: --times go beyond --end-time %g s" % args.end_time)
    mpm = {}
    for kv in args.mpm:
        if "=" not in kv:
            raise SystemExit("sheetFlow.py: --mpm %s: not KEY=VALUE" % kv)
        k, v = kv.split("=", 1)
        mpm[k] = v
    if mpm and not args.tag:
        raise SystemExit("sheetFlow.py: --mpm needs --tag, the variant's name")
    path = os.path.join(here, "sheetFlow.json")
    store = json.load(open(path)) if os.path.isfile(path) else {"runs": []}
    if not args.stored:
        work = tempfile.mkdtemp(prefix="slideMPM_sheetFlow_")
        res = run_case(CASE, args.cells, args.ppc, work, numerics=dict(writeFields="yes", **mpm),
                       tag="_sheet" + args.tag, end_time=args.end_time)
        if "failed" in res:
            raise SystemExit("sheetFlow.py: Case 5 H0/%d failed:\n%s" % (args.cells, res["failed"]))
        d = os.path.join(work, "case%02d_h%d_p%d_sheet%s" % (CASE, args.cells, args.ppc, args.tag))
        run = analyse(d, args.cells, args.ppc, args.tag, times, mpm)
        run["wall"] = res["wall"]
        if not mpm and args.cells == 10 and args.ppc == 4 and args.end_time >= 20.0:
            figure(d, scene_of(d)[0], os.path.join(here, "sheetFlow.png"))
        print("Case 5 H0/%d %dx%d%s: analysed %s" % (args.cells, args.ppc, args.ppc, args.tag, d), flush=True)
        if args.keep:
            print("kept %s" % d)
        else:
            shutil.rmtree(work, ignore_errors=True)
        store["runs"] = [r for r in store["runs"]
                         if (r["cells"], r["ppc"], r["tag"]) != (run["cells"], run["ppc"], run["tag"])] + [run]
        with open(path, "w") as f:
            json.dump(store, f, indent=1)
    write_md(store)


if __name__ == "__main__":
    main()
