#!/usr/bin/env python3
"""Particle shifting against the particles' crowding on the base (README, open problem 13): runs slideMPM on a
slide for each shift coefficient (mpmDict `particleShifting`, 0 = off) and number of particles per cell, and writes
shifting.md, shifting.json and shifting.png beside this script. Two studies:

- Case 1 (the default): the rate-free Case 1 (Case 1 without Eq. (1)'s rate term, paper.CASE1_RATE_FREE_SCENE;
  quadratic transfer, as numerics.py's rateFree variant) at H0/20 to 40 s. Without shifting the runout at 40 s
  depends on the particles per cell (2x2 216 m, 4x4 334 m, 8x8 397 m), because particles crowd into the cell on the
  no-slip base and the base's nodes then weigh a yield stress by the overfill. If shifting removes the crowding, the
  runout stops depending on the particles per cell, and stops depending on the coefficient once it is large enough
  to keep up with the crowding. slideFoam's rate-free Case 1 (validation/cfd/table1.json, H0/20 with H0/80 on the
  base) is set beside it.
- Any other Table 1 case (--case 10, --case 13): the case as tabled, Eq. (1) and remoulding, with Table 1's numerics
  (APIC, H0/10) to 30 s, by which the unshifted fronts of Cases 10 and 13 have stalled (README, open problem 3).
  The question: does the front at 30 s converge in the particles per cell, with and without shifting, and to what?
  Both columns are run here. --cells runs the study at other cells too (H0/5 and H0/20 were run at 8x8 with
  shifting 0.03, the count that is within about 1 % of 16x16 at H0/10): does the front converge in the cell where
  it has converged in the particles?
  --xi-per-cell runs the remoulding cases (10-13, whose tutorials count xi per shear band of H0/60) with xi counted
  per cell instead (mpmDict shearBandThickness 0): is the band's scaling of xi with the cell what keeps Case 13 from
  converging in the cell? Case 2 is Case 13 without remoulding (the same s_uo, rate term and slope), the same
  question's control.

Usage: validation/mpm/shifting.py [--case 1] [--shifts 0.01,0.03,0.1] [--ppc 2,4,8] [--cells 10]
                                  [--xi-per-cell] [--stored] [--import DIR ...]
(For Case 1 the row without shifting is numerics.py's rateFree variant at H0/20, read from numerics.json: run it
there. 2 threads, Case 1: 2x2 1-3 minutes, 4x4 3-4 minutes, 8x8 8-10 minutes a run; Cases 10 and 13 to 30 s:
4x4 about 30 s (at H0/20 2-4 minutes, at H0/40 18-30 minutes), 8x8 about 100 s (at H0/5 15 s, at H0/20
11-13 minutes), 16x16 about 7 minutes a run. A run keeps
the stored results of the other points; --import reads finished run directories named
case<NN>_h<cells>_p<ppc>_k<shift>[_cell] instead of running them)"""
import argparse
import json
import math
import os
import re
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from table1 import run_case, case_result, front_at  # noqa: E402
from numerics import RATE_FREE_CLAY  # noqa: E402
from paper import CASE1_RATE_FREE_SCENE  # noqa: E402
from cfdcase import get_entry  # noqa: E402


def study(case):
    """(cells per H0, end time [s], sceneProperties entries, mpmDict entries, description) of a case's study."""
    if case == 1:
        return (20, 40.0, CASE1_RATE_FREE_SCENE, {"transfer": "quadratic", **RATE_FREE_CLAY},
                "the rate-free Case 1 (no rate term, s_uo 225 Pa), quadratic transfer, H0/20")
    return (10, 30.0, None, {}, "Table 1 Case %d as tabled (Eq. (1)%s), APIC, H0/10"
            % (case, ", remoulding" if remoulds(case) else ", no remoulding"))


