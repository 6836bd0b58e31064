#include "damOutput.H"

#include <algorithm>
#include <cmath>

#include "basalResistance.H"

namespace slide
{
namespace dam
{

output::RunoutSample runoutSample(const SlideColumns& s, double time, double rho)
{
    output::RunoutSample r;
    r.time = time;
    r.front = s.front();
    r.rear = s.rear();
    r.frontVelocity = s.U.back();
    const int N = s.nColumns();
    for (int j = 0; j <= N; ++j)
    {
        r.maxVelocity = std::max(r.maxVelocity, std::max(std::fabs(s.U[j]), std::fabs(s.Up[j])));
        const double m = s.nodeArea(j);
        r.kineticEnergy += 0.5*rho*m*s.U[j]*s.U[j];
    }
    for (int i = 0; i < N; ++i) r.maxThickness = std::max(r.maxThickness, s.columnThickness(i));
    r.mass = rho*s.totalArea();
    return r;
}

double shearStrength(const SlideColumns& s, const scene::Scene& sc, int j)
{
    return sc.rheology.strength(s.basalRate[j], s.xi[j]);
}

double basalStress(const SlideColumns& s, const scene::Scene& sc, int j)
{
    const auto regime = static_cast<rheology::BasalRegime>(s.regime[j]);
    const double sb = sc.interface.basalStrength(std::fabs(s.U[j]));
    if (regime == rheology::BasalRegime::confinedSliding || regime == rheology::BasalRegime::plugSliding) return sb;
    if (s.Up[j] == 0.0) return 0.0;
    return std::min(shearStrength(s, sc, j), sb);
}

std::vector<output::SiteFlow> siteFlow(const SlideColumns& s, const std::vector<scene::Site>& sites)
{
    std::vector<output::SiteFlow> flow(sites.size());
    for (std::size_t k = 0; k < sites.size(); ++k)
    {
        const double at = sites[k].position;
        if (at < s.x.front() || at > s.x.back()) continue;
        // The column over the site: the last node at or before it.
        const int i = std::min(static_cast<int>(std::upper_bound(s.x.begin(), s.x.end(), at) - s.x.begin()) - 1,
                               s.nColumns() - 1);
        const double w = (at - s.x[i])/(s.x[i + 1] - s.x[i]);
        flow[k].covered = true;
        flow[k].thickness = s.columnThickness(i);
        flow[k].velocity = (1.0 - w)*s.U[i] + w*s.U[i + 1];
    }
    return flow;
}

output::PolyData profile(const SlideColumns& s, const scene::Scene& sc)
{
    output::PolyData pd;
    pd.cells = output::PolyData::Cells::polyline;
    const int n = s.nNodes();
    std::vector<double> sArc(n), D(n), U(n), Up(n), Ds(n), xi(n), su(n), tauB(n), remoulded(n), regime(n);
    for (int j = 0; j < n; ++j)
    {
        // The ends of a free slide have zero depth; a wall end keeps its column's.
        const bool freeEnd = (j == n - 1) || (j == 0 && !s.rearWall);
        const double h = freeEnd ? 0.0 : s.nodeThickness(j);
        const scene::Point2 b = sc.base.point(s.x[j]);
        const scene::Point2 nrm = sc.base.normal(s.x[j]);
        pd.addPoint(b.x + h*nrm.x, 0.0, b.z + h*nrm.z);
        sArc[j] = s.x[j];
        D[j] = h;
        U[j] = s.U[j];
        Up[j] = s.Up[j];
        Ds[j] = s.shearLayer[j];
        xi[j] = s.xi[j];
        su[j] = shearStrength(s, sc, j);
        tauB[j] = basalStress(s, sc, j);
        remoulded[j] = sc.rheology.remouldingFactor(s.xi[j]);
        regime[j] = s.regime[j];
    }
    pd.addScalar("s", sArc);
    pd.addScalar("thickness", D);
    pd.addScalar("U", U);
    pd.addScalar("plugVelocity", Up);
    pd.addScalar("shearLayerThickness", Ds);
    pd.addScalar("xi", xi);
    pd.addScalar("s_u", su);
    pd.addScalar("basalStress", tauB);
    pd.addScalar("remouldedRatio", remoulded);
    pd.addScalar("basalRegime", regime);
    return pd;
}

double gravityWork(const SlideColumns& s, const scene::Scene& sc)
{
    const int N = s.nColumns();
    double w = 0.0;
    for (int j = 0; j <= N; ++j)
    {
        const double m = s.nodeArea(j);
        w += m*(sc.base.point(s.x0[j]).z - sc.base.point(s.x[j]).z);
    }
    return sc.slide.density*sc.g*w;
}

std::string detectMechanism(const SlideColumns& s, double g)
{
    // Block sliding is coherent motion: most of the mass moves within 10 % of the
    // mass-averaged velocity, and that velocity is not a creep.
    const int N = s.nColumns();
    double M = 0.0, P = 0.0;
    for (int j = 0; j <= N; ++j)
    {
        const double m = s.nodeArea(j);
        M += m;
        P += m*s.U[j];
    }
    const double V = P/M;
    double coherent = 0.0;
    for (int j = 0; j <= N; ++j)
    {
        const double m = s.nodeArea(j);
        if (std::fabs(s.U[j] - V) <= 0.1*std::fabs(V)) coherent += m;
    }
    if (std::fabs(V) > 0.1*std::sqrt(g*s.initialHeight) && coherent > 0.8*M) return "block sliding";
    return "viscous elongation";
}

} // namespace dam
} // namespace slide
