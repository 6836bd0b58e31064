#!/usr/bin/env python3
"""The CI subset of the DAM validation: coarse, short slideDAM runs (fast setting,
200 columns) on Table 1 cases, checked against the paper where slideDAM meets it
and against the mechanism the paper reports. Exits non-zero on any miss.
Usage: ciCheck.py <slideDAM executable> <work dir>"""
import os
import re
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from slidefoam_io import front_at, read_runout, read_summary  # noqa: E402
from cfdcase import get_entry  # noqa: E402
import layerProfile  # noqa: E402

app, work = sys.argv[1], sys.argv[2]


def run(case, end_time=None, extra=""):
    d = os.path.join(work, case.replace("/", "_") + ("_" + extra.split()[1].rstrip(";") if extra else ""))
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(os.path.join(top, "tutorials", case), d, ignore=shutil.ignore_patterns("postProcessing", "log.*"))
    with open(os.path.join(d, "system", "damDict"), "w") as f:
        f.write("setting fast;\nwriteFields no;\n" + extra)
    if end_time is not None:
        ctl = os.path.join(d, "system", "controlDict")
        text = re.sub(r"endTime\s+[^;]+;", "endTime %g;" % end_time, open(ctl).read())
        text = re.sub(r"stopAtRest\s+[^;]+;", "stopAtRest no;", text)
        open(ctl, "w").write(text)
    subprocess.run([app, "-case", d], check=True, stdout=subprocess.DEVNULL)
    out = os.path.join(d, "postProcessing", "slideDAM")
    return read_summary(os.path.join(out, "summary.json")), read_runout(os.path.join(out, "runout.dat"))


checks = []


def check(name, value, target, rel):
    ok = abs(value - target) <= rel * abs(target)
    checks.append(ok)
    print("%-58s %10.3f  target %8.3f +- %4.1f %%  %s" % (name, value, target, 100 * rel, "ok" if ok else "MISS"))


s, r = run("table1/case02")
check("Case 2 runout at rest [m] (paper DAM 62 m)", s["runout_m"], 62.0, 0.05)
s, r = run("table1/case10")
# Case 10's front stalls at about 123.5-124.5 m from 50 s to 450 s (200 columns), while the body behind it, thicker than the
# remoulded yield thickness, creeps on under Eq. (1) and then carries the front to 132.8 m by ~1200 s, when every
# node is below restVelocity (README, "Creep after the front stalls"). Which of the two the paper's "end of
# motion" is, it does not say; the stall is checked against its DAM, the rest is checked to come.
ok = s["at_rest"]
checks.append(ok)
print("%-58s %10s  %s" % ("Case 10 comes to rest (at %.0f m, %.0f s)" % (s["runout_m"], s["end_time_s"]), ok,
                          "ok" if ok else "MISS"))
# At rest its thickest column is about the depth at which a steady layer of the remoulded clay creeps at
# restVelocity (Eq. (1)'s plug speed, layerProfile.rest_depth; 1.097 m): the rest the creep above comes to is
# Eq. (1)'s, not the numerics'. slideDAM stops 2.3 % thinner (200 columns), its surface's slope driving it too.
scene = os.path.join(top, "tutorials", "table1", "case10", "constant", "sceneProperties")
if (get_entry(scene, "angle"), get_entry(scene, "density")) != (layerProfile.THETA, layerProfile.RHO):
    raise SystemExit("ciCheck.py: Case 10's slope or density is not layerProfile's")
remoulded = {k: get_entry(scene, k) for k in ("s_uo", "eta", "n", "gdotRef")}
remoulded["s_uo"] *= get_entry(scene, "deltaRem")
restDepth = layerProfile.rest_depth(
    get_entry(os.path.join(top, "tutorials", "table1", "case10", "system", "controlDict"), "restVelocity"), remoulded)
check("Case 10 thickest column at rest [m] (steady layer at rest)", r["maxThickness"][-1], restDepth, 0.05)
history = list(zip(r["time"], r["front"]))
stalled = [front_at(history, 100.0), front_at(history, 400.0)]
ok = stalled[1] - stalled[0] < 0.01*stalled[1]
checks.append(ok)
print("%-58s %10.2f  < 1 %% of the front  %s" % ("Case 10 front's travel from 100 to 400 s [m] (stalled)",
                                                stalled[1] - stalled[0], "ok" if ok else "MISS"))