def tutorial_entry(case, dictionary, key):
    """A number of the case's tutorial (dictionary: constant/sceneProperties, system/mpmDict), or None."""
    return get_entry(os.path.join(here, "..", "..", "tutorials", "table1", "case%02d" % case, dictionary), key)


def remoulds(case):
    """Whether the case's scene remoulds (deltaRem < 1)."""
    return (tutorial_entry(case, "constant/sceneProperties", "deltaRem") or 1) < 1


def numerics_of(case, shift, xi_per_cell=False):
    num = dict(study(case)[3])
    if shift > 0:
        num["particleShifting"] = shift
    if xi_per_cell:
        num["shearBandThickness"] = 0
    return num


def counts_bands(case):
    """Whether the case's tutorial counts xi per shear band (a shearBandThickness > 0 in its mpmDict)."""
    return (tutorial_entry(case, "system/mpmDict", "shearBandThickness") or 0) > 0


def row_of(res, shift, times, xi_per_cell=False):
    history = res.pop("history", None) or []
    res["shift"] = shift
    if xi_per_cell:
        res["xiPerCell"] = True
    res["frontAt"] = front_at(history, times)
    return res


def times_of(case):
    end = study(case)[1]
    return tuple(t for t in (10, 20, 30) if t < end)


def slidefoam_rate_free():
    """slideFoam's rate-free Case 1 at H0/20 to 40 s, the finest base stored (a row of ../cfd/table1.json)."""
    path = os.path.join(here, "..", "cfd", "table1.json")
    rows = [r for r in json.load(open(path)) if r.get("rate_free") and r["case"] == 1 and r.get("end_time") == 40]
    return max(rows, key=lambda r: r.get("refinement") or 0) if rows else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", type=int, default=1, help="1: the rate-free Case 1; another: that Table 1 case")
    ap.add_argument("--shifts", default=None, help="default 0.01,0.03,0.1 (Case 1), 0,0.03 (another case)")
    ap.add_argument("--ppc", default=None, help="default 2,4,8 (Case 1), 4,8,16 (another case)")
    ap.add_argument("--cells", default=None, help="cells per H0, default the study's (20 for Case 1, else 10)")
    ap.add_argument("--xi-per-cell", action="store_true",
                    help="count xi per cell, not per the tutorial's shear band (Cases 10-13)")
    ap.add_argument("--stored", action="store_true", help="rewrite shifting.md and .png from shifting.json")
    ap.add_argument("--import", dest="imports", nargs="*", default=[],
                    help="finished run directories case<NN>_h<cells>_p<ppc>_k<shift> to store instead of running")
    args = ap.parse_args()
    case = args.case
    cells, end, scene, _, _ = study(case)
    per_cell = args.xi_per_cell
    if per_cell and not counts_bands(case):
        raise SystemExit("shifting.py: --xi-per-cell: Case %d's tutorial counts xi per cell already (no "
                         "shearBandThickness in its system/mpmDict)" % case)
    shifts = args.shifts or ("0.01,0.03,0.1" if case == 1 else "0,0.03")
    ppcs = args.ppc or ("2,4,8" if case == 1 else "4,8,16")
    cell_list = [int(n) for n in args.cells.split(",")] if args.cells else [cells]
    path = os.path.join(here, "shifting.json")
    stored = json.load(open(path)) if os.path.isfile(path) else []
    new = []
    for d in args.imports:
        m = re.search(r"case(\d\d)_h(\d+)_p(\d+)_k([0-9.eE+-]+?)(_cell)?$", d.rstrip("/"))
        if not m or int(m.group(1)) != case:
            raise SystemExit("shifting.py: --import %s: not a run directory case%02d_h<cells>_p<ppc>_k<shift>[_cell] "
                             "of this study" % (d, case))
        if bool(m.group(5)) != per_cell:
            raise SystemExit("shifting.py: --import %s: %s, so %s --xi-per-cell" % (
                d, "xi per cell (_cell)" if m.group(5) else "xi as the tutorial counts it",
                "with" if m.group(5) else "without"))
        res = case_result(case, int(m.group(2)), int(m.group(3)), d)
        if abs(res["endTime"] - end) > 1e-6 and not res["atRest"]:
            raise SystemExit("shifting.py: --import %s: ended at %g s, not the study's %g s" % (d, res["endTime"], end))
        new.append(row_of(res, float(m.group(4)), times_of(case), per_cell))
    if not args.stored and not args.imports:
        work = tempfile.mkdtemp(prefix="slideMPM_shifting_")
        for shift in [float(s) for s in shifts.split(",")]:
            if case == 1 and not shift > 0:
                raise SystemExit("shifting.py: --shifts: Case 1's runs without shifting are numerics.py's rateFree "
                                 "variant")
            for n, ppc in [(n, int(p)) for n in cell_list for p in ppcs.split(",")]:
                res = run_case(case, n, ppc, work, numerics=numerics_of(case, shift, per_cell), scene=scene,
                               tag="_k%g%s" % (shift, "_cell" if per_cell else ""), end_time=end)
                if "failed" in res:
                    raise SystemExit("shifting.py: the run with shift %g, H0/%d, %dx%d failed:\n%s"
                                     % (shift, n, ppc, ppc, res["failed"]))
                new.append(row_of(res, shift, times_of(case), per_cell))
                print("Case %d, shift %g, H0/%d, %dx%d: %.2f m at %g s, %.0f s wall" % (
                    case, shift, n, ppc, ppc, new[-1]["runout"], new[-1]["endTime"], new[-1]["wall"]), flush=True)
    key = lambda r: (r["case"], r["cells"]) + series_of(r)
    keys = {key(r) for r in new}
    results = sorted([r for r in stored if key(r) not in keys] + new, key=key)
    if new:
        with open(path, "w") as f:
            json.dump(results, f, indent=1)
    write(results)


