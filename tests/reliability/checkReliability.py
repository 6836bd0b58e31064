#!/usr/bin/env python3
"""Blow-ups and static stability, per method, on the Krone-Wright flume scene.

  blowup <app> <work>   A time step far above the stable one (damDict/mpmDict
                        deltaT; controlDict adjustTimeStep no for slideFoam) must
                        make the run stop with a non-zero exit and a message
                        naming the time, the place and the quantity; what was
                        written before stays (runout.dat rows before that time,
                        all finite; the last good state or time directory), and
                        no summary.json claims a runout.
  static <app> <work>   The slurry made strong (s_uo 2 kPa: 4 s_uo/(rho g) =
                        0.76 m > H0 = 0.3 m, basal driving stress 189 Pa) and
                        released without its end wall stays put for 2 s: front
                        and rear move less than 1 mm, speeds stay below 1 mm/s
                        (slideMPM: its elastic clay rings, so the front stays
                        within twice the face's elastic bulge and does not drift).

Usage: checkReliability.py blowup|static slideDAM|slideMPM|slideFoam <work dir> [bin dir]
  bin dir: where the application is (default: found on etc/bashrc's PATH)"""
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import make_case, prepare, run, time_dirs, read_field  # noqa: E402
from runner import which  # noqa: E402
from slidefoam_io import read_runout  # noqa: E402

flume = os.path.join(top, "tutorials", "kroneWrightRun15")
# Coarse numerics per method: the checks are about control flow, not accuracy.
METHOD_DICT = {"slideDAM": ("damDict", "setting fast;\ncolumns 100;\nwriteFields no;\n"),
               "slideMPM": ("mpmDict", "setting fast;\ncellsPerHeight 10;\nparticlesPerCell 2;\nwriteFields no;\n"),
               "slideFoam": ("cfdDict", "cellsPerHeight 8;\nreach 1;\n")}
results = []


def check(name, ok, detail=""):
    results.append(ok)
    print("%-4s %s%s" % ("ok" if ok else "FAIL", name, ("  (" + detail + ")") if detail else ""))


def case_for(app, work, name, scene=None, control=None, extra=""):
    d = make_case(flume, work, name, scene=scene, control=control)
    file, text = METHOD_DICT[app]
    open(os.path.join(d, "system", file), "w").write(text + extra)
    return d


bindir = None


def run_method(app, d):
    if app == "slideFoam":
        prepare(d)
    exe = os.path.join(bindir, app) if bindir else which(app)
    return run(d, exe, "-case", ".", check=False)


def blowup(app, work):
    if app == "slideFoam":
        # Coarse cells of 3.75 cm: a fixed step of 0.05 s is a Courant number of ~1.5 at 1 m/s.
        d = case_for(app, work, "blowup", control={"endTime": 1, "adjustTimeStep": "no", "deltaT": 0.05,
                                                   "writeInterval": 0.05})
        open(os.path.join(d, "system", "cfdDict"), "w").write("cellsPerHeight 8;\nreach 20;\n")
    else:
        d = case_for(app, work, "blowup", control={"endTime": 1}, extra="deltaT 0.05;\n")
    rc = run_method(app, d)
    log = open(os.path.join(d, "log." + app)).read()
    check("%s exits non-zero on a time step far above the stable one" % app, rc != 0, "exit %d" % rc)
    m = re.search(r"(?:numerical )?blow-up at time ([0-9.eE+-]+) s", log)
    check("%s names the time of the blow-up" % app, m is not None, m.group(0) if m else log[-400:])
    t_bad = float(m.group(1)) if m else math.inf
    place = re.search(r"(node \d+ of \d+ at s = \S+ m|particle \d+ at s = \S+ m along the base|in cell \d+ at \()",
                      log)
    check("%s names the place" % app, place is not None, place.group(0) if place else "")
    if app == "slideFoam":
        check("slideFoam names the remedy for a step too long", "Reduce maxCo / maxDeltaT" in log, log[-300:])
    quantity = re.search(r"(node order|velocity|kinetic energy|NaN|\|U\| = \S+ m/s)", log)
    check("%s names the quantity" % app, quantity is not None, quantity.group(0) if quantity else "")
    out = os.path.join(d, "postProcessing", app)
    check("%s leaves no summary.json" % app, not os.path.exists(os.path.join(out, "summary.json")))
    r = read_runout(os.path.join(out, "runout.dat"))
    times = list(r["time"])
    finite = all(math.isfinite(v) for k in ("front", "rear", "maxVelocity") for v in r[k])
    check("%s keeps runout.dat up to the blow-up (rows before %g s, all finite)" % (app, t_bad),
          len(times) >= 1 and max(times) < t_bad and finite, "%d rows, last at %g s" % (len(times), max(times)))
    if app == "slideFoam":
        last = [t for t in time_dirs(d) if 0 < float(t) < t_bad and os.path.exists(os.path.join(d, t, "U"))]
        ok = bool(last) and all(math.isfinite(float(v)) for v in read_field(d, last[-1], "U").ravel())
        check("slideFoam keeps its last written time (finite U)", ok, last[-1] if last else "none")
    else:
        states = [t for t in time_dirs(d) if os.path.exists(os.path.join(d, t, app + ".state"))]
        ok = bool(states) and float(states[-1]) < t_bad
        check("%s keeps its last good restart state" % app, ok, states[-1] + "/" + app + ".state" if states else "none")


