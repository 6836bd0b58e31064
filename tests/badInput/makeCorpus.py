#!/usr/bin/env python3
"""Writes the bad-input corpus (tests/badInput/NN-name/) from the flagship
scene (tutorials/kroneWrightRun15): each entry is one defect in one file, the
file as a user would have written it, and an `expected` file saying which
file, line and key every method's error must name. The expectation is set here,
from where the defect was put, never from what the programs print.

Run it after changing the flagship scene's files; checkBadInput.py runs the
methods on the entries (CTest badInput_*).

expected:
    file    <file relative to the case>
    line    <line the error must name>
    key     <qualified key the error must name, or - where a syntax error has none>
    methods all | <application> ...   (all: slideDAM slideMPM slideFoamCase slideFoam;
                                      a method dictionary is read by its method only)
    why     <the defect, in words>
"""
import os
import re
import shutil

here = os.path.dirname(os.path.abspath(__file__))
top = os.path.abspath(os.path.join(here, "..", ".."))
flume = os.path.join(top, "tutorials", "kroneWrightRun15")

SCENE = "constant/sceneProperties"
CONTROL = "system/controlDict"


def read(rel):
    return open(os.path.join(flume, rel)).read().split("\n")


def line_of(lines, pattern):
    """1-based line of the first line matching pattern."""
    rx = re.compile(pattern)
    for i, s in enumerate(lines):
        if rx.search(s):
            return i + 1
    raise ValueError("no line matches %r" % pattern)


def replace(lines, pattern, new):
    i = line_of(lines, pattern)
    out = list(lines)
    out[i - 1] = new
    return out, i


def delete(lines, pattern):
    i = line_of(lines, pattern)
    return lines[:i - 1] + lines[i:], i


def entry_value(key, value):
    return "    %-12s %s;" % (key, value)


scene0 = read(SCENE)
control0 = read(CONTROL)

# Variants of the scene the defects are put into.
polylineBase = ["base", "{", "    profile   polyline;",
                "    points    ((0 0) (10 -0.6) (20 -0.9) (30 -0.9));", "    interface noSlip;", "}"]


def remove_block(lines, name):
    """The lines without dictionary `name` (its name line to its closing brace), and its first line."""
    a = line_of(lines, r"^%s\s*$" % name)
    b = a + lines[a:].index("}")
    return lines[:a - 1] + lines[b + 1:], a


def with_base(lines, block):
    a = line_of(lines, r"^base\s*$")
    b = a + lines[a:].index("}")
    return lines[:a - 1] + block + lines[b + 1:]


scenePolyline = with_base(scene0, polylineBase)


def with_slide(lines, block):
    a = line_of(lines, r"^slide\s*$")
    b = a + lines[a:].index("}")
    return lines[:a - 1] + block + lines[b + 1:]


sceneProfile = with_slide(scene0, ["slide", "{", "    shape        profile;",
                                   "    thickness    ((0 0.3) (0.9 0.3) (1.8 0.1));",
                                   "    rearWall     yes;", "    density      1073;", "}"])


def with_interface(lines, iface_lines):
    out, i = replace(lines, r"^\s*interface\s", iface_lines[0])
    return out[:i] + iface_lines[1:] + out[i:], i


corpus = []


def add(name, why, file, lines, line, key, methods="all", also=None):
    """also: {file: lines} of the scene the defect needs around it, written beside the defective file (a setting that
    is wrong only for some scenes); the error must still name the defective file."""
    corpus.append(dict(name=name, why=why, file=file, text="\n".join(lines), line=line, key=key, methods=methods,
                       also={f: "\n".join(ls) for f, ls in (also or {}).items()}))


def scene_sub(name, why, pattern, new, key, base=None):
    lines, i = replace(base or scene0, pattern, new)
    add(name, why, SCENE, lines, i, key)


def scene_missing(name, why, pattern, dict_pattern, key, base=None):
    lines, _ = delete(base or scene0, pattern)
    add(name, why, SCENE, lines, line_of(lines, dict_pattern) if dict_pattern else 1, key)


def control_sub(name, why, pattern, new, key, methods="all"):
    lines, i = replace(control0, pattern, new)
    add(name, why, CONTROL, lines, i, key, methods)


