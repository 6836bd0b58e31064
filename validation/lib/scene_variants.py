"""Variants of a SlideFoam case's scene, each run by one method in a folder of its own: what slideSweep and
slideBackAnalysis share.

A variant is a copy of the case's constant/ and system/ with some entries set by OpenFOAM's foamDictionary. A KEY is
an entry of constant/sceneProperties as a slash path (rheology/s_uo, base/s_b) or FILE:PATH for another dictionary
of the case (system/controlDict:endTime). A finished run is reused when its files, the method's binary and its values
are those asked for (its stamp, sweepRun.json).
"""
import hashlib
import json
import os
import shutil
import subprocess
import time

from runner import slidefoam_env, which
from slidefoam_io import failure_reason, read_summary

SCENE = "constant/sceneProperties"
METHODS = ("slideDAM", "slideMPM", "slideFoam")
SITE_FIELDS = [("arrival_time_s", "arrival [s]"), ("peak_speed_m_s", "peak speed [m/s]"),
               ("peak_momentum_flux_m3_s2", "peak h V^2 [m3/s2]"), ("max_thickness_m", "largest thickness [m]"),
               ("final_thickness_m", "final thickness [m]")]


class VariantError(Exception):
    """A key or value the case cannot take: its message names the file and the key."""


def split_key(key):
    """(file in the case, path in it) of a KEY."""
    if ":" in key:
        f, path = key.split(":", 1)
        return f, path
    return SCENE, key


def foam_dictionary(*args):
    """OpenFOAM's foamDictionary with these arguments: (exit status, output). It writes the whole file back on
    -set, every number at its precision (6 digits by default: a polyline vertex at 1054.911 m came back as
    1054.91), and reads -value at it too; 15 digits give back any decimal of up to 15."""
    p = subprocess.run(["foamDictionary", "-precision", "15"] + list(args), stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, env=slidefoam_env())
    return p.returncode, p.stdout.decode(errors="replace")


def check_keys(case, keys):
    """Every key an entry with a value (not a sub-dictionary) in its file of the case; outside the scene a missing
    one is let through, to be added."""
    for key in keys:
        f, path = split_key(key)
        full = os.path.join(case, f)
        if not os.path.isfile(full):
            raise VariantError("%s: no such file for key '%s'" % (full, key))
        rc, out = foam_dictionary("-entry", path, "-value", full)
        if rc != 0 and f == SCENE:
            raise VariantError("%s has no entry '%s' (key '%s')" % (full, path, key))
        if out.lstrip().startswith("{"):
            raise VariantError("%s: '%s' is a dictionary, not a value (key '%s'); name one of its entries, e.g. %s/..."
                 % (full, path, key, key))


def binaries(method):
    """The executables and libraries a method's run depends on: slideFoam's run also runs slideDAM (whose runout
    sizes its mesh) and slideFoamCase, and loads the project's OpenFOAM library."""
    if method != "slideFoam":
        return [which(method)]
    env = slidefoam_env()
    libs = [os.path.join(d, "libslideFoamModels.so") for d in (env.get("FOAM_USER_LIBBIN"), env.get("FOAM_LIBBIN"))
            if d]
    return [which(app) for app in ("slideFoam", "slideFoamCase", "slideDAM")] \
        + [p for p in libs if os.path.isfile(p)][:1]


def tree_digest(case, exes):
    """What a run's result depends on besides its values: the case's constant/ and system/ files and the method's
    binaries."""
    h = hashlib.sha256()
    for sub in ("constant", "system"):
        root = os.path.join(case, sub)
        for d, dirs, files in sorted(os.walk(root)):
            dirs[:] = sorted(x for x in dirs if x != "polyMesh")
            for name in sorted(files):
                p = os.path.join(d, name)
                h.update(os.path.relpath(p, case).encode())
                with open(p, "rb") as f:
                    h.update(f.read())
    for exe in exes:
        with open(exe, "rb") as f:
            h.update(f.read())
    return h.hexdigest()


