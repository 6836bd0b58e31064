#!/usr/bin/python3
"""Probabilistic runout with slideSweep: does slideDAM's answer agree with slideMPM's, and how many runs does it
take? On two scenes a Latin hypercube of uncertain strength (and slope or sensitivity) is run by slideDAM and by
slideMPM on the same scenes (one seed: the runs pair up), and by slideDAM again on many more scenes as the
sampling reference:

- Table 1 Case 2 (the weak slide the three methods and the paper agree on within 7 %): s_uo lognormal, mean
  500 Pa, COV 0.25; slope uniform 3.43 +- 0.5 deg; sites 40 and 60 m ahead of the initial front.
- The Mediterranean escarpment (the sensitive slab the methods do not agree on): s_uo lognormal, mean 15 kPa,
  COV 0.3 (the field samples' strength with a spread of the order site investigations report); 1/S_t
  uniform from 1/60 to 1/20 (S_t 40 measured); the tutorial's pipeline and cable (hypothetical). And slideDAM
  over a grid of s_uo from 15 to 40 kPa: the strength from which its slab stands.

And slideFoam over the same scenes too (Case 2's since session 82, the escarpment's since session 85): the CFD's
probabilistic answer beside the other two.

slideMPM at the tutorials' fast set-ups, without field output, one run at a time on 2 threads; slideFoam at its
tutorial's (H0/10 with H0/40 on the base, maxDeltaT 0.05 s), one run at a time on 2 MPI ranks. Writes sweep.json,
sweep.md and sweep.png here. ~95 min on 2 cores.

Usage: validation/sweep/sweep.py [--stored] [--labels DAM,MPM,CFD,"DAM reference"] [--cases C1,C2]
  --stored: redraw sweep.md and sweep.png from sweep.json without running
  --labels: run only these sweeps (and the stand grid with DAM) and keep the others from sweep.json
  --cases: run only the scenes whose names contain these words (case aside: case2, escarpment) and keep the
           others from sweep.json
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "validation", "lib"))
import options  # noqa: E402
from cfdcase import copy_scene, set_sites  # noqa: E402
from plotting import pyplot  # noqa: E402
from runner import run_tool, slidefoam_env  # noqa: E402

CASES = [
    {"name": "Table 1 Case 2", "tutorial": "tutorials/table1/case02", "sites": [("d40", 80.0), ("d60", 100.0)],
     "samples": [("rheology/s_uo", "lognormal", 500, 0.25), ("base/angle", "uniform", 2.93, 3.93)],
     "n": 24, "nReference": 256, "cfd": True},
    {"name": "Mediterranean escarpment", "tutorial": "tutorials/mediterraneanEscarpment", "sites": None,
     "samples": [("rheology/s_uo", "lognormal", 15000, 0.3), ("rheology/deltaRem", "uniform", 0.0167, 0.05)],
     "n": 20, "nReference": 512, "standGrid": list(range(15000, 40001, 1000)), "cfd": True},
]
SEED = 1
LABELS = ("DAM", "MPM", "CFD", "DAM reference")
METHOD = {"DAM": "slideDAM", "MPM": "slideMPM", "CFD": "slideFoam", "DAM reference": "slideDAM"}


def labels_of(spec):
    return [label for label in LABELS if label != "CFD" or spec.get("cfd")]


def sweep(case, out, method, n, samples):
    """slideSweep's result; a run that failed is in it with its reason (slideSweep then exits with 1)."""
    cmd = [os.path.join(TOP, "bin", "slideSweep"), "-case", case, "-dir", out, "-method", method,
           "-samples", str(n), "-seed", str(SEED), "-set", "system/mpmDict:writeFields", "no"]
    for key, dist, *p in samples:
        cmd += ["-sample", key, dist] + ["%g" % v for v in p]
    result, wall = run_tool(cmd, os.path.join(out, "sweep.json"))
    return {"statistics": result["statistics"], "wall": wall,
            "runs": [{"values": r["values"], "runout": r.get("runout_m"), "atRest": r.get("at_rest"),
                      "wall": r.get("wall_time_s"), "failed": r.get("failed"),
                      "sites": [s["arrival_time_s"] for s in r.get("sites", [])]} for r in result["runs"]]}


