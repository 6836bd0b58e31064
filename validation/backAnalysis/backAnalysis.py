#!/usr/bin/python3
"""Back-analysis with slideBackAnalysis: which strength or basal resistance makes each method reproduce an observed
runout, and how far the methods' answers lie apart. The paper back-analyses its two field cases; here slideDAM and
slideMPM each solve for the entry that reproduces the observation:

- Finneidfjord's outrunner block on a constant basal resistance s_b (the paper: a runout of 1380 m needs s_b below
  60 Pa, against a static limit of 161 Pa), checked against the rigid block's equation of motion on the tutorial's
  base, which gives the exact s_b for a block that stays rigid; the scene's end at 1200 s, so that every run stops;
  slideFoam run once with slideDAM's answer (check_at; 84 min to two hours on 2 MPI ranks since session 90's base; its
  block stops 1.3 % (session 89) or 4.0 % (session 92, on the slide's share) short of the rigid block, and
  0.5 % with the tutorial's baseSlideTrace 1e-3 (session 97, 84 min), ../cfd/README.md);
- the same block hydroplaning (s_b = 0.5 rho_w C_F V^2): the drag coefficient C_F for 1380 m (the paper takes
  C_F = 0.003 from De Blasio et al. 2004 and gets 1381 m with its DAM and 1400 m with its MPM), with the rigid block
  again, and the end at 1200 s again; slideMPM run once with slideDAM's answer (check_at; slideFoam not: its block
  stops at about 480 s, nearly two hours on 2 MPI ranks; session 87 measured its speed on Zone C instead,
  ../cfd/README.md);
- the Mediterranean escarpment: the intact strength s_uo for the observed 420 m (the paper's laboratory value is
  15 kPa, with which its DAM ran 462 m and its MPM 444 m), asked of slideFoam too since session 85 (two to five
  minutes a run on 2 MPI ranks, its search about 25 min);
- Table 1 Case 3, whose s_uo is garbled in the paper: the s_uo for the paper's 19.7 m (DAM and MPM) and 19.4 m (CFD,
  asked of slideFoam since session 82: two or three minutes a run on 2 MPI ranks, its search after the others'),
  each method run to rest (the scene's 600 s).

Each at the tutorial's set-up (Case 3: Table 1's, slideDAM 800 columns, slideMPM H0/10 with 4x4 particles, slideFoam
H0/10 with H0/40 on the base and the tutorials' maxDeltaT 0.05 s), the
tolerance 1 % of the target (0.2 % for C_F, to which the runout is nearly blind). slideMPM's searches run two at a
time on one thread each. Writes backAnalysis.json, backAnalysis.md and backAnalysis.png here; the runs stay in
platforms/validation-work/backAnalysis. About three hours on 2 cores.

Usage: validation/backAnalysis/backAnalysis.py [--stored] [--methods M1,M2] [--studies S1,S2]
  --stored: redraw backAnalysis.md and backAnalysis.png from backAnalysis.json without running
  --methods: run only these methods' searches and keep the others' from backAnalysis.json
  --studies: run only the studies whose names contain these words (case aside: escarpment, hydroplaning, case3)
             and keep the others' from backAnalysis.json
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(TOP, "validation", "lib"))
import options  # noqa: E402
import rigid_block  # noqa: E402
from cfdcase import copy_scene  # noqa: E402
from plotting import pyplot  # noqa: E402
from runner import run_tool, which  # noqa: E402
import scene_variants  # noqa: E402
from scene_variants import VariantError, binaries, prepare_run, run_one, tree_digest  # noqa: E402
from slidefoam_io import read_summary  # noqa: E402

TOLERANCE = 0.01
METHODS = ("slideDAM", "slideMPM", "slideFoam")
STUDIES = [
    {"name": "Finneidfjord block, constant s_b", "tutorial": "tutorials/finneidfjord", "constantResistance": 100,
     "find": ("base/s_b", 20.0, 160.0), "unit": "Pa", "set": {"system/controlDict:endTime": "1200"},
     "checkOnly": ("slideFoam",),
     "target": {"slideDAM": 1380.0, "slideMPM": 1380.0, "slideFoam": 1380.0},
     "paper": "below 60 Pa (DAM and MPM)", "rigid": "s_b"},
    {"name": "Finneidfjord block, hydroplaning", "tutorial": "tutorials/finneidfjord",
     "find": ("base/C_F", 0.001, 0.03), "unit": "", "set": {"system/controlDict:endTime": "1200"},
     "tolerance": 0.002, "checkOnly": ("slideMPM",),
     "target": {"slideDAM": 1380.0, "slideMPM": 1380.0},
     "paper": "0.003 taken (De Blasio et al. 2004): 1381 m (DAM), 1400 m (MPM)", "rigid": "C_F"},
    {"name": "Mediterranean escarpment", "tutorial": "tutorials/mediterraneanEscarpment",
     "find": ("rheology/s_uo", 8000.0, 30000.0), "unit": "Pa",
     "target": {"slideDAM": 420.0, "slideMPM": 420.0, "slideFoam": 420.0},
     "paper": "15 kPa measured: 462 m (DAM), 444 m (MPM)"},
    {"name": "Table 1 Case 3", "tutorial": "tutorials/table1/case03", "mpmCost": 3,
     "find": ("rheology/s_uo", 1000.0, 3000.0), "unit": "Pa",
     "target": {"slideDAM": 19.7, "slideMPM": 19.7, "slideFoam": 19.4},
     "paper": "garbled; table1.csv reads 1 kPa"},
]


def foam_dictionary(path, *args):
    """foamDictionary's output on the dictionary at path; its failure stops the study with what it said."""
    rc, out = scene_variants.foam_dictionary(*(list(args) + [path]))
    if rc != 0:
        raise SystemExit("foamDictionary %s %s failed:\n%s" % (" ".join(args), path, out[-1500:]))
    return out


