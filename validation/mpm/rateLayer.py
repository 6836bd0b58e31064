#!/usr/bin/env python3
"""Eq. (1)'s shear layer on a no-slip base in slideMPM, against its exact steady profile: how fast a layer of Table 1
Case 1's clay (s_uo 150 Pa, eta 0.35, n 0.15, gdot_ref 0.06 1/s, rho' 600 kg/m3, 3.43 deg) flows when the cell is
thicker than the layer's own shear layer, with Eq. (1)'s rate taken per cell and per band (mpmDict shearBandRate,
band H0/60 of Table 1 = 0.0833 m).

Why: at n = 0.15 the steady layer's rate falls by e over l = n (tau_b - s_uo)/(rho' g S) above the base (4.1 cm for a
0.7 m layer, 2.6 cm for 0.6 m; validation/lib/layerProfile.py), and nearly all of its slip happens there. A cell
thicker than l spreads that slip over the cell, so at a given slip its rate, and Eq. (1)'s strength, is lower: the
layer runs faster than Eq. (1)'s. Taken per band the rate is the cell's times cell/band, as if the slip crossed a band
of the given thickness: right where the band is l, and a fixed error elsewhere. What a runout sees of this is where the
deposit stops (README, open problem 5); this is the same question on a layer with an exact answer.

The layer (80 m x 0.7 m, released from its geostatic state) is written every 2 s. In its middle (the particles
weighed by a tent 10 m wide) its thickness (mass over rho'), the slope of that thickness along the base and its plug
speed (the mean velocity of the top half of its particles) are set beside the exact plug speed of a layer of that
thickness, driven by its weight and by its hydrostatic pressure's gradient: a finite layer is not uniform (its rear
stays put, so it stretches downslope), and the plug's speed grows as the thickness, or the driving stress, to the
power 20 here (m tau_b/(tau_b - s_uo), m = (n + 1)/n). The exact layer relaxes in about 3.6 s
(rho h U/((tau_b - s_uo) l)); the windows average 24-32 and 32-40 s. --case 2 runs a 2.4 m layer of Case 2's clay
(s_uo 500 Pa, eta 0.45, n 0.23: plug 0.071 m/s, l = 0.23 m), whose weak slide shortens with the cell too. Writes
rateLayer.md and rateLayer.json beside itself; --import analyses finished run directories instead of running.

Usage: validation/mpm/rateLayer.py [--case 1] [--cells 2,4,8] [--ppc 4] [--rates cell,band] [--transfers apic,quadratic]
       [--work DIR] [--stored] [--import DIR ...]   (after ./Allwmake; cells per layer height: 2, 4, 8 are Table 1's
       H0/14, H0/29, H0/57 for Case 1's layer and H0/4, H0/8, H0/17 for Case 2's; on 2 cores Case 1 H/8 takes about
       10 minutes a run, Case 2 H/16 11 minutes, the others seconds to 1.5 minutes)"""
import argparse
import json
import math
import os
import re
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import make_case  # noqa: E402
from layerProfile import CASE1, G, RHO, S, THETA, exact  # noqa: E402
from runner import run_method  # noqa: E402
from slidefoam_io import particles_on_planar_base, read_summary  # noqa: E402

import numpy as np  # noqa: E402

# The layer of each Table 1 case's clay (its tutorial's sceneProperties; both on 3.43 deg): thick enough to flow at
# 0.07-0.12 m/s in steady state, a little thicker than their deposits (Case 1 0.6 m, Case 2 2.0 m in slideDAM).
LAYERS = {1: {"material": CASE1, "height": 0.7},
          2: {"material": {"s_uo": 500.0, "eta": 0.45, "n": 0.23, "gdotRef": 0.06}, "height": 2.4}}
LENGTH = 80.0
BAND = 5.0/60.0                    # Table 1's H0/60, as the remoulding tutorials' shearBandThickness
WINDOWS = ((24.0, 32.0), (32.0, 40.0))
END = WINDOWS[-1][1]
HALF_WINDOW = 5.0                 # the tent over the middle that weighs the particles [m]


