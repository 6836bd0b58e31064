#!/usr/bin/env python3
"""Why a plug that should slide rigid stretches in slideFoam: the Finneidfjord block's 2 m of 15 kPa clay (its
scene: 500 kg/m3 submerged, no rate effect, no softening, a light ambient, the tutorial's mesh and plug set-up) cut to
20 m and started at 4 m/s on a planar base at the angle where its weight along the slope equals s_b (83.2 Pa, the
constant s_b slideDAM back-analyses for the tutorial), so that a rigid block would slide on at 4 m/s for ever.

A block of s_u 15 kPa and 2 m cannot deform: its spreading stress rho' g H / 2 is 4.9 kPa (slideDAM and slideMPM
keep the tutorial's 60 m block 60 m long: tutorials/finneidfjord/README.md). At each written time (every 10 s)
slideFoam's block is measured from its cells (each 0.5 m column's thickness is the sum of alpha times its cells'
heights): its length (alpha 0.5 on the base, runout.dat), its body (the columns
thicker than 0.6 H0), the tongue on the base ahead of the body and the tail behind it (length, area), the necks
(the body's area short of H0 x its length), and its front: how far behind the foremost column the slide's full
cells (alpha > 0.99) are yielding (their viscosity below a tenth of the cap, i.e. a strain rate over ten times
plugCreepRate).

Variants: default (the tutorial's set-up but its baseSlideTrace, set to 0: s_b on the slide's share of each base face,
the solver's default until session 98),
wholeFace (s_b on every face whose cell holds slide, slideFoam's base until session 90), ambientRelax (the default
with the light ambient relaxed to rest in 0.5 s, cfdDict ambientRelaxationTime), faceViscosity (the slide's
viscosity at each face's own rate), stifferCap (a third of the tutorial's plugCreepRate), slideTrace (base faces
under less than 1e-4 of slide stuck as the ambient's: the traces of plug around the block otherwise leave the base
there frictionless), slideTrace1e-3 and slideTrace1e-2 (the same with floors of 1e-3 and 1e-2), defaultHalfStep and
slideTraceHalfStep (those two with the time step halved, maxDeltaT 0.0025 s), slideTraceAlphaCo (slideTrace with the
interface's Courant number held to 0.035), slideTrace1e-3AlphaCo (slideTrace1e-3 with it held to 0.07).

Usage: validation/cfd/plugStretch.py [--variants default,wholeFace,ambientRelax,faceViscosity,stifferCap,slideTrace,...] [--end 100]
                                      [--cells N] [--speed V] [--work DIR]
       validation/cfd/plugStretch.py --measure CASE
--speed: start the block at this speed instead of 4 m/s (its report plugStretch[_H0_<N>]_V<speed>.md/.json).
--measure: measure a finished, reconstructed slideFoam run of a block instead (the Finneidfjord tutorial's on its
polyline, whose columns stand vertical): the same table, printed, nothing run or written.
(after ./Allwmake; 8-15 minutes a variant on one core, the variants one after the other; writes plugStretch.md
and plugStretch.json beside this script, plugStretch_H0_<N>.md/.json with --cells N)"""
import argparse
import json
import math
import os
import re
import sys
import time

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import (cell_geometry, get_entry, make_case, prepare, read_field, run_slidefoam, time_dirs,  # noqa: E402
                     variant_arguments, write_study)
from slidefoam_io import read_runout  # noqa: E402

TEMPLATE = os.path.join(top, "tutorials", "finneidfjord")
LENGTH, SPEED = 20.0, 4.0
VARIANTS = {
    "default": "the tutorial's set-up but its baseSlideTrace (0): s_b on the slide's share of each base face",
    "wholeFace": "s_b on every face whose cell holds slide (cfdDict baseStrength wholeFace)",
    "ambientRelax": "the default, the light ambient relaxed to rest in 0.5 s (cfdDict ambientRelaxationTime 0.5)",
    "faceViscosity": "the default, the slide's viscosity at each face's own strain rate (cfdDict faceViscosity yes)",
    "stifferCap": "the default at a third of the tutorial's plugCreepRate, a cap three times as high",
    "slideTrace": "the default, base faces whose cell holds under 1e-4 of slide the ambient's (cfdDict baseSlideTrace 1e-4)",
}
EXTRA = {"default": {}, "wholeFace": {"baseStrength": "wholeFace"}, "ambientRelax": {"ambientRelaxationTime": 0.5},
         "faceViscosity": {"faceViscosity": "yes"}, "stifferCap": {"plugCreepRate": "2.461e-4"},
         "slideTrace": {"baseSlideTrace": "1e-4"}}