# --- missing keys: the error names the enclosing dictionary's line
scene_missing("missing-g", "gravity not given", r"^g\s", None, "g")
scene_missing("missing-s_uo", "no intact strength", r"^\s*s_uo\s", r"^rheology\s*$", "rheology.s_uo")
scene_missing("missing-eta", "no rate parameter", r"^\s*eta\s", r"^rheology\s*$", "rheology.eta")
scene_missing("missing-deltaRem", "no remoulded ratio", r"^\s*deltaRem\s", r"^rheology\s*$", "rheology.deltaRem")
scene_missing("missing-height", "no slide height", r"^\s*height\s", r"^slide\s*$", "slide.height")
scene_missing("missing-density", "no submerged density", r"^\s*density\s+1073", r"^slide\s*$", "slide.density")
scene_missing("missing-angle", "planar base without its angle", r"^\s*angle\s", r"^base\s*$", "base.angle")
scene_missing("missing-interface", "base without an interface", r"^\s*interface\s", r"^base\s*$", "base.interface")
scene_missing("missing-shape", "slide without a shape", r"^\s*shape\s", r"^slide\s*$", "slide.shape")
lines, _ = remove_block(scene0, "rheology")
add("missing-rheology-dict", "no rheology dictionary at all", SCENE, lines, 1, "rheology")
lines, _ = delete(control0, r"^endTime\s")
add("missing-endTime", "controlDict without endTime", CONTROL, lines, 1, "endTime")
lines, _ = delete(control0, r"^writeInterval\s")
add("missing-writeInterval", "controlDict without writeInterval", CONTROL, lines, 1, "writeInterval")

# --- wrong types
scene_sub("type-s_uo-word", "a word where a number belongs", r"^\s*s_uo\s", entry_value("s_uo", "high"), "rheology.s_uo")
scene_sub("type-angle-list", "a list where a number belongs", r"^\s*angle\s", entry_value("angle", "(3 4)"), "base.angle")
scene_sub("type-density-string", "a string where a number belongs", r"^\s*density\s+1073",
          entry_value("density", '"1073"'), "slide.density")
scene_sub("type-rearWall-number", "a number where yes/no belongs", r"^\s*rearWall\s", entry_value("rearWall", "2"),
          "slide.rearWall")
lines, a = remove_block(scene0, "slide")
lines = lines[:a - 1] + ["slide 1.8;"] + lines[a - 1:]
add("type-slide-value", "a value where the slide dictionary belongs", SCENE, lines, a, "slide")
scene_sub("type-model-unknown", "a rheology model that does not exist", r"^\s*model\s", entry_value("model", "Bingham"),
          "rheology.model")
scene_sub("type-interface-unknown", "an interface that does not exist", r"^\s*interface\s",
          entry_value("interface", "sticky"), "base.interface")
scene_sub("type-phase-unknown", "an ambient phase that does not exist", r"^\s*phase\s", entry_value("phase", "oil"),
          "ambient.phase")
scene_sub("type-n-two-values", "two values for one key", r"^\s*n\s", entry_value("n", "1 2"), "rheology.n")
control_sub("type-endTime-word", "a word where the end time belongs", r"^endTime\s", "endTime         later;", "endTime")

# --- syntax
a = line_of(scene0, r"^slide\s*$")
b = a + scene0[a:].index("}")  # the slide dictionary's closing brace, 0-based
lines = scene0[:b] + scene0[b + 1:]
add("syntax-unclosed-brace", "the slide dictionary's '}' is missing", SCENE, lines, a + 1, "slide")
lines = scene0 + ["}"]
add("syntax-extra-brace", "a '}' without its '{'", SCENE, lines, len(lines), "-")
scene_sub("syntax-missing-semicolon", "an entry without its ';'", r"^\s*s_uo\s", "    s_uo     42.5", "rheology.s_uo")
scene_sub("syntax-unterminated-string", "a title string without its closing quote", r"^title\s",
          'title       "Krone-Wright Run 15 flume;', "-")
lines = scene0[:line_of(scene0, r"^g\s")] + ["/* an unfinished comment"] + scene0[line_of(scene0, r"^g\s"):]
add("syntax-unterminated-comment", "a /* comment never closed", SCENE, lines, line_of(lines, r"^/\* an unfinished"), "-")
scene_sub("syntax-duplicate-key", "s_uo given twice (the second silently winning would hide a typo)", r"^\s*eta\s",
          entry_value("s_uo", "40"), "rheology.s_uo")
scene_sub("syntax-unknown-key", "a typo (s_u0) that would otherwise silently take a default", r"^\s*s_uo\s",
          entry_value("s_u0", "42.5"), "rheology.s_u0")
