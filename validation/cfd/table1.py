#!/usr/bin/env python3
"""Regenerates the CFD column of Table 1 (Dong, Wang & Cui 2020): runs slideFoam
on tutorials/table1/caseNN (slideDAM first, whose runout sizes the mesh, as the
tutorials' Allrun does) at one or more meshes, and writes beside this script
table1.md (the paper's CFD/DAM/MPM runouts, slideFoam's per mesh, the error
against the paper's CFD, at rest or not, wall time), table1.png and table1.json.

Usage: validation/cfd/table1.py [--cells 10] [--cases 1,2,3] [--base-refinement 4] [--processors 2] [--keep]
                                 [--scene-end] [--ahead-height 0.75] [--ahead-from 20] [--behind 200]
                                 [--max-co 0.25] [--max-delta-t 0.01] [--outer-correctors] [--xi-per-cell]
                                 [--rate-free] [--wall-function] [--whole-face] [--transpose-mean] [--slide-trace]
                                 [--no-slide-trace]
                                 [--top slip]
                                 [--reach 1600] [--end-time 100]
                                 [--replot] [--continue CASE_DIR --end-time 200]
(after ./Allwmake; Cases 1-3 at H0/10 take a few minutes on 2 cores)"""
import argparse
import json
import math
import os
import re
import shutil
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import get_entry, make_case, run, run_regenerating, set_entry, set_method_entries  # noqa: E402
from paper import CASE1_RATE_FREE_SCENE, paper_table, wall_function_acts  # noqa: E402
from runner import run_method, which  # noqa: E402
from slidefoam_io import base_cells, read_summary, read_runout, unresolved  # noqa: E402


def fatal_error(log):
    """The first FOAM FATAL ERROR's message in a solver log (one line; its rank prefix dropped), or None."""
    m = re.search(r"FOAM FATAL (?:IO )?ERROR:\s*\n(?:\[\d+\] )?(.+)", log)
    return m.group(1).strip() if m else None


# The on/off run options, in the order of the work directory's name: (option and row key, the name's suffix,
# the row's description, the cfdDict entry it sets or None). Each is part of a row's key.
SWITCHES = [
    ("xi_per_cell", "_perCell", ", xi per cell", ("shearBandThickness", 0)),
    ("rate_free", "_rateFree", ", no rate effect", None),
    ("wall_function", "_wallFunction", ", Eq. (1)'s wall function on the base", ("rateWallFunction", "yes")),
    ("face_viscosity", "_faceViscosity", ", the slide's viscosity at each face's rate", ("faceViscosity", "yes")),
    ("outer_correctors", "_outer3", ", three outer correctors a step", ("outerCorrectors", 3)),
    ("whole_face", "_wholeFace", ", s_b on every base face the slide touches", ("baseStrength", "wholeFace")),
    ("transpose_mean", "_transposeMean", ", the base's transpose flux's running mean taken out",
     ("transposeShear", "runningMean")),
    ("slide_trace", "_slideTrace", ", base faces under less than 1e-4 of slide the ambient's",
     ("baseSlideTrace", "1e-4")),
    # The solver's default floor is 1e-3 since session 98; the frictional rows stored before ran without one.
    ("no_slide_trace", "_noSlideTrace", ", no slide-trace floor on the base (baseSlideTrace 0)",
     ("baseSlideTrace", "0")),
]


def counting(r):
    """What the row's switches add to its mesh's description (", xi per cell", ...), else ""."""
    return "".join(text for key, _, text, _ in SWITCHES if r.get(key))


def case_name(c, cells, mesh):
    """The work directory's name of a run: caseNN_H0_n with what the row's key adds (--continue reads it back)."""
    return ("case%02d_H0_%d" % (c, cells) + "".join(suffix for key, suffix, _, _ in SWITCHES if mesh.get(key))
            + ("_dt%g" % mesh["max_delta_t"] if mesh.get("max_delta_t") else "")
            + ("_co%g" % mesh["max_co"] if mesh.get("max_co") else ""))


