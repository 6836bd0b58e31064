// slideMPM on small scenes: conservation of the transfers, a rigid block on a
// frictional slope against the sliding law (on a planar base and on a
// polyline base whose grid rows follow it), an elastic layer's settlement
// under gravity against the analytical one (and what the B-bar changes at
// nu = 0.49), no penetration of the base, a stable slide that stays, and
// particle splitting (what it keeps exactly, and what it changes in a runout),
// the energy budget (a sliding block's friction, PIC's dissipation), and a block
// released above the base falling onto it (the base holds only material that touches it).
#include "backgroundGrid.H"
#include "blockScene.H"
#include "baseFrame.H"
#include "materialPoints.H"
#include "mpmControls.H"
#include "mpmOutput.H"
#include "siteSampling.H"
#include "timeIntegrator.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <vector>

using namespace slide;

namespace
{

using scene::blockScene;

// The controls with Young's modulus E instead of their ratio to s_uo.
mpm::MpmControls withYoungsModulus(mpm::MpmControls c, const double E, const double s_uo)
{
    c.youngsModulusRatio = E/s_uo;
    return c;
}

// The strength of a block that slides as a rigid body: 150 times the shear
// stress of a 1 m block of rho' 500 on a 10 degree slope (below 200 Pa with
// s_b = 200 Pa on the base). E = 100 s_uo sets the time step, which scales as
// 1/sqrt(E): with 100 kPa these tests took 1.8 times as many steps. With
// 10 kPa the block rang along its length with a period of 0.7 s and settled
// 1.3 mm: its speed at 1 s was 5.6 % above the law's (5 % allowed).
constexpr double rigidStrength = 3e4;

// Table 1 Case 11's slide: 40 m x 5 m, 5 kPa, very sensitive (S_t = 40, xi95 = 10), no rate effect.
scene::Scene case11Scene()
{
    scene::Interface iface;
    scene::Scene sc = blockScene(3.43, 40.0, 5.0, 600.0, 5000.0, iface);
    sc.rheology.deltaRem = 0.025;
    sc.rheology.xi95 = 10.0;
    return sc;
}

struct SceneRun
{
    scene::Scene sc;
    mpm::MpmControls controls;
    mpm::BaseFrame frame;
    mpm::UndrainedClay clay;
    mpm::MaterialPoints points;
    mpm::BackgroundGrid grid;
    mpm::TimeIntegrator integrator;
    mpm::StepStatistics stats;
    double t = 0.0;

    SceneRun(const scene::Scene& s, const mpm::MpmControls& c, double E, bool geostatic = true)
    :
        sc(s), controls(c), frame(mpm::BaseFrame::fromScene(s)),
        clay(withYoungsModulus(c, E, s.rheology.s_uo).clay(s.rheology, s.slide.height/c.cellsPerHeight)),
        points(mpm::MaterialPoints::seed(s, frame, clay, c.poissonRatio, s.slide.height/c.cellsPerHeight,
                                         c.particlesPerCell, geostatic, mpm::gridRows(frame, c))),
        grid(s.slide.height/c.cellsPerHeight, frame.rearX, mpm::gridRows(frame, c)),
        integrator(frame, clay, mpm::basalContact(s.interface), c, s.slide.density),
        stats(mpm::TimeIntegrator::statistics(points, grid.rows))
    {}

    void advance(double T) { mpm::advanceTo(integrator, points, grid, t, T, stats); }
};

mpm::MpmControls controls(int cellsPerHeight, int ppc, double nu = 0.49)
{
    mpm::MpmControls c;
    c.cellsPerHeight = cellsPerHeight;
    c.particlesPerCell = ppc;
    c.poissonRatio = nu;
    return c;
}

// Mass-averaged displacement along the frame's x and y, and mean x velocity.
void centreOfMass(const mpm::HostPoints& hp, double& x, double& y, double& u)
{
    double M = 0.0;
    x = y = u = 0.0;
    for (int p = 0; p < hp.count; ++p)
    {
        M += hp.mass(p);
        x += hp.mass(p)*hp.position(p, 0);
        y += hp.mass(p)*hp.position(p, 1);
        u += hp.mass(p)*hp.velocity(p, 0);
    }
    x /= M;
    y /= M;
    u /= M;
}

} // namespace

TEST(SlideMPM, TransfersConserveMassAndMomentum)
{
    // After a step of a slumping slide, the grid holds the particles' mass and
    // (APIC) momentum exactly: partition of unity and linear reproduction.
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 50.0;
    SceneRun r(blockScene(10.0, 4.0, 1.0, 600.0, 200.0, iface), controls(8, 2), 100.0*200.0);
    r.advance(0.5);
    const double dt = r.integrator.stableTimeStep(r.grid.d, r.stats.maxSpeed);
    ASSERT_TRUE(r.grid.fit(r.stats.xmin, r.stats.xmax, r.stats.ymin, r.stats.ymax, 1ull << 30));
    r.integrator.step(r.points, r.grid, dt);   // leaves the grid of the step behind
    // Particle state after the step versus the grid's momentum before the forces:
    // check the transfer alone on a fresh scatter of the current particles.
    r.stats = mpm::TimeIntegrator::statistics(r.points, r.grid.rows);
    ASSERT_TRUE(r.grid.fit(r.stats.xmin, r.stats.xmax, r.stats.ymin, r.stats.ymax, 1ull << 30));
    const mpm::HostPoints hp(r.points);
    r.integrator.step(r.points, r.grid, 0.0);  // dt = 0: the grid holds exactly the transfer
    auto nodal = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.grid.nodal);
    double mg = 0.0, px = 0.0, py = 0.0, mp = 0.0, qx = 0.0, qy = 0.0;
    for (int i = 0; i < r.grid.ni; ++i)
        for (int j = 0; j < r.grid.nj; ++j)
        {
            mg += nodal(i, j, mpm::BackgroundGrid::mass);
            px += nodal(i, j, mpm::BackgroundGrid::momentumX);
            py += nodal(i, j, mpm::BackgroundGrid::momentumY);
        }
    for (int p = 0; p < hp.count; ++p)
    {
        mp += hp.mass(p);
        qx += hp.mass(p)*hp.velocity(p, 0);
        qy += hp.mass(p)*hp.velocity(p, 1);
    }
    EXPECT_NEAR(mg, mp, 1e-12*mp);
    const double scale = mp*std::max(1e-3, r.stats.maxSpeed);
    EXPECT_NEAR(px, qx, 1e-11*scale);
    EXPECT_NEAR(py, qy, 1e-11*scale);
    EXPECT_GT(std::fabs(qx), 1e-3*mp);   // the slide is moving: the check is not trivial
}

TEST(SlideMPM, BlockSumsAreTheParticleSums)
{
    // nodeSums perBlock (blocks of particles summed in scratch memory, then
    // added to the grid) gathers the sums perParticle does, in another order:
    // every node's mass, momentum and volume agree to round-off, for blocks
    // within a column of cells and for blocks that run across columns.
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 50.0;
    SceneRun r(blockScene(10.0, 4.0, 1.0, 600.0, 200.0, iface), controls(8, 2), 100.0*200.0);
    r.advance(0.5);   // moved, and sorted by cell on the way
    ASSERT_TRUE(r.grid.fit(r.stats.xmin, r.stats.xmax, r.stats.ymin, r.stats.ymax, 1ull << 30));
    const double dt = r.integrator.stableTimeStep(r.grid.d, r.stats.maxSpeed);
    auto sums = [&](const mpm::MpmControls::NodeSums how, const int block)
    {
        mpm::MpmControls c = r.controls;
        c.nodeSums = how;
        c.blockParticles = block;
        const mpm::TimeIntegrator integrator(r.frame, r.clay, mpm::basalContact(r.sc.interface), c, r.sc.slide.density);
        integrator.particleToGrid(r.points, r.grid, dt);
        auto copy = Kokkos::create_mirror(r.grid.nodal);   // a copy, not the grid's own view on the host
        Kokkos::deep_copy(copy, r.grid.nodal);
        return copy;
    };
    const auto reference = sums(mpm::MpmControls::NodeSums::perParticle, 128);
    double largest[4] = {0.0, 0.0, 0.0, 0.0};
    int filled = 0;
    for (int i = 0; i < r.grid.ni; ++i)
        for (int j = 0; j < r.grid.nj; ++j)
        {
            for (int c = 0; c < 4; ++c) largest[c] = std::max(largest[c], std::fabs(reference(i, j, c)));
            if (reference(i, j, mpm::BackgroundGrid::mass) > 0.0) ++filled;
        }
    ASSERT_GT(filled, 100);
    ASSERT_GT(largest[mpm::BackgroundGrid::momentumX], 0.0);   // the slide moves: momentum is summed too
    for (const int block : {16, 128, 1024})
    {
        const auto blocks = sums(mpm::MpmControls::NodeSums::perBlock, block);
        double worst = 0.0;
        for (int i = 0; i < r.grid.ni; ++i)
            for (int j = 0; j < r.grid.nj; ++j)
                for (int c = 0; c < 4; ++c)
                {
                    worst = std::max(worst, std::fabs(blocks(i, j, c) - reference(i, j, c))/largest[c]);
                }
        std::cout << "blocks of " << block << " particles: largest difference " << worst
                  << " of the largest node value" << std::endl;
        EXPECT_LT(worst, 1e-13) << "blocks of " << block << " particles";
    }
}