scene_sub("syntax-macro", "an #include the scene reader does not follow", r"^g\s", '#include "gravity"', "-")
scene_sub("syntax-unclosed-list", "a list whose ')' is missing", r"^\s*angle\s", entry_value("angle", "(3.43"),
          "base.angle")
scene_sub("syntax-non-ascii", "a non-ASCII character (a degree sign)", r"^\s*angle\s",
          "    angle     3.43\u00b0;", "-")
add("syntax-empty-file", "an empty sceneProperties", SCENE, [""], 1, "g")

# --- out of range: rheology
scene_sub("range-s_uo-negative", "negative intact strength", r"^\s*s_uo\s", entry_value("s_uo", "-42.5"), "rheology.s_uo")
scene_sub("range-s_uo-zero", "zero intact strength", r"^\s*s_uo\s", entry_value("s_uo", "0"), "rheology.s_uo")
scene_sub("range-s_uo-inf", "a strength that overflows a double", r"^\s*s_uo\s", entry_value("s_uo", "1e400"),
          "rheology.s_uo")
scene_sub("range-eta-negative", "negative rate parameter", r"^\s*eta\s", entry_value("eta", "-0.1"), "rheology.eta")
scene_sub("range-n-zero", "n = 0", r"^\s*n\s", entry_value("n", "0"), "rheology.n")
scene_sub("range-n-negative", "n < 0", r"^\s*n\s", entry_value("n", "-0.5"), "rheology.n")
scene_sub("range-gdotRef-zero", "zero reference strain rate", r"^\s*gdotRef\s", entry_value("gdotRef", "0"),
          "rheology.gdotRef")
scene_sub("range-deltaRem-zero", "delta_rem = 0 (outside (0, 1])", r"^\s*deltaRem\s", entry_value("deltaRem", "0"),
          "rheology.deltaRem")
scene_sub("range-deltaRem-above-one", "delta_rem = 1.5 (outside (0, 1])", r"^\s*deltaRem\s",
          entry_value("deltaRem", "1.5"), "rheology.deltaRem")
scene_sub("range-deltaRem-negative", "delta_rem < 0", r"^\s*deltaRem\s", entry_value("deltaRem", "-0.2"),
          "rheology.deltaRem")
lines, i = replace(scene0, r"^\s*deltaRem\s", entry_value("deltaRem", "0.3"))
lines = lines[:i] + [entry_value("xi95", "0")] + lines[i:]
add("range-xi95-zero", "remoulding with xi95 = 0", SCENE, lines, i + 1, "rheology.xi95")
lines, i = replace(scene0, r"^\s*deltaRem\s", entry_value("deltaRem", "0.3"))
add("missing-xi95", "remoulding (delta_rem < 1) without xi95", SCENE, lines, line_of(lines, r"^rheology\s*$"),
    "rheology.xi95")

# --- out of range: slide, base, interface, ambient, gravity
scene_sub("range-density-zero", "zero submerged density", r"^\s*density\s+1073", entry_value("density", "0"),
          "slide.density")
scene_sub("range-density-negative", "negative submerged density", r"^\s*density\s+1073", entry_value("density", "-600"),
          "slide.density")
scene_sub("range-height-negative", "negative height: the slide starts below the base", r"^\s*height\s",
          entry_value("height", "-0.3"), "slide.height")
scene_sub("range-length-zero", "a slide of zero length", r"^\s*length\s", entry_value("length", "0"), "slide.length")
scene_sub("range-angle-steep", "a 75 deg base (beyond [0, 60])", r"^\s*angle\s", entry_value("angle", "75"),
          "base.angle")
scene_sub("range-angle-negative", "a planar base inclined uphill", r"^\s*angle\s", entry_value("angle", "-5"),
          "base.angle")