for floor in ("1e-3", "1e-2"):
    VARIANTS["slideTrace" + floor] = "slideTrace with a floor of %s (cfdDict baseSlideTrace %s)" % (floor, floor)
    EXTRA["slideTrace" + floor] = {"baseSlideTrace": floor}
# The time step halved (the tutorial's maxDeltaT 0.005 s sets it; Co stays under 0.2): whether the front's numerical
# stress at speed is the step's.
CONTROL = {}
for base in ("default", "slideTrace"):
    VARIANTS[base + "HalfStep"] = "%s, maxDeltaT halved to 0.0025 s" % base
    EXTRA[base + "HalfStep"], CONTROL[base + "HalfStep"] = EXTRA[base], {"maxDeltaT": 0.0025}
# The same by interFoam's own knob: the interface's Courant number (cells of 0.01 < alpha < 0.99), which at 7 m/s
# on H0/4 cells is 0.07 at the tutorial's step, capped at 0.035.
VARIANTS["slideTraceAlphaCo"] = "slideTrace, maxAlphaCo 0.035 (the tutorial's 0.5)"
EXTRA["slideTraceAlphaCo"], CONTROL["slideTraceAlphaCo"] = EXTRA["slideTrace"], {"maxAlphaCo": 0.035}
# On H0/8 cells the tutorial's step moves a 7 m/s block 0.14 cells: 0.07, as on H0/4, asks for maxAlphaCo 0.07.
VARIANTS["slideTrace1e-3AlphaCo"] = "slideTrace1e-3, maxAlphaCo 0.07 (the tutorial's 0.5)"
EXTRA["slideTrace1e-3AlphaCo"], CONTROL["slideTrace1e-3AlphaCo"] = EXTRA["slideTrace1e-3"], {"maxAlphaCo": 0.07}


def tutorial_scene():
    """height, density, s_uo, s_b of the Finneidfjord tutorial's block with slideDAM's constant s_b, and the
    tutorial's cfdDict entries but its baseSlideTrace, which is 0 (the variants set their own)."""
    path = os.path.join(TEMPLATE, "constant", "sceneProperties")
    text = open(path).read()
    slide = re.search(r"slide\s*\{([^}]*)\}", text).group(1)
    rheology = re.search(r"rheology\s*\{([^}]*)\}", text).group(1)
    values = {}
    for key, block in (("height", slide), ("density", slide), ("s_uo", rheology)):
        m = re.search(r"\b%s\s+([-\d.eE+]+)\s*;" % key, block)
        if not m:
            raise SystemExit("%s: no key '%s'" % (path, key))
        values[key] = float(m.group(1))
    # slideDAM's back-analysed constant s_b for the tutorial's runout (validation/backAnalysis).
    path = os.path.join(top, "validation", "backAnalysis", "backAnalysis.json")
    rows = [r for r in json.load(open(path)) if r.get("study") == "Finneidfjord block, constant s_b"]
    if not rows or "slideDAM" not in rows[0]:
        raise SystemExit("%s: no slideDAM row for the study 'Finneidfjord block, constant s_b'" % path)
    values["s_b"] = float(rows[0]["slideDAM"]["result"]["best"]["value"])
    cfd = {}
    for line in open(os.path.join(TEMPLATE, "system", "cfdDict")):
        m = re.match(r"^\s*(\w+)\s+([^;]+);", line)
        # The base's trace floor is a variant here (slideTrace...): "default" is the share alone, as the tutorial
        # was until session 96 set baseSlideTrace 1e-3 (and the solver until session 98).
        if m and m.group(1) not in ("FoamFile", "version", "format", "class", "object", "baseSlideTrace"):
            cfd[m.group(1)] = m.group(2).strip()
    cfd["baseSlideTrace"] = "0"
    return values, cfd


def case_name(variant, cells, speed=SPEED):
    """A run's directory: the variant's name, with its mesh where that is not the tutorial's and its start speed
    where that is not SPEED."""
    return variant + ("" if cells is None else "_H0_%d" % cells) + ("" if speed == SPEED else "_V%g" % speed)