# Mesh and run options passed to cfdDict as numbers: (option and row key, cfdDict entry, help).
CFD_ENTRIES = [
    ("ahead_height", "aheadHeightRatio", "mesh height over H0 from H0 ahead of the slide on (cfdDict aheadHeightRatio; "
     "default: the full height): the long weak slides, which thin as they run out"),
    ("ahead_from", "aheadHeightFrom", "where the lower top starts, metres ahead of the initial front (cfdDict "
     "aheadHeightFrom; default: H0)"),
    ("behind", "behind", "mesh behind the slide's rear [m] (cfdDict behind; default: from slideDAM's upslope "
     "spreading, rerun with more where the rear leaves the mesh)"),
    ("reach", "reach", "mesh ahead of the initial front [m] (cfdDict reach; default: from slideDAM's runout): with "
     "--end-time, a mesh as long as the slide gets by then"),
    ("ambient_relaxation", "ambientRelaxationTime", "the light ambient relaxes to rest on this time scale [s] "
     "(cfdDict ambientRelaxationTime, the ambientDamping fvOption; default: undamped): with a lid (Case 4), whose "
     "ambient keeps circulating after the slide stops"),
    ("end_time", "endTime", "slideFoam stops here [s] (cfdDict endTime): part of a run the CFD cannot follow to the "
     "end here"),
]


def unresolved_note(r):
    return " (unresolved: alpha max %.2f)" % r["alpha_max"] if unresolved(r) else ""


def run_case(c, cells, processors, work, mesh, scene_end=False, retries=2):
    """mesh: refinement, max_co, max_delta_t, xi_per_cell, rate_free, top and CFD_ENTRIES' keys (None: the tutorial's or
    slideDAM's)."""
    src = os.path.join(top, "tutorials", "table1", "case%02d" % c)
    cfd = {"setting": "fast", "cellsPerHeight": cells, "baseRefinement": mesh["refinement"], "processors": processors}
    for key, _, _, entry in SWITCHES:
        if entry and mesh.get(key):
            cfd[entry[0]] = entry[1]
    if mesh.get("top"):
        cfd["top"] = mesh["top"]
    for key, entry, _ in CFD_ENTRIES:
        if mesh.get(key) is not None:
            cfd[entry] = "%.6g" % mesh[key]
    control = dict({"maxCo": mesh["max_co"], "maxAlphaCo": mesh["max_co"]} if mesh.get("max_co") else {},
                   **({"maxDeltaT": mesh["max_delta_t"]} if mesh.get("max_delta_t") else {})) or None
    # The tutorial's cfdDict with the mesh set: what else it says (a scene's shearBandThickness) is kept.
    d = make_case(src, work, case_name(c, cells, mesh), control=control,
                  scene=CASE1_RATE_FREE_SCENE if mesh.get("rate_free") else None)
    set_method_entries(d, "cfdDict", cfd)
    run(d, which("slideDAM"), "-case", ".")
    dam = read_summary(os.path.join(d, "postProcessing", "slideDAM", "summary.json"))
    if dam["at_rest"] and not scene_end:
        # The CFD's regularised plug creeps where the deposit is near its yield
        # thickness long after the front has stopped: run as long as the DAM took.
        set_entry(os.path.join(d, "system", "controlDict"), "endTime", math.ceil(dam["end_time_s"]))
    failed = run_regenerating(d, processors, retries)
    # A mesh regenerated longer says how long in its cfdDict.
    for key in ("reach", "behind"):
        value = get_entry(os.path.join(d, "system", "cfdDict"), key)
        if value is not None:
            mesh = dict(mesh, **{key: value})
    if failed:
        log = os.path.join(d, "log.slideFoam")
        log = open(log).read() if os.path.exists(log) else ""
        return dict({"case": c, "cells": cells, "failed": failed[-600:], "reason": fatal_error(log)}, **mesh)
    return case_row(c, cells, d, dam["runout_m"], mesh)


