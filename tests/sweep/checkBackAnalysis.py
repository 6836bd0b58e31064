"""slideBackAnalysis against the rigid block on a frictional slope (blockOnFrictionalSlope/), whose front travels
x(T) = 0.5 a T^2 by the end time T, with a = g sin(theta) - s_b/(rho' H), and reaches a site d ahead at
t = sqrt(2 d/a): so the s_b that gives a runout x is rho' H (g sin(theta) - 2 x/T^2), and the s_b that brings the
front to the site at t is rho' H (g sin(theta) - 2 d/t^2).

    python3 checkBackAnalysis.py WORKDIR

- The search itself (its Search class, fed made-up observables): a straight line is matched within the tolerance
  in a few runs; a step across the target is reported as a jump, its bracket narrowed to 1e-4 of the range; a
  target outside the ends is "not bracketed" after two runs; a run that fails ends the search naming it; a
  non-monotone observable is flagged, a wiggle below the tolerance is not; the run limit is kept.
- slideDAM on the block: the s_b for a runout of 12 m, for its front of 99 % of the mass 0.4 m behind that, and
  for the site 10 m ahead reached at 8 s, each against the law; the same command again reuses every run; a target beyond both ends: exit 1, "not bracketed" in the report.
- Bad options, keys and observables: exit 1, the file and key or option named, nothing written.
"""
import importlib.machinery
import importlib.util
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
CASE = os.path.join(HERE, "blockOnFrictionalSlope")
TOOL = os.path.join(TOP, "bin", "slideBackAnalysis")
G, RHO, H, T, ANGLE = 9.81, 500.0, 2.0, 10.0, 3.0
failures = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


def s_b_for_runout(x):
    return RHO*H*(G*math.sin(math.radians(ANGLE)) - 2.0*x/T**2)


def arrival(s_b, d):
    return math.sqrt(2.0*d/(G*math.sin(math.radians(ANGLE)) - s_b/(RHO*H)))