def stand_grid(case, values):
    """[[s_uo, runout], ...] of slideDAM over a grid of s_uo: where its slide stops moving at all."""
    out = os.path.join(case, "sweepDAMstand")
    subprocess.run([os.path.join(TOP, "bin", "slideSweep"), "-case", case, "-dir", out, "-vary", "rheology/s_uo"]
                   + ["%g" % v for v in values], env=slidefoam_env())
    with open(os.path.join(out, "sweep.json")) as f:
        return [[float(r["values"]["rheology/s_uo"]), r.get("runout_m")] for r in json.load(f)["runs"]]


def measure(labels, stored, cases=None):
    """The sweeps of the given labels on the given scenes (all where None); the others' kept from the stored
    data."""
    work = os.path.join(TOP, "platforms", "validation-work", "sweep")
    data = []
    for spec in CASES:
        case = os.path.join(work, os.path.basename(spec["tutorial"]))
        if os.path.exists(case):
            subprocess.run(["rm", "-rf", case], check=True)
        copy_scene(os.path.join(TOP, spec["tutorial"]), case)
        if spec["sites"]:
            set_sites(case, spec["sites"])
        entry = {"case": spec["name"], "tutorial": spec["tutorial"], "samples": spec["samples"], "seed": SEED}
        old = ([e for e in stored if e["case"] == spec["name"]] or [{}])[0]
        chosen = options.is_chosen(spec["name"], cases)
        for label in labels_of(spec):
            if label not in labels or not chosen:
                if label in old:
                    entry[label] = old[label]
                continue
            n = spec["nReference"] if label == "DAM reference" else spec["n"]
            entry[label] = sweep(case, os.path.join(case, "sweep" + label.replace(" ", "")), METHOD[label], n,
                                 spec["samples"])
            print("%s, %s over %d scenes: %.0f s" % (spec["name"], label, n, entry[label]["wall"]), flush=True)
        if spec.get("standGrid"):
            entry["standGrid"] = (stand_grid(case, spec["standGrid"]) if "DAM" in labels and chosen
                                  else old.get("standGrid"))
        data.append(entry)
    return data


def fmt(v, f="%.1f"):
    return "-" if v is None else f % v


MOVED = 1.0   # [m]: a front that travelled less stood; its slide did not fail


def paired(entry, a="DAM", b="MPM"):
    """a / b runout ratios of the scenes both ran (the same values, one seed) where both slides moved, and
    the scenes where only one of them did: ([ratios], {label: [s_uo of the scenes where it alone stood]})."""
    ratios, stood = [], {a: [], b: []}
    for d, m in zip(entry[a]["runs"], entry[b]["runs"]):
        assert d["values"] == m["values"]
        if d["runout"] is None or m["runout"] is None:
            continue
        if d["runout"] >= MOVED and m["runout"] >= MOVED:
            ratios.append(d["runout"]/m["runout"])
        elif d["runout"] >= MOVED or m["runout"] >= MOVED:
            stood[b if d["runout"] >= MOVED else a].append(float(d["values"]["rheology/s_uo"]))
    return sorted(ratios), stood


def ran_and_stood(entry, label):
    """The s_uo of the label's scenes whose slide ran out (front travelling MOVED or more), and of those where it
    stood."""
    runs = [(float(r["values"]["rheology/s_uo"]), r["runout"]) for r in entry[label]["runs"]
            if r["runout"] is not None]
    return [v for v, x in runs if x >= MOVED], [v for v, x in runs if x < MOVED]


