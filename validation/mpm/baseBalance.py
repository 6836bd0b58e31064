#!/usr/bin/env python3
"""The grid's force balance of a slideMPM run on a planar base, from its written particles.

Usage: validation/mpm/baseBalance.py CASE --time T [--bin 40] [--rows]

CASE is a slideMPM case run with `writeFields yes` on a planar base fitted to the grid (the default), with the
quadratic B-splines slideMPM uses (nodes every cell along the base, rows at (j + 1/2) d above it, the base's own
row on it). For the frame written nearest to T it rebuilds the nodal forces the particles' stress and weight put on
the grid, with the cell-mean pressure of slideMPM's B-bar, and prints, per bin of the base:
  - the slide's weight along the base (rho' g h sin theta, from the particles' mass);
  - the load on the base's nodes (the downslope force the particles' stress and weight put on the base's node row,
    which the no-slip base cancels), at rest the basal traction;
  - the net force on the rows above, which is zero for material at rest, and its mean over their mass;
  - the particles' shear stress in the lowest quarter of the base cell.
With --rows it also prints the particles' shear stress by quarter-cell rows from the base.

Why: a deposit at rest whose lowest particles carry less shear stress than its weight asks looks as if the base held
it some other way (open problems 9 and 13 of README.md). The base's nodes take the traction of the whole base cell,
weighted towards the base, and the weight of the mass they hold; this script says whether they take the weight.
The cell size and the base's angle are read from the case (mpmDict cellsPerHeight, sceneProperties)."""
import argparse
import math
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "lib"))
from cfdcase import get_entry  # noqa: E402
from slidefoam_io import particles_on_planar_base  # noqa: E402


def entry(path, key, why=""):
    value = get_entry(path, key)
    if value is None:
        sys.exit("%s: no number '%s'%s" % (path, key, why))
    return value


def quadratic_bspline(u):
    """First of the three nodes (integer positions) supporting u, their weights and derivatives per unit."""
    first = np.floor(u - 0.5).astype(int)
    f = u - first
    w = np.stack([0.5*(1.5 - f)**2, 0.75 - (f - 1.0)**2, 0.5*(f - 0.5)**2], 1)
    dw = np.stack([-(1.5 - f), -2.0*(f - 1.0), f - 0.5], 1)
    return first, w, dw


def frame_stress(a, theta):
    """The particles' stress in the base's frame (t downslope, n out of the base) from the global (x, z) one."""
    c, s = math.cos(theta), math.sin(theta)
    tx, tz, nx, nz = c, -s, s, c
    sxx, szz, sxz = a["sigma_xx"], a["sigma_zz"], a["sigma_xz"]
    stt = tx*tx*sxx + 2*tx*tz*sxz + tz*tz*szz
    snn = nx*nx*sxx + 2*nx*nz*sxz + nz*nz*szz
    stn = tx*nx*sxx + (tx*nz + tz*nx)*sxz + tz*nz*szz
    return stt, snn, stn


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--time", type=float, required=True)
    ap.add_argument("--bin", type=float, default=40.0, help="bin length along the base [m]")
    ap.add_argument("--rows", action="store_true")
    args = ap.parse_args()
    scene = os.path.join(args.case, "constant", "sceneProperties")
    theta_deg = entry(scene, "angle", " (this check needs a planar base)")
    rho = entry(scene, "density")
    d = entry(scene, "height")/entry(os.path.join(args.case, "system", "mpmDict"), "cellsPerHeight")
    g = entry(scene, "g")
    theta = math.radians(theta_deg)

    x, y, u, a = particles_on_planar_base(args.case, args.time, theta_deg)
    y = np.maximum(y, 0.0)
    stt, snn, stn = frame_stress(a, theta)
    V, m = a["volume"], a["mass"]
    # slideMPM's B-bar: each particle's pressure replaced by its cell's volume-weighted mean.
    p = -(stt + snn + a["sigma_yy"])/3.0
    cell = np.floor(x/d).astype(np.int64)*1000003 + np.floor(y/d).astype(np.int64)
    _, inv = np.unique(cell, return_inverse=True)
    pbar = np.bincount(inv, V*p)/np.bincount(inv, V)
    stt = stt + p - pbar[inv]
    snn = snn + p - pbar[inv]

    ax, wx, dwx = quadratic_bspline(x/d)
    ay, wy, dwy = quadratic_bspline(y/d - 0.5)
    s = y/d
    inBase = s < 1.0   # the base cell: the base's node (1 - s)^2, the next two 2s - 3s^2/2 and s^2/2
    ay = np.where(inBase, -1, ay)
    sb = s[inBase]
    wy[inBase] = np.stack([(1 - sb)**2, 2*sb - 1.5*sb**2, 0.5*sb**2], 1)
    dwy[inBase] = np.stack([-2*(1 - sb), 2 - 3*sb, sb], 1)
    i0 = ax.min()
    shape = (ax.max() - i0 + 3, ay.max() + 4)
    Ft = np.zeros(shape)
    M = np.zeros(shape)
    for i in range(3):
        for j in range(3):
            N = wx[:, i]*wy[:, j]
            Nx, Ny = dwx[:, i]*wy[:, j]/d, wx[:, i]*dwy[:, j]/d
            idx = (ax + i - i0, ay + j + 1)
            np.add.at(Ft, idx, -V*(stt*Nx + stn*Ny) + m*g*math.sin(theta)*N)
            np.add.at(M, idx, m*N)

    print("%s at %g s (frame nearest), cell %.4g m, %d particles, largest speed %.3f m/s" % (
        args.case, args.time, d, len(x), np.abs(u).max()))
    print("%-13s %7s %10s %14s %18s %14s %12s" % ("bin [m]", "h [m]", "weight", "on base nodes", "rows above, net",
                                                 "|F|/M above", "lowest s_tn"))
    xs = (np.arange(shape[0]) + i0)*d
    L = args.bin
    lo = math.floor(x.min()/L)*L
    while lo < x.max():
        sel = (xs >= lo) & (xs < lo + L)
        pm = (x >= lo) & (x < lo + L)
        if pm.sum() >= 10:
            h = m[pm].sum()/rho/L
            weight = m[pm].sum()*g*math.sin(theta)/L
            base = Ft[sel, 0].sum()/L
            above = Ft[sel, 1:].sum()/L
            accel = np.abs(Ft[sel, 1:]).sum()/max(M[sel, 1:].sum(), 1e-30)
            low = pm & (y < 0.25*d)
            print("%6.0f-%-6.0f %7.3f %7.0f Pa %11.0f Pa %15.0f Pa %9.3f m/s2 %9.0f Pa" % (
                lo, lo + L, h, weight, base, above, accel, stn[low].mean() if low.any() else float("nan")))
            if args.rows:
                rows = [stn[pm & (y >= k*d/4) & (y < (k + 1)*d/4)] for k in range(8)]
                print("               s_tn by quarter-cell rows from the base [Pa]: " +
                      " ".join("%.0f" % r.mean() for r in rows if len(r) >= 5))
        lo += L


if __name__ == "__main__":
    main()