TEST(SlideMPM, RigidBlockOnFrictionalSlopeFollowsTheSlidingLaw)
{
    // s_uo far above every stress: the block slides as a rigid body with
    // a = g sin(theta) - s_b/(rho H).
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 200.0;
    const scene::Scene sc = blockScene(5.0, 8.0, 1.0, 500.0, rigidStrength, iface);
    SceneRun r(sc, controls(8, 2), 100.0*rigidStrength);
    double x0, y0, u0;
    centreOfMass(mpm::HostPoints(r.points), x0, y0, u0);
    const double a = sc.g*std::sin(5.0*M_PI/180.0) - iface.s_b/(sc.slide.density*sc.slide.height);
    // The release rings elastically (stick-slip of the basal nodes while the
    // block's shear strain builds up); the sliding law holds from then on.
    r.advance(1.0);
    double x1, y1, u1;
    centreOfMass(mpm::HostPoints(r.points), x1, y1, u1);
    EXPECT_NEAR(u1, a*1.0, 0.05*a);
    r.advance(3.0);
    double x3, y3, u3;
    centreOfMass(mpm::HostPoints(r.points), x3, y3, u3);
    EXPECT_NEAR((u3 - u1)/2.0, a, 0.01*a);
    EXPECT_NEAR(x3 - x0, 0.5*a*9.0, 0.03*0.5*a*9.0);
    EXPECT_NEAR(y3, y0, 1e-3*sc.slide.height);
    // Frictionless: a = g sin(theta).
    iface.s_b = 0.0;
    SceneRun f(blockScene(5.0, 8.0, 1.0, 500.0, rigidStrength, iface), controls(8, 2), 100.0*rigidStrength);
    f.advance(1.0);
    double x, y, u;
    centreOfMass(mpm::HostPoints(f.points), x, y, u);
    EXPECT_NEAR(u, sc.g*std::sin(5.0*M_PI/180.0), 0.01*sc.g*std::sin(5.0*M_PI/180.0));
}

TEST(SlideMPM, SiteOnTheSlopeSeesTheSlidingBlockArriveAtTheLawsTime)
{
    // The block of the test above and a site 1 m ahead of its front: sampled every
    // step, the block arrives when its foremost particle centre has slid there under
    // a = g sin(theta) - s_b/(rho H), covers the site 1 m thick and runs over it at a t.
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 200.0;
    scene::Scene sc = blockScene(5.0, 8.0, 1.0, 500.0, rigidStrength, iface);
    sc.sites = {{"pipeline", 9.0}, {"beyond", 40.0}};
    SceneRun r(sc, controls(8, 2), 100.0*rigidStrength);
    const mpm::SiteSampler sampler(sc.sites, r.frame, r.grid.d);
    const std::filesystem::path dir = std::filesystem::temp_directory_path()
        /("slideMPMSiteTest_" + std::to_string(::getpid()));
    output::SiteMonitor sites(sc.sites, sc.slide.frontPosition(), dir.string(), "slideMPM", false, 0.0);
    const double xmax0 = r.stats.xmax;
    sites.observe(0.0, sampler.sample(r.points, r.stats));
    mpm::advanceTo(r.integrator, r.points, r.grid, r.t, 3.0, r.stats, nullptr,
                   [&](double t) { sites.observe(t, sampler.sample(r.points, r.stats)); });
    const double a = sc.g*std::sin(5.0*M_PI/180.0) - iface.s_b/(sc.slide.density*sc.slide.height);
    const output::SiteRecord& at = sites.records()[0];
    EXPECT_NEAR(at.arrival, std::sqrt(2.0*(9.0 - xmax0)/a), 0.03*std::sqrt(2.0*(9.0 - xmax0)/a));
    // The stiff block rings from its release: the mean velocity lies within 1-2 % of the law
    // (the test above), the particles over the site within 5 % (measured +4.6 % at 3 s).
    EXPECT_NEAR(at.peakSpeed, a*3.0, 0.05*a*3.0);
    EXPECT_NEAR(at.peakSpeedTime, 3.0, 1e-9);
    EXPECT_NEAR(at.maxThickness, 1.0, 0.01);
    EXPECT_TRUE(at.now.covered);
    // h V^2 at its largest at the end, where the block runs fastest over the site.
    EXPECT_NEAR(at.peakMomentumFlux, at.now.thickness*at.now.velocity*at.now.velocity,
                0.02*at.now.thickness*at.now.velocity*at.now.velocity);
    // The device's reduction is the tent-weighted sum over the particles, as on the host.
    const mpm::HostPoints hp(r.points);
    double area = 0.0, mass = 0.0, momentum = 0.0;
    for (int p = 0; p < hp.count; ++p)
    {
        const double w = std::max(0.0, 1.0 - std::fabs(hp.position(p, 0) - 9.0)/r.grid.d);
        area += w*hp.volume(p);
        mass += w*hp.mass(p);
        momentum += w*hp.mass(p)*hp.velocity(p, 0);
    }
    EXPECT_NEAR(at.now.thickness, area/r.grid.d, 1e-12);
    EXPECT_NEAR(at.now.velocity, momentum/mass, 1e-12);
    EXPECT_TRUE(std::isnan(sites.records()[1].arrival));
    std::filesystem::remove_all(dir);
}

namespace
{

// Mass-averaged velocity and displacement along a direction (tx, ty) of the frame.
void alongDirection(const mpm::HostPoints& hp, const double tx, const double ty, double& x, double& u)
{
    double M = 0.0;
    x = u = 0.0;
    for (int p = 0; p < hp.count; ++p)
    {
        M += hp.mass(p);
        x += hp.mass(p)*(hp.position(p, 0)*tx + hp.position(p, 1)*ty);
        u += hp.mass(p)*(hp.velocity(p, 0)*tx + hp.velocity(p, 1)*ty);
    }
    x /= M;
    u /= M;
}

// The sliding law's acceleration, a/(g sin(theta) - s_b/(rho H)) - 1, of a
// rigid block on the 10 degree first segment of a base that flattens 60 m on,
// from 1 to 3 s, and the block's lowest height above the segment at 3 s.
void blockOnPolyline(const mpm::MpmControls::BaseBoundary base, double& accelerationError, double& lowest,
                     bool& sheared)
{
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 200.0;
    scene::Scene sc = blockScene(10.0, 8.0, 1.0, 500.0, rigidStrength, iface);
    const double theta = 10.0*M_PI/180.0;
    sc.base = scene::BaseProfile::polyline({{0.0, 0.0}, {60.0*std::cos(theta), -60.0*std::sin(theta)},
                                            {60.0*std::cos(theta) + 200.0, -60.0*std::sin(theta)}});
    mpm::MpmControls c = controls(8, 2);
    c.baseBoundary = base;
    SceneRun r(sc, c, 100.0*rigidStrength);
    sheared = r.grid.rows.on;
    // The segment's downslope tangent in the frame of the chord (2.3 deg below it).
    const double slope = r.frame.level.slope(0.0), n = std::sqrt(1.0 + slope*slope);
    const double tx = 1.0/n, ty = slope/n;
    const double a = sc.g*std::sin(theta) - iface.s_b/(sc.slide.density*sc.slide.height);
    r.advance(1.0);
    double x1, u1, x3, u3;
    alongDirection(mpm::HostPoints(r.points), tx, ty, x1, u1);
    r.advance(3.0);
    const mpm::HostPoints hp(r.points);
    alongDirection(hp, tx, ty, x3, u3);
    accelerationError = (u3 - u1)/2.0/a - 1.0;
    lowest = 1e300;
    for (int p = 0; p < hp.count; ++p)
    {
        lowest = std::min(lowest, hp.position(p, 1) - r.frame.level.height(hp.position(p, 0)));
    }
}

} // namespace

