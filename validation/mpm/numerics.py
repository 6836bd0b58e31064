#!/usr/bin/env python3
"""How far a converged Table 1 runout of slideMPM is the MPM's own numerics: runs slideMPM on a Table 1 case with
the quadratic transfer (`transfer quadratic`, which keeps a velocity profile across the flow through the
transfers where APIC loses a little of it every step: README, open problem 10), with a ten times stiffer clay
(`youngsModulusRatio 1000`, where the paper's is 100) and with both, at one or more cells, and sets them beside
the default numerics' row of table1.json (APIC, E = 100 s_uo: the Table 1 run itself). Writes numerics.md and
numerics.json beside this script.

The question it answers (Case 2 by default): Case 2 converges in the cell to about 56 m at the paper's 4x4
particles (H0/40 and H0/60 within 1.7 %), 17 % short of the paper's MPM (68 m), while slideFoam and slideDAM run
61-64 m. If the runout at a fine cell still moved with the transfer, the convergence in the cell would be APIC's
and not the model's. On Case 1, whose runout falls with every cell from H0/20 on (README, open problem 5), the
rate-free variants (below) ask how much of that fall is Eq. (1)'s rate term met in a shear layer the cell sets,
and rateFreeStiff, rateFreeUnscaled, rateFreeWithinCell and rateFreeNoSplitting how much of the rate-free MPM's
shortfall against slideFoam and slideDAM is its elastic clay, the mass scaling of the grid row above the base, the
base's contact or particle splitting, and the cellCapped variants how much is the particles crowding into the
base's cell (README, open problem 13), and the shifted variants what particle shifting against that crowding changes
(shifting.py has its study); courantHalf, withinCell, unscaled and noSplitting ask the same of the time step
(Courant 0.15), the base's contact, the mass scaling of the row above the base and particle splitting on any case
(session 61: on Case 2 from H0/10 to H0/20 only the contact changes the trend); --ppc sets the particles per cell
and direction (2, 4, 6 and 8 were run).

Usage: validation/mpm/numerics.py [--cases 2] [--cells 20,40] [--ppc 4] [--variants quadratic,stiff,...]
                                  [--end-time T] [--stored] [--import DIR ...]
(4x4 with the quadratic transfer on 2 cores: Case 2 5 minutes at H0/20 and 34 minutes at H0/40, Case 1 7 minutes
at H0/20 and 29 minutes at H0/40 to 40 s, rate-free 3 and 18 minutes; the stiff variants take about three times
the steps; a run keeps the stored results of the other cases, cells and variants; --end-time stops the runs at T s,
to set a run beside a Table 1 row that was stopped there; --import stores finished run directories named
case<NN>_h<cells>_p<ppc>_<variant>, as this script names them, instead of running)"""
import argparse
import json
import os
import re
import shutil
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from table1 import cauchy_rate, case_result, front_at, run_case, paper_table  # noqa: E402
from paper import CASE1_RATE_FREE_SCENE  # noqa: E402

