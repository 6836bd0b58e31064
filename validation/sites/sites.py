#!/usr/bin/python3
"""What the three methods say passes over sites ahead of a slide (pipeline or cable
crossings): sceneProperties `sites`, recorded every step by each method
(src/output/siteMonitor.H). Runs slideDAM, slideMPM and slideFoam at the tutorials'
own set-ups on two scenes with sites at several distances ahead of the initial front:
Table 1 Case 2 (a weak slide whose runout the three methods and the paper agree on
within 7 %) and the Mediterranean escarpment (a sensitive slab whose runout they do
not agree on). Also times slideMPM on the flagship flume (its `fast` set-up) with its two
gauges and without sites, three runs each, alternating: the cost of the per-step
reduction over the particles. Writes sites.json, sites.md and sites.png here. ~9 min on 2 cores.

Usage: validation/sites/sites.py [--stored]
  --stored: redraw sites.md and sites.png from sites.json without running
"""
import json
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "validation", "lib"))
import options  # noqa: E402
from cfdcase import copy_scene  # noqa: E402
from runner import run_method, slidefoam_env  # noqa: E402
from slidefoam_io import read_summary  # noqa: E402

# (name, tutorial, initial front's arc length [m], distances of the sites ahead of it [m])
CASES = [("Table 1 Case 2", "tutorials/table1/case02", 40.0, [5, 10, 20, 30, 40, 50]),
         ("Mediterranean escarpment", "tutorials/mediterraneanEscarpment", 58.476, [40, 100, 200, 300, 450])]
METHODS = [("slideDAM", "DAM"), ("slideMPM", "MPM"), ("slideFoam", "CFD")]


def with_sites(scene_path, positions):
    """The scene with its `sites` block (if any) replaced by sites at the given arc lengths."""
    text = open(scene_path).read()
    k = text.find("\nsites")
    if k >= 0:
        depth, j = 0, text.index("{", k)
        while True:
            depth += {"{": 1, "}": -1}.get(text[j], 0)
            j += 1
            if depth == 0:
                break
        text = text[:k] + text[j:]
    text += "\nsites\n{\n" + "".join("    d%g { position %.6g; }\n" % (d, s) for d, s in positions) + "}\n"
    with open(scene_path, "w") as f:
        f.write(text)


def measure():
    work = os.path.join(TOP, "platforms", "validation-work", "sites")
    data = []
    for name, tutorial, front, distances in CASES:
        case = os.path.join(work, os.path.basename(tutorial))
        if os.path.exists(case):
            shutil.rmtree(case)
        copy_scene(os.path.join(TOP, tutorial), case)
        with_sites(os.path.join(case, "constant", "sceneProperties"), [(d, front + d) for d in distances])
        entry = {"case": name, "tutorial": tutorial, "distances": distances, "methods": {}}
        for app, short in METHODS:
            t0 = time.time()
            if app == "slideFoam":
                subprocess.run(["bash", "-c", ". '%s/bin/tools/RunFunctions' && runSlideFoam" % TOP], cwd=case,
                               check=True, env=slidefoam_env())
                summary = read_summary(os.path.join(case, "postProcessing", app, "summary.json"))
            else:
                summary, _ = run_method(app, case, env={"OMP_NUM_THREADS": "2", "OMP_PROC_BIND": "false"})
            entry["methods"][short] = {"runout": summary["runout_m"], "atRest": summary["at_rest"],
                                       "end": summary["end_time_s"], "wall": time.time() - t0,
                                       "sites": summary["sites"]}
            print("%s %s: runout %.1f m, %.0f s" % (name, short, summary["runout_m"], time.time() - t0), flush=True)
        data.append(entry)
    return data


def measure_overhead(runs=3):
    """Wall time [s] of slideMPM's flume at its fast set-up with the tutorial's two gauges and with no sites."""
    work = os.path.join(TOP, "platforms", "validation-work", "sites")
    walls = {"with": [], "without": []}
    for k in range(runs):
        for label in ("with", "without"):
            case = os.path.join(work, "flume_" + label)
            if os.path.exists(case):
                shutil.rmtree(case)
            copy_scene(os.path.join(TOP, "tutorials", "kroneWrightRun15"), case)
            if label == "without":
                with_sites(os.path.join(case, "constant", "sceneProperties"), [])
                text = open(os.path.join(case, "constant", "sceneProperties")).read()
                with open(os.path.join(case, "constant", "sceneProperties"), "w") as f:
                    f.write(text.replace("\nsites\n{\n}\n", "\n"))
            summary, _ = run_method("slideMPM", case, env={"OMP_NUM_THREADS": "2", "OMP_PROC_BIND": "false"})
            walls[label].append(summary["wall_time_s"])
            print("flume slideMPM %s sites: %.2f s" % (label, summary["wall_time_s"]), flush=True)
    return walls


