"""A rigid block on a polyline base, by its equation of motion: the exact runout that the methods' rigid slides must
give, on a frictional base (constant s_b) or a hydroplaning one (s_b = 0.5 rho_w C_F V^2).

Per unit width, with positions as arc lengths along the base and the block bending over the kinks as a depth-averaged
slide does: rho' H L dV/dt = rho' g H (the drop of the base across the block's footprint) - L s_b(V). It is released
at rest with its rear at the polyline's start; its runout is the toe's travel until its downslope motion first
stops (where an adverse slope would pull it back, the methods end there too)."""
import math
import os
import shutil

# A block that climbs a flank: 40 m x 2 m, rho' 500, s_uo 30 kPa (rigid: 4 s_uo/(rho' g) = 24 m >> 2 m), on a 3 deg
# slope 100 m long and then a 2 deg rise, frictional with s_b 50 Pa, below the rise's pull (342 Pa): it stops on
# the rise and would slide back.
CLIMB = {"length": 40.0, "height": 2.0, "density": 500.0, "s_uo": 3e4, "s_b": 50.0,
         "points": [(0.0, 0.0), (99.86295, -5.23360), (299.74113, 1.74588)]}


def base_elevation(points):
    """The base's elevation as a function of the arc length along it (extended straight past its ends)."""
    arc, z = [0.0], [points[0][1]]
    for (x0, z0), (x1, z1) in zip(points, points[1:]):
        arc.append(arc[-1] + math.hypot(x1 - x0, z1 - z0))
        z.append(z1)

    def elevation(s):
        k = next((k for k in range(len(arc) - 2) if s <= arc[k + 1]), len(arc) - 2)
        return z[k] + (z[k + 1] - z[k])*(s - arc[k])/(arc[k + 1] - arc[k])
    return elevation


def speed_on_contact(points, area, density, s_b, times, fronts, rears, v0, g=9.81):
    """The block's speed by the same law when its footprint is the one a method measured (front and rear along
    the base at the given times) instead of its starting length: rho' A dV/dt = rho' g A (drop across the
    footprint)/L - s_b L, from v0 at times[0], the footprint linear in time between the samples. A method whose
    block stretches is braked by s_b over the longer contact; this separates that from an error in the base's law."""
    import numpy as np
    from scipy.integrate import solve_ivp
    elevation = base_elevation(points)

    def rhs(t, y):
        front, rear = (float(np.interp(t, times, v)) for v in (fronts, rears))
        length = front - rear
        return [g*(elevation(rear) - elevation(front))/length - s_b*length/(density*area)]
    sol = solve_ivp(rhs, (times[0], times[-1]), [v0], t_eval=times, rtol=1e-10, atol=1e-10, max_step=1.0)
    return sol.y[0]


def runout(points, length, height, density, g=9.81, s_b=None, c_f=None, rho_water=1000.0):
    from scipy.integrate import solve_ivp
    elevation = base_elevation(points)

    def rhs(t, y):
        rear, v = y
        resist = s_b if s_b is not None else 0.5*rho_water*c_f*v*v
        return [v, g*(elevation(rear) - elevation(rear + length))/length - resist/(density*height)]

    def stopped(t, y):
        return y[1] if t > 1e-6 else 1.0
    stopped.terminal, stopped.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 1e5), [0.0, 0.0], events=stopped, rtol=1e-10, atol=1e-10, max_step=0.5)
    return sol.y[0][-1]


def write_climb_case(dest, end_time=100.0):
    """The CLIMB block as a case, with coarse damDict and mpmDict (2 cells through the block for slideMPM)."""
    if os.path.exists(dest):
        shutil.rmtree(dest)
    os.makedirs(os.path.join(dest, "constant"))
    os.makedirs(os.path.join(dest, "system"))
    head = "FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n"
    c = CLIMB
    with open(os.path.join(dest, "constant", "sceneProperties"), "w") as f:
        f.write(head % "sceneProperties" + "title \"Rigid block climbing a flank\";\ng 9.81;\n"
                "slide { shape rectangle; length %g; height %g; rearPosition 0; density %g; }\n"
                "rheology { model HerschelBulkleyRemoulding; s_uo %g; eta 0; deltaRem 1; }\n"
                "base { profile polyline; points (%s); interface frictional; s_b %g; }\n"
                "ambient { phase light; }\n" % (c["length"], c["height"], c["density"], c["s_uo"],
                                                 " ".join("(%.10g %.10g)" % p for p in c["points"]), c["s_b"]))
    with open(os.path.join(dest, "system", "controlDict"), "w") as f:
        f.write(head % "controlDict" + "application slideFoam;\nstartFrom startTime;\nstartTime 0;\n"
                "stopAt endTime;\nendTime %g;\nwriteControl adjustableRunTime;\nwriteInterval 10;\n"
                "stopAtRest yes;\nrestVelocity 0.01;\n" % end_time)
    with open(os.path.join(dest, "system", "damDict"), "w") as f:
        f.write(head % "damDict" + "setting fast;\ncolumns 100;\n")
    with open(os.path.join(dest, "system", "mpmDict"), "w") as f:
        f.write(head % "mpmDict" + "setting fast;\ncellsPerHeight 2;\nparticlesPerCell 2;\nwriteFields no;\n")
    return dest


def climb_runout():
    return runout(CLIMB["points"], CLIMB["length"], CLIMB["height"], CLIMB["density"], s_b=CLIMB["s_b"])
