// Geometry of the base: planar and polyline, arc length, normals.
#include "baseProfile.H"

#include <gtest/gtest.h>

#include <cmath>

using slide::scene::BaseProfile;

TEST(BaseProfile, PlanarSlope)
{
    const BaseProfile b = BaseProfile::planar(5.0);
    const double t = 5.0*M_PI/180.0;
    EXPECT_NEAR(b.angle(123.0), t, 1e-14);
    EXPECT_NEAR(b.point(10.0).x, 10.0*std::cos(t), 1e-12);
    EXPECT_NEAR(b.point(10.0).z, -10.0*std::sin(t), 1e-12);
    EXPECT_NEAR(b.elevation(b.point(10.0).x), b.point(10.0).z, 1e-12);
    EXPECT_NEAR(b.arcLengthAtX(b.point(10.0).x), 10.0, 1e-12);
    // The normal points out of the base, upwards.
    EXPECT_GT(b.normal(0.0).z, 0.0);
    EXPECT_NEAR(b.normal(0.0).x*b.tangent(0.0).x + b.normal(0.0).z*b.tangent(0.0).z, 0.0, 1e-15);
}

TEST(BaseProfile, PolylineArcLengthAndSegments)
{
    const BaseProfile b = BaseProfile::polyline({{0, 0}, {3, -4}, {13, -4}});
    EXPECT_DOUBLE_EQ(b.length(), 15.0);
    EXPECT_EQ(b.nSegments(), 2);
    EXPECT_DOUBLE_EQ(b.segmentStart(1), 5.0);
    EXPECT_NEAR(b.point(2.5).x, 1.5, 1e-12);
    EXPECT_NEAR(b.point(2.5).z, -2.0, 1e-12);
    EXPECT_NEAR(b.point(10.0).x, 8.0, 1e-12);
    EXPECT_NEAR(b.point(10.0).z, -4.0, 1e-12);
    EXPECT_NEAR(b.angle(1.0), std::atan2(4.0, 3.0), 1e-12);
    EXPECT_NEAR(b.angle(7.0), 0.0, 1e-12);
    EXPECT_NEAR(b.elevation(1.5), -2.0, 1e-12);
    EXPECT_NEAR(b.arcLengthAtX(8.0), 10.0, 1e-12);
    // Beyond the ends the end segments continue.
    EXPECT_NEAR(b.point(20.0).x, 18.0, 1e-12);
    EXPECT_NEAR(b.point(-5.0).x, -3.0, 1e-12);
    EXPECT_NEAR(b.point(-5.0).z, 4.0, 1e-12);
}

TEST(BaseProfile, WarnsOnceTheSlidePassesAnEndVertex)
{
    const BaseProfile b = BaseProfile::polyline({{0, 0}, {3, -4}, {13, -4}});   // 15 m long
    EXPECT_EQ(b.pastEndWarning(0.0, 15.0, 1.0), "");
    const std::string last = b.pastEndWarning(2.0, 15.5, 7.5);
    EXPECT_NE(last.find("at t = 7.5 s"), std::string::npos) << last;
    EXPECT_NE(last.find("passed the last vertex"), std::string::npos) << last;
    EXPECT_NE(last.find("base.points"), std::string::npos) << last;
    EXPECT_NE(b.pastEndWarning(-0.1, 10.0, 1.0).find("passed the first vertex"), std::string::npos);
    // A planar base has no ends.
    EXPECT_EQ(BaseProfile::planar(5.0).pastEndWarning(-10.0, 1e6, 1.0), "");
}
