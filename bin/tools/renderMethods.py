# ParaView (pvbatch) script: the final states of the methods that ran on a case,
# one above the other in one picture, written to postProcessing/comparison/finalStates.png.
#
#     xvfb-run -a pvbatch $SLIDEFOAM_DIR/bin/tools/renderMethods.py <caseDir> [exaggeration]
#
# (Debian's ParaView 5.11 renders headless only under an X server; RunFunctions'
# renderCase does this.) slideDAM: the profile's surface; slideMPM: the particles;
# slideFoam: the cells with alpha.slide >= 0.5; all coloured by the accumulated
# plastic shear strain xi on one colour scale, so that the methods compare. On a planar base the
# DAM and MPM output (x, z) is turned into the slope frame slideFoam's mesh uses
# (x along the base, y normal to it); heights are exaggerated for long slides.
import math
import os
import re
import sys

from paraview.simple import (Calculator, ColorBy, CreateView, GetColorTransferFunction, GetScalarBar,
                             OpenFOAMReader, PVDReader, Render, SaveScreenshot, Show, Text, Threshold, Transform)

case = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
name = os.path.basename(case)
scene = open(os.path.join(case, "constant", "sceneProperties")).read()
m = re.search(r"^\s*angle\s+([0-9.eE+-]+);", scene, re.M)
planar = m is not None and re.search(r"^\s*profile\s+planar;", scene, re.M) is not None
theta = math.radians(float(m.group(1))) if planar else 0.0

view = CreateView("RenderView")
view.ViewSize = [1600, 900]
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass

layers = []   # (label, source, colour array, association)


def final_time(source):
    times = list(source.TimestepValues) if hasattr(source.TimestepValues, "__len__") else [source.TimestepValues]
    return times[-1] if times else 0.0


def to_slope_frame(source):
    """(x, 0, z) -> (s, h, 0) on a planar base: the frame of slideFoam's mesh."""
    if not planar:
        calc = Calculator(Input=source)
        calc.CoordinateResults = 1
        calc.Function = "coordsX*iHat + coordsZ*jHat"
        return calc
    calc = Calculator(Input=source)
    calc.CoordinateResults = 1
    c, s = math.cos(theta), math.sin(theta)
    calc.Function = "(coordsX*%r - coordsZ*%r)*iHat + (coordsX*%r + coordsZ*%r)*jHat" % (c, s, s, c)
    return calc


dam_pvd = os.path.join(case, "postProcessing", "slideDAM", "profile.pvd")
if os.path.isfile(dam_pvd):
    src = PVDReader(FileName=dam_pvd)
    layers.append(("slideDAM", to_slope_frame(src), "xi", "POINTS", final_time(src)))
mpm_pvd = os.path.join(case, "postProcessing", "slideMPM", "particles.pvd")
if os.path.isfile(mpm_pvd):
    src = PVDReader(FileName=mpm_pvd)
    layers.append(("slideMPM", to_slope_frame(src), "xi", "POINTS", final_time(src)))
foam = os.path.join(case, name + ".foam")
if os.path.isfile(foam) and os.path.isdir(os.path.join(case, "constant", "polyMesh")):
    src = OpenFOAMReader(FileName=foam)
    src.MeshRegions = ["internalMesh"]
    src.CellArrays = ["alpha.slide", "xi", "U"]
    t = final_time(src)
    thr = Threshold(Input=src)
    thr.Scalars = ["CELLS", "alpha.slide"]
    try:
        thr.LowerThreshold, thr.UpperThreshold = 0.5, 2.0   # alpha overshoots 1 by round-off
    except AttributeError:
        thr.ThresholdRange = [0.5, 2.0]
    layers.append(("slideFoam", thr, "xi", "CELLS", t))

if not layers:
    sys.exit("renderMethods: no output of slideDAM, slideMPM or slideFoam under %s" % case)

# Extent along the base, to choose the height exaggeration and the offsets between layers.
bounds = []
for label, src, array, assoc, t in layers:
    src.UpdatePipeline(t)
    bounds.append(src.GetDataInformation().GetBounds())
length = max(b[1] for b in bounds) - min(b[0] for b in bounds)
height = max(b[3] - b[2] for b in bounds) or 1.0
exaggeration = float(sys.argv[2]) if len(sys.argv) > 2 else max(1.0, round(0.15*length/height))
gap = 1.6*height*exaggeration

shown = []
xi_max = 1.0
for k, (label, src, array, assoc, t) in enumerate(layers):
    tr = Transform(Input=src)
    tr.Transform.Scale = [1.0, exaggeration, 1.0]
    tr.Transform.Translate = [0.0, -k*gap, 0.0]
    tr.UpdatePipeline(t)
    data = tr.PointData if assoc == "POINTS" else tr.CellData
    if array in data.keys():
        xi_max = max(xi_max, data[array].GetRange()[1])
    shown.append((label, tr, array, assoc, t))

print("renderMethods: xi up to %g" % xi_max)
lut = GetColorTransferFunction("xi")
lut.ApplyPreset("Viridis (matplotlib)", True)
lut.RescaleTransferFunction(0.0, xi_max)
lut.AutomaticRescaleRangeMode = "Never"

for k, (label, tr, array, assoc, t) in enumerate(shown):
    disp = Show(tr, view)
    ColorBy(disp, (assoc, array))
    disp.LookupTable = lut
    if label == "slideMPM":
        disp.SetRepresentationType("Points")
        disp.PointSize = 2
    if label == "slideDAM":
        disp.LineWidth = 3
    text = Text(Text="%s, t = %g s" % (label, t))
    tdisp = Show(text, view)
    tdisp.Color = [0, 0, 0]
    tdisp.FontSize = 14
    tdisp.WindowLocation = "Any Location"
    tdisp.Position = [0.01, 0.80 - k*0.8/len(layers)]

# After Show: showing a source rescales its colour map to that source's range.
lut.RescaleTransferFunction(0.0, xi_max)
bar = GetScalarBar(lut, view)
bar.Title = "xi (accumulated plastic shear strain)"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.WindowLocation = "Any Location"
bar.Orientation = "Horizontal"
bar.Position = [0.62, 0.02]
bar.ScalarBarLength = 0.33
bar.Visibility = 1

title = Text(Text="%s: final states, heights x %g" % (name, exaggeration))
tdisp = Show(title, view)
tdisp.Color = [0, 0, 0]
tdisp.WindowLocation = "Upper Center"
view.ViewTime = max(t for _, _, _, _, t in layers)
view.InteractionMode = "2D"
view.CameraParallelProjection = 1
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraPosition = [0.0, 0.0, 1.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
Render(view)
out = os.path.join(case, "postProcessing", "comparison")
os.makedirs(out, exist_ok=True)
SaveScreenshot(os.path.join(out, "finalStates.png"), view, ImageResolution=[1600, 900])
print("renderMethods: wrote %s" % os.path.join(out, "finalStates.png"))
