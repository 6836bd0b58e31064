// Quadratic B-spline shape functions: partition of unity, linear
// reproduction (what makes APIC's affine transfer exact), gradients, the
// half-space integral the level-set base contact uses, the base's span of
// B-splines fitted to a planar base, and the quadratic transfer mode.
#include "quadraticBSpline.H"

#include <gtest/gtest.h>

#include <algorithm>

using slide::mpm::QuadraticBSpline;

TEST(QuadraticBSpline, PartitionOfUnityAndLinearReproduction)
{
    for (double x = -3.0; x <= 3.0; x += 0.0137)
    {
        int first;
        double w[3], dw[3];
        QuadraticBSpline::evaluate(x, first, w, dw);
        double sw = 0.0, sx = 0.0, sdw = 0.0, sxdw = 0.0;
        for (int a = 0; a < 3; ++a)
        {
            EXPECT_GE(w[a], 0.0);
            EXPECT_NEAR(w[a], QuadraticBSpline::value(x - (first + a)), 1e-14);
            sw += w[a];
            sx += w[a]*(first + a);
            sdw += dw[a];
            sxdw += dw[a]*(first + a);
        }
        EXPECT_NEAR(sw, 1.0, 1e-14) << x;
        EXPECT_NEAR(sx, x, 1e-13) << x;       // sum w_i x_i = x
        EXPECT_NEAR(sdw, 0.0, 1e-13) << x;    // gradient of a constant
        EXPECT_NEAR(sxdw, 1.0, 1e-13) << x;   // gradient of x
        // APIC: sum w_i (x_i - x)^2 = 1/4 (cell units) for every x.
        double m2 = 0.0;
        for (int a = 0; a < 3; ++a) m2 += w[a]*(first + a - x)*(first + a - x);
        EXPECT_NEAR(m2, 1.0/QuadraticBSpline::apicInverseFactor, 1e-13);
    }
}

TEST(QuadraticBSpline, DerivativeMatchesFiniteDifference)
{
    const double h = 1e-6;
    for (double x = -2.2; x <= 2.2; x += 0.071)
    {
        int first;
        double w[3], dw[3];
        QuadraticBSpline::evaluate(x, first, w, dw);
        for (int a = 0; a < 3; ++a)
        {
            const double t = x - (first + a);
            const double fd = (QuadraticBSpline::value(t + h) - QuadraticBSpline::value(t - h))/(2.0*h);
            EXPECT_NEAR(dw[a], fd, 1e-6);
        }
    }
}

TEST(QuadraticBSpline, HalfSpaceIntegral)
{
    // Midpoint rule on a fine grid against the closed form.
    for (double t = -2.0; t <= 2.0; t += 0.05)
    {
        double s = 0.0;
        const int n = 40000;
        const double a = t, b = 2.0, du = (b - a)/n;
        for (int k = 0; k < n; ++k) s += QuadraticBSpline::value(a + (k + 0.5)*du)*du;
        EXPECT_NEAR(QuadraticBSpline::integralFrom(t), t < 1.5 ? s : 0.0, 1e-8) << t;
    }
    // A base on a grid line: the node on it collects half, the one below 1/48.
    EXPECT_NEAR(QuadraticBSpline::integralFrom(0.0), 0.5, 1e-15);
    EXPECT_NEAR(QuadraticBSpline::integralFrom(1.0), 1.0/48.0, 1e-15);
}

namespace
{

// The y weights of a fitted base's stencil at height s (cells above the
// base); node k of the stencil is the lattice row first + k, row -1 the base's.
struct FittedColumn
{
    int first;
    double w[3], dw[3], dy[3], q[3], invQ, apicY;
    bool baseSpan;
    explicit FittedColumn(const double s, const bool allQuadratic = false)
    {
        const slide::mpm::Stencil st(0.0, s, 0.0, 1.0, 0, 0, true, allQuadratic);
        first = st.by;
        baseSpan = st.baseSpan;
        for (int k = 0; k < 3; ++k)
        {
            w[k] = st.wy[k];
            dw[k] = st.dwy[k];
            dy[k] = st.dy[k];
            q[k] = st.quadratic ? st.q[k] : 0.0;
        }
        invQ = st.quadratic ? st.invQ : 0.0;
        apicY = st.apicY;
    }
};

// The three functions of the base's span in closed form (Steffen et al. 2008).
double fittedBaseFunction(const int row, const double s)
{
    if (row == -1) return s < 1.0 ? (1.0 - s)*(1.0 - s) : 0.0;
    if (row == 0) return s < 1.0 ? 2.0*s - 1.5*s*s : (s < 2.0 ? 0.5*(2.0 - s)*(2.0 - s) : 0.0);
    return QuadraticBSpline::value(s - (row + 0.5));   // interior rows: the standard function at (row + 1/2) d
}

} // namespace