def static(app, work):
    # No end wall: the face of the slurry is free and must stand by its strength.
    d = case_for(app, work, "static", scene={"s_uo": 2000, "rearWall": "no"},
                 control={"endTime": 2, "writeInterval": 0.25, "stopAtRest": "no"})
    rc = run_method(app, d)
    check("%s runs the strong slurry to 2 s" % app, rc == 0, "exit %d" % rc)
    if rc != 0:
        return
    r = read_runout(os.path.join(d, "postProcessing", app, "runout.dat"))
    t = r["time"]
    front = max(abs(v) for v in r["front"])
    rear = max(abs(v - r["rear"][0]) for v in r["rear"])
    speed = max(r["maxVelocity"])
    if app != "slideMPM":
        check("%s: the front stays put (< 1 mm)" % app, front < 1e-3, "max |front travel| %.3g m" % front)
        check("%s: the rear stays put (< 1 mm)" % app, rear < 1e-3, "max |rear travel| %.3g m" % rear)
        check("%s: no creep (max speed < 1 mm/s)" % app, speed < 1e-3, "max speed %.3g m/s" % speed)
        return
    # The MPM clay is elastic below its strength (E = 100 s_uo): the free face
    # relaxes its geostatic lateral stress K0 rho g H0 and the slide rings in
    # undamped elastic waves. Bound: twice the face's elastic bulge
    # K0 rho g H0^2 / E; and no drift: the front's mean over the second second
    # within 1 mm of its mean over the first.
    s_uo, rho, g, H0, nu = 2000.0, 1073.0, 9.81, 0.3, 0.49
    bound = 2*nu/(1 - nu)*rho*g*H0**2/(100*s_uo)
    check("slideMPM: the front moves less than twice the elastic bulge of the face", front < bound,
          "max |front travel| %.3g m, bound %.3g m" % (front, bound))
    check("slideMPM: the rear moves less than twice the elastic bulge", rear < bound,
          "max |rear travel| %.3g m" % rear)
    first = [f for tt, f in zip(t, r["front"]) if 0 < tt <= 1]
    second = [f for tt, f in zip(t, r["front"]) if tt > 1]
    drift = abs(sum(second)/len(second) - sum(first)/len(first))
    check("slideMPM: no drift of the front (mean over 1-2 s within 1 mm of 0-1 s)", drift < 1e-3, "%.3g m" % drift)
    thick = max(abs(v - H0) for v in r["maxThickness"])
    check("slideMPM: the slide keeps its height (within 1 %)", thick < 0.01*H0, "max |dH| %.3g m" % thick)


def main():
    global bindir
    if len(sys.argv) not in (4, 5) or sys.argv[1] not in ("blowup", "static") or sys.argv[2] not in METHOD_DICT:
        sys.exit(__doc__)
    bindir = sys.argv[4] if len(sys.argv) == 5 else None
    work = os.path.abspath(sys.argv[3])
    os.makedirs(work, exist_ok=True)
    {"blowup": blowup, "static": static}[sys.argv[1]](sys.argv[2], work)
    print("%d passed, %d failed" % (sum(results), len(results) - sum(results)))
    sys.exit(0 if all(results) else 1)


if __name__ == "__main__":
    main()