# (key, heading, mpmDict entries, sceneProperties entries); "apic" is table1.json's row, the default numerics.
# The "rateFree" variants are not numerics but Case 1 without Eq. (1)'s rate term (paper.CASE1_RATE_FREE_SCENE, which
# says why), with the quadratic transfer and with APIC; E = (100/1.5) s_uo keeps Case 1's 15 kPa (ten times that in
# rateFreeStiff); rateFreeUnscaled turns off baseRowMassScaling, rateFreeWithinCell sets baseContact withinCell,
# rateFreeNoSplitting turns off particleSplitting, rateFreeCellCapped (and cellCapped, on any case) sets stressQuadrature
# cellCapped, rateFreeShifted (and shifted, on any case) sets particleShifting SHIFT. The script refuses the rate-free
# ones on another case.
# mpmDict particleShifting of the shifted variants: the smallest of shifting.py's coefficients whose rate-free Case 1
# runs alike at 2x2 and 4x4 particles (410.6 and 413.7 m at 40 s; 0.01 leaves 4x4 at 396.7 m, 0.1 parts 2x2 and 4x4
# by 3 %: shifting.md).
SHIFT = 0.03
# mpmDict of the bandRate variant: Eq. (1)'s rate taken in a band of the paper's cell, H0/60, as the remoulding
# tutorials take xi (README, "Eq. (1)'s layer on a no-slip slope"): does the runout then stop depending on the cell?
BAND_RATE = {"shearBandThickness": "0.0833333", "shearBandRate": "yes"}
RATE_FREE_CLAY = {"youngsModulusRatio": 100*150/CASE1_RATE_FREE_SCENE["s_uo"]}   # E = 100 x Case 1's 150 Pa
VARIANTS = (("apic", "APIC, E = 100 s_uo (Table 1's row)", None, None),
            ("quadratic", "quadratic transfer", {"transfer": "quadratic"}, None),
            ("stiff", "E = 1000 s_uo", {"youngsModulusRatio": 1000}, None),
            ("quadraticStiff", "quadratic transfer, E = 1000 s_uo", {"transfer": "quadratic",
                                                                    "youngsModulusRatio": 1000}, None),
            ("cellCapped", "APIC, stress quadrature capped at each cell's area", {"stressQuadrature": "cellCapped"},
             None),
            ("shifted", "APIC, particle shifting %g" % SHIFT, {"particleShifting": SHIFT}, None),
            ("bandRate", "APIC, Eq. (1)'s rate and xi per H0/60 band", BAND_RATE, None),
            ("courantHalf", "APIC, Courant number 0.15", {"courant": 0.15}, None),
            ("withinCell", "APIC, base contact withinCell", {"baseContact": "withinCell"}, None),
            ("unscaled", "APIC, no mass scaling of the row above the base", {"baseRowMassScaling": "no"}, None),
            ("noSplitting", "APIC, no particle splitting", {"particleSplitting": "no"}, None),
            ("rateFreeApic", "APIC, no rate effect, 1.5 s_uo (another model)", RATE_FREE_CLAY, CASE1_RATE_FREE_SCENE),
            ("rateFree", "quadratic transfer, no rate effect, 1.5 s_uo (another model)",
             {"transfer": "quadratic", **RATE_FREE_CLAY}, CASE1_RATE_FREE_SCENE),
            ("rateFreeStiff", "quadratic transfer, no rate effect, 1.5 s_uo, E = 1000 x 150 Pa (another model)",
             {"transfer": "quadratic", "youngsModulusRatio": 10*RATE_FREE_CLAY["youngsModulusRatio"]},
             CASE1_RATE_FREE_SCENE),
            ("rateFreeUnscaled", "quadratic transfer, no rate effect, 1.5 s_uo, no mass scaling of the row above "
             "the base (another model)", {"transfer": "quadratic", "baseRowMassScaling": "no", **RATE_FREE_CLAY},
             CASE1_RATE_FREE_SCENE),
            ("rateFreeWithinCell", "quadratic transfer, no rate effect, 1.5 s_uo, base contact withinCell (another "
             "model)", {"transfer": "quadratic", "baseContact": "withinCell", **RATE_FREE_CLAY}, CASE1_RATE_FREE_SCENE),
            ("rateFreeNoSplitting", "quadratic transfer, no rate effect, 1.5 s_uo, no particle splitting (another "
             "model)", {"transfer": "quadratic", "particleSplitting": "no", **RATE_FREE_CLAY}, CASE1_RATE_FREE_SCENE),
            ("rateFreeCellCapped", "quadratic transfer, no rate effect, 1.5 s_uo, stress quadrature capped at each "
             "cell's area (another model)", {"transfer": "quadratic", "stressQuadrature": "cellCapped",
                                             **RATE_FREE_CLAY}, CASE1_RATE_FREE_SCENE),
            ("rateFreeShifted", "quadratic transfer, no rate effect, 1.5 s_uo, particle shifting %g (another model)"
             % SHIFT, {"transfer": "quadratic", "particleShifting": SHIFT, **RATE_FREE_CLAY}, CASE1_RATE_FREE_SCENE))
RATE_FREE = ("rateFreeApic", "rateFree", "rateFreeStiff", "rateFreeUnscaled", "rateFreeWithinCell", "rateFreeNoSplitting",
             "rateFreeCellCapped", "rateFreeShifted")
KEYS = [v[0] for v in VARIANTS]


