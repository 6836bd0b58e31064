// Unit tests of the shared rheology library: Eq. (1), its regularised apparent
// viscosity, the BING shape factors for general n and the regimes of Eq. (5).
#include "HerschelBulkleyRemoulding.H"
#include "basalResistance.H"
#include "bingShapeFactors.H"
#include "checkParameters.H"
#include "wallLayer.H"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace slide::rheology;

namespace
{

// Eq. (1)'s six parameters, as Table 1 lists them.
HerschelBulkleyRemoulding table1Material(double s_uo, double eta, double n, double gdotRef, double deltaRem = 1.0,
                                         double xi95 = 1.0)
{
    HerschelBulkleyRemoulding m;
    m.s_uo = s_uo;
    m.eta = eta;
    m.n = n;
    m.gdotRef = gdotRef;
    m.deltaRem = deltaRem;
    m.xi95 = xi95;
    return m;
}

// Table 1, Case 10: s_uo 0.5 kPa, eta 0.45, n 0.23, gdot_ref 0.06, delta_rem 0.5, xi95 10.
HerschelBulkleyRemoulding case10() { return table1Material(500.0, 0.45, 0.23, 0.06, 0.5, 10.0); }

// Table 1, Case 1: s_uo 150 Pa, eta 0.35, n 0.15, gdot_ref 0.06, no remoulding.
HerschelBulkleyRemoulding case1() { return table1Material(150.0, 0.35, 0.15, 0.06); }

double centralDifference(const std::function<double(double)>& f, double x, double h)
{
    return (f(x + h) - f(x - h))/(2.0*h);
}

// Simpson's rule on [0, b] with N (even) intervals.
double simpson(const std::function<double(double)>& f, double b, int N = 20000)
{
    const double h = b/N;
    double s = f(0.0) + f(b);
    for (int i = 1; i < N; ++i) s += f(i*h)*(i % 2 ? 4.0 : 2.0);
    return s*h/3.0;
}

} // namespace

TEST(Eq1Strength, NoRemouldingWhenDeltaRemIsOne)
{
    HerschelBulkleyRemoulding m = case10();
    m.deltaRem = 1.0;
    for (double xi : {0.0, 1.0, 10.0, 1e3})
    {
        EXPECT_DOUBLE_EQ(m.remouldingFactor(xi), 1.0);
        EXPECT_DOUBLE_EQ(m.strength(0.3, xi), m.strength(0.3, 0.0));
    }
}

TEST(Eq1Strength, Xi95GivesNinetyFivePercentOfTheLoss)
{
    const HerschelBulkleyRemoulding m = case10();
    const double lossFraction = (1.0 - m.remouldingFactor(m.xi95))/(1.0 - m.deltaRem);
    EXPECT_NEAR(lossFraction, 0.95, 1e-3);    // 1 - exp(-3) = 0.9502
    EXPECT_NEAR(m.remouldingFactor(1e6), m.deltaRem, 1e-12);
    EXPECT_DOUBLE_EQ(m.remouldingFactor(0.0), 1.0);
}

TEST(Eq1Strength, RateIndependentWhenEtaIsZero)
{
    HerschelBulkleyRemoulding m = case10();
    m.eta = 0.0;
    for (double g : {0.0, 1e-6, 0.06, 1.0, 100.0})
    {
        EXPECT_DOUBLE_EQ(m.strength(g, 0.0), m.s_uo);
        EXPECT_DOUBLE_EQ(m.strength(g, 5.0), m.s_uo*m.remouldingFactor(5.0));
    }
}

TEST(Eq1Strength, ReferenceRateGivesOnePlusEta)
{
    const HerschelBulkleyRemoulding m = case10();
    EXPECT_NEAR(m.strength(m.gdotRef, 0.0), m.s_uo*(1.0 + m.eta), 1e-9);
    EXPECT_NEAR(m.strength(-m.gdotRef, 0.0), m.s_uo*(1.0 + m.eta), 1e-9);   // rate sign does not matter
}