TEST(SlideMPM, RigidBlockOnAPolylineBaseFollowsTheSlidingLaw)
{
    // The grid lies in the frame of the base's chord, so the first segment
    // crosses its rows at 7.7 deg. Fitted, the rows follow the segment and the
    // block slides as on a planar base (1 % there; measured -0.3 %); cut by the
    // grid (the staircase of nodes on and below the base) +1.9 % (+2.3 % with s_uo 100 kPa), and on the
    // Mediterranean escarpment the cut base dissipated half of gravity's work
    // (validation/mpm/README.md, open problem 11).
    using Base = mpm::MpmControls::BaseBoundary;
    double fittedError, fittedLowest, cutError, cutLowest;
    bool fittedSheared, cutSheared;
    blockOnPolyline(Base::fitted, fittedError, fittedLowest, fittedSheared);
    blockOnPolyline(Base::levelSet, cutError, cutLowest, cutSheared);
    std::cout << "acceleration error against the sliding law: rows along the base " << fittedError
              << ", base cut by the grid " << cutError << std::endl;
    EXPECT_TRUE(fittedSheared);
    EXPECT_FALSE(cutSheared);
    EXPECT_LT(std::fabs(fittedError), 0.01);
    EXPECT_GE(fittedLowest, -1e-9);
    EXPECT_GE(cutLowest, -1e-9);
}

namespace
{

// Time-averaged mean vertical displacement of the middle third of a long
// elastic layer released stress free under gravity on a no-slip base; the
// undamped oscillation averages to the static settlement.
double layerSettlement(double nu, int cellsPerHeight, double L, mpm::MpmControls::BaseBoundary base)
{
    scene::Interface iface;
    const double H = 1.0, rho = 1000.0, E = 1e6;
    scene::Scene sc = blockScene(0.0, L, H, rho, 1e12, iface);
    mpm::MpmControls c = controls(cellsPerHeight, 2, nu);
    c.baseBoundary = base;
    SceneRun r(sc, c, E, false);
    const mpm::HostPoints h0(r.points);
    const double M = E*(1.0 - nu)/((1.0 + nu)*(1.0 - 2.0*nu));
    const double period = 4.0*H/std::sqrt(M/rho);
    const double T = 12.0*period;
    double sum = 0.0, time = 0.0;
    while (r.t < T - 1e-9)
    {
        const double t0 = r.t;
        r.advance(std::min(T, r.t + period/20.0));
        const mpm::HostPoints hp(r.points);
        double s = 0.0, m = 0.0;
        for (int p = 0; p < hp.count; ++p)
        {
            if (h0.position(p, 0) < 0.4*L || h0.position(p, 0) > 0.6*L) continue;
            s += hp.mass(p)*(hp.position(p, 1) - h0.position(p, 1));
            m += hp.mass(p);
        }
        sum += (s/m)*(r.t - t0);
        time += r.t - t0;
    }
    return -sum/time;
}

} // namespace

TEST(SlideMPM, ElasticLayerSettlesAsTheAnalyticalColumn)
{
    // 1D confined compression: mean displacement over the depth is
    // rho g H^2/(3 M), M = lambda + 2G the constrained modulus. With the base a
    // knot line of the B-splines (fitted, the default) the no-slip condition
    // acts on the base line: measured +0.6 % at H/8 and -0.5 % at H/16 for
    // nu = 0.3. Where the base cuts the grid (levelSet) its nodes hold the
    // lowest cell, an error first order in the cell size: +7.5 % and +3.3 %.
    // At nu = 0.49 the free ends reach further in, so the layer is longer.
    using Base = mpm::MpmControls::BaseBoundary;
    for (double nu : {0.3, 0.49})
    {
        const double E = 1e6, M = E*(1.0 - nu)/((1.0 + nu)*(1.0 - 2.0*nu));
        const double exact = 1000.0*9.81*1.0/(3.0*M);
        const double L = nu < 0.4 ? 12.0 : 40.0;
        const double coarse = layerSettlement(nu, 8, L, Base::fitted), fine = layerSettlement(nu, 16, L, Base::fitted);
        const double cutCoarse = layerSettlement(nu, 8, L, Base::levelSet);
        const double cutFine = layerSettlement(nu, 16, L, Base::levelSet);
        std::printf("nu %.2f: settlement H/8 %+.1f %%, H/16 %+.1f %% (base cutting the grid: %+.1f %%, %+.1f %%) "
                    "of the exact %.4e m\n", nu, 100.0*(coarse/exact - 1.0), 100.0*(fine/exact - 1.0),
                    100.0*(cutCoarse/exact - 1.0), 100.0*(cutFine/exact - 1.0), exact);
        EXPECT_NEAR(coarse, exact, 0.02*exact) << "nu = " << nu;
        EXPECT_NEAR(fine, exact, 0.02*exact) << "nu = " << nu;
        EXPECT_GT(cutCoarse - exact, 0.05*exact) << "nu = " << nu;
        EXPECT_LT(std::fabs(cutFine - exact), 0.6*std::fabs(cutCoarse - exact)) << "nu = " << nu;
    }
}

namespace
{

// A free-standing elastic block on a frictionless base, released stress free
// under gravity: sigma_yy = -rho g (H - y), sigma_xx = sigma_xy = 0,
// sigma_zz = nu sigma_yy solve it exactly, with a mean settlement of
// (1 - nu^2) rho g H^2/(3 E) and a pressure (1 + nu) rho g (H - y)/3.
// Returns the time-averaged mean settlement; pressureError the time-averaged
// RMS pressure error over rho g H.
double freeBlockSettlement(double nu, mpm::MpmControls::VolumetricLocking locking, int ppc, double& pressureError,
                           mpm::MpmControls::BaseBoundary base)
{
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 0.0;
    const double H = 1.0, L = 3.0, rho = 1000.0, E = 1e6, g = 9.81;
    scene::Scene sc = blockScene(0.0, L, H, rho, 1e12, iface);
    mpm::MpmControls c = controls(8, ppc, nu);
    c.volumetricLocking = locking;
    c.baseBoundary = base;
    SceneRun r(sc, c, E, false);
    const mpm::HostPoints h0(r.points);
    const double period = 4.0*H/std::sqrt(E/rho);
    const double T = 10.0*period;
    double sum = 0.0, time = 0.0, err = 0.0;
    int samples = 0;
    while (r.t < T - 1e-9)
    {
        const double t0 = r.t;
        r.advance(std::min(T, r.t + period/20.0));
        const mpm::HostPoints hp(r.points);
        double s = 0.0, m = 0.0, e2 = 0.0;
        for (int p = 0; p < hp.count; ++p)
        {
            s += hp.mass(p)*(hp.position(p, 1) - h0.position(p, 1));
            m += hp.mass(p);
            const double pr = -(hp.stress(p, 0) + hp.stress(p, 1) + hp.stress(p, 2))/3.0;
            const double exact = (1.0 + nu)*rho*g*(H - h0.position(p, 1))/3.0;
            e2 += (pr - exact)*(pr - exact);
        }
        sum += (s/m)*(r.t - t0);
        time += r.t - t0;
        err += std::sqrt(e2/hp.count)/(rho*g*H);
        ++samples;
    }
    pressureError = err/samples;
    return -sum/time;
}

} // namespace