def middle(case, t):
    """Thickness, its slope along the base, plug speed and basal plastic rate of the layer's middle at the frame
    nearest t. The particles are weighed by a tent over the middle 10 m, so that one crossing its edge changes
    nothing at once (counted in or out of a window the thickness jumps by a particle's share, and the exact plug
    speed by 20 times that). The slope is the first moment of the mass under a tent 20 m wide: for h = h0 + g x,
    sum m x T(x) = rho g int x^2 T dx = rho g L^3/6 (T(x) = 1 - |x|/L), a weight that vanishes at its ends too."""
    s, n, u, arr = particles_on_planar_base(case, t, THETA)
    mid = 0.5*(s.min() + s.max())
    w = np.maximum(1.0 - np.abs(s - mid)/HALF_WINDOW, 0.0)
    near = w > 0.0
    z = n - n[near].min()
    thickness = float((w*arr["mass"]).sum()/(RHO*HALF_WINDOW))
    x = s - mid
    L = 2.0*HALF_WINDOW
    moment = x*np.maximum(1.0 - np.abs(x)/L, 0.0)/(L**3/6.0)
    slope = float((arr["mass"]*moment).sum()/RHO)
    # The stretching layer's longitudinal deviatoric stress, which the exact layer leaves out: the same moment of
    # the particles' V (sigma_ss - sigma_nn) is d/ds of its depth integral, a traction per unit base [Pa].
    c, sn = math.cos(math.radians(THETA)), math.sin(math.radians(THETA))
    sxx, szz, sxz = arr["sigma_xx"], arr["sigma_zz"], arr["sigma_xz"]
    deviator = (c*c - sn*sn)*(sxx - szz) - 4.0*c*sn*sxz
    longitudinal = float((arr["volume"]*deviator*moment).sum())
    top = near & (z > 0.5*thickness)
    bottom = near & (z < 0.25*thickness)
    return (thickness, slope, float((w*u)[top].sum()/w[top].sum()),
            float(np.average(arr["plasticShearStrainRate"][bottom], weights=w[bottom])), longitudinal)


def run(work, case, cells, ppc, rate, transfer="apic", app="slideMPM"):
    name = "rateLayer_case%d_h%d_p%d_%s_%s" % (case, cells, ppc, rate, transfer)
    mpm = ("setting fast;\ncellsPerHeight %d;\nparticlesPerCell %d;\ntransfer %s;\nwriteState no;\nprogressInterval 30;\n"
           % (cells, ppc, transfer))
    if rate == "band":
        mpm += "shearBandThickness %.7g;\nshearBandRate yes;\n" % BAND
    d = make_case(os.path.join(top, "tutorials", "table1", "case%02d" % case), work, name,
                  scene={"length": LENGTH, "height": LAYERS[case]["height"]},
                  control={"endTime": END, "writeInterval": 2, "stopAtRest": "no"},
                  dicts={"system/mpmDict": mpm})
    run_method(app, d)
    return analyse(d, case, cells, ppc, rate, transfer)


def analyse(d, case, cells, ppc, rate, transfer):
    """The row of rateLayer.json from a finished run in directory d."""
    summary = read_summary(os.path.join(d, "postProcessing", "slideMPM", "summary.json"))
    H, material = LAYERS[case]["height"], LAYERS[case]["material"]
    r = {"case": case, "cells": cells, "ppc": ppc, "rate": rate, "transfer": transfer, "cell_m": H/cells,
         "wall": summary["wall_time_s"], "particles": summary["problem_size"], "history": [], "windows": []}
    for t in range(2, int(END) + 1, 2):
        h, slope, plug, basal, longitudinal = middle(d, float(t))
        r["history"].append({"t": t, "thickness": h, "surfaceSlope": slope, "plug": plug, "basalPlasticRate": basal,
                             "longitudinalDeviatoric": longitudinal})
    for t0, t1 in WINDOWS:
        rows = [x for x in r["history"] if t0 <= x["t"] <= t1]
        h = float(np.mean([x["thickness"] for x in rows]))
        slope = float(np.mean([x["surfaceSlope"] for x in rows]))
        plug = float(np.mean([x["plug"] for x in rows]))
        longitudinal = float(np.mean([x["longitudinalDeviatoric"] for x in rows]))
        ex = exact(h, material=material, surface_slope=slope)
        r["windows"].append({"t0": t0, "t1": t1, "thickness": h, "surfaceSlope": slope, "plug": plug,
                             "longitudinalDeviatoric": longitudinal,
                             "exactPlug": ex["plug"], "exactPlugUniform": exact(h, material=material)["plug"],
                             "decayLength": ex["decay_length"], "basalRate": ex["basal_rate"]})
    return r