def tool(*args):
    p = subprocess.run([sys.executable, TOOL] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def load_module():
    loader = importlib.machinery.SourceFileLoader("slideBackAnalysis", TOOL)
    spec = importlib.util.spec_from_loader("slideBackAnalysis", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def check_search(mod):
    def made_up(observable):
        def evaluate(text, index):
            v = observable(float(text))
            return {"run": index, "at_rest": True, "observed": v, "failed": None if v is not None else "no number"}
        return evaluate

    s = mod.Search(made_up(lambda x: 3.0*x + 1.0), "k", "runout", 10.0, 1e-3, 30)
    outcome, _ = s.solve(0.0, 10.0)
    best = s.runs[-1]
    check(outcome == "matched" and abs(best["observed"] - 10.0) <= 0.01 and len(s.runs) <= 4,
          "a line: matched at k = %.6g (exact 3) in %d runs" % (best["value"], len(s.runs)))

    s = mod.Search(made_up(lambda x: 0.0 if x > 3.3 else 200.0), "k", "runout", 100.0, 1e-3, 40)
    outcome, message = s.solve(0.0, 10.0)
    a, b = s.bracket()
    check(outcome == "jump" and a["value"] <= 3.3 < b["value"] and b["value"] - a["value"] <= 1e-4*10.0
          and "jumps from 200" in message,
          "a step across the target: a jump at %.6g..%.6g, found in %d runs" % (a["value"], b["value"], len(s.runs)))

    s = mod.Search(made_up(lambda x: x), "k", "runout", 50.0, 1e-3, 30)
    outcome, message = s.solve(0.0, 10.0)
    check(outcome == "not bracketed" and len(s.runs) == 2 and "both below the target 50" in message,
          "a target beyond both ends: not bracketed after the two ends (%s)" % message)

    s = mod.Search(made_up(lambda x: None if x > 4 else x), "k", "runout", 5.0, 1e-3, 30)
    outcome, message = s.solve(0.0, 10.0)
    check(outcome == "run failed" and "run 2" in message, "a failing run ends the search naming it (%s)" % message)

    s = mod.Search(made_up(lambda x: x + 3.0*math.sin(x)), "k", "runout", 5.0, 1e-9, 5)
    outcome, _ = s.solve(0.0, 10.0)
    check(outcome == "out of runs" and len(s.runs) == 5, "the run limit kept (5 runs, %s)" % outcome)

    # Scatter at the answer: a line measures none; a line with a scatter of +-1.5 on a tolerance of 0.5 (a front's
    # particles, a creep's stop) is found to scatter by more than the tolerance, and the entry's range widens.
    def with_scatter(amplitude):
        s = mod.Search(made_up(lambda x: 100.0 - 5.0*x + amplitude*math.sin(1e5*x)), "k", "runout", 50.0, 1e-2, 30)
        outcome, _ = s.solve(0.0, 20.0)
        sides = s.sensitivity(0.05)
        rows = s.scatter_runs(4, 0.002)
        return s, mod.analyse(s, outcome, sides, rows), rows
    s, result, rows = with_scatter(0.0)
    check(result["outcome"] == "matched" and len(rows) == 4 and result["scatter"]["value"] < 1e-9
          and "resolution_with_scatter" not in result and abs(result["resolution"] - 0.5/5.0) < 1e-9,
          "a line: no scatter at the answer (%.2g), the entry open by the tolerance over the slope, 0.1"
          % result["scatter"]["value"])
    s, result, rows = with_scatter(1.5)
    check(0.5 < result["scatter"]["value"] <= 3.0 + 1e-9 and abs(result["resolution_with_scatter"]
                                                                  - (0.5 + result["scatter"]["value"])/5.0) < 0.05,
          "a line with a scatter of +-1.5: %.3g measured (more than the tolerance 0.5, at most twice the amplitude), "
          "the entry open by %.3g" % (result["scatter"]["value"], result["resolution_with_scatter"]))

    # A scatter of +-2 on the tolerance of 0.5: the search ends on a "jump" that the runs beside it show is the
    # scatter; a true step's runs stay by the ends on their sides.
    s = mod.Search(made_up(lambda x: 100.0 - 5.0*x + 2.0*math.sin(1e5*x)), "k", "runout", 50.0, 1e-2, 30)
    outcome, _ = s.solve(0.0, 20.0)
    a, b = s.bracket()
    result = mod.analyse(s, outcome, [None, None], s.scatter_runs(4, 0.002, around=0.5*(a["value"] + b["value"])))
    check(outcome == "jump" and result.get("jump_is_scatter") is True,
          "a scatter of +-2 ends the search on a jump, read as scatter (%.3g beside it)" % result["scatter"]["value"])
    s = mod.Search(made_up(lambda x: 10.0 - 0.1*x if x < 3.3 else 200.0 - 0.1*x), "k", "runout", 100.0, 1e-3, 40)
    outcome, _ = s.solve(0.0, 10.0)
    a, b = s.bracket()
    result = mod.analyse(s, outcome, [None, None], s.scatter_runs(4, 0.002, around=0.5*(a["value"] + b["value"])))
    check(outcome == "jump" and result.get("jump_is_scatter") is False and result["scatter"]["value"] < 0.01,
          "a true step: its runs beside the jump stay by their sides' ends (%.3g), not read as scatter"
          % result["scatter"]["value"])

    rows = [{"run": i + 1, "value": float(i), "observed": v} for i, v in enumerate([0.0, 1.0, 0.5, 2.0, 1.999])]
    breaks = mod.monotone_breaks(rows, 0.01)
    check([(p[0]["run"], p[1]["run"]) for p in breaks] == [(2, 3)],
          "a turn of 0.5 against the trend flagged, one of 0.001 (below the tolerance) not")


def main():
    check_search(load_module())
    work = os.path.abspath(sys.argv[1])
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)

    # The runout: s_b from the law within the tolerance's share of its slope, dx/ds_b = -T^2/(2 rho' H).
    out = os.path.join(work, "runout")
    target, tol = 12.0, 1e-3
    args = ["-case", CASE, "-dir", out, "-find", "base/s_b", "100", "900", "-match", "runout", "%g" % target,
            "-tolerance", "%g" % tol]
    rc, stdout, stderr = tool(*args)
    with open(os.path.join(out, "backAnalysis.json")) as f:
        result = json.load(f)["result"]
    exact = s_b_for_runout(target)
    band = tol*target/(T**2/(2*RHO*H))
    found = result["best"]["value"]
    check(rc == 0 and result["outcome"] == "matched" and abs(found - exact) <= band,
          "runout %g m: s_b %.4f Pa, the law's %.4f Pa within %.2f Pa (exit %d, %d runs) %s"
          % (target, found, exact, band, rc, result["runs"], stderr.strip()[-300:]))
    check(abs(result["elasticity"] - (-T**2/(2*RHO*H))*found/target) < 1e-6,
          "its sensitivity d ln x / d ln s_b %.4f, the law's (a straight line)" % result["elasticity"])
    check(all(os.path.isfile(os.path.join(out, f)) for f in ("backAnalysis.md", "backAnalysis.png")),
          "backAnalysis.md and backAnalysis.png written")
    md = open(os.path.join(out, "backAnalysis.md")).read()
    check("foremost material lies 0.4 beyond the front of 99 % of the mass, 1 % of the deposit's length" in md
          and "-match massFront matches" not in md,
          "the rigid block's last 1 % of the mass: 1 % of its 40 m, its runout not flagged as set by a tip")
    rc, stdout, _ = tool(*args)
    check(rc == 0 and stdout.count("reused") == result["runs"] and open(os.path.join(out, "backAnalysis.md")).read()
          == md, "the same command again reuses all %d runs and writes the same report" % result["runs"])
    # Interrupted before its report: its runs are its own, not foreign files.
    for name in ("backAnalysis.json", "backAnalysis.md", "backAnalysis.png"):
        os.remove(os.path.join(out, name))
    rc, stdout, _ = tool(*args)
    check(rc == 0 and stdout.count("reused") == result["runs"],
          "a search interrupted before its report: its %d runs reused, not refused as foreign" % result["runs"])

    # The front of 99 % of the mass: the rigid block's lies 1 % of its 40 m behind its front, so 11.6 m asks the
    # s_b of a 12 m runout.
    out = os.path.join(work, "massFront")
    rc, stdout, stderr = tool("-case", CASE, "-dir", out, "-find", "base/s_b", "100", "900", "-match", "massFront",
                              "%g" % (target - 0.01*40.0), "-tolerance", "%g" % tol)
    with open(os.path.join(out, "backAnalysis.json")) as f:
        result = json.load(f)["result"]
    found = result["best"]["value"]
    check(rc == 0 and abs(found - exact) <= band,
          "front of 99 %% of the mass %g m: s_b %.4f Pa, the law's for a %g m runout %.4f Pa within %.2f Pa (exit %d)"
          % (target - 0.4, found, target, exact, band, rc))

    # A site's arrival: the front 10 m ahead at 8 s.
    out = os.path.join(work, "arrival")
    t, d = 8.0, 10.0
    rc, stdout, stderr = tool("-case", CASE, "-dir", out, "-find", "base/s_b", "100", "300", "-match",
                              "sites/tenMetres/arrival_time_s", "%g" % t, "-tolerance", "1e-3")
    with open(os.path.join(out, "backAnalysis.json")) as f:
        result = json.load(f)["result"]
    found = result["best"]["value"]
    exact = RHO*H*(G*math.sin(math.radians(ANGLE)) - 2.0*d/t**2)
    # slideDAM records the arrival at the step that passes the site: within a few hundredths of a second here.
    check(rc == 0 and abs(arrival(found, d) - t) <= 0.03 + 1e-3*t,
          "arrival %g s at the site %g m ahead: s_b %.3f Pa (the law's %.3f), whose law's arrival is %.4f s"
          % (t, d, found, exact, arrival(found, d)))

    # Not bracketed: the runout at s_b 100 Pa is 20.7 m.
    out = os.path.join(work, "notBracketed")
    rc, stdout, stderr = tool("-case", CASE, "-dir", out, "-find", "base/s_b", "100", "900", "-match", "runout", "30")
    check(rc == 1 and "not bracketed" in open(os.path.join(out, "backAnalysis.md")).read(),
          "a runout beyond both ends: exit %d, not bracketed in the report" % rc)

    # Refusals: nothing written.
    out = os.path.join(work, "refused")
    for extra, words in [
            (["-find", "base/s_bb", "1", "2", "-match", "runout", "5"], ["sceneProperties", "base/s_bb"]),
            (["-find", "base/s_b", "2", "1", "-match", "runout", "5"], ["LO must be below HI"]),
            (["-find", "base/s_b", "1", "2", "-match", "speed", "5"], ["-match speed", "sites/NAME/FIELD"]),
            (["-find", "base/s_b", "1", "2", "-match", "sites/nowhere/arrival_time_s", "5"], ["no site 'nowhere'"]),
            (["-find", "base/s_b", "1", "2", "-match", "runout", "x"], ["'x' is not a number"]),
            (["-find", "base/s_b", "1", "2"], ["-match is required"]),
            (["-find", "base/s_b", "1", "2", "-match", "runout", "5", "-tolerance", "2"], ["-tolerance 2"]),
            (["-find", "base/s_b", "1", "2", "-match", "runout", "5", "-method", "slideFEM"],
             ["-method slideFEM", "slideFoam"]),
            (["-find", "base/s_b", "1", "2", "-match", "runout", "5", "-set", "base/s_b", "3"], ["given twice"])]:
        rc, stdout, stderr = tool("-case", CASE, "-dir", out, *extra)
        check(rc == 1 and all(w in stderr for w in words) and not os.path.exists(out),
              "%s refused naming %s, nothing written (exit %d: %s)" % (" ".join(extra), " and ".join(words), rc,
                                                                      stderr.strip()[:200]))
    foreign = os.path.join(work, "foreign")
    os.makedirs(foreign)
    open(os.path.join(foreign, "notes.txt"), "w").write("mine\n")
    rc, _, stderr = tool("-case", CASE, "-dir", foreign, "-find", "base/s_b", "100", "900", "-match", "runout", "12")
    check(rc == 1 and "did not write" in stderr and os.listdir(foreign) == ["notes.txt"],
          "a -dir holding other files refused, left as it was")

    print("%d passed, %d failed" % (0 if failures else 1, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