def constant_resistance(case, s_b):
    """The tutorial's hydroplaning base made frictional with a constant s_b, as in the paper's first runs."""
    scene = os.path.join(case, "constant", "sceneProperties")
    foam_dictionary(scene, "-entry", "base/interface", "-set", "frictional")
    for key in ("base/C_F", "base/rhoWater"):
        foam_dictionary(scene, "-entry", key, "-remove")
    foam_dictionary(scene, "-entry", "base/s_b", "-add", "%g" % s_b)


def scene_numbers(case):
    """The block and base of a Finneidfjord case: (length, height, rho', rho_w, polyline points)."""
    scene = os.path.join(case, "constant", "sceneProperties")

    def value(key):
        return foam_dictionary(scene, "-entry", key, "-value").strip()
    points = [float(v) for v in value("base/points").replace("(", " ").replace(")", " ").split()]
    return (float(value("slide/length")), float(value("slide/height")), float(value("slide/density")),
            float(value("base/rhoWater")), list(zip(points[0::2], points[1::2])), float(value("g")))


def rigid_answer(numbers, kind, target, lo, hi):
    """The s_b or C_F with which the rigid block's equation of motion stops at the target."""
    from scipy.optimize import brentq
    length, height, rho, rho_w, points, g = numbers

    def miss(v):
        return rigid_block.runout(points, length, height, rho, g, rho_water=rho_w,
                                  **({"s_b": v} if kind == "s_b" else {"c_f": v})) - target
    return brentq(miss, lo, hi, xtol=1e-10*(hi - lo))


def back_analyse(case, method, study, out, threads=None):
    key, lo, hi = study["find"]
    cmd = [os.path.join(TOP, "bin", "slideBackAnalysis"), "-case", case, "-dir", out, "-method", method,
           "-find", key, "%g" % lo, "%g" % hi, "-match", "runout", "%g" % study["target"][method],
           "-tolerance", "%g" % study.get("tolerance", TOLERANCE), "-set", "system/mpmDict:writeFields", "no"]
    for key, value in study.get("set", {}).items():
        cmd += ["-set", key, value]
    if threads:
        cmd += ["-threads", str(threads)]
    j, wall = run_tool(cmd, os.path.join(out, "backAnalysis.json"))
    return {"result": j["result"], "wall": wall,
            "runs": [{"value": r["value"], "runout": r.get("observed"), "atRest": r.get("at_rest"),
                      "failed": r.get("failed") if r.get("observed") is None else None} for r in j["runs"]]}