def write(data):
    lines = ["# Probabilistic runout: slideDAM against slideMPM over the same uncertain scenes", "",
             "Regenerated by `validation/sweep/sweep.py` (`--stored` redraws from sweep.json) with `bin/slideSweep`. "
             "Each scene's uncertain entries are drawn as a Latin hypercube (seed %d); slideDAM and slideMPM run the "
             "same scenes, so their runs pair up, and slideDAM runs many more as the sampling reference. Runouts "
             "in metres of front travel; P10 / P50 / P90 over the runs; a site's probability: the share of runs "
             "whose front passed it. slideDAM's `fast` and slideMPM's `fast` set-ups (the tutorials'), slideMPM "
             "without field output on 2 threads." % SEED, ""]
    heads = {"DAM": "slideDAM, %d scenes", "MPM": "slideMPM, the same %d", "CFD": "slideFoam, the same %d",
             "DAM reference": "slideDAM, %d scenes"}
    for entry in data:
        labels = [k for k in LABELS if k in entry]
        n = {k: entry[k]["statistics"]["runs"] for k in labels}
        lines += ["## %s (`%s`)" % (entry["case"], entry["tutorial"]), "",
                  "Drawn: " + "; ".join("`%s` %s %s" % (k, d, " ".join("%g" % v for v in p))
                                       for k, d, *p in entry["samples"]) + ".", "",
                  "| | " + " | ".join(heads[k] % n[k] for k in labels) + " |", "|---|" + "---|"*len(labels)]
        st = {k: entry[k]["statistics"] for k in labels}
        lines.append("| finished / still moving at the end / failed | " + " | ".join(
            "%d / %d / %d" % (st[k]["finished"], st[k]["still_moving"], st[k]["failed"]) for k in labels) + " |")
        for q in ("P10", "P50", "P90", "mean", "sd"):
            lines.append("| runout %s [m] | " % q + " | ".join(fmt(st[k]["runout_m"][q]) for k in labels) + " |")
        for i, site in enumerate(st["DAM"]["sites"]):
            lines.append("| P(reached) %s, %g m ahead | " % (site["name"], site["distance_from_initial_front_m"])
                         + " | ".join("%.2f (%d)" % (st[k]["sites"][i]["probability_reached"],
                                                     st[k]["sites"][i]["reached"]) for k in labels) + " |")
            lines.append("| peak h V^2 there, P50 / P90 [m3/s2] | " + " | ".join(
                "%s / %s" % (fmt(st[k]["sites"][i]["peak_momentum_flux_m3_s2"]["P50"], "%.3g"),
                             fmt(st[k]["sites"][i]["peak_momentum_flux_m3_s2"]["P90"], "%.3g")) for k in labels) + " |")
        for key, *_ in entry["samples"]:
            lines.append("| rank correlation of the runout with `%s` | " % key + " | ".join(
                fmt(st[k]["rank_correlation_with_runout"].get(key), "%+.2f") for k in labels) + " |")
        lines.append("| wall time of the sweep [s] | " + " | ".join("%.0f" % entry[k]["wall"] for k in labels) + " |")
        r, stood = paired(entry)
        if r:
            lines += ["", "Paired, scene by scene, where both slides moved (a front travelling %g m or more): "
                      "slideDAM's runout over slideMPM's is %.2f at the median, %.2f to %.2f over the %d pairs; "
                      "slideDAM runs further in %d of them." % (MOVED, r[len(r)//2], r[0], r[-1], len(r),
                                                               sum(1 for x in r if x > 1))]
        for other in ("MPM", "DAM"):
            rc = paired(entry, "CFD", other)[0] if "CFD" in entry else []
            if rc:
                lines += ["", "slideFoam's runout over slide%s's, scene by scene: %.2f at the median, %.2f to %.2f "
                          "over the %d pairs; slideFoam runs further in %d of them." % (
                              other, rc[len(rc)//2], rc[0], rc[-1], len(rc), sum(1 for x in rc if x > 1))]
        grid = entry.get("standGrid")
        if grid:
            ran = [v for v, x in grid if x is not None and x >= MOVED]
            stands = [v for v, x in grid if x is not None and x < MOVED]
            mpm_ran, mpm_stood = ran_and_stood(entry, "MPM")
            lines += ["", "Where the slide stands: slideDAM over s_uo %.0f to %.0f Pa in steps of %.0f Pa runs out "
                      "up to %.0f Pa (%.1f m) and stands from %s Pa; in the sample slideMPM's slide ran out up to "
                      "%s Pa and stood from %s Pa." % (
                          grid[0][0], grid[-1][0], grid[1][0] - grid[0][0], max(ran),
                          dict((v, x) for v, x in grid)[max(ran)],
                          "%.0f" % min(stands) if stands else "none of them",
                          "%.0f" % max(mpm_ran) if mpm_ran else "-", "%.0f" % min(mpm_stood) if mpm_stood else "-")]
            if "CFD" in entry:
                cfd_ran, cfd_stood = ran_and_stood(entry, "CFD")
                lines[-1] += " slideFoam's ran out up to %s Pa and stood from %s Pa." % (
                    "%.0f" % max(cfd_ran) if cfd_ran else "-", "%.0f" % min(cfd_stood) if cfd_stood else "-")
        pairs = [(stood, "MPM", "DAM"), (stood, "DAM", "MPM")]
        if "CFD" in entry:
            stood_cfd = paired(entry, "CFD", "MPM")[1]
            pairs += [(stood_cfd, "CFD", "MPM"), (stood_cfd, "MPM", "CFD")]
        for stood, method, other in pairs:
            if stood[method]:
                lines += ["", "In %d scene%s %s's slide stood (front under %g m) where %s's ran out: s_uo "
                          "%s Pa." % (len(stood[method]), "s"[:len(stood[method]) > 1], METHOD[method], MOVED,
                                      METHOD[other],
                                      ", ".join("%.0f" % v for v in sorted(stood[method])))]
        lines.append("")
    lines += ["![exceedance curves and paired runouts](sweep.png)", ""]
    with open(os.path.join(HERE, "sweep.md"), "w") as f:
        f.write("\n".join(lines))

    plt = pyplot()
    fig, ax = plt.subplots(len(data), 2, figsize=(11, 4*len(data)), squeeze=False)
    for row, entry in zip(ax, data):
        for label, style in (("DAM", "C0"), ("MPM", "C1"), ("CFD", "C2"), ("DAM reference", "C0:")):
            if label not in entry:
                continue
            x = sorted(r["runout"] for r in entry[label]["runs"] if r["runout"] is not None)
            n = len(x)
            row[0].step(x, [(n - i)/n for i in range(n)], style[:2], ls=style[2:] or "-", where="post",
                        label="%s, %d scenes" % (label.replace("DAM", "slideDAM").replace("MPM", "slideMPM")
                                                 .replace("CFD", "slideFoam"), n))
        for i, site in enumerate(entry["DAM"]["statistics"]["sites"]):
            row[0].axvline(site["distance_from_initial_front_m"], color="grey", ls="--", lw=0.8)
            row[0].annotate(site["name"], (site["distance_from_initial_front_m"], 1.0), fontsize=7, color="grey",
                            rotation=90, va="top", ha="right")
        row[0].set(xlabel="runout [m]", ylabel="share of runs reaching at least x", title=entry["case"])
        row[0].legend(fontsize=8)
        lim = 0.0
        for label, colour in (("DAM", "C0"), ("CFD", "C2")):
            if label not in entry:
                continue
            pairs = [(d["runout"], m["runout"]) for d, m in zip(entry[label]["runs"], entry["MPM"]["runs"])
                     if d["runout"] is not None and m["runout"] is not None]
            if pairs:
                row[1].scatter([m for _, m in pairs], [d for d, _ in pairs], s=16, color=colour,
                               label=METHOD[label])
                lim = max(lim, max(max(p) for p in pairs)*1.05)
        if lim > 0:
            row[1].plot([0, lim], [0, lim], "k:", lw=0.8)
            row[1].set(xlim=(0, lim), ylim=(0, lim))
            row[1].legend(fontsize=8)
        row[1].set(xlabel="slideMPM runout [m]", ylabel="its runout [m]",
                   title="the same scenes, paired with slideMPM's")
        for a in row:
            a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "sweep.png"), dpi=100)


def main():
    args = options.parse(__doc__, flags=("--stored",), valued=("--labels", "--cases"))
    path = os.path.join(HERE, "sweep.json")
    stored = json.load(open(path)) if os.path.isfile(path) else []
    if args.get("--stored"):
        data = stored
    else:
        labels = args["--labels"].split(",") if args.get("--labels") else list(LABELS)
        if any(label not in LABELS for label in labels):
            sys.exit("--labels: each one of %s" % ", ".join(LABELS))
        cases = options.chosen_names(args.get("--cases"), [c["name"] for c in CASES], "--cases")
        data = measure(labels, stored, cases)
        with open(path, "w") as f:
            json.dump(data, f, indent=1)
    write(data)
    print("Written: %s" % os.path.join(HERE, "sweep.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
