#include "damIntegrator.H"

#include "application.H"
#include "basalResistance.H"
#include "bingShapeFactors.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slide
{
namespace dam
{

namespace
{

constexpr double restingPlugSpeed = 1e-12;   // [m/s]

// Velocity after a step under a yield-type resistance of magnitude r*dt:
// stops exactly when the resistance can absorb the trial velocity.
inline double project(const double trial, const double resistance)
{
    if (std::fabs(trial) <= resistance) return 0.0;
    return trial > 0.0 ? trial - resistance : trial + resistance;
}

std::string at(const SlideColumns& s, int j)
{
    std::ostringstream os;
    os << "node " << j << " of " << s.nNodes() << " at s = " << s.x[j] << " m along the base";
    return os.str();
}

} // namespace


DamIntegrator::DamIntegrator(const scene::Scene& sc, const DamControls& controls)
:
    scene_(sc),
    controls_(controls),
    material_(sc.rheology),
    rho_(sc.slide.density),
    g_(sc.g),
    a1_(rheology::shapeFactorA1(sc.rheology.n)),
    beta_(rheology::basalRateFactor(sc.rheology.n)),
    c_(rheology::momentumFluxFactor(sc.rheology.n))
{
    // D_s = D (1 - U/U_p)/(1 - a1) in [f D, (1 - f) D]  <=>  U/U_p in [rMin, rMax]
    const double f = controls_.minShearLayerFraction;
    rMax_ = 1.0 - f*(1.0 - a1_);
    rMin_ = a1_ + f*(1.0 - a1_);
    invOneMinusA1_ = 1.0/(1.0 - a1_);
    invRho_ = 1.0/rho_;
    const double b = sc.slide.length/controls_.columns;
    paperDt_ = 0.001*std::sqrt(b/g_);
}

double DamIntegrator::timeStep(const SlideColumns& s) const
{
    if (controls_.deltaT > 0.0) return controls_.deltaT;
    return stableTimeStep(s);
}

double DamIntegrator::stableTimeStep(const SlideColumns& s) const
{
    if (controls_.timeStep == DamControls::TimeStep::paper) return paperDt_;
    double dxMin = HUGE_VAL, speed = 0.0;
    const int N = s.nColumns();
    for (int i = 0; i < N; ++i)
    {
        const double dx = s.x[i + 1] - s.x[i];
        dxMin = std::min(dxMin, dx);
        const double D = s.area[i]/dx;
        const double u = std::max(std::max(std::fabs(s.U[i]), std::fabs(s.U[i + 1])),
                                  std::max(std::fabs(s.Up[i]), std::fabs(s.Up[i + 1])));
        const double c = std::sqrt(g_*D);
        const double dU = std::fabs(s.U[i + 1] - s.U[i]);
        speed = std::max(speed, u + c*(1.0 + controls_.viscosityLinear) + 2.0*controls_.viscosityQuadratic*dU);
    }
    return controls_.courant*dxMin/speed;
}

double DamIntegrator::maxSpeed(const SlideColumns& s)
{
    double v = 0.0;
    for (int j = 0; j < s.nNodes(); ++j) v = std::max({v, std::fabs(s.U[j]), std::fabs(s.Up[j])});
    return v;
}

bool DamIntegrator::atRest(const double maxSpeed, const double previousMaxSpeed, const double restVelocity)
{
    // Slow is not enough: a slide that starts from rest under a small net force (a block
    // released on a gentle slope) is slow for its first steps but accelerating.
    return maxSpeed <= restVelocity && maxSpeed <= previousMaxSpeed;
}

void DamIntegrator::advance(SlideColumns& s, const double dt, const double time)
{
    if (controls_.timeScheme == DamControls::TimeScheme::euler)
    {
        step(s, dt, time);
        return;
    }
    // Forward Euler amplifies the shortest waves of Eq. (3)'s momentum-flux bracket, a central
    // difference, every step (validation/dam/sheetStability.md); this scheme does not up to Courant sqrt(3).
    // stage <- w stage + (1 - w) s: convex, so the nodes keep their order and a node at rest stays so.
    auto blend = [&s](SlideColumns& stage, const double w)
    {
        for (std::size_t k = 0; k < s.x.size(); ++k)
        {
            stage.x[k] = w*stage.x[k] + (1.0 - w)*s.x[k];
            stage.U[k] = w*stage.U[k] + (1.0 - w)*s.U[k];
            stage.Up[k] = w*stage.Up[k] + (1.0 - w)*s.Up[k];
            stage.xi[k] = w*stage.xi[k] + (1.0 - w)*s.xi[k];
        }
        stage.rigidVelocity = w*stage.rigidVelocity + (1.0 - w)*s.rigidVelocity;
    };
    stage_ = s;
    step(stage_, dt, time);
    step(stage_, dt, time + dt);
    blend(stage_, 0.25);
    step(stage_, dt, time + 0.5*dt);
    blend(stage_, 2.0/3.0);
    std::swap(s, stage_);
}

void DamIntegrator::step(SlideColumns& s, const double dt, const double time)
{
    const int N = s.nColumns();
    const int nNodes = N + 1;
    D_.resize(N);
    F_.resize(N);
    Q_.resize(N);
    sinT_.resize(nNodes);
    cosT_.resize(nNodes);
    xNew_.resize(nNodes);
    UNew_.resize(nNodes);
    UpNew_.resize(nNodes);
    xiNew_.resize(nNodes);
    tauY_.resize(nNodes);

    // Columns: thickness and the momentum-flux bracket of Eq. (3),
    // D [(c - 1) U_p^2 - c U U_p + U^2], at column-mean velocities.
    for (int i = 0; i < N; ++i)
    {
        const double dx = s.x[i + 1] - s.x[i];
        if (!(dx > 0.0))
        {
            throw output::BlowUp(time, "column " + std::to_string(i) + " between " + at(s, i) + " and the next node",
                                 "column length", "nodes crossed: dx = " + std::to_string(dx) + " m");
        }
        D_[i] = s.area[i]/dx;
        const double Ub = 0.5*(s.U[i] + s.U[i + 1]);
        const double Upb = 0.5*(s.Up[i] + s.Up[i + 1]);
        F_[i] = D_[i]*((c_ - 1.0)*Upb*Upb - c_*Ub*Upb + Ub*Ub);
        // Artificial viscous pressure (von Neumann-Richtmyer) in compressing columns,
        // so that a bore (wave breaking, the paper's "Riemann problem") spreads over
        // a few columns instead of crushing one; zero where the slide stretches.
        const double dU = s.U[i + 1] - s.U[i];
        Q_[i] = dU < 0.0
            ? D_[i]*dU*(controls_.viscosityQuadratic*dU - controls_.viscosityLinear*std::sqrt(g_*D_[i]))
            : 0.0;
    }

    const bool planar = scene_.base.isPlanar();
    const double theta0 = scene_.base.angle(0.0);
    for (int j = 0; j < nNodes; ++j)
    {
        const double th = planar ? theta0 : scene_.base.angle(s.x[j]);
        sinT_[j] = std::sin(th);
        cosT_[j] = std::cos(th);
    }

    const scene::Interface& iface = scene_.interface;
    const bool frictional = iface.type != scene::Interface::Type::noSlip;
    const bool enhanced = controls_.frictionalBase == DamControls::FrictionalBase::enhanced;

    // Rigid translation of the confined body (Eq. 5, first branch): mass-weighted
    // over the nodes in that regime.
    double confinedMass = 0.0, confinedDrive = 0.0, confinedBase = 0.0;
    auto nodeRegime = [&](int j, double tauY) -> rheology::BasalRegime
    {
        if (!frictional) return rheology::BasalRegime::noSlip;
        const double sb = iface.basalStrength(std::fabs(s.U[j]));
        const double confine = rheology::confiningResistance(tauY, sinT_[j]);
        if (enhanced && sb <= confine) return rheology::BasalRegime::confinedSliding;
        if (sb <= tauY) return rheology::BasalRegime::plugSliding;
        return rheology::BasalRegime::cappedShear;   // capped at s_b or not: decided with s_u below
    };
    for (int j = 0; j < nNodes; ++j)
    {
        if (s.rearWall && j == 0) continue;
        const double tauY = tauY_[j] = material_.thresholdStrength(s.xi[j]);
        s.regime[j] = static_cast<int>(nodeRegime(j, tauY));
        if (s.regime[j] == static_cast<int>(rheology::BasalRegime::confinedSliding))
        {
            const double m = s.nodeArea(j);
            const double ell = s.nodeBaseLength(j);
            confinedMass += m;
            confinedDrive += m*g_*sinT_[j];
            confinedBase += ell;
        }
    }
    // The rigid velocity is a state of its own: recomputing it as the mean of the
    // node velocities would feed the local slump of the faces back into the
    // translation. A body that becomes confined starts with no rigid velocity.
    const double Vold = confinedMass > 0.0 ? s.rigidVelocity : 0.0;
    double Vnew = 0.0;
    if (confinedMass > 0.0)
    {
        const double sb = iface.basalStrength(std::fabs(Vold));
        Vnew = project(Vold + dt*confinedDrive/confinedMass, dt*sb*confinedBase/(rho_*confinedMass));
    }

    for (int j = 0; j < nNodes; ++j)
    {
        if (s.rearWall && j == 0)
        {
            xNew_[j] = s.x[j];
            UNew_[j] = UpNew_[j] = 0.0;
            xiNew_[j] = s.xi[j];
            s.shearLayer[j] = 0.0;
            s.basalRate[j] = 0.0;
            continue;
        }
        const bool hasL = j > 0, hasR = j < N;
        const double DL = hasL ? D_[j - 1] : 0.0;
        const double DR = hasR ? D_[j] : 0.0;
        const double m = s.nodeArea(j);
        const double ell = s.nodeBaseLength(j);
        const double D = m/ell;
        const double invD = ell/m;

        // Driving accelerations of Eqs. (2)-(3), per unit mass of the control volume.
        const double aGravity = g_*sinT_[j];
        const double QL = hasL ? Q_[j - 1] : 0.0;
        const double QR = hasR ? Q_[j] : 0.0;
        // Hydrostatic thrust between columns. At a free face (faceStability): gate, a
        // face lower than H_stability = 4 s_u/(rho g) stands and a higher one thrusts
        // hydrostatically as in BING; rankine, the undrained active thrust
        // rho g D^2/2 - 2 s_u D, which vanishes at the same height; none, BING's.
        const double tauY = tauY_[j];
        auto faceThrust = [&](double Dface)
        {
            const double hydrostatic = 0.5*g_*cosT_[j]*Dface*Dface;
            switch (controls_.faceStability)
            {
                case DamControls::FaceStability::none: return hydrostatic;
                case DamControls::FaceStability::gate:
                    return Dface > rheology::faceStabilityThickness(tauY, rho_, g_) ? hydrostatic : 0.0;
                default: return std::max(hydrostatic - 2.0*tauY*Dface/rho_, 0.0);
            }
        };
        const double PL = hasL ? (hasR ? 0.5*g_*cosT_[j]*DL*DL : faceThrust(DL)) : 0.0;
        const double PR = hasR ? (hasL || s.rearWall ? 0.5*g_*cosT_[j]*DR*DR : faceThrust(DR)) : 0.0;
        const double aPressure = (PL - PR + QL - QR)/m;
        const double aFlux = ((hasR ? F_[j] : 0.0) - (hasL ? F_[j - 1] : 0.0))/m;

        const rheology::BasalRegime regime = static_cast<rheology::BasalRegime>(s.regime[j]);
        double U = s.U[j], Up = s.Up[j];
        double xi = s.xi[j];
        double Ds = 0.0, rateB = 0.0;

        if (regime == rheology::BasalRegime::confinedSliding)
        {
            // Local slump under gravity and the virtual confining resistance, on top
            // of the rigid translation of the confined body.
            const double confine = rheology::confiningResistance(tauY, sinT_[j]);
            const double local = project(U - Vold + dt*(aGravity + aPressure), dt*confine/(rho_*D));
            U = Up = Vnew + local;
        }
        else if (regime == rheology::BasalRegime::plugSliding)
        {
            // A plug on the base: Eq. (2) with s_uo replaced by s_b, no shear layer.
            const double sb = iface.basalStrength(std::fabs(U));
            U = Up = project(U + dt*(aGravity + aPressure), dt*sb/(rho_*D));
        }
        else
        {
            // Shear layer under a plug: Eqs. (2) and (3), basal stress s_u(beta U_p/D_s, xi)
            // capped at s_b (Eq. 5, last two branches).
            const double cap = frictional ? iface.basalStrength(std::fabs(U)) : HUGE_VAL;
            const int jl = hasL ? j - 1 : j, jr = hasR ? j + 1 : j;
            const double dUpdx = (s.Up[jr] - s.Up[jl])/(s.x[jr] - s.x[jl]);
            const double aPlug = aGravity + aPressure - (Up - U)*dUpdx;
            const double aLayer = aGravity + aPressure + aFlux;
            // A plug slower than this is at rest: the linearised resistance's Jacobian grows as 1/|U_p|, and at
            // a few 1e-224 m/s it froze a node that 70 m/s2 pushed (Table 1 Case 4, validation/dam/README.md).
            if (std::fabs(Up) < restingPlugSpeed)
            {
                // At rest: the plug is the whole column, and it yields only when the
                // driving stress exceeds the strength; a shear layer then starts thin.
                Up = project(dt*aPlug, dt*tauY/(rho_*D));
                U = rMax_*Up;
                Ds = Up != 0.0 ? D*(1.0 - rMax_)/(1.0 - a1_) : 0.0;
                if (Up != 0.0) rateB = beta_*std::fabs(Up)/Ds;   // the new layer's, for the output's s_u
            }
            else
            {
                // Moving: p = |U_p|, u = |U| in the direction of motion; the resistance
                // terms are linearised in (u, p) (Rosenbrock-Euler), since D_s, and with it
                // the plug thickness and the basal rate, react fast to both velocities.
                const double sgn = Up > 0.0 ? 1.0 : -1.0;
                const double p = std::fabs(Up);
                const double invP = 1.0/p;
                const double r = std::min(std::max(sgn*U*invP, rMin_), rMax_);
                const double u = r*p;
                const double ds = D*(1.0 - r)*invOneMinusA1_;
                const double invDs = 1.0/ds;
                const double invDp = 1.0/(D - ds);
                const double rate = beta_*p*invDs;
                double dsu = 0.0;
                const double su = material_.strength(rate, xi, dsu);
                const bool capped = su >= cap;
                const double tau = capped ? cap : su;
                const double Ru = sgn*aLayer - tau*invRho_*invD;
                const double Rp = sgn*aPlug - tauY*invRho_*invDp;
                // Jacobian of the resistances (derivation in README): with K_p = tau_y/(rho D_p^2),
                // K_u = s_u'(rate)/(rho D): J_pp = -K_p D r/(p(1-a1)), J_pu = -J_pp/r,
                // J_uu = -K_u beta/(D_s (1-r)), J_up = J_uu (1 - 2r); 1/(1 - r) = D/(D_s (1 - a1)).
                const double Kp = tauY*invRho_*invDp*invDp;
                const double Jpu = Kp*D*invP*invOneMinusA1_;
                const double Jpp = -Jpu*r;
                const double Ku = capped ? 0.0 : dsu*invRho_*invD;
                const double Juu = -Ku*beta_*invDs*D*invDs*invOneMinusA1_;
                const double Jup = Juu*(1.0 - 2.0*r);
                const double m11 = 1.0 - dt*Juu, m12 = -dt*Jup;
                const double m21 = -dt*Jpu, m22 = 1.0 - dt*Jpp;
                const double dtOverDet = dt/(m11*m22 - m12*m21);
                const double du = (m22*Ru - m12*Rp)*dtOverDet;
                const double dp = (m11*Rp - m21*Ru)*dtOverDet;
                const double pNew = p + dp;
                // Arrest as at rest: when the column's static strength exceeds its driving
                // stress, a velocity that this margin removes within the step is removed.
                const double staticMargin = tauY*invRho_*invD - std::fabs(aPlug);
                if (!(pNew > 0.0) || (staticMargin > 0.0 && pNew <= dt*staticMargin))
                {
                    U = Up = 0.0;
                }
                else
                {
                    const double uNew = std::min(std::max(u + du, rMin_*pNew), rMax_*pNew);
                    U = sgn*uNew;
                    Up = sgn*pNew;
                    const double invPNew = 1.0/pNew;
                    Ds = D*(1.0 - uNew*invPNew)*invOneMinusA1_;
                    const double rateNew = beta_*pNew/Ds;
                    rateB = rateNew;
                    // Remoulding: the shear layer's plastic strain accumulates at the basal rate.
                    xi += rateNew*dt;
                }
            }
        }
        UNew_[j] = U;
        UpNew_[j] = Up;
        xiNew_[j] = xi;
        // Trapezoidal in time: exact for a constant acceleration.
        xNew_[j] = s.x[j] + 0.5*(s.U[j] + U)*dt;
        s.shearLayer[j] = Ds;
        s.basalRate[j] = rateB;
        if (!std::isfinite(U) || !std::isfinite(Up) || !std::isfinite(xi))
        {
            throw output::BlowUp(time + dt, at(s, j), !std::isfinite(U) ? "depth-averaged velocity U"
                                 : !std::isfinite(Up) ? "plug velocity U_p" : "plastic shear strain xi",
                                 "D = " + std::to_string(D) + " m");
        }
    }
    for (int j = 1; j < nNodes; ++j)
    {
        if (!(xNew_[j] > xNew_[j - 1]))
        {
            throw output::BlowUp(time + dt, at(s, j), "node order",
                                 "nodes would cross; the time step is too large for the velocity field");
        }
    }
    s.rigidVelocity = Vnew;
    s.x.swap(xNew_);
    s.U.swap(UNew_);
    s.Up.swap(UpNew_);
    s.xi.swap(xiNew_);
}

} // namespace dam
} // namespace slide
