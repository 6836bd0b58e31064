// The runout mechanism classifier on slides built by hand from cells, as
// slideFoam gives them (slideMPM's particles are checked in mpmSceneTest).
#include "runoutMechanism.H"

#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <filesystem>
#include <functional>

namespace fs = std::filesystem;
using namespace slide;
using namespace slide::output;

namespace
{

constexpr double H0 = 5.0, rho = 600.0, dx = 0.5, dy = 0.125;

MechanismView view()
{
    MechanismView v;
    v.H0 = H0;
    v.columnWidth = std::max(dx, 0.2*H0);
    v.basalLayer = 2.0*dy;
    return v;
}

// A remoulding clay (S_t 40, as Table 1 Case 11) and one that does not remould.
rheology::HerschelBulkleyRemoulding clay(bool remoulds = true)
{
    rheology::HerschelBulkleyRemoulding m;
    m.s_uo = 5000.0;
    m.deltaRem = remoulds ? 0.025 : 1.0;
    m.xi95 = 30.0;
    return m;
}

// A cell dx wide and `height` high, full of slide, centred at (s, h).
MaterialSample cell(double s, double h, double height, double velocity, double xi)
{
    MaterialSample c;
    c.s = s;
    c.halfLength = 0.5*dx;
    c.h = h;
    c.halfHeight = 0.5*height;
    c.mass = rho*dx*height;
    c.velocity = velocity;
    c.xi = xi;
    c.vote = dx*height;
    return c;
}

// Cells dx by dy from s0 to s1, from the base up to height(s); velocity and xi
// as functions of (s, h).
void addMaterial(std::vector<MaterialSample>& out, double s0, double s1, const std::function<double(double)>& height,
                 const std::function<double(double, double)>& velocity,
                 const std::function<double(double, double)>& xi, double cellHeight = dy)
{
    for (double s = s0 + 0.5*dx; s < s1; s += dx)
    {
        for (double h = 0.5*cellHeight; h < height(s); h += cellHeight)
        {
            out.push_back(cell(s, h, cellHeight, velocity(s, h), xi(s, h)));
        }
    }
}

auto flat(double H) { return [H](double) { return H; }; }
auto uniform(double u) { return [u](double, double) { return u; }; }

} // namespace

TEST(RunoutMechanism, RigidBlockSlidesAndAShearedLayerElongates)
{
    std::vector<MaterialSample> block;
    addMaterial(block, 0.0, 40.0, flat(H0), uniform(10.0), uniform(0.0));
    const Mechanism sliding = detectMechanism(block, view(), clay());
    EXPECT_EQ(sliding.name, "block sliding");
    EXPECT_EQ(sliding.bodies, 1);
    EXPECT_EQ(sliding.grabens, 0);
    EXPECT_NEAR(sliding.basalSlipRatio, 1.0, 1e-12);
    EXPECT_EQ(sliding.shearBand, "none");

    // The same block creeping (0.1 m/s, under a tenth of sqrt(g H0) = 7 m/s) does not slide.
    std::vector<MaterialSample> creep;
    addMaterial(creep, 0.0, 40.0, flat(H0), uniform(0.1), uniform(0.0));
    EXPECT_EQ(detectMechanism(creep, view(), clay()).name, "viscous elongation");

    // Sheared from a no-slip base (a parabolic profile): the basal layer lags the whole.
    std::vector<MaterialSample> layer;
    addMaterial(layer, 0.0, 40.0, flat(H0), [](double, double h) { return 10.0*(2.0*h/H0 - (h/H0)*(h/H0)); },
                uniform(0.0));
    const Mechanism elongating = detectMechanism(layer, view(), clay());
    EXPECT_EQ(elongating.name, "viscous elongation");
    EXPECT_LT(elongating.basalSlipRatio, 0.2);
}

