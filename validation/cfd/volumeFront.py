#!/usr/bin/env python3
"""The front of a slideFoam run read from the slide's volume instead of the alpha = 0.5 contour on the base: the
position along the base beyond which a given share of the slide's volume lies. A thin base cell is filled past
alpha 0.5 by a little spray that lands on it, and the contour then reads that patch as the front (or the rear); the
volume's quantile does not see a patch that holds less than the share.

Usage: validation/cfd/volumeFront.py CASE_DIR [--time T] [--shares 0.001,0.01]
(a kept case of validation/cfd/table1.py, its fields reconstructed at T, default the latest; needs the OpenFOAM
environment of etc/bashrc for postProcess, which writes the cell centres and volumes into that time)"""
import argparse
import os
import re
import subprocess

import numpy as np


def internal_field(path):
    """The internalField of an ascii OpenFOAM volume field: an (n,) or (n, 3) array."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", text)
    if not m:
        raise SystemExit("%s: no nonuniform ascii internalField" % path)
    body = text[m.end():text.index(")\n;", m.end())]
    if m.group(1) == "vector":
        return np.array([[float(v) for v in t.split()] for t in re.findall(r"\(([^()]+)\)", body)])
    return np.array(body.split(), dtype=float)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--time", default=None)
    ap.add_argument("--shares", default="0.001,0.01")
    args = ap.parse_args()
    times = [t for t in os.listdir(args.case) if re.match(r"^[0-9.eE+-]+$", t) and t != "0"
             and os.path.exists(os.path.join(args.case, t, "alpha.slide"))]
    if not times:
        raise SystemExit("%s: no reconstructed time with alpha.slide" % args.case)
    t = args.time or max(times, key=float)
    if not os.path.exists(os.path.join(args.case, t, "alpha.slide")):
        raise SystemExit("%s: no %s/alpha.slide" % (args.case, t))
    print("%s at %s s, the front's travel from the initial front:" % (args.case, t))
    for share in (float(s) for s in args.shares.split(",")):
        print("  with %g of the slide beyond it: %.2f m" % (share, quantile_front(args.case, t, share)
                                                           - quantile_front(args.case, "0", share)))


def quantile_front(case, t, share):
    """The largest cell centre along the base with at least `share` of the slide's volume at or beyond it."""
    d = os.path.join(case, t)
    if not (os.path.exists(os.path.join(d, "C")) and os.path.exists(os.path.join(d, "V"))):
        for func in ("writeCellCentres", "writeCellVolumes"):
            subprocess.run(["postProcess", "-case", case, "-time", t, "-func", func], check=True,
                           stdout=subprocess.DEVNULL)
    alpha = internal_field(os.path.join(d, "alpha.slide"))
    x = internal_field(os.path.join(d, "C"))[:, 0]
    slide = alpha.clip(0.0, 1.0)*internal_field(os.path.join(d, "V"))
    order = np.argsort(x)
    beyond = slide[order][::-1].cumsum()[::-1]/slide.sum()
    return x[order][beyond >= share].max()


if __name__ == "__main__":
    main()
