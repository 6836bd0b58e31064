#!/usr/bin/env python3
"""Does slideMPM's under-resolved-front warning fire where Table 1's runouts depend on the cell, and only there?

Why: session 61 (frontZone.md) found that a weak slide's runout changes with the cell where its flowing front is
under about three cells thick, on Cases 1 and 2. slideMPM now measures, at every write, the slide's foremost H0 along
the base (its particles' volume over that length is its thickness, their mass-weighted velocity along the base its
speed), warns the first time that zone moves under three cells thick, and writes to summary.json the fewest cells
through it while it moved and how far the front ran after writes that found it under three (front_* entries;
applications/solvers/slideMPM/frontResolution.H). That rule was read off two cases; here it meets the others, whose
runouts at two or more cells are stored in table1.json, so the comparison is out of sample for every case but 1 and 2.

Each case is run with 4x4 particles at each of --cells to its scene's end, or to --cut's time for the long ones
(the front's travel under three cells is counted to that time). The runouts whose cell dependence is the check are
table1.json's, as stored: the change from each cell to the next finer one stored there.

Writes frontResolution.md and frontResolution.json beside itself; --stored rewrites the md from the json.

Usage: validation/mpm/frontResolution.py [--cases 1,2,3,4,6,7,9,10,12,13] [--cells 10,20] [--cut 3:100,4:130,10:60,13:60]
       [--stored]
(after ./Allwmake; on 2 cores H0/10 takes about 15 minutes for the ten cases, H0/20 about 75 minutes for
Cases 1, 2, 10 and 13 to 60 s, 12 and the face collapses)"""
import argparse
import json
import os
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from table1 import run_case  # noqa: E402
from slidefoam_io import front_at  # noqa: E402

RESOLVED_CELLS = 3   # slideMPM's FrontResolution::resolvedCells, which the warning uses
CONVERGED = 0.02     # a change within 2 % per halving counts as converged, as the cheaper set-up


def stored_runouts():
    """{case: {cells: row}} of table1.json's 4x4 rows with the touching contact."""
    rows = json.load(open(os.path.join(here, "table1.json")))
    out = {}
    for r in rows:
        if r.get("ppc") == 4 and r.get("runout") is not None and r.get("baseContact") == "touching":
            out.setdefault(r["case"], {})[r["cells"]] = r
    return out


def front_then(row, t):
    """A stored row's front travel at time t: its runout if it came to rest before."""
    if row.get("atRest") and t >= row["endTime"]:
        return row["runout"]
    return front_at([h[:2] for h in row["history"]], t)


def next_finer_change(stored, case, cells):
    """(the next finer stored cell, the relative change of the front travel to it, the time compared: the
    runouts where both came to rest, else the fronts at the earlier end), or (None, None, None)."""
    runs = stored.get(case, {})
    finer = sorted(c for c in runs if c > cells)
    if cells not in runs or not finer:
        return None, None, None
    a, b = runs[cells], runs[finer[0]]
    t = min(float("inf") if r.get("atRest") else r["endTime"] for r in (a, b))
    if t == float("inf"):
        return finer[0], b["runout"]/a["runout"] - 1.0, None
    return finer[0], front_then(b, t)/front_then(a, t) - 1.0, t


def row_of(c, cells, res, summary):
    return {"case": c, "cells": cells, "runout": res.get("runout"), "endTime": res.get("endTime"),
            "atRest": res.get("atRest"), "endTimeCut": res.get("endTimeCut"), "wall": res.get("wall"),
            "minCells": summary.get("front_min_cells_moving"), "minCellsTime": summary.get("front_min_cells_time_s"),
            "underFrom": summary.get("front_under_resolved_from_s"),
            "travelUnder": summary.get("front_travel_under_resolved_m"),
            "fractionUnder": summary.get("front_travel_under_resolved_fraction")}


def fmt(v, f="%.2f"):
    return "-" if v is None else f % v


