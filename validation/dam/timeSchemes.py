#!/usr/bin/env python3
"""Where slideDAM's two time schemes part: the face collapses (Table 1 Cases 6-8) and the surging sheets (Cases 4, 5).

    validation/dam/timeSchemes.py [--fine] [--stored]

Session 76 found forward Euler (the table's) and Shu-Osher's third-order step (damDict `timeScheme rk3`) within 1 %
of each other on Table 1 Cases 1-4, 10, 12 and 13, and apart on Case 5 (7517 against 9622 m) and the face-collapse
Cases 6-8 (2.70 / 5.80 / 47.24 against 2.56 / 5.19 / 44.84 m), all at 800 columns and Courant 0.5. This script asks
of each case whether the two schemes approach one runout as the step shrinks, or whether the runout is not a
function of the step at all:
- step: Cases 6, 7 and 8 at 800 columns with forward Euler at Courant 0.5/2^k (k = 0 ... 5) and rk3 at 0.5/2^k
  (k = 0 ... 4). The runout at rest against the Courant number; each scheme's limit estimated from its two
  smallest steps as a first-order sequence (Richardson: 2 R(c/2) - R(c)), and the error of the table's set-up
  (forward Euler at 0.5) against the mean of the two limits;
- ensemble: Cases 4 and 5 (the weakest clay, 50 Pa, on 3.43 and 10 deg), each with N-4 ... N+4 columns at Courant
  0.5, N = 200, 400 and 800 (and 1600 with --fine) with forward Euler and N = 800 with rk3, and Case 4 at Courant
  0.125 with N = 800 (and 1600), each run as the tutorial's case (its controlDict too: the step is cut to land on the
  write times, so a different writeInterval is a different run). The runout's mean and spread per N, and for each
  run how often its front stalled (below the tutorial's restVelocity) and then moved again faster than 1 m/s
  before the final rest: the surges, as slideDAM counts them every step (summary.json `front_surges`).
Writes timeSchemes.json, timeSchemes.md and timeSchemes.png here (about 10 minutes on 2 cores, 14 with --fine);
--stored rewrites the .md and .png from the .json."""
import os
import shutil
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
from cfdcase import make_case  # noqa: E402
from paper import paper_table  # noqa: E402
from runner import TOP, run_method  # noqa: E402
import options  # noqa: E402

COLUMNS = 800                     # the table's
FACE_CASES = (6, 7, 8)
SURGE_CASES = (4, 5)
EULER_COURANTS = tuple(0.5/2**k for k in range(6))
RK3_COURANTS = tuple(0.5/2**k for k in range(5))
ENSEMBLE_HALF = 4
# (scheme, N, Courant number, cases): Case 5 at a smaller step takes too long (67 s a run at 800 columns and 0.125).
ENSEMBLES = (("euler", 200, 0.5, SURGE_CASES), ("euler", 400, 0.5, SURGE_CASES), ("euler", 800, 0.5, SURGE_CASES),
             ("euler", 800, 0.125, (4,)), ("rk3", 800, 0.5, SURGE_CASES))
FINE_ENSEMBLES = (("euler", 1600, 0.5, SURGE_CASES), ("euler", 1600, 0.125, (4,)))


def ensembles_in_order():
    """Forward Euler's by N and then by the step, then rk3's."""
    return sorted(ENSEMBLES + FINE_ENSEMBLES, key=lambda e: (e[0] == "rk3", e[1], -e[2]))


def case_dir(case):
    return os.path.join(TOP, "tutorials", "table1", "case%02d" % case)


def run(work, case, scheme, columns, courant):
    d = make_case(case_dir(case), work, "case%d_%s_%d_%g" % (case, scheme, columns, courant),
                  dicts={"system/damDict": "setting fast;\ncolumns %d;\ntimeScheme %s;\ncourant %g;\nwriteFields no;\n"
                         "writeState no;\n" % (columns, scheme, courant)})
    s, r = run_method("slideDAM", d)
    row = {"case": case, "scheme": scheme, "columns": columns, "courant": courant, "runout": s["runout_m"],
           "at_rest": s["at_rest"], "end_time": s["end_time_s"], "wall": s["wall_time_s"]}
    if case in SURGE_CASES:
        row["surges"] = s["front_surges"]
        row["max_thickness_after"] = float(r["maxThickness"][r["time"] >= 30.0].max())
    if plotted(row):
        keep = np.arange(0, len(r["time"]), 5)
        row["front"] = [[float(r["time"][i]), float(r["front"][i])] for i in keep]
    shutil.rmtree(d, ignore_errors=True)
    return row


