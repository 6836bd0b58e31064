"""slideFoam cases from SlideFoam scenes, for tests and validation scripts:
copy a scene case, edit its scene and run control, generate the CFD case
(slideFoamCase, blockMesh), run slideFoam serially or with MPI, and
read OpenFOAM ASCII fields back."""
import json
import os
import re
import shutil
import subprocess

import numpy as np

from runner import TOP, slidefoam_env, which

GENERATED = ["0", "0.orig", "constant/polyMesh", "postProcessing", "processor*"]


def set_entry(path, key, value, add=False):
    """Sets `key value;` (top level or inside a block) in an OpenFOAM-style dictionary; a missing key is an
    error, or appended at the end (top level) with add=True."""
    text = open(path).read()
    new, n = re.subn(r"^(\s*%s\s+)[^;]*;" % re.escape(key), lambda m: m.group(1) + str(value) + ";", text,
                     count=1, flags=re.M)
    if n == 0:
        if not add:
            raise KeyError("%s: no entry %s" % (path, key))
        new = text + ("" if text.endswith("\n") else "\n") + "%s %s;\n" % (key, value)
    open(path, "w").write(new)


def get_word(path, key):
    """The value of the first `key value;` of an OpenFOAM-style dictionary, as written, or None where it has none."""
    m = re.search(r"^\s*%s\s+([^;\s]+)\s*;" % re.escape(key), open(path).read(), re.M)
    return m.group(1) if m else None


def get_entry(path, key):
    """A top-level number `key value;` of an OpenFOAM-style dictionary, or None where it has none."""
    word = get_word(path, key)
    return float(word) if word is not None else None


def set_method_entries(case, method_dict, entries):
    """Sets or adds top-level entries of a method dictionary (system/damDict, mpmDict): what the tutorial's
    dictionary says beyond them (a scene's shearBandThickness, ...) is kept."""
    for k, v in entries.items():
        set_entry(os.path.join(case, "system", method_dict), k, v, add=True)


def set_sites(case, sites):
    """Replaces the scene's `sites` block (if any) by sites {name {position s;} ...} from [(name, s), ...]; no
    sites: the block removed."""
    path = os.path.join(case, "constant", "sceneProperties")
    text = open(path).read()
    k = text.find("\nsites")
    if k >= 0:
        depth, j = 0, text.index("{", k)
        while True:
            depth += {"{": 1, "}": -1}.get(text[j], 0)
            j += 1
            if depth == 0:
                break
        text = text[:k] + text[j:]
    if sites:
        text = text.rstrip("\n") + "\n\nsites\n{\n" + "".join("    %s { position %.10g; }\n" % kv for kv in sites) + "}\n"
    with open(path, "w") as f:
        f.write(text)


def copy_scene(template, dest):
    """A copy of a case holding its scene only: RunFunctions' cleanCase removes what runs left in the copy (time
    directories with slideFoam's fields and the DAM/MPM states, logs, postProcessing, slideFoamCase's files)."""
    shutil.copytree(template, dest, ignore=shutil.ignore_patterns("postProcessing", "processor*"))
    subprocess.run(["bash", "-c", ". '%s/bin/tools/RunFunctions' && cleanCase" % TOP], cwd=dest, check=True)


def make_case(template, work, name, scene=None, control=None, cfd=None, dicts=None, dam=None, mpm=None):
    """A copy of a scene case with scene/control entries replaced, system/cfdDict written from the `cfd` entries,
    whole files written from `dicts` ({path in the case: text}, e.g. {"system/mpmDict": "..."}), and entries
    set or added in the case's own damDict and mpmDict from `dam` and `mpm`."""
    d = os.path.join(work, name)
    if os.path.exists(d):
        shutil.rmtree(d)
    copy_scene(template, d)
    for k, v in (scene or {}).items():
        set_entry(os.path.join(d, "constant", "sceneProperties"), k, v)
    for k, v in (control or {}).items():
        set_entry(os.path.join(d, "system", "controlDict"), k, v)
    if cfd is not None:
        with open(os.path.join(d, "system", "cfdDict"), "w") as f:
            for k, v in cfd.items():
                f.write("%s %s;\n" % (k, v))
    for rel, text in (dicts or {}).items():
        with open(os.path.join(d, rel), "w") as f:
            f.write(text)
    if dam:
        set_method_entries(d, "damDict", dam)
    if mpm:
        set_method_entries(d, "mpmDict", mpm)
    return d