TEST(QuadraticBSpline, FittedBaseIsAKnotLine)
{
    // On the base the base's function is 1 and every other 0 (a velocity set
    // on the base's nodes is the base line's and no other's); the weights are
    // a partition of unity reproducing y with the base node on the base, and
    // match the open knot vector's functions; above the base's cell nothing
    // changes.
    for (double s = 0.0; s < 3.0; s += 0.0173)
    {
        const FittedColumn c(s);
        EXPECT_EQ(c.baseSpan, s < 1.0) << s;
        double sw = 0.0, sdy = 0.0, sdw = 0.0, sydw = 0.0;
        for (int k = 0; k < 3; ++k)
        {
            const int row = c.first + k;
            const double y = row == -1 ? 0.0 : row + 0.5;   // Greville abscissae
            EXPECT_NEAR(c.dy[k], y - s, 1e-14) << s;
            EXPECT_NEAR(c.w[k], fittedBaseFunction(row, s), 1e-14) << "row " << row << ", s " << s;
            EXPECT_GE(c.w[k], 0.0);
            sw += c.w[k];
            sdy += c.w[k]*c.dy[k];
            sdw += c.dw[k];
            sydw += c.dw[k]*y;
        }
        EXPECT_NEAR(sw, 1.0, 1e-14) << s;
        EXPECT_NEAR(sdy, 0.0, 1e-14) << s;
        EXPECT_NEAR(sdw, 0.0, 1e-13) << s;
        EXPECT_NEAR(sydw, 1.0, 1e-13) << s;
    }
    const FittedColumn onBase(0.0);
    EXPECT_EQ(onBase.first, -1);
    EXPECT_DOUBLE_EQ(onBase.w[0], 1.0);
    EXPECT_DOUBLE_EQ(onBase.w[1], 0.0);
    EXPECT_DOUBLE_EQ(onBase.w[2], 0.0);
    // A particle put back onto the base a round-off below it weighs as on it.
    const FittedColumn below(-1e-12);
    EXPECT_EQ(below.first, -1);
    EXPECT_DOUBLE_EQ(below.w[0], 1.0);
}

TEST(QuadraticBSpline, FittedBaseDerivativesAndContinuity)
{
    const double h = 1e-6;
    for (double s = 0.01; s < 2.5; s += 0.043)
    {
        const FittedColumn c(s);
        for (int k = 0; k < 3; ++k)
        {
            const int row = c.first + k;
            const double fd = (fittedBaseFunction(row, s + h) - fittedBaseFunction(row, s - h))/(2.0*h);
            EXPECT_NEAR(c.dw[k], fd, 1e-6) << "row " << row << ", s " << s;
        }
    }
    // C1 across the top of the base's cell: row 0's function and slope agree from both sides.
    const double e = 1e-9;
    const FittedColumn lo(1.0 - e), hi(1.0 + e);
    EXPECT_EQ(lo.first, -1);
    EXPECT_EQ(hi.first, 0);
    EXPECT_NEAR(lo.w[1], hi.w[0], 1e-8);
    EXPECT_NEAR(lo.dw[1], hi.dw[0], 1e-8);
    EXPECT_NEAR(lo.w[0], 0.0, 1e-8);
    EXPECT_NEAR(lo.dw[0], 0.0, 1e-8);
}

TEST(QuadraticBSpline, QuadraticModeCarriesThreeRowsExactly)
{
    // APIC's y factor is 1/D_yy (4 off the base's span), and the quadratic
    // mode is orthogonal to 1 and dy under the weights, so the three modes take
    // any three nodal values to the particle and back unchanged, in the base's
    // span and above it, wherever the mode's norm is above its floor (it is
    // below only within about a tenth of a cell of the base, of the base
    // cell's top and of the midpoints between rows, where the floor damps it).
    for (double s = 0.02; s < 3.0; s += 0.037)
    {
        const FittedColumn c(s, true);
        EXPECT_TRUE(c.baseSpan == (s < 1.0) && (c.baseSpan || c.apicY == QuadraticBSpline::apicInverseFactor)) << s;
        double D = 0.0, q0 = 0.0, q1 = 0.0, N = 0.0;
        for (int k = 0; k < 3; ++k)
        {
            D += c.w[k]*c.dy[k]*c.dy[k];
            q0 += c.w[k]*c.q[k];
            q1 += c.w[k]*c.q[k]*c.dy[k];
            N += c.w[k]*c.q[k]*c.q[k];
        }
        EXPECT_NEAR(c.apicY, 1.0/D, 1e-12*c.apicY) << s;
        EXPECT_NEAR(q0, 0.0, 1e-14) << s;
        EXPECT_NEAR(q1, 0.0, 1e-14) << s;
        EXPECT_NEAR(c.invQ, 1.0/std::max(N, QuadraticBSpline::minQuadraticNorm), 1e-10*c.invQ) << s;
        if (N < QuadraticBSpline::minQuadraticNorm) continue;
        const double v[3] = {0.3, -1.7, 2.2};   // any nodal values
        double v0 = 0.0, c1 = 0.0, c2 = 0.0;
        for (int k = 0; k < 3; ++k)
        {
            v0 += c.w[k]*v[k];
            c1 += c.w[k]*v[k]*c.dy[k];
            c2 += c.w[k]*v[k]*c.q[k];
        }
        c1 *= c.apicY;
        c2 *= c.invQ;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(v0 + c1*c.dy[k] + c2*c.q[k], v[k], 1e-11) << s;
    }
    // The rows where 2 x 2 particles are seeded are far above the floor.
    for (double s : {0.25, 0.75, 1.25, 1.75})
    {
        const FittedColumn c(s, true);
        EXPECT_LT(c.invQ, 0.9/QuadraticBSpline::minQuadraticNorm) << s;
    }
}