def measure(fine):
    work = tempfile.mkdtemp(prefix="slideDAM_timeSchemes_")
    jobs = [(c, "euler", COLUMNS, co) for c in FACE_CASES for co in EULER_COURANTS]
    jobs += [(c, "rk3", COLUMNS, co) for c in FACE_CASES for co in RK3_COURANTS]
    for scheme, n, courant, cases in ENSEMBLES + (FINE_ENSEMBLES if fine else ()):
        jobs += [(c, scheme, m, courant) for c in cases for m in range(n - ENSEMBLE_HALF, n + ENSEMBLE_HALF + 1)]
    # The longest first, so that the two workers finish together.
    jobs.sort(key=lambda j: -(j[2]**2*(1 if j[0] == 5 else 0.1) if j[0] in SURGE_CASES else 1.0)/j[3]
                           *(3 if j[1] == "rk3" else 1))

    def one(job):
        row = run(work, *job)
        print("case %d, %s, %d columns, Courant %g: %.3f m%s, %.1f s of wall" % (
            job + (row["runout"], "" if row["at_rest"] else " (moving at %g s)" % row["end_time"], row["wall"])),
            flush=True)
        return row
    with ThreadPoolExecutor(max_workers=2) as pool:
        rows = list(pool.map(one, jobs))
    shutil.rmtree(work, ignore_errors=True)
    return {"runs": sorted(rows, key=lambda r: (r["case"], r["scheme"], r["columns"], -r["courant"]))}


def plotted(row):
    """Whether a run's front history is plotted: Case 5's forward-Euler ensemble at the table's set-up."""
    return ((row["case"], row["scheme"], row["courant"]) == (5, "euler", 0.5)
            and abs(row["columns"] - COLUMNS) <= ENSEMBLE_HALF)


def ensemble(runs, case, scheme, n, courant):
    return sorted((r for r in runs if r["case"] == case and r["scheme"] == scheme and r["courant"] == courant
                   and abs(r["columns"] - n) <= ENSEMBLE_HALF), key=lambda r: r["columns"])


def richardson(rows):
    """First-order limit from the two smallest steps of a sequence halving the Courant number."""
    a, b = sorted(rows, key=lambda r: r["courant"])[:2]
    return 2.0*a["runout"] - b["runout"]


