"""The steady flow of an infinite layer of Eq. (1)'s material (no remoulding) on a no-slip slope: its exact profile,
and the profile with slideFoam's viscosity cap, for validation/cfd/rateLayer.py and slideFoam_layer.
Table 1 Case 1's material and slope by default."""
import math

import numpy as np

THETA = 3.43
RHO = 600.0
G = 9.81
S_UO, ETA, N_HB, GDOT_REF = 150.0, 0.35, 0.15, 0.06   # Table 1 Case 1 (tutorials/table1/case01)
S = math.sin(math.radians(THETA))


CASE1 = {"s_uo": S_UO, "eta": ETA, "n": N_HB, "gdotRef": GDOT_REF}


def yield_depth(strength):
    """The thickest layer a rate-free strength holds at rest on the slope: s/(rho' g sin(theta)) [m]."""
    return strength/(RHO*G*S)


def exact(h, rho_ambient=0.0, material=None, surface_slope=0.0):
    """Yield height, plug speed, basal rate and decay length of the steady layer of depth h, and its profile, for
    Eq. (1) without remoulding (`material`: s_uo, eta, n, gdotRef; Case 1's by default; n = 1 is Bingham's). The
    layer's along-slope weight is its excess over the ambient's (which the ambient's hydrostatic pressure carries,
    and which slideFoam's alongSlopeGravity leaves out): rho' - rho_ambient. surface_slope dh/ds: a layer whose
    thickness changes slowly along the base, taken as locally uniform, is driven by its hydrostatic pressure's
    gradient as well, the weight along the base becoming rho g (S - cos(theta) dh/ds)."""
    mat = dict(CASE1, **(material or {}))
    s_uo, eta, n, gdot_ref = mat["s_uo"], mat["eta"], mat["n"], mat["gdotRef"]
    w = (RHO - rho_ambient)*G*(S - math.cos(math.radians(THETA))*surface_slope)
    xb = w*h/s_uo - 1.0
    if xb <= 0.0:
        raise ValueError("a layer %g m deep is held by s_uo (depth at yield %g m)" % (h, s_uo/w))
    m = (n + 1.0)/n
    a = plug_coefficient(mat, w)
    zy = h - s_uo/w

    def u(z):
        x = np.maximum(w*(h - np.asarray(z, dtype=float))/s_uo - 1.0, 0.0)
        return a*(xb**m - x**m)
    return {"yield_height": zy, "plug": a*xb**m, "basal_rate": gdot_ref*(xb/eta)**(1.0/n),
            "decay_length": n*(w*h - s_uo)/w, "relaxation_time": RHO*h*a*xb**m/(n*(w*h - s_uo)),
            "u": u}


def capped_profile(h, rho_ambient, mu_max, material=None, points=200001):
    """The steady profile of the layer with slideFoam's regularisation `cap` (the apparent viscosity s_u/gdot
    capped at mu_max: below the rate g_c where s_u(g_c)/g_c = mu_max the material creeps at tau/mu_max), by
    quadrature of the rate over the depth: what slideFoam converges to as its cells shrink. Returns u(z)."""
    mat = dict(CASE1, **(material or {}))
    s_uo, eta, n, gdot_ref = mat["s_uo"], mat["eta"], mat["n"], mat["gdotRef"]
    w = (RHO - rho_ambient)*G*S

    def strength(g):
        return s_uo*(1.0 + eta*(g/gdot_ref)**n)
    lo, hi = 1e-300, 1e6        # g_c: s_u(g)/g falls through mu_max once
    for _ in range(400):
        mid = math.sqrt(lo*hi)
        lo, hi = (mid, hi) if strength(mid)/mid > mu_max else (lo, mid)
    g_c = math.sqrt(lo*hi)
    z = np.linspace(0.0, h, points)
    tau = w*(h - z)
    x = np.maximum(tau/s_uo - 1.0, 0.0)
    rate = np.where(tau <= mu_max*g_c, tau/mu_max, gdot_ref*(x/eta)**(1.0/n))
    u = np.concatenate(([0.0], np.cumsum(0.5*(rate[1:] + rate[:-1])*np.diff(z))))
    return lambda zz: np.interp(zz, z, u)



def plug_coefficient(material, w):
    """a of the steady layer's plug speed a x_b^((n + 1)/n), x_b = w h/s_uo - 1 (w: the weight along the base per
    unit volume): the same for every depth."""
    s_uo, eta, n, gdot_ref = material["s_uo"], material["eta"], material["n"], material["gdotRef"]
    return gdot_ref*s_uo/w*eta**(-1.0/n)*n/(n + 1.0)


def rest_depth(rest_velocity, material=None):
    """The depth of the steady layer whose plug moves at rest_velocity (exact()'s plug speed inverted). Eq. (1)'s
    rate term vanishes only with the rate, so a long deposit thicker than its yield depth creeps on and thins until
    its plug is about this slow: where a method's rest test (everything slower than restVelocity) stops it."""
    mat = dict(CASE1, **(material or {}))
    w = RHO*G*S
    xb = (rest_velocity/plug_coefficient(mat, w))**(mat["n"]/(mat["n"] + 1.0))
    return mat["s_uo"]*(1.0 + xb)/w
