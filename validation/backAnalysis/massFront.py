#!/usr/bin/python3
"""What sets slideMPM's runout on the Mediterranean escarpment, and what a back-analysis of it can match.

Session 80's back-analysis (backAnalysis.md) found slideMPM's s_uo for the observed 420 m at 10.3 kPa, on runs
whose runout stepped 13 m (3 %) within 1 % of s_uo and alternated between "breakaway" and "viscous elongation".
This study measures, on the tutorial's set-up (slideMPM H0/10 with 4x4 particles, slideDAM 800 columns):

- the runout (foremost material) and the front of 99 % of the mass against s_uo, slideMPM over 8-20 kPa and
  slideDAM over 8-30 kPa (slideSweep -vary rheology/s_uo);
- slideMPM's repeatability at one input (s_uo 10.3 kPa): the scan's run on one thread again on one thread, and
  twice on two threads, whose particle-to-grid sums add in a varying order;
- the back-analysis of 420 m on the front of 99 % of the mass (slideBackAnalysis -match massFront) with both
  methods, beside session 80's on the foremost material (backAnalysis.md);
- slideMPM's back-analysis of 420 m on the runout again, in the bracket the scan puts it in (10.0-10.5 kPa), for
  the scatter runs slideBackAnalysis makes at its answer since session 81.

Writes massFront.json, massFront.md and massFront.png here; the runs stay in
platforms/validation-work/backAnalysis/massFront. About 80 minutes on 2 cores.

Usage: validation/backAnalysis/massFront.py [--stored]
  --stored: redraw massFront.md and massFront.png from massFront.json without running
"""
import json
import os
import shutil
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "validation", "lib"))
import options  # noqa: E402
from cfdcase import copy_scene  # noqa: E402
from plotting import pyplot  # noqa: E402
from runner import run_tool, which  # noqa: E402
from slidefoam_io import read_summary  # noqa: E402
from scene_variants import run_one  # noqa: E402

TUTORIAL = "tutorials/mediterraneanEscarpment"
KEY = "rheology/s_uo"
TARGET = 420.0
TOLERANCE = 0.01
SCAN = {"slideMPM": [8000, 9000, 9500, 10000, 10250, 10300, 10400, 10500, 11000, 12000, 13000, 14000, 15000,
                     17000, 20000],
        "slideDAM": list(range(8000, 30001, 500))}
REPEAT_AT = 10300
WORK = os.path.join(TOP, "platforms", "validation-work", "backAnalysis", "massFront")
NO_FIELDS = ["-set", "system/mpmDict:writeFields", "no"]


def scan(case, method):
    out = os.path.join(WORK, "scan_" + method)
    cmd = [os.path.join(TOP, "bin", "slideSweep"), "-case", case, "-dir", out, "-method", method, "-np", "2",
           "-vary", KEY] + ["%d" % v for v in SCAN[method]] + NO_FIELDS
    j, wall = run_tool(cmd, os.path.join(out, "sweep.json"))
    return {"wall": wall, "runs": [{"value": float(r["values"][KEY]), "runout": r.get("runout_m"),
                                    "massFront": r.get("mass_front_m"), "atRest": r.get("at_rest"),
                                    "mechanism": r.get("mechanism"), "runWall": r.get("wall_time_s"),
                                    "failed": r.get("failed")} for r in j["runs"]]}


def repeat(scan_dir, threads, name):
    """The scan's run at REPEAT_AT again, in a copy, on `threads` threads."""
    source = [os.path.join(scan_dir, "runs", d) for d in sorted(os.listdir(os.path.join(scan_dir, "runs")))
              if json.load(open(os.path.join(scan_dir, "runs", d, "sweepRun.json")))["values"][KEY]
              == "%d" % REPEAT_AT][0]
    run_dir = os.path.join(WORK, "repeat", name)
    if os.path.exists(run_dir):
        shutil.rmtree(run_dir)
    os.makedirs(run_dir)
    for sub in ("constant", "system"):
        shutil.copytree(os.path.join(source, sub), os.path.join(run_dir, sub))
    rc, wall = run_one(run_dir, which("slideMPM"), "slideMPM", threads)
    s = read_summary(os.path.join(run_dir, "postProcessing", "slideMPM", "summary.json"))
    with open(os.path.join(source, "postProcessing", "slideMPM", "runout.dat"), "rb") as a, \
            open(os.path.join(run_dir, "postProcessing", "slideMPM", "runout.dat"), "rb") as b:
        identical = a.read() == b.read()
    return {"name": name, "threads": threads, "runout": s["runout_m"], "massFront": s["front_of_99_percent_mass_m"],
            "mechanism": s["mechanism"], "identicalToScan": identical, "wall": wall}