def check_at(case, study, value, out, method, threads):
    """The method run once with slideDAM's answer, where a search of its own would cost hours to find what that
    run tells: slideMPM on the hydroplaning block, whose runout agrees with slideDAM's to a fraction of the
    tolerance at every value both ran (-0.012 % at C_F 0.001, 0.0285 and 0.03) over a range of C_F the runout is
    nearly blind to; slideFoam on the constant s_b, an hour a run at the tutorial's maxDeltaT 0.005 s, whose runout
    there against slideDAM's and the rigid block's is its error, and with the runout's slope (0.3 % for 1 % on s_b)
    says how far its own answer would lie from slideDAM's. Set up as slideSweep sets up its runs, and kept where
    the case's files, the method's binaries and the value are those of the run already there."""
    import time
    fixed = dict(study.get("set", {}), **{"system/mpmDict:writeFields": "no"})
    try:
        kept = prepare_run(case, out, method, fixed, {study["find"][0]: "%.10g" % value},
                           tree_digest(case, binaries(method)))
    except VariantError as e:
        raise SystemExit(str(e))
    t0 = time.time()
    if not kept and run_one(out, which(method), method, threads)[0] != 0:
        raise SystemExit("%s failed on %s: see its logs there" % (method, out))
    s = read_summary(os.path.join(out, "postProcessing", method, "summary.json"))
    row = {"value": value, "runout": s["runout_m"], "atRest": s["at_rest"], "failed": None}
    return {"result": {"outcome": "check", "runs": 1, "best": {"value": value, "observed": s["runout_m"],
                                                               "at_rest": s["at_rest"]},
                       "message": "slideDAM's %s %.6g: runout %.2f m" % (study["find"][0], value, s["runout_m"])},
            "wall": s["wall_time_s"] if kept else time.time() - t0, "runs": [row]}


def methods_of(study):
    """The methods a study asks: those it has a target for."""
    return [m for m in METHODS if m in study["target"]]


def measure(methods, stored, studies=None):
    """The given studies' (all where None) searches by the given methods; the other entries kept from the stored
    data."""
    from concurrent.futures import ThreadPoolExecutor
    work = os.path.join(TOP, "platforms", "validation-work", "backAnalysis")
    data, cases = [], []
    for study in STUDIES:
        # The case afresh from its tutorial; the searches' runs beside it, reused where its files are unchanged.
        folder = os.path.join(work, study["name"].replace(" ", "").replace(",", "_"))
        case = os.path.join(folder, "case")
        if os.path.exists(case):
            subprocess.run(["rm", "-rf", case], check=True)
        copy_scene(os.path.join(TOP, study["tutorial"]), case)
        entry = {"study": study["name"], "tutorial": study["tutorial"], "find": study["find"],
                 "target": study["target"], "paper": study["paper"], "unit": study["unit"],
                 "tolerance": study.get("tolerance", TOLERANCE)}
        if study.get("rigid"):
            entry["numbers"] = scene_numbers(case)
            entry["rigid"] = rigid_answer(entry["numbers"], study["rigid"], study["target"]["slideDAM"],
                                          *study["find"][1:])
        if study.get("constantResistance"):
            constant_resistance(case, study["constantResistance"])
        old = [e for e in stored if e["study"] == study["name"]]
        chosen = options.is_chosen(study["name"], studies)
        for method in methods_of(study):
            if (method not in methods or not chosen) and old and method in old[0]:
                entry[method] = old[0][method]
        data.append(entry)
        cases.append((study, folder, case, chosen))
    wanted = [(k, m) for k, study in enumerate(STUDIES) for m in methods_of(study) if m in methods and cases[k][3]]
    # slideDAM's searches take seconds; slideMPM's, on slides of a few thousand particles, run two at a time on one
    # thread each, which the small problems use about as well as two threads; slideFoam's, on 2 MPI ranks, after.
    dam_jobs = [(k, m, None) for k, m in wanted if m == "slideDAM"]
    # The longest (Table 1 Case 3's runs to rest at 600 s, 4x4 particles in H0/10 cells) first.
    mpm_jobs = [(k, m, 1) for k, m in sorted(wanted, key=lambda km: -STUDIES[km[0]].get("mpmCost", 1))
                if m == "slideMPM"]
    cfd_jobs = [(k, m, 2) for k, m in wanted if m == "slideFoam"]

    def one(job):
        k, method, threads = job
        study, folder, case, _ = cases[k]
        if method in study.get("checkOnly", ()):
            dam = ([f for (j, m, _), f in done if j == k and m == "slideDAM"] or [data[k]["slideDAM"]])[0]["result"]
            return job, check_at(case, study, dam["best"]["value"], os.path.join(folder, method + "check"), method,
                                 threads)
        return job, back_analyse(case, method, study, os.path.join(folder, method), threads)
    done = [one(job) for job in dam_jobs]
    with ThreadPoolExecutor(max_workers=2) as pool:
        done += list(pool.map(one, mpm_jobs))
    done += [one(job) for job in cfd_jobs]
    for (k, method, _), found in done:
        study, entry = STUDIES[k], data[k]
        entry[method] = found
        r = found["result"]
        print("%s, %s: %s (%.0f s)" % (study["name"], method, r["message"], found["wall"]), flush=True)
        if study.get("rigid") and r["outcome"] in ("matched", "check"):
            # The rigid block's runout with the method's answer: the method's own error there.
            length, height, rho, rho_w, points, g = entry["numbers"]
            found["rigidRunout"] = rigid_block.runout(
                points, length, height, rho, g, rho_water=rho_w,
                **({"s_b": r["best"]["value"]} if study["rigid"] == "s_b" else {"c_f": r["best"]["value"]}))
    return data


