#!/usr/bin/env python3
"""How strong a block slideFoam can slide: a rectangular block released on a frictionless base (frictional, s_b 0),
for strengths s_uo from half its weight's stress rho' g H0 to 64 times it, against the rigid block's law
(centre of mass g sin(theta) (1 - rho_ambient/rho') t^2/2). A block whose faces stand (4 s_uo > rho' g H0) and that
nothing shears from below does not yield: every strength here gives the same rigid block, so any difference between
the rows is the solver's.

Two blocks, each at H0/10 with the solver's defaults (maxDeltaT as the case sets it, one outer corrector):
- the Krone-Wright flume's slurry without its end wall (1.8 m x 0.3 m, 1073 kg/m3, 3.43 deg; the scene of
  slideFoam_base's frictionless block), to 2 s;
- Table 1 Case 9's block (40 m x 5 m, 600 kg/m3, 5 deg), its rate effect off (eta 0, so that s_uo is the strength at
  every rate), to 3 s.
Each row: the centre of mass's travel against the law, the spread of the downslope velocity over the cells full of
slide (alpha > 0.99; a rigid block has none), the largest normal velocity there, and a blow-up's time.

Usage: validation/cfd/strongBlock.py [--ratios 0.5,1,2,3.2,4,8,16,32,64] [--work DIR] [--jobs 2]
(after ./Allwmake; about 5 minutes on 2 cores; writes strongBlock.md and strongBlock.json beside this script)"""
import argparse
import json
import math
import os
import re
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import make_case, prepare, read_field, run, time_dirs  # noqa: E402
from runner import which  # noqa: E402
from scene_variants import foam_dictionary  # noqa: E402

BLOCKS = [
    {"name": "flume", "title": "Krone-Wright flume's slurry, 0.3 m", "tutorial": "tutorials/kroneWrightRun15",
     "scene": {"rearWall": "no"}, "cfd": {"reach": 8, "behind": 4}, "end": 2.0},
    {"name": "case09", "title": "Table 1 Case 9's block, 5 m, rate effect off", "tutorial": "tutorials/table1/case09",
     "scene": {"eta": 0}, "cfd": {"reach": 60, "behind": 10}, "end": 3.0},
]


def scene_numbers(tutorial):
    """rho' [kg/m3], H0 [m], theta [rad], ambient density [kg/m3] of the tutorial's scene (a light ambient's 1 kg/m3
    where it gives none, as the scene reader takes it)."""
    path = os.path.join(top, tutorial, "constant", "sceneProperties")

    def value(key, default=None):
        rc, out = foam_dictionary("-entry", key, "-value", path)
        if rc != 0:
            if default is None:
                raise SystemExit("%s: no entry '%s'" % (path, key))
            return default
        return float(out.strip())
    return (value("slide/density"), value("slide/height"), math.radians(value("base/angle")),
            value("ambient/density", 1.0))


def run_block(block, ratio, work):
    rho, height, theta, rho_ambient = scene_numbers(block["tutorial"])
    s_uo = ratio*rho*9.81*height
    name = "%s_ratio%g" % (block["name"], ratio)
    end = block["end"]
    c = make_case(os.path.join(top, block["tutorial"]), work, name, scene=dict(block["scene"], s_uo="%.6g" % s_uo),
                  control={"endTime": end, "writeInterval": end/4}, cfd=dict({"cellsPerHeight": 10}, **block["cfd"]))
    path = os.path.join(c, "constant", "sceneProperties")
    text, n = re.subn(r"interface\s+\w+;(\s*s_b\s+[0-9.eE+-]+;)?", "interface frictional;\n    s_b 0;",
                      open(path).read(), count=1)
    assert n == 1, path
    open(path, "w").write(text)
    prepare(c)
    rc = run(c, which("slideFoam"), check=False)
    log = open(os.path.join(c, "log.slideFoam")).read()
    blow = re.search(r"blow-up at time ([0-9.eE+-]+) s: \|U\| = ([0-9.eE+-]+) m/s, alpha = ([0-9.eE+-]+)", log)
    row = {"block": block["name"], "ratio": ratio, "s_uo": s_uo, "exit": rc, "end": end,
           "blowUp": {"time": float(blow.group(1)), "speed": float(blow.group(2)), "alpha": float(blow.group(3))}
           if blow else None}
    last = time_dirs(c)[-1]
    row["time"] = float(last)
    rigid_acc = 9.81*math.sin(theta)*(1 - rho_ambient/rho)
    row["rigid"] = 0.5*rigid_acc*row["time"]**2
    if row["time"] > 0:
        run(c, "postProcess", "-func", "writeCellCentres", "-time", "0")
        x = read_field(c, "0", "C")[:, 0]
        a0, a1 = read_field(c, "0", "alpha.slide"), read_field(c, last, "alpha.slide")
        row["travel"] = float((a1*x).sum()/a1.sum() - (a0*x).sum()/a0.sum())
        U = read_field(c, last, "U")
        full = a1 > 0.99
        row["speedMean"] = float(U[full, 0].mean())
        row["speedSpread"] = float(U[full, 0].std())
        row["normalMax"] = float(np.abs(U[full, 1]).max())
        row["rigidSpeed"] = rigid_acc*row["time"]
    return row