def write_md(rows, stored):
    lines = ["# The under-resolved-front warning against Table 1's cell dependence (`frontResolution.py`)", "",
             "4x4 particles, APIC, `touching` contact. The front zone is the slide's foremost H0 (5 m); \"fewest "
             "cells\" is its thickness over the cell at the write where it was thinnest while it moved faster than "
             "the scene's restVelocity; \"travel under %d cells\" is the front's travel after writes that found it "
             "moving under %d cells thick, as a share of the runout of this run (cut where the end time says so). "
             "The last two columns are table1.json's stored runs: the change from this cell to the next finer "
             "one stored, of the runout where both came to rest, else of the fronts at the earlier run's end, and "
             "whether it is within %d %%." % (RESOLVED_CELLS, RESOLVED_CELLS, 100*CONVERGED), "",
             "| case | cell | end (s) | runout here (m) | fewest cells (at s) | warned from (s) | travel under %d cells "
             "| stored: change to the next finer cell | within %d %% |" % (RESOLVED_CELLS, 100*CONVERGED),
             "|---|---|---|---|---|---|---|---|---|"]
    agree = disagree = 0
    for r in sorted(rows, key=lambda r: (r["case"], r["cells"])):
        finer, change, when = next_finer_change(stored, r["case"], r["cells"])
        warned = r.get("underFrom") is not None
        within = None if change is None else abs(change) <= CONVERGED
        if within is not None:
            agree += warned != within
            disagree += warned == within
        end = "%.0f%s" % (r["endTime"], " (at rest)" if r["atRest"] else " (moving)")
        lines.append("| %d | H0/%d | %s | %s | %s (%s) | %s | %s m (%s %%) | %s | %s |" % (
            r["case"], r["cells"], end, fmt(r["runout"]), fmt(r["minCells"]), fmt(r["minCellsTime"], "%g"),
            fmt(r["underFrom"], "%g"), fmt(r["travelUnder"], "%.1f"), fmt(r["fractionUnder"] and
                                                                          100*r["fractionUnder"], "%.0f"),
            "-" if change is None else "%+.1f %% (H0/%d%s)" % (100*change, finer,
                                                               "" if when is None else ", at %g s" % when),
            "-" if within is None else ("yes" if within else "no")))
    lines += ["", "The warning and the stored cell dependence agree on %d of the %d rows that have a finer stored "
              "cell (warned and not within %d %%, or not warned and within it)." % (agree, agree + disagree,
                                                                                   100*CONVERGED), ""]
    with open(os.path.join(here, "frontResolution.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", default="1,2,3,4,6,7,9,10,12,13")
    ap.add_argument("--cells", default="10,20")
    ap.add_argument("--cut", default="3:100,4:130,10:60,13:60",
                    help="CASE:T,... end times for cases whose scene runs longer than is needed here")
    ap.add_argument("--stored", action="store_true")
    args = ap.parse_args()
    path = os.path.join(here, "frontResolution.json")
    rows = json.load(open(path))["runs"] if os.path.exists(path) else []
    if not args.stored:
        cut = {int(k): float(v) for k, v in (p.split(":") for p in args.cut.split(",") if p)}
        work = tempfile.mkdtemp(prefix="frontResolution.")
        print("work directory:", work, flush=True)
        for cells in (int(c) for c in args.cells.split(",")):
            for c in (int(c) for c in args.cases.split(",")):
                res = run_case(c, cells, 4, work, end_time=cut.get(c))
                if "failed" in res:
                    raise SystemExit("frontResolution.py: case %d at H0/%d failed:\n%s" % (c, cells, res["failed"]))
                summary = json.load(open(os.path.join(work, "case%02d_h%d_p4" % (c, cells), "postProcessing",
                                                      "slideMPM", "summary.json")))
                rows = [r for r in rows if (r["case"], r["cells"]) != (c, cells)] + [row_of(c, cells, res, summary)]
                with open(path, "w") as f:
                    json.dump({"runs": rows}, f, indent=1)
    write_md(rows, stored_runouts())


if __name__ == "__main__":
    main()