def imported(d):
    """analyse() of a run directory named as run() names them (rateLayer_case<C>_h<cells>_p<ppc>_<rate>_<transfer>;
    before --case, rateLayer_h<cells>_p<ppc>_<rate>_<transfer> for Case 1)."""
    m = re.search(r"rateLayer_(?:case(\d+)_)?h(\d+)_p(\d+)_(cell|band)_(apic|quadratic)$", d.rstrip("/"))
    if not m:
        raise SystemExit("rateLayer.py: --import %s: not a run directory rateLayer_case<C>_h<cells>_p<ppc>_<rate>_"
                         "<transfer>" % d)
    return analyse(d, int(m.group(1) or 1), int(m.group(2)), int(m.group(3)), m.group(4), m.group(5))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", type=int, default=1, choices=sorted(LAYERS), help="whose clay (Table 1 case)")
    ap.add_argument("--cells", default="2,4,8")
    ap.add_argument("--ppc", type=int, default=4)
    ap.add_argument("--rates", default="cell,band")
    ap.add_argument("--transfers", default="apic", help="apic, quadratic or both (comma-separated)")
    ap.add_argument("--work", default=None)
    ap.add_argument("--stored", action="store_true", help="rewrite rateLayer.md from rateLayer.json without running")
    ap.add_argument("--import", dest="imports", nargs="*", default=[],
                    help="finished run directories to analyse and store instead of running")
    args = ap.parse_args()
    path = os.path.join(here, "rateLayer.json")
    stored = json.load(open(path)) if os.path.isfile(path) else []
    if args.stored:
        write_table(stored)
        return
    work = args.work or tempfile.mkdtemp(prefix="rateLayer_")
    results = [imported(d) for d in args.imports]
    for cells in [] if args.imports else [int(c) for c in args.cells.split(",")]:
        for rate, transfer in ((r, t) for r in args.rates.split(",") for t in args.transfers.split(",")):
            r = run(work, args.case, cells, args.ppc, rate, transfer)
            results.append(r)
            w = r["windows"][-1]
            print("Case %d's clay, cell H/%d, rate per %s, %s: %.4f m thick, plug %.4f m/s against %.4f m/s exact "
                  "(%.2f x); %.0f s"
                  % (args.case, cells, rate, transfer, w["thickness"], w["plug"], w["exactPlug"], w["plug"]/w["exactPlug"],
                     r["wall"]), flush=True)
    # Runs of other set-ups stay (a run replaces the stored one of its cell, particles, rate and transfer).
    key = lambda r: (r["case"], r["cells"], r["ppc"], r["rate"], r["transfer"])
    new = {key(r) for r in results}
    results = sorted([r for r in stored if key(r) not in new] + results,
                     key=lambda r: (r["case"], r["transfer"], r["ppc"], r["cells"], r["rate"]))
    with open(path, "w") as f:
        json.dump(results, f, indent=1)
    write_table(results)


def excess_strength(w, material):
    """The basal stress [Pa] by which the exact layer as thick as the MPM's would have to be held back to flow at the
    MPM's plug speed: its plug speed goes as (tau_b - s_uo)^m, m = (n + 1)/n."""
    tau_b = RHO*G*(S - math.cos(math.radians(THETA))*w["surfaceSlope"])*w["thickness"]
    m = (material["n"] + 1.0)/material["n"]
    return (tau_b - material["s_uo"])*(1.0 - (w["plug"]/w["exactPlug"])**(1.0/m)), tau_b