def table1_row(table1, case, cells, ppc):
    """The Table 1 run of this case and set-up among table1.json's rows, or None."""
    rows = [r for r in table1 if r["case"] == case and r["cells"] == cells and r["ppc"] == ppc
            and r.get("baseContact") == "touching" and "failed" not in r]
    return rows[-1] if rows else None


def change_against(r, base):
    """The bracket of variant row r against the default's row `base`, compared at the same time: a run still moving
    at its end is set beside the other's front at that time (a Table 1 row keeps its history), never beside a
    runout reached later (Case 3's default row ran to rest at 435 s, its variants to 100 s)."""
    end = lambda x: float("inf") if x["atRest"] else x["endTime"]
    t = min(end(r), end(base))
    if t == end(r) == end(base):
        return " (%+.1f %%)" % (100.0*(r["runout"]/base["runout"] - 1.0))
    if t == end(r):
        # A default row at rest before t stands where it stopped.
        ref = base["runout"] if base["atRest"] and t >= base["endTime"] else \
            front_at(base.get("history") or [], (t,))["%g" % t]
        return " (%+.1f %% against the default's front at %g s)" % (100.0*(r["runout"]/ref - 1.0), t) \
            if ref else " (the default's front at %g s not stored)" % t
    # The variant ran on past a default row that ended moving; its own front at that time is not stored.
    return " (the default ended moving at %g s)" % t


def row_of(res, key):
    """numerics.json's row of a run of variant `key` (run_case's or case_result's dict)."""
    res["variant"] = key
    history = res.pop("history", None) or []
    # The front at the times the README compares meshes at (the history itself is too long to store).
    res["frontAt"] = front_at(history, (10, 20, 25, 30))
    return res


def imported(d):
    """The row of a finished run directory case<NN>_h<cells>_p<ppc>_<variant>."""
    m = re.search(r"case(\d+)_h(\d+)_p(\d+)_(\w+)$", d.rstrip("/"))
    if not m or m.group(4) not in KEYS[1:]:
        raise SystemExit("numerics.py: --import %s: not a run directory case<NN>_h<cells>_p<ppc>_<variant> "
                         "(variants: %s)" % (d, ", ".join(KEYS[1:])))
    if m.group(4) in RATE_FREE and int(m.group(1)) != 1:
        raise SystemExit("numerics.py: --import %s: a rate-free variant of Case 1 only" % d)
    _, _, numerics, scene = VARIANTS[KEYS.index(m.group(4))]
    # The variant's entries as run_case writes them (`key value;`), so a run of other numerics is not stored as it.
    for name, entries in (("system/mpmDict", numerics), ("constant/sceneProperties", scene)):
        text = open(os.path.join(d, name)).read()
        for k, v in (entries or {}).items():
            if not re.search(r"^\s*%s\s+%s\s*;" % (re.escape(k), re.escape(str(v))), text, re.M):
                raise SystemExit("numerics.py: --import %s: %s has no '%s %s;' of the variant %s"
                                 % (d, name, k, v, m.group(4)))
    row = case_result(int(m.group(1)), int(m.group(2)), int(m.group(3)), d)
    if "particleShifting" not in (numerics or {}) and row["particleShifting"] != 0.0:
        raise SystemExit("numerics.py: --import %s: run with particleShifting %g, the variant %s without"
                         % (d, row["particleShifting"], m.group(4)))
    return row_of(row, m.group(4))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", default="2")
    ap.add_argument("--cells", default="20,40")
    ap.add_argument("--ppc", type=int, default=4)
    ap.add_argument("--variants", default="quadratic,stiff,quadraticStiff")
    ap.add_argument("--stored", action="store_true", help="rewrite numerics.md from numerics.json without running")
    ap.add_argument("--end-time", type=float, default=None, help="stop the runs at this time [s]")
    ap.add_argument("--import", dest="imports", nargs="*", default=[],
                    help="finished run directories case<NN>_h<cells>_p<ppc>_<variant> to store instead of running")
    args = ap.parse_args()
    cells = [int(x) for x in args.cells.split(",")]
    wanted = args.variants.split(",")
    asked = [v for v in wanted if v in RATE_FREE]
    if asked and args.cases != "1":
        raise SystemExit("numerics.py: --variants %s: Case 1's strength without the rate term, --cases 1 only"
                         % ",".join(asked))
    for v in wanted:
        if v not in KEYS[1:]:
            raise SystemExit("numerics.py: --variants: unknown variant '%s' (known: %s)" % (v, ", ".join(KEYS[1:])))
    path = os.path.join(here, "numerics.json")
    stored = json.load(open(path)) if os.path.isfile(path) else []
    results = []
    if args.imports:
        results = [imported(d) for d in args.imports]
    elif not args.stored:
        work = tempfile.mkdtemp(prefix="slideMPM_numerics_")
        for case, n, (key, _, numerics, scene) in [(c, n, v) for c in [int(x) for x in args.cases.split(",")]
                                             for n in cells for v in VARIANTS if v[0] in wanted]:
            res = run_case(case, n, args.ppc, work, numerics=numerics, scene=scene, tag="_" + key,
                           end_time=args.end_time)
            results.append(row_of(res, key))
            print("case %d H0/%d %s: %s" % (case, n, key, "FAILED" if "failed" in res else
                                            "%.2f m, %s, %.0f s wall" % (
                                                res["runout"], "at rest by %.1f s" % res["endTime"]
                                                if res["atRest"] else "moving at %g s" % res["endTime"],
                                                res["wall"])), flush=True)
        shutil.rmtree(work, ignore_errors=True)
    if not args.stored:
        new = {(r["case"], r["cells"], r["ppc"], r["variant"]) for r in results}
        results = [r for r in stored if (r["case"], r["cells"], r["ppc"], r["variant"]) not in new] + results
        results.sort(key=lambda r: (r["case"], r["ppc"], r["cells"], KEYS.index(r["variant"])))
        with open(path, "w") as f:
            json.dump(results, f, indent=1)
    else:
        results = stored
    write_table(results)


