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
    for d in slidefoam_env()["PATH"].split(":"):
        p = os.path.join(d, app)
        if os.access(p, os.X_OK):
            return p
    raise SystemExit("%s is not built: run ./Allwmake first" % app)