TEST(Eq1Strength, BinghamSpecialCase)
{
    const HerschelBulkleyRemoulding m = bingham(42.5, 0.3);
    for (double g : {0.0, 0.5, 2.0, 40.0})
    {
        EXPECT_NEAR(m.strength(g, 0.0), 42.5 + 0.3*g, 1e-12);
    }
    EXPECT_NEAR(m.consistency(), 0.3, 1e-15);
}

TEST(Eq1Strength, MonotoneInRateAndStrain)
{
    const HerschelBulkleyRemoulding m = case10();
    double prev = m.strength(0.0, 0.0);
    for (double g = 1e-4; g < 1e3; g *= 1.5)
    {
        const double s = m.strength(g, 0.0);
        EXPECT_GT(s, prev);
        prev = s;
    }
    prev = m.strength(0.1, 0.0);
    for (double xi = 0.1; xi < 200; xi *= 1.5)
    {
        const double s = m.strength(0.1, xi);
        EXPECT_LT(s, prev);
        EXPECT_GE(s, m.deltaRem*m.strength(0.1, 0.0) - 1e-9);
        prev = s;
    }
}

TEST(Eq1Strength, DerivativesMatchFiniteDifferences)
{
    for (double n : {0.15, 0.23, 0.5, 1.0, 1.7})
    {
        HerschelBulkleyRemoulding m = case10();
        m.n = n;
        for (double g : {0.003, 0.06, 0.5, 7.0})
        {
            for (double xi : {0.0, 2.0, 30.0})
            {
                const double fdRate = centralDifference([&](double x) { return m.strength(x, xi); }, g, 1e-6*g);
                EXPECT_NEAR(m.strengthRateDerivative(g, xi), fdRate, 1e-6*std::fabs(fdRate) + 1e-9)
                    << "n " << n << " gdot " << g << " xi " << xi;
                double dsdg = 0.0;
                EXPECT_NEAR(m.strength(g, xi, dsdg), m.strength(g, xi), 1e-12*m.strength(g, xi));
                EXPECT_NEAR(dsdg, m.strengthRateDerivative(g, xi), 1e-12*std::fabs(dsdg));
                const double fdXi = centralDifference([&](double x) { return m.strength(g, x); }, xi + 1.0, 1e-5);
                EXPECT_NEAR(m.strengthStrainDerivative(g, xi + 1.0), fdXi, 1e-6*std::fabs(fdXi) + 1e-9);
            }
        }
    }
}

TEST(ApparentViscosity, CapIsOpenFOAMsHerschelBulkley)
{
    const HerschelBulkleyRemoulding m = case10();
    ViscosityRegularisation reg;
    reg.type = Regularisation::cap;
    reg.muMax = 1e4;
    // Yielded: s_u/gdot; unyielded: the cap.
    EXPECT_NEAR(apparentViscosity(m, 1.0, 0.0, reg), m.strength(1.0, 0.0), 1e-9);
    EXPECT_DOUBLE_EQ(apparentViscosity(m, 1e-5, 0.0, reg), 1e4);
    EXPECT_DOUBLE_EQ(apparentViscosity(m, 0.0, 0.0, reg), 1e4);
    EXPECT_DOUBLE_EQ(apparentViscosityDerivative(m, 1e-5, 0.0, reg), 0.0);
}

TEST(ApparentViscosity, PapanastasiouLimits)
{
    const HerschelBulkleyRemoulding m = case10();
    ViscosityRegularisation reg;
    reg.type = Regularisation::papanastasiou;
    reg.m = 100.0;
    // gdot -> 0: m s_uo R; large m gdot: s_u/gdot.
    EXPECT_NEAR(apparentViscosity(m, 0.0, 3.0, reg), 100.0*m.thresholdStrength(3.0), 1e-9);
    const double g = 5.0;
    EXPECT_NEAR(apparentViscosity(m, g, 3.0, reg), m.strength(g, 3.0)/g, 1e-12*m.strength(g, 3.0));
    // Finite everywhere and positive.
    for (double x = 0.0; x < 10.0; x += 0.01)
    {
        const double mu = apparentViscosity(m, x, 0.0, reg);
        EXPECT_TRUE(std::isfinite(mu));
        EXPECT_GT(mu, 0.0);
    }
}

