// The output contract: runout.dat, summary.json, VTK XML + .pvd series.
#include "application.H"
#include "dictionary.H"
#include "outputContract.H"
#include "restartState.H"
#include "siteMonitor.H"
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

TEST(RestartState, ValuesRoundTripBitForBit)
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
    f.add("none", std::vector<double>{});
    f.write((d/"x.state").string());
    const StateFile g = StateFile::read((d/"x.state").string());
    const std::vector<double>& back = g.vector("values");
    ASSERT_EQ(back.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        EXPECT_EQ(std::memcmp(&back[i], &values[i], sizeof(double)), 0) << "value " << i << ": " << values[i];
    }
    EXPECT_EQ(g.scalar("time"), 4.1);
    EXPECT_TRUE(g.vector("none").empty());
    // Raw doubles: the file is the values' bytes and a line per key, not text.
    const std::string text = slurp(d/"x.state");
    EXPECT_NE(text.find("\nvalues 14\n"), std::string::npos);
    EXPECT_LT(text.size(), 8*(values.size() + 1) + 200);
    fs::remove_all(d);
}

TEST(RestartState, ReadsTheHexadecimalStatesOfEarlierVersions)
{
    const fs::path d = freshDir("hexState");
    std::ofstream((d/"old.state").string())
        << "// SlideFoam restart state: key, count, values as hexadecimal floats\n"
        << "time 1\n0x1.0666666666666p+2\nvalues 3\n-0x1.8p+0\n0x0p+0\n-0x0p+0\n";
    const StateFile g = StateFile::read((d/"old.state").string());
    EXPECT_EQ(g.scalar("time"), 4.1);
    ASSERT_EQ(g.vector("values").size(), 3u);
    EXPECT_EQ(g.vector("values")[0], -1.5);
    EXPECT_FALSE(std::signbit(g.vector("values")[1]));
    EXPECT_TRUE(std::signbit(g.vector("values")[2]));
    fs::remove_all(d);
}

TEST(RestartState, ATruncatedStateNamesFileAndKey)
{
    // A state cut short (a full disk, a copy broken off) is refused, naming the
    // key whose values are missing, rather than read as zeros.
    const fs::path d = freshDir("cutState");
    StateFile f;
    f.add("time", {4.1});
    f.add("position", std::vector<double>(1000, 0.5));
    const std::string path = (d/"cut.state").string();
    f.write(path);
    fs::resize_file(path, fs::file_size(path) - 100);
    try
    {
        StateFile::read(path);
        ADD_FAILURE() << "a truncated state was read";
    }
    catch (const slide::scene::InputError& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find("position"), std::string::npos) << what;
        EXPECT_NE(what.find("truncated"), std::string::npos) << what;
    }
    fs::remove_all(d);
}

TEST(RestartState, ScheduleResumesUnderAChangedWriteInterval)
{
    // A run written every 5 s, stopped after its write at 160 s (index 33: next
    // write 165 s), restarted with writeInterval 0.5. Keeping the old index under the
    // new interval put the next write at 16.5 s, behind the restart: a negative
    // step that blew the run up.
    slide::scene::RunControl rc;
    rc.endTime = 300.0;
    rc.writeInterval = 5.0;
    WriteSchedule written(rc);
    double t = 0.0;
    while (written.index() < 33)
    {
        const WriteSchedule::Step s = written.clip(t, 0.7);
        t = s.time;
        if (written.writeDue(s)) written.next();
    }
    ASSERT_DOUBLE_EQ(t, 160.0);
    RestartClock clock;
    clock.time = t;
    clock.scheduleOrigin = written.origin();
    clock.scheduleIndex = written.index();
    clock.scheduleInterval = written.interval();
    StateFile f;
    clock.addTo(f);
    const fs::path d = freshDir("schedule");
    f.write((d/"s.state").string());
    const RestartClock back = RestartClock::readFrom(StateFile::read((d/"s.state").string()));

    // Same interval: the same write times, so a restart continues bit for bit.
    WriteSchedule same = back.schedule(rc);
    EXPECT_EQ(same.index(), 33);
    EXPECT_EQ(same.clip(t, 100.0).time, 165.0);

    // A new interval counts from the restart.
    rc.writeInterval = 0.5;
    WriteSchedule changed = back.schedule(rc);
    const WriteSchedule::Step s = changed.clip(t, 100.0);
    EXPECT_GT(s.dt, 0.0);
    EXPECT_DOUBLE_EQ(s.time, 160.5);
    EXPECT_TRUE(changed.writeDue(s));

    // A state from before the interval was kept (none stored) restarts the same safe way.
    RestartClock old = back;
    old.scheduleInterval = 0.0;
    rc.writeInterval = 5.0;
    EXPECT_DOUBLE_EQ(old.schedule(rc).clip(t, 100.0).time, 165.0);
    fs::remove_all(d);
}

