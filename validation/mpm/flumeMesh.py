#!/usr/bin/env python3
"""The paper's own mesh check of its MPM on the Krone-Wright Run 15 flume: "the
solutions based on mesh sizes of H0/60 and H0/120 were nearly identical". Runs
slideMPM at the paper's 4x4 particles per cell on cells H0/30, H0/60 and H0/120
to 4.1 s and compares the front and the thickness profile at 4.1 s, each against
the finest cell. Writes flumeMesh.md and flumeMesh.png beside this script.

A run writes no particle fields on its way (at H0/120 a frame is about 200 MB);
it is then restarted from its state at 4.0 s with the fields switched on, so the
profile at 4.1 s comes from the same motion (a restart continues bit for bit).
With --work DIR a run whose summary already reaches 4.1 s is read, not rerun.

Usage: validation/mpm/flumeMesh.py [--settings 30x4,60x4,120x4] [--work DIR]
(after ./Allwmake; on 2 cores H0/60 takes about 8 minutes, H0/120 about 65)"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import make_case, set_entry, set_method_entries  # noqa: E402
from slidefoam_io import read_summary, particles_on_planar_base  # noqa: E402
from runner import slidefoam_env, which  # noqa: E402

FLUME = os.path.join(top, "tutorials", "kroneWrightRun15")
GATE = 1.8          # the front starts at the gate, 1.8 m from the end wall
H0 = 0.3            # the slurry's initial height [m]
ANGLE = 3.43        # the flume's slope [deg]
PROFILE_TIME = 4.1  # the paper's profile time [s]


def slide_mpm(case, threads):
    env = dict(slidefoam_env())
    env["OMP_PROC_BIND"] = "false"
    if threads:
        env["OMP_NUM_THREADS"] = str(threads)
    with open(os.path.join(case, "log.slideMPM"), "a") as log:
        p = subprocess.run([which("slideMPM"), "-case", case], stdout=log, stderr=subprocess.STDOUT, env=env)
    if p.returncode != 0:
        raise SystemExit("slideMPM failed in %s: see its log.slideMPM" % case)


def run(work, cells, ppc, threads):
    """The summary of the run to 4.1 s and the particles at 4.1 s, in the base's frame."""
    d = os.path.join(work, "slideMPM_%dx%d" % (cells, ppc))
    out = os.path.join(d, "postProcessing", "slideMPM")
    kept = os.path.join(out, "summary.run.json")
    ctl = os.path.join(d, "system", "controlDict")
    if not os.path.exists(kept):
        done = os.path.join(out, "summary.json")
        if not (os.path.exists(done) and abs(read_summary(done)["end_time_s"] - PROFILE_TIME) < 1e-6):
            make_case(FLUME, work, os.path.basename(d), control={"endTime": PROFILE_TIME},
                      dicts={"system/mpmDict": "setting fast;\ncellsPerHeight %d;\nparticlesPerCell %d;\n"
                             "writeFields no;\nprogressInterval 60;\npurgeState 2;\n" % (cells, ppc)})
            slide_mpm(d, threads)
        shutil.copy(done, kept)
    if not os.path.exists(os.path.join(out, "particles.pvd")):
        # The last 0.1 s again from the state at 4.0 s, now writing the particles.
        set_entry(ctl, "startFrom", "startTime")
        set_entry(ctl, "startTime", "%g" % (PROFILE_TIME - 0.1))
        set_method_entries(d, "mpmDict", {"writeFields": "yes"})
        slide_mpm(d, threads)
    s = read_summary(kept)
    if abs(s["end_time_s"] - PROFILE_TIME) > 1e-6:
        raise SystemExit("%s ends at %g s, not %g s" % (kept, s["end_time_s"], PROFILE_TIME))
    again = read_summary(os.path.join(out, "summary.json"))
    along, height, _, arrays = particles_on_planar_base(d, PROFILE_TIME, ANGLE)
    return {"cells": cells, "ppc": ppc, "summary": s, "front": GATE + s["runout_m"],
            "restartFront": GATE + again["runout_m"], "along": along, "volume": arrays["volume"],
            "speed": np.hypot(arrays["velocity"][:, 0], arrays["velocity"][:, 2])}


