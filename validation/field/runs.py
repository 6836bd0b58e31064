#!/usr/bin/python3
"""Runs the field tutorials (tutorials/finneidfjord, tutorials/mediterraneanEscarpment)
with their Allrun (slideDAM, slideMPM, slideFoam on the polyline base, then
compareMethods) and stores what compareMethods wrote in runs.json here, for
validation/report.py. ~20 min on 2 cores (slideFoam on Finneidfjord 9 min).

Usage: validation/field/runs.py [--stored]   (--stored: collect without running)
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
CASES = {"Finneidfjord": "finneidfjord", "Mediterranean escarpment": "mediterraneanEscarpment"}


def main():
    runs = {}
    for name, case in CASES.items():
        d = os.path.join(TOP, "tutorials", case)
        if "--stored" not in sys.argv[1:]:
            subprocess.run(["./Allclean"], cwd=d, check=True)
            print("running", d, flush=True)
            subprocess.run(["./Allrun"], cwd=d, check=True)
        rec = json.load(open(os.path.join(d, "postProcessing", "comparison", "comparison.json")))
        runs[name] = dict(rec["methods"], paper=rec["paper"])
    with open(os.path.join(HERE, "runs.json"), "w") as f:
        json.dump(runs, f, indent=1)
    for name, r in runs.items():
        print(name, {m: v.get("runout", v.get("failed")) for m, v in r.items() if m != "paper"})


if __name__ == "__main__":
    main()