TEST(SlideMPM, CellAveragingRemovesVolumetricLocking)
{
    // At nu = 0.49 the per-particle volumetric constraint of plain MPM stiffens
    // the block (too little settlement) and scatters its pressure, most where
    // the base cuts the grid: two rows of base nodes hold the normal velocity
    // of the lowest cell. The cell-averaged B-bar relieves it. (With the
    // B-splines fitted to the base only the base line is held, and the free
    // block does not lock: measured, plain 2.1767e-03 m and B-bar 2.1783e-03 m,
    // RMS pressure errors 0.217 and 0.211; validation/mpm/README.md has what
    // the B-bar still does in a sliding slide.)
    using Locking = mpm::MpmControls::VolumetricLocking;
    const auto cut = mpm::MpmControls::BaseBoundary::levelSet;
    const double nu = 0.49, E = 1e6;
    const double exact = (1.0 - nu*nu)*1000.0*9.81/(3.0*E);
    double errNone, errBbar;
    const int ppc = 4;   // the paper's 4 x 4: the more particles per cell, the more plain MPM locks
    const double none = freeBlockSettlement(nu, Locking::none, ppc, errNone, cut);
    const double bbar = freeBlockSettlement(nu, Locking::cellAveraging, ppc, errBbar, cut);
    std::printf("free block on a base cutting the grid: settlement exact %.4e m, plain %.4e m, B-bar %.4e m; "
                "RMS pressure error / (rho g H): plain %.3f, B-bar %.3f\n", exact, none, bbar, errNone, errBbar);
    EXPECT_NEAR(bbar, exact, 0.1*exact);
    EXPECT_LT(std::fabs(bbar - exact), std::fabs(none - exact));
    EXPECT_LT(errBbar, 0.8*errNone);
}

// The base's load from a shear stress tau in particles crowded into the cells
// on the base: a block squashed to half its height, volumes kept, so every cell
// holds particles of twice its area (as the base cell of a thinning slide
// holds 1.1-2 times its area: validation/mpm/README.md, open problem 13). With
// the particles' volumes as weights the base's nodes take twice tau per unit
// length; with stressQuadrature cellCapped, tau. Unsquashed, the two agree.
double baseLoadOfAShearStress(const mpm::MpmControls::StressQuadrature quadrature, const double squash)
{
    const double tau = 100.0;
    scene::Interface iface;
    mpm::MpmControls c = controls(8, 4);
    c.stressQuadrature = quadrature;
    SceneRun r(blockScene(0.0, 4.0, 1.0, 600.0, 1e5, iface), c, 1e7, false);
    mpm::MaterialPoints& mp = r.points;
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.position);
    auto sig = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.stress);
    for (int p = 0; p < mp.count; ++p)
    {
        x(p, 1) *= squash;
        for (int k = 0; k < 4; ++k) sig(p, k) = 0.0;
        sig(p, 3) = tau;
    }
    Kokkos::deep_copy(mp.position, x);
    Kokkos::deep_copy(mp.stress, sig);
    const mpm::StepStatistics st = mpm::TimeIntegrator::statistics(mp, r.grid.rows);
    EXPECT_TRUE(r.grid.fit(st.xmin, st.xmax, st.ymin, st.ymax, 1ull << 30));
    r.grid.pressureSumsCurrent = false;
    const double dt = 1.0;   // with v = 0 and a flat base, a node's x momentum is dt times its internal force
    r.integrator.particleToGrid(mp, r.grid, dt);
    auto nodal = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.grid.nodal);
    // The base's node row; columns two cells or more inside either end.
    const int baseRow = -1 - r.grid.j0, d8 = 8;
    double load = 0.0;
    int columns = 0;
    for (int i = 0; i < r.grid.ni; ++i)
    {
        const double xi = r.grid.xOrigin + (r.grid.i0 + i)*r.grid.d;
        if (xi < 2.0*r.grid.d || xi > 4.0 - 2.0*r.grid.d) continue;
        load += nodal(i, baseRow, mpm::BackgroundGrid::momentumX)/(dt*r.grid.d);
        ++columns;
    }
    EXPECT_GT(columns, 4*d8 - 8);
    return load/columns;
}

TEST(SlideMPM, CellCappedQuadratureWeighsACrowdedCellByItsArea)
{
    using Q = mpm::MpmControls::StressQuadrature;
    const double full = baseLoadOfAShearStress(Q::particleVolume, 1.0);
    const double fullCapped = baseLoadOfAShearStress(Q::cellCapped, 1.0);
    const double crowded = baseLoadOfAShearStress(Q::particleVolume, 0.5);
    const double crowdedCapped = baseLoadOfAShearStress(Q::cellCapped, 0.5);
    std::printf("base load of a 100 Pa shear stress per unit length: full cells %.6f (capped %.6f) Pa, "
                "cells holding twice their area %.6f (capped %.6f) Pa\n", full, fullCapped, crowded, crowdedCapped);
    // The base's node's function falls off as (1 - s)^2 in the base cell: its
    // slope 2(1 - s)/d weighs tau to tau per unit length, sign aside.
    EXPECT_NEAR(std::fabs(full), 100.0, 1e-9*100.0);
    EXPECT_NEAR(fullCapped, full, 1e-9*100.0);
    EXPECT_NEAR(crowded, 2.0*full, 1e-9*100.0);
    EXPECT_NEAR(crowdedCapped, full, 1e-9*100.0);
}

// A stress-free block (2 m x 1 m, H0/8, 4 x 4 particles, no gravity) whose
// particles were squeezed to `squash` of its height, volumes kept, so that
// every cell holds 1/squash of its area, run for 500 steps with particle
// shifting: the largest excess fill of a node (its mass over what the
// seeding gives it, less 1), the height of the particles' centre of volume, the highest and
// lowest particle, the largest move and the mass lost. Without stress or
// gravity the grid gives no velocity: whatever moves is the shifting.
struct CrowdedBlock
{
    double largestExcess, centroidHeight, top, lowest, largestMove, massChange;
};

CrowdedBlock shiftCrowdedBlock(const double squash, const double shifting)
{
    scene::Interface iface;
    scene::Scene sc = blockScene(0.0, 2.0, 1.0, 600.0, 1e5, iface);
    sc.g = 0.0;
    mpm::MpmControls c = controls(8, 4);
    c.particleShifting = shifting;
    SceneRun r(sc, c, 1e7, false);
    // The particles' places in order (sorting by cell reorders the particles).
    auto places = [](const mpm::HostPoints& hp)
    {
        std::vector<std::pair<double, double>> xy;
        for (int p = 0; p < hp.count; ++p) xy.emplace_back(hp.position(p, 0), hp.position(p, 1));
        std::sort(xy.begin(), xy.end());
        return xy;
    };
    double massBefore = 0.0;
    std::vector<std::pair<double, double>> before;
    {
        auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.position);
        for (int p = 0; p < r.points.count; ++p) hx(p, 1) *= squash;
        Kokkos::deep_copy(r.points.position, hx);
        r.stats = mpm::TimeIntegrator::statistics(r.points, r.grid.rows);
        const mpm::HostPoints hp(r.points);
        before = places(hp);
        for (int p = 0; p < hp.count; ++p) massBefore += hp.mass(p);
    }
    const double dt = r.integrator.timeStep(r.grid.d, 0.0);
    r.advance(500*dt);
    const mpm::HostPoints hp(r.points);
    CrowdedBlock b{0.0, 0.0, -1e300, 1e300, 0.0, 0.0};   // massChange: the mass, then less the mass before
    double volume = 0.0;
    b.centroidHeight = 0.0;
    for (int p = 0; p < hp.count; ++p)
    {
        b.top = std::max(b.top, hp.position(p, 1));
        b.lowest = std::min(b.lowest, hp.position(p, 1));
        b.massChange += hp.mass(p);
        b.centroidHeight += hp.volume(p)*hp.position(p, 1);
        volume += hp.volume(p);
    }
    b.centroidHeight /= volume;
    EXPECT_TRUE(r.grid.fit(r.stats.xmin, r.stats.xmax, r.stats.ymin, r.stats.ymax, 1ull << 30));
    r.grid.pressureSumsCurrent = false;
    r.integrator.particleToGrid(r.points, r.grid, dt);
    auto nodal = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.grid.nodal);
    const double fullMass = 600.0*r.grid.d*r.grid.d;
    for (int i = 0; i < r.grid.ni; ++i)
    {
        for (int j = 0; j < r.grid.nj; ++j)
        {
            const double share = mpm::seededShare(r.grid.j0 + j, c.particlesPerCell);
            if (share > 0.0)
            {
                b.largestExcess = std::max(b.largestExcess,
                                           nodal(i, j, mpm::BackgroundGrid::mass)/(fullMass*share) - 1.0);
            }
        }
    }
    b.massChange -= massBefore;
    const auto after = places(hp);
    EXPECT_EQ(after.size(), before.size());
    for (std::size_t k = 0; k < std::min(after.size(), before.size()); ++k)
    {
        b.largestMove = std::max(b.largestMove, std::hypot(after[k].first - before[k].first,
                                                           after[k].second - before[k].second));
    }
    return b;
}