scene_sub("range-g-zero", "no gravity", r"^g\s", "g           0;", "g")
lines, i = with_interface(scene0, [entry_value("interface", "frictional")])
add("missing-s_b", "a frictional base without s_b", SCENE, lines, line_of(lines, r"^base\s*$"), "base.s_b")
lines, i = with_interface(scene0, [entry_value("interface", "frictional"), entry_value("s_b", "-50")])
add("range-s_b-negative", "negative basal strength", SCENE, lines, i + 1, "base.s_b")
lines, i = with_interface(scene0, [entry_value("interface", "hydroplaning"), entry_value("C_F", "-0.003")])
add("range-C_F-negative", "negative drag coefficient", SCENE, lines, i + 1, "base.C_F")
lines, i = with_interface(scene0, [entry_value("interface", "hydroplaning")])
add("missing-C_F", "hydroplaning without C_F", SCENE, lines, line_of(lines, r"^base\s*$"), "base.C_F")
lines, i = with_interface(scene0, [entry_value("interface", "noSlip"), entry_value("s_b", "50")])
add("unused-s_b", "s_b with a no-slip base (it would be silently ignored)", SCENE, lines, i + 1, "base.s_b")
scene_sub("range-ambient-heavier", "an ambient phase as heavy as the slide", r"^\s*density\s+1\.2",
          "    density   2000;", "ambient.density")

# --- base polyline and slide geometry
scene_sub("polyline-not-monotonic", "a base polyline whose x goes back", r"^\s*points\s",
          "    points    ((0 0) (10 -0.6) (8 -0.9) (30 -0.9));", "base.points", scenePolyline)
scene_sub("polyline-one-point", "a polyline of one point", r"^\s*points\s", "    points    ((0 0));", "base.points",
          scenePolyline)
scene_sub("polyline-steep-segment", "a polyline segment at 80 deg", r"^\s*points\s",
          "    points    ((0 0) (10 -0.6) (10.1 -1.2) (30 -1.2));", "base.points", scenePolyline)
scene_sub("polyline-not-numbers", "a polyline point that is not a pair", r"^\s*points\s",
          "    points    ((0 0) (10) (30 -0.9));", "base.points", scenePolyline)
lines, i = replace(scenePolyline, r"^\s*rearPosition\s", entry_value("rearPosition", "29"))
add("slide-off-polyline", "a slide whose front lies beyond the base polyline", SCENE, lines, i, "slide.rearPosition")
scene_sub("profile-below-base", "a thickness profile going negative: the slide starts below the base",
          r"^\s*thickness\s", "    thickness    ((0 0.3) (0.9 -0.1) (1.8 0.1));", "slide.thickness", sceneProfile)
scene_sub("profile-not-increasing", "a thickness profile whose s goes back", r"^\s*thickness\s",
          "    thickness    ((0 0.3) (0.9 0.3) (0.5 0.1));", "slide.thickness", sceneProfile)

# --- run control
control_sub("time-end-before-start", "endTime before startTime", r"^endTime\s", "endTime         -1;", "endTime")
control_sub("time-end-equals-start", "endTime equal to startTime: nothing to run", r"^endTime\s",
            "endTime         0;", "endTime")
control_sub("time-start-negative", "a negative startTime", r"^startTime\s", "startTime       -2;", "startTime")
control_sub("time-writeInterval-zero", "writeInterval 0", r"^writeInterval\s", "writeInterval   0;", "writeInterval")
control_sub("time-restVelocity-negative", "a negative rest velocity", r"^restVelocity\s", "restVelocity    -1;",
            "restVelocity")
control_sub("time-startFrom-unknown", "startFrom a word OpenFOAM does not know", r"^startFrom\s",
            "startFrom       middle;", "startFrom")

# --- method dictionaries: absurd resolutions and bad numerics, read by their method only
dam0 = read("system/damDict")
mpm0 = read("system/mpmDict")
cfd0 = read("system/cfdDict")
add("dam-columns-absurd", "1e9 columns", "system/damDict", dam0[:-1] + ["columns     1000000000;", ""],
    len(dam0), "columns", "slideDAM")
add("dam-setting-unknown", "a setting that does not exist", "system/damDict",
    [("setting     paper;" if s.startswith("setting") else s) for s in dam0], line_of(dam0, r"^setting"), "setting",
    "slideDAM")
add("mpm-resolution-memory", "H0/100000 cells: more memory than the machine has", "system/mpmDict",
    mpm0[:-1] + ["cellsPerHeight   100000;", ""], len(mpm0), "cellsPerHeight", "slideMPM")
add("mpm-poisson-half", "nu = 0.5 (the elastic wave speed is infinite)", "system/mpmDict",
    mpm0[:-1] + ["poissonRatio     0.5;", ""], len(mpm0), "poissonRatio", "slideMPM")
add("mpm-courant-above-one", "Courant number 3", "system/mpmDict", mpm0[:-1] + ["courant          3;", ""], len(mpm0),
    "courant", "slideMPM")
