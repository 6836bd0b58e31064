// Quadratic B-spline shape functions: partition of unity, linear
// reproduction (what makes APIC's affine transfer exact), gradients, and the
// half-space integral the base contact uses.
#include "quadraticBSpline.H"

#include <gtest/gtest.h>

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