check("Case 10 front while stalled, at 400 s [m] (paper DAM 125 m)", stalled[1], 125.0, 0.05)
# Case 12 has no rate term, so its wholly remoulded clay (s_uo delta_rem = 250 Pa) holds at most
# h_c = s_uo delta_rem/(rho' g sin(theta)) = 0.71 m on its slope: its front runs out as a thinner sheet and stops
# where the sheet's momentum is spent (at rest by 66 s, 429.7 m with 200 columns). Having travelled hundreds of
# metres its columns are remoulded through (xi >> xi95), so none can stand thicker than h_c. slideDAM stops
# 0.660 m thick (-7 %); without remoulding (delta_rem 1) 1.27 m, which this would catch.
s, r = run("table1/case12")
scene = os.path.join(top, "tutorials", "table1", "case12", "constant", "sceneProperties")
if (get_entry(scene, "angle"), get_entry(scene, "density")) != (layerProfile.THETA, layerProfile.RHO):
    raise SystemExit("ciCheck.py: Case 12's slope or density is not layerProfile's")
yieldDepth = layerProfile.yield_depth(get_entry(scene, "s_uo")*get_entry(scene, "deltaRem"))
ok = s["at_rest"] and r["maxThickness"][-1] <= 1.02*yieldDepth
checks.append(ok)
print("%-58s %10.3f  <= %.3f m (+2 %%), at rest: %s  %s" % ("Case 12 thickest column at rest [m] (remoulded h_c)",
      r["maxThickness"][-1], yieldDepth, s["at_rest"], "ok" if ok else "MISS"))
s, r = run("table1/case09")
# The paper's "up to 12 m/s at 20 s" and "~3 m" are read off its Fig. 8(b)/9: +-15 %.
check("Case 9 front velocity at 20 s [m/s] (paper ~12 m/s)", r["frontVelocity"][-1], 12.0, 0.15)
check("Case 9 thickness at 20 s [m] (paper ~3 m, H_stability 3.4 m)", r["maxThickness"][-1], 3.0, 0.15)
accelerating = r["frontVelocity"][-1] > r["frontVelocity"][-6] + 1.0
checks.append(accelerating)
print("%-58s %10s  %s" % ("Case 9 still accelerating (gain over the last 5 s > 1 m/s)", accelerating,
                          "ok" if accelerating else "MISS"))
ok = s["mechanism"] == "block sliding"
checks.append(ok)
print("%-58s %10s  target %s  %s" % ("Case 9 mechanism", s["mechanism"], "block sliding", "ok" if ok else "MISS"))
enhanced = s["runout_m"]
s, r = run("table1/case09", extra="frictionalBase original;\nfaceStability none;\n")
ok = s["runout_m"] > 1.2 * enhanced and r["maxThickness"][-1] < 0.5 * 3.4
checks.append(ok)
print("%-58s %10.1f  > 1.2 x %.1f m, thinner than H_stab/2  %s" % ("Case 9 original algorithm over-predicts [m]",
      s["runout_m"], enhanced, "ok" if ok else "MISS"))
for case in ("table1/case04", "table1/case05"):
    s, r = run(case)
    ok = s["at_rest"]
    checks.append(ok)
    print("%-58s %10s  %s" % (case + " runs stably to rest", s["at_rest"], "ok" if ok else "MISS"))
# A rigid block that climbs a rise whose pull its base cannot hold stops where its downslope motion first does: the
# equation of motion's runout (rigid_block.CLIMB; measured +0.07 % with 100 columns).
import rigid_block  # noqa: E402
d = rigid_block.write_climb_case(os.path.join(work, "climb"))
subprocess.run([app, "-case", d], check=True, stdout=subprocess.DEVNULL)
s = read_summary(os.path.join(d, "postProcessing", "slideDAM", "summary.json"))
check("Rigid block climbing a rise, first stop [m]", s["runout_m"], rigid_block.climb_runout(), 0.01)
print("%d passed, %d failed" % (sum(checks), len(checks) - sum(checks)))
sys.exit(0 if all(checks) else 1)