TEST(ApparentViscosity, DerivativesMatchFiniteDifferences)
{
    const HerschelBulkleyRemoulding m = case10();
    for (Regularisation type : {Regularisation::cap, Regularisation::papanastasiou})
    {
        ViscosityRegularisation reg;
        reg.type = type;
        reg.muMax = 1e5;
        reg.m = 50.0;
        for (double g : {0.02, 0.2, 1.0, 20.0})
        {
            const double fd = centralDifference([&](double x) { return apparentViscosity(m, x, 1.0, reg); }, g, 1e-6*g);
            EXPECT_NEAR(apparentViscosityDerivative(m, g, 1.0, reg), fd, 1e-5*std::fabs(fd) + 1e-6)
                << "type " << static_cast<int>(type) << " gdot " << g;
        }
    }
}

TEST(BingShapeFactors, BinghamValues)
{
    EXPECT_NEAR(shapeFactorA1(1.0), 2.0/3.0, 1e-15);
    EXPECT_NEAR(shapeFactorA2(1.0), 8.0/15.0, 1e-15);
    EXPECT_NEAR(basalRateFactor(1.0), 2.0, 1e-15);
    EXPECT_NEAR(momentumFluxFactor(1.0), 1.4, 1e-15);
}

TEST(BingShapeFactors, MatchIntegralsOfTheVelocityProfile)
{
    const double Up = 2.0, Ds = 0.7, Dp = 1.3, D = Dp + Ds;
    for (double n : {0.15, 0.23, 0.3, 0.5, 1.0, 1.5})
    {
        const double p = (n + 1.0)/n;
        auto u = [&](double z) { return z < Ds ? Up*(1.0 - std::pow(1.0 - z/Ds, p)) : Up; };
        const double q = simpson(u, Ds) + Up*Dp;
        const double q2 = simpson([&](double z) { return u(z)*u(z); }, Ds) + Up*Up*Dp;
        EXPECT_NEAR(q, Up*(Dp + shapeFactorA1(n)*Ds), 1e-8) << "n " << n;
        EXPECT_NEAR(q2, Up*Up*(Dp + shapeFactorA2(n)*Ds), 1e-8) << "n " << n;
        // du/dz at the base
        const double h = 1e-7;
        EXPECT_NEAR((u(h) - u(0.0))/h, basalRateFactor(n)*Up/Ds, 1e-4*Up/Ds) << "n " << n;
        // The closure inverts the definition of U, and Eq. (3)'s flux term with
        // alpha1 = a1, alpha2 = a2 equals integral u^2 - U^2 D.
        const double U = q/D;
        EXPECT_NEAR(shearLayerThickness(D, U, Up, n), Ds, 1e-9);
        EXPECT_NEAR(depthAveragedVelocity(D, Ds, Up, n), U, 1e-12);
        const double c = momentumFluxFactor(n);
        EXPECT_NEAR(D*((1.0 - c)*Up*Up + c*U*Up - U*U), q2 - U*U*D, 1e-8) << "n " << n;
        const double a1 = shapeFactorA1(n), a2 = shapeFactorA2(n);
        EXPECT_NEAR(c, (1.0 - a2)/(1.0 - a1), 1e-14);
        // Eq. (3)'s flux bracket is -(integral u^2 dz - U^2 D) (dam-bing-notes.md).
        EXPECT_NEAR(U*U*D + (a1 - a2)/(1.0 - a1)*Up*Up*D - (1.0 - a2)/(1.0 - a1)*Up*U*D, -(q2 - U*U*D), 1e-8);
        EXPECT_NEAR(basalShearRate(Up, Ds, n), basalRateFactor(n)*Up/Ds, 1e-12);
    }
}