def write_table(results):
    paper = paper_table()
    table1 = json.load(open(os.path.join(here, "table1.json")))
    lines = ["# slideMPM's converged Table 1 runouts against its own numerics", "",
             "Regenerated by `validation/mpm/numerics.py` (its docstring says why). Runout: the front's travel (m) "
             "at rest, or at the end time where still moving; in brackets the change against the default "
             "numerics (APIC, E = 100 s_uo: table1.json's row, marked where it ran with the Cauchy stress's rate, "
             "before session 40); numerical: the energy budget's remainder, the share of gravity's work that is neither "
             "kinetic, elastic, plastic nor the boundary's (what the discretisation lost; absent from rows run "
             "before it was stored); wall: seconds on 2 threads of the 2-core machine that ran it. The rate-free columns are Case 1 without Eq. (1)'s "
             "rate term and with s_uo 225 Pa (the script's comment says why): another model, to be read down the "
             "column, between cells; their brackets say only how far that model runs beyond Eq. (1).", "",
             "| case | cell | particles per cell | paper MPM [m] | " + " | ".join(v[1] for v in VARIANTS) + " |",
             "|---|---|---|---|" + "---|"*len(VARIANTS)]
    for case, ppc, n in sorted({(r["case"], r["ppc"], r["cells"]) for r in results}):
        base = table1_row(table1, case, n, ppc)
        row = {"apic": base}
        row.update({r["variant"]: r for r in results
                    if (r["case"], r["ppc"], r["cells"]) == (case, ppc, n)})
        cells = []
        for key in KEYS:
            r = row.get(key)
            if r is None:
                cells.append("-")
                continue
            if "failed" in r:
                cells.append("failed")
                continue
            text = "%.2f" % r["runout"]
            if key != "apic" and base is not None:
                text += change_against(r, base)
            text += ", at rest by %.0f s" % r["endTime"] if r["atRest"] else ", moving at %g s" % r["endTime"]
            if r.get("numericalDissipation") is not None:
                text += ", numerical %.1f %%" % (100.0*r["numericalDissipation"])
            text += ", %.0f s wall" % r["wall"]
            if key == "apic" and cauchy_rate(r):
                text += ", Cauchy stress rate"
            cells.append(text)
        lines.append("| %d | H0/%d | %dx%d | %s | %s |" % (case, n, ppc, ppc, paper[case][1].get("MPM", "-"),
                                                         " | ".join(cells)))
    out = os.path.join(here, "numerics.md")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
