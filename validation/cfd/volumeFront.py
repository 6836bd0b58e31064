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
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from cfdcase import read_field, time_dirs  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--time", default=None)
    ap.add_argument("--shares", default="0.001,0.01")
    args = ap.parse_args()
    times = [t for t in time_dirs(args.case) if t != "0" and os.path.exists(os.path.join(args.case, t, "alpha.slide"))]
    if not times:
        raise SystemExit("%s: no reconstructed time with alpha.slide" % args.case)
    t = args.time or times[-1]
    if not os.path.exists(os.path.join(args.case, t, "alpha.slide")):
        raise SystemExit("%s: no %s/alpha.slide" % (args.case, t))
    now, start = slide_along_base(args.case, t), slide_along_base(args.case, "0")
    print("%s at %s s, the front's travel from the initial front:" % (args.case, t))
    for share in (float(s) for s in args.shares.split(",")):
        print("  with %g of the slide beyond it: %.2f m" % (share, quantile_front(*now, share)
                                                           - quantile_front(*start, share)))


def slide_along_base(case, t):
    """The cells' centres along the base and the slide's volume in each, at time t (sorted along the base)."""
    if not all(os.path.exists(os.path.join(case, t, f)) for f in ("C", "V")):
        for func in ("writeCellCentres", "writeCellVolumes"):
            subprocess.run(["postProcess", "-case", case, "-time", t, "-func", func], check=True,
                           stdout=subprocess.DEVNULL)
    x = read_field(case, t, "C")[:, 0]
    slide = read_field(case, t, "alpha.slide").clip(0.0, 1.0)*read_field(case, t, "V")
    order = np.argsort(x)
    return x[order], slide[order]


def quantile_front(x, slide, share):
    """The largest cell centre along the base with at least `share` of the slide's volume at or beyond it."""
    beyond = slide[::-1].cumsum()[::-1]/slide.sum()
    return x[beyond >= share].max()


if __name__ == "__main__":
    main()
