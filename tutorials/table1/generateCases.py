#!/usr/bin/env python3
"""Writes the 13 case directories of Table 1 (Dong, Wang & Cui 2020) from the
cleaned table (table1.csv): L0 = 40 m, H0 = 5 m, rho' = 600 kg/m3, a
rectangular slide released at rest on a planar base. Run once; the cases are
committed. Usage: generateCases.py [path/to/table1.csv]"""
import csv
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
table = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "../../../shared/reference/table1.csv")

# End times: long enough for the slowest slide to come to rest (Case 4/5 run for
# kilometres), and the paper's snapshot times where the slide does not stop (Case 9
# accelerates on its weak base) or where its rest is out of reach: Case 11's wholly
# remoulded layer (s_uo delta_rem = 125 Pa) runs 2.3 km in slideDAM, at rest by 204 s,
# as far as Case 4's, which the CFD does not follow to rest here. Case 12 (250 Pa
# remoulded) runs to rest, slideDAM by 65 s (session 75).
end_times = {1: 400, 2: 200, 3: 600, 4: 2000, 5: 3000, 6: 100, 7: 100, 8: 100, 9: 20, 10: 2000,
             11: 30, 12: 200, 13: 3000}

header = """/*--------------------------------*- C++ -*----------------------------------*\\
  SlideFoam scene: Table 1, Case {case} of Dong, Wang & Cui (2020).
  Written by tutorials/table1/generateCases.py from table1.csv.
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      {obj};
}}

"""


ALLRUN = """#!/bin/bash
# Table 1 Case {case}: slideDAM, slideMPM and slideFoam (those built), each logging to
# log.<application>, then the comparison (postProcessing/comparison/).
cd "${{0%/*}}" || exit 1
[ -n "${{SLIDEFOAM_DIR:-}}" ] || . ../../../etc/bashrc
. "$SLIDEFOAM_DIR/bin/tools/RunFunctions"
runAllMethods
"""

CFDDICT = """// Cells of H0/10 = 0.5 m; the mesh reaches 1.3 x slideDAM's runout + 2 H0 ahead
// of the front and 1.3 x its upslope spreading + 2 H0 behind the rear (slideDAM
// runs first in Allrun). "setting reference" is H0/60, the paper's flume mesh:
// 36 times the cells, far too many at this scale on a few cores.
// The deposits of the weak cases thin to 0.5-1 m, one or two such cells: on the
// base the cells are 4 times thinner (H0/40), graded up to H0/10 (Case 1 ran
// past 409 m with uniform H0/10 cells and stopped at 341 m with this grading).
setting         fast;
cellsPerHeight  10;
baseRefinement  4;
"""

DAMDICT = """// 800 columns with the adaptive time step: converged in columns for these cases
// (validation/dam/README.md). "setting reference" is the paper's 4000 columns with
// dt = 0.001 sqrt(b/g): minutes to hours here.
setting     fast;
columns     800;
"""

MPMDICT = """// Cell H0/10 with the paper's 4 x 4 particles (12,800 particles): a minute or
// two per case. With 2 x 2 the particles crowd into the cell on the base of a
// thin, fast layer (Case 1: 20 % over-full by 20 s, and 215 m instead of 287 m;
// validation/mpm/README.md). "setting reference" is the paper's H0/60
// with 4 x 4 (460,800 particles): hours here. The error of this setting against
// finer ones is measured in validation/mpm (README there).
setting          fast;
cellsPerHeight   10;
particlesPerCell 4;
writeFields      yes;
// Restart states of the last 2 writes only: a state holds every particle (about
// 550 bytes each, 250 MB at "setting reference"), and a case writes one a second.
purgeState       2;
"""

# Cases with remoulding: xi counts bands of the paper's cell, H0/60 (validation/mpm/shearBand.md).
MPMBAND = """// Eq. (1)'s remoulding acts in shear bands, as thin as the cells that carry them:
// the paper's MPM had cells of H0/60 = 0.083 m and its xi95 counts their strain.
// Here xi counts the strain of a band that thin in each 0.5 m cell (band strain
// = 6 x cell strain), so a band remoulds at the same slip whatever the cell;
// without it, finer cells remould sooner (validation/mpm/shearBand.md).
shearBandThickness 0.0833333;
"""

# The same counting in slideFoam (validation/cfd/shearBand.md).
CFDBAND = """// Remoulding counted per shear band of the paper's MPM cell, H0/60, as slideMPM
// does (mpmDict): band strain = 6 x cell strain in the 0.5 m cells, 1.5 x on the
// base's 0.125 m cells (validation/cfd/shearBand.md).
shearBandThickness 0.0833333;
"""

