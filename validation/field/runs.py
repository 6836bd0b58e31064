#!/usr/bin/python3
"""Runs the field tutorials (tutorials/finneidfjord, tutorials/mediterraneanEscarpment)
with their Allrun (slideDAM, slideMPM, slideFoam on the polyline base, then
compareMethods) and stores what compareMethods wrote in runs.json here, for
validation/report.py. ~55 min on 2 cores (slideFoam on Finneidfjord, 2 ranks to rest at 241 s, 47 min).

Usage: validation/field/runs.py [--stored] [--only finneidfjord|mediterraneanEscarpment]
  --stored: collect the tutorials' last results without running
  --only:   run that tutorial alone; the other's entry in runs.json is kept
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "validation", "lib"))
import options  # noqa: E402
CASES = {"Finneidfjord": "finneidfjord", "Mediterranean escarpment": "mediterraneanEscarpment"}


def main():
    opts = options.parse(__doc__, flags=("--stored",), valued=("--only",))
    only = opts.get("--only")
    if only is not None and only not in CASES.values():
        raise SystemExit("--only: one of %s" % ", ".join(CASES.values()))
    path = os.path.join(HERE, "runs.json")
    runs = json.load(open(path)) if only and os.path.isfile(path) else {}
    for name, case in CASES.items():
        if only is not None and case != only:
            continue
        d = os.path.join(TOP, "tutorials", case)
        if "--stored" not in opts:
            subprocess.run(["./Allclean"], cwd=d, check=True)
            print("running", d, flush=True)
            subprocess.run(["./Allrun"], cwd=d, check=True)
        rec = json.load(open(os.path.join(d, "postProcessing", "comparison", "comparison.json")))
        runs[name] = dict(rec["methods"], paper=rec["paper"])
    with open(path, "w") as f:
        json.dump(runs, f, indent=1)
    for name, r in runs.items():
        print(name, {m: v.get("runout", v.get("failed")) for m, v in r.items() if m != "paper"})


if __name__ == "__main__":
    main()
