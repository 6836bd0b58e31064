#!/usr/bin/env python3
"""Particle shifting against the particles' crowding on the base (README, open problem 13): runs slideMPM on the
rate-free Case 1 (Case 1 without Eq. (1)'s rate term, paper.CASE1_RATE_FREE_SCENE; quadratic transfer, as
numerics.py's rateFree variant) at H0/20 to 40 s for each shift coefficient (mpmDict `particleShifting`, 0 = off)
and particles per cell, and writes shifting.md, shifting.json and shifting.png beside this script.

The question: without shifting the runout at 40 s depends on the particles per cell (2x2 216 m, 4x4 334 m, 8x8
397 m), because particles crowd into the cell on the no-slip base and the base's nodes then weigh a yield stress by
the overfill. If shifting removes the crowding, the runout stops depending on the particles per cell, and stops
depending on the coefficient once it is large enough to keep up with the crowding. slideFoam's rate-free Case 1
(validation/cfd/table1.json, H0/20 with H0/80 on the base) is set beside it.

Usage: validation/mpm/shifting.py [--shifts 0.01,0.03,0.1] [--ppc 2,4,8] [--end-time 40] [--stored]
       [--import DIR ...]
(The row without shifting is numerics.py's rateFree variant at H0/20, read from numerics.json: run it there.)
(2 threads: 2x2 1-3 minutes, 4x4 3-4 minutes, 8x8 8-10 minutes a run; a run keeps the stored results of the other
points; --import reads finished run directories named case01_h20_p<ppc>_k<shift> instead of running them)"""
import argparse
import json
import os
import re
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from table1 import run_case, case_result, front_at  # noqa: E402
from numerics import RATE_FREE_CLAY  # noqa: E402
from paper import CASE1_RATE_FREE_SCENE  # noqa: E402

CELLS = 20


def numerics_of(shift):
    num = {"transfer": "quadratic", **RATE_FREE_CLAY}
    if shift > 0:
        num["particleShifting"] = shift
    return num


def row_of(res, shift):
    history = res.pop("history", None) or []
    res["shift"] = shift
    res["frontAt"] = front_at(history, (10, 20, 30))
    return res


def slidefoam_rate_free():
    """slideFoam's rate-free Case 1 at H0/20 to 40 s, the finest base stored (a row of ../cfd/table1.json)."""
    path = os.path.join(here, "..", "cfd", "table1.json")
    rows = [r for r in json.load(open(path)) if r.get("rate_free") and r["case"] == 1 and r.get("end_time") == 40]
    return max(rows, key=lambda r: r.get("refinement") or 0) if rows else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shifts", default="0.01,0.03,0.1")
    ap.add_argument("--ppc", default="2,4,8")
    ap.add_argument("--end-time", type=float, default=40.0)
    ap.add_argument("--stored", action="store_true", help="rewrite shifting.md and .png from shifting.json")
    ap.add_argument("--import", dest="imports", nargs="*", default=[],
                    help="finished run directories case01_h20_p<ppc>_k<shift> to store instead of running")
    args = ap.parse_args()
    path = os.path.join(here, "shifting.json")
    stored = json.load(open(path)) if os.path.isfile(path) else []
    new = []
    for d in args.imports:
        m = re.search(r"case01_h%d_p(\d+)_k([0-9.eE+-]+)$" % CELLS, d.rstrip("/"))
        if not m:
            raise SystemExit("shifting.py: --import %s: not a run directory case01_h%d_p<ppc>_k<shift>" % (d, CELLS))
        new.append(row_of(case_result(1, CELLS, int(m.group(1)), d), float(m.group(2))))
    if not args.stored and not args.imports:
        work = tempfile.mkdtemp(prefix="slideMPM_shifting_")
        for shift in [float(s) for s in args.shifts.split(",")]:
            if not shift > 0:
                raise SystemExit("shifting.py: --shifts: the runs without shifting are numerics.py's rateFree variant")
            for ppc in [int(p) for p in args.ppc.split(",")]:
                res = run_case(1, CELLS, ppc, work, numerics=numerics_of(shift), scene=CASE1_RATE_FREE_SCENE,
                               tag="_k%g" % shift, end_time=args.end_time)
                if "failed" in res:
                    raise SystemExit("shifting.py: the run with shift %g, %dx%d failed:\n%s"
                                     % (shift, ppc, ppc, res["failed"]))
                new.append(row_of(res, shift))
                print("shift %g, %dx%d: %.2f m at %g s, %.0f s wall" % (shift, ppc, ppc, new[-1]["runout"],
                                                                       new[-1]["endTime"], new[-1]["wall"]),
                      flush=True)
    keys = {(r["shift"], r["ppc"]) for r in new}
    results = sorted([r for r in stored if (r["shift"], r["ppc"]) not in keys] + new,
                     key=lambda r: (r["shift"], r["ppc"]))
    if new:
        with open(path, "w") as f:
            json.dump(results, f, indent=1)
    write(results)