def run(case, *cmd, log=None, check=True):
    """Runs an application in a case, its output in log.<app> as runApplication does."""
    # PWD the case's, or OpenFOAM warns that it is not the working directory.
    env = dict(slidefoam_env(), PWD=os.path.abspath(case))
    log = log or "log." + os.path.basename(cmd[0])
    with open(os.path.join(case, log), "w") as f:
        p = subprocess.run(list(cmd), cwd=case, stdout=f, stderr=subprocess.STDOUT, env=env)
    if check and p.returncode != 0:
        tail = open(os.path.join(case, log)).read()[-3000:]
        raise RuntimeError("%s failed in %s:\n%s" % (" ".join(cmd), case, tail))
    return p.returncode


def prepare(case):
    """slideFoamCase, blockMesh, 0.orig -> 0 (the slide's initial extent is in 0.orig/alpha.slide)."""
    run(case, which("slideFoamCase"), "-case", ".")
    run(case, "blockMesh")
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"), dirs_exist_ok=True)


def run_slidefoam(case, processors=1, app="slideFoam"):
    exe = which(app) if app.startswith("slide") else app
    if processors == 1:
        return run(case, exe)
    set_entry(os.path.join(case, "system", "decomposeParDict"), "numberOfSubdomains", processors)
    set_entry(os.path.join(case, "system", "decomposeParDict"), "n", "(%d 1 1)" % processors)
    run(case, "decomposePar", "-force")
    run(case, "mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(processors), exe, "-parallel",
        log="log." + app)
    return run(case, "reconstructPar", "-latestTime")


def run_sized(case, processors=1, retries=2):
    """slideFoam on a scene case as its Allrun runs it: slideDAM first where system/cfdDict gives no reach (its runout
    and spreading size the mesh), then run_regenerating. Returns None, or why it failed."""
    cfd = os.path.join(case, "system", "cfdDict")
    if not os.path.isfile(cfd) or get_entry(cfd, "reach") is None:
        try:
            run(case, which("slideDAM"), "-case", ".")
        except RuntimeError as e:
            return str(e)[-1500:]
    return run_regenerating(case, processors, retries)


def run_regenerating(case, processors=1, retries=2):
    """slideFoamCase, blockMesh and slideFoam. slideDAM's reach bounds neither end of the CFD's (Table 1 Case 8's
    block slides on past slideDAM's 47 m; Case 4's rear spreads upslope past slideDAM's): where the slide leaves the
    mesh, the case is regenerated with cfdDict's reach (or behind) three times the travel it had when it left, at least
    twice the mesh that was too short, and run afresh, up to `retries` times. Returns None, or the reason the
    last try failed (its step and the end of its log)."""
    from slidefoam_io import read_runout
    cfd = os.path.join(case, "system", "cfdDict")
    for attempt in range(retries + 1):
        try:
            prepare(case)
            run_slidefoam(case, processors)
            return None
        except RuntimeError as e:
            log = os.path.join(case, "log.slideFoam")
            log = open(log, errors="replace").read() if os.path.isfile(log) else ""
            ends = [(key, phrase) for key, end, phrase in (
                ("reach", "downslope", "reach ahead of the front"), ("behind", "upslope", "mesh behind the rear"))
                if "%s end of the mesh" % end in log]
            if attempt == retries or not ends:
                return str(e)[-1500:]
            key, phrase = ends[0]
            # The travel when it left (slideFoam writes runout.dat's row and the fields at that time before it stops).
            r = read_runout(os.path.join(case, "postProcessing", "slideFoam", "runout.dat"))
            travel = r["front"][-1] if key == "reach" else r["rear"][0] - r["rear"][-1]
            mesh = float(re.search(r"%s ([0-9.eE+-]+) m" % phrase,
                                   open(os.path.join(case, "log.slideFoamCase")).read()).group(1))
            longer = max(3.0*travel, 2.0*mesh)
            print("%s: the slide left the mesh (%s %.4g m); regenerating it with %s %.4g m"
                  % (case, key, mesh, key, longer), flush=True)
            if not os.path.isfile(cfd):
                open(cfd, "w").close()   # slideFoamCase's defaults, and the longer mesh
            set_entry(cfd, key, "%.6g" % longer, add=True)
            # Afresh from the start on the new mesh: the fields and records of the run that left the old one go.
            for stale in time_dirs(case) + ["postProcessing/slideFoam"]:
                shutil.rmtree(os.path.join(case, stale))
            subprocess.run(["bash", "-c", "rm -rf processor*"], cwd=case, check=True)


