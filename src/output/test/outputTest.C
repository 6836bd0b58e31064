// The output contract: runout.dat, summary.json, VTK XML + .pvd series.
#include "application.H"
#include "dictionary.H"
#include "outputContract.H"
#include "restartState.H"
#include "vtkWriter.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;
using namespace slide::output;

namespace
{

std::string slurp(const fs::path& p)
{
    std::ifstream is(p, std::ios::binary);
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}

fs::path freshDir(const std::string& name)
{
    const fs::path d = fs::temp_directory_path()/("slideOutputTest_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

} // namespace

TEST(RestartState, HexFloatsRoundTripBitForBit)
{
    // Restarts must continue bit-identically: every double, signed zeros,
    // subnormals and the extremes included, comes back exactly.
    const fs::path d = freshDir("state");
    const double tiny = std::numeric_limits<double>::denorm_min();
    const std::vector<double> values{0.0, -0.0, 1.0, -1.5, 0.1, -1.0/3.0, 6.02214076e23, -2.5e-310, tiny, -tiny,
                                     std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                     std::numeric_limits<double>::min(), std::numeric_limits<double>::infinity()};
    StateFile f;
    f.add("values", values);
    f.add("time", {4.1});
    f.write((d/"x.state").string());
    const StateFile g = StateFile::read((d/"x.state").string());
    const std::vector<double>& back = g.vector("values");
    ASSERT_EQ(back.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        EXPECT_EQ(std::memcmp(&back[i], &values[i], sizeof(double)), 0) << "value " << i << ": " << values[i];
    }
    EXPECT_EQ(g.scalar("time"), 4.1);
    EXPECT_NE(slurp(d/"x.state").find("\n-0x1.8p+0\n"), std::string::npos);   // C99 %a form
    fs::remove_all(d);
}

TEST(OutputContract, RunoutLogRoundTripAndRestart)
{
    const fs::path c = freshDir("runout");
    {
        RunoutLog log(c.string(), "slideDAM");
        for (int i = 0; i <= 4; ++i)
        {
            RunoutSample s;
            s.time = 0.5*i;
            s.front = 1.25*i;
            s.rear = -0.1*i;
            s.mass = 579.42;
            log.write(s);
        }
    }
    const auto rows = readRunoutLog((c/"postProcessing/slideDAM/runout.dat").string());
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_DOUBLE_EQ(rows[3].front, 3.75);
    EXPECT_DOUBLE_EQ(rows[4].mass, 579.42);
    EXPECT_EQ(slurp(c/"postProcessing/slideDAM/runout.dat").rfind("# time [s]  front [m]  rear [m]", 0), 0u);
    // A restart from t = 1 keeps the rows up to 1 and continues.
    {
        RunoutLog log(c.string(), "slideDAM", true, 1.0);
        RunoutSample s;
        s.time = 1.5;
        s.front = 9.0;
        log.write(s);
    }
    const auto again = readRunoutLog((c/"postProcessing/slideDAM/runout.dat").string());
    ASSERT_EQ(again.size(), 4u);
    EXPECT_DOUBLE_EQ(again[2].time, 1.0);
    EXPECT_DOUBLE_EQ(again[3].front, 9.0);
    fs::remove_all(c);
}

TEST(OutputContract, SummaryIsWholeJsonAndStaleOneIsRemoved)
{
    const fs::path c = freshDir("summary");
    Summary s;
    s.method = "slideDAM";
    s.caseName = "case \"2\"";
    s.runout = 61.5;
    s.endTime = 40.0;
    s.atRest = true;
    s.wallTime = 0.25;
    s.problemSize = 4001;
    s.problemSizeUnit = "columns";
    s.backend = "serial";
    s.addString("mechanism", "elongation");
    s.addNumber("bad", NAN);
    s.write(c.string());
    const std::string j = slurp(c/"postProcessing/slideDAM/summary.json");
    EXPECT_NE(j.find("\"runout_m\": 61.5"), std::string::npos) << j;
    EXPECT_NE(j.find("\"case\": \"case \\\"2\\\"\""), std::string::npos) << j;
    EXPECT_NE(j.find("\"at_rest\": true"), std::string::npos);
    EXPECT_NE(j.find("\"mechanism\": \"elongation\""), std::string::npos);
    EXPECT_NE(j.find("\"bad\": null"), std::string::npos);
    EXPECT_FALSE(fs::exists(c/"postProcessing/slideDAM/summary.json.tmp"));
    prepareOutput(c.string(), "slideDAM");
    EXPECT_FALSE(fs::exists(c/"postProcessing/slideDAM/summary.json"));
    fs::remove_all(c);
}

TEST(OutputContract, VtkPolyDataAndPvdSeries)
{
    const fs::path c = freshDir("vtk");
    PolyData pd;
    pd.cells = PolyData::Cells::vertices;
    for (int i = 0; i < 3; ++i) pd.addPoint(i, 0, -0.1*i);
    pd.addScalar("xi", {0.0, 1.0, 2.0});
    pd.addVector("U", {1, 0, 0, 2, 0, 0, 3, 0, 0});
    EXPECT_THROW(pd.addScalar("wrong", {1.0}), std::logic_error);

    PvdSeries series(c.string(), "particles");
    series.add(0.0, pd);
    series.add(0.5, pd);
    const std::string vtp = slurp(c/"particles/particles_000001.vtp");
    EXPECT_EQ(vtp.rfind("<?xml", 0), 0u);
    EXPECT_NE(vtp.find("NumberOfPoints=\"3\" NumberOfVerts=\"3\""), std::string::npos);
    EXPECT_NE(vtp.find("Name=\"U\" NumberOfComponents=\"3\""), std::string::npos);
    // The appended block of the first array holds its 3 doubles after a UInt64 byte count.
    const std::size_t start = vtp.find("_", vtp.find("<AppendedData")) + 1;
    std::uint64_t nbytes = 0;
    std::memcpy(&nbytes, vtp.data() + start, 8);
    EXPECT_EQ(nbytes, 24u);
    double xi1 = 0.0;
    std::memcpy(&xi1, vtp.data() + start + 8 + 8, 8);
    EXPECT_DOUBLE_EQ(xi1, 1.0);

    std::string pvd = slurp(c/"particles.pvd");
    EXPECT_NE(pvd.find("timestep=\"0.5\" part=\"0\" file=\"particles/particles_000001.vtp\""), std::string::npos);
    // A restart from t = 0 drops the later step, and a reopened series sees what is on disk.
    PvdSeries reopened(c.string(), "particles");
    reopened.truncateAfter(0.0);
    pvd = slurp(c/"particles.pvd");
    EXPECT_EQ(pvd.find("timestep=\"0.5\""), std::string::npos);
    EXPECT_FALSE(fs::exists(c/"particles/particles_000001.vtp"));
    fs::remove_all(c);
}

TEST(Application, MemoryCheckRefusesAbsurdSizes)
{
    ASSERT_GT(availableMemoryBytes(), 0u);
    EXPECT_NO_THROW(checkMemory(1024, "test", "f", 1, "k"));
    try
    {
        checkMemory(1ull << 60, "a grid of 1e18 cells", "case/system/mpmDict", 7, "cellSize");
        FAIL() << "no error";
    }
    catch (const slide::scene::InputError& e)
    {
        EXPECT_EQ(e.file(), "case/system/mpmDict");
        EXPECT_EQ(e.line(), 7);
        EXPECT_EQ(e.key(), "cellSize");
        EXPECT_NE(e.message().find("GiB"), std::string::npos);
    }
}