TEST(BingShapeFactors, ShearLayerThicknessIsClipped)
{
    EXPECT_DOUBLE_EQ(shearLayerThickness(1.0, 2.0, 1.0, 1.0), 0.0);   // U > U_p: no shear layer
    EXPECT_DOUBLE_EQ(shearLayerThickness(1.0, 0.0, 1.0, 1.0), 1.0);   // U << U_p: whole column
    EXPECT_DOUBLE_EQ(shearLayerThickness(1.0, 0.5, 0.0, 1.0), 0.0);   // at rest
    EXPECT_DOUBLE_EQ(basalShearRate(1.0, 0.0, 0.5), 0.0);
}

TEST(Eq5BasalRegimes, FourBranches)
{
    // Case 6-9 material: s_uo 5 kPa on a 5 deg slope; 4 sin(theta) s_uo = 1743 Pa.
    const double suo = 5000.0, sinT = std::sin(5.0*M_PI/180.0);
    const double shear = 9000.0;   // s_u at the basal rate
    const BasalResistance r9 = frictionalBasalResistance(450.0, suo, shear, sinT);     // Case 9
    EXPECT_EQ(r9.regime, BasalRegime::confinedSliding);
    EXPECT_DOUBLE_EQ(r9.tau_b, 450.0);
    EXPECT_NEAR(r9.tau_confine, 4.0*sinT*suo, 1e-9);
    EXPECT_NEAR(confiningResistance(suo, sinT), 1743.1, 0.1);
    EXPECT_DOUBLE_EQ(confiningResistance(suo, -sinT), confiningResistance(suo, sinT));   // a rising base too
    EXPECT_FALSE(r9.shearLayer);
    const BasalResistance r8 = frictionalBasalResistance(1800.0, suo, shear, sinT);    // Case 8
    EXPECT_EQ(r8.regime, BasalRegime::plugSliding);
    EXPECT_DOUBLE_EQ(r8.tau_b, 1800.0);
    EXPECT_DOUBLE_EQ(r8.tau_confine, 0.0);
    const BasalResistance r7 = frictionalBasalResistance(6000.0, suo, shear, sinT);    // Case 7
    EXPECT_EQ(r7.regime, BasalRegime::cappedShear);
    EXPECT_DOUBLE_EQ(r7.tau_b, 6000.0);
    EXPECT_TRUE(r7.shearLayer);
    const BasalResistance rn = frictionalBasalResistance(1e9, suo, shear, sinT);
    EXPECT_EQ(rn.regime, BasalRegime::noSlip);
    EXPECT_DOUBLE_EQ(rn.tau_b, shear);
    // Boundaries belong to the lower branch, as Eq. (5) writes them (<=).
    EXPECT_EQ(frictionalBasalResistance(suo, suo, shear, sinT).regime, BasalRegime::plugSliding);
    EXPECT_EQ(frictionalBasalResistance(shear, suo, shear, sinT).regime, BasalRegime::cappedShear);
}

TEST(CriticalThicknesses, PaperValues)
{
    // Case 9: H_stability = 4 s_uo/(rho g) = 3.4 m as printed in the paper.
    EXPECT_NEAR(faceStabilityThickness(5000.0, 600.0, 9.81), 3.4, 0.005);
    // Flume: uniform-flow plug 0.0675 m (dam-bing-notes).
    EXPECT_NEAR(slumpThickness(42.5, 1073.0, 9.81, std::sin(3.43*M_PI/180.0)), 0.0675, 0.0002);
    EXPECT_NEAR(basalFrictionThickness(450.0, 600.0, 9.81, std::sin(5.0*M_PI/180.0)), 0.877, 0.001);
    // Finneidfjord: 7.2 m/s with C_F 0.003 gives the paper's 78 Pa.
    EXPECT_NEAR(hydroplaningResistance(1000.0, 0.003, 7.2), 78.0, 0.5);
}