def case_row(c, cells, d, dam_runout, mesh):
    """table1.json's row for a run that ended in case directory d (its summary.json and runout.dat)."""
    s = read_summary(os.path.join(d, "postProcessing", "slideFoam", "summary.json"))
    r = read_runout(os.path.join(d, "postProcessing", "slideFoam", "runout.dat"))
    # Restarts before session 35 wrote their start time's row twice.
    first = [i for i, t in enumerate(r["time"]) if i == 0 or t > r["time"][i - 1]]
    # The mesh's options first: the run's own end time replaces the cfdDict endTime asked for (--end-time).
    return {**mesh, "case": c, "cells": cells, "runout": s["runout_m"], "at_rest": s["at_rest"],
            "end_time": s["end_time_s"],
            "wall": s["wall_time_s"], "n": s["problem_size"],
            # From runout.dat's slide mass, so that it spans every leg of a restarted run.
            "volume_change": float(r["mass"][-1]/r["mass"][0] - 1),
            "xi_max": s["xi_max"], "dam_runout": dam_runout,
            "top_cells_slide_share_max": s.get("top_cells_slide_share_max"),
            "alpha_max": s["alpha_max"], "slide_share_above_half": s.get("slide_share_above_half"),
            "front_velocity": float(r["frontVelocity"][-1]), "max_velocity": float(r["maxVelocity"][-1]),
            # Read off the cells since session 36 (src/output/runoutMechanism.H); absent from older runs.
            "mechanism": s.get("mechanism"), "mechanism_history": s.get("mechanism_history"),
            "shear_band": s.get("shear_band"),
            # time, front, front velocity (runout.dat's, the alpha-weighted speed of the front's column; rows
            # before session 37 hold time and front alone).
            "history": [[float(r["time"][i]), float(r["front"][i]), float(r["frontVelocity"][i])] for i in first]}


def row_key(r):
    # The base's cells too: Case 3 ran at H0/40 with H0/40 and with H0/80 on the base.
    return ((r["case"], r["cells"], base_cells(r)) + tuple(bool(r.get(key)) for key, _, _, _ in SWITCHES)
            + (r.get("max_delta_t") or 0.0, r.get("max_co") or 0.0))


def scene_dam_runout(c):
    """slideDAM's runout on Table 1 Case c's tutorial scene as it stands (its damDict and end time)."""
    work = tempfile.mkdtemp(prefix="slideFoam_table1_dam_")
    d = make_case(os.path.join(top, "tutorials", "table1", "case%02d" % c), work, "case%02d" % c)
    runout = run_method("slideDAM", d)[0]["runout_m"]
    shutil.rmtree(work)
    return runout


