#include "frontResolution.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace slide
{
namespace mpm
{

FrontZone frontZone(const HostPoints& hp, const BaseFrame& frame, const double length)
{
    FrontZone z;
    if (hp.count == 0) return z;
    const BaseLevelSet& level = frame.level;
    const double front = level.arcLength(hp.frontX());
    z.length = std::min(length, front - level.arcLength(hp.rearX()));
    double volume = 0.0, mass = 0.0, momentum = 0.0;
    for (int p = 0; p < hp.count; ++p)
    {
        const double x = hp.position(p, 0);
        if (level.arcLength(x) < front - z.length) continue;
        // Along the base's local tangent (1, slope)/|.| of the frame.
        const double slope = level.slope(x);
        const double along = (hp.velocity(p, 0) + slope*hp.velocity(p, 1))/std::sqrt(1.0 + slope*slope);
        volume += hp.volume(p);
        mass += hp.mass(p);
        momentum += hp.mass(p)*along;
    }
    if (z.length > 0.0) z.thickness = volume/z.length;
    if (mass > 0.0) z.speed = momentum/mass;
    return z;
}

std::vector<double> FrontRecord::values() const
{
    return {previousFront, previousUnder ? 1.0 : 0.0, minCells, minCellsTime, firstTime, travel};
}

FrontRecord FrontRecord::fromValues(const std::vector<double>& v, const std::string& path, const std::string& key)
{
    if (v.size() != 6) throw scene::InputError(path, 0, key, "expected 6 values, found " + std::to_string(v.size()));
    FrontRecord r;
    r.previousFront = v[0];
    r.previousUnder = v[1] != 0.0;
    r.minCells = v[2];
    r.minCellsTime = v[3];
    r.firstTime = v[4];
    r.travel = v[5];
    return r;
}

FrontResolution::FrontResolution(const double cellSize, const double zoneLength, const double restVelocity,
                                 const FrontRecord& record)
:
    cellSize_(cellSize), zoneLength_(zoneLength), restVelocity_(restVelocity), r_(record)
{}

std::string FrontResolution::observe(const double t, const double front, const FrontZone& zone)
{
    if (r_.previousUnder) r_.travel += std::max(0.0, front - r_.previousFront);
    const bool moving = zone.speed > restVelocity_;
    const double n = cells(zone);
    r_.previousUnder = moving && n < resolvedCells;
    r_.previousFront = front;
    if (moving && n < r_.minCells)
    {
        r_.minCells = n;
        r_.minCellsTime = t;
    }
    if (!r_.previousUnder || r_.firstTime >= 0.0) return "";
    r_.firstTime = t;
    std::ostringstream os;
    os << std::setprecision(3) << "Warning: at t = " << t << " s the slide's front (its foremost " << zone.length
       << " m) is " << zone.thickness << " m thick, " << n << " cells of " << cellSize_ << " m, and moves at "
       << zone.speed << " m/s. A weak slide's runout changes with the cell where its moving front is under about "
       << resolvedCells << " cells thick (validation/mpm/README.md, \"Where the cells part\"); where the runout "
       << "matters, rerun with smaller cells (cellsPerHeight in system/mpmDict) and compare. summary.json's "
       << "front_travel_under_resolved_m says how far the front ran so.";
    return os.str();
}

void FrontResolution::addTo(output::Summary& s, const double runout) const
{
    s.addNumber("front_zone_length_m", zoneLength_);
    s.addNumber("front_min_cells_moving", r_.minCells);
    s.addNumber("front_min_cells_time_s", r_.minCellsTime >= 0.0 ? r_.minCellsTime : NAN);
    s.addNumber("front_under_resolved_from_s", r_.firstTime >= 0.0 ? r_.firstTime : NAN);
    s.addNumber("front_travel_under_resolved_m", r_.travel);
    s.addNumber("front_travel_under_resolved_fraction", runout > 0.0 ? r_.travel/runout : 0.0);
}

std::string FrontResolution::report(const double runout) const
{
    if (r_.minCellsTime < 0.0) return "";
    std::ostringstream os;
    os << std::setprecision(3) << "Front: at least " << r_.minCells << " cells through it while it moved (t = "
       << r_.minCellsTime << " s); " << r_.travel << " m of the " << runout << " m runout run under "
       << resolvedCells << " cells" << (r_.firstTime >= 0.0 ? " (see the warning above)" : "") << "\n";
    return os.str();
}

} // namespace mpm
} // namespace slide