TEST(CheckParameters, RejectsBadValuesNamingTheKey)
{
    const HerschelBulkleyRemoulding good = case10();
    EXPECT_TRUE(checkParameters(good).empty());
    struct Bad { const char* key; std::function<void(HerschelBulkleyRemoulding&)> set; };
    const std::vector<Bad> bad = {
        {"s_uo", [](HerschelBulkleyRemoulding& m) { m.s_uo = 0.0; }},
        {"s_uo", [](HerschelBulkleyRemoulding& m) { m.s_uo = -5.0; }},
        {"s_uo", [](HerschelBulkleyRemoulding& m) { m.s_uo = NAN; }},
        {"eta", [](HerschelBulkleyRemoulding& m) { m.eta = -0.1; }},
        {"n", [](HerschelBulkleyRemoulding& m) { m.n = 0.0; }},
        {"n", [](HerschelBulkleyRemoulding& m) { m.n = -1.0; }},
        {"gdotRef", [](HerschelBulkleyRemoulding& m) { m.gdotRef = 0.0; }},
        {"deltaRem", [](HerschelBulkleyRemoulding& m) { m.deltaRem = 0.0; }},
        {"deltaRem", [](HerschelBulkleyRemoulding& m) { m.deltaRem = 1.2; }},
        {"xi95", [](HerschelBulkleyRemoulding& m) { m.xi95 = 0.0; }},
        {"xi95", [](HerschelBulkleyRemoulding& m) { m.xi95 = INFINITY; }},
    };
    for (const Bad& b : bad)
    {
        HerschelBulkleyRemoulding m = good;
        b.set(m);
        const ParameterProblem p = checkParameters(m);
        EXPECT_EQ(p.key, b.key);
        EXPECT_FALSE(p.message.empty());
    }
}

TEST(PlasticShearRate, OnlyYieldedMaterialAccumulatesStrain)
{
    const HerschelBulkleyRemoulding m = case10();
    ViscosityRegularisation reg;
    reg.type = Regularisation::cap;
    reg.muMax = 1e4;
    // The cap binds below gdot_c where s_u(gdot_c) = muMax gdot_c: found by bisection.
    double lo = 0.0, hi = 10.0;
    for (int i = 0; i < 200; ++i)
    {
        const double mid = 0.5*(lo + hi);
        (m.strength(mid, 0.0) < reg.muMax*mid ? hi : lo) = mid;
    }
    EXPECT_EQ(plasticShearRate(m, 0.999*lo, 0.0, reg), 0.0);
    EXPECT_DOUBLE_EQ(plasticShearRate(m, 1.001*hi, 0.0, reg), 1.001*hi);
    EXPECT_DOUBLE_EQ(plasticShearRate(m, -2.0, 0.0, reg), 2.0);
    // Papanastasiou: yielded once the weight is within 5 % of 1.
    reg.type = Regularisation::papanastasiou;
    reg.m = 100.0;
    EXPECT_EQ(plasticShearRate(m, 0.029, 0.0, reg), 0.0);
    EXPECT_DOUBLE_EQ(plasticShearRate(m, 0.031, 0.0, reg), 0.031);
}

TEST(ShearBandStrainFactor, CellsCoarserThanTheBandCarryItsStrain)
{
    // Slip delta across a band of thickness t: strain delta/t. A cell of size h
    // holding the band shows delta/h; times the factor it is delta/t again.
    const double delta = 0.3, t = 0.05;
    for (const double h : {0.05, 0.1, 0.5, 2.0})
    {
        EXPECT_NEAR(delta/h*shearBandStrainFactor(t, h), delta/t, 1e-12*delta/t);
    }
    // Cells finer than the band resolve it; no thickness set means no scaling.
    EXPECT_EQ(shearBandStrainFactor(t, 0.01), 1.0);
    EXPECT_EQ(shearBandStrainFactor(0.0, 0.5), 1.0);
    EXPECT_EQ(shearBandStrainFactor(-1.0, 0.5), 1.0);
}