def block_case(variant, work, end, cells, speed=SPEED):
    sc, cfd = tutorial_scene()
    angle = math.degrees(math.asin(sc["s_b"] / (sc["density"] * 9.81 * sc["height"])))
    text = ("FoamFile { version 2.0; format ascii; class dictionary; object sceneProperties; }\n"
            "title \"the Finneidfjord block at the angle where its weight matches s_b\";\ng 9.81;\n"
            "slide { shape rectangle; length %g; height %g; rearPosition 0; density %g; }\n"
            "rheology { model HerschelBulkleyRemoulding; s_uo %g; eta 0; deltaRem 1; }\n"
            "base { profile planar; angle %.6f; interface frictional; s_b %.10g; }\nambient { phase light; }\n"
            % (LENGTH, sc["height"], sc["density"], sc["s_uo"], angle, sc["s_b"]))
    # Serial, on a mesh that reaches as far as the rigid block slides.
    cfd = dict(cfd, processors=1, reach=int(speed * end + 20), behind=10, **EXTRA[variant])
    if cells is not None:
        cfd["cellsPerHeight"] = cells
    control = dict({"endTime": end, "writeInterval": 10}, **CONTROL.get(variant, {}))
    d = make_case(TEMPLATE, work, case_name(variant, cells, speed), control=control, cfd=cfd,
                  dicts={"constant/sceneProperties": text})
    prepare(d)
    # The slide at its start speed along the slope, the ambient at rest.
    path = os.path.join(d, "0", "U")
    alpha = np.clip(read_field(d, "0", "alpha.slide"), 0, 1)
    body = "internalField   nonuniform List<vector>\n%d\n(\n%s\n)\n;" % (
        len(alpha), "\n".join("(%.6g 0 0)" % (speed * a) for a in alpha))
    text = open(path).read()
    new = re.sub(r"internalField\s+uniform\s*\([^)]*\)\s*;", body, text, count=1)
    if new == text:
        raise SystemExit("%s: no uniform internalField to replace" % path)
    with open(path, "w") as f:
        f.write(new)
    t0 = time.time()
    run_slidefoam(d)
    with open(os.path.join(d, "wall.txt"), "w") as f:
        f.write("%.0f\n" % (time.time() - t0))
    return d


def shape(d, H0):
    """Per written time: the block's columns, measured from its cells."""
    V, Cx, _ = cell_geometry(d)
    Cx = np.round(Cx, 6)
    xs = np.unique(Cx)
    dx = float(np.median(np.diff(xs)))
    column = np.searchsorted(xs, Cx)
    # slideFoamCase's meshes span z from 0 to their depth (meshLayout.C), planar or over a polyline.
    depth = 2 * float(read_field(d, "0", "Cz")[0])
    muMax = float(get_entry(os.path.join(d, "constant", "transportProperties"), "muMax"))
    # The slide phase is transportProperties' first.
    rho = float(get_entry(os.path.join(d, "constant", "transportProperties"), "rho"))
    r = read_runout(os.path.join(d, "postProcessing", "slideFoam", "runout.dat"))
    rows = []
    for t in time_dirs(d):
        if not os.path.exists(os.path.join(d, t, "alpha.slide")):
            continue
        a = np.clip(read_field(d, t, "alpha.slide"), 0, 1)
        h = np.bincount(column, weights=a * V, minlength=len(xs)) / (dx * depth)
        live = np.where(h > 0.01)[0]
        thick = np.where(h > 0.6 * H0)[0]
        rear, front = thick[0], thick[-1]
        ahead = live[live > front]
        behind = live[live < rear]
        k = int(np.argmin(np.abs(r["time"] - float(t))))
        row = {"t": float(t), "length": float(r["front"][k] - r["rear"][k]), "speed": float(r["frontVelocity"][k]),
               "body": float((front - rear + 1) * dx), "tongue": float(len(ahead) * dx),
               "tongue_area": float(h[ahead].sum() * dx), "tail": float(len(behind) * dx),
               "tail_area": float(h[behind].sum() * dx),
               "neck_deficit": float(np.clip(H0 - h[rear:front + 1], 0, None).sum() * dx)}
        if os.path.exists(os.path.join(d, t, "nu1")):
            mu = rho * read_field(d, t, "nu1")
            yielding = (a > 0.99) & (mu < 0.1 * muMax)
            xf = xs[live[-1]] + 0.5 * dx
            xr = xs[live[0]] - 0.5 * dx
            mid = 0.5 * (xf + xr)
            row["front_yield"] = float(xf - Cx[yielding & (Cx > mid)].min()) if (yielding & (Cx > mid)).any() else 0.0
            row["rear_yield"] = float(Cx[yielding & (Cx < mid)].max() - xr) if (yielding & (Cx < mid)).any() else 0.0
            row["full_cells"] = int((a > 0.99).sum())
            row["yielding_cells"] = int(yielding.sum())
        rows.append(row)
    return rows


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--end", type=float, default=100.0)
    ap.add_argument("--cells", type=int, default=None, help="cells per H0 (default: the tutorial's cfdDict)")
    ap.add_argument("--speed", type=float, default=SPEED, help="the block's start speed, m/s (default %g)" % SPEED)
    ap.add_argument("--measure", default=None, help="a finished, reconstructed block run to measure (no run)")
    args, variants, work = variant_arguments(ap, VARIANTS, "plugStretch", "a variant already run there to --end "
                                             "(its runout.dat reaching it) is read, not rerun")
    H0 = tutorial_scene()[0]["height"]
    if args.measure:
        print_rows(shape(args.measure, H0))
        return
    results = {}
    for v in variants:
        d = os.path.join(work, case_name(v, args.cells, args.speed))
        runout = os.path.join(d, "postProcessing", "slideFoam", "runout.dat")
        done = os.path.exists(runout) and read_runout(runout)["time"][-1] >= args.end - 1e-6
        if not done:
            print("%s: running slideFoam to %g s (serial)" % (v, args.end), flush=True)
            d = block_case(v, work, args.end, args.cells, args.speed)
        wall = os.path.join(d, "wall.txt")
        results[v] = {"rows": shape(d, H0), "wall": float(open(wall).read()) if os.path.exists(wall) else None}
        last = results[v]["rows"][-1]
        print("%-12s at %g s: length %.2f m, body %.1f m, tongue %.1f m (%.2f m2), neck deficit %.2f m2"
              % (v, last["t"], last["length"], last["body"], last["tongue"], last["tongue_area"],
                 last["neck_deficit"]), flush=True)
    write_report(results, args)


