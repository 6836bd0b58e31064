#!/usr/bin/env python3
"""Why a method's block on a constant s_b slows faster than the rigid block: the rigid block's law run on the
footprint the method measured (its front and rear along the base, runout.dat) against the same law on the block's
starting length, both from the method's speed at a start time. A block that stretches is braked by s_b over its
longer contact, so where the law on the measured footprint follows the method's speed, the extra brake is the
stretch and not an error in the base's law; what remains between them is the base's own error.

Made for backAnalysis.py's constant-s_b check of slideFoam on the Finneidfjord block (its run directory is the
default), but any run of a block on a frictional base with runout.dat and constant/sceneProperties will do.

Usage: validation/backAnalysis/contactBrake.py [--run DIR] [--method slideFoam] [--from 100] [--to T]
(seconds; --to leaves out the rows after T, where a stopped block rests on a static s_b that the law, which
only brakes, does not hold; writes contactBrake.md beside this script when run on the default directory)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "validation", "lib"))
import options  # noqa: E402
import rigid_block  # noqa: E402
import scene_variants  # noqa: E402
from slidefoam_io import read_runout  # noqa: E402

DEFAULT_RUN = os.path.join(TOP, "platforms", "validation-work", "backAnalysis", "Finneidfjordblock_constants_b",
                           "slideFoamcheck")


def scene_value(scene, key):
    rc, out = scene_variants.foam_dictionary("-entry", key, "-value", scene)
    if rc != 0:
        raise SystemExit("%s: no key '%s' (foamDictionary: %s)" % (scene, key, out.strip()[-300:]))
    return out.strip()


def main():
    args = options.parse(__doc__, valued=("--run", "--method", "--from", "--to"))
    run = os.path.abspath(args.get("--run") or DEFAULT_RUN)
    method = args.get("--method") or "slideFoam"
    start = float(args.get("--from") or 100)
    scene = os.path.join(run, "constant", "sceneProperties")
    path = os.path.join(run, "postProcessing", method, "runout.dat")
    for p in (scene, path):
        if not os.path.isfile(p):
            raise SystemExit("%s: not found (run the method there first)" % p)
    if scene_value(scene, "base/interface") != "frictional":
        raise SystemExit("%s: key 'base/interface' is not frictional: the law here takes a constant s_b" % scene)
    s_b = float(scene_value(scene, "base/s_b"))
    density = float(scene_value(scene, "slide/density"))
    g = float(scene_value(scene, "g"))
    coords = [float(v) for v in scene_value(scene, "base/points").replace("(", " ").replace(")", " ").split()]
    points = list(zip(coords[0::2], coords[1::2]))
    # runout.dat's front and rear are measured from the initial front, the law's from the base's start.
    origin = float(scene_value(scene, "slide/rearPosition")) + float(scene_value(scene, "slide/length"))
    r = read_runout(path)
    keep = r["time"] >= start - 1e-9
    if args.get("--to"):
        keep &= r["time"] <= float(args["--to"]) + 1e-9
    if r["time"][0] > 0 or abs(r["front"][0]) > 1.0:
        raise SystemExit("%s: does not start at the release (time %g s, front %g m)" % (path, r["time"][0], r["front"][0]))
    if keep.sum() < 2:
        raise SystemExit("%s: fewer than two rows from %g s on" % (path, start))
    t, front, rear, speed = (r[k][keep] for k in ("time", "front", "rear", "frontVelocity"))
    area = r["mass"][keep][0]/density
    length = front - rear
    measured = rigid_block.speed_on_contact(points, area, density, s_b, t, origin + front, origin + rear, speed[0], g)
    fixed = rigid_block.speed_on_contact(points, area, density, s_b, t, origin + front, origin + front - length[0],
                                         speed[0], g)
    lines = ["# A block on a constant s_b: the rigid block's law on %s's measured footprint" % method, "",
             "Written by `validation/backAnalysis/contactBrake.py` from `%s` (s_b %.6g Pa, rho' %g kg/m3, "
             "slide area %.2f m2). Both laws start from %s's front speed at %g s; \"law, L(t)\" brakes with s_b "
             "over the block's length as %s measured it (front - rear of the alpha 0.5 contour along the base), "
             "\"law, L(%g s)\" over the length it had then. The last column is the brake that %s's speed implies "
             "beyond the law on its own footprint, from the start: rho' A (V_law,L(t) - V)/(L t)."
             % (os.path.relpath(path, TOP), s_b, density, area, method, start, method, start, method), "",
             "| t [s] | front [m] | length [m] | %s speed [m/s] | law, L(t) [m/s] | law, L(%g s) [m/s] | "
             "brake beyond the law on L(t) [Pa] |" % (method, start), "|---|---|---|---|---|---|---|"]
    for i in range(len(t)):
        residual = (density*area*(measured[i] - speed[i])/(length[i]*(t[i] - t[0]))) if t[i] > t[0] else 0.0
        lines.append("| %g | %.1f | %.2f | %.3f | %.3f | %.3f | %+.2f |"
                     % (t[i], front[i], length[i], speed[i], measured[i], fixed[i], residual))
    text = "\n".join(lines) + "\n"
    print(text)
    if run == os.path.abspath(DEFAULT_RUN) and method == "slideFoam":
        with open(os.path.join(HERE, "contactBrake.md"), "w") as f:
            f.write(text)
        print("wrote %s" % os.path.join(HERE, "contactBrake.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
