// The front zone read off the particles (thickness, speed, length), and the
// record of how far a front ran under three cells thick: when it warns, what
// it counts, and that a restart carries it on.
#include "blockScene.H"
#include "baseFrame.H"
#include "frontResolution.H"
#include "materialPoints.H"
#include "mpmControls.H"
#include "mpmOutput.H"
#include "timeIntegrator.H"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace slide;

namespace
{

// Table 1's slide (40 m x 5 m) at H0/10 with 2x2 particles, geostatic, at rest.
struct SeededSlide
{
    scene::Scene sc = scene::blockScene(3.43, 40.0, 5.0, 600.0, 500.0, scene::Interface());
    mpm::MpmControls c;
    mpm::BaseFrame frame = mpm::BaseFrame::fromScene(sc);
    double d = 0.5;
    mpm::MaterialPoints points;

    SeededSlide()
    {
        c.cellsPerHeight = 10;
        c.particlesPerCell = 2;
        const mpm::UndrainedClay clay = c.clay(sc.rheology, d);
        points = mpm::MaterialPoints::seed(sc, frame, clay, c.poissonRatio, d, c.particlesPerCell, true,
                                           mpm::gridRows(frame, c));
    }
};

mpm::FrontZone zone(double thickness, double speed)
{
    mpm::FrontZone z;
    z.length = 5.0;
    z.thickness = thickness;
    z.speed = speed;
    return z;
}

} // namespace

TEST(FrontResolution, ZoneOfTheSeededSlideIsItsHeight)
{
    SeededSlide s;
    const mpm::HostPoints hp(s.points);
    const mpm::FrontZone z = mpm::frontZone(hp, s.frame, 5.0);
    EXPECT_DOUBLE_EQ(z.length, 5.0);
    EXPECT_NEAR(z.thickness, 5.0, 1e-9);
    EXPECT_EQ(z.speed, 0.0);
    // A zone longer than the slide is the slide.
    const mpm::FrontZone whole = mpm::frontZone(hp, s.frame, 100.0);
    EXPECT_NEAR(whole.length, 40.0, 1e-9);
    EXPECT_NEAR(whole.thickness, 5.0, 1e-9);
}

TEST(FrontResolution, ZoneReadsAThinnedFrontAndItsSpeed)
{
    // The foremost 5 m squashed to a fifth of its height (positions and
    // volumes), moving at 2 m/s along the base; the rest still.
    SeededSlide s;
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.position);
    auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.velocity);
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.volume);
    const double front = mpm::HostPoints(s.points).frontX();
    for (int p = 0; p < s.points.count; ++p)
    {
        if (x(p, 0) < front - 5.0) continue;
        x(p, 1) *= 0.2;
        vol(p) *= 0.2;
        v(p, 0) = 2.0;
    }
    Kokkos::deep_copy(s.points.position, x);
    Kokkos::deep_copy(s.points.velocity, v);
    Kokkos::deep_copy(s.points.volume, vol);
    const mpm::FrontZone z = mpm::frontZone(mpm::HostPoints(s.points), s.frame, 5.0);
    EXPECT_NEAR(z.thickness, 1.0, 1e-9);
    EXPECT_NEAR(z.speed, 2.0, 1e-12);
    EXPECT_NEAR(mpm::FrontResolution(s.d, 5.0, 0.01).cells(z), 2.0, 1e-9);
}

TEST(FrontResolution, TheMassFrontIsTheBodysNotAThrownParticles)
{
    // The seeded slide's mass lies evenly along its 40 m: 99 % of it lies behind
    // 39.6 m from its rear, to within a particle's spacing (0.25 m at 2x2).
    SeededSlide s;
    const mpm::HostPoints seeded(s.points);
    const double rear = seeded.rearX(), front = seeded.frontX();
    EXPECT_NEAR(front - rear, 40.0, 1e-9);
    EXPECT_NEAR(seeded.massFrontX(0.99), rear + 39.6, 0.25);
    EXPECT_LE(seeded.massFrontX(0.99), front);
    EXPECT_NEAR(seeded.massFrontX(1.0), front - 0.125, 1e-9);   // the foremost particle's centre

    // One particle thrown 500 m ahead moves the front by 500 m and the mass front
    // by no more than a particle's spacing.
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.position);
    x(0, 0) = front + 500.0;
    Kokkos::deep_copy(s.points.position, x);
    const mpm::HostPoints thrown(s.points);
    EXPECT_GT(thrown.frontX(), front + 499.0);
    EXPECT_NEAR(thrown.massFrontX(0.99), seeded.massFrontX(0.99), 0.25);
}