TEST(RunoutMechanism, BodiesPartedByEmptyColumnsOrARemouldedFilmBreakAway)
{
    // Two slabs 2 m apart (two columns empty): breakaway; 0.5 m apart: one body.
    for (const double gap : {2.0, 0.5})
    {
        std::vector<MaterialSample> two;
        addMaterial(two, 0.0, 20.0, flat(2.0), uniform(5.0), uniform(0.0));
        addMaterial(two, 20.0 + gap, 40.0, flat(2.0), uniform(5.0), uniform(0.0));
        const Mechanism m = detectMechanism(two, view(), clay());
        EXPECT_EQ(m.bodies, gap > 1.0 ? 2 : 1) << "gap " << gap;
        EXPECT_EQ(m.name, gap > 1.0 ? "breakaway" : "block sliding") << "gap " << gap;
    }
    // Joined by a film one cell high (below H0/20) over 10 m: remoulded it parts
    // them, intact (or in a clay that does not remould) it joins them, and a
    // remoulded film one column long parts nothing.
    auto filmed = [](double filmLength, double filmXi)
    {
        std::vector<MaterialSample> s;
        addMaterial(s, 0.0, 15.0, flat(2.0), uniform(0.0), uniform(0.0));
        addMaterial(s, 15.0, 15.0 + filmLength, flat(dy), uniform(0.0), uniform(filmXi));
        addMaterial(s, 15.0 + filmLength, 40.0, flat(2.0), uniform(0.0), uniform(0.0));
        return s;
    };
    EXPECT_EQ(detectMechanism(filmed(10.0, 100.0), view(), clay()).bodies, 2);
    EXPECT_EQ(detectMechanism(filmed(10.0, 100.0), view(), clay()).name, "breakaway");
    EXPECT_EQ(detectMechanism(filmed(10.0, 100.0), view(), clay(false)).bodies, 1);
    EXPECT_EQ(detectMechanism(filmed(10.0, 0.0), view(), clay()).bodies, 1);
    EXPECT_EQ(detectMechanism(filmed(1.0, 100.0), view(), clay()).bodies, 1);
}

TEST(RunoutMechanism, NotchesOneCoarseCellDeepAreNoGrabens)
{
    // A rigid block on cells of H0/4 (the Finneidfjord block's mesh) whose top
    // cell is missing in 1 m notches every 5 m: a quarter of H0 deep, more than
    // H0/5, but one cell, which is the interface's noise at that mesh. It slides.
    const double coarse = 0.25*H0;
    auto notched = [coarse](double depthInCells)
    {
        return [coarse, depthInCells](double s)
        {
            return std::fmod(s, 5.0) < 1.0 && s > 2.0 && s < 38.0 ? H0 - depthInCells*coarse : H0;
        };
    };
    MechanismView coarseView = view();
    coarseView.basalLayer = 2.0*coarse;
    std::vector<MaterialSample> block;
    addMaterial(block, 0.0, 40.0, notched(1.0), uniform(10.0), uniform(0.0), coarse);
    const Mechanism sliding = detectMechanism(block, coarseView, clay(false));
    EXPECT_EQ(sliding.grabens, 0);
    EXPECT_EQ(sliding.name, "block sliding");
    // Two cells deep (half of H0) they are grabens on that mesh too.
    std::vector<MaterialSample> deep;
    addMaterial(deep, 0.0, 40.0, notched(2.0), uniform(10.0), uniform(0.0), coarse);
    const Mechanism spread = detectMechanism(deep, coarseView, clay(false));
    EXPECT_GE(spread.grabens, 2);
    EXPECT_EQ(spread.name, "spreading (horsts and grabens)");
}

TEST(RunoutMechanism, GrabensOrHorstsMeanSpreading)
{
    // Two troughs 2 m deep (more than H0/5) in a 5 m surface: two grabens.
    std::vector<MaterialSample> troughs;
    addMaterial(troughs, 0.0, 60.0,
                [](double s) { return (std::fabs(s - 20.0) < 2.0 || std::fabs(s - 40.0) < 2.0) ? 3.0 : H0; },
                uniform(1.0), uniform(0.0));
    const Mechanism spread = detectMechanism(troughs, view(), clay());
    EXPECT_EQ(spread.grabens, 2);
    EXPECT_EQ(spread.name, "spreading (horsts and grabens)");
    EXPECT_EQ(spread.shearBand, "in the body");

    // A flat surface remoulded through the body in two 3 m bands: three intact
    // blocks (horsts); remoulded in the basal layer only, one body sheared along the base.
    auto banded = [](bool throughBody)
    {
        std::vector<MaterialSample> s;
        addMaterial(s, 0.0, 40.0, flat(H0), uniform(0.0), [throughBody](double x, double h)
        {
            const bool band = (x >= 12.0 && x < 15.0) || (x >= 26.0 && x < 29.0);
            return band && (throughBody || h < 2.0*dy) ? 100.0 : 0.0;
        });
        return s;
    };
    const Mechanism horsts = detectMechanism(banded(true), view(), clay());
    EXPECT_EQ(horsts.horsts, 3);
    EXPECT_EQ(horsts.grabens, 0);
    EXPECT_EQ(horsts.name, "spreading (horsts and grabens)");
    EXPECT_EQ(detectMechanism(banded(true), view(), clay(false)).horsts, 0);
    const Mechanism basal = detectMechanism(banded(false), view(), clay());
    EXPECT_EQ(basal.horsts, 0);
    EXPECT_EQ(basal.name, "viscous elongation");

    // Remoulded along the whole base only: the shear band is along the base.
    std::vector<MaterialSample> sheared;
    addMaterial(sheared, 0.0, 40.0, flat(H0), uniform(1.0),
                [](double, double h) { return h < 2.0*dy ? 50.0 : 0.0; });
    EXPECT_EQ(detectMechanism(sheared, view(), clay()).shearBand, "along the base");
}

