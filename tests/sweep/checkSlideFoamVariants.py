"""slideSweep and slideBackAnalysis with -method slideFoam, on the rigid block on a frictional slope
(blockOnFrictionalSlope/, made strong enough to stand, s_uo 20 kPa, and not so stiff that its capped viscosity
blows the CFD up, as 1e7 Pa does), whose front travels x(T) = 0.5 a T^2 by the end time T with
a = g sin(theta) - s_b/(rho' H). The end at T = 4 s and the step at maxDeltaT 0.002 s: at the tutorials' 0.05 s the
base's lagged traction holds a slow block back (-10 % at 10 s with s_b 275 Pa; validation/cfd/README.md, "The base's
traction and the time step"), and at 0.002 s slideFoam_base asserts the block within 3 % of the law.

    python3 checkSlideFoamVariants.py WORKDIR

- slideSweep over s_b on a mesh too short (cfdDict reach 1 m): each run regenerates the mesh longer once the slide
  leaves it, and every runout lies within 5 % of the law (the CFD's sliding block's accuracy that slideFoam_base
  asserts on a frictionless base); the same command again reuses both runs.
- slideBackAnalysis for the s_b of a runout, each run's mesh sized by slideDAM's runout as in the tutorials' Allrun:
  the s_b found lies within what the 5 % on the runout and the search's tolerance leave of the law's s_b.
"""
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
CASE = os.path.join(HERE, "blockOnFrictionalSlope")
G, RHO, H, T, ANGLE = 9.81, 500.0, 2.0, 4.0, 3.0
ACCURACY = 0.05   # of the runout: the CFD block's, as slideFoam_base asserts it
COMMON = ["-method", "slideFoam", "-set", "rheology/s_uo", "20000", "-set", "system/controlDict:endTime", "%g" % T,
          "-set", "system/controlDict:maxDeltaT", "0.002"]
failures = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


def law_runout(s_b):
    return 0.5*(G*math.sin(math.radians(ANGLE)) - s_b/(RHO*H))*T**2


def law_s_b(x):
    return RHO*H*(G*math.sin(math.radians(ANGLE)) - 2.0*x/T**2)


def tool(name, *args):
    p = subprocess.run([sys.executable, os.path.join(TOP, "bin", name)] + list(args), stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT)
    return p.returncode, p.stdout.decode()


def check_sweep(work):
    out = os.path.join(work, "sweep")
    args = ["-case", CASE, "-dir", out, "-vary", "base/s_b", "200", "275", "-set", "system/cfdDict:reach", "1",
            "-np", "2"] + COMMON
    rc, log = tool("slideSweep", *args)
    print(log)
    check(rc == 0, "slideSweep -method slideFoam: exit %d" % rc)
    if rc != 0:
        return
    report = json.load(open(os.path.join(out, "sweep.json")))
    for run in report["runs"]:
        s_b = float(run["values"]["base/s_b"])
        exact = law_runout(s_b)
        check(abs(run["runout_m"]/exact - 1) < ACCURACY,
              "sweep run s_b %g Pa: runout %.3f m, the law's %.3f m (within %g %%)"
              % (s_b, run["runout_m"], exact, 100*ACCURACY))
        cfd = open(os.path.join(out, run["dir"], "system", "cfdDict")).read()
        reach = [float(line.split()[1].rstrip(";")) for line in cfd.splitlines() if line.startswith("reach")]
        check(reach and reach[-1] > exact,
              "sweep run s_b %g Pa: the 1 m mesh the slide left regenerated with reach %s m"
              % (s_b, reach[-1] if reach else "?"))
    said = {line.split(":")[0] for line in log.splitlines() if "the slide left the mesh" in line}
    check(said == {os.path.join(out, run["dir"]) for run in report["runs"]},
          "the tool says which run's mesh it regenerated: %s" % ", ".join(sorted(said)))
    rc, log = tool("slideSweep", *args)
    check(rc == 0 and "Reused 2 finished runs" in log, "the same sweep again reuses both runs (exit %d)" % rc)


def check_back_analysis(work):
    out = os.path.join(work, "backAnalysis")
    target = 2.2
    rc, log = tool("slideBackAnalysis", "-case", CASE, "-dir", out, "-find", "base/s_b", "150", "350", "-match",
                   "runout", "%g" % target, "-tolerance", "0.01", "-scatterRuns", "0", "-sensitivityStep", "0",
                   "-threads", "2", *COMMON)
    print(log)
    check(rc == 0, "slideBackAnalysis -method slideFoam: exit %d" % rc)
    if rc != 0:
        return
    result = json.load(open(os.path.join(out, "backAnalysis.json")))["result"]
    found, exact = result["best"]["value"], law_s_b(target)
    # The runout within ACCURACY of the law and the match within the tolerance of the target: through the law,
    # ds_b/dx = -2 rho' H / T^2.
    allowed = 2*RHO*H/T**2*target*(ACCURACY + 0.01)
    check(abs(found - exact) <= allowed, "s_b for a runout of %g m: %.2f Pa, the law's %.2f Pa (within %.1f Pa)"
          % (target, found, exact, allowed))
    first = os.path.join(out, "runs", "0001")
    check(os.path.isfile(os.path.join(first, "postProcessing", "slideDAM", "summary.json"))
          and "slideDAM's runout" in open(os.path.join(first, "log.slideFoamCase")).read(),
          "each run's mesh sized by slideDAM's runout, run first in its folder")


def main():
    work = os.path.abspath(sys.argv[1])
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)
    check_sweep(work)
    check_back_analysis(work)
    print("\n%d failures" % len(failures))
    for f in failures:
        print("  " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