def back_analyse(case, method, observable="massFront", bracket=(8000, 30000)):
    out = os.path.join(WORK, "%s_%s" % (observable, method))
    cmd = [os.path.join(TOP, "bin", "slideBackAnalysis"), "-case", case, "-dir", out, "-method", method,
           "-find", KEY, "%g" % bracket[0], "%g" % bracket[1], "-match", observable, "%g" % TARGET,
           "-tolerance", "%g" % TOLERANCE] + NO_FIELDS + (["-threads", "1"] if method == "slideMPM" else [])
    j, wall = run_tool(cmd, os.path.join(out, "backAnalysis.json"))
    r = j["result"]
    return {"wall": wall, "outcome": r["outcome"], "value": r["best"]["value"] if r.get("best") else None,
            "observed": r["best"]["observed"] if r.get("best") else None, "message": r["message"],
            "elasticity": r.get("elasticity"), "scatter": r.get("scatter"),
            "resolution": r.get("resolution"), "resolutionWithScatter": r.get("resolution_with_scatter"),
            "runsWithinBand": r.get("runs_within_band"),
            "runs": [{"value": x["value"], "massFront": x.get("mass_front_m"), "runout": x.get("runout_m"),
                      "purpose": x.get("purpose")} for x in j["runs"]]}


# The scan puts slideMPM's runout of 420 m between 10.0 kPa (420.8 m) and 10.5 kPa (412.0 m).
RUNOUT_BRACKET = (10000, 10500)


def measure():
    os.makedirs(WORK, exist_ok=True)
    case = os.path.join(WORK, "case")
    if os.path.exists(case):
        shutil.rmtree(case)
    copy_scene(os.path.join(TOP, TUTORIAL), case)
    data = {"tutorial": TUTORIAL, "key": KEY, "target": TARGET, "tolerance": TOLERANCE, "repeatAt": REPEAT_AT}
    t0 = time.time()
    data["scan"] = {m: scan(case, m) for m in ("slideDAM", "slideMPM")}
    print("scans done (%.0f s)" % (time.time() - t0), flush=True)
    # The search on one thread beside the repeats: one on one thread, then two on two (sharing the cores with it).
    with ThreadPoolExecutor(max_workers=2) as pool:
        searches = pool.submit(lambda: dict(
            {m: back_analyse(case, m) for m in ("slideDAM", "slideMPM")},
            runoutMPM=back_analyse(case, "slideMPM", "runout", RUNOUT_BRACKET)))
        repeats = pool.submit(lambda: [repeat(os.path.join(WORK, "scan_slideMPM"), t, n)
                                       for t, n in ((1, "oneThread"), (2, "twoThreadsA"), (2, "twoThreadsB"))])
        data["backAnalysis"], data["repeats"] = searches.result(), repeats.result()
    data["wall"] = time.time() - t0
    with open(os.path.join(HERE, "massFront.json"), "w") as f:
        json.dump(data, f, indent=1)
    return data


def stored_search():
    """The search on the foremost material (backAnalysis.json, backAnalysis.py): {method: its entry in the
    Mediterranean escarpment's study}."""
    with open(os.path.join(HERE, "backAnalysis.json")) as f:
        studies = json.load(f)
    entry = [s for s in studies if s["study"] == "Mediterranean escarpment"][0]
    return {m: entry[m] for m in ("slideDAM", "slideMPM")}