def write_table(results):
    lines = ["# Eq. (1)'s shear layer on a no-slip base in slideMPM (written by rateLayer.py)"]
    for case in sorted({r["case"] for r in results}):
        rows = [r for r in results if r["case"] == case]
        H, material = LAYERS[case]["height"], LAYERS[case]["material"]
        e0 = exact(H, material=material)
        lines += ["", "## Table 1 Case %d's clay" % case, "",
                  "%g m x %g m layer of Table 1 Case %d's clay (s_uo %g Pa, eta %g, n %g, gdot_ref %g 1/s), rho' %g "
                  "kg/m3, %.2f deg, released from its geostatic state; Eq. (1)'s rate per cell, or per band of %.4f m "
                  "(Table 1's H0/60; `shearBandRate yes`). Exact steady layer %g m thick: plug %.4f m/s, basal rate "
                  "%.2f 1/s, decay length l = %.4f m. The middle of the layer (a tent 10 m wide): its thickness (mass / "
                  "rho') and its slope along the base (dh/ds, from a tent 20 m wide), its plug speed (the top half's "
                  "mean velocity, tent-weighted), and the exact plug speed of a layer that thick, driven by its weight "
                  "and by its pressure's gradient, rho g h (S - cos(theta) dh/ds) at the base (in brackets: without the "
                  "gradient's share, as if the layer were uniform); left out of it, the gradient of the stretching "
                  "layer's longitudinal deviatoric stress (d/ds of the depth integral of sigma_ss - sigma_nn, from "
                  "the particles), as a share of tau_b: the comparison's resolution; the excess basal strength is the "
                  "stress by which that exact layer would have to be held back to flow at the MPM's plug speed (its plug speed goes as (tau_b - s_uo)^m, m = (n + 1)/n = "
                  "%.2f): what the MPM's base holds beyond Eq. (1). The script's docstring says why."
                  % (LENGTH, H, case, material["s_uo"], material["eta"], material["n"], material["gdotRef"], RHO,
                     THETA, BAND, H, e0["plug"], e0["basal_rate"], e0["decay_length"],
                     (material["n"] + 1.0)/material["n"]), "",
                  "| cell [m] | Eq. (1)'s rate | transfer | particles per cell | window [s] | thickness [m] | dh/ds | "
                  "plug [m/s] | exact plug, same thickness and slope (uniform) [m/s] | longitudinal deviator | "
                  "MPM / exact | excess basal strength [Pa] (of tau_b) | exact l [m] | particles | wall [s] |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in rows:
            for w in r["windows"]:
                excess, tau_b = excess_strength(w, material)
                lines.append("| %.4f (H/%d) | per %s | %s | %dx%d | %g-%g | %.4f | %.5f | %.4f | %.4f (%.4f) | "
                             "%+.1f %% | %.2f | %.1f (%.1f %%) | %.4f | %d | %.0f |"
                             % (r["cell_m"], r["cells"], r["rate"], r["transfer"], r["ppc"], r["ppc"],
                                w["t0"], w["t1"], w["thickness"], w["surfaceSlope"], w["plug"], w["exactPlug"],
                                w["exactPlugUniform"], 100.0*w["longitudinalDeviatoric"]/tau_b,
                                w["plug"]/w["exactPlug"], excess, 100.0*excess/tau_b, w["decayLength"], r["particles"],
                                r["wall"]))
        lines += ["", "Histories of the middle (time [s]: thickness [m], dh/ds, plug speed [m/s], mean plastic rate "
                  "of the bottom quarter [1/s]):", ""]
        for r in rows:
            lines.append("- H/%d, %dx%d, per %s, %s: " % (r["cells"], r["ppc"], r["ppc"], r["rate"],
                                                        r["transfer"])
                         + "; ".join("%d: %.4f, %.5f, %.4f, %.3f" % (x["t"], x["thickness"], x["surfaceSlope"],
                                                                     x["plug"], x["basalPlasticRate"])
                                     for x in r["history"]))
    with open(os.path.join(here, "rateLayer.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % os.path.join(here, "rateLayer.md"))


if __name__ == "__main__":
    main()