TEST(SlideMPM, ParticleShiftingSpreadsACrowdedBlockAndLeavesAFullOneAlone)
{
    // Particles crowd into the cell on a no-slip base of a thinning slide
    // (1.1-2 times its area: validation/mpm/README.md, open problem 13);
    // particleShifting moves them down the gradient of their nodes' excess
    // fill. Here every cell of a block holds 1.25 times its area: shifted, the
    // particles spread up until they fill the block's 1 m by volume.
    const double k = 0.1;
    const CrowdedBlock still = shiftCrowdedBlock(0.8, 0.0);
    const CrowdedBlock spread = shiftCrowdedBlock(0.8, k);
    const CrowdedBlock full = shiftCrowdedBlock(1.0, k);
    std::printf("crowded block (1.25 x its area per cell): largest excess fill of a node %.4f unshifted, %.4f "
                "shifted; centre of volume %.4f m unshifted, %.4f m shifted (0.5 m spread); top %.4f -> %.4f m, "
                "lowest %.4f m; a seeded block's largest move %.3e m, largest excess %.1e\n", still.largestExcess,
                spread.largestExcess, still.centroidHeight, spread.centroidHeight, still.top, spread.top,
                spread.lowest, full.largestMove, full.largestExcess);
    EXPECT_NEAR(still.largestExcess, 0.25, 0.01);   // the squash moves the base rows' sampling off the seeding
    EXPECT_NEAR(still.centroidHeight, 0.4, 1e-9);
    EXPECT_EQ(still.largestMove, 0.0);
    EXPECT_LT(spread.largestExcess, 0.05);
    EXPECT_GT(spread.centroidHeight, 0.44);   // 0.47 m if the particles filled 0.94 m evenly
    EXPECT_LT(spread.centroidHeight, 0.5);
    EXPECT_GT(spread.top, still.top + 0.08);
    EXPECT_LT(spread.top, 1.0);
    EXPECT_GE(spread.lowest, 0.0);            // not through the base
    EXPECT_EQ(spread.massChange, 0.0);
    // A block as seeded has no excess to shed (round-off aside).
    EXPECT_LT(full.largestExcess, 1e-12);
    EXPECT_LT(full.largestMove, 1e-12);
}

TEST(SlideMPM, NoMaterialThroughTheBase)
{
    // A weak slide slumping down a 10 degree slope on each interface.
    for (auto type : {scene::Interface::Type::noSlip, scene::Interface::Type::frictional})
    {
        scene::Interface iface;
        iface.type = type;
        iface.s_b = 100.0;
        SceneRun r(blockScene(10.0, 4.0, 1.0, 600.0, 300.0, iface), controls(8, 2), 100.0*300.0);
        r.advance(3.0);
        const mpm::HostPoints hp(r.points);
        double ymin = 1e300, M = 0.0;
        for (int p = 0; p < hp.count; ++p)
        {
            ymin = std::min(ymin, hp.position(p, 1));
            M += hp.mass(p);
        }
        EXPECT_GE(ymin, 0.0) << "interface " << static_cast<int>(type);
        EXPECT_EQ(M, 600.0*4.0*1.0);   // particle masses never change
        EXPECT_GT(r.stats.xmax, 4.0);  // and the slide did move
    }
}

TEST(SlideMPM, UnrecordedStepsLeaveTheDynamicsAlone)
{
    // s_u and the strain rates are recorded only by the steps whose end is
    // written: the motion must not depend on it, and a step that records must
    // leave the values that recording every step would have left.
    scene::Interface iface;
    const scene::Scene sc = blockScene(10.0, 4.0, 1.0, 600.0, 200.0, iface);
    SceneRun every(sc, controls(8, 2), 100.0*200.0), last(sc, controls(8, 2), 100.0*200.0);
    const int steps = 40;   // below sortInterval: no reordering in between
    for (int k = 0; k < steps; ++k)
    {
        for (SceneRun* r : {&every, &last})
        {
            ASSERT_TRUE(r->grid.fit(r->stats.xmin, r->stats.xmax, r->stats.ymin, r->stats.ymax, 1ull << 30));
            const double dt = r->integrator.stableTimeStep(r->grid.d, r->stats.maxSpeed);
            r->stats = r->integrator.step(r->points, r->grid, dt, r == &every || k == steps - 1);
        }
    }
    const mpm::HostPoints a(every.points), b(last.points);
    ASSERT_EQ(a.count, b.count);
    // Where the nodes' sums are added atomically (CUDA, and its code paths on
    // the host), their order, and with it the round-off, changes from run to
    // run: the two runs agree to round-off there, bit for bit elsewhere. Each
    // field's largest difference is taken relative to its largest value.
    struct Field { const char* name; std::function<double(const mpm::HostPoints&, int)> value; };
    const std::vector<Field> fields = {
        {"x", [](const mpm::HostPoints& h, int p) { return h.position(p, 0); }},
        {"y", [](const mpm::HostPoints& h, int p) { return h.position(p, 1); }},
        {"u", [](const mpm::HostPoints& h, int p) { return h.velocity(p, 0); }},
        {"v", [](const mpm::HostPoints& h, int p) { return h.velocity(p, 1); }},
        {"sigma_xx", [](const mpm::HostPoints& h, int p) { return h.stress(p, 0); }},
        {"sigma_yy", [](const mpm::HostPoints& h, int p) { return h.stress(p, 1); }},
        {"sigma_zz", [](const mpm::HostPoints& h, int p) { return h.stress(p, 2); }},
        {"sigma_xy", [](const mpm::HostPoints& h, int p) { return h.stress(p, 3); }},
        {"xi", [](const mpm::HostPoints& h, int p) { return h.plasticShearStrain(p); }},
        {"s_u", [](const mpm::HostPoints& h, int p) { return h.strength(p); }},
        {"shear strain rate", [](const mpm::HostPoints& h, int p) { return h.shearStrainRate(p); }},
        {"plastic shear strain rate", [](const mpm::HostPoints& h, int p) { return h.plasticShearStrainRate(p); }},
    };
    for (const Field& f : fields)
    {
        double largest = 0.0, difference = 0.0;
        for (int p = 0; p < a.count; ++p)
        {
            largest = std::max(largest, std::abs(f.value(a, p)));
            difference = std::max(difference, std::abs(f.value(a, p) - f.value(b, p)));
        }
        if (mpm::nodeScatterIsAtomic)
        {
            std::cout << f.name << ": largest difference " << difference << " of largest value " << largest << "\n";
            EXPECT_LE(difference, 1e-9*largest) << f.name;
        }
        else
        {
            EXPECT_EQ(difference, 0.0) << f.name;
        }
    }
    double maxRate = 0.0;
    for (int p = 0; p < a.count; ++p) maxRate = std::max(maxRate, a.plasticShearStrainRate(p));
    EXPECT_GT(maxRate, 0.0);   // the block slumps: the rates compared are not all zero
}

