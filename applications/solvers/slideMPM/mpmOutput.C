#include "mpmOutput.H"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <vector>

namespace slide
{
namespace mpm
{

namespace
{

// A copy on the host that does not alias the device view, even where the
// backend's memory is the host's (a snapshot, not a window).
template<class V>
typename V::HostMirror snapshot(const V& v)
{
    typename V::HostMirror h = Kokkos::create_mirror(v);
    Kokkos::deep_copy(h, v);
    return h;
}

} // namespace

HostPoints::HostPoints(const MaterialPoints& mp)
:
    count(mp.count),
    spacing(mp.spacing),
    position(snapshot(mp.position)),
    velocity(snapshot(mp.velocity)),
    size(snapshot(mp.size)),
    quadraticMode(snapshot(mp.quadraticMode)),
    stress(snapshot(mp.stress)),
    affine(snapshot(mp.affine)),
    velocityGradient(snapshot(mp.velocityGradient)),
    mass(snapshot(mp.mass)),
    volume(snapshot(mp.volume)),
    plasticShearStrain(snapshot(mp.plasticShearStrain)),
    strength(snapshot(mp.strength)),
    shearStrainRate(snapshot(mp.shearStrainRate)),
    plasticShearStrainRate(snapshot(mp.plasticShearStrainRate)),
    plasticWork(snapshot(mp.plasticWork))
{}

double HostPoints::frontX() const
{
    double x = -1e300;
    for (int p = 0; p < count; ++p) x = std::max(x, position(p, 0) + halfExtent(p, 0));
    return x;
}

double HostPoints::rearX() const
{
    double x = 1e300;
    for (int p = 0; p < count; ++p) x = std::min(x, position(p, 0) - halfExtent(p, 0));
    return x;
}

double HostPoints::massFrontX(const double share) const
{
    if (count == 0) return 0.0;
    std::vector<int> order(count);
    for (int p = 0; p < count; ++p) order[p] = p;
    std::sort(order.begin(), order.end(), [this](int a, int b) { return position(a, 0) < position(b, 0); });
    const double behind = share*totalMass();
    double m = 0.0;
    for (const int p : order)
    {
        m += mass(p);
        if (m >= behind) return position(p, 0);
    }
    return position(order.back(), 0);
}

double HostPoints::totalMass() const
{
    double m = 0.0;
    for (int p = 0; p < count; ++p) m += mass(p);
    return m;
}

output::RunoutSample runoutSample(const HostPoints& hp, const BaseFrame& frame, const double t,
                                  const double initialFront, const double cellSize)
{
    output::RunoutSample s;
    s.time = t;
    int front = 0;
    std::map<long long, double> top;   // per grid column: highest particle above the base
    for (int p = 0; p < hp.count; ++p)
    {
        const double x = hp.position(p, 0), y = hp.position(p, 1);
        const double vx = hp.velocity(p, 0), vy = hp.velocity(p, 1);
        if (x > hp.position(front, 0)) front = p;
        const double v2 = vx*vx + vy*vy;
        s.maxVelocity = std::max(s.maxVelocity, std::sqrt(v2));
        s.mass += hp.mass(p);
        s.kineticEnergy += 0.5*hp.mass(p)*v2;
        const long long c = static_cast<long long>(std::floor(x/cellSize));
        const double h = y + hp.halfExtent(p, 1) - frame.level.height(x);
        auto it = top.find(c);
        if (it == top.end() || h > it->second) top[c] = h;
    }
    for (const auto& c : top) s.maxThickness = std::max(s.maxThickness, c.second);
    s.front = frame.level.arcLength(hp.frontX()) - initialFront;
    s.rear = frame.level.arcLength(hp.rearX()) - initialFront;
    if (hp.count > 0) s.frontVelocity = hp.velocity(front, 0);
    return s;
}

output::PolyData particleData(const HostPoints& hp, const BaseFrame& frame,
                              const rheology::HerschelBulkleyRemoulding& material)
{
    output::PolyData pd;
    pd.cells = output::PolyData::Cells::vertices;
    const int n = hp.count;
    std::vector<double> vel(3*n), sxx(n), szz(n), sxz(n), syy(n), pressure(n), tau(n), su(n), ratio(n), xi(n),
        rate(n), plastic(n), mass(n), volume(n);
    const double c = std::cos(frame.angle), s = std::sin(frame.angle);
    for (int p = 0; p < n; ++p)
    {
        double X, Z;
        frame.toGlobal(hp.position(p, 0), hp.position(p, 1), X, Z);
        pd.addPoint(X, 0.0, Z);
        double VX, VZ;
        frame.vectorToGlobal(hp.velocity(p, 0), hp.velocity(p, 1), VX, VZ);
        vel[3*p] = VX;
        vel[3*p + 1] = 0.0;
        vel[3*p + 2] = VZ;
        // sigma_global = R sigma R^T, R = [t n] with t = (c, -s), n = (s, c).
        const double a = hp.stress(p, 0), b = hp.stress(p, 1), o = hp.stress(p, 3);
        sxx[p] = c*c*a + 2.0*c*s*o + s*s*b;
        szz[p] = s*s*a - 2.0*c*s*o + c*c*b;
        sxz[p] = -c*s*a + (c*c - s*s)*o + c*s*b;
        syy[p] = hp.stress(p, 2);
        const double sig[4] = {a, b, hp.stress(p, 2), o};
        pressure[p] = -(a + b + hp.stress(p, 2))/3.0;
        tau[p] = UndrainedClay::shearStress(sig);
        su[p] = hp.strength(p);
        ratio[p] = material.remouldingFactor(hp.plasticShearStrain(p));
        xi[p] = hp.plasticShearStrain(p);
        rate[p] = hp.shearStrainRate(p);
        plastic[p] = hp.plasticShearStrainRate(p);
        mass[p] = hp.mass(p);
        volume[p] = hp.volume(p);
    }
    pd.addVector("velocity", vel);
    pd.addScalar("sigma_xx", sxx);
    pd.addScalar("sigma_zz", szz);
    pd.addScalar("sigma_xz", sxz);
    pd.addScalar("sigma_yy", syy);
    pd.addScalar("pressure", pressure);
    pd.addScalar("shearStress", tau);
    pd.addScalar("s_u", su);
    pd.addScalar("remouldedRatio", ratio);
    pd.addScalar("xi", xi);
    pd.addScalar("shearStrainRate", rate);
    pd.addScalar("plasticShearStrainRate", plastic);
    // Per unit width: what an energy or mass budget over the particles needs (they differ after splitting).
    pd.addScalar("mass", mass);
    pd.addScalar("volume", volume);
    return pd;
}

output::Mechanism detectMechanism(const HostPoints& hp, const BaseFrame& frame, const double H0, const double g,
                                  const double cellSize, const rheology::HerschelBulkleyRemoulding& material)
{
    std::vector<output::MaterialSample> samples(hp.count);
    for (int p = 0; p < hp.count; ++p)
    {
        output::MaterialSample& q = samples[p];
        q.s = hp.position(p, 0);
        q.halfLength = hp.halfExtent(p, 0);
        q.h = hp.position(p, 1) - frame.level.height(hp.position(p, 0));
        q.halfHeight = hp.halfExtent(p, 1);
        q.mass = hp.mass(p);
        q.velocity = hp.velocity(p, 0);
        q.xi = hp.plasticShearStrain(p);
    }
    output::MechanismView view;
    view.H0 = H0;
    view.g = g;
    view.columnWidth = std::max(cellSize, 0.2*H0);
    view.basalLayer = 2.0*hp.spacing;
    return output::detectMechanism(samples, view, material);
}

EnergyState energyState(const HostPoints& hp, const BaseFrame& frame, const UndrainedClay& clay, const double density,
                        const double cellSize)
{
    const double inertia = 0.25*cellSize*cellSize;
    const double G = clay.shearModulus, K = clay.lame + 2.0*clay.shearModulus/3.0;
    EnergyState e;
    for (int p = 0; p < hp.count; ++p)
    {
        const double m = hp.mass(p);
        e.potential -= m*(frame.gravityX*hp.position(p, 0) + frame.gravityY*hp.position(p, 1));
        double CC = 0.0;
        for (int c = 0; c < 4; ++c) CC += hp.affine(p, c)*hp.affine(p, c);
        e.kinetic += 0.5*m*(hp.velocity(p, 0)*hp.velocity(p, 0) + hp.velocity(p, 1)*hp.velocity(p, 1) + inertia*CC);
        const double sxx = hp.stress(p, 0), syy = hp.stress(p, 1), szz = hp.stress(p, 2), sxy = hp.stress(p, 3);
        const double mean = (sxx + syy + szz)/3.0;
        const double ss = (sxx - mean)*(sxx - mean) + (syy - mean)*(syy - mean) + (szz - mean)*(szz - mean)
                        + 2.0*sxy*sxy;
        const double J = clay.kirchhoffRate ? hp.volume(p)*density/m : 1.0;   // as the elasticity counts it
        e.elastic += J*hp.volume(p)*(ss/(4.0*G) + mean*mean/(2.0*K));
        e.plastic += hp.plasticWork(p);
    }
    return e;
}

namespace
{

const char* const energyHeader =
    "# energy budget per unit width [J/m] since t = 0: gravityWork = kinetic + elasticChange + plastic + boundary"
    " + numerical\n"
    "# time [s]  gravityWork  kinetic  elasticChange  plasticDissipation  boundaryWork  numericalDissipation"
    "  numerical/gravityWork\n";

} // namespace

EnergyLog::EnergyLog(const std::string& caseDir, const bool append, const double startTime)
:
    path_(output::methodOutputDir(caseDir, "slideMPM") + "/energy.dat"),
    os_(output::openHistory(path_, energyHeader, append, startTime))
{}

EnergyBudget energyBudget(const EnergyState& now, const EnergyState& start, const double boundaryWork)
{
    EnergyBudget b;
    b.gravity = start.potential - now.potential;
    b.kinetic = now.kinetic - start.kinetic;
    b.elastic = now.elastic - start.elastic;
    b.plastic = now.plastic - start.plastic;
    b.boundary = boundaryWork;
    b.numerical = b.gravity - b.kinetic - b.elastic - b.plastic - b.boundary;
    return b;
}

void EnergyLog::write(const double t, const EnergyState& now, const EnergyState& start, const double boundaryWork)
{
    const EnergyBudget b = energyBudget(now, start, boundaryWork);
    os_ << std::setprecision(10) << t << ' ' << b.gravity << ' ' << b.kinetic << ' ' << b.elastic << ' ' << b.plastic
        << ' ' << b.boundary << ' ' << b.numerical << ' ' << (b.gravity > 0.0 ? b.numerical/b.gravity : 0.0) << '\n';
    os_.flush();
}

} // namespace mpm
} // namespace slide
