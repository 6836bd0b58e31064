"""What the two shear band studies (validation/mpm/shearBand.py, validation/cfd/shearBand.py) share: runs
keyed by scene, cells per H0 and band thickness (0: xi per cell), each with its front history."""
from slidefoam_io import front_at


def spread_lines(results, names, mesh_word, t=10.0):
    """Markdown lines: each scene's front at t over the cells it ran at, per cell and per band, finest over
    coarsest (1 = objective in the mesh); stored runs of an older code ("stale") left out."""
    lines = ["", "Front at %g s, finest over coarsest %s (1 = mesh-objective):" % (t, mesh_word), ""]
    for name in names:
        for banded in (False, True):
            fs = sorted((r["cells"], front_at(r["history"], t)) for r in results
                        if r["scene"] == name and (r["band"] > 0) == banded and not r.get("stale")
                        and front_at(r["history"], t))
            if len(fs) >= 2:
                lines.append("- %s, %s: %s; finest/coarsest %.2f" % (
                    name, "per band" if banded else "per cell", ", ".join("H0/%d %.1f m" % f for f in fs),
                    fs[-1][1]/fs[0][1]))
    return lines + [""]


def plot_runs(ax, results, name, prefix=""):
    """A scene's front histories on an axis: per band solid, per cell dashed."""
    from plotting import plot_history
    for r in results:
        if r["scene"] == name:
            plot_history(ax, r["history"], "-" if r["band"] > 0 else "--",
                         "%sH0/%d, %s" % (prefix, r["cells"], "band H0/60" if r["band"] > 0 else "per cell"))
