#!/usr/bin/env python3
"""slideDAM speed against error: the Krone-Wright flume and Table 1 Case 2 at
the paper's reference discretisation (4000 columns, dt = 0.001 sqrt(b/g)) and
at cheaper settings (fewer columns, adaptive Courant time step). Prints a table
and writes benchmark.md and benchmark.png beside this script.

Usage: validation/dam/benchmark.py [--quick]   (after ./Allwmake; --quick skips the reference runs)"""
import os
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from slidefoam_io import read_summary  # noqa: E402
from runner import slidefoam_env, which  # noqa: E402
import options  # noqa: E402

SETTINGS = [("reference", None), ("3200 cols", 3200), ("800 cols", 800), ("200 cols", 200), ("50 cols", 50)]
CASES = [("Krone-Wright flume (front at 4.1 s)", "tutorials/kroneWrightRun15"),
         ("Table 1 Case 2 (front at 20 s)", "tutorials/table1/case02")]


def run(case, columns, work):
    d = os.path.join(work, os.path.basename(case) + "_" + str(columns))
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(os.path.join(top, case), d, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    with open(os.path.join(d, "system", "damDict"), "w") as f:
        if columns is None:
            f.write("setting reference;\nwriteFields no;\n")
        else:
            f.write("setting fast;\ncolumns %d;\nwriteFields no;\n" % columns)
    # Compare at a fixed time, before the slow creep phase.
    ctl = os.path.join(d, "system", "controlDict")
    text = open(ctl).read()
    if "case02" in case:
        import re
        text = re.sub(r"endTime\s+[^;]+;", "endTime 20;", text)
        text = re.sub(r"stopAtRest\s+[^;]+;", "stopAtRest no;", text)
        open(ctl, "w").write(text)
    subprocess.run([which("slideDAM"), "-case", d], check=True, stdout=subprocess.DEVNULL, env=slidefoam_env())
    s = read_summary(os.path.join(d, "postProcessing", "slideDAM", "summary.json"))
    return s["runout_m"], s["wall_time_s"], s["problem_size"]


def main():
    quick = "--quick" in options.parse(__doc__, flags=("--quick",))
    work = tempfile.mkdtemp(prefix="slideDAM_bench_")
    rows = []
    for title, case in CASES:
        results = []
        for name, cols in SETTINGS:
            if quick and cols is None:
                continue
            runout, wall, n = run(case, cols, work)
            results.append((name, n, runout, wall))
            print("%-40s %-10s %6d columns  front %9.4f m  wall %8.3f s" % (title, name, n, runout, wall), flush=True)
        ref = results[0][2]
        for name, n, runout, wall in results:
            rows.append((title, name, n, runout, 100.0 * abs(runout - ref) / abs(ref), wall))
    with open(os.path.join(here, "benchmark.md"), "w") as f:
        f.write("| case | setting | columns | front [m] | error vs %s [%%] | wall time [s] |\n" % SETTINGS[0][0])
        f.write("|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s | %s | %d | %.4f | %.3f | %.3f |\n" % r)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for title, _ in CASES:
        pts = [(r[5], max(r[4], 1e-4)) for r in rows if r[0] == title and r[4] > 0]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=title)
    ax.set_xlabel("wall time on one core [s]")
    ax.set_ylabel("front error against the finest run [%]")
    ax.set_title("slideDAM: speed against error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "benchmark.png"), dpi=120)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