def unshifted():
    """numerics.py's rateFree rows at H0/20 to 40 s: Case 1's study without shifting."""
    path = os.path.join(here, "numerics.json")
    rows = json.load(open(path)) if os.path.isfile(path) else []
    cells, end = study(1)[:2]
    out = []
    for r in rows:
        if r["variant"] == "rateFree" and r["case"] == 1 and r["cells"] == cells and r.get("endTimeCut") == end:
            out.append(dict(r, shift=0.0, frontAt={t: r["frontAt"].get(t) for t in ("10", "20", "30")}))
    return out


# A Richardson limit is read only where the observed order lies in this range: below it the changes hardly shrink,
# and the extrapolation would add several times the last change on the strength of a pre-asymptotic ratio.
MIN_ORDER, MAX_ORDER = 0.5, 4.0


def convergence(values):
    """The observed order of three values at a doubling resolution (particles per cell, or cells per H0), and the
    limit it gives (None where the differences do not shrink monotonically)."""
    (p1, a), (p2, b), (p3, c) = values
    if p2 != 2*p1 or p3 != 2*p2 or (b - a)*(c - b) <= 0 or abs(c - b) >= abs(b - a):
        return None
    order = math.log2((b - a)/(c - b))
    return order, c + (c - b)/(2**order - 1)


def limit_lines(label, runout, name, what):
    """The Richardson line of the finest triplet at doubling resolution among runout {resolution: front}: a coarser
    one holds the pre-asymptotic points (2x2's slide stops by 39 s)."""
    finest = [q for q in sorted(runout, reverse=True) if 2*q in runout and 4*q in runout][:1]
    lines = []
    for p in finest:
        pts = [(q, runout[q]) for q in (p, 2*p, 4*p)]
        conv = convergence(pts)
        span = "%s%s to %s" % (label, name(p), name(4*p))
        if conv and not MIN_ORDER <= conv[0] <= MAX_ORDER:
            lines.append("- %s: the changes %+.1f and %+.1f m, an observed order of %.2f: too far from the asymptotic "
                         "range to extrapolate." % (span, pts[1][1] - pts[0][1], pts[2][1] - pts[1][1], conv[0]))
        elif conv:
            lines.append("- %s: observed order %.2f %s, limit %.1f m (Richardson)." % (span, conv[0], what, conv[1]))
        else:
            lines.append("- %s: the changes %s do not shrink monotonically: no limit read." % (span, " and ".join(
                "%+.1f m" % (pts[i + 1][1] - pts[i][1]) for i in range(2))))
    return lines


