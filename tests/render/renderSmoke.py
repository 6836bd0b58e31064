#!/usr/bin/python3
"""Smoke test of the ParaView renders (CTest render_smoke, registered only where
pvbatch and xvfb-run are installed: bin/tools/slidefoam-setup --paraview).
Runs slideDAM and slideMPM briefly on the flume, renders with renderCase, and
checks that the picture exists and shows both methods (coloured pixels in two
separate bands), not a blank or black frame.

Usage: renderSmoke.py <bin dir> <work dir>"""
import os
import shutil
import subprocess
import sys

top = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def main():
    bindir, work = sys.argv[1:3]
    d = os.path.join(work, "flume")
    shutil.rmtree(d, ignore_errors=True)
    for sub in ("constant", "system"):
        shutil.copytree(os.path.join(top, "tutorials", "kroneWrightRun15", sub), os.path.join(d, sub))
    ctrl = os.path.join(d, "system", "controlDict")
    text = open(ctrl).read().replace("endTime         4.1;", "endTime         0.5;")
    open(ctrl, "w").write(text)
    open(os.path.join(d, "system", "damDict"), "w").write("setting fast;\ncolumns 50;\nwriteFields yes;\n")
    open(os.path.join(d, "system", "mpmDict"), "w").write(
        "setting fast;\ncellsPerHeight 5;\nparticlesPerCell 2;\nwriteFields yes;\n")
    for app in ("slideDAM", "slideMPM"):
        subprocess.run([os.path.join(bindir, app), "-case", d], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["bash", "-c", ". '%s/etc/bashrc' && . \"$SLIDEFOAM_DIR/bin/tools/RunFunctions\" && renderCase"
                    % top], cwd=d, check=True)
    png = os.path.join(d, "postProcessing", "comparison", "finalStates.png")
    import matplotlib.image as mpimg
    img = mpimg.imread(png)[:, :, :3]
    h, w, _ = img.shape
    coloured = (img.max(axis=2) - img.min(axis=2)) > 0.15        # not white, grey or black
    rows = coloured[:int(0.85*h)].any(axis=1)                    # above the colour bar
    bands, inside = 0, False
    for r in rows:
        if r and not inside:
            bands += 1
        inside = r
    print("%s: %dx%d, coloured pixels %.2f %%, bands %d" % (png, w, h, 100.0*coloured.mean(), bands))
    if (w, h) != (1600, 900) or coloured.mean() < 0.002 or bands < 2:
        raise SystemExit("FAIL: the render does not show both methods")
    print("render smoke test passed")


if __name__ == "__main__":
    main()
