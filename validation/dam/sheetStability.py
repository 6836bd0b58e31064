#!/usr/bin/env python3
"""How slideDAM's Table 1 Cases 1 and 12 converge in the columns and the Courant number: thin, fast sheets.

    validation/dam/sheetStability.py [--fine] [--stored]

Case 12 has no rate term. Its wholly remoulded clay (s_uo delta_rem = 250 Pa) holds at most 0.71 m on its slope, so
its front runs out as a thinner sheet and stops where the sheet's momentum is spent; Case 1's weak clay runs out as a
sheet too. Until session 76 slideDAM's Case 12 fell from 439 to 406 m between 800 and 6400 columns at the fast
setting's Courant number 0.5. Two mechanisms can make a sheet's runout depend on the columns:
- the explicit step: the momentum-flux bracket of Eq. (3), its column value taken at the mean of its two nodes'
  velocities, is a central difference stepped by forward Euler, which amplifies the shortest waves by a factor of
  about 1 + nu^2/2 every step (nu the step's Courant number on that term); a finer column at a fixed Courant number
  takes more steps, so the growth goes as courant x columns, and a smaller Courant number removes it (a build
  without the bracket did not depend on the step: README, "Thin, fast sheets and the explicit step");
- the sheet's own instability: the basal stress of a rate-free clay is s_u whatever the speed, so per unit mass it
  resists a thinner stretch more (s_u/(rho D)). Linearised about a uniform sheet of thickness D with one velocity,
  lambda^2 = -(k^2 c^2 + i k D K), c^2 = g cos(theta) D, K = s_u/(rho D^2), one wave grows, at up to
  sigma_inf = s_u/(2 rho D c) for waves shorter than about 2 pi/k*, k* = s_u/(rho g cos(theta) D^2). This growth is
  the model's and does not depend on the step.
The script runs slideDAM (fast setting, tutorials/table1) on:
- a matrix: Cases 1 and 12 with 200, 800, 3200 and 6400 columns (and 12800 with --fine) at Courant numbers 0.5,
  0.25 and 0.125, marking the cell the default (courant left out: min(0.5, 1600/columns)) takes;
- ensembles: Case 12 with N-4 ... N+4 columns at N = 800, Courant 0.5 (the Table 1 set-up), and with --fine at
  N = 6400, Courant 0.5 and 0.25: how much a run's runout moves with a change as small as one column;
- growth: for each Case 12 run of the matrix, the thickness of its sheet (the front 150 m less its last 5 m) against
  its 20 m running mean, as an RMS of the relative deviation at each second; its steepest growth over 4 s once the
  sheet is thinner than h_c = s_u/(rho' g sin(theta)), against sigma_inf at the sheet's mean thickness and s_u.
Writes sheetStability.json, sheetStability.md and sheetStability.png here (about 5 minutes on 2 cores, 25 with
--fine); --stored rewrites the .md and .png from the .json."""
import math
import os
import shutil
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
from cfdcase import get_entry, make_case  # noqa: E402
from runner import TOP, run_method  # noqa: E402
from slidefoam_io import read_pvd, read_vtp  # noqa: E402
import options  # noqa: E402
import layerProfile  # noqa: E402

ENSEMBLE_HALF = 4          # N-4 ... N+4 columns
SHEET_BACK, SHEET_TIP = 150.0, 5.0   # the sheet: from 150 m behind the front to 5 m behind it [m]
WINDOW = 20.0              # running mean's length [m]
FIT_SPAN = 4.0             # the span of the growth fitted [s]
CASES = (1, 12)
COLUMNS, FINE_COLUMNS = (200, 800, 3200, 6400), (12800,)
COURANTS = (0.5, 0.25, 0.125)
ENSEMBLES, FINE_ENSEMBLES = ((800, 0.5),), ((6400, 0.5), (6400, 0.25))   # Case 12's (N, Courant)


def default_courant(columns):
    """slideDAM's Courant number where damDict leaves it out (DamControls::courantColumns)."""
    return min(0.5, 1600.0/columns)


def case_dir(case):
    return os.path.join(TOP, "tutorials", "table1", "case%02d" % case)


def run(work, case, columns, courant, fields=False):
    """slideDAM on Table 1's case: (runout, at rest, end time, wall time, profile.pvd or None)."""
    d = make_case(case_dir(case), work, "case%d_%d_%g" % (case, columns, courant),
                  dicts={"system/damDict": "setting fast;\ncolumns %d;\ncourant %g;\nwriteFields %s;\nwriteState no;\n"
                         % (columns, courant, "yes" if fields else "no")})
    s, _ = run_method("slideDAM", d)
    pvd = os.path.join(d, "postProcessing", "slideDAM", "profile.pvd") if fields else None
    return s["runout_m"], s["at_rest"], s["end_time_s"], s["wall_time_s"], pvd