def row_cells(x):
    """A measured time's table cells after its time: speed, length, body, tongue, tail, necks, yielding."""
    y = ("%.1f, %.1f" % (x["front_yield"], x["rear_yield"])) if "front_yield" in x else "-"
    c = ("%d of %d" % (x["yielding_cells"], x["full_cells"])) if "full_cells" in x else "-"
    return ("%.3f | %.2f | %.1f | %.1f, %.2f | %.1f, %.2f | %.2f | %s | %s"
            % (x["speed"], x["length"], x["body"], x["tongue"], x["tongue_area"], x["tail"], x["tail_area"],
               x["neck_deficit"], y, c))


HEADER = ("t [s] | speed [m/s] | length [m] | body [m] | tongue [m], [m2] | tail [m], [m2] | neck deficit [m2] "
          "| yielding from the front, rear [m] | yielding cells of full")


def print_rows(rows):
    print(HEADER)
    for x in rows:
        if x["t"] > 0:
            print("%g | %s" % (x["t"], row_cells(x)))


def write_report(results, args):
    sc, cfd = tutorial_scene()
    mesh = ("its mesh H0/%s" % cfd["cellsPerHeight"]) if args.cells is None else ("a mesh of H0/%d" % args.cells)
    name = "plugStretch" + ("" if args.cells is None else "_H0_%d" % args.cells) + (
        "" if args.speed == SPEED else "_V%g" % args.speed)
    lines = ["# A plug that should slide rigid: slideFoam's stretch of the Finneidfjord block",
             "",
             "Written by `validation/cfd/plugStretch.py --end %g%s%s`. The tutorial's block (H0 %g m, s_uo %g Pa, "
             "%g kg/m3, no rate effect, the tutorial's plug set-up, %s) cut to %g m, started at %g m/s "
             "on a planar base at the angle where its weight along the slope equals s_b = %.2f Pa: a rigid block "
             "slides on at %g m/s. Its spreading stress rho' g H0/2 = %.1f kPa is a third of s_u, so it cannot "
             "deform. Body: the columns thicker than 0.6 H0; tongue and tail: the slide on the base ahead of and "
             "behind it; necks: the body's area short of H0 over its length; yielding: full cells (alpha > 0.99) "
             "whose viscosity is below a tenth of the cap, how far they reach from the block's ends."
             % (args.end, "" if args.cells is None else " --cells %d" % args.cells,
                "" if args.speed == SPEED else " --speed %g" % args.speed,
                sc["height"], sc["s_uo"], sc["density"], mesh, LENGTH, args.speed, sc["s_b"], args.speed,
                sc["density"] * 9.81 * sc["height"] / 2 / 1000),
             "",
             "| variant | wall [s] |",
             "|---|---|"]
    for v, r in results.items():
        lines.append("| %s: %s | %s |" % (v, VARIANTS[v], "%.0f" % r["wall"] if r["wall"] else "-"))
    lines += ["", "| variant | %s |" % HEADER, "|---|---|---|---|---|---|---|---|---|---|"]
    for v, r in results.items():
        for x in r["rows"]:
            if x["t"] == 0 or (x["t"] % 20 and x["t"] != r["rows"][-1]["t"]):
                continue
            lines.append("| %s | %g | %s |" % (v, x["t"], row_cells(x)))
    write_study(here, name, lines, results)


if __name__ == "__main__":
    main()