def write(rows, blocks):
    with open(os.path.join(here, "strongBlock.json"), "w") as f:
        json.dump(rows, f, indent=1)
    out = ["# How strong a block slideFoam can slide", "",
           "Regenerated by `strongBlock.py` (its docstring: the set-up). A block released on a frictionless base; "
           "every strength gives the same rigid block (its faces stand, nothing shears it from below), so the rows "
           "should all be the rigid block's law. ratio: s_uo / (rho' g H0). Travel: the centre of mass's, against "
           "the law's at the same time. Spread: the standard deviation of the downslope velocity over the cells "
           "full of slide, against their mean.", ""]
    for block in blocks:
        rho, height, theta, _ = scene_numbers(block["tutorial"])
        out += ["## %s (rho' g H0 = %.0f Pa), to %g s" % (block["title"], rho*9.81*height, block["end"]), "",
                "| ratio | s_uo [Pa] | ended at [s] | travel [m] | rigid law [m] | error | mean speed [m/s] | "
                "rigid speed [m/s] | spread | largest normal speed [m/s] | blow-up |",
                "|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in (r for r in rows if r["block"] == block["name"]):
            b = r["blowUp"]
            cells = ["%g" % r["ratio"], "%.4g" % r["s_uo"], "%.4g" % r["time"]]
            if "travel" in r:
                cells += ["%.4f" % r["travel"], "%.4f" % r["rigid"], "%+.1f %%" % (100*(r["travel"]/r["rigid"] - 1)),
                          "%.3f" % r["speedMean"], "%.3f" % r["rigidSpeed"],
                          "%.1f %%" % (100*r["speedSpread"]/abs(r["speedMean"])), "%.3f" % r["normalMax"]]
            else:
                cells += ["-"]*7
            cells.append("%.4g s: %.3g m/s at alpha %.2g" % (b["time"], b["speed"], b["alpha"]) if b else "-")
            out.append("| " + " | ".join(cells) + " |")
        out.append("")
    with open(os.path.join(here, "strongBlock.md"), "w") as f:
        f.write("\n".join(out))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ratios", default="0.5,1,2,3.2,4,8,16,32,64")
    ap.add_argument("--work", default=os.path.join(top, "platforms", "validation-work", "strongBlock"))
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    try:
        ratios = [float(r) for r in args.ratios.split(",")]
    except ValueError:
        raise SystemExit("--ratios: a comma-separated list of numbers, got '%s'" % args.ratios)
    os.makedirs(args.work, exist_ok=True)
    jobs = [(b, r) for b in BLOCKS for r in ratios]
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = list(pool.map(lambda job: run_block(job[0], job[1], args.work), jobs))
    for r in rows:
        print("%s ratio %g: %s" % (r["block"], r["ratio"], "travel %.4f m (rigid %.4f m) at %g s" % (
            r["travel"], r["rigid"], r["time"]) if "travel" in r else "no write"), flush=True)
    write(rows, BLOCKS)


if __name__ == "__main__":
    main()
