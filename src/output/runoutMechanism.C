#include "runoutMechanism.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace slide
{
namespace output
{

namespace
{

// The weighted median of (value, vote) pairs: with equal votes, the element a
// sort would put at n/2 (what nth_element picked before cells voted by volume).
double median(std::vector<std::pair<double, double>> v)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    double total = 0.0;
    for (const auto& e : v) total += e.second;
    double sum = 0.0;
    for (const auto& e : v)
    {
        sum += e.second;
        if (sum > 0.5*total) return e.first;
    }
    return v.back().first;
}

const char* mechanismHeader =
    "# time [s]  bodies  grabens  horsts  basalSlipRatio  basalStrainRatio  shearBand  mechanism\n"
    "# (shearBand and mechanism as their index: shearBand 0 along the base, 1 in the body, 2 none;"
    " mechanism 0 viscous elongation, 1 block sliding, 2 spreading (horsts and grabens), 3 breakaway)\n";

const std::vector<std::string>& shearBandNames()
{
    static const std::vector<std::string> names{"along the base", "in the body", "none"};
    return names;
}

int indexOf(const std::vector<std::string>& names, const std::string& name)
{
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw std::runtime_error("unknown name '" + name + "' for mechanism.dat");
    return static_cast<int>(it - names.begin());
}

} // namespace

Mechanism detectMechanism(const std::vector<MaterialSample>& samples, const MechanismView& view,
                          const rheology::HerschelBulkleyRemoulding& material)
{
    Mechanism m;
    if (samples.empty())
    {
        m.name = "none";
        return m;
    }
    const double H0 = view.H0;
    // Columns along the base: occupancy, top surface, basal layer.
    const double width = view.columnWidth;
    double x0 = 1e300, x1 = -1e300;
    for (const MaterialSample& p : samples)
    {
        x0 = std::min(x0, p.s - p.halfLength);
        x1 = std::max(x1, p.s + p.halfLength);
    }
    const int nCol = static_cast<int>(std::ceil((x1 - x0)/width)) + 1;
    auto column = [&](const MaterialSample& p)
    {
        return std::min(nCol - 1, std::max(0, static_cast<int>((p.s - x0)/width)));
    };
    std::vector<double> top(nCol, -1.0), bottom(nCol, 1e300);
    double sampleHeight = 0.0;   // the tallest sample: how finely the tops are known
    for (const MaterialSample& p : samples)
    {
        const int c = column(p);
        top[c] = std::max(top[c], p.h + p.halfHeight);
        bottom[c] = std::min(bottom[c], p.h - p.halfHeight);
        sampleHeight = std::max(sampleHeight, 2.0*p.halfHeight);
    }
    // Bodies: runs of occupied columns separated by at least two empty ones (2 H0/5).
    // On a base that holds what touches it (no-slip), a body sliding away on its
    // remoulded basal band leaves the band behind as a film, so the columns
    // between never empty: a remoulded film (below H0/20, half its strength lost)
    // over two columns or more also parts a run, where the parts on both sides
    // reach H0/5 (slabs, not the film's own ripples or a thin tongue).
    std::vector<std::vector<std::pair<double, double>>> columnXi(nCol);
    if (material.deltaRem < 1.0)
    {
        for (const MaterialSample& p : samples) columnXi[column(p)].emplace_back(p.xi, p.vote);
    }
    auto remouldedFilm = [&](int c)
    {
        return material.deltaRem < 1.0 && top[c] >= 0.0 && top[c] < remouldedFilmHeight*H0
            && (material.remouldingFactor(median(columnXi[c])) - material.deltaRem)/(1.0 - material.deltaRem) <= 0.5;
    };
    m.bodies = 0;
    int empty = 2, gap = 2, slabs = 0;
    bool slab = false;                 // the part since the last gap reaches H0/5
    auto endPart = [&]() { if (slab) ++slabs; slab = false; };
    for (int c = 0; c < nCol; ++c)
    {
        if (top[c] < 0.0 || remouldedFilm(c))
        {
            empty = top[c] < 0.0 ? empty + 1 : 0;
            if (++gap == 2) endPart();
            continue;
        }
        if (empty >= 2)
        {
            // A run parted from the last by empty columns: its slabs, or itself.
            m.bodies += std::max(slabs, 1)*(c > 0 ? 1 : 0);
            slabs = 0;
        }
        slab = slab || top[c] >= 0.2*H0;
        empty = 0;
        gap = 0;
    }
    endPart();
    m.bodies += std::max(slabs, 1);
    // Grabens: surface depressions deeper than H0/5 below the crests on both sides
    // (crests = running maxima within 2 H0), found on the column tops, and deeper
    // than one and a half samples: a cell less than half slide is no sample, so on
    // a mesh of H0/4 (the Finneidfjord block's) a top cell that the interface
    // leaves partly empty drops its column a whole cell, a quarter of H0.
    const double grabenDepth = std::max(0.2*H0, 1.5*sampleHeight);
    const int reach = std::max(2, static_cast<int>(std::ceil(2.0*H0/width)));
    int c = 0;
    while (c < nCol)
    {
        if (top[c] < 0.0) { ++c; continue; }
        double left = 0.0, right = 0.0;
        for (int k = std::max(0, c - reach); k < c; ++k) left = std::max(left, top[k]);
        for (int k = c + 1; k <= std::min(nCol - 1, c + reach); ++k) right = std::max(right, top[k]);
        bool localMin = true;
        for (int k = std::max(0, c - 1); k <= std::min(nCol - 1, c + 1); ++k)
        {
            if (top[k] >= 0.0 && top[k] < top[c]) localMin = false;
        }
        if (localMin && std::min(left, right) - top[c] > grabenDepth)
        {
            ++m.grabens;
            c += reach;   // one graben per trough
            continue;
        }
        ++c;
    }
    // Basal layer: the samples within basalLayer of the lowest in their column, where that one is on the base.
    double M = 0.0, P = 0.0, Mb = 0.0, Pb = 0.0;
    std::vector<std::pair<double, double>> xiBase, xiBody;
    std::vector<std::vector<std::pair<double, double>>> bodyXi(nCol);   // per column, above its basal layer (horsts)
    for (const MaterialSample& p : samples)
    {
        const int col = column(p);
        const double above = p.h - bottom[col];   // its centre above its column's bottom
        if (above >= view.basalLayer) bodyXi[col].emplace_back(p.xi, p.vote);
        M += p.mass;
        P += p.mass*p.velocity;
        if (above < view.basalLayer && bottom[col] < view.basalLayer)
        {
            Mb += p.mass;
            Pb += p.mass*p.velocity;
            xiBase.emplace_back(p.xi, p.vote);
        }
        else
        {
            xiBody.emplace_back(p.xi, p.vote);
        }
    }
    // Horsts: in a remoulding material, blocks whose body (above the basal layer)
    // has kept nine tenths of its strength, at least H0/5 high and two columns
    // long, each parted from the next by columns whose body has lost half of it
    // (the shear bands and grabens between the paper's horsts), or none left.
    if (material.deltaRem < 1.0)
    {
        const double loss = 1.0 - material.deltaRem;
        int run = 0;              // intact columns in the current block
        bool parted = true;       // remoulded columns since the last block
        for (int col = 0; col <= nCol; ++col)
        {
            const bool occupied = col < nCol && top[col] >= 0.0;
            const double kept = occupied && !bodyXi[col].empty()
                ? (material.remouldingFactor(median(bodyXi[col])) - material.deltaRem)/loss : 0.0;
            if (occupied && kept >= 0.9 && top[col] >= 0.2*H0)
            {
                ++run;
                continue;
            }
            if (run >= 2 && parted)
            {
                ++m.horsts;
                parted = false;
            }
            run = 0;
            if (occupied && kept <= 0.5) parted = true;
        }
        if (m.horsts < 2) m.horsts = 0;
    }
    // Speeds and strains below these are nil: a ratio over round-off (an advected
    // xi of 1e-320 in a plug) would overflow, and trap where FPEs do (OpenFOAM).
    const double nilSpeed = 1e-12, nilStrain = 1e-9;
    const double V = M > 0.0 ? P/M : 0.0;
    m.basalSlipRatio = (Mb > 0.0 && std::fabs(V) > nilSpeed) ? (Pb/Mb)/V : 0.0;
    const double xb = median(xiBase), xr = median(xiBody);
    m.basalStrainRatio = xr > nilStrain ? xb/xr : (xb > nilStrain ? 1e9 : 1.0);
    m.shearBand = (xb > 0.5 && m.basalStrainRatio > 3.0) ? shearBandNames()[0]
                : (m.grabens > 0 || m.horsts > 0 ? shearBandNames()[1] : shearBandNames()[2]);

    const std::vector<std::string>& names = mechanismNames();
    if (m.bodies > 1) m.name = names[3];
    else if (m.grabens >= 2 || m.horsts >= 2) m.name = names[2];
    else if (std::fabs(V) > 0.1*std::sqrt(view.g*H0) && m.basalSlipRatio > 0.8) m.name = names[1];
    else m.name = names[0];
    return m;
}

void addMechanism(Summary& summary, const MechanismHistory& history, const Mechanism& finalState, const bool atRest,
                  const double H0)
{
    summary.addString("mechanism", runMechanism(history, finalState.name, atRest));
    summary.addString("final_state_mechanism", finalState.name);
    summary.addString("shear_band", finalState.shearBand);
    summary.addNumber("bodies", finalState.bodies);
    summary.addNumber("breakaway_film_height_m", remouldedFilmHeight*H0);
    summary.addNumber("grabens", finalState.grabens);
    summary.addNumber("horsts", finalState.horsts);
    summary.addNumber("basal_slip_ratio", finalState.basalSlipRatio);
    summary.extra.emplace_back("mechanism_history", mechanismHistoryJson(history));
}

MechanismLog::MechanismLog(const std::string& caseDir, const std::string& method, const bool append,
                           const double startTime)
:
    path_(methodOutputDir(caseDir, method) + "/mechanism.dat"),
    os_(openHistory(path_, mechanismHeader, append, startTime)),
    kept_(append ? readMechanismLog(path_) : MechanismHistory())
{}

void MechanismLog::write(const double time, const Mechanism& m)
{
    if (m.name == "none") return;   // no material to look at: nothing to record
    os_ << std::setprecision(10) << time << ' ' << m.bodies << ' ' << m.grabens << ' ' << m.horsts << ' '
        << std::setprecision(6) << m.basalSlipRatio << ' ' << m.basalStrainRatio << ' '
        << indexOf(shearBandNames(), m.shearBand) << ' ' << indexOf(mechanismNames(), m.name) << '\n';
    os_.flush();
}

MechanismHistory readMechanismLog(const std::string& path)
{
    MechanismHistory rows;
    std::ifstream is(path);
    std::string line;
    const std::vector<std::string>& names = mechanismNames();
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        double t, slip, strain;
        int bodies, grabens, horsts, band, code;
        if (ls >> t >> bodies >> grabens >> horsts >> slip >> strain >> band >> code && code >= 0
            && code < static_cast<int>(names.size()))
        {
            rows.emplace_back(t, names[code]);
        }
    }
    return rows;
}

} // namespace output
} // namespace slide