TEST(FrontResolution, CountsTheTravelOfAMovingFrontUnderThreeCells)
{
    mpm::FrontResolution r(0.5, 5.0, 0.01);
    EXPECT_EQ(r.observe(0.0, 0.0, zone(5.0, 0.0)), "");           // at rest: not a moving front
    EXPECT_TRUE(std::isinf(r.record().minCells));
    EXPECT_EQ(r.observe(1.0, 3.0, zone(2.0, 3.0)), "");           // 4 cells
    EXPECT_DOUBLE_EQ(r.record().minCells, 4.0);
    const std::string warning = r.observe(2.0, 8.0, zone(1.0, 4.0));   // 2 cells: warned once
    EXPECT_NE(warning.find("t = 2 s"), std::string::npos) << warning;
    EXPECT_NE(warning.find("2 cells of 0.5 m"), std::string::npos) << warning;
    EXPECT_DOUBLE_EQ(r.record().travel, 0.0);                     // the travel before it was at 4 cells
    EXPECT_EQ(r.observe(3.0, 12.0, zone(0.9, 3.0)), "");
    EXPECT_DOUBLE_EQ(r.record().travel, 4.0);
    EXPECT_DOUBLE_EQ(r.record().minCells, 1.8);
    EXPECT_DOUBLE_EQ(r.record().minCellsTime, 3.0);

    // A restart here carries the record on: the two go on alike.
    const mpm::FrontRecord saved = mpm::FrontRecord::fromValues(r.record().values(), "state", "frontResolution");
    mpm::FrontResolution restarted(0.5, 5.0, 0.01, saved);
    for (mpm::FrontResolution* q : {&r, &restarted})
    {
        EXPECT_EQ(q->observe(4.0, 13.0, zone(0.8, 0.005)), "");   // stopped: its last metre counts, no new minimum
        EXPECT_EQ(q->observe(5.0, 13.1, zone(0.8, 0.005)), "");   // creep at rest does not
        EXPECT_DOUBLE_EQ(q->record().travel, 5.0);
        EXPECT_DOUBLE_EQ(q->record().minCells, 1.8);
        EXPECT_DOUBLE_EQ(q->record().firstTime, 2.0);
    }
    EXPECT_NE(r.report(13.1).find("5 m of the 13.1 m runout"), std::string::npos) << r.report(13.1);
}

TEST(FrontResolution, AResolvedFrontIsNotWarned)
{
    mpm::FrontResolution r(0.125, 5.0, 0.01);
    EXPECT_EQ(r.observe(1.0, 3.0, zone(0.8, 4.0)), "");   // 6.4 cells
    EXPECT_EQ(r.observe(2.0, 8.0, zone(0.4, 2.0)), "");   // 3.2 cells
    EXPECT_EQ(r.observe(3.0, 9.0, zone(0.1, 0.0)), "");   // 0.8 cells, at rest
    EXPECT_DOUBLE_EQ(r.record().travel, 0.0);
    EXPECT_LT(r.record().firstTime, 0.0);
    EXPECT_DOUBLE_EQ(r.record().minCells, 3.2);
}

TEST(FrontResolution, ABrokenRecordNamesItsFileAndKey)
{
    try
    {
        mpm::FrontRecord::fromValues({1.0, 2.0}, "case/5/slideMPM.state", "frontResolution");
        FAIL() << "no error for 2 values";
    }
    catch (const scene::InputError& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("case/5/slideMPM.state"), std::string::npos) << what;
        EXPECT_NE(what.find("frontResolution"), std::string::npos) << what;
    }
}

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    Kokkos::ScopeGuard kokkos(argc, argv);
    return RUN_ALL_TESTS();
}