add("cfd-resolution-memory", "H0/2000 cells: more memory than the machine has", "system/cfdDict",
    cfd0[:-1] + ["cellsPerHeight  2000;", ""], len(cfd0), "cellsPerHeight", "slideFoamCase")
add("cfd-unknown-key", "a typo in cfdDict (cellPerHeight)", "system/cfdDict", cfd0[:-1] + ["cellPerHeight   30;", ""],
    len(cfd0), "cellPerHeight", "slideFoamCase")
add("mpm-split-length-zero", "particles split at zero length (every check would halve them all)", "system/mpmDict",
    mpm0[:-1] + ["maxParticleLength 0;", ""], len(mpm0), "maxParticleLength", "slideMPM")
add("cfd-end-after-scene", "slideFoam's end time (10 s) after the scene's (4.1 s)", "system/cfdDict",
    cfd0[:-1] + ["endTime         10;", ""], len(cfd0), "endTime", "slideFoamCase")

add("cfd-ahead-height-above", "a mesh higher ahead of the slide (2 H0) than over it (1.3 H0)", "system/cfdDict",
    cfd0[:-1] + ["aheadHeightRatio 2;", ""], len(cfd0), "aheadHeightRatio", "slideFoamCase")

add("mpm-band-negative", "a negative shear band thickness", "system/mpmDict",
    mpm0[:-1] + ["shearBandThickness -0.01;", ""], len(mpm0), "shearBandThickness", "slideMPM")
add("cfd-band-negative", "a negative shear band thickness for slideFoam's remoulding", "system/cfdDict",
    cfd0[:-1] + ["shearBandThickness -0.01;", ""], len(cfd0), "shearBandThickness", "slideFoamCase")
add("mpm-initial-stress-word", "an initial stress slideMPM does not know (lithostatic)", "system/mpmDict",
    mpm0[:-1] + ["initialStress lithostatic;", ""], len(mpm0), "initialStress", "slideMPM")
add("cfd-ahead-from-negative", "the lower top starting behind the initial front (-5 m)", "system/cfdDict",
    cfd0[:-1] + ["aheadHeightFrom -5;", ""], len(cfd0), "aheadHeightFrom", "slideFoamCase")
add("mpm-purge-state-negative", "a negative number of restart states to keep", "system/mpmDict",
    [("purgeState       -2;" if s.startswith("purgeState") else s) for s in mpm0], line_of(mpm0, r"^purgeState"),
    "purgeState", "slideMPM")
add("cfd-ambient-relaxation-negative", "a negative relaxation time for the light ambient", "system/cfdDict",
    cfd0[:-1] + ["ambientRelaxationTime -2;", ""], len(cfd0), "ambientRelaxationTime", "slideFoamCase")
add("cfd-top-unknown", "a top slideFoamCase does not know (lid; it takes open or slip)", "system/cfdDict",
    cfd0[:-1] + ["top             lid;", ""], len(cfd0), "top", "slideFoamCase")
add("mpm-shifting-level-set", "particle shifting over a base that cuts the grid (its nodes' fill is not known)",
    "system/mpmDict", mpm0[:-1] + ["baseBoundary     levelSet;", "particleShifting 0.05;", ""], len(mpm0) + 1,
    "particleShifting", "slideMPM")
add("cfd-wall-function-papanastasiou", "Eq. (1)'s wall function with the Papanastasiou regularisation (it follows the "
    "capped profile)", "system/cfdDict", cfd0[:-1] + ["regularisation  papanastasiou;", "rateWallFunction yes;", ""],
    len(cfd0) + 1, "rateWallFunction", "slideFoamCase")
add("cfd-face-viscosity-not-bool", "face viscosities asked with a word that is not yes or no", "system/cfdDict",
    cfd0[:-1] + ["faceViscosity   faces;", ""], len(cfd0), "faceViscosity", "slideFoamCase")
add("mpm-particles-per-cell-above", "64 x 64 particles per cell (beyond the 32 a convergence study in the particles "
    "needs)", "system/mpmDict", mpm0[:-1] + ["particlesPerCell 64;", ""], len(mpm0), "particlesPerCell", "slideMPM")
add("mpm-phase-times-not-bool", "phase times asked with a word that is not yes or no", "system/mpmDict",
    mpm0[:-1] + ["phaseTimes       fenced;", ""], len(mpm0), "phaseTimes", "slideMPM")