def value_text(v, unit, digits=4):
    if v is None:
        return "-"
    if unit == "Pa" and v >= 1000:
        return "%.*g kPa" % (digits, v/1000.0)
    return ("%.*g %s" % (digits, v, unit)).strip()


def found(entry, method):
    r = entry[method]["result"]
    return r["best"]["value"] if r["outcome"] == "matched" else None


def nearest(entry, method):
    """The value found, or where the search ended on a scatter above the tolerance the nearest run's."""
    r = entry[method]["result"]
    return r["best"]["value"] if r["outcome"] == "matched" or r.get("jump_is_scatter") else None


def write(data):
    lines = ["# Back-analysis: the entry that makes each method reproduce an observed runout", "",
             "Regenerated by `validation/backAnalysis/backAnalysis.py` (`--stored` redraws from backAnalysis.json) "
             "with `bin/slideBackAnalysis`: Brent's method over runs of the case, each search stopping where a run's "
             "runout lies within the tolerance of the target; then runs 5 % either side of the answer (or the "
             "search's own, 2.5-10 % away) give the runout's local slope. Each method at its tutorial's set-up "
             "(Case 3: Table 1's). Columns: the value found and its run's runout; the per cent the runout moves for "
             "1 % on the entry there; the runout's scatter from run to run at the answer (how far runs 0.2 % "
             "either side of it part from that slope; since session 81); the range of the entry that the "
             "tolerance leaves open (tolerance over the slope; where the scatter exceeds the tolerance, the two "
             "together over the slope, in bold); for the Finneidfjord block, the runout of the rigid block's equation of motion with the value "
             "found (`../lib/rigid_block.py`), against which the method's own runout there is its error.", "",
             "| study | entry | target [m] | paper | method | value found | its runout [m] | runs, wall | "
             "sensitivity | scatter at the answer [m] | the tolerance leaves | rigid block's runout with it [m] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for e in data:
        for method in [m for m in METHODS if m in e]:
            f = e[method]
            r = f["result"]
            cells = [e["study"], "`%s`" % e["find"][0], "%g +- %g %%" % (e["target"][method], 100*e["tolerance"]),
                     e["paper"], method]
            if r["outcome"] == "matched":
                cells += [value_text(r["best"]["value"], e["unit"]), "%.1f" % r["best"]["observed"]]
            elif r["outcome"] == "check":
                cells += ["not searched: slideDAM's %s, run once" % value_text(r["best"]["value"], e["unit"]),
                          "%.1f" % r["best"]["observed"]]
            elif r.get("jump_is_scatter"):
                # Brent's bracket closed on a scatter above the tolerance: the nearest run is as good a match as
                # the scatter allows.
                cells += ["none by the search: the target lies within a scatter of %.2g m at %s (nearest run: %s)"
                          % (r["scatter"]["value"], value_text(r["bracket"]["low"]["value"], e["unit"]),
                             value_text(r["best"]["value"], e["unit"])), "%.1f" % r["best"]["observed"]]
            else:
                cells += ["none: %s" % r["message"], "-"]
            # The runs' own wall times (a search repeated reuses them, in seconds).
            cells.append("%d, %.0f s" % (r["runs"], r.get("wall_time_s", f["wall"])))
            cells.append("-" if r.get("elasticity") is None else "%.2g %%" % abs(r["elasticity"]))
            cells.append("-" if r.get("scatter") is None else "%.2g" % r["scatter"]["value"])
            if r.get("resolution_with_scatter") is not None:
                cells.append("**+-%.2g %%**" % (100*r["resolution_with_scatter"]/abs(r["best"]["value"])))
            else:
                cells.append("-" if r.get("resolution") is None
                             else "+-%.2g %%" % (100*r["resolution"]/abs(r["best"]["value"])))
            cells.append("-" if f.get("rigidRunout") is None else "%.1f (its runout %+.2f %%)" % (
                f["rigidRunout"], 100*(r["best"]["observed"]/f["rigidRunout"] - 1)))
            lines.append("| " + " | ".join(cells) + " |")
    lines += [""] + ["%s's answer over slideDAM's: " % method + "; ".join(
        "%s %s" % (e["study"], "%s%.3f" % ("" if found(e, method) else "~", nearest(e, method)/found(e, "slideDAM"))
                   if nearest(e, method) and found(e, "slideDAM") else "-") for e in data if method in e)
        + (" (~: the nearest run, where the target lies within the scatter)" if any(
            method in e and nearest(e, method) and not found(e, method) for e in data) else "") + "."
        for method in METHODS[1:] if any(method in e for e in data)] + [
              "The rigid block's exact answers (its equation of motion solved for the target): " + "; ".join(
                  "%s %s" % (e["study"], value_text(e["rigid"], e["unit"])) for e in data if e.get("rigid")) + "."]
    lines += ["", "Runs of each search (entry: runout [m]; * still moving at the end time):", ""]
    for e in data:
        for method in [m for m in METHODS if m in e]:
            lines.append("- %s, %s: %s" % (e["study"], method, "; ".join(
                "%s: %s%s" % (value_text(r["value"], e["unit"], 6), "failed" if r["runout"] is None else
                              "%.1f" % r["runout"], "" if r["atRest"] in (True, None) else "*")
                for r in sorted(e[method]["runs"], key=lambda r: r["value"]))))
    lines += ["", "![runout against the entry, each method's runs](backAnalysis.png)", ""]
    with open(os.path.join(HERE, "backAnalysis.md"), "w") as f:
        f.write("\n".join(lines))

    plt = pyplot()
    fig, axes = plt.subplots(1, len(data), figsize=(4.6*len(data), 3.8))
    for ax, e in zip(axes, data):
        scale = 1000.0 if e["unit"] == "Pa" and e["find"][2] >= 1000 else 1.0
        for k, method in enumerate(METHODS):
            if method not in e:
                continue
            runs = sorted((r for r in e[method]["runs"] if r["runout"] is not None), key=lambda r: r["value"])
            ax.plot([r["value"]/scale for r in runs], [r["runout"] for r in runs], "o-", ms=4, lw=0.8,
                    color="C%d" % k, label=method)
            v = found(e, method)
            if v is not None:
                ax.axvline(v/scale, color="C%d" % k, ls=":", lw=1)
        if e.get("rigid") is not None:
            ax.axvline(e["rigid"]/scale, color="k", ls="--", lw=0.8, label="rigid block")
        for t in sorted(set(e["target"].values())):
            ax.axhline(t, color="C2", lw=1, label="target %g m" % t)
        unit = "kPa" if scale == 1000.0 else e["unit"]
        ax.set(xlabel="%s%s" % (e["find"][0], " [%s]" % unit if unit else ""), ylabel="runout [m]",
               title=e["study"])
        ax.title.set_fontsize(9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "backAnalysis.png"), dpi=100)


def main():
    import json
    args = options.parse(__doc__, flags=("--stored",), valued=("--methods", "--studies"))
    path = os.path.join(HERE, "backAnalysis.json")
    stored = json.load(open(path)) if os.path.isfile(path) else []
    if args.get("--stored"):
        return write(stored)
    methods = args["--methods"].split(",") if args.get("--methods") else list(METHODS)
    unknown = [m for m in methods if m not in METHODS]
    if unknown:
        sys.exit("--methods: %s is not one of %s" % (", ".join(unknown), ", ".join(METHODS)))
    studies = options.chosen_names(args.get("--studies"), [st["name"] for st in STUDIES], "--studies")
    data = measure(methods, stored, studies)
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
    write(data)


if __name__ == "__main__":
    main()
