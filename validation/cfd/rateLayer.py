#!/usr/bin/env python3
"""What base cell Eq. (1)'s rate term needs: an infinite layer of Table 1 Case 1's slide (s_uo 150 Pa, eta 0.35,
n 0.15, gdot_ref 0.06 1/s, rho' 600, 3.43 deg) in steady flow on a no-slip base, run by slideFoam as one column of
cells with cyclic ends under a frictionless lid, against its exact profile.

In a steady layer of depth h the shear stress is tau(z) = w (h - z), w = rho' g S, S = sin(theta). Below the yield
height z_y = h - s_uo/w Eq. (1) gives the rate gdot = gdot_ref (x/eta)^(1/n), x = tau/s_uo - 1, and

    u(z) = A [x_b^m - x(z)^m],   A = gdot_ref s_uo/w eta^(-1/n) n/(n + 1),   m = (n + 1)/n,

with x_b = w h/s_uo - 1 at the base; above z_y the plug moves at u(z_y) = A x_b^m. At n = 0.15 the rate falls off
upwards from the base over l = n (tau_b - s_uo)/w, a few centimetres for the layers Case 1 runs and stops as
(validation/cfd/README.md, "Why the rate term needs cells so thin"). slideFoam regularises the plug by capping the
apparent viscosity (cfdDict regularisation cap, muMax from plugCreepRate): below the rate where s_u/gdot reaches
muMax the material creeps at tau/muMax, so its exact profile differs from Eq. (1)'s by that creep; both are given,
the capped one by quadrature, and the runs converge to the capped one.

The layer has no ambient over it (none matters to an infinite layer); its along-slope weight is a body force
(src/slideFoamModels/alongSlopeGravity), the excess of its density over the scene's light ambient (1 kg/m3), and
gravity's part normal to the base stays with p_rgh. Each run: uniform cells of h/N through the layer (--cells),
started at rest, run to --end-time (by default twelve of the exact layer's relaxation times rho' h U/(n (tau_b -
s_uo))); the plug speed is the mean of the cells above the yield height, read at each quarter of the run (how
steady it is). Writes rateLayer.md and rateLayer.json beside itself.

Usage: validation/cfd/rateLayer.py [--depths 0.65,0.85] [--cells 4,8,16,32,64,128] [--end-time T] [--work DIR]
       [--keep]   (after ./Allwmake)"""
import argparse
import json
import math
import os
import re
import shutil
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(top, "validation", "lib"))
from cfdcase import make_case, read_field, run, time_dirs  # noqa: E402
from runner import which  # noqa: E402
from layerProfile import ETA, G, GDOT_REF, N_HB, RHO, S, S_UO, THETA, capped_profile, exact  # noqa: E402

import numpy as np  # noqa: E402

TEMPLATE = os.path.join(top, "tutorials", "table1", "case01")
LENGTH = 1.0          # the column's width along the slope [m]; the flow is uniform along it


def mu_max_of(case):
    text = open(os.path.join(case, "constant", "transportProperties")).read()
    return float(re.search(r"^\s*muMax\s+([^;\s]+);", text, re.M).group(1))


def block_mesh(h, cells, ambient=0.0):
    """One column: `cells` uniform cells through the layer and, with ambient > 0, as many of the same size as fill
    that much light ambient over it (a jump of the cell size at the interface spiked the ambient); the lid on top."""
    d = h/cells
    na = int(round(ambient/d))
    top = h + na*d
    blocks = "    hex (0 1 2 3 4 5 6 7) (1 %d 1) simpleGrading (1 1 1)\n" % cells
    if na:
        blocks += "    hex (3 2 8 9 7 6 10 11) (1 %d 1) simpleGrading (1 1 1)\n" % na
    lid = "(9 11 10 8)" if na else "(3 7 6 2)"
    ends = ("(0 4 7 3) (3 7 11 9)", "(1 2 6 5) (2 8 10 6)") if na else ("(0 4 7 3)", "(1 2 6 5)")
    empty = "(0 3 2 1) (4 5 6 7)" + (" (3 9 8 2) (7 6 10 11)" if na else "")
    L = LENGTH
    return """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
// One column of an infinite layer (validation/cfd/rateLayer.py): cyclic ends, %d uniform cells through the slide,
// %d of light ambient over it, a frictionless lid on top.
scale 1;
vertices
(
    (0 0 0) (%g 0 0) (%g %g 0) (0 %g 0)
    (0 0 0.1) (%g 0 0.1) (%g %g 0.1) (0 %g 0.1)
    (%g %g 0) (0 %g 0) (%g %g 0.1) (0 %g 0.1)
);
blocks
(
%s);
boundary
(
    base { type wall; faces ((0 1 5 4)); }
    lid { type patch; faces (%s); }
    upslope { type cyclic; neighbourPatch downslope; faces (%s); }
    downslope { type cyclic; neighbourPatch upslope; faces (%s); }
    frontAndBack { type empty; faces (%s); }
);
""" % (cells, na, L, L, h, h, L, L, h, h, L, top, top, L, top, top, blocks, lid, ends[0], ends[1], empty)