def cell_geometry(case, time="0"):
    """The cells' volumes and centres (V, Cx, Cy) of a serial or reconstructed case at `time`, written by
    postProcess (writeCellVolumes, writeCellCentres)."""
    for func in ("writeCellVolumes", "writeCellCentres"):
        run(case, "postProcess", "-func", func, "-time", time, log="log.postProcess." + func)
    return read_field(case, time, "V"), read_field(case, time, "Cx"), read_field(case, time, "Cy")


def variant_arguments(ap, variants, name, reuse):
    """Parses a variant study's command line: ap's own arguments, --variants (a comma list of the keys of
    `variants`, all by default) and --work (default /tmp/slideFoam_<name>, made if missing; `reuse` says which
    runs found there are read, not rerun). Returns (args, the variants chosen, the work directory)."""
    ap.add_argument("--variants", default=",".join(variants))
    ap.add_argument("--work", default=None, help="work directory (default: /tmp/slideFoam_%s); %s" % (name, reuse))
    args = ap.parse_args()
    chosen = args.variants.split(",")
    for v in chosen:
        if v not in variants:
            raise SystemExit("--variants: unknown variant '%s' (expected %s)" % (v, ", ".join(variants)))
    work = args.work or os.path.join("/tmp", "slideFoam_" + name)
    os.makedirs(work, exist_ok=True)
    return args, chosen, work


def write_study(directory, name, lines, results):
    """A study's report: <name>.md from its lines and <name>.json from its results, in `directory`."""
    with open(os.path.join(directory, name + ".md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(directory, name + ".json"), "w") as f:
        json.dump(results, f, indent=1)
    print("wrote %s" % os.path.join(directory, name + ".md"))


def time_dirs(case):
    out = []
    for n in os.listdir(case):
        try:
            out.append((float(n), n))
        except ValueError:
            pass
    return [n for _, n in sorted(out)]


def _nonuniform_list(kind, n, body):
    """The n values of an ASCII nonuniform List<kind> whose opening parenthesis ends just before body."""
    if kind == "vector":
        # A list of up to ten is written on one line: "4((x y z) ... );"
        end = body.index("\n)") if "\n)" in body[:body.index(";")] else body.index(");")
        vals = re.findall(r"\(([^()]*)\)", body[:end])
        return np.array([[float(x) for x in v.split()] for v in vals[:n]])
    return np.array([float(x) for x in body[:body.index(")")].split()[:n]])


def read_field(case, time, name):
    """internalField of an ASCII volScalarField/volVectorField as a numpy array."""
    text = open(os.path.join(case, time, name)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text)
    if m:
        return _nonuniform_list(m.group(1), int(m.group(2)), text[m.end():])
    m = re.search(r"internalField\s+uniform\s+(\([^)]*\)|[^;]+);", text)
    if not m:
        raise ValueError("no internalField in %s/%s/%s" % (case, time, name))
    v = m.group(1).strip()
    return np.array([float(x) for x in v.strip("()").split()])


def read_patch(case, time, name, patch):
    """The value entry of one patch of an ASCII field (nonuniform only), as a numpy array."""
    path = os.path.join(case, time, name)
    text = open(path).read()
    start = re.search(r"\n\s*%s\s*\{" % re.escape(patch), text[text.index("boundaryField"):])
    if not start:
        raise ValueError("%s: no patch %s" % (path, patch))
    text = text[text.index("boundaryField") + start.end():]
    m = re.search(r"value\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text[:text.index("}")])
    if not m:
        raise ValueError("%s: patch %s has no nonuniform value" % (path, patch))
    return _nonuniform_list(m.group(1), int(m.group(2)), text[m.end():])


def patch_cells(case, patch):
    """The cell next to each face of a patch of the case's (serial, ASCII) mesh, in the patch's face order."""
    mesh = os.path.join(case, "constant", "polyMesh")
    b = re.search(r"\n\s*%s\s*\{[^}]*nFaces\s+(\d+);[^}]*startFace\s+(\d+);" % re.escape(patch),
                  open(os.path.join(mesh, "boundary")).read())
    if not b:
        raise ValueError("%s/boundary: no patch %s" % (mesh, patch))
    text = open(os.path.join(mesh, "owner")).read()
    m = re.search(r"\n(\d+)\s*\(", text[text.index("}"):])
    owner = np.array(text[text.index("}") + m.end():].split(")")[0].split(), dtype=int)
    start, n = int(b.group(2)), int(b.group(1))
    return owner[start:start + n]
