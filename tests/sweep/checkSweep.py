"""slideSweep against the rigid block on a frictional slope (blockOnFrictionalSlope/), whose front travels
x(T) = 0.5 a T^2 by the end time T with a = g sin(theta) - s_b/(rho' H) where a > 0, and stays put otherwise.

    python3 checkSweep.py WORKDIR

- A Latin hypercube of s_b ~ uniform(200, 700) Pa, 20 scenes: every run's runout is the law's; the share of runs
  that reach each site is the law's probability within 1/20 (each of the 20 strata of s_b holds one run, so the
  sample's distribution of s_b is within 1/20 of the true one everywhere); the median runout is the law's within
  the runout across one stratum; the runout falls with s_b (rank correlation below -0.9).
- The same command again reuses every run; -report rewrites the same report from them.
- The distributions' quantiles against their closed forms.
- A grid of s_b x angle, each run's end time set to 5 s by -set: four runs, each the law's.
- Bad options and a key the scene lacks: exit 1, the file and key named, nothing written; a value the scene
  refuses: that run failed with the scene's reason in sweep.md, the others reported, exit 1.
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
SWEEP = os.path.join(TOP, "bin", "slideSweep")
G, RHO, H, T = 9.81, 500.0, 2.0, 10.0
failures = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


def law(s_b, angle=3.0, end=T):
    a = G*math.sin(math.radians(angle)) - s_b/(RHO*H)
    return max(0.0, 0.5*a*end*end)


def sweep(*args):
    p = subprocess.run([sys.executable, SWEEP, "-case", CASE] + list(args), stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE)
    return p.returncode, p.stdout.decode(), p.stderr.decode()


def check_distributions():
    """slideSweep's quantiles against closed forms: the lognormal's median m/sqrt(1 + COV^2) and its mean, the
    normal's mean + SD at Phi(1), the triangular's at its mode and halfway into each side's area."""
    import importlib.machinery
    import importlib.util
    loader = importlib.machinery.SourceFileLoader("slideSweep", SWEEP)
    spec = importlib.util.spec_from_loader("slideSweep", loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    q = mod.quantile
    m, v = 15000.0, 0.3
    check(abs(q("lognormal", [m, v], 0.5) - m/math.sqrt(1 + v*v)) < 1e-6*m, "lognormal median m/sqrt(1 + COV^2)")
    k = 20000
    mean = sum(q("lognormal", [m, v], (i + 0.5)/k) for i in range(k))/k
    check(abs(mean - m) < 2e-3*m, "lognormal mean %.1f from its quantiles, %g given" % (mean, m))
    check(abs(q("normal", [10.0, 2.0], 0.8413447460685429) - 12.0) < 1e-9, "normal: mean + SD at Phi(1)")
    check(abs(q("triangular", [0.0, 1.0, 3.0], 1.0/3.0) - 1.0) < 1e-12, "triangular: the mode at F = (c-a)/(b-a)")
    check(abs(q("triangular", [0.0, 1.0, 3.0], 1.0/6.0) - math.sqrt(0.5)) < 1e-12
          and abs(q("triangular", [0.0, 1.0, 3.0], 2.0/3.0) - (3.0 - math.sqrt(2.0))) < 1e-12,
          "triangular: sqrt(F (b-a)(c-a)) below the mode, b - sqrt((1-F)(b-a)(b-c)) above")
    check(q("uniform", [2.0, 4.0], 0.25) == 2.5, "uniform: LO + F (HI - LO)")


def main():
    check_distributions()
    work = os.path.abspath(sys.argv[1])
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)

    # The Latin hypercube.
    out = os.path.join(work, "samples")
    n, lo, hi = 20, 200.0, 700.0
    rc, stdout, stderr = sweep("-dir", out, "-sample", "base/s_b", "uniform", "%g" % lo, "%g" % hi, "-samples", str(n))
    check(rc == 0, "the sampled sweep ran (exit %d) %s" % (rc, stderr.strip()[-500:]))
    with open(os.path.join(out, "sweep.json")) as f:
        result = json.load(f)
    runs, stats = result["runs"], result["statistics"]
    s_b = [float(r["values"]["base/s_b"]) for r in runs]
    check(len(runs) == n and all(lo <= v <= hi for v in s_b), "%d runs with s_b in [%g, %g]" % (n, lo, hi))
    check(sorted(int((v - lo)/(hi - lo)*n) for v in s_b) == list(range(n)), "one s_b in each of the %d strata" % n)
    worst = max(abs(r["runout_m"] - law(v)) for r, v in zip(runs, s_b))
    check(worst < 1e-3, "every runout the law's within 1 mm (worst %.2e m)" % worst)
    scene = open(os.path.join(out, "runs", "0001", "constant", "sceneProperties")).read()
    check("500.0000001;" in scene and ("%s;" % runs[0]["values"]["base/s_b"]) in scene,
          "the run's scene holds its s_b as recorded (%s) and the density's ten digits as written"
          % runs[0]["values"]["base/s_b"])
    fs = [v/(RHO*G*H*math.sin(math.radians(3.0))) for v in s_b]
    check(all(abs(r["rigid_slab_factor_of_safety"]/f - 1) < 2e-9 for r, f in zip(runs, fs))
          and all((r["runout_m"] > 0) == (f < 1) for r, f in zip(runs, fs)),
          "every run's rigid-slab factor of safety s_b/(rho' g H sin(theta)), and the blocks above 1 stood")
    for site in stats["sites"]:
        d = site["distance_from_initial_front_m"]
        # Reached within T where a >= 2 d/T^2, i.e. s_b <= rho H (g sin(theta) - 2 d/T^2).
        s_star = RHO*H*(G*math.sin(math.radians(3.0)) - 2.0*d/T**2)
        p = min(1.0, max(0.0, (s_star - lo)/(hi - lo)))
        check(abs(site["probability_reached"] - p) <= 1.0/n + 1e-12,
              "site %g m ahead reached in %.2f of the runs, the law's probability %.3f within 1/%d"
              % (d, site["probability_reached"], p, n))
        reached = [r for r, v in zip(runs, s_b) if law(v) >= d]
        check(site["reached"] == len(reached), "site %g m ahead: %d runs reached it, as the law says of their s_b"
              % (d, site["reached"]))
    median = law(0.5*(lo + hi))
    stratum = law(0.5*(lo + hi) - (hi - lo)/n) - median
    check(abs(stats["runout_m"]["P50"] - median) <= stratum,
          "median runout %.2f m, the law's %.2f m within one stratum's %.2f m" % (stats["runout_m"]["P50"], median,
                                                                                stratum))
    corr = stats["rank_correlation_with_runout"]["base/s_b"]
    check(corr < -0.9, "the runout falls with s_b (rank correlation %.2f)" % corr)
    check(all(os.path.isfile(os.path.join(out, f)) for f in ("sweep.md", "sweep.csv", "sweep.png")),
          "sweep.md, sweep.csv and sweep.png written")
    md = open(os.path.join(out, "sweep.md")).read()
    check("- %d of %d runs, e.g. run 1: s_uo 1e+07 Pa, S_t 1 lies where slideDAM's runout differed" % (n, n) in md,
          "the applicability warning every run gave is reported once, for all %d runs" % n)
    with open(os.path.join(out, "sweep.csv")) as f:
        check(len(f.read().splitlines()) == n + 1, "sweep.csv: a header and a row per run")

    # The same again: every run reused, the same report; -report from the runs gives it too.
    md = open(os.path.join(out, "sweep.md")).read()
    rc, stdout, _ = sweep("-dir", out, "-sample", "base/s_b", "uniform", "%g" % lo, "%g" % hi, "-samples", str(n))
    check(rc == 0 and "Reused %d finished runs" % n in stdout and "Run 0001" not in stdout,
          "the same sweep again reuses all %d runs" % n)
    check(open(os.path.join(out, "sweep.md")).read() == md, "and writes the same report")
    os.remove(os.path.join(out, "sweep.md"))
    p = subprocess.run([sys.executable, SWEEP, "-dir", out, "-report"], stdout=subprocess.PIPE)
    check(p.returncode == 0 and open(os.path.join(out, "sweep.md")).read() == md, "-report rewrites the same report")

    # Sites moved by the sweep: their place "varies", their statistics over the runs.
    out = os.path.join(work, "movedSite")
    rc, stdout, stderr = sweep("-dir", out, "-vary", "sites/tenMetres/position", "50", "60")
    with open(os.path.join(out, "sweep.json")) as f:
        moved = json.load(f)["statistics"]["sites"]
    check(rc == 0 and moved[2]["position_m"] is None and moved[0]["position_m"] == 42
          and "| tenMetres | varies | varies | 1 of 2 |" in open(os.path.join(out, "sweep.md")).read(),
          "a swept site position is reported as varying (reached at 10 m, not at 20 m: the law's %.2f m at s_b 300 Pa),"
          " the others at their place" % law(300.0))

    # A grid, run to 5 s (-set, in every run).
    out = os.path.join(work, "grid")
    rc, stdout, stderr = sweep("-dir", out, "-vary", "base/s_b", "100", "300", "-vary", "base/angle", "3", "5",
                               "-set", "system/controlDict:endTime", "5")
    check(rc == 0, "the grid ran (exit %d) %s" % (rc, stderr.strip()[-500:]))
    with open(os.path.join(out, "sweep.json")) as f:
        runs = json.load(f)["runs"]
    combos = sorted((r["values"]["base/s_b"], r["values"]["base/angle"]) for r in runs)
    check(combos == [("100", "3"), ("100", "5"), ("300", "3"), ("300", "5")], "the grid's four combinations")
    worst = max(abs(r["runout_m"] - law(float(r["values"]["base/s_b"]), float(r["values"]["base/angle"]), 5.0))
                for r in runs)
    check(worst < 1e-3 and all(r["end_time_s"] == 5.0 for r in runs),
          "every grid run ended at the -set 5 s, its runout the law's within 1 mm (worst %.2e m)" % worst)

    # Refusals: nothing written.
    for args, words in [
        (["-vary", "rheology/nope", "1", "2"], ["constant/sceneProperties", "rheology/nope"]),
        (["-vary", "slide", "1"], ["constant/sceneProperties", "'slide' is a dictionary"]),
        (["-vary", "base/s_b", "1", "-set", "system/nope:columns", "10"], ["system/nope", "no such file"]),
        (["-vary", "base/s_b", "1", "-set", "base/s_b", "10"], ["a key is given twice"]),
        (["-vary", "base/s_b", "1", "-set", "base/angle"], ["-set takes a key and one value"]),
        (["-vary", "base/s_b", "1", "-set", "system/damDict:columns/x", "3"],
         ["system/damDict", "could not set 'columns/x'"]),
        (["-sample", "base/s_b", "uniform", "700", "200", "-samples", "5"], ["-sample base/s_b uniform", "LO"]),
        (["-sample", "base/s_b", "gamma", "1", "2", "-samples", "5"], ["-sample takes", "uniform"]),
        (["-sample", "base/s_b", "uniform", "1", "2"], ["-samples N"]),
        (["-vary", "base/s_b", "1", "-sample", "base/angle", "uniform", "1", "2", "-samples", "3"], ["not both"]),
        (["-vary", "base/s_b", "1", "-method", "slideFEM"], ["-method slideFEM", "slideFoam"]),
        (["-vary", "base/s_b", "1", "-np", "0"], ["-np 0"]),
        (["-vary", "base/s_b", "1", "-bogus"], ["unknown option '-bogus'"]),
    ]:
        bad = os.path.join(work, "refused")
        rc, _, stderr = sweep("-dir", bad, *args)
        check(rc == 1 and all(w in stderr for w in words) and not os.path.exists(bad),
              "%s refused naming %s, nothing written (exit %d: %s)" % (" ".join(args), " and ".join(words), rc,
                                                                       stderr.strip()))
    foreign = os.path.join(work, "foreign")
    os.makedirs(foreign)
    open(os.path.join(foreign, "notes.txt"), "w").write("mine\n")
    rc, _, stderr = sweep("-dir", foreign, "-vary", "base/s_b", "100")
    check(rc == 1 and "did not write" in stderr and os.listdir(foreign) == ["notes.txt"],
          "a -dir holding other files is refused and left as it was")

    # A value the scene refuses: that run failed with the reason, the other reported.
    out = os.path.join(work, "oneBad")
    rc, stdout, stderr = sweep("-dir", out, "-vary", "base/s_b", "-5", "300")
    md = open(os.path.join(out, "sweep.md")).read() if os.path.isfile(os.path.join(out, "sweep.md")) else ""
    check(rc == 1 and "| 1 | -5 | failed: log.slideDAM:" in md and "s_b" in md.split("| 1 | -5 |")[1].split("\n")[0]
          and "| 2 | 300 | %.1f |" % law(300.0) in md,
          "s_b -5: that run failed naming s_b, the other reported, exit %d" % rc)

    # A method dictionary's missing key is added, and the method refuses a misspelt one by name.
    out = os.path.join(work, "misspelt")
    rc, stdout, stderr = sweep("-dir", out, "-vary", "base/s_b", "300", "-set", "system/damDict:colums", "10")
    md = open(os.path.join(out, "sweep.md")).read() if os.path.isfile(os.path.join(out, "sweep.md")) else ""
    check(rc == 1 and "key 'colums': unknown key" in md, "a misspelt damDict key added by -set: the run refused "
          "naming it, exit %d" % rc)

    if failures:
        print("\n%d checks FAILED" % len(failures))
        return 1
    print("\nall checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