def write(data):
    runs = data["runs"]
    paper = paper_table()
    face = {(r["case"], r["scheme"], r["courant"]): r for r in runs if r["case"] in FACE_CASES}
    lines = ["Regenerated by `validation/dam/timeSchemes.py` (the method in its docstring): slideDAM, fast setting, "
             "tutorials/table1.", "",
             "**The face collapses against the step** (%d columns; runout at rest [m]):" % COLUMNS, "",
             "| case | scheme | %s | limit (Richardson) |" % " | ".join("Courant %g" % c for c in EULER_COURANTS),
             "|---|---|%s---|" % ("---|"*len(EULER_COURANTS))]
    limits = {}
    for c in FACE_CASES:
        for scheme, courants in (("euler", EULER_COURANTS), ("rk3", RK3_COURANTS)):
            seq = [face[(c, scheme, co)] for co in courants if (c, scheme, co) in face]
            limits[(c, scheme)] = richardson(seq)
            cells = ["%.3f" % face[(c, scheme, co)]["runout"] if (c, scheme, co) in face else "-"
                     for co in EULER_COURANTS]
            lines.append("| %d | %s | %s | %.3f |" % (c, scheme, " | ".join(cells), limits[(c, scheme)]))
    lines += ["", "| case | paper DAM [m] | limits euler / rk3 [m] | their difference | the table's (euler, 0.5) "
              "against their mean | rk3 at 0.5 against it |", "|---|---|---|---|---|---|"]
    for c in FACE_CASES:
        le, lr = limits[(c, "euler")], limits[(c, "rk3")]
        mean = 0.5*(le + lr)
        lines.append("| %d | %s | %.3f / %.3f | %+.2f %% | %+.1f %% | %+.1f %% |" % (
            c, paper[c][1].get("DAM", "-"), le, lr, 100.0*(le - lr)/mean,
            100.0*(face[(c, "euler", 0.5)]["runout"] - mean)/mean, 100.0*(face[(c, "rk3", 0.5)]["runout"] - mean)/mean))
    lines += ["", "**The surging sheets with N-%d ... N+%d columns** (runout at rest [m]; surges: how often the "
              "front stalled and was carried on again, slideDAM's summary.json `front_surges`; the largest thickness "
              "after 30 s against the slide's initial 5 m):" % (ENSEMBLE_HALF, ENSEMBLE_HALF), "",
              "| case | paper DAM [m] | scheme | N | Courant | runouts [m] | mean [m] | min-max against the mean | "
              "surges per run | largest thickness after 30 s [m] | at rest by [s] |",
              "|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in SURGE_CASES:
        for scheme, n, courant, _ in ensembles_in_order():
            ens = ensemble(runs, c, scheme, n, courant)
            if not ens:
                continue
            x = np.array([r["runout"] for r in ens])
            lines.append("| %d | %s | %s | %d | %g | %s | %.0f | %+.1f / %+.1f %% | %d-%d | %.1f-%.1f | %.0f-%.0f%s |" % (
                c, paper[c][1].get("DAM", "-"), scheme, n, courant, " ".join("%.0f" % v for v in x), x.mean(),
                100.0*(x.min() - x.mean())/x.mean(), 100.0*(x.max() - x.mean())/x.mean(),
                min(r["surges"] for r in ens), max(r["surges"] for r in ens),
                min(r["max_thickness_after"] for r in ens), max(r["max_thickness_after"] for r in ens),
                min(r["end_time"] for r in ens), max(r["end_time"] for r in ens),
                "" if all(r["at_rest"] for r in ens) else " (some moving)"))
    lines.append("")
    with open(os.path.join(HERE, "timeSchemes.md"), "w") as f:
        f.write("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    ax = axes[0]
    for c, col in zip(FACE_CASES, ("C0", "C1", "C2")):
        for scheme, courants, style in (("euler", EULER_COURANTS, "o-"), ("rk3", RK3_COURANTS, "s--")):
            pts = [(co, face[(c, scheme, co)]["runout"]) for co in courants if (c, scheme, co) in face]
            mean = 0.5*(limits[(c, "euler")] + limits[(c, "rk3")])
            ax.plot([p[0] for p in pts], [100.0*(p[1] - mean)/mean for p in pts], style, color=col,
                    label="Case %d, %s" % (c, scheme))
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xscale("log", base=2)
    ax.set_xlabel("Courant number")
    ax.set_ylabel("runout against the mean of the two limits [%]")
    ax.set_title("Face collapses (Cases 6-8, %d columns): both schemes, one limit" % COLUMNS, fontsize=9)
    ax.legend(fontsize=7, ncol=2)
    ax = axes[1]
    shown = []
    for scheme, n, courant, _ in ensembles_in_order():
        found = False
        for c, marker in zip(SURGE_CASES, ("s", "o")):
            ens = ensemble(runs, c, scheme, n, courant)
            if ens:
                found = True
                ax.plot([len(shown) + (0.15 if c == 5 else -0.15)]*len(ens),
                        [r["runout"]/paper[c][1]["DAM"] for r in ens], marker,
                        color="C3" if scheme == "rk3" else "C0", mfc="none" if c == 4 else None, ms=4,
                        label="Case %d" % c if not shown else None)
        if found:
            shown.append("%s\n%d\n%g" % (scheme, n, courant))
    ax.axhline(1.0, color="k", ls=":", label="paper's DAM")
    ax.set_xticks(range(len(shown)))
    ax.set_xticklabels(shown, fontsize=8)
    ax.set_ylabel("runout at rest / the paper's DAM")
    ax.set_title("Cases 4 and 5: N-%d ... N+%d columns (scheme, N, Courant)" % (ENSEMBLE_HALF, ENSEMBLE_HALF),
                 fontsize=9)
    ax.legend(fontsize=8)
    ax = axes[2]
    for r in filter(plotted, runs):
        t, x = zip(*r["front"])
        ax.plot(t, x, lw=0.8, label="%d columns" % r["columns"])
    ax.set_xlabel("t [s]")
    ax.set_ylabel("front [m]")
    ax.set_title("Case 5, forward Euler: the front stalls and is overrun", fontsize=9)
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "timeSchemes.png"), dpi=110)


def main():
    write(options.measured_or_stored(__doc__, os.path.join(HERE, "timeSchemes.json"), measure))
    print(open(os.path.join(HERE, "timeSchemes.md")).read())


if __name__ == "__main__":
    main()
