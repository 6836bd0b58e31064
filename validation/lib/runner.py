"""Finds SlideFoam's applications and the environment they need (etc/bashrc)."""
import os
import subprocess

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
_env = None


def slidefoam_env():
    """The environment etc/bashrc sets up, captured once."""
    global _env
    if _env is None:
        out = subprocess.run(["bash", "-c", ". '%s/etc/bashrc' > /dev/null 2>&1; env -0" % TOP],
                             check=True, stdout=subprocess.PIPE).stdout.decode()
        _env = dict(item.split("=", 1) for item in out.split("\0") if "=" in item)
    return _env


def which(app):
    """The executable of `app` on SlideFoam's PATH, or the one SLIDEFOAM_<APP>_BINARY names (e.g.
    SLIDEFOAM_SLIDEMPM_BINARY=platforms/<opts>/bin-cuda/slideMPM runs the validation scripts on a GPU)."""
    key = "SLIDEFOAM_%s_BINARY" % app.upper()
    if os.environ.get(key):
        exe = os.path.abspath(os.environ[key])
        if not os.access(exe, os.X_OK):
            raise SystemExit("%s=%s: not an executable" % (key, os.environ[key]))
        return exe
    for d in slidefoam_env()["PATH"].split(":"):
        p = os.path.join(d, app)
        if os.access(p, os.X_OK):
            return p
    raise SystemExit("%s is not built: run ./Allwmake first" % app)


def run_method(app, case_dir, env=None):
    """Runs slideDAM or slideMPM (a name found on SlideFoam's PATH, or an executable's path, as CTest gives
    it) on case_dir, log in log.<app>, and returns (summary, runout) as slidefoam_io reads them; a failed run
    raises SystemExit with the end of its log."""
    from slidefoam_io import read_runout, read_summary
    exe = app if os.path.sep in app else which(app)
    app = os.path.basename(app)
    log = os.path.join(case_dir, "log." + app)
    with open(log, "w") as f:
        rc = subprocess.run([exe, "-case", case_dir], stdout=f, stderr=subprocess.STDOUT,
                            env=dict(slidefoam_env(), **(env or {}))).returncode
    if rc != 0:
        raise SystemExit("%s failed on %s (exit %d):\n%s" % (app, case_dir, rc, open(log).read()[-2000:]))
    out = os.path.join(case_dir, "postProcessing", app)
    return read_summary(os.path.join(out, "summary.json")), read_runout(os.path.join(out, "runout.dat"))


def run_tool(cmd, report):
    """Runs one of the project's tools (slideSweep, slideBackAnalysis) and returns (its JSON report, wall time);
    a tool that exits with 1 over a failed run still writes the report, which says so."""
    import json
    import time
    t0 = time.time()
    subprocess.run(cmd, env=slidefoam_env())
    with open(report) as f:
        return json.load(f), time.time() - t0