def sheet_deviation(pvd):
    """[(t, RMS of (h - running mean)/running mean over the sheet, mean h, mean s_u, least xi)] per written time."""
    out = []
    du = 0.05
    k = int(round(WINDOW/du))
    for t, path in read_pvd(pvd):
        _, a = read_vtp(path)
        s, h = a["s"], a["thickness"]
        su = np.arange(s[-1] - SHEET_BACK, s[-1] - SHEET_TIP, du)
        if su[0] - WINDOW/2 < s[0]:
            continue   # the slide is still shorter than the sheet's window
        ext = np.arange(su[0] - WINDOW/2, su[-1] + WINDOW/2 + du/2, du)
        mean = np.convolve(np.interp(ext, s, h), np.ones(k)/k, mode="valid")[:len(su)]
        hu = np.interp(su, s, h)
        inside = s >= su[0]
        out.append((t, float(np.sqrt(np.mean(((hu - mean)/mean)**2))), float(hu.mean()),
                    float(np.mean(np.interp(su, s, a["s_u"]))), float(a["xi"][inside].min())))
    return out


def growth_rate(rows, rho, g_normal):
    """The steepest growth of the RMS over FIT_SPAN seconds while the sheet is thinner than the remoulded clay
    holds (layerProfile.yield_depth), and, over that span, the sheet's mean thickness, s_u and sigma_inf."""
    thin = [r for r in rows if r[2] < layerProfile.yield_depth(r[3])]
    best = None
    for i in range(len(thin)):
        w = [r for r in thin[i:] if r[0] <= thin[i][0] + FIT_SPAN + 1e-9]
        if w[-1][0] < thin[i][0] + FIT_SPAN - 1e-9:
            break
        rate = float(np.polyfit([r[0] for r in w], np.log([r[1] for r in w]), 1)[0])
        if best is None or rate > best[0]:
            best = (rate, w)
    if best is None:
        return None
    rate, w = best
    D = float(np.mean([r[2] for r in w]))
    s_u = float(np.mean([r[3] for r in w]))
    return {"from": w[0][0], "to": w[-1][0], "rate": rate, "thickness": D, "s_u": s_u,
            "least_xi": min(r[4] for r in w), "sigma_inf": s_u/(2.0*rho*D*math.sqrt(g_normal*D)),
            "k_star": s_u/(rho*g_normal*D*D), "thin_from": thin[0][0]}


def measure(fine):
    work = tempfile.mkdtemp(prefix="slideDAM_sheetStability_")
    jobs = [(case, n, co, n, case == 12) for case in CASES for n in COLUMNS + (FINE_COLUMNS if fine else ())
            for co in COURANTS]
    for n, co in ENSEMBLES + (FINE_ENSEMBLES if fine else ()):
        jobs += [(12, m, co, n, False) for m in range(n - ENSEMBLE_HALF, n + ENSEMBLE_HALF + 1) if m != n]
    # The longest first, so that the two workers finish together (steps go as columns^2/Courant).
    jobs.sort(key=lambda j: -j[1]**2/j[2])

    def one(job):
        out = run(work, *job[:3], fields=job[4])
        case, m, co = job[:3]
        print("case %d, %d columns, Courant %g: %.2f m%s, %.0f s" % (case, m, co, out[0], "" if out[1] else
              " (moving at %g s)" % out[2], out[3]), flush=True)
        row = {"case": case, "columns": m, "courant": co, "of": job[3], "runout": out[0], "at_rest": out[1],
               "end_time": out[2], "wall": out[3]}
        if out[4]:
            row["series"] = sheet_deviation(out[4])
            shutil.rmtree(os.path.dirname(os.path.dirname(out[4])), ignore_errors=True)
        return row
    with ThreadPoolExecutor(max_workers=2) as pool:
        rows = list(pool.map(one, jobs))
    shutil.rmtree(work, ignore_errors=True)
    return {"runs": sorted(rows, key=lambda r: (r["case"], r["columns"], -r["courant"]))}


def spread(runs):
    r = np.array([x["runout"] for x in runs])
    return r.mean(), r.min(), r.max(), 100.0*(r.max() - r.min())/r.mean()


