#!/usr/bin/env python3
"""slideMPM's speed against error on a GPU and on this machine's cores, from stored runs.

Reads the flume summaries (summary.json, as deviceBenchmark.sh stores them:
<backend>_flume_<cells>x<ppc>.json) of a CUDA folder and an OpenMP folder, and
plots wall time against the front's difference from the finest set-up, one
series per backend, into device.png beside this script; prints the table.

    validation/mpm/deviceReport.py [--cuda DIR] [--openmp DIR] [--label-cuda TEXT] [--label-openmp TEXT]

The defaults are session 59's: one H200 (deviceRuns/session59/call4/a_*) and
2 OpenMP threads here on the same day (deviceRuns/session59/local).
"""
import argparse
import glob
import json
import os
import re

here = os.path.dirname(os.path.abspath(__file__))
GATE = 1.8   # the front starts at the gate, 1.8 m from the end wall: final_length_m is measured from the wall


def flume_runs(folder, backend):
    """{(cells, ppc): summary} of the flume runs of `backend` in `folder`."""
    runs = {}
    for path in glob.glob(os.path.join(folder, "*%s_flume_*.json" % backend)):
        m = re.search(r"_flume_(\d+)x(\d+)\.json$", path)
        if not m:
            continue
        with open(path) as f:
            s = json.load(f)
        if abs(s["end_time_s"] - 4.1) > 1e-9:
            raise SystemExit("%s: ends at %g s, not the flume's 4.1 s" % (path, s["end_time_s"]))
        runs[(int(m.group(1)), int(m.group(2)))] = s
    if not runs:
        raise SystemExit("no %s flume runs (<backend>_flume_<cells>x<ppc>.json) in %s" % (backend, folder))
    return runs


def main():
    session = os.path.join(here, "deviceRuns", "session59")
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cuda", default=os.path.join(session, "call4"))
    ap.add_argument("--openmp", default=os.path.join(session, "local"))
    ap.add_argument("--label-cuda", default="CUDA, one H200")
    ap.add_argument("--label-openmp", default="OpenMP, 2 threads, the development machine")
    args = ap.parse_args()

    series = [(args.label_cuda, flume_runs(args.cuda, "cuda")), (args.label_openmp, flume_runs(args.openmp, "openmp"))]
    finest = max(set(series[0][1]) & set(series[1][1]), key=lambda k: (k[0], k[1]))
    rows = []
    for label, runs in series:
        ref = runs[finest]["final_length_m"]
        for (cells, ppc), s in sorted(runs.items()):
            rows.append((label, cells, ppc, s["problem_size"], s["steps"], s["wall_time_s"],
                         s["particle_updates_per_second"], s["final_length_m"],
                         100.0*(s["final_length_m"]/ref - 1.0)))
    lines = ["| backend | cell | particles per cell | particles | steps | wall time [s] | particle-updates/s | "
             "front [m] | difference against H0/%d %dx%d |" % (finest[0], finest[1], finest[1]),
             "|---|---|---|---|---|---|---|---|---|"]
    for label, cells, ppc, n, steps, wall, rate, front, diff in rows:
        lines.append("| %s | H0/%d | %dx%d | %d | %d | %.1f | %.3g | %.6f | %+.2f %% |"
                     % (label, cells, ppc, ppc, n, steps, wall, rate, front, diff))
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for (label, runs), marker in zip(series, ("o", "s")):
        pts = [(r[5], max(abs(r[8]), 1e-2), r[1], r[2]) for r in rows if r[0] == label and (r[1], r[2]) != finest]
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker + "-", label=label)
        for wall, err, cells, ppc in pts:
            ax.annotate("H0/%d %dx%d" % (cells, ppc, ppc), (wall, err), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
        ax.axvline(runs[finest]["wall_time_s"], ls=":", color=ax.lines[-1].get_color(), lw=1)
    ax.set_xlabel("wall time [s] (dotted: the H0/%d %dx%d reference run)" % (finest[0], finest[1], finest[1]))
    ax.set_ylabel("front difference against H0/%d %dx%d [%%]" % (finest[0], finest[1], finest[1]))
    ax.set_title("slideMPM, Krone-Wright flume to 4.1 s (the paper: 3.5 h on a Titan Xp)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    out = os.path.join(here, "device.png")
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