# The lid: no stress along it, no flow through it, the pressure fixed there (the free surface's).
LID = {"U": "type slip;", "p_rgh": "type fixedValue; value uniform 0;", "alpha.slide": "type zeroGradient;",
       "xi": "type zeroGradient;"}


def layer_fields(path, field, alpha=None):
    """The generated field with the layer's patches: its base as generated, the lid, cyclic ends; alpha.slide's
    internal field `alpha` (a list over the cells)."""
    text = open(path).read()
    start = text.index("boundaryField")
    body = text[start:]
    entries = re.findall(r'^    ("?[\w|()]+"?)\s*\n    \{(.*?)^    \}', body, re.M | re.S)
    out = ["boundaryField\n{\n"]
    for name, inner in entries:
        names = name.strip('"').strip("()").split("|")
        for patch in ("base", "frontAndBack"):
            if patch in names:
                out.append("    %s\n    {%s    }\n" % (patch, inner))
    out.append("    lid\n    {\n        %s\n    }\n" % LID[field])
    out.append("    \"(upslope|downslope)\"\n    {\n        type cyclic;\n    }\n}\n")
    head = text[:start]
    if field == "alpha.slide":
        values = "nonuniform List<scalar> %d\n(\n%s\n)" % (len(alpha), "\n".join("%g" % a for a in alpha))
        head = re.sub(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(.*?\n\)\s*;",
                      lambda m: "internalField   %s;" % values, head, count=1, flags=re.S)
    open(path, "w").write(head + "".join(out))


def ambient_density(case):
    text = open(os.path.join(case, "constant", "transportProperties")).read()
    return float(re.search(r"^ambient\s*\{[^}]*?\brho\s+([^;\s]+);", text, re.M | re.S).group(1))


def run_layer(h, cells, end_time, work, material=None, name=None, ambient=0.0, wall_function=False,
              face_viscosity=False):
    """slideFoam's run of the layer (Case 1's material, or `material`'s entries instead; `ambient` m of the scene's
    light ambient over it); its cell centres' heights and the velocity along the slope at each write."""
    name = name or "layer_h%g_N%d" % (h, cells)
    case = make_case(TEMPLATE, work, name,
                     scene=dict({"length": LENGTH, "height": h, "rearPosition": 0}, **(material or {})),
                     control={"endTime": end_time, "writeInterval": end_time/4, "stopAtRest": "no"},
                     cfd=dict({"cellsPerHeight": 4, "reach": 1, "behind": 1},
                              **({"rateWallFunction": "yes"} if wall_function else {}),
                              **({"faceViscosity": "yes"} if face_viscosity else {})))
    run(case, which("slideFoamCase"), "-case", ".")
    open(os.path.join(case, "system", "blockMeshDict"), "w").write(block_mesh(h, cells, ambient))
    # Gravity split: p_rgh carries the part normal to the base, a body force the part along it (a cyclic
    # p_rgh cannot carry that; src/slideFoamModels/alongSlopeGravity).
    gpath = os.path.join(case, "constant", "g")
    text = open(gpath).read()
    text = re.sub(r"^value\s+\(([^)]*)\);", "value           (0 %.10g 0);" % (-G*math.cos(math.radians(THETA))),
                  text, count=1, flags=re.M)
    open(gpath, "w").write(text)
    with open(os.path.join(case, "constant", "fvOptions"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }\n"
                "alongSlope\n{\n    type alongSlopeGravity;\n    acceleration (%.10g 0 0);\n}\n" % (G*S))
    run(case, "blockMesh")
    run(case, "postProcess", "-func", "writeCellCentres", log="log.writeCellCentres")
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    y = read_field(case, "constant", "C")[:, 1]
    for f in ("U", "p_rgh", "alpha.slide", "xi"):
        shutil.copy(os.path.join(case, "0.orig", f), os.path.join(case, "0", f))
        layer_fields(os.path.join(case, "0", f), f, np.where(y < h, 1.0, 0.0))
    t0 = time.time()
    run(case, which("slideFoam"))
    wall = time.time() - t0
    times = [t for t in time_dirs(case) if float(t) > 0]
    plugs = []
    rho_ambient = ambient_density(case)
    for t in times:
        u = read_field(case, t, "U")[:, 0]
        plugs.append((float(t), u))
    return {"depth": h, "cells": cells, "cell": h/cells, "y": y, "history": plugs, "wall": wall,
            "rho_ambient": rho_ambient, "mu_max": mu_max_of(case),
            "capped": capped_profile(h, rho_ambient, mu_max_of(case), material), "case": case}