def report(data):
    ok = {m: sorted((r for r in data["scan"][m]["runs"] if not r["failed"]), key=lambda r: r["value"])
          for m in data["scan"]}
    lines = ["# The escarpment's runout against s_uo: foremost material and the front of 99 % of the mass", "",
             "Regenerated by `validation/backAnalysis/massFront.py` (`--stored` redraws from massFront.json) on the "
             "tutorial `%s` at its set-up (slideDAM 800 columns; slideMPM H0/10 with 4x4 particles, one thread a "
             "run). Runout: the travel of the foremost material (summary.json's `runout_m`); mass front: the travel "
             "of the point with 99 %% of the slide behind it (`front_of_99_percent_mass_m`). Every run at rest." %
             data["tutorial"], ""]
    for m in ("slideMPM", "slideDAM"):
        lines += ["## %s over s_uo (slideSweep, %.0f s)" % (m, data["scan"][m]["wall"]), "",
                  "| s_uo [kPa] | runout [m] | mass front [m] | runout - mass front [m] | mechanism | wall [s] |",
                  "|---|---|---|---|---|---|"]
        for r in ok[m]:
            if m == "slideDAM" and r["value"] % 2000 and r["value"] not in (15000,):
                continue   # the table every 2 kPa; the figure has every run
            lines.append("| %.2f | %.1f | %.1f | %.1f | %s | %.3g |" % (
                r["value"]/1000, r["runout"], r["massFront"], r["runout"] - r["massFront"], r["mechanism"],
                r["runWall"]))
        lines.append("")
    reps = data["repeats"]
    scan_run = [r for r in ok["slideMPM"] if r["value"] == data["repeatAt"]][0]
    lines += ["## slideMPM run again at s_uo %.1f kPa" % (data["repeatAt"]/1000), "",
              "| run | threads | runout [m] | mass front [m] | mechanism | runout.dat identical to the scan's |",
              "|---|---|---|---|---|---|",
              "| the scan's | 1 | %.2f | %.2f | %s | - |" % (scan_run["runout"], scan_run["massFront"],
                                                           scan_run["mechanism"])]
    for r in reps:
        lines.append("| %s | %d | %.2f | %.2f | %s | %s |" % (r["name"], r["threads"], r["runout"], r["massFront"],
                                                             r["mechanism"], "yes" if r["identicalToScan"] else "no"))
    stored = stored_search()
    lines += ["", "## Back-analysis of the observed %g m" % data["target"], "",
              "| method | on the runout (backAnalysis.md) | on the mass front | its runs |",
              "|---|---|---|---|"]
    for m in ("slideDAM", "slideMPM"):
        b = data["backAnalysis"][m]
        lines.append("| %s | %.2f kPa | %s | %d, %.0f s |" % (
            m, stored[m]["result"]["best"]["value"]/1000,
            "%.2f kPa (mass front %.1f m)" % (b["value"]/1000, b["observed"]) if b["outcome"] == "matched"
            else b["message"], len(b["runs"]), b["wall"]))
    again = data["backAnalysis"].get("runoutMPM")
    if again:
        sc = again.get("scatter") or {}
        lines += ["", "slideMPM's search on the runout again, in the scan's bracket %g-%g kPa, with the scatter runs "
                  "0.2 %% either side of its answer (slideBackAnalysis since session 81): %s." % (
                      RUNOUT_BRACKET[0]/1000, RUNOUT_BRACKET[1]/1000, again["message"])]
        if sc:
            lines[-1] += " The runout parts from the slope through the match by up to %.3g m there" % sc["value"]
            if again.get("resolutionWithScatter"):
                lines[-1] += (", more than the tolerance (%.3g m): s_uo is fixed no closer than +-%.2g %% (the "
                              "tolerance alone: +-%.2g %%)" % (
                                  TOLERANCE*TARGET, 100*again["resolutionWithScatter"]/again["value"],
                                  100*again["resolution"]/again["value"]))
            lines[-1] += "."
        lines += ["", "Its runs (s_uo [kPa]: runout, mass front [m]): " + "; ".join(
            "%.4g%s: %.1f, %.1f" % (r["value"]/1000, " (%s)" % r["purpose"] if r.get("purpose") else "",
                                    r["runout"], r["massFront"])
            for r in sorted(again["runs"], key=lambda r: r["value"]) if r["runout"] is not None) + "."]
    lines += ["", "![runout and mass front against s_uo](massFront.png)", ""]
    with open(os.path.join(HERE, "massFront.md"), "w") as f:
        f.write("\n".join(lines))

    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.2))
    colours = {"slideDAM": "C0", "slideMPM": "C3"}
    for k, lo_hi in enumerate(((8, 30), (9.5, 12.5))):
        a = ax[k]
        for m in ("slideDAM", "slideMPM") if k == 0 else ("slideMPM",):
            rows = [r for r in ok[m] if lo_hi[0] <= r["value"]/1000 <= lo_hi[1]]
            a.plot([r["value"]/1000 for r in rows], [r["runout"] for r in rows], "o-", color=colours[m], ms=3,
                   label="%s runout" % m)
            a.plot([r["value"]/1000 for r in rows], [r["massFront"] for r in rows], "s--", color=colours[m], ms=3,
                   mfc="none", label="%s mass front" % m)
        if k == 1:
            a.plot([data["repeatAt"]/1000]*len(reps), [r["runout"] for r in reps], "x", color="k",
                   label="slideMPM again at %.1f kPa" % (data["repeatAt"]/1000))
            a.plot([data["repeatAt"]/1000]*len(reps), [r["massFront"] for r in reps], "+", color="k")
            searched = [r for r in stored["slideMPM"]["runs"] if r["runout"] is not None
                        and lo_hi[0] <= r["value"]/1000 <= lo_hi[1]]
            a.plot([r["value"]/1000 for r in searched], [r["runout"] for r in searched], "^", color="C1", ms=5,
                   mfc="none", label="slideMPM runout, backAnalysis.md's search")
        a.axhspan(data["target"]*(1 - data["tolerance"]), data["target"]*(1 + data["tolerance"]), color="grey",
                  alpha=0.3, label="observed %g m +- %g %%" % (data["target"], 100*data["tolerance"]))
        a.set_xlabel("s_uo [kPa]")
        a.set_ylabel("travel [m]")
        a.set_xlim(*lo_hi)
        a.set_title("the escarpment, %g-%g kPa%s" % (lo_hi + ("" if k == 0 else ", slideMPM",)), fontsize=9)
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=7)
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "massFront.png"), dpi=110)
    print("Written: %s" % os.path.join(HERE, "massFront.md"))


def main():
    args = options.parse(__doc__, flags=("--stored",))
    if args.get("--stored"):
        with open(os.path.join(HERE, "massFront.json")) as f:
            data = json.load(f)
    else:
        data = measure()
    report(data)


if __name__ == "__main__":
    main()