# Case 11 moves by shear bands in its body, which a 0.5 m cell cannot hold apart.
MPMFINE = """// At this cell the slide moves as one remoulded layer. Its horsts and grabens
// (the paper's Fig. 8) need cells of H0/40 (validation/mpm/shearBand.md):
//     cellsPerHeight 40; particlesPerCell 2;    (103,000 particles, 12 min on 2 cores)
"""

ALLCLEAN = """#!/bin/bash
cd "${{0%/*}}" || exit 1
[ -n "${{SLIDEFOAM_DIR:-}}" ] || . ../../../etc/bashrc
. "$SLIDEFOAM_DIR/bin/tools/RunFunctions"
cleanCase
"""


def num(s):
    return float(s) if s.strip() else None


def fmt(x):
    return ("%.6g" % x)


# What the paper shows of each case beyond its runout (its Figs. 7-10).
SHOWS = {2: "the profile at 10 s (Fig. 7)", 9: "block sliding at 20 s: ~200 m, ~12 m/s, thickness near H_stability = 3.4 m, "
         "against ~350 m for the original DAM algorithm (Fig. 9)",
         11: "spreading with horsts and grabens by 10 s and a front wedge breaking away by 30 s (MPM, Fig. 8)",
         12: "a shear band along the base (MPM)"}