def unshifted():
    """numerics.py's rateFree rows at H0/20 to 40 s: this study without shifting."""
    path = os.path.join(here, "numerics.json")
    rows = json.load(open(path)) if os.path.isfile(path) else []
    out = []
    for r in rows:
        if r["variant"] == "rateFree" and r["case"] == 1 and r["cells"] == CELLS and r.get("endTimeCut") == 40.0:
            out.append(dict(r, shift=0.0, frontAt={t: r["frontAt"].get(t) for t in ("10", "20", "30")}))
    return out


def write(results):
    results = unshifted() + results
    cfd = slidefoam_rate_free()
    shifts = sorted({r["shift"] for r in results})
    ppcs = sorted({r["ppc"] for r in results})
    at = {(r["shift"], r["ppc"]): r for r in results}
    lines = ["# Particle shifting: the rate-free Case 1's runout against the particles per cell", "",
             "Regenerated by `validation/mpm/shifting.py` (its docstring says why). slideMPM, rate-free Case 1 "
             "(no rate term, s_uo 225 Pa), quadratic transfer, H0/20, to 40 s. Each entry: the front at 40 s, then "
             "at 10 / 20 / 30 s, the front's speed at 40 s, and the wall time on 2 threads. `particleShifting` 0 is "
             "no shifting.", ""]
    if cfd:
        lines += ["slideFoam (H0/20 with H0/%d on the base, ../cfd/table1.json): %.1f m at 40 s, the front still "
                  "moving at %.1f m/s." % (20*cfd["refinement"], cfd["runout"], cfd["front_velocity"]), "",
                  "The row for 0 is numerics.py's rateFree variant (numerics.json).", ""]
    lines += ["| particleShifting | " + " | ".join("%dx%d" % (p, p) for p in ppcs) + " |",
              "|---|" + "---|"*len(ppcs)]
    for s in shifts:
        cells = []
        for p in ppcs:
            r = at.get((s, p))
            if r is None:
                cells.append("-")
                continue
            f = r["frontAt"]
            cells.append("**%.1f m** (%s; %.2f m/s; %.0f s)" % (
                r["runout"], " / ".join("%.1f" % f[t] if f.get(t) is not None else "-" for t in ("10", "20", "30")),
                r["frontVelocity"], r["wall"]))
        lines.append("| %g | %s |" % (s, " | ".join(cells)))
    out = os.path.join(here, "shifting.md")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % out)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for s in shifts:
        pts = [(p, at[(s, p)]["runout"]) for p in ppcs if (s, p) in at]
        ax.plot([p for p, _ in pts], [v for _, v in pts], "o-", label="particleShifting %g" % s)
    if cfd:
        ax.axhline(cfd["runout"], color="k", ls="--", lw=1, label="slideFoam at 40 s (still moving)")
    ax.set_xlabel("particles per cell and direction")
    ax.set_ylabel("front at 40 s [m]")
    ax.set_xticks(ppcs)
    ax.set_title("slideMPM, rate-free Case 1, H0/20")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(here, "shifting.png")
    fig.savefig(png, dpi=120)
    print("wrote %s" % png)


if __name__ == "__main__":
    main()