TEST(SlideMPM, StableSlideStaysPut)
{
    // Strong block (4 s_uo/(rho g) = 68 m >> H) on a no-slip 5 degree base.
    scene::Interface iface;
    SceneRun r(blockScene(5.0, 8.0, 1.0, 600.0, 1e5, iface), controls(8, 2), 100.0*1e5);
    const double front0 = mpm::HostPoints(r.points).frontX();
    // Released on the slope, the block takes up its elastic shear strain
    // (rho g H sin(theta)/G ~ 1.5e-4) and rings about it; it must not drift.
    auto meanFront = [&](double T)
    {
        double s = 0.0;
        int n = 0;
        while (r.t < T - 1e-9)
        {
            r.advance(std::min(T, r.t + 0.01));
            s += mpm::HostPoints(r.points).frontX();
            ++n;
        }
        return s/n;
    };
    meanFront(1.0);
    const double early = meanFront(2.0), late = meanFront(3.0);
    EXPECT_LT(std::fabs(late - early), 1e-5);
    EXPECT_LT(std::fabs(late - front0), 1e-3);
    const mpm::HostPoints hp(r.points);
    double xiMax = 0.0;
    for (int p = 0; p < hp.count; ++p) xiMax = std::max(xiMax, hp.plasticShearStrain(p));
    EXPECT_EQ(xiMax, 0.0);   // it never yielded
}

TEST(SlideMPM, SplittingKeepsMassMomentumAndTheAffineField)
{
    // A block whose particles are pulled apart 3x along the base (as an
    // elongating slide leaves them): every particle lies in an under-filled
    // cell with a domain 3 spacings long, so each is split once along x.
    scene::Interface iface;
    SceneRun r(blockScene(5.0, 4.0, 1.0, 600.0, 200.0, iface), controls(8, 2), 100.0*200.0);
    const double a = r.points.spacing;
    {
        auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.position);
        auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.velocity);
        auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.affine);
        auto len = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.size);
        for (int p = 0; p < r.points.count; ++p)
        {
            x(p, 0) *= 3.0;
            len(p, 0) *= 3.0;
            len(p, 1) /= 3.0;
            v(p, 0) = 1.0 + 0.1*x(p, 0);
            v(p, 1) = -0.05*x(p, 1);
            C(p, 0) = 0.1; C(p, 1) = 0.02; C(p, 2) = -0.03; C(p, 3) = -0.05;
        }
        Kokkos::deep_copy(r.points.position, x);
        Kokkos::deep_copy(r.points.velocity, v);
        Kokkos::deep_copy(r.points.affine, C);
        Kokkos::deep_copy(r.points.size, len);
    }
    r.stats = mpm::TimeIntegrator::statistics(r.points, r.grid.rows);
    const mpm::HostPoints before(r.points);
    ASSERT_TRUE(r.grid.fit(r.stats.xmin, r.stats.xmax, r.stats.ymin, r.stats.ymax, 1ull << 30));
    const int n = r.points.count;
    EXPECT_EQ(r.integrator.splitting().split(r.points, r.grid, r.frame.level, 10*n), n);
    const mpm::HostPoints after(r.points);
    auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.affine);
    ASSERT_EQ(after.count, 2*n);
    double m0 = 0.0, m1 = 0.0, px0 = 0.0, px1 = 0.0, py0 = 0.0, py1 = 0.0;
    for (int p = 0; p < n; ++p)
    {
        m0 += before.mass(p);
        px0 += before.mass(p)*before.velocity(p, 0);
        py0 += before.mass(p)*before.velocity(p, 1);
    }
    for (int p = 0; p < 2*n; ++p)
    {
        m1 += after.mass(p);
        px1 += after.mass(p)*after.velocity(p, 0);
        py1 += after.mass(p)*after.velocity(p, 1);
    }
    EXPECT_EQ(m1, m0);
    EXPECT_NEAR(px1, px0, 1e-13*std::fabs(px0));
    EXPECT_NEAR(py1, py0, 1e-13*std::fabs(py0));
    for (int p = 0; p < n; ++p)
    {
        const int c = n + p;   // every parent split: its child is n + p
        // Halves a quarter of the parent's domain (0.75 a) either side along x,
        // each with half its mass, volume and domain length.
        EXPECT_NEAR(after.position(p, 0) - before.position(p, 0), 0.75*a, 1e-12);
        EXPECT_NEAR(after.position(c, 0) - before.position(p, 0), -0.75*a, 1e-12);
        EXPECT_EQ(after.position(c, 1), before.position(p, 1));
        EXPECT_EQ(after.mass(c), 0.5*before.mass(p));
        EXPECT_EQ(after.volume(p), 0.5*before.volume(p));
        EXPECT_NEAR(after.size(p, 0), 1.5*a, 1e-12);
        EXPECT_EQ(after.size(c, 1), before.size(p, 1));
        // On the parent's affine velocity field v + C (x - x_p).
        EXPECT_NEAR(after.velocity(p, 0), before.velocity(p, 0) + C(p, 0)*0.75*a, 1e-12);
        EXPECT_NEAR(after.velocity(c, 1), before.velocity(p, 1) - C(p, 2)*0.75*a, 1e-12);
        EXPECT_EQ(C(c, 1), C(p, 1));
    }
    // Domains as long, but in the seeded block, whose cells are full: nothing is split.
    SceneRun full(blockScene(5.0, 4.0, 1.0, 600.0, 200.0, iface), controls(8, 2), 100.0*200.0);
    auto len = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), full.points.size);
    for (int p = 0; p < full.points.count; ++p) len(p, 0) = 3.0*a;
    Kokkos::deep_copy(full.points.size, len);
    ASSERT_TRUE(full.grid.fit(full.stats.xmin, full.stats.xmax, full.stats.ymin, full.stats.ymax, 1ull << 30));
    EXPECT_EQ(full.integrator.splitting().split(full.points, full.grid, full.frame.level, 10*n), 0);
    // A split that would pass the particle limit changes nothing and says how many it needed.
    EXPECT_EQ(r.integrator.splitting().split(r.points, r.grid, r.frame.level, 2*n), 0);   // at rest: sizes 1.5 a
    auto len2 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.size);
    for (int p = 0; p < 2*n; ++p) len2(p, 0) = 3.0*a;
    Kokkos::deep_copy(r.points.size, len2);
    EXPECT_LT(r.integrator.splitting().split(r.points, r.grid, r.frame.level, 2*n), 0);
    EXPECT_EQ(r.points.count, 2*n);
}

TEST(SlideMPM, HorstsAreIntactBlocksPartedByRemouldedMaterial)
{
    // Case 11's slide at H0/5, its particles given xi by hand: remoulded through
    // the body in two 3 m bands, intact elsewhere, is three horsts (spreading);
    // remoulded in the basal layer only, one intact body; no remoulding in the
    // material, no horsts whatever xi says.
    const scene::Scene sc = case11Scene();
    SceneRun r(sc, controls(5, 2), 100.0*sc.rheology.s_uo);
    const double H0 = sc.slide.height, d = H0/5.0;
    auto withXi = [&](bool throughBody)
    {
        const mpm::HostPoints hp(r.points);
        const double rear = hp.rearX();
        auto xi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.plasticShearStrain);
        for (int p = 0; p < hp.count; ++p)
        {
            const double s = hp.position(p, 0) - rear;
            const bool band = (s >= 12.0 && s < 15.0) || (s >= 26.0 && s < 29.0);
            const bool basal = hp.position(p, 1) < 2.0*hp.spacing;
            xi(p) = band && (throughBody || basal) ? 100.0 : 0.0;
        }
        Kokkos::deep_copy(r.points.plasticShearStrain, xi);
        return mpm::detectMechanism(mpm::HostPoints(r.points), r.frame, H0, sc.g, d, sc.rheology);
    };
    const output::Mechanism parted = withXi(true);
    EXPECT_EQ(parted.horsts, 3);
    EXPECT_EQ(parted.grabens, 0);   // the surface is flat: only xi tells
    EXPECT_EQ(parted.name, "spreading (horsts and grabens)");
    EXPECT_EQ(parted.shearBand, "in the body");
    const output::Mechanism basal = withXi(false);
    EXPECT_EQ(basal.horsts, 0);
    EXPECT_EQ(basal.name, "viscous elongation");
    scene::Scene intact = sc;
    intact.rheology.deltaRem = 1.0;
    withXi(true);
    EXPECT_EQ(mpm::detectMechanism(mpm::HostPoints(r.points), r.frame, H0, sc.g, d, intact.rheology).horsts, 0);
}