TEST(RestartState, PurgeWriteKeepsTheLastStatesOfThisMethodOnly)
{
    const fs::path c = freshDir("purge");
    // Time 1 also holds another method's state, time 2 a field slideFoam wrote.
    fs::create_directories(c/"1");
    std::ofstream(c/"1"/"slideDAM.state") << "other method";
    fs::create_directories(c/"2");
    std::ofstream(c/"2"/"U") << "a CFD field";
    StatePurge purge(c.string(), "slideMPM", 2);
    for (double t : {0.5, 1.0, 2.0, 2.5, 3.0})
    {
        StateFile f;
        f.add("time", t);
        f.write(statePath(c.string(), t, "slideMPM"));
        purge.written(t);
    }
    purge.written(3.0);   // the last time written again: it must not push out 2.5
    EXPECT_FALSE(fs::exists(c/"0.5"));                  // emptied: removed
    EXPECT_FALSE(fs::exists(c/"1"/"slideMPM.state"));
    EXPECT_TRUE(fs::exists(c/"1"/"slideDAM.state"));
    EXPECT_FALSE(fs::exists(c/"2"/"slideMPM.state"));
    EXPECT_TRUE(fs::exists(c/"2"/"U"));
    EXPECT_TRUE(fs::exists(c/"2.5"/"slideMPM.state"));
    EXPECT_TRUE(fs::exists(c/"3"/"slideMPM.state"));

    // purgeWrite 0 (the default) keeps every write.
    StatePurge keepAll(c.string(), "slideMPM", 0);
    for (double t : {4.0, 5.0, 6.0})
    {
        StateFile f;
        f.add("time", t);
        f.write(statePath(c.string(), t, "slideMPM"));
        keepAll.written(t);
    }
    for (const char* t : {"2.5", "3", "4", "5", "6"}) EXPECT_TRUE(fs::exists(c/t/"slideMPM.state")) << t;
    fs::remove_all(c);
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
        // What a restart finds: the run's start (slideFoam's volume reference) and its own start row.
        ASSERT_EQ(log.kept().size(), 3u);
        EXPECT_DOUBLE_EQ(log.kept().front().mass, 579.42);
        EXPECT_DOUBLE_EQ(log.kept().back().time, 1.0);
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

namespace
{

// A front passing two sites at 2 m/s from s = 10 m, the slide 1 m thick behind
// it and 4 m long, its speed 2 m/s until 3 s and slowing after; a third site it never reaches.
std::vector<SiteFlow> passingSlide(const double t, const std::vector<slide::scene::Site>& sites)
{
    const double front = 10.0 + 2.0*std::min(t, 3.0) + (t > 3.0 ? 0.5*(t - 3.0) : 0.0);
    const double speed = t < 3.0 ? 2.0 : 0.5;
    std::vector<SiteFlow> flow(sites.size());
    for (std::size_t k = 0; k < sites.size(); ++k)
    {
        const double x = sites[k].position;
        if (x > front || x < front - 4.0) continue;
        flow[k].covered = true;
        flow[k].thickness = 1.0 + 0.1*(front - x);
        flow[k].velocity = speed;
    }
    return flow;
}

} // namespace

TEST(SiteMonitor, RecordsArrivalPeakAndPassageAndRestoresThemAtARestart)
{
    const fs::path c = freshDir("sites");
    const std::vector<slide::scene::Site> sites{{"pipe", 12.0}, {"cable", 15.0}, {"far", 100.0}};
    const double dt = 0.25;
    const auto run = [&](SiteMonitor& m, double t0, double t1)
    {
        for (double t = t0; t <= t1 + 1e-9; t += dt)
        {
            m.observe(t, passingSlide(t, sites));
            if (std::fabs(t - std::round(t)) < 1e-9) m.write(t);
        }
    };
    {
        SiteMonitor m(sites, 10.0, c.string(), "slideDAM", false, 0.0);
        run(m, 0.0, 8.0);
        const auto& r = m.records();
        // The front (10 + 2 t) reaches 12 m at 1 s and 15 m at 2.5 s; it slows to 0.5 m/s after 3 s.
        EXPECT_DOUBLE_EQ(r[0].arrival, 1.0);
        EXPECT_DOUBLE_EQ(r[1].arrival, 2.5);
        EXPECT_DOUBLE_EQ(r[0].peakSpeed, 2.0);
        EXPECT_DOUBLE_EQ(r[0].peakSpeedTime, 1.0);        // the first time at the peak
        EXPECT_DOUBLE_EQ(r[1].peakSpeedTime, 2.5);
        EXPECT_DOUBLE_EQ(r[1].maxThicknessTime, 8.0);      // the deposit thickens as the front creeps on
        // The rear (front - 4) leaves 12 m at 3 s: last covered then, thickest (1.4 m) just before.
        EXPECT_DOUBLE_EQ(r[0].lastCovered, 3.0);
        EXPECT_NEAR(r[0].maxThickness, 1.4, 1e-12);
        EXPECT_DOUBLE_EQ(r[0].maxThicknessTime, 3.0);
        // h V^2 grows with the thickness while the speed holds, 1.35 m x (2 m/s)^2 at 2.75 s, and falls as the
        // slide slows at 3 s, where the thickness peaks.
        EXPECT_NEAR(r[0].peakMomentumFlux, 5.4, 1e-12);
        EXPECT_DOUBLE_EQ(r[0].peakMomentumFluxTime, 2.75);
        EXPECT_FALSE(r[0].now.covered);
        EXPECT_TRUE(r[1].now.covered);
        EXPECT_TRUE(std::isnan(r[2].arrival));
        const std::string json = m.json();
        EXPECT_NE(json.find("\"name\": \"far\", \"position_m\": 100, \"distance_from_initial_front_m\": 90, "
                            "\"recorded_from_s\": 0, \"arrival_time_s\": null"), std::string::npos) << json;
        EXPECT_NE(json.find("\"covered_at_end\": true, \"final_thickness_m\": 1.35"), std::string::npos) << json;
    }
    const std::string path = (c/"postProcessing/slideDAM/sites.dat").string();
    const std::string uninterrupted = slurp(path);
    // A restart at 2 s restores the record of that row and, run on, writes the same file.
    ASSERT_EQ(readSiteRecords(path, sites, 2.0).size(), 3u);
    EXPECT_DOUBLE_EQ(readSiteRecords(path, sites, 2.0)[0].arrival, 1.0);
    {
        SiteMonitor m(sites, 10.0, c.string(), "slideDAM", true, 2.0);
        EXPECT_DOUBLE_EQ(m.records()[0].peakSpeedTime, 1.0);
        run(m, 2.25, 8.0);
    }
    EXPECT_EQ(slurp(path), uninterrupted);
    // Other sites at a restart: a fresh file, the records kept from the restart on.
    {
        const std::vector<slide::scene::Site> moved{{"pipe", 13.0}};
        EXPECT_TRUE(readSiteRecords(path, moved, 2.0).empty());
        SiteMonitor m(moved, 10.0, c.string(), "slideDAM", true, 2.0);
        EXPECT_DOUBLE_EQ(m.records()[0].recordedFrom, 2.0);
        EXPECT_TRUE(std::isnan(m.records()[0].arrival));
        m.observe(2.0, passingSlide(2.0, moved));
        EXPECT_DOUBLE_EQ(m.records()[0].arrival, 2.0);
    }
    // No sites: nothing written.
    {
        const fs::path e = freshDir("noSites");
        SiteMonitor m({}, 10.0, e.string(), "slideDAM", false, 0.0);
        m.write(0.0);
        EXPECT_FALSE(fs::exists(e/"postProcessing/slideDAM/sites.dat"));
        Summary sum;
        m.addTo(sum);
        EXPECT_TRUE(sum.extra.empty());
        fs::remove_all(e);
    }
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