def summarise(r, ex):
    """Plug speed (mean above the yield height) at each write, errors against the exact profile and against the
    capped one (the same mean of it over the run's cells)."""
    y = r["y"]
    slide = y < r["depth"]
    plug = slide & (y > ex["yield_height"])
    t, u = r["history"][-1]
    capped = r["capped"](y)
    base = np.argmin(y)
    return dict(r, cell_over_l=r["cell"]/ex["decay_length"], exact_plug=ex["plug"],
                capped_plug=float(capped[plug].mean()),
                plugs=[(tt, float(uu[plug].mean())) for tt, uu in r["history"]],
                plug=float(u[plug].mean()), time=t,
                rms_error=float(np.sqrt(np.mean((u[slide] - capped[slide])**2))),
                wall_cell=float(u[base]), wall_cell_capped=float(capped[base]))


def write_report(rows, args):
    suffix = (("Ambient" if args.ambient else "") + ("WallFunction" if args.wall_function else "")
              + ("FaceViscosity" if args.face_viscosity else ""))
    md = os.path.join(here, "rateLayer%s.md" % suffix)
    with open(md, "w") as f:
        f.write("# What base cell Eq. (1)'s rate term needs: Case 1's slide as a steady infinite layer\n\n")
        f.write("Regenerated by `validation/cfd/rateLayer.py --depths %s --cells %s%s%s`. An infinite layer of Table 1 "
                "Case 1's material (s_uo %g Pa, eta %g, n %g, gdot_ref %g 1/s, rho' %g kg/m3, %g deg) on a no-slip "
                "base under a frictionless lid%s: slideFoam on one column with cyclic ends, uniform cells of h/N "
                "through the layer, started at rest, run to %s. Its along-slope drive is its excess over the scene's "
                "light ambient (rho' - %g kg/m3, `alongSlopeGravity`), and the exact profile is of that drive "
                "(`rateLayer.py`'s docstring). l = n (tau_b - s_uo)/(rho' g S): the height over which the rate falls "
                "by e above the base. Plug: the mean speed of the cells above the yield height.\n\n"
                % (args.depths, args.cells, " --ambient %g" % args.ambient if args.ambient else "",
                   (" --wall-function" if args.wall_function else "")
                   + (" --face-viscosity" if args.face_viscosity else ""), S_UO, ETA, N_HB,
                   GDOT_REF, RHO, THETA,
                   " with %g m of the scene's light ambient between them (cells of the layer's size)" % args.ambient
                   if args.ambient else "",
                   "%g s" % args.end_time if args.end_time else "twelve of the exact layer's relaxation times "
                   "(at least 20 s)", rows[0]["rho_ambient"]))
        for h in sorted({r["depth"] for r in rows}):
            mine = sorted((r for r in rows if r["depth"] == h), key=lambda r: r["cells"])
            ex = exact(h, mine[0]["rho_ambient"])
            f.write("## h = %g m: tau_b = %.1f Pa, yield height %.3f m, l = %.2f cm, basal rate %.3g 1/s, plug "
                    "%.4g m/s, relaxation time %.2g s\n\n" % (h, (RHO - mine[0]["rho_ambient"])*G*S*h,
                                                             ex["yield_height"], 100*ex["decay_length"],
                                                             ex["basal_rate"], ex["plug"], ex["relaxation_time"]))
            f.write("| N | cell [cm] | cell / l | plug at the end [m/s] | against Eq. (1) | against Eq. (1) capped | "
                    "plug at each quarter of the run [m/s] | RMS profile error / capped plug | wall cell's speed / "
                    "capped there | wall [s] |\n")
            f.write("|---|---|---|---|---|---|---|---|---|---|\n")
            for r in mine:
                s = summarise(r, ex)
                f.write("| %d | %.2f | %.2f | %.4g | %+.1f %% | %+.1f %% | %s | %.3f | %.3f | %.0f |\n"
                        % (s["cells"], 100*s["cell"], s["cell_over_l"], s["plug"], 100*(s["plug"]/ex["plug"] - 1),
                           100*(s["plug"]/s["capped_plug"] - 1), ", ".join("%.4g" % p for _, p in s["plugs"]),
                           s["rms_error"]/s["capped_plug"], s["wall_cell"]/s["wall_cell_capped"], s["wall"]))
            f.write("\nExact plug %.4g m/s; with the cap (muMax %.6g Pa s) %.4g m/s at the top, %.4g m/s averaged "
                    "over the finest run's cells above the yield height.\n" % (ex["plug"], mine[-1]["mu_max"],
                                                                                float(mine[-1]["capped"](h)),
                                                                                summarise(mine[-1], ex)["capped_plug"]))
            f.write("\n")
    keep = ("depth", "cells", "cell", "cell_over_l", "plug", "plugs", "exact_plug", "capped_plug", "rms_error",
            "wall_cell", "wall_cell_capped", "time", "wall", "rho_ambient", "mu_max")
    out = []
    for r in rows:
        s = summarise(r, exact(r["depth"], r["rho_ambient"]))
        out.append({k: s[k] for k in keep})
    with open(os.path.join(here, "rateLayer%s.json" % suffix), "w") as f:
        json.dump(out, f, indent=1)
    print("wrote", md)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--depths", default="0.65,0.85")
    p.add_argument("--cells", default="4,8,16,32,64,128")
    p.add_argument("--end-time", type=float, default=0.0,
                   help="[s]; 0: twelve relaxation times of each layer (the exact one's), at least 20 s")
    p.add_argument("--ambient", type=float, default=0.0,
                   help="[m] of the scene's light ambient over the layer (0: none, the lid on the layer)")
    p.add_argument("--wall-function", action="store_true",
                   help="cfdDict rateWallFunction yes: the base's stress from Eq. (1)'s profile through the wall cell")
    p.add_argument("--face-viscosity", action="store_true",
                   help="cfdDict faceViscosity yes: the slide's viscosity on each face at the face's own strain rate")
    p.add_argument("--work", default="")
    p.add_argument("--keep", action="store_true")
    args = p.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="rateLayer")
    os.makedirs(work, exist_ok=True)
    rows = []
    for h in [float(x) for x in args.depths.split(",")]:
        end = args.end_time or max(20.0, round(12*exact(h)["relaxation_time"]))
        for n in [int(x) for x in args.cells.split(",")]:
            r = run_layer(h, n, end, work, ambient=args.ambient, wall_function=args.wall_function,
                          face_viscosity=args.face_viscosity)
            s = summarise(r, exact(h, r["rho_ambient"]))
            print("h %g m, N %d: plug %s m/s (exact %.4g, capped %.4g), %.1f s wall"
                  % (h, n, ", ".join("%.4g at %g s" % (p, t) for t, p in s["plugs"]), s["exact_plug"],
                     s["capped_plug"], r["wall"]),
                  flush=True)
            rows.append(r)
    write_report(rows, args)
    if not args.keep and not args.work:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