TEST(SlideMPM, RemouldedFilmOnTheBasePartsBodies)
{
    // Case 11's slide at H0/20, its middle 10 m brought down to the lowest
    // particle row (a film 0.125 m high, below H0/20 = 0.25 m): a body that slid
    // away on its remoulded band leaves the band on a no-slip base, so the
    // columns between never empty. Remoulded, the film parts the two slabs
    // (breakaway); intact, or in a material that does not remould, it joins them;
    // a remoulded film one column (1 m) long parts nothing.
    const scene::Scene sc = case11Scene();
    SceneRun r(sc, controls(20, 2), 100.0*sc.rheology.s_uo);
    const double H0 = sc.slide.height, d = H0/20.0;
    const mpm::HostPoints seeded(r.points);
    const double rear = seeded.rearX(), lowest = 0.5*seeded.spacing;
    auto film = [&](double from, double to, double filmXi)
    {
        auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.position);
        auto xi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.plasticShearStrain);
        for (int p = 0; p < seeded.count; ++p)
        {
            const double s = seeded.position(p, 0) - rear;
            const bool inFilm = s >= from && s < to;
            x(p, 1) = inFilm ? lowest : seeded.position(p, 1);
            xi(p) = inFilm ? filmXi : 0.0;
        }
        Kokkos::deep_copy(r.points.position, x);
        Kokkos::deep_copy(r.points.plasticShearStrain, xi);
    };
    auto detect = [&](const rheology::HerschelBulkleyRemoulding& material)
    {
        return mpm::detectMechanism(mpm::HostPoints(r.points), r.frame, H0, sc.g, d, material);
    };
    film(15.0, 25.0, 100.0);
    const output::Mechanism parted = detect(sc.rheology);
    EXPECT_EQ(parted.bodies, 2);
    EXPECT_EQ(parted.name, "breakaway");
    scene::Scene intact = sc;
    intact.rheology.deltaRem = 1.0;
    EXPECT_EQ(detect(intact.rheology).bodies, 1);
    film(15.0, 25.0, 0.0);
    EXPECT_EQ(detect(sc.rheology).bodies, 1);
    film(15.0, 16.0, 100.0);
    EXPECT_EQ(detect(sc.rheology).bodies, 1);
}

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    Kokkos::ScopeGuard kokkos(argc, argv);
    return RUN_ALL_TESTS();
}

TEST(SlideMPM, ShearBandThicknessRemouldsTwoMeshesAlike)
{
    // Table 1 Case 11: a strong (5 kPa), very sensitive (S_t = 40, xi95 = 10)
    // slide whose 5 m faces collapse (4 s_uo/(rho g) = 3.4 m) and remould.
    // Counted per cell, the collapse zone's strain grows as the cells shrink
    // and so does the runout; counted as a band 1/60 of the slide thick
    // (the paper's cell), H0/10 and H0/20 agree far better. (H0/40, where more bands fit
    // in the slide, parted from both where the base cut the grid: 12.0 m at 3 s;
    // validation/mpm/shearBand.md.)
    const scene::Scene sc = case11Scene();
    auto travel = [&](int cellsPerHeight, double band)
    {
        mpm::MpmControls c = controls(cellsPerHeight, 2);
        c.shearBandThickness = band;
        SceneRun r(sc, c, 100.0*sc.rheology.s_uo);
        const double front0 = mpm::HostPoints(r.points).frontX();
        r.advance(3.0);
        return mpm::HostPoints(r.points).frontX() - front0;
    };
    const double band = 5.0/60.0;
    const double coarse = travel(10, band), fine = travel(20, band);
    const double coarseCell = travel(10, 0.0), fineCell = travel(20, 0.0);
    std::printf("Case 11 front travel at 3 s, H0/10 and H0/20: band %.2f and %.2f m, per cell %.2f and %.2f m\n",
                coarse, fine, coarseCell, fineCell);
    // Measured with the B-splines fitted to the base: the band's runs 7 % apart,
    // per cell 20 % (where the base cut the grid: 1 % and 39 %).
    EXPECT_NEAR(coarse, fine, 0.1*fine);
    EXPECT_GT(fineCell, 1.15*coarseCell);          // what the band removes
    EXPECT_GT(coarse, 1.5*fineCell);               // and the band remoulds the collapse far sooner
}

namespace
{

mpm::EnergyState energyNow(SceneRun& r)
{
    return mpm::energyState(mpm::HostPoints(r.points), r.frame, r.clay, r.sc.slide.density, r.grid.d);
}

// The energy budget of a run from its start: what mpmOutput's EnergyLog writes.
mpm::EnergyBudget budgetSince(const mpm::EnergyState& start, SceneRun& r, const double boundaryWork)
{
    return mpm::energyBudget(energyNow(r), start, boundaryWork);
}

} // namespace

TEST(SlideMPM, EnergyBudgetOfASlidingBlockIsItsFriction)
{
    // A rigid block (s_uo far above every stress) on a 5 degree slope with
    // s_b = 200 Pa: gravity's work goes into kinetic energy and into the
    // base's friction, s_b L times the distance slid; nothing into plastic flow,
    // little into the discretisation.
    scene::Interface iface;
    iface.type = scene::Interface::Type::frictional;
    iface.s_b = 200.0;
    const scene::Scene sc = blockScene(5.0, 8.0, 1.0, 500.0, rigidStrength, iface);
    SceneRun r(sc, controls(8, 2), 100.0*rigidStrength);
    const mpm::EnergyState start = energyNow(r);
    double x0, y0, u0;
    centreOfMass(mpm::HostPoints(r.points), x0, y0, u0);
    double boundaryWork = 0.0;
    mpm::advanceTo(r.integrator, r.points, r.grid, r.t, 3.0, r.stats, &boundaryWork);
    double x3, y3, u3;
    centreOfMass(mpm::HostPoints(r.points), x3, y3, u3);
    const mpm::EnergyBudget b = budgetSince(start, r, boundaryWork);
    const double M = sc.slide.density*sc.slide.length*sc.slide.height;
    // Gravity's work is the centre of mass's descent, along the slope and, as the
    // block, seeded in the geostatic stress of a wide layer, settles free of
    // side confinement (by (1 - nu^2) rho g H^2/(3 E), 4e-4 m), normal to it.
    const double theta = 5.0*M_PI/180.0;
    EXPECT_NEAR(b.gravity, M*sc.g*(std::sin(theta)*(x3 - x0) - std::cos(theta)*(y3 - y0)), 1e-9*b.gravity);
    EXPECT_LT(y3 - y0, -1e-4);   // it settled: the normal term is not nothing
    EXPECT_NEAR(b.boundary, iface.s_b*sc.slide.length*(x3 - x0), 0.03*b.boundary);
    EXPECT_NEAR(b.kinetic, 0.5*M*u3*u3, 0.02*b.kinetic);
    EXPECT_EQ(b.plastic, 0.0);
    EXPECT_LT(std::fabs(b.numerical), 0.01*b.gravity);
    EXPECT_GT(b.boundary, 0.3*b.gravity);   // friction took a good share: the check is not trivial
}