TEST(RunoutMechanism, CellsVoteByVolume)
{
    // Blocks of cells 0.5 m high on a remoulded graded layer of many thin cells
    // (a mesh refined towards the base): counted by volume, the body above the
    // basal layer is intact and the three blocks are horsts; counted one vote a
    // cell, its many thin remoulded cells would outvote it.
    std::vector<MaterialSample> s;
    for (double x = 0.5*dx; x < 40.0; x += dx)
    {
        const bool band = (x >= 12.0 && x < 15.0) || (x >= 26.0 && x < 29.0);
        auto add = [&](double h, double height, double xi) { s.push_back(cell(x, h, height, 1.0, xi)); };
        // 0.25 m basal layer in 0.0625 m cells, then 0.4 m of 0.02 m cells (remoulded
        // where the blocks are not), then 4 m of 0.5 m cells (remoulded in the bands).
        for (double h = 0.03125; h < 0.25; h += 0.0625) add(h, 0.0625, 100.0);
        for (double h = 0.26; h < 0.65; h += 0.02) add(h, 0.02, 100.0);
        for (double h = 0.9; h < 5.0; h += 0.5) add(h, 0.5, band ? 100.0 : 0.0);
    }
    EXPECT_EQ(detectMechanism(s, view(), clay()).horsts, 3);
    for (MaterialSample& c : s) c.vote = 1.0;
    EXPECT_EQ(detectMechanism(s, view(), clay()).horsts, 0);
}

TEST(RunoutMechanism, NothingToLookAt)
{
    EXPECT_EQ(detectMechanism({}, view(), clay()).name, "none");
}

// Round-off in a plug (an advected xi of 1e-320, a mean speed of 1e-300) is
// nothing to divide by: the ratios stay finite with overflow trapped, as
// OpenFOAM traps it (a sheared layer under a plug stopped slideFoam so).
TEST(RunoutMechanism, RoundOffIsNil)
{
    std::vector<MaterialSample> layer;
    addMaterial(layer, 0.0, 1.0, flat(0.65), uniform(0.03), [](double, double h) { return h < 0.2 ? 1.0 : 1e-320; });
    std::vector<MaterialSample> still;
    addMaterial(still, 0.0, 1.0, flat(0.65), uniform(1e-300), uniform(0.0));
    const int before = fegetexcept();
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    const Mechanism sheared = detectMechanism(layer, view(), clay(false));
    const Mechanism resting = detectMechanism(still, view(), clay(false));
    fedisableexcept(FE_ALL_EXCEPT);
    feenableexcept(before);
    EXPECT_EQ(sheared.basalStrainRatio, 1e9);
    EXPECT_EQ(sheared.shearBand, "along the base");
    EXPECT_EQ(resting.basalSlipRatio, 0.0);
    EXPECT_EQ(resting.name, "viscous elongation");
}

TEST(RunoutMechanism, LogRoundTripAndRestart)
{
    const fs::path dir = fs::temp_directory_path()/"slidefoam_mechanismLog";
    fs::remove_all(dir);
    std::vector<MaterialSample> block, two;
    addMaterial(block, 0.0, 40.0, flat(H0), uniform(10.0), uniform(0.0));
    addMaterial(two, 0.0, 10.0, flat(2.0), uniform(0.0), uniform(0.0));
    addMaterial(two, 13.0, 20.0, flat(2.0), uniform(0.0), uniform(0.0));
    {
        MechanismLog log(dir.string(), "slideFoam");
        EXPECT_TRUE(log.kept().empty());
        log.write(0.0, detectMechanism(block, view(), clay()));
        log.write(1.0, detectMechanism(two, view(), clay()));
        log.write(1.5, detectMechanism({}, view(), clay()));   // no material: no row
        log.write(2.0, detectMechanism(block, view(), clay()));
    }
    const MechanismHistory all = readMechanismLog((dir/"postProcessing"/"slideFoam"/"mechanism.dat").string());
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[1], std::make_pair(1.0, std::string("breakaway")));
    EXPECT_EQ(all[2].second, "block sliding");
    // A restart at 1 s keeps the rows up to it and drops the rest.
    MechanismLog restarted(dir.string(), "slideFoam", true, 1.0);
    ASSERT_EQ(restarted.kept().size(), 2u);
    EXPECT_EQ(restarted.kept().back(), std::make_pair(1.0, std::string("breakaway")));
    fs::remove_all(dir);
}