def thickness_profile(r, edges):
    """Thickness of each column along the base: the particles' volume (per unit width) in it over its width. Each
    particle's volume is spread evenly over its own length along the base, taken as sqrt(volume), so that columns
    narrower than a coarse set-up's particle spacing are not alternately empty and over-full."""
    a = np.sqrt(r["volume"])
    w = r["volume"]/a
    lo, hi = r["along"] - 0.5*a, r["along"] + 0.5*a

    def ramp_sum(starts, x):
        # sum_i w_i max(x - start_i, 0) at each x, by sorting and prefix sums.
        order = np.argsort(starts)
        s, ws = starts[order], w[order]
        W = np.concatenate(([0.0], np.cumsum(ws)))
        WS = np.concatenate(([0.0], np.cumsum(ws*s)))
        k = np.searchsorted(s, x)
        return x*W[k] - WS[k]

    cumulative = ramp_sum(lo, edges) - ramp_sum(hi, edges)   # volume at or behind each edge
    return np.diff(cumulative)/np.diff(edges)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--settings", default="30x4,60x4,120x4")
    ap.add_argument("--work", help="keep the runs here, and read those already there")
    ap.add_argument("--threads", type=int, default=0, help="OpenMP threads (default: all cores)")
    args = ap.parse_args()
    settings = [tuple(int(v) for v in s.split("x")) for s in args.settings.split(",")]
    work = os.path.abspath(args.work) if args.work else tempfile.mkdtemp(prefix="slideMPM_flumeMesh_")
    os.makedirs(work, exist_ok=True)
    runs = []
    for cells, ppc in settings:
        r = run(work, cells, ppc, args.threads)
        runs.append(r)
        s = r["summary"]
        print("H0/%d %dx%d: %d particles, %d steps, %.1f s, front %.4f m (restart from 4.0 s: %.4f m)"
              % (cells, ppc, ppc, s["problem_size"], s["steps"], s["wall_time_s"], r["front"], r["restartFront"]),
              flush=True)

    # Columns one coarsest cell wide: no set-up resolves the profile more finely than its cell.
    column = H0/min(cells for cells, _ in settings)
    edges = np.arange(0.0, max(r["along"].max() for r in runs) + 2*column, column)
    centres = 0.5*(edges[1:] + edges[:-1])
    for r in runs:
        r["h"] = thickness_profile(r, edges)
    ref = runs[-1]
    mask = ref["h"] > 1e-4
    lines = ["# slideMPM's mesh check on the Krone-Wright Run 15 flume (the paper's: H0/60 against H0/120)", "",
             "Regenerated by `validation/mpm/flumeMesh.py --settings %s`. Front = distance from the end wall at "
             "%.1f s. Thickness = the particles' volume in columns %.1f mm wide (the coarsest cell) along the "
             "base over the column's width (each particle's volume spread over a length sqrt(volume)); profile "
             "difference = mean |h - h_finest| over the finest run's deposit, over H0 = %.1f m (the "
             "measure of `../cfd/flume.md`). Wall time of the run to %.1f s on this machine, without the restart "
             "that writes the particles at %.1f s." % (args.settings, PROFILE_TIME, column*1000, H0, PROFILE_TIME,
                                                      PROFILE_TIME), "",
             "| cell | particles per cell | particles at 4.1 s | steps | wall time [s] | front [m] | "
             "front - finest [mm] | profile difference | max thickness [m] |", "|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        s = r["summary"]
        r["perr"] = float(np.mean(np.abs(r["h"][mask] - ref["h"][mask])))/H0
        lines.append("| H0/%d | %dx%d | %d | %d | %.1f | %.4f | %+.1f | %.4f | %.4f |"
                     % (r["cells"], r["ppc"], r["ppc"], s["problem_size"], s["steps"], s["wall_time_s"], r["front"],
                        1000*(r["front"] - ref["front"]), r["perr"], r["h"].max()))
    if len(runs) >= 3:
        f1, f2, f3 = (r["front"] for r in runs[-3:])
        ratio = runs[-2]["cells"]/runs[-3]["cells"]
        if abs(runs[-1]["cells"]/runs[-2]["cells"] - ratio) > 1e-9:
            lines += ["", "The last three cells are not refined by one ratio: no observed order."]
        elif (f2 - f1) != 0.0 and (f3 - f2)/(f2 - f1) > 0.0:
            p = np.log((f2 - f1)/(f3 - f2))/np.log(ratio)
            lines += ["", "Observed order of the front from the last three cells: %.2f; Richardson's front from "
                      "the two finest: %.4f m." % (p, f3 + (f3 - f2)/(ratio**p - 1.0))]
        else:
            lines += ["", "The front's changes between the last three cells change sign: no observed order."]
    with open(os.path.join(here, "flumeMesh.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 3.5))
    for r in runs:
        ax.plot(centres, r["h"], label="H0/%d, %dx%d (front %.3f m)" % (r["cells"], r["ppc"], r["ppc"], r["front"]))
    ax.set_xlabel("distance from the end wall along the base [m]")
    ax.set_ylabel("thickness at %.1f s [m]" % PROFILE_TIME)
    ax.legend()
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "flumeMesh.png"), dpi=120)
    if not args.work:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