def write(data):
    scene = os.path.join(case_dir(12), "constant", "sceneProperties")
    if (get_entry(scene, "angle"), get_entry(scene, "density")) != (layerProfile.THETA, layerProfile.RHO):
        raise SystemExit("sheetStability.py: Case 12's slope or density is not layerProfile's")
    g_normal = layerProfile.G*math.cos(math.radians(layerProfile.THETA))
    runs = data["runs"]
    matrix = {(r["case"], r["columns"], r["courant"]): r for r in runs if r["of"] == r["columns"]}
    columns = sorted({k[1] for k in matrix})
    with open(os.path.join(HERE, "sheetStability.md"), "w") as f:
        f.write("Regenerated by `validation/dam/sheetStability.py` (the method and the linear theory in its docstring): "
                "slideDAM, fast setting, tutorials/table1. Runout at rest [m]; **bold**: the Courant number slideDAM "
                "takes where damDict leaves it out, min(0.5, 1600/columns) since session 76 (0.5 before).\n\n")
        for case in CASES:
            f.write("| Case %d: columns | %s |\n|---|%s\n" % (case, " | ".join("Courant %g" % c for c in COURANTS),
                                                              "---|"*len(COURANTS)))
            for n in columns:
                cells = []
                for co in COURANTS:
                    r = matrix.get((case, n, co))
                    v = "-" if r is None else "%.1f%s" % (r["runout"], "" if r["at_rest"] else " (moving)")
                    cells.append("**%s**" % v if r is not None and co == default_courant(n) else v)
                f.write("| %d | %s |\n" % (n, " | ".join(cells)))
            f.write("\n")
        f.write("Case 12 with N-%d ... N+%d columns: how far a run moves with a change of one column.\n\n"
                "| N | Courant | runouts [m] | mean [m] | spread (max - min)/mean |\n|---|---|---|---|---|\n"
                % (ENSEMBLE_HALF, ENSEMBLE_HALF))
        for n, co in ENSEMBLES + FINE_ENSEMBLES:
            ens = sorted((r for r in runs if r["case"] == 12 and r["of"] == n and r["courant"] == co),
                         key=lambda r: r["columns"])
            if len(ens) < 2:
                continue
            m, _, _, sp = spread(ens)
            f.write("| %d | %g | %s | %.1f | %.2f %% |\n" % (n, co, " ".join("%.1f" % r["runout"] for r in ens), m, sp))
        f.write("\nCase 12's sheet (the front %g m less its last %g m): RMS of its thickness's relative deviation from "
                "the %g m running mean. Once the sheet is thinner than the remoulded clay holds (h_c, from the time "
                "given), its steepest growth over %g s is fitted as exp(rate t) and set against the linear theory's "
                "sigma_inf = s_u/(2 rho D c) at the sheet's mean thickness D and s_u over that span:\n\n"
                % (SHEET_BACK, SHEET_TIP, WINDOW, FIT_SPAN))
        f.write("| columns | Courant | RMS at 20 / 25 / 30 / 35 s | thinner than h_c from [s] | steepest growth over [s] "
                "| growth rate [1/s] | D [m] | s_u [Pa] | least xi | sigma_inf [1/s] | rate / sigma_inf | 2 pi/k* [m] |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in runs:
            if "series" not in r:
                continue
            at = {round(x[0], 6): x[1] for x in r["series"]}
            rms = " / ".join("%.3f" % at[t] if t in at else "-" for t in (20.0, 25.0, 30.0, 35.0))
            fit = r["fit"] = growth_rate(r["series"], layerProfile.RHO, g_normal)
            if fit is None:
                f.write("| %d | %g | %s | not thinner for %g s | | | | | | | | |\n" % (r["columns"], r["courant"], rms,
                                                                                   FIT_SPAN))
                continue
            f.write("| %d | %g | %s | %.0f | %.0f-%.0f | %.3f | %.3f | %.1f | %.0f | %.3f | %.2f | %.1f |\n" % (
                r["columns"], r["courant"], rms, fit["thin_from"], fit["from"], fit["to"], fit["rate"],
                fit["thickness"], fit["s_u"], fit["least_xi"], fit["sigma_inf"], fit["rate"]/fit["sigma_inf"],
                2*math.pi/fit["k_star"]))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    for ax, case in zip(axes[:2], CASES):
        for co, col in zip(COURANTS, ("C3", "C0", "C2")):
            pts = [(n, matrix[(case, n, co)]["runout"]) for n in columns if (case, n, co) in matrix]
            ax.plot(*zip(*pts), "o-", color=col, label="Courant %g" % co)
        if case == 12:
            for n, co in ENSEMBLES + FINE_ENSEMBLES:
                ens = [r for r in runs if r["case"] == 12 and r["of"] == n and r["courant"] == co]
                ax.plot([r["columns"] for r in ens], [r["runout"] for r in ens], ".",
                        color={0.5: "C3", 0.25: "C0"}[co], ms=3)
        dflt = [(n, matrix[(case, n, default_courant(n))]["runout"]) for n in columns
                if (case, n, default_courant(n)) in matrix]
        ax.plot(*zip(*dflt), "k--", lw=1, label="default since session 76")
        ax.set_xscale("log")
        ax.set_xlabel("columns")
        ax.set_ylabel("runout at rest [m]")
        ax.set_title("Table 1 Case %d: slideDAM against the columns" % case, fontsize=9)
        ax.legend(fontsize=8)
    ax = axes[2]
    for r in runs:
        if "series" in r and r["courant"] in (0.5, 0.125) and r["columns"] >= 800:
            ax.semilogy([x[0] for x in r["series"]], [x[1] for x in r["series"]],
                        "-" if r["courant"] == 0.5 else ":", label="%d columns, Courant %g" % (r["columns"], r["courant"]))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("RMS relative thickness deviation of the sheet")
    ax.set_title("Case 12: thickness waves on the sheet", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "sheetStability.png"), dpi=110)


def main():
    write(options.measured_or_stored(__doc__, os.path.join(HERE, "sheetStability.json"), measure))
    print(open(os.path.join(HERE, "sheetStability.md")).read())


if __name__ == "__main__":
    main()
