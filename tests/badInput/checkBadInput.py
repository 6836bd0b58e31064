#!/usr/bin/env python3
"""Runs methods on the bad-input corpus (tests/badInput/NN-name/, written by
makeCorpus.py) and checks the bad-input contract for each entry and method:
  - a non-zero exit status;
  - an error naming the entry's file, line and key (`file:line: key 'k'`;
    slideFoam checks the scene with the shared reader before OpenFOAM reads
    anything, so it answers in the same words);
  - nothing lost and nothing misleading written: an earlier run's
    postProcessing/<app>/summary.json and runout.dat (planted before the run)
    are left byte for byte, and slideFoamCase leaves no half-built CFD case.

Usage: checkBadInput.py <bin dir> <work dir> <app>[,<app>...] [entry-regex]
  apps: slideDAM slideMPM slideFoamCase slideFoam (slideFoam needs OpenFOAM's
  blockMesh on PATH: the corpus runs on a coarse meshed copy of the flume)."""
import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import copy_scene  # noqa: E402

flume = os.path.join(top, "tutorials", "kroneWrightRun15")
ALL = ["slideDAM", "slideMPM", "slideFoamCase", "slideFoam"]
# What slideFoamCase writes; none of it may be left after a refused scene.
CFD_OUTPUTS = ["system/blockMeshDict", "system/fvSchemes", "system/fvSolution", "constant/transportProperties",
               "constant/g", "0.orig"]


def read_expected(d):
    e = {}
    for s in open(os.path.join(d, "expected")):
        k, _, v = s.strip().partition(" ")
        e[k] = v.strip()
    e["line"] = int(e["line"])
    e["methods"] = ALL if e["methods"] == "all" else e["methods"].split()
    return e


def run(cmd, cwd, log):
    with open(log, "w") as f:
        return subprocess.call(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=dict(os.environ, PWD=cwd))


def prepare_bases(bindir, work, apps):
    """The flume, short; for slideFoam also meshed (coarse) as Allrun would."""
    base = os.path.join(work, "base")
    shutil.rmtree(base, ignore_errors=True)
    copy_scene(flume, base)
    bases = {a: base for a in apps}
    if "slideFoamCase" in apps or "slideFoam" in apps:
        # slideFoamCase sizes the mesh from slideDAM's runout: give it one.
        if run([os.path.join(bindir, "slideDAM"), "-case", "."], base, os.path.join(work, "log.base.slideDAM")):
            sys.exit("FAIL: slideDAM on the good flume case (see %s/log.base.slideDAM)" % work)
    if "slideFoam" in apps:
        cfd = os.path.join(work, "base-cfd")
        shutil.rmtree(cfd, ignore_errors=True)
        shutil.copytree(base, cfd)
        open(os.path.join(cfd, "system", "cfdDict"), "w").write("cellsPerHeight 6;\nreach 0.5;\n")
        for cmd in ([os.path.join(bindir, "slideFoamCase"), "-case", "."], ["blockMesh"], ["cp", "-r", "0.orig", "0"]):
            if run(cmd, cfd, os.path.join(work, "log.base.%s" % os.path.basename(cmd[0]))):
                sys.exit("FAIL: preparing the CFD base case: %s" % " ".join(cmd))
        bases["slideFoam"] = cfd
    return bases


def names_location(text, e):
    f, line, key = re.escape(e["file"]), e["line"], e["key"]
    ours = re.compile(r"%s:%d: %s" % (f, line, "key '%s'" % re.escape(key) if key != "-" else ""))
    return bool(ours.search(text))


def check(bindir, work, bases, entry, app):
    e = read_expected(os.path.join(here, entry))
    case = os.path.join(work, "%s.%s" % (entry, app))
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(bases[app], case)
    out = os.path.join(case, "postProcessing", app)
    shutil.rmtree(out, ignore_errors=True)
    planted = {}
    if app != "slideFoamCase":
        os.makedirs(out)
        planted = {"summary.json": '{\n  "method": "%s",\n  "note": "an earlier good run",\n  "runout_m": 1.5\n}\n' % app,
                   "runout.dat": "# time [s]  front [m]  rear [m]  frontVelocity [m/s]\n0 0 0 0\n1 1.5 0 0\n"}
        for name, before in planted.items():
            open(os.path.join(out, name), "w").write(before)
    # The defective file, and the scene around it where the defect is one only in some scenes (makeCorpus's also).
    for root, _, files in os.walk(os.path.join(here, entry)):
        for name in files:
            rel = os.path.relpath(os.path.join(root, name), os.path.join(here, entry))
            if rel != "expected":
                shutil.copyfile(os.path.join(root, name), os.path.join(case, rel))
    if app == "slideFoamCase":
        for p in CFD_OUTPUTS:
            assert not os.path.exists(os.path.join(case, p)), p
    log = os.path.join(case, "log." + app)
    rc = run([os.path.join(bindir, app), "-case", "."], case, log)
    text = open(log, errors="replace").read()
    problems = []
    if rc == 0:
        problems.append("exit status 0")
    if not names_location(text, e):
        problems.append("the error does not name %s:%d key '%s'" % (e["file"], e["line"], e["key"]))
    for name, before in planted.items():
        p = os.path.join(out, name)
        if not os.path.exists(p):
            problems.append("the earlier run's %s was removed" % name)
        elif open(p).read() != before:
            problems.append("the earlier run's %s was overwritten" % name)
    if os.path.exists(out) and set(os.listdir(out)) - set(planted):
        problems.append("wrote " + ", ".join(sorted(set(os.listdir(out)) - set(planted))))
    if app == "slideFoamCase":
        left = [p for p in CFD_OUTPUTS if os.path.exists(os.path.join(case, p))]
        if left:
            problems.append("left a half-built case: " + ", ".join(left))
    err = [s for s in text.splitlines() if e["file"] in s][-1:] or text.strip().splitlines()[-1:]
    if not problems:
        shutil.rmtree(case)
    return entry, app, problems, (err[0].strip() if err else "")


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    bindir, work, apps = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3].split(",")
    pick = re.compile(sys.argv[4]) if len(sys.argv) > 4 else None
    for a in apps:
        if a not in ALL:
            sys.exit("unknown application %s (one of %s)" % (a, ", ".join(ALL)))
    os.makedirs(work, exist_ok=True)
    entries = sorted(d for d in os.listdir(here) if re.match(r"\d{2,}-", d) and (not pick or pick.search(d)))
    if len(entries) < 1:
        sys.exit("FAIL: no corpus entries")
    bases = prepare_bases(bindir, work, apps)
    jobs = [(en, a) for en in entries for a in apps if a in read_expected(os.path.join(here, en))["methods"]]
    env_threads = os.environ.get("OMP_NUM_THREADS")
    os.environ["OMP_NUM_THREADS"] = "1"   # two refusals at a time on two cores
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda j: check(bindir, work, bases, *j), jobs))
    if env_threads is not None:
        os.environ["OMP_NUM_THREADS"] = env_threads
    failed = 0
    for entry, app, problems, err in results:
        if problems:
            failed += 1
            print("FAIL %-34s %-14s %s\n     last error line: %s" % (entry, app, "; ".join(problems), err))
        else:
            print("ok   %-34s %-14s %s" % (entry, app, err[:110]))
    print("%d entries, %d runs: %d passed, %d failed" % (len(entries), len(results), len(results) - failed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