def prepare_run(case, run_dir, method, fixed, values, digest):
    """The run's case in run_dir, the fixed entries set and then its own; True where the run already there is
    this one, finished, and is kept."""
    stamp = {"method": method, "fixed": fixed, "values": values, "digest": digest}
    stamp_path = os.path.join(run_dir, "sweepRun.json")
    summary = os.path.join(run_dir, "postProcessing", method, "summary.json")
    if os.path.isfile(stamp_path) and os.path.isfile(summary):
        with open(stamp_path) as f:
            if json.load(f) == stamp:
                return True
    if os.path.exists(run_dir):
        shutil.rmtree(run_dir)
    for sub in ("constant", "system"):
        shutil.copytree(os.path.join(case, sub), os.path.join(run_dir, sub), ignore=shutil.ignore_patterns("polyMesh"))
    for key, value in list(fixed.items()) + list(values.items()):
        f, path = split_key(key)
        rc, out = foam_dictionary("-entry", path, "-set", value, os.path.join(run_dir, f))
        if rc != 0:
            detail = " ".join(line.strip() for line in out.splitlines() if line.strip() and "FOAM" not in line)
            raise VariantError("%s: foamDictionary could not set '%s' to %s (key '%s'): %s"
                               % (os.path.join(case, f), path, value, key, detail[:300]))
    with open(stamp_path, "w") as f:
        json.dump(stamp, f, indent=1)
    return False


def run_one(run_dir, exe, method, threads):
    """One variant's run; threads: slideMPM's OpenMP threads, slideFoam's MPI ranks. Returns (exit status, wall)."""
    if method == "slideFoam":
        from cfdcase import run_sized
        start = time.time()
        return (0 if run_sized(run_dir, threads or 1) is None else 1), time.time() - start
    env = dict(slidefoam_env())
    if threads:
        env["OMP_NUM_THREADS"] = str(threads)
        env["OMP_PROC_BIND"] = "false"
    start = time.time()
    with open(os.path.join(run_dir, "log." + method), "w") as log:
        rc = subprocess.run([exe, "-case", "."], cwd=run_dir, stdout=log, stderr=subprocess.STDOUT,
                            env=env).returncode
    return rc, time.time() - start


def collect(run_dir, method, values, index):
    row = {"run": index, "dir": os.path.relpath(run_dir, os.path.dirname(os.path.dirname(run_dir))),
           "values": values}
    summary = os.path.join(run_dir, "postProcessing", method, "summary.json")
    if not os.path.isfile(summary):
        # slideFoam's run starts with slideDAM's, whose runout sizes its mesh.
        dam_failed = method == "slideFoam" and not os.path.isfile(
            os.path.join(run_dir, "postProcessing", "slideDAM", "summary.json")) and failure_reason(run_dir, "slideDAM")
        row["failed"] = dam_failed or failure_reason(run_dir, method) or "did not run"
        return row
    j = read_summary(summary)
    with open(os.path.join(run_dir, "log." + method), errors="replace") as f:
        row["warnings"] = [line.strip()[len("Warning: "):] for line in f if line.startswith("Warning: ")]
    row.update({"runout_m": j["runout_m"], "mass_front_m": j.get("front_of_99_percent_mass_m"),
                "final_length_m": j.get("final_length_m"),
                "at_rest": j["at_rest"], "end_time_s": j["end_time_s"],
                "rigid_slab_factor_of_safety": j.get("rigid_slab_factor_of_safety"),
                "mechanism": j.get("mechanism", "-"), "wall_time_s": j["wall_time_s"],
                "sites": [{k: s.get(k) for k in ["name", "position_m", "distance_from_initial_front_m"]
                           + [f for f, _ in SITE_FIELDS] + ["covered_at_end"]} for s in j.get("sites", [])]})
    return row


def foreign_files(out_dir, report):
    """Whether out_dir holds files a variants tool did not write: anything but its report (e.g. sweep.json) and a
    runs/ folder whose entries are stamped runs (an interrupted tool leaves runs without its report)."""
    if not os.path.isdir(out_dir) or not os.listdir(out_dir) or os.path.isfile(os.path.join(out_dir, report)):
        return False
    if os.listdir(out_dir) != ["runs"]:
        return True
    runs = os.path.join(out_dir, "runs")
    return not all(os.path.isfile(os.path.join(runs, name, "sweepRun.json")) for name in os.listdir(runs))
