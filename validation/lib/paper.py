"""The paper's Table 1 values per case, from the comments the case generator
(tutorials/table1/generateCases.py) wrote from ../shared/reference/table1.csv."""
import os

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def paper_table():
    """{case: (mechanism, {"DAM": m, "MPM": m, "CFD": m})} with the values the paper gives."""
    rows = {}
    for c in range(1, 14):
        text = open(os.path.join(TOP, "tutorials", "table1", "case%02d" % c, "constant", "sceneProperties")).read()
        line = [l for l in text.splitlines() if l.startswith("// Paper:")][0]
        mech, _, runs = line[len("// Paper: "):].partition("; runout ")
        vals = {}
        for part in runs.split(", "):
            bits = part.split()
            if len(bits) >= 2 and bits[0] in ("DAM", "MPM", "CFD"):
                try:
                    vals[bits[0]] = float(bits[1])
                except ValueError:
                    pass
        rows[c] = (mech, vals)
    return rows