TEST(ReturnStrength, MeetsEq1AtThePlasticRate)
{
    // tau - G x = s_u(x/dt, xi) for every branch: shear thinning (Cases 1 and
    // 10's n 0.15 and 0.23, n 0.5), Bingham (n 1, the closed form), shear
    // thickening (n 1.5), rate independent (eta 0); intact and partly remoulded;
    // from a trial stress a billionth above the threshold (where u^n is
    // steepest) to a hundred times it (Halley started far above the root).
    const double G = 100.0*500.0/2.98;
    for (const double dt : {1e-5, 1e-3})
    for (const double n : {0.15, 0.23, 0.5, 1.0, 1.5})
    for (const double eta : {0.0, 0.45})
    for (const double xi : {0.0, 4.0})
    {
        HerschelBulkleyRemoulding m = case10();
        m.n = n;
        m.eta = eta;
        const double threshold = m.thresholdStrength(xi);
        double x = -1.0;
        EXPECT_EQ(m.returnStrength(0.9*threshold, G, dt, xi, x), threshold);
        EXPECT_EQ(x, 0.0);
        for (const double excess : {1e-9, 1e-6, 0.01, 0.5, 3.0, 100.0})
        {
            const double tau = threshold*(1.0 + excess);
            const double s = m.returnStrength(tau, G, dt, xi, x);
            EXPECT_GT(x, 0.0);
            EXPECT_GE(s, threshold);
            EXPECT_LE(s, tau);
            EXPECT_NEAR(s, m.strength(x/dt, xi), 1e-12*tau);
            EXPECT_NEAR(tau - G*x, s, 1e-12*tau)
                << "dt " << dt << " n " << n << " eta " << eta << " xi " << xi << " excess " << excess;
        }
    }
}


TEST(ReturnStrength, WarmStartFindsTheSameRoot)
{
    // A material point's return started from the strength of its step before
    // (slideMPM keeps it) lands on the cold start's root from any previous
    // strength: the root itself, one near it, far below or above it, at the
    // threshold (an elastic step before: the cold start), and from a strength
    // whose remoulding has moved on (xi grew since).
    const double G = 100.0*500.0/2.98;
    for (const double dt : {1e-5, 1e-3})
    for (const double n : {0.15, 0.23, 0.5, 1.5})
    for (const double xi : {0.0, 4.0})
    for (const double excess : {1e-9, 1e-6, 0.01, 0.5, 3.0, 100.0})
    {
        HerschelBulkleyRemoulding m = case10();
        m.n = n;
        const double R = m.thresholdStrength(xi);
        const double tau = R*(1.0 + excess);
        double xCold = 0.0;
        const double cold = m.returnStrengthFromThreshold(tau, R, G, dt, xCold);
        for (const double previous : {cold, cold*(1.0 + 1e-6), R + 0.5*(cold - R), R + 1e-3*(cold - R),
                                      R + 10.0*(cold - R), R, 0.0, m.thresholdStrength(0.0)*1.5})
        {
            double x = -1.0;
            const double s = m.returnStrengthFromThreshold(tau, R, G, dt, x, previous);
            EXPECT_NEAR(s, cold, 1e-12*tau)
                << "dt " << dt << " n " << n << " xi " << xi << " excess " << excess << " previous " << previous;
            EXPECT_NEAR(x, xCold, 1e-12*tau/G);
            EXPECT_NEAR(tau - G*x, s, 1e-12*tau);
        }
    }
}