def entry(r, times):
    """A table entry: the front at the end, at the earlier times, its speed, the thickest point, the wall time."""
    f = r["frontAt"]
    return "**%.1f m** (%s; %.2f m/s; %s; %.0f s)" % (
        r["runout"], " / ".join("%.1f" % f[t] if f.get(t) is not None else "-" for t in times), r["frontVelocity"],
        "%.2f m thick" % r["maxThickness"] if r.get("maxThickness") else "-", r["wall"])


def series_of(r):
    """A row's series in the cell: its shift, particles per cell and whether xi was counted per cell."""
    return r["shift"], r["ppc"], r.get("xiPerCell", False)


def series_label(series):
    s, p, per_cell = series
    return "%g, %dx%d%s" % (s, p, p, ", xi per cell" if per_cell else "")


def cell_table(case, rows):
    """The front against the cell, for each series run at more than one cell."""
    end = study(case)[1]
    times = [str(t) for t in times_of(case)]
    sets = sorted({series_of(r) for r in rows
                   if len({q["cells"] for q in rows if series_of(q) == series_of(r)}) > 1})
    if not sets:
        return []
    cells = sorted({r["cells"] for r in rows if series_of(r) in sets})
    at = {series_of(r) + (r["cells"],): r for r in rows}
    per_cell = any(series[2] for series in sets)
    lines = ["", "The front at %g s against the cell (each entry as above%s):" % (
                 end, "; \"xi per cell\": mpmDict shearBandThickness 0, where the tutorial counts the strain of a "
                      "band of H0/60" if per_cell else ""), "",
             "| particleShifting, particles | " + " | ".join("H0/%d" % n for n in cells) + " |",
             "|---|" + "---|"*len(cells)]
    for series in sets:
        entries = []
        for n in cells:
            r = at.get(series + (n,))
            entries.append("-" if r is None else entry(r, times))
        lines.append("| %s | %s |" % (series_label(series), " | ".join(entries)))
    lines.append("")
    for series in sets:
        lines += limit_lines("particleShifting %s, " % series_label(series),
                             {n: at[series + (n,)]["runout"] for n in cells if series + (n,) in at},
                             lambda n: "H0/%d" % n, "in the cell")
    return lines


def case_table(case, all_rows, cfd):
    cells, end, _, _, what = study(case)
    rows = [r for r in all_rows if r["cells"] == cells and not r.get("xiPerCell")]
    times = [str(t) for t in times_of(case)]
    shifts = sorted({r["shift"] for r in rows})
    ppcs = sorted({r["ppc"] for r in rows})
    at = {(r["shift"], r["ppc"]): r for r in rows}
    lines = ["## Case %d: %s, to %g s" % (case, what, end), ""]
    lines.append("Each entry: the front at %g s, then at %s s, the front's speed at %g s, the thickest point of the "
                 "slide at %g s, and the wall time on 2 threads. `particleShifting` 0 is no shifting."
                 % (end, " / ".join(times), end, end))
    lines.append("")
    if case == 1 and cfd:
        lines += ["slideFoam (H0/20 with H0/%d on the base, ../cfd/table1.json): %.1f m at 40 s, the front still "
                  "moving at %.1f m/s." % (20*cfd["refinement"], cfd["runout"], cfd["front_velocity"]), "",
                  "The row for 0 is numerics.py's rateFree variant (numerics.json).", ""]
    lines += ["| particleShifting | " + " | ".join("%dx%d" % (p, p) for p in ppcs) + " |",
              "|---|" + "---|"*len(ppcs)]
    for s in shifts:
        entries = []
        for p in ppcs:
            r = at.get((s, p))
            entries.append("-" if r is None else entry(r, times))
        lines.append("| %g | %s |" % (s, " | ".join(entries)))
    lines.append("")
    for s in shifts:
        lines += limit_lines("particleShifting %g, " % s, {p: at[(s, p)]["runout"] for p in ppcs if (s, p) in at},
                             lambda p: "%dx%d" % (p, p), "in the particles per cell and direction")
    lines += cell_table(case, all_rows)
    if lines[-1]:
        lines.append("")
    return lines