def fmt(v, f="%.2f"):
    return "-" if v is None else f % v


def write_md(data):
    lines = ["# What passes over a site: the three methods at the same places",
             "", "Regenerated by `validation/sites/sites.py` (`--stored` redraws from `sites.json`). Sites in "
             "`constant/sceneProperties` (`sites { name { position s; } }`), recorded every step by each method "
             "(`postProcessing/<method>/sites.dat`, `summary.json` \"sites\"; `src/output/siteMonitor.H`). A site is "
             "covered while it lies between the slide's rear and front; its arrival is when the front passes it; "
             "speed is the depth-averaged velocity along the base over the site; thickness is normal to the base. "
             "Each method at its tutorial's set-up; \"-\": never reached.", ""]
    for e in data["cases"]:
        lines += ["## %s (`%s`)" % (e["case"], e["tutorial"]), ""]
        lines.append("Runout: " + ", ".join("%s %.1f m (%s, %.0f s wall)" % (
            m, r["runout"], "at rest" if r["atRest"] else "moving at %g s" % r["end"], r["wall"])
            for m, r in e["methods"].items()) + ".")
        lines += ["", "| ahead of the initial front [m] | quantity | " + " | ".join(e["methods"]) + " |",
                  "|---|---|" + "---|"*len(e["methods"])]
        for k, d in enumerate(e["distances"]):
            for key, label, f in [("arrival_time_s", "arrival [s]", "%.2f"), ("peak_speed_m_s", "peak speed [m/s]", "%.2f"),
                                  ("max_thickness_m", "largest thickness [m]", "%.2f"),
                                  ("final_thickness_m", "final thickness [m]", "%.2f")]:
                lines.append("| %g | %s | %s |" % (d, label, " | ".join(fmt(r["sites"][k][key], f)
                                                                     for r in e["methods"].values())))
        lines.append("")
    lines += ["![arrival and peak speed against the distance ahead](sites.png)", ""]
    w = data.get("overhead")
    if w:
        lo = lambda v: min(v)
        lines += ["## What sampling costs slideMPM", "",
                  "The flume (`tutorials/kroneWrightRun15`, slideMPM's `fast` set-up, 2 threads) with its two gauges "
                  "and without sites, %d runs each, alternating: %s s with, %s s without; fastest %.2f against "
                  "%.2f s (%+.1f %%). slideDAM and slideFoam read the sites off columns they have already summed." % (
                      len(w["with"]), " / ".join("%.2f" % v for v in w["with"]),
                      " / ".join("%.2f" % v for v in w["without"]), lo(w["with"]), lo(w["without"]),
                      100*(lo(w["with"])/lo(w["without"]) - 1)), ""]
    with open(os.path.join(HERE, "sites.md"), "w") as f:
        f.write("\n".join(lines))


def plot(data):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = data["cases"]
    fig, ax = plt.subplots(2, len(cases), figsize=(5.5*len(cases), 7))
    for c, e in enumerate(cases):
        for m, r in e["methods"].items():
            d = [x for x, s in zip(e["distances"], r["sites"]) if s["arrival_time_s"] is not None]
            arrival = [s["arrival_time_s"] for s in r["sites"] if s["arrival_time_s"] is not None]
            speed = [s["peak_speed_m_s"] for s in r["sites"] if s["arrival_time_s"] is not None]
            ax[0][c].plot(d, arrival, "o-", label="%s (runout %.0f m)" % (m, r["runout"]))
            ax[1][c].plot(d, speed, "o-", label=m)
        ax[0][c].set(title=e["case"], ylabel="arrival [s]")
        ax[1][c].set(xlabel="site ahead of the initial front [m]", ylabel="peak speed over the site [m/s]")
        for a in ax[:, c]:
            a.grid(alpha=0.3)
            a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "sites.png"), dpi=100)


def main():
    opts = options.parse(__doc__, flags=("--stored",))
    path = os.path.join(HERE, "sites.json")
    if opts.get("--stored"):
        data = json.load(open(path))
    else:
        data = {"cases": measure(), "overhead": measure_overhead()}
        with open(path, "w") as f:
            json.dump(data, f, indent=1)
    write_md(data)
    plot(data)
    print(open(os.path.join(HERE, "sites.md")).read())


if __name__ == "__main__":
    main()