// Eq. (1)'s flow next to a wall (wallLayer.H) on Table 1 Case 1's material:
// the closed-form speed against a quadrature of the capped model's rate, the
// whole steady layer against its exact plug speed, and the inverse.
TEST(WallLayer, SpeedIsTheIntegralOfTheCappedRate)
{
    const HerschelBulkleyRemoulding m = case1();
    const double muMax = 47574.46101, k = 600.0*9.81*std::sin(3.43*M_PI/180.0);
    ViscosityRegularisation reg;
    reg.muMax = muMax;
    const double tauCap = capStress(m, 0.0, muMax);
    // At the cap stress the two branches give one rate.
    EXPECT_NEAR(m.strength(tauCap/muMax, 0.0), tauCap, 1e-9*tauCap);
    // The rate as the model gives it: the g solving apparentViscosity(g) g = tau.
    auto rate = [&](double tau)
    {
        if (tau <= tauCap) return tau/muMax;
        double lo = tauCap/muMax, hi = 1e6;
        for (int it = 0; it < 200; ++it)
        {
            const double mid = std::sqrt(lo*hi);
            (apparentViscosity(m, mid, 0.0, reg)*mid < tau ? lo : hi) = mid;
        }
        return std::sqrt(lo*hi);
    };
    for (const double tauWall : {100.0, 190.0, 228.9, 300.0})
    {
        for (const double z : {0.005, 0.02, 0.1})
        {
            const double quad = simpson([&](double zz) { return rate(std::fmax(tauWall - k*zz, 0.0)); }, z, 20000);
            EXPECT_NEAR(wallLayerSpeed(m, 0.0, muMax, tauWall, k, z), quad, 1e-6*quad + 1e-15)
                << "tauWall " << tauWall << " z " << z;
        }
    }
    // No gradient: the rate at the wall stress times z.
    EXPECT_NEAR(wallLayerSpeed(m, 0.0, muMax, 228.9, 0.0, 0.01), rate(228.9)*0.01, 1e-9);
}

TEST(WallLayer, WholeSteadyLayerIsEq1sPlug)
{
    // Over the whole depth h (tauWall = k h) with a cap too high to creep, the speed
    // at the surface is the exact plug speed gdot_ref s_uo/k eta^(-1/n) n/(n+1) x_b^((n+1)/n).
    const HerschelBulkleyRemoulding m = case1();
    const double k = 599.0*9.81*std::sin(3.43*M_PI/180.0), h = 0.65;
    const double xb = k*h/m.s_uo - 1.0, e = (m.n + 1.0)/m.n;
    const double plug = m.gdotRef*m.s_uo/k*std::pow(m.eta, -1.0/m.n)/e*std::pow(xb, e);
    EXPECT_NEAR(wallLayerSpeed(m, 0.0, 1e30, k*h, k, h), plug, 1e-9*plug);
    EXPECT_NEAR(plug, 0.02558, 5e-5);   // validation/cfd/rateLayer.md's exact plug
}

TEST(WallLayer, StressInvertsSpeed)
{
    const HerschelBulkleyRemoulding m = case1();
    const double muMax = 47574.46101, k = 352.0;
    for (const double tauWall : {50.0, 160.0, 228.9, 400.0})
    {
        for (const double z : {0.003, 0.05})
        {
            const double u = wallLayerSpeed(m, 0.0, muMax, tauWall, k, z);
            EXPECT_NEAR(wallLayerStress(m, 0.0, muMax, u, k, z), tauWall, 1e-8*tauWall);
        }
    }
    EXPECT_EQ(wallLayerStress(m, 0.0, muMax, 0.0, k, 0.01), 0.0);
    // A thin cell sees no gradient: the wall stress is Eq. (1)'s strength at u/z.
    const double g = 0.9, z = 1e-6;
    EXPECT_NEAR(wallLayerStress(m, 0.0, muMax, g*z, k, z), m.strength(g, 0.0), 1e-3);
}