def readme(case, row, paper):
    """The case's README: what it is, what the paper found, what each method can show."""
    strength = "s_uo %s kPa" % row["s_uo_kPa"]
    if num(row["eta"]):
        strength += ", eta %s, n %s, gdot_ref %s 1/s" % (row["eta"], row["n"], row["gdot_ref"])
    if (num(row["delta_rem"]) or 1.0) < 1:
        strength += ", delta_rem %s, xi95 %s" % (row["delta_rem"], row["xi95"])
    base = "no-slip" if row["base"] != "frictional" else "frictional, s_b %s kPa" % row["s_b_kPa"]
    lines = ["# Table 1, Case %d" % case, "",
             "A 40 m x 5 m slide (rho' = 600 kg/m3) released at rest on a %s deg planar base (%s); %s." % (
                 row["theta_deg"], base, strength), "",
             "- Paper: %s; runout %s." % (row["mechanism"], paper or "not given")]
    if case in SHOWS:
        lines.append("- The paper also shows %s." % SHOWS[case])
    if (num(row["delta_rem"]) or 1.0) < 1:
        lines.append("- slideMPM and slideFoam count the remoulding strain xi per shear band of the paper's MPM cell, "
                     "H0/60 (`shearBandThickness` in `system/mpmDict` and `cfdDict`): Eq. (1) has no length scale, "
                     "and counted per cell the remoulding depends on the cell (`validation/mpm/shearBand.md`, "
                     "`validation/cfd/shearBand.md`).")
    if case == 11:
        lines.append("- slideMPM at this tutorial's cell, H0/10, moves the slide as one remoulded layer. With "
                     "`cellsPerHeight 40; particlesPerCell 2;` in `system/mpmDict` (12 minutes on 2 cores) it parts "
                     "into horsts and grabens by 10 s, as the paper's Fig. 8 shows: `validation/snapshots/snapshots.png`, "
                     "`validation/mpm/shearBand.md`.")
    if case == 11:
        lines.append("- The scene ends at 30 s, the paper's snapshot. slideDAM runs the wholly remoulded layer (125 Pa) on to "
                     "rest by 204 s, 2.3 km out, as far as Case 4 and beyond what slideFoam can follow here.")
    if case == 12:
        lines.append("- Runs to rest (200 s at most; the scene ended at 40 s until session 75). Its remoulded strength, "
                     "250 Pa, holds 0.71 m on this slope, so the front runs out as a thinner sheet. slideDAM stops it at "
                     "439 m by 65 s, and at 428 m with its step converged (`columns 3200; courant 0.125;` in "
                     "`system/damDict`: `validation/dam/sheetStability.md`). slideFoam at this case's cfdDict stops its front at 389 m, but the sheet's thin tip "
                     "jitters on to 200 s; with `maxDeltaT 0.01;` in `system/controlDict` it comes to rest at 418 m by "
                     "78 s. slideMPM at this case's H0/10 stops it at 278 m. Its particles crowd the cell on the base "
                     "there; with `particleShifting 0.03;` in `system/mpmDict` it runs 381 m (426 m at H0/20). The "
                     "CFD's and the MPM's runouts of this sheet are not converged in their cells: `validation/README.md`, "
                     "\"Case 12 run to rest\".")
    if case == 3:
        lines.append("- The paper's s_uo for this case is garbled; `table1.csv` reads it as 1 kPa, an inference. At 1 kPa "
                     "the three methods run 21.0-23.6 m and still creep at 100 s (their deposits, 3.5-3.7 m, are thicker "
                     "than the 2.84 m that s_uo holds on this slope); each reaches the paper's runout at s_uo 1.07-1.17 "
                     "kPa (`validation/case3/strength.md`).")
    if case == 4:
        lines.append("- slideFoam does not reach the end of this case: its layer, 0.3-0.7 m thick at 12-19 m/s, grows a head "
                     "that throws material into the light ambient, and the run stops at 33-42 s with the error that "
                     "0.1 % of the slide has left through the mesh's top, on every mesh tried up to H0/20. With "
                     "`top slip;` in `system/cfdDict` (a lid) it runs on, but the layer thins towards its yield "
                     "thickness, 0.14 m: on 0.25 m base cells it runs on unresolved (2410 m, still 10.6 m/s at 193 s), "
                     "and with H0/20 and 0.125 m base cells the front stalls twice (1331 m at 119-170 s, 1682 m at "
                     "233-250 s) over a deposit at rest at about its yield thickness, and surges of the last thick slide "
                     "carry it on: 1897.5 m at 330 s, on a mesh carried on to 2400 m by "
                     "`bin/tools/extendSlideMesh`. The slide is at rest there, but the light ambient keeps circulating "
                     "under the lid (4.7 m/s mean). With `ambientRelaxationTime 2;` in `system/cfdDict` from 336 s "
                     "the circulation dies out; at 375, 379 and 380 s every slide cell is slower than 5 mm/s (up to 0.2 m/s "
                     "between: its half-cell stretches are stirred on and off), with the front "
                     "at 1887.5 m. The run's rest test still fails on material smeared below alpha 0.5 beyond the "
                     "front (`validation/cfd/README.md`, \"Case 4\"). slideDAM and slideMPM run it to rest.")
    if case == 5:
        lines.append("- slideFoam on this case (slideDAM's 7.5 km, at rest by 418 s) needs a mesh several kilometres long: "
                     "about 4 times Case 4's cells, hours on a few cores. Its first 30 s have been run (42,530 cells, "
                     "508 s on 2 ranks, `top slip;`): the front is at 813 m at 30 s, within 2.7 % of slideMPM's "
                     "foremost particle at 10, 20 and 30 s and 17-20 % behind slideDAM (`validation/cfd/README.md`, "
                     "\"Case 4\", where Case 5 follows).")
    if case in (4, 5):
        lines.append("- slideDAM warns at the end that the front surged: its thin sheet stalls and is overrun by thicker "
                     "parts of the body behind it, and the runout is then one draw from a spread. With a few columns "
                     "more or fewer (`columns` in `system/damDict`) it moves by %s around a mean that grows with the "
                     "columns (`validation/dam/timeSchemes.md`)." % ("2-4 %" if case == 4 else "3-10 %"))
    if case in (6, 7):
        lines.append("- slideMPM and slideFoam stop this slide at 1.5-1.9 m where the paper has 7.9-8.7 m: Eq. (1)'s "
                     "rate effect strengthens a collapsing face (s_u 1.86 s_uo at 1 1/s) and it stands again. Without "
                     "it (`eta 0;` in `constant/sceneProperties`) they give 4.4-4.9 m, still short "
                     "(`validation/mpm/rateEffect.md`, `validation/cfd/README.md`).")
    if case == 8:
        lines.append("- A sensitive case. The block slides on s_b = 1.8 kPa, less than its drive (2.6 kPa at 5 m), "
                     "until its contact with the base is longer than its weight along the slope over s_b, 57 m; how "
                     "fast it stretches decides the runout. slideFoam (the base's s_b on the slide's share of each face): 145.1 m at 100 s at H0/10, "
                     "128-133 m at H0/20, 136-178 m with its plug-momentum options (on the whole face 112.6, 127.0 and "
                     "68-91 m); slideMPM's block stays shorter than 57 m and slides on "
                     "(557 m at 100 s); slideDAM 47 m. Without Eq. (1)'s rate effect (`eta 0;` in "
                     "`constant/sceneProperties`) slideFoam stops it at 34.6 m (32.8 m at H0/20) and slideMPM at 33.9 m, the paper's "
                     "30-35 m (`validation/cfd/frictionalBlock.md`).")
    if "spreading" in row["mechanism"] or "shear band" in row["mechanism"]:
        lines.append("- slideDAM runs this case but cannot show it: one velocity profile per column has no shear band, "
                     "no horsts and grabens and no breakaway; the comparison says so.")
    lines += ["- `./Allrun`: slideDAM, slideMPM and slideFoam (`log.<application>`), then `compareMethods` writes "
              "`postProcessing/comparison/comparison.md` and `histories.png`.",
              "- Settings: `system/damDict`, `mpmDict`, `cfdDict` (fast by default; `setting reference` for the "
              "paper's). The Table 1 comparison of all cases: `validation/README.md`.", ""]
    return "\n".join(lines)


