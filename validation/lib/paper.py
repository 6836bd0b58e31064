"""The paper's Table 1 values per case, from the comments the case generator
(tutorials/table1/generateCases.py) wrote from ../shared/reference/table1.csv."""
import os

from cfdcase import get_word

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def paper_line(scene_path):
    """(mechanism, {"DAM": m, "MPM": m, "CFD": m, "observed": m}) from the scene's '// Paper:' comment,
    e.g. '// Paper: block sliding; runout DAM 1381 m, MPM 1400 m, observed 1340 m;'."""
    lines = [l for l in open(scene_path).read().splitlines() if l.startswith("// Paper:")]
    if not lines:
        return "", {}
    mech, _, runs = lines[0][len("// Paper: "):].partition("; runout ")
    vals = {}
    for part in runs.rstrip(";").split(", "):
        bits = part.split()
        if len(bits) >= 2 and bits[0] in ("DAM", "MPM", "CFD", "observed"):
            try:
                vals[bits[0]] = float(bits[1])
            except ValueError:
                pass
    return mech, vals


def paper_table():
    """{case: (mechanism, {"DAM": m, "MPM": m, "CFD": m})} with the values the paper gives."""
    return {c: paper_line(os.path.join(TOP, "tutorials", "table1", "case%02d" % c, "constant", "sceneProperties"))
            for c in range(1, 14)}



def scene_word(case, key):
    """A Table 1 case scene's entry `key value;` (the first), as written."""
    path = os.path.join(TOP, "tutorials", "table1", "case%02d" % case, "constant", "sceneProperties")
    word = get_word(path, key)
    if word is None:
        raise SystemExit("%s: no %s" % (path, key))
    return word


def wall_function_acts(case):
    """Whether slideFoam's rateWallFunction can act on a Table 1 case: a no-slip base under Eq. (1)'s rate term
    (slideFoamCase refuses it elsewhere)."""
    return scene_word(case, "interface") == "noSlip" and float(scene_word(case, "eta")) > 0.0

# Not the paper's: Case 1 without Eq. (1)'s rate term, a diagnostic of how a method's runout depends on its cells
# (validation/mpm/numerics.py, validation/cfd/table1.py --rate-free). In a shear layer a cell or two thick the strain
# rate, and with it the rate term's strength, grows as the cell shrinks: a runout that falls with the cell with the
# rate term and not without it falls by the rate term's resolution. s_uo 225 Pa is Eq. (1)'s strength at about
# 1 1/s (150 (1 + 0.35 (1/0.06)^0.15) = 229 Pa).
CASE1_RATE_FREE_SCENE = {"eta": 0, "s_uo": 225}