def continue_case(d, end_time, processors, rows, ambient_relaxation=None):
    """Runs a kept case of an earlier table1.py run (its work directory, decomposed on `processors` ranks) on from
    its latest time to end_time (cfdDict endTime, startFrom latestTime), or collects a leg already run so by hand,
    and returns its table1.json row with the legs (start, end, wall time, cells) it took. d may be the case
    carried on to a longer mesh by bin/tools/extendSlideMesh (named as the case it came from). ambient_relaxation:
    the light ambient relaxes to rest on this time scale [s] from the leg's start on (cfdDict ambientRelaxationTime
    and the constant/fvOptions slideFoamCase writes for it)."""
    m = re.match(r"case(\d+)_H0_(\d+)%s(?:_dt([0-9.e+-]+))?(?:_co([0-9.e+-]+))?$" % "".join("(%s)?" % suffix for _, suffix, _, _ in SWITCHES),
                 os.path.basename(os.path.normpath(d)))
    if not m:
        raise SystemExit("--continue: %s is not a case directory of table1.py (caseNN_H0_n)" % d)
    key = row_key(dict({"case": int(m.group(1)), "cells": int(m.group(2)),
                        "refinement": int(get_entry(os.path.join(d, "system", "cfdDict"), "baseRefinement") or 1)},
                       **{key: bool(m.group(3 + i)) for i, (key, _, _, _) in enumerate(SWITCHES)},
                       max_delta_t=float(m.group(3 + len(SWITCHES))) if m.group(3 + len(SWITCHES)) else None,
                       max_co=float(m.group(4 + len(SWITCHES))) if m.group(4 + len(SWITCHES)) else None))
    old = [r for r in rows if row_key(r) == key and "failed" not in r]
    if not old:
        raise SystemExit("--continue: table1.json has no run of Case %d at H0/%d to continue" % key[:2])
    old = old[0]
    legs = old.get("legs") or [[0.0, old["end_time"], old["wall"]]]
    summary = os.path.join(d, "postProcessing", "slideFoam", "summary.json")
    s = read_summary(summary) if os.path.exists(summary) else {}
    if s.get("end_time_s", 0) > legs[-1][1]:
        print("Case %d H0/%d: collecting the leg from %g to %g s run by hand" % (key[0], key[1], legs[-1][1],
                                                                                 s["end_time_s"]), flush=True)
    elif end_time <= legs[-1][1]:
        raise SystemExit("--continue: Case %d H0/%d already ran to %g s; give a later --end-time"
                         % (key[0], key[1], legs[-1][1]))
    else:
        # A leg stopped by hand after its last collected time: the run goes on from its latest write, and the
        # stopped leg (its log's last wall time) is counted.
        times = [float(t) for t in os.listdir(os.path.join(d, "processor0")) if re.match(r"^[0-9.eE+-]+$", t)]
        latest = max(times) if times else legs[-1][1]
        stopped_log = os.path.join(d, "log.slideFoam.from%g" % legs[-1][1])
        if latest > legs[-1][1] + 1e-9 and os.path.exists(stopped_log):
            walls = re.findall(r"^ExecutionTime = .* ClockTime = ([0-9.eE+-]+) s", open(stopped_log).read(), re.M)
            os.replace(stopped_log, stopped_log + ".stopped%g" % latest)
            legs = legs + [[legs[-1][1], latest, float(walls[-1]) if walls else 0.0, old["n"]]]
        if ambient_relaxation:
            set_method_entries(d, "cfdDict", {"ambientRelaxationTime": "%g" % ambient_relaxation})
            with open(os.path.join(d, "constant", "fvOptions"), "w") as f:
                f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class dictionary;\n"
                        "    object fvOptions;\n}\n// Written by table1.py --continue, as slideFoamCase writes it "
                        "for cfdDict ambientRelaxationTime\nambientDamping\n{\n    type ambientDamping;\n"
                        "    relaxationTime %g;\n}\n" % ambient_relaxation)
            # Each tau with the time it started from, for the row's description.
            steps = old.get("ambient_relaxation_steps") or []
            if not steps or steps[-1][1] != ambient_relaxation:
                steps = steps + [[latest, ambient_relaxation]]
            old = dict(old, ambient_relaxation_steps=steps)
        set_method_entries(d, "cfdDict", {"endTime": "%g" % end_time})
        set_entry(os.path.join(d, "system", "controlDict"), "startFrom", "latestTime")
        # slideDAM's end time, which table1.py gave the run, would stop it first.
        set_entry(os.path.join(d, "system", "controlDict"), "endTime", "%g" % end_time)
        log = "log.slideFoam.from%g" % legs[-1][1]
        run(d, "mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(processors), which("slideFoam"),
            "-parallel", log=log)
        run(d, "reconstructPar", "-latestTime")
        s = read_summary(summary)
    legs = [leg if len(leg) > 3 else leg + [old["n"]] for leg in legs]
    legs = legs + [[legs[-1][1], s["end_time_s"], s["wall_time_s"], s["problem_size"]]]
    mesh = {k: old.get(k) for k in ["refinement", "max_co", "max_delta_t", "top", "ambient_relaxation_steps"]
            + [e[0] for e in SWITCHES] + [e[0] for e in CFD_ENTRIES]}
    # A case carried on to a longer mesh (bin/tools/extendSlideMesh) says how long in its cfdDict.
    for k, entry, _ in CFD_ENTRIES:
        value = get_entry(os.path.join(d, "system", "cfdDict"), entry)
        if k != "end_time" and value is not None:
            mesh[k] = value
    # The scene's slideDAM run anew: a run carried on past the scene's end time it started with (Cases 3, 10
    # and 13 before session 54) compares with slideDAM run as long. The rate-free scene is not the tutorial's.
    row = case_row(key[0], key[1], d, old["dam_runout"] if old.get("rate_free") else scene_dam_runout(key[0]), mesh)
    row.update(wall=sum(leg[2] for leg in legs), legs=legs)
    # summary.json's largest share of the slide in the top cells is its own leg's.
    shares = [r.get("top_cells_slide_share_max") for r in (old, row) if r.get("top_cells_slide_share_max") is not None]
    row["top_cells_slide_share_max"] = max(shares) if shares else None
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cells", default="10")
    ap.add_argument("--cases", default="1,2,3")
    ap.add_argument("--base-refinement", type=int, default=4, help="cells on the base this many times thinner")
    ap.add_argument("--processors", type=int, default=2)
    ap.add_argument("--keep", action="store_true", help="keep the other cases/meshes of table1.json in the table")
    ap.add_argument("--scene-end", action="store_true",
                    help="run to the scene's end time (stopping at rest) instead of as long as slideDAM took: "
                         "for the strong slides, whose faces slideDAM collapses in seconds")
    for key, _, text in CFD_ENTRIES:
        ap.add_argument("--" + key.replace("_", "-"), type=float, default=None, help=text)
    ap.add_argument("--max-co", type=float, default=None,
                    help="maxCo and maxAlphaCo of the run (default: the tutorial's controlDict, 0.5)")
    ap.add_argument("--max-delta-t", type=float, default=None,
                    help="maxDeltaT of the run [s] (default: the tutorial's controlDict, 0.05 s): on a frictional base "
                    "the lagged traction over-brakes a plug at a long step (validation/cfd/README.md, \"The base's "
                    "traction and the time step\")")
    ap.add_argument("--xi-per-cell", action="store_true",
                    help="xi counts the strain of each cell (cfdDict shearBandThickness 0) instead of the tutorial's "
                    "shear bands of H0/60: the remoulding Cases 10-13 as the CFD ran them until session 29")
    ap.add_argument("--rate-free", action="store_true",
                    help="Case 1 without Eq. (1)'s rate term (eta 0, s_uo 225 Pa; validation/lib/paper.py): how "
                    "much of the runout's dependence on the cells is the rate term's")
    ap.add_argument("--wall-function", action="store_true",
                    help="cfdDict rateWallFunction yes: the no-slip base's stress from Eq. (1)'s profile through the "
                    "wall cell (validation/cfd/rateLayer.md)")
    ap.add_argument("--face-viscosity", action="store_true",
                    help="cfdDict faceViscosity yes: the slide's viscosity on each face at the face's own strain rate "
                    "instead of the mean of the two cells' (validation/cfd/rateLayer.md)")
    ap.add_argument("--outer-correctors", action="store_true",
                    help="cfdDict outerCorrectors 3: PIMPLE's outer correctors converge each step's momentum, which "
                    "one SIMPLEC step loses in a flowing slurry (validation/cfd/README.md, \"The step's momentum\")")
    ap.add_argument("--whole-face", action="store_true",
                    help="a frictional base's s_b on every face whose cell holds slide (cfdDict baseStrength wholeFace, "
                         "slideFoam's only base until session 90), not on the slide's share of each face")
    ap.add_argument("--transpose-mean", action="store_true",
                    help="a slipping base takes out the explicit transpose flux's normal traction and running mean "
                         "(cfdDict transposeShear runningMean), not only near a polyline's kinks")
    ap.add_argument("--slide-trace", action="store_true",
                    help="a frictional base's faces under less than 1e-4 of slide held as the ambient's (cfdDict "
                         "baseSlideTrace 1e-4; the solver's default 1e-3: validation/cfd/README.md, \"Where the "
                         "front's stress starts\")")
    ap.add_argument("--no-slide-trace", action="store_true",
                    help="a frictional base's s_b on the slide's share of every face, down to none (cfdDict "
                         "baseSlideTrace 0): the solver's default until session 98")
    ap.add_argument("--top", choices=["open", "slip"], default=None,
                    help="the mesh's top (cfdDict top; default open): slip closes it with a lid that keeps the spray "
                    "a fast thin head throws into the light ambient (Case 4) in the domain")
    ap.add_argument("--replot", action="store_true", help="rewrite table1.md and table1.png from table1.json, "
                    "running nothing")
    ap.add_argument("--continue", dest="cont", metavar="CASE_DIR",
                    help="run a kept case of an earlier run (its work directory, e.g. /tmp/slideFoam_table1_*/"
                    "case04_H0_20) on from its latest time to --end-time, and replace its row (legs and wall times "
                    "summed); a leg already run by hand to there is collected")
    args = ap.parse_args()
    cells = [int(v) for v in args.cells.split(",")]
    cases = [] if args.replot or args.cont else [int(v) for v in args.cases.split(",")]
    args.keep = args.keep or args.replot or bool(args.cont)
    if args.rate_free and cases != [1]:
        raise SystemExit("table1.py: --rate-free is Case 1's strength without the rate term: --cases 1 only")
    if args.wall_function:
        # slideFoamCase refuses it there; said before any case runs, so that no failed row is stored for it.
        refused = [c for c in cases if args.rate_free or not wall_function_acts(c)]
        if refused:
            raise SystemExit("table1.py: --wall-function acts on a no-slip base under Eq. (1)'s rate term; Cases %s "
                             "have no rate term or another base" % ", ".join(map(str, refused)))
    paper = paper_table()
    work = tempfile.mkdtemp(prefix="slideFoam_table1_")
    results = []
    if args.cont:
        if args.end_time is None:
            raise SystemExit("--continue needs --end-time")
        results.append(continue_case(args.cont, args.end_time, args.processors,
                                     json.load(open(os.path.join(here, "table1.json"))), args.ambient_relaxation))
    for c in cases:
        for n in cells:
            mesh = dict({key: getattr(args, key) for key, _, _ in CFD_ENTRIES},
                        **{key: getattr(args, key) for key, _, _, _ in SWITCHES},
                        refinement=args.base_refinement, max_co=args.max_co, max_delta_t=args.max_delta_t,
                        top=args.top)
            r = run_case(c, n, args.processors, work, mesh, args.scene_end)
            results.append(r)
            print(json.dumps({k: v for k, v in r.items() if k != "history"}), flush=True)
    if args.keep and os.path.exists(os.path.join(here, "table1.json")):
        # Earlier runs of other case/mesh pairs stay in the table.
        done = {row_key(r) for r in results}
        results = [r for r in json.load(open(os.path.join(here, "table1.json"))) if row_key(r) not in done] + results
        results.sort(key=row_key)
    json.dump(results, open(os.path.join(here, "table1.json"), "w"), indent=1)

    lines = ["# slideFoam: the CFD column of Table 1", "",
             "Regenerated by `validation/cfd/table1.py` on a 2-core machine. Runout: front (alpha 0.5 on the base) from",
             "the initial front at rest or at the case's end time. Error against the paper's CFD (Fluent) where it",
             "gives one; the aim (issue) is within 12 %.", "",
             "Mechanism: read off the slide's cells (alpha >= 0.1, each the layer alpha times its height on its",
             "floor) by the classifier slideMPM uses on its particles",
             "(`src/output/runoutMechanism.H`), at the end (while moving) or the one seen at most writes (at rest);",
             "\"-\": a run made before slideFoam detected it.", "",
             "| case | mesh | cells | paper CFD [m] | slideFoam [m] | error | mechanism | at rest | end [s] | front speed "
             "at end [m/s] | volume change | slideDAM [m] | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    def paper_cfd(r):
        # Without the rate term it is another slide: the paper has no runout for it.
        return None if r.get("rate_free") else paper[r["case"]][1].get("CFD")
    for r in results:
        cfd = paper_cfd(r)
        mesh = "H0/%d" % r["cells"] + (" (H0/%d on the base)" % base_cells(r) if r["refinement"] > 1
                                       else "")
        if r.get("ahead_height"):
            mesh += ", %g H0 high ahead" % r["ahead_height"]
            if r.get("ahead_from") is not None:
                mesh += " from %g m" % r["ahead_from"]
        if r.get("reach"):
            mesh += ", %.0f m ahead" % r["reach"]
        if r.get("behind"):
            mesh += ", %g m behind" % r["behind"]
        if r.get("max_co"):
            mesh += ", maxCo %g" % r["max_co"]
        if r.get("max_delta_t"):
            mesh += ", maxDeltaT %g s" % r["max_delta_t"]
        if r.get("top") == "slip":
            mesh += ", lid on top"
        if r.get("ambient_relaxation_steps"):
            mesh += ", ambient relaxed to rest in " + ", ".join("%g s from %g s" % (tau, t0)
                                                               for t0, tau in r["ambient_relaxation_steps"])
        legs = r.get("legs", [])
        if len(legs) > 1:
            mesh += ", restarted at %s" % ", ".join(
                "%g s" % b[0] + (" on a longer mesh of %d cells" % b[3] if len(b) > 3 and len(a) > 3 and b[3] != a[3]
                                 else "") for a, b in zip(legs, legs[1:]))
        mesh += counting(r)
        if "failed" in r:
            lines.append("| %d | %s | | %s | failed: %s | | | | | | | | |"
                         % (r["case"], mesh, cfd or "-", r.get("reason") or "see the run's log"))
            continue
        err = "%+.1f %%" % (100*(r["runout"]/cfd - 1)) if cfd else "-"
        rest = ("yes" if r["at_rest"] else "no") + unresolved_note(r)
        lines.append("| %d | %s | %d | %s | %.1f | %s | %s | %s | %.0f | %.2g | %.1e | %.1f | %.0f |"
                     % (r["case"], mesh, r["n"], cfd or "-", r["runout"], err, r.get("mechanism") or "-", rest,
                        r["end_time"], r["front_velocity"], r["volume_change"], r["dam_runout"], r["wall"]))
    open(os.path.join(here, "table1.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 4))
    ok = [r for r in results if "failed" not in r]
    def mesh_label(r):
        # The base's cells where another row of the case has the same cells above them.
        twins = [o for o in ok if (o["case"], o["cells"]) == (r["case"], r["cells"]) and base_cells(o) != base_cells(r)]
        return "H0/%d%s%s" % (r["cells"], ", H0/%d base" % base_cells(r) if twins else "", counting(r))
    labels = ["C%d %s" % (r["case"], mesh_label(r)) for r in ok]
    xs = range(len(ok))
    ax[0].bar([x - 0.2 for x in xs], [paper_cfd(r) or 0 for r in ok], 0.4, label="paper CFD")
    ax[0].bar([x + 0.2 for x in xs], [r["runout"] for r in ok], 0.4, label="slideFoam")
    ax[0].set_xticks(list(xs))
    ax[0].set_xticklabels(labels, rotation=60, ha="right", fontsize=7)
    ax[0].set_ylabel("runout [m]")
    ax[0].set_yscale("log")
    ax[0].legend()
    for r in ok:
        h = r["history"]
        ax[1].plot([p[0] for p in h], [p[1] for p in h], label="Case %d %s" % (r["case"], mesh_label(r)))
    ax[1].set_xlabel("time [s]")
    ax[1].set_ylabel("front travel [m]")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "table1.png"), dpi=110)


if __name__ == "__main__":
    main()
