// The slide-base contact law on one grid column: no penetration, free
// separation, no slip, and a tangential impulse capped at s_b.
#include "baseContact.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace slide::mpm;

TEST(BaseContact, FullColumnCoversItsBase)
{
    // A base on a grid line: node on it (offset 0) and the one below (offset 1)
    // with the volumes a full half-space gives them.
    const double d = 0.5;
    const double off[2] = {1.0, 0.0};
    const double vol[2] = {d*d/48.0, 0.5*d*d};
    EXPECT_NEAR(BasalContact::contactFraction(2, vol, off, d), 1.0, 1e-14);
    const double half[2] = {0.5*vol[0], 0.5*vol[1]};
    EXPECT_NEAR(BasalContact::contactFraction(2, half, off, d), 0.5, 1e-14);
}

TEST(BaseContact, NoPenetrationAndFreeSeparation)
{
    BasalContact c;
    c.type = BasalContact::Type::frictional;
    c.s_b = 0.0;
    const double m[2] = {1.0, 1.0};
    double vx[2] = {2.0, 2.0}, vy[2] = {-1.0, 0.5};
    c.apply(2, m, vx, vy, 1.0, 0.0, 1.0, 1.0, 0.1, 0.0);
    EXPECT_EQ(vy[0], 0.0);    // pressing node: normal velocity removed
    EXPECT_EQ(vy[1], 0.5);    // separating node: free
    EXPECT_EQ(vx[0], 2.0);    // no friction
    EXPECT_EQ(vx[1], 2.0);
}

TEST(BaseContact, ColumnLeavingTheBaseIsFree)
{
    // Faster away from the base than the separation speed: no resistance.
    BasalContact c;
    c.type = BasalContact::Type::frictional;
    c.s_b = 1e9;
    const double m[2] = {1.0, 1.0};
    double vx[2] = {2.0, 2.0}, vy[2] = {0.5, 0.3};
    c.apply(2, m, vx, vy, 1.0, 0.0, 1.0, 1.0, 0.1, 0.1);
    EXPECT_EQ(vx[0], 2.0);
    EXPECT_EQ(vy[1], 0.3);
    // Within the separation speed it still resists (a resting slide's jitter).
    double ux[2] = {2.0, 2.0}, uy[2] = {0.05, 0.01};
    c.apply(2, m, ux, uy, 1.0, 0.0, 1.0, 1.0, 0.1, 0.1);
    EXPECT_EQ(ux[0], 0.0);
}

TEST(BaseContact, NoSlipStops)
{
    BasalContact c;
    const double m[1] = {3.0};
    double vx[1] = {2.0}, vy[1] = {-0.1};
    c.apply(1, m, vx, vy, 1.0, 0.0, 1.0, 1.0, 0.1, 0.0);
    EXPECT_EQ(vx[0], 0.0);
    EXPECT_EQ(vy[0], 0.0);
}

TEST(BaseContact, FrictionalImpulseIsCapped)
{
    // Sloping base (tangent at 30 deg): the tangential momentum drops by exactly
    // s_b * base length * covered fraction * dt when that is less than it has.
    BasalContact c;
    c.type = BasalContact::Type::frictional;
    c.s_b = 100.0;
    const double th = M_PI/6.0, tx = std::cos(th), ty = std::sin(th), nx = -ty, ny = tx;
    const double m[2] = {2.0, 6.0};
    double vx[2], vy[2];
    for (int k = 0; k < 2; ++k)
    {
        vx[k] = 3.0*tx - 0.2*nx;
        vy[k] = 3.0*ty - 0.2*ny;
    }
    const double dt = 1e-3, L = 0.5, f = 0.8;
    c.apply(2, m, vx, vy, tx, ty, L, f, dt, 0.0);
    double P = 0.0;
    for (int k = 0; k < 2; ++k)
    {
        P += m[k]*(vx[k]*tx + vy[k]*ty);
        EXPECT_NEAR(vx[k]*nx + vy[k]*ny, 0.0, 1e-15);
    }
    EXPECT_NEAR(P, 8.0*3.0 - 100.0*L*f*dt, 1e-12);
    // A cap larger than the momentum sticks the column.
    c.s_b = 1e9;
    c.apply(2, m, vx, vy, tx, ty, L, f, dt, 0.0);
    EXPECT_EQ(vx[0], 0.0);
    EXPECT_EQ(vy[1], 0.0);
}

TEST(BaseContact, HydroplaningResistanceGrowsWithSpeed)
{
    BasalContact c;
    c.type = BasalContact::Type::hydroplaning;
    c.rhoWater = 1000.0;
    c.C_F = 0.003;
    const double m[1] = {1000.0};
    double vx[1] = {10.0}, vy[1] = {0.0};
    c.apply(1, m, vx, vy, 1.0, 0.0, 1.0, 1.0, 0.01, 0.0);
    // s_b = 0.5 * 1000 * 0.003 * 100 = 150 Pa over 1 m for 0.01 s: 1.5 N s.
    EXPECT_NEAR(vx[0], 10.0 - 1.5/1000.0, 1e-12);
}
