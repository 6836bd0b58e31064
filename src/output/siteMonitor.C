#include "siteMonitor.H"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace slide
{
namespace output
{

namespace
{

constexpr int valuesPerSite = 13;
const double notYet = std::numeric_limits<double>::quiet_NaN();

// The line that says which sites a sites.dat holds: a restart checks it.
std::string sitesLine(const std::vector<scene::Site>& sites)
{
    std::ostringstream os;
    os << std::setprecision(12) << "# sites (name position along the base [m]):";
    for (const scene::Site& s : sites) os << ' ' << s.name << ' ' << s.position;
    return os.str();
}

std::string header(const std::vector<scene::Site>& sites)
{
    std::ostringstream os;
    os << sitesLine(sites) << '\n'
       << "# time [s], then per site: covered (0/1)  thickness [m]  velocity [m/s]  arrival [s]  peakSpeed [m/s]"
          "  peakSpeedTime [s]  thicknessAtPeakSpeed [m]  peakMomentumFlux hV^2 [m3/s2]  peakMomentumFluxTime [s]"
          "  maxThickness [m]  maxThicknessTime [s]  lastCovered [s]"
          "  recordedFrom [s]  (nan: not yet)\n";
    return os.str();
}

void putNumber(std::ostream& os, const double v)
{
    if (std::isnan(v)) os << " nan";
    else os << ' ' << v;
}

} // namespace


SiteRecord::SiteRecord()
:
    arrival(notYet),
    peakSpeed(notYet),
    peakSpeedTime(notYet),
    thicknessAtPeakSpeed(notYet),
    peakMomentumFlux(notYet),
    peakMomentumFluxTime(notYet),
    maxThickness(notYet),
    maxThicknessTime(notYet),
    lastCovered(notYet)
{}


std::vector<SiteRecord> readSiteRecords(const std::string& path, const std::vector<scene::Site>& sites,
                                        const double time)
{
    std::ifstream is(path);
    std::string line;
    if (!std::getline(is, line) || line != sitesLine(sites)) return {};
    std::vector<SiteRecord> last;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        std::string word;
        std::vector<double> v;
        // operator>> does not read "nan"; stod does. A damaged row is skipped.
        try
        {
            while (ls >> word) v.push_back(std::stod(word));
        }
        catch (const std::exception&)
        {
            continue;
        }
        if (v.size() != 1 + valuesPerSite*sites.size() || v[0] > time*(1.0 + 1e-12) + 1e-300) continue;
        std::vector<SiteRecord> row(sites.size());
        for (std::size_t k = 0; k < sites.size(); ++k)
        {
            const double* x = &v[1 + valuesPerSite*k];
            SiteRecord& r = row[k];
            r.now.covered = x[0] != 0.0;
            r.now.thickness = x[1];
            r.now.velocity = x[2];
            r.arrival = x[3];
            r.peakSpeed = x[4];
            r.peakSpeedTime = x[5];
            r.thicknessAtPeakSpeed = x[6];
            r.peakMomentumFlux = x[7];
            r.peakMomentumFluxTime = x[8];
            r.maxThickness = x[9];
            r.maxThicknessTime = x[10];
            r.lastCovered = x[11];
            r.recordedFrom = x[12];
        }
        last = row;
    }
    return last;
}


SiteMonitor::SiteMonitor(const std::vector<scene::Site>& sites, const double initialFrontPosition,
                         const std::string& caseDir, const std::string& method, const bool append,
                         const double startTime)
:
    sites_(sites),
    initialFront_(initialFrontPosition),
    records_(sites.size())
{
    for (SiteRecord& r : records_) r.recordedFrom = startTime;
    if (sites_.empty()) return;
    path_ = (fs::path(methodOutputDir(caseDir, method))/"sites.dat").string();
    std::vector<SiteRecord> kept = append ? readSiteRecords(path_, sites_, startTime) : std::vector<SiteRecord>();
    if (!kept.empty()) records_ = kept;
    // The same sites: keep the rows to the restart; others (or none kept): a fresh file.
    os_ = openHistory(path_, header(sites_), !kept.empty(), startTime);
}

void SiteMonitor::observe(const double time, const std::vector<SiteFlow>& flow)
{
    if (flow.size() != records_.size())
    {
        throw std::logic_error("SiteMonitor::observe: " + std::to_string(flow.size()) + " observations for "
                               + std::to_string(records_.size()) + " sites");
    }
    for (std::size_t k = 0; k < records_.size(); ++k)
    {
        SiteRecord& r = records_[k];
        r.now = flow[k];
        if (!r.now.covered) continue;
        if (std::isnan(r.arrival)) r.arrival = time;
        r.lastCovered = time;
        const double speed = std::fabs(r.now.velocity);
        // isnan, not an ordered comparison: that raises FE_INVALID on NaN, which
        // OpenFOAM traps (FOAM_SIGFPE).
        if (std::isnan(r.peakSpeed) || speed > r.peakSpeed)
        {
            r.peakSpeed = speed;
            r.peakSpeedTime = time;
            r.thicknessAtPeakSpeed = r.now.thickness;
        }
        const double flux = r.now.thickness*r.now.velocity*r.now.velocity;
        if (std::isnan(r.peakMomentumFlux) || flux > r.peakMomentumFlux)
        {
            r.peakMomentumFlux = flux;
            r.peakMomentumFluxTime = time;
        }
        if (std::isnan(r.maxThickness) || r.now.thickness > r.maxThickness)
        {
            r.maxThickness = r.now.thickness;
            r.maxThicknessTime = time;
        }
    }
}

void SiteMonitor::write(const double time)
{
    if (sites_.empty()) return;
    // The time as runout.dat writes it; the record with every digit: a restart restores
    // it from this row, and a rounded maximum would be overtaken by a deposit at rest
    // that keeps its thickness exactly.
    os_ << std::setprecision(10) << time << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (const SiteRecord& r : records_)
    {
        os_ << ' ' << (r.now.covered ? 1 : 0);
        for (double v : {r.now.thickness, r.now.velocity, r.arrival, r.peakSpeed, r.peakSpeedTime,
                         r.thicknessAtPeakSpeed, r.peakMomentumFlux, r.peakMomentumFluxTime, r.maxThickness,
                         r.maxThicknessTime, r.lastCovered, r.recordedFrom})
        {
            putNumber(os_, v);
        }
    }
    os_ << '\n';
    os_.flush();
}

std::string SiteMonitor::json() const
{
    std::ostringstream os;
    os << '[';
    for (std::size_t k = 0; k < sites_.size(); ++k)
    {
        const SiteRecord& r = records_[k];
        os << (k ? ",\n    " : "\n    ") << "{\"name\": " << jsonEscape(sites_[k].name)
           << ", \"position_m\": " << jsonNumber(sites_[k].position)
           << ", \"distance_from_initial_front_m\": " << jsonNumber(sites_[k].position - initialFront_)
           << ", \"recorded_from_s\": " << jsonNumber(r.recordedFrom)
           << ", \"arrival_time_s\": " << jsonNumber(r.arrival)
           << ", \"peak_speed_m_s\": " << jsonNumber(r.peakSpeed)
           << ", \"peak_speed_time_s\": " << jsonNumber(r.peakSpeedTime)
           << ", \"thickness_at_peak_speed_m\": " << jsonNumber(r.thicknessAtPeakSpeed)
           << ", \"peak_momentum_flux_m3_s2\": " << jsonNumber(r.peakMomentumFlux)
           << ", \"peak_momentum_flux_time_s\": " << jsonNumber(r.peakMomentumFluxTime)
           << ", \"max_thickness_m\": " << jsonNumber(r.maxThickness)
           << ", \"max_thickness_time_s\": " << jsonNumber(r.maxThicknessTime)
           << ", \"last_covered_s\": " << jsonNumber(r.lastCovered)
           << ", \"covered_at_end\": " << (r.now.covered ? "true" : "false")
           << ", \"final_thickness_m\": " << jsonNumber(r.now.covered ? r.now.thickness : 0.0) << '}';
    }
    os << (sites_.empty() ? "]" : "\n  ]");
    return os.str();
}

void SiteMonitor::addTo(Summary& summary) const
{
    if (!sites_.empty()) summary.extra.emplace_back("sites", json());
}

} // namespace output
} // namespace slide