TEST(SlideMPM, EnergyBudgetShowsWhatPICDissipatesAndAPICKeeps)
{
    // A weak slide slumping on a no-slip 10 degree slope: its energy goes into
    // plastic flow; the remainder is the discretisation's. PIC's transfers damp
    // the motion (measured: 75 % of gravity's work to 1.5 s, plastic flow 24 %,
    // and gravity did a quarter of APIC's work); APIC keeps it (4 %, plastic 50 %).
    double numerical[2], plastic[2];
    int k = 0;
    for (auto transfer : {mpm::MpmControls::Transfer::pic, mpm::MpmControls::Transfer::apic})
    {
        scene::Interface iface;
        mpm::MpmControls c = controls(8, 2);
        c.transfer = transfer;
        SceneRun r(blockScene(10.0, 4.0, 1.0, 600.0, 300.0, iface), c, 100.0*300.0);
        const mpm::EnergyState start = energyNow(r);
        double boundaryWork = 0.0;
        mpm::advanceTo(r.integrator, r.points, r.grid, r.t, 1.5, r.stats, &boundaryWork);
        const mpm::EnergyBudget b = budgetSince(start, r, boundaryWork);
        EXPECT_NEAR(b.boundary, 0.0, 1e-9*b.gravity);   // a no-slip base does no work
        EXPECT_GT(b.gravity, 0.0);
        numerical[k] = b.numerical/b.gravity;
        plastic[k] = b.plastic/b.gravity;
        std::cout << (k == 0 ? "PIC" : "APIC") << ": numerical " << numerical[k] << ", plastic " << plastic[k]
                  << " of gravity's work " << b.gravity << " J/m" << std::endl;
        ++k;
    }
    EXPECT_GT(numerical[0], 0.5);
    EXPECT_LT(numerical[1], 0.1);
    EXPECT_LT(numerical[1], 0.1*numerical[0]);
    EXPECT_GT(plastic[1], 0.3);
}

TEST(SlideMPM, BlockReleasedAboveTheBaseFallsOntoIt)
{
    // A strong block released 0.45 of a cell above a no-slip base (stress
    // free, gravity on at t = 0) must fall freely onto it: 0.5 g t^2. With
    // `withinCell` contact the base's nodes, whose functions reach a cell up,
    // are held still under it and it hovers where it was released: the
    // B-spline field spans the gap, and falling into it would compress the
    // clay. `touching` frees them until the material fills the base cell's
    // lowest eighth half as much as the rest of the cell.
    for (auto contact : {mpm::MpmControls::BaseContact::withinCell, mpm::MpmControls::BaseContact::touching})
    {
        scene::Interface iface;
        mpm::MpmControls c = controls(8, 4);
        c.baseContact = contact;
        SceneRun r(blockScene(0.0, 4.0, 1.0, 600.0, 1e5, iface), c, 100.0*1e5, false);
        const double d = r.grid.d, gap = 0.45*d;
        {
            auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r.points.position);
            for (int p = 0; p < r.points.count; ++p) hx(p, 1) += gap;
            Kokkos::deep_copy(r.points.position, hx);
            r.stats = mpm::TimeIntegrator::statistics(r.points, r.grid.rows);
        }
        auto lowest = [&]()
        {
            const mpm::HostPoints hp(r.points);
            double low = 1e300;
            for (int p = 0; p < hp.count; ++p) low = std::min(low, hp.position(p, 1) - 0.5*hp.size(p, 1));
            return low;
        };
        const double t1 = 0.05, freeFall = 0.5*9.81*t1*t1;   // 0.35 of the gap
        r.advance(t1);
        const double drop = gap - lowest();
        r.advance(0.5);
        const double landed = lowest();
        std::cout << (contact == mpm::MpmControls::BaseContact::touching ? "touching" : "withinCell")
                  << ": drop in " << t1 << " s " << drop << " m (free fall " << freeFall << " m), lowest at 0.5 s "
                  << landed/d << " cells above the base\n";
        if (contact == mpm::MpmControls::BaseContact::touching)
        {
            EXPECT_NEAR(drop, freeFall, 0.01*freeFall);
            EXPECT_GE(landed, 0.0);
            EXPECT_LT(landed, mpm::baseTouchStrip*d);
        }
        else
        {
            EXPECT_LT(drop, 0.01*freeFall);
            EXPECT_GT(landed, 0.95*gap);
        }
    }
}

TEST(SlideMPM, ThinLayerOnTheBaseStaysStill)
{
    // A layer of clay 0.04 of a cell thick at rest on a no-slip base (stress
    // free, gravity on). Over a fitted base the row above the base's node has
    // the function 2s - 3s^2/2: the layer gives that node a mass of order t^2/d
    // and a stiffness of order t, so its own frequency needs a Courant number
    // below sqrt(t/d) = 0.2 and the bulk's 0.3 rings it unstably (the thin
    // tails that blew up the escarpment on 30 deg and the map's 150 Pa, S_t 10
    // slide). With baseRowMassScaling the node rings at most at 1/dt.
    for (const bool scaling : {false, true})
    {
        scene::Interface iface;
        mpm::MpmControls c = controls(8, 4);
        c.baseRowMassScaling = scaling;
        SceneRun r(blockScene(0.0, 4.0, 1.0, 600.0, 1e5, iface), c, 100.0*1e5, false);
        const double d = r.grid.d, t = 0.04*d, squash = t/1.0;
        {
            // The 1 m block squashed into the layer, density kept.
            mpm::MaterialPoints& mp = r.points;
            auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.position);
            auto s = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.size);
            auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.mass);
            auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mp.volume);
            for (int p = 0; p < mp.count; ++p)
            {
                x(p, 1) *= squash;
                s(p, 1) *= squash;
                m(p) *= squash;
                V(p) *= squash;
            }
            Kokkos::deep_copy(mp.position, x);
            Kokkos::deep_copy(mp.size, s);
            Kokkos::deep_copy(mp.mass, m);
            Kokkos::deep_copy(mp.volume, V);
            r.stats = mpm::TimeIntegrator::statistics(r.points, r.grid.rows);
        }
        bool finite = true;
        double fastest = 0.0;
        try
        {
            for (int k = 1; k <= 10; ++k)
            {
                r.advance(0.01*k);
                fastest = std::max(fastest, r.stats.maxSpeed);
            }
        }
        catch (const std::runtime_error&)
        {
            finite = false;
        }
        std::cout << "baseRowMassScaling " << (scaling ? "yes" : "no") << ": " << (finite ? "finite" : "blew up")
                  << ", fastest particle " << fastest << " m/s by " << r.t << " s\n";
        if (scaling)
        {
            EXPECT_TRUE(finite);
            // Free fall for one step is g dt = 0.0007 m/s; the layer settles by 1 % of its thickness.
            EXPECT_LT(fastest, 0.01);
            const mpm::HostPoints hp(r.points);
            for (int p = 0; p < hp.count; ++p)
            {
                ASSERT_GE(hp.position(p, 1), 0.0);
                ASSERT_LT(hp.position(p, 1), t);
            }
        }
        else
        {
            EXPECT_TRUE(!finite || fastest > 1.0);
        }
    }
}

// purgeState keeps slideMPM's restart states alone (89 MB a write on the
// flume at H0/60): absent it follows controlDict's purgeWrite, which would
// also purge slideFoam's time directories.
TEST(SlideMPM, PurgeStateOverridesPurgeWriteForStatesOnly)
{
    using scene::Dictionary;
    const mpm::MpmControls absent = mpm::MpmControls::read(Dictionary::parse("setting fast;\n", "system/mpmDict"));
    EXPECT_EQ(absent.statesKept(0), 0);
    EXPECT_EQ(absent.statesKept(3), 3);
    const mpm::MpmControls two =
        mpm::MpmControls::read(Dictionary::parse("setting fast;\npurgeState 2;\n", "system/mpmDict"));
    EXPECT_EQ(two.statesKept(0), 2);
    EXPECT_EQ(two.statesKept(5), 2);
    const mpm::MpmControls all =
        mpm::MpmControls::read(Dictionary::parse("setting fast;\npurgeState 0;\n", "system/mpmDict"));
    EXPECT_EQ(all.statesKept(4), 0);
    try
    {
        mpm::MpmControls::read(Dictionary::parse("setting fast;\npurgeState -1;\n", "system/mpmDict"));
        ADD_FAILURE() << "purgeState -1 was accepted";
    }
    catch (const scene::InputError& e)
    {
        EXPECT_EQ(e.key(), "purgeState");
        EXPECT_EQ(e.line(), 2);
        EXPECT_EQ(e.file(), "system/mpmDict");
    }
}