rows = [r for r in csv.reader(line for line in open(table) if not line.startswith("#"))]
names = rows[0]
for r in rows[1:]:
    row = dict(zip(names, r))
    case = int(row["case"])
    d = os.path.join(here, "case%02d" % case)
    os.makedirs(os.path.join(d, "constant"), exist_ok=True)
    os.makedirs(os.path.join(d, "system"), exist_ok=True)
    eta = num(row["eta"]) or 0.0
    n = num(row["n"])
    gref = num(row["gdot_ref"])
    drem = num(row["delta_rem"]) or 1.0
    xi95 = num(row["xi95"])
    rheo = ["    model    HerschelBulkleyRemoulding;   // Eq. (1)",
            "    s_uo     %s;%s// [Pa]" % (fmt(1000 * num(row["s_uo_kPa"])), " " * 10),
            "    eta      %s;" % fmt(eta)]
    if eta > 0:
        rheo += ["    n        %s;" % fmt(n), "    gdotRef  %s;              // [1/s]" % fmt(gref)]
    rheo += ["    deltaRem %s;" % fmt(drem)]
    if drem < 1:
        rheo += ["    xi95     %s;" % fmt(xi95)]
    base = ["    profile   planar;", "    angle     %s;            // [deg]" % fmt(num(row["theta_deg"]))]
    if row["base"] == "frictional":
        base += ["    interface frictional;", "    s_b       %s;             // [Pa]" % fmt(1000 * num(row["s_b_kPa"]))]
    else:
        base += ["    interface noSlip;"]
    paper = ", ".join("%s %s m" % (m, row["runout_%s_m" % m]) for m in ("DAM", "MPM", "CFD") if row["runout_%s_m" % m])
    scene = header.format(case=case, obj="sceneProperties") + """title       "Table 1 Case {case}";

// Paper: {mech}; runout {paper}

g           9.81;

slide
{{
    shape        rectangle;
    length       40;            // L0 [m]
    height       5;             // H0 [m]
    rearPosition 0;
    density      600;           // submerged rho' [kg/m3]
}}

rheology
{{
{rheo}
}}

base
{{
{base}
}}

ambient
{{
    phase     light;            // submerged weight and inertia carried by rho'
}}
""".format(case=case, mech=row["mechanism"], paper=paper or "not given", rheo="\n".join(rheo), base="\n".join(base))
    control = header.format(case=case, obj="controlDict") + """application     slideFoam;

startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {end};

writeControl    adjustableRunTime;
writeInterval   1;
// Keep only the last N writes (restart states; slideFoam's time directories); 0: all.
purgeWrite      0;

// All material slower than restVelocity counts as at rest.
stopAtRest      {stop};
restVelocity    0.01;           // [m/s]

// CFD numerics (slideFoam only)
deltaT          1e-3;
adjustTimeStep  yes;
maxCo           0.5;
maxAlphaCo      0.5;
maxDeltaT       0.05;
writeFormat     ascii;
writePrecision  8;
timeFormat      general;
timePrecision   6;
runTimeModifiable no;
""".format(end=end_times[case], stop="no" if case in (9, 11) else "yes")
    with open(os.path.join(d, "constant", "sceneProperties"), "w") as f:
        f.write(scene)
    with open(os.path.join(d, "system", "controlDict"), "w") as f:
        f.write(control)
    with open(os.path.join(d, "system", "damDict"), "w") as f:
        f.write(header.format(case=case, obj="damDict") + DAMDICT)
    with open(os.path.join(d, "system", "mpmDict"), "w") as f:
        f.write(header.format(case=case, obj="mpmDict") + MPMDICT + (MPMBAND if drem < 1 else "")
                + (MPMFINE if case == 11 else ""))
    with open(os.path.join(d, "system", "cfdDict"), "w") as f:
        f.write(header.format(case=case, obj="cfdDict") + CFDDICT + (CFDBAND if drem < 1 else ""))
    with open(os.path.join(d, "README.md"), "w") as f:
        f.write(readme(case, row, paper))
    for name, text in (("Allrun", ALLRUN), ("Allclean", ALLCLEAN)):
        path = os.path.join(d, name)
        with open(path, "w") as f:
            f.write(text.format(case=case))
        os.chmod(path, 0o755)
    print("wrote", d)