add("mpm-band-rate-without-band", "Eq. (1)'s rate asked of a shear band whose thickness is not given",
    "system/mpmDict", mpm0[:-1] + ["shearBandRate    yes;", ""], len(mpm0), "shearBandRate", "slideMPM")

add("mpm-node-sums-word", "a particle-to-grid summation slideMPM does not know (perWarp; it takes perParticle or "
    "perBlock)", "system/mpmDict", mpm0[:-1] + ["nodeSums         perWarp;", ""], len(mpm0), "nodeSums", "slideMPM")
add("mpm-block-particles-zero", "blocks of no particles for particle-to-grid by blocks", "system/mpmDict",
    mpm0[:-1] + ["nodeSums         perBlock;", "blockParticles   0;", ""], len(mpm0) + 1, "blockParticles", "slideMPM")
add("cfd-outer-correctors-zero", "no outer corrector a step (PIMPLE needs at least one)", "system/cfdDict",
    cfd0[:-1] + ["outerCorrectors 0;", ""], len(cfd0), "outerCorrectors", "slideFoamCase")

add("cfd-face-force-one-outer", "gravity's along-slope part as a face force with one outer corrector (the SIMPLEC step "
    "takes it with a momentum error)", "system/cfdDict", cfd0[:-1] + ["alongSlopeGravity faceForce;", ""], len(cfd0),
    "alongSlopeGravity", "slideFoamCase")
add("cfd-wall-function-frictional", "Eq. (1)'s wall function asked over a frictional base (it acts on a no-slip "
    "base only, and would leave the run as if never asked)", "system/cfdDict", cfd0[:-1] + ["rateWallFunction yes;", ""],
    len(cfd0), "rateWallFunction", "slideFoamCase",
    also={SCENE: replace(scene0, r"^\s*interface\s",
                         entry_value("interface", "frictional") + "\n" + entry_value("s_b", "20"))[0]})
add("cfd-wall-function-rate-free", "Eq. (1)'s wall function asked of a slide without a rate term (eta 0)",
    "system/cfdDict", cfd0[:-1] + ["rateWallFunction yes;", ""], len(cfd0), "rateWallFunction", "slideFoamCase",
    also={SCENE: replace(scene0, r"^\s*eta\s", entry_value("eta", "0"))[0]})
add("dam-timeScheme-unknown", "a time scheme slideDAM does not have (rk4)", "system/damDict",
    dam0[:-1] + ["timeScheme  rk4;", ""], len(dam0), "timeScheme", "slideDAM")

scene_sub("site-not-a-dictionary", "a site given as a bare position instead of a sub-dictionary",
          r"^\s*gauge3m\s", "    gauge3m     3;", "sites.gauge3m")
scene_sub("site-position-word", "a site's position that is not a number",
          r"^\s*gauge5m\s", "    gauge5m     { position five; }", "sites.gauge5m.position")
scene_sub("site-unknown-key", "a site with a key no method reads (depth)",
          r"^\s*gauge5m\s", "    gauge5m     { position 5; depth 1; }", "sites.gauge5m.depth")
add("cfd-slide-trace-one", "base faces under less than all of the slide counted as the ambient's (baseSlideTrace 1: "
    "the alpha below which a face is stuck must lie in [0, 1))", "system/cfdDict",
    cfd0[:-1] + ["baseSlideTrace  1;", ""], len(cfd0), "baseSlideTrace", "slideFoamCase")


def main():
    for d in os.listdir(here):
        if os.path.isdir(os.path.join(here, d)) and re.match(r"\d{2,}-", d):
            shutil.rmtree(os.path.join(here, d))
    names = set()
    for k, e in enumerate(corpus, 1):
        assert e["name"] not in names, e["name"]
        names.add(e["name"])
        d = os.path.join(here, "%02d-%s" % (k, e["name"]))
        os.makedirs(os.path.join(d, os.path.dirname(e["file"])))
        with open(os.path.join(d, e["file"]), "w", encoding="utf-8") as f:
            f.write(e["text"])
        for rel, text in e["also"].items():
            os.makedirs(os.path.join(d, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(d, rel), "w", encoding="utf-8") as f:
                f.write(text)
        with open(os.path.join(d, "expected"), "w") as f:
            f.write("file    %s\nline    %d\nkey     %s\nmethods %s\nwhy     %s\n"
                    % (e["file"], e["line"], e["key"], e["methods"], e["why"]))
    print("%d entries written to %s" % (len(corpus), here))


if __name__ == "__main__":
    main()