def log2_axis(ax, ticks, label):
    ax.set_xscale("log", base=2)
    ax.set_xticks(ticks)
    ax.set_xticklabels([str(t) for t in ticks])
    ax.set_xlabel(label)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)


def write(results):
    results = unshifted() + results
    cfd = slidefoam_rate_free()
    cases = sorted({r["case"] for r in results})
    lines = ["# Particle shifting: the runout against the particles per cell", "",
             "Regenerated by `validation/mpm/shifting.py` (its docstring says why).", ""]
    for c in cases:
        lines += case_table(c, [r for r in results if r["case"] == c], cfd)
    out = os.path.join(here, "shifting.md")
    with open(out, "w") as f:
        f.write("\n".join(lines))
    print("wrote %s" % out)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    # A second row of panels for the cases run at more than one cell: the front against the cell.
    multi = {c: sorted({r["cells"] for r in results if r["case"] == c}) for c in cases}
    nrows = 2 if any(len(v) > 1 for v in multi.values()) else 1
    fig, axes = plt.subplots(nrows, len(cases), figsize=(4.6*len(cases), 4.2*nrows), squeeze=False)
    for ax, c in zip(axes[0], cases):
        rows = [r for r in results if r["case"] == c and r["cells"] == study(c)[0] and not r.get("xiPerCell")]
        at = {(r["shift"], r["ppc"]): r for r in rows}
        ppcs = sorted({r["ppc"] for r in rows})
        for s in sorted({r["shift"] for r in rows}):
            pts = [(p, at[(s, p)]["runout"]) for p in ppcs if (s, p) in at]
            ax.plot([p for p, _ in pts], [v for _, v in pts], "o-", label="particleShifting %g" % s)
        if c == 1 and cfd:
            ax.axhline(cfd["runout"], color="k", ls="--", lw=1, label="slideFoam at 40 s (still moving)")
        log2_axis(ax, ppcs, "particles per cell and direction")
        ax.set_ylabel("front at %g s [m]" % study(c)[1])
        ax.set_title("slideMPM, %s Case %d, H0/%d" % ("rate-free" if c == 1 else "Table 1", c, study(c)[0]),
                     fontsize=9)
    for ax, c in zip(axes[1] if nrows > 1 else [], cases):
        rows = [r for r in results if r["case"] == c]
        sets = sorted({series_of(r) for r in rows})
        if len(multi[c]) < 2:
            ax.set_visible(False)
            continue
        for series in sets:
            pts = sorted((r["cells"], r["runout"]) for r in rows if series_of(r) == series)
            if len(pts) > 1:
                ax.plot([n for n, _ in pts], [v for _, v in pts], "^--" if series[2] else "s-",
                        label="particleShifting %s" % series_label(series))
        log2_axis(ax, multi[c], "cells per H0")
        ax.set_ylabel("front at %g s [m]" % study(c)[1])
        ax.set_title("slideMPM, %s Case %d, against the cell" % ("rate-free" if c == 1 else "Table 1", c), fontsize=9)
    fig.tight_layout()
    png = os.path.join(here, "shifting.png")
    fig.savefig(png, dpi=120)
    print("wrote %s" % png)


if __name__ == "__main__":
    main()
