// Single-particle constitutive driver of the MPM's undrained clay against the
// shared rheology (Eq. 1): rate curve, softening curve, elastic modulus,
// objectivity under rigid rotation, resistance to large compression, and the
// plastic strain bookkeeping.
#include "undrainedClay.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace slide;
using mpm::UndrainedClay;

namespace
{

rheology::HerschelBulkleyRemoulding material(double eta, double n, double deltaRem, double xi95)
{
    rheology::HerschelBulkleyRemoulding m;
    m.s_uo = 1000.0;
    m.eta = eta;
    m.n = n;
    m.gdotRef = 0.06;
    m.deltaRem = deltaRem;
    m.xi95 = xi95;
    return m;
}

// Simple shear dvx/dy = gdot for a time T in steps dt; returns sigma_xy.
double shear(const UndrainedClay& c, double gdot, double T, double dt, double& xi, double* sig)
{
    const double L[4] = {0.0, gdot, 0.0, 0.0};
    double su = 0.0, rate = 0.0;
    for (double t = 0.0; t < T - 1e-12; t += dt) c.update(L, 0.0, dt, sig, xi, su, rate);
    return sig[3];
}

} // namespace

TEST(UndrainedClay, SimpleShearRateIsTheEngineeringShearRate)
{
    EXPECT_NEAR(UndrainedClay::shearStrainRate(0.0, 0.0, 0.5*0.3), 0.3, 1e-15);
    // Pure shear (plane strain) of the same magnitude.
    EXPECT_NEAR(UndrainedClay::shearStrainRate(0.15, -0.15, 0.0), 0.3, 1e-15);
}

TEST(UndrainedClay, ElasticShearModulus)
{
    const UndrainedClay c = UndrainedClay::fromYoungs(material(0.0, 1.0, 1.0, 1.0), 1e5, 0.49);
    double sig[4] = {0, 0, 0, 0}, xi = 0.0;
    const double gamma = 1e-3;   // well below yield (s_uo/G = 0.03)
    const double tau = shear(c, 1e-2, gamma/1e-2, 1e-3, xi, sig);
    EXPECT_NEAR(tau, c.shearModulus*gamma, 1e-3*c.shearModulus*gamma);
    EXPECT_EQ(xi, 0.0);
}

TEST(UndrainedClay, RateCurveFollowsEquation1)
{
    // At steady simple shear the stress sits on s_u(gdot) of the shared library,
    // with the rate taken as the total or the plastic one (equal once the elastic
    // strain is steady; the Jaumann spin keeps it drifting by up to 3e-4).
    const rheology::HerschelBulkleyRemoulding m = material(0.45, 0.23, 1.0, 1.0);
    for (bool plastic : {false, true})
    {
        const UndrainedClay c = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49, plastic);
        for (double gdot : {0.006, 0.06, 0.6, 6.0, 60.0})
        {
            double sig[4] = {0, 0, 0, 0}, xi = 0.0;
            const double T = 0.5/gdot;          // 50 % shear strain: well past yield
            const double tau = shear(c, gdot, T, T/2000.0, xi, sig);
            // On the yield surface sqrt(J2) = s_u; the spin of simple shear tilts a
            // little of it into normal stress differences.
            EXPECT_NEAR(UndrainedClay::shearStress(sig), m.strength(gdot, 0.0), 1e-3*m.strength(gdot, 0.0))
                << gdot << (plastic ? " plastic" : " total");
            EXPECT_NEAR(tau, m.strength(gdot, 0.0), 0.01*m.strength(gdot, 0.0)) << gdot;
        }
    }
}

TEST(UndrainedClay, PlasticRateYieldsAtTheThresholdStrength)
{
    // Loaded from rest at a high rate, the total-rate variant yields at
    // s_u(gdot) at once; the plastic-rate one yields at s_uo, then hardens to
    // s_u(gdot) as the flow takes over the rate.
    const rheology::HerschelBulkleyRemoulding m = material(0.45, 0.23, 1.0, 1.0);
    const double gdot = 6.0, dt = 1e-5;
    const UndrainedClay total = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49, false);
    const UndrainedClay plastic = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49, true);
    double a[4] = {0, 0, 0, 0}, b[4] = {0, 0, 0, 0}, xa = 0.0, xb = 0.0;
    const double L[4] = {0.0, gdot, 0.0, 0.0};
    double suA = 0.0, suB = 0.0, r;
    while (xa == 0.0) total.update(L, 0.0, dt, a, xa, suA, r);
    while (xb == 0.0) plastic.update(L, 0.0, dt, b, xb, suB, r);
    EXPECT_NEAR(suA, m.strength(gdot, 0.0), 1e-9*m.s_uo);
    EXPECT_LT(suB, 1.1*m.s_uo);
    EXPECT_GT(xb/dt, 0.0);
}

TEST(UndrainedClay, SofteningCurveFollowsEquation1)
{
    // Rate-independent, sensitive clay: after yield, s_u follows the remoulding
    // factor of the accumulated plastic shear strain, and xi grows by the
    // applied strain less the elastic part.
    const rheology::HerschelBulkleyRemoulding m = material(0.0, 1.0, 0.2, 10.0);
    const UndrainedClay c = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49);
    double sig[4] = {0, 0, 0, 0}, xi = 0.0;
    const double gdot = 1.0, dt = 1e-4;
    double gamma = 0.0;
    for (double target : {0.5, 2.0, 5.0, 10.0, 20.0})
    {
        shear(c, gdot, target - gamma, dt, xi, sig);
        gamma = target;
        const double tau = UndrainedClay::shearStress(sig);
        // s_u is taken with xi at the start of the last step.
        EXPECT_NEAR(tau, m.strength(gdot, xi), 1e-4*m.s_uo) << target;
        // xi = gamma - tau/G, less what the Jaumann spin turned into normal stress.
        EXPECT_NEAR(xi, gamma - tau/c.shearModulus, 1e-3*gamma) << target;
    }
    EXPECT_LT(sig[3], 0.3*m.s_uo);   // 20 shear strain: close to the remoulded 0.2 s_uo
}

TEST(UndrainedClay, ShearBandThinnerThanTheCellSoftensFaster)
{
    // A cell five times the band's thickness: the band's strain is five times
    // the cell's, so the clay softens along Eq. (1) at five times the strain
    // (the same curve as the unscaled clay sheared five times as far).
    const rheology::HerschelBulkleyRemoulding m = material(0.0, 1.0, 0.2, 10.0);
    UndrainedClay band = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49);
    band.bandStrainFactor = rheology::shearBandStrainFactor(0.1, 0.5);
    ASSERT_DOUBLE_EQ(band.bandStrainFactor, 5.0);
    const UndrainedClay cell = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49);
    double sigBand[4] = {0, 0, 0, 0}, xiBand = 0.0, sigCell[4] = {0, 0, 0, 0}, xiCell = 0.0;
    shear(band, 1.0, 2.0, 1e-4, xiBand, sigBand);
    shear(cell, 1.0, 2.0, 1e-4, xiCell, sigCell);
    // The cell's plastic strain is the applied 2 less the elastic part, as unscaled.
    const double tauBand = UndrainedClay::shearStress(sigBand);
    EXPECT_NEAR(xiBand, 5.0*(2.0 - tauBand/band.shearModulus), 5e-3*xiBand);
    EXPECT_NEAR(xiCell, 2.0 - UndrainedClay::shearStress(sigCell)/cell.shearModulus, 1e-3*xiCell);
    EXPECT_NEAR(tauBand, m.strength(1.0, xiBand), 1e-4*m.s_uo);
    EXPECT_LT(UndrainedClay::shearStress(sigBand), 0.5*UndrainedClay::shearStress(sigCell));
}

TEST(UndrainedClay, ShearBandRateIsTheCellsTimesTheBandFactor)
{
    // A cell six times the band's thickness (H0/10 cells, H0/60 bands): the
    // cell's slip crosses the band, so in steady shear at the cell's rate gdot
    // the clay holds Eq. (1)'s strength at 6 gdot, with each way of taking
    // the rate; the cell's plastic strain is unchanged by it (xi unscaled
    // here: bandStrainFactor 1, so the rate alone is tested).
    const rheology::HerschelBulkleyRemoulding m = material(0.45, 0.23, 1.0, 1.0);
    const double factor = rheology::shearBandStrainFactor(5.0/60.0, 0.5);
    ASSERT_NEAR(factor, 6.0, 1e-12);
    for (int way = 0; way < 2; ++way)
    {
        UndrainedClay band = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49, way == 0);
        band.bandRateFactor = factor;
        const UndrainedClay cell = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49, way == 0);
        // Up to 36 1/s in the band (2.9 s_uo): a slide's shear layers reach
        // about 10 1/s, and higher the Jaumann spin of the larger elastic
        // strain turns more of the rate away from the yield surface.
        for (double gdot : {0.006, 0.6, 6.0})
        {
            const double T = 2.0/gdot;   // 200 % shear strain: steady
            double sb[4] = {0, 0, 0, 0}, sc[4] = {0, 0, 0, 0}, xb = 0.0, xc = 0.0;
            shear(band, gdot, T, T/2000.0, xb, sb);
            shear(cell, gdot, T, T/2000.0, xc, sc);
            const char* name = way == 0 ? " plastic" : " total";
            EXPECT_NEAR(UndrainedClay::shearStress(sb), m.strength(factor*gdot, 0.0),
                        1e-3*m.strength(factor*gdot, 0.0)) << gdot << name;
            EXPECT_NEAR(UndrainedClay::shearStress(sc), m.strength(gdot, 0.0), 1e-3*m.strength(gdot, 0.0))
                << gdot << name;
            // Both flow at the cell's rate: the same plastic strain less the
            // larger elastic strain the band's higher strength holds (to what
            // the Jaumann spin turns into normal stress differences).
            EXPECT_NEAR(xb, xc - (UndrainedClay::shearStress(sb) - UndrainedClay::shearStress(sc))/band.shearModulus,
                        2e-3*xc) << gdot << name;
        }
    }
}

TEST(UndrainedClay, RigidRotationLeavesTheStressInvariants)
{
    // Jaumann rate: a spinning particle keeps its principal stresses.
    const UndrainedClay c = UndrainedClay::fromYoungs(material(0.0, 1.0, 1.0, 1.0), 1e5, 0.3);
    double sig[4] = {-3000.0, -2500.0, -2750.0, 300.0}, xi = 0.0, su, rate;   // inside the yield surface
    const double tau0 = UndrainedClay::shearStress(sig), tr0 = sig[0] + sig[1];
    const double w = 2.0;   // rad/s
    const double L[4] = {0.0, w, -w, 0.0};
    for (int k = 0; k < 10000; ++k) c.update(L, 0.0, 1e-4, sig, xi, su, rate);   // 2 rad
    EXPECT_NEAR(UndrainedClay::shearStress(sig), tau0, 2e-3*tau0);
    EXPECT_NEAR(sig[0] + sig[1], tr0, 1e-9*std::fabs(tr0));
    EXPECT_EQ(rate, 0.0);
}

TEST(UndrainedClay, CompressionResistanceGrowsWithoutBound)
{
    // Kirchhoff's rate: the mean Kirchhoff stress J p is K ln(1/J) at every J,
    // so the force of a particle on the grid (V0 J p) grows as it is squeezed.
    // Cauchy's rate gave p = K ln(1/J), a force V0 K J ln(1/J) that peaks at
    // J = 1/e (a fourteenth of the way here) and falls to nothing after.
    const UndrainedClay c = UndrainedClay::fromYoungs(material(0.0, 1.0, 1.0, 1.0), 1e5, 0.49);
    const double K = c.lame + 2.0/3.0*c.shearModulus;
    const double rate = -1.0, dt = 1e-3;   // isotropic in plane, with a deviator that yields at s_uo
    const double L[4] = {rate, 0.0, 0.0, rate};
    double sig[4] = {0.0, 0.0, 0.0, 0.0}, xi = 0.0, su = 0.0, gdot = 0.0, J = 1.0, lastForce = 0.0;
    for (int k = 0; k < 7000; ++k)   // to J = e^-14
    {
        const double stretch = UndrainedClay::stretchFactor(2.0*rate*dt);
        c.update(L, 2.0*rate, dt, sig, xi, su, gdot, true, 0.0, 1.0/stretch, 1.0/(J*stretch));
        J *= stretch;
        const double force = -J*UndrainedClay::third*(sig[0] + sig[1] + sig[2]);
        ASSERT_GT(force, lastForce) << "step " << k << ", J " << J;
        ASSERT_NEAR(force, -K*std::log(J), 1e-9*K*std::fabs(std::log(J))) << "step " << k;
        // s_u bounds the Cauchy stress, to the round-off of a deviator taken from
        // components of the size of p (1e11 Pa by the end).
        const double p = -UndrainedClay::third*(sig[0] + sig[1] + sig[2]);
        ASSERT_LE(UndrainedClay::shearStress(sig), c.strength.s_uo + 1e-15*p) << "step " << k;
        lastForce = force;
    }
    EXPECT_LT(J, 1e-6);
    EXPECT_GT(xi, 1.0);

    // The same compression under Cauchy's rate: the force peaks at J = 1/e, at
    // K/e, and is down to 14 e^-14 K by J = e^-14.
    UndrainedClay cauchy = c;
    cauchy.kirchhoffRate = false;
    double s2[4] = {0.0, 0.0, 0.0, 0.0}, peak = 0.0, peakJ = 0.0, force = 0.0;
    xi = 0.0;
    J = 1.0;
    for (int k = 0; k < 7000; ++k)
    {
        const double stretch = UndrainedClay::stretchFactor(2.0*rate*dt);
        cauchy.update(L, 2.0*rate, dt, s2, xi, su, gdot, true, 0.0, 1.0/stretch, 1.0/(J*stretch));
        J *= stretch;
        force = -J*UndrainedClay::third*(s2[0] + s2[1] + s2[2]);
        if (force > peak) { peak = force; peakJ = J; }
    }
    EXPECT_NEAR(peakJ, std::exp(-1.0), 2e-3);
    EXPECT_NEAR(peak, K/std::exp(1.0), 1e-6*K);
    EXPECT_LT(force, 1e-4*peak);
    EXPECT_LT(force, 1e-5*lastForce);
}

TEST(UndrainedClay, StrainRateLeftOutChangesNothingElse)
{
    // The time integrator skips the shear strain rate on steps whose state is not
    // written: stress, xi and s_u must be the same bits either way, through the
    // elastic range, yield, rate hardening and remoulding.
    const UndrainedClay c = UndrainedClay::fromYoungs(material(0.45, 0.23, 0.3, 10.0), 1e5, 0.49);
    const double L[4] = {0.02, 1.5, -0.3, -0.02};
    double a[4] = {0, 0, 0, 0}, b[4] = {0, 0, 0, 0}, xa = 0.0, xb = 0.0;
    double suA = 0.0, suB = 0.0, rateA = 0.0, rateB = -1.0;
    int plasticSteps = 0;
    for (int k = 0; k < 2000; ++k)
    {
        const double dXiA = c.update(L, L[0] + L[3], 1e-3, a, xa, suA, rateA, true);
        const double dXiB = c.update(L, L[0] + L[3], 1e-3, b, xb, suB, rateB, false);
        ASSERT_EQ(dXiA, dXiB) << "step " << k;
        plasticSteps += dXiA > 0.0;
        for (int i = 0; i < 4; ++i) ASSERT_EQ(a[i], b[i]) << "step " << k << ", component " << i;
        ASSERT_EQ(xa, xb);
        ASSERT_EQ(suA, suB);
        ASSERT_EQ(rateB, 0.0);
    }
    EXPECT_GT(rateA, 1.0);                 // the rate was computed where asked for
    EXPECT_GT(plasticSteps, 1000);         // the loading went well past yield
    EXPECT_GT(xa, 1.0);                    // and remoulded: below the intact strength at its rate
    EXPECT_LT(suA, 0.9*c.strength.s_uo*c.strength.rateFactor(rateA));
}

namespace
{

// Steady simple shear at gdot under strainRate previousPlastic, fed back as the
// integrator does: the mean sqrt(J2) and plastic rate over the second half of
// `steps` steps of dt, and how many yielding steps followed an elastic one (at
// which su must be s_uo).
struct LaggedShear { double meanTau = 0.0, meanRate = 0.0; int steps = 0, afterElastic = 0; };
LaggedShear laggedShear(const UndrainedClay& c, double gdot, double dt, int steps)
{
    const double L[4] = {0.0, gdot, 0.0, 0.0};
    double sig[4] = {0, 0, 0, 0}, xi = 0.0, su = 0.0, r = 0.0, previousRate = 0.0;
    LaggedShear out;
    for (int k = 0; k < steps; ++k)
    {
        const double before = previousRate;
        const double dXi = c.update(L, 0.0, dt, sig, xi, su, r, true, previousRate);
        previousRate = dXi/dt;
        if (k < steps/2) continue;
        ++out.steps;
        out.meanTau += UndrainedClay::shearStress(sig);
        out.meanRate += previousRate;
        if (before == 0.0 && dXi > 0.0)
        {
            ++out.afterElastic;
            EXPECT_NEAR(su, c.strength.s_uo, 1e-9*c.strength.s_uo);
        }
    }
    out.meanTau /= out.steps;
    out.meanRate /= out.steps;
    return out;
}

} // namespace

TEST(UndrainedClay, PreviousStepRateLosesTheRateEffectAsTheStepShrinks)
{
    // strainRate previousPlastic: Eq. (1) at the plastic rate of the step before.
    // A step after an elastic one sees s_uo and yields by the whole overshoot;
    // the next sees that large rate and stays elastic. Under steady simple shear
    // the strength alternates and the mean stress sits near s_uo instead of the
    // s_u(gdot) that the rate solved with the return gives
    // (RateCurveFollowsEquation1), the closer the smaller the step: the scheme
    // loses Eq. (1)'s rate effect as dt -> 0, where the rate solved with the
    // return converges.
    const rheology::HerschelBulkleyRemoulding m = material(0.45, 0.23, 1.0, 1.0);
    UndrainedClay c = UndrainedClay::fromYoungs(m, 100.0*m.s_uo, 0.49, true);
    c.previousStepRate = true;
    for (double gdot : {0.06, 0.6, 6.0})
    {
        const double elasticPerStep = 2.5e-4;   // gdot dt: G gdot dt = 0.8 % of s_uo a step
        const LaggedShear s = laggedShear(c, gdot, elasticPerStep/gdot, 2000);
        std::printf("gdot %g, G gdot dt %.3g s_uo: mean sqrt(J2) %.1f Pa (s_uo %.0f, s_u(gdot) %.1f), %d of %d "
                    "steps yield after an elastic one, mean plastic rate %.4g\n", gdot,
                    c.shearModulus*elasticPerStep/m.s_uo, s.meanTau, m.s_uo, m.strength(gdot, 0.0), s.afterElastic,
                    s.steps, s.meanRate);
        EXPECT_NEAR(s.meanRate, gdot, 0.01*gdot);   // the flow takes the imposed rate on average
        EXPECT_EQ(2*s.afterElastic, s.steps);      // every other step
        EXPECT_LT(s.meanTau - m.s_uo, 0.02*(m.strength(gdot, 0.0) - m.s_uo));
    }
    // Larger steps keep more of the rate effect (the elastic step after a yield
    // reaches further up); smaller ones less.
    const double gdot = 0.6;
    double previous = 1e300;
    for (double elasticPerStep : {1e-2, 1e-3, 1e-4})
    {
        const LaggedShear s = laggedShear(c, gdot, elasticPerStep/gdot, 4000);
        std::printf("gdot %g, G gdot dt %.3g s_uo: mean sqrt(J2) %.1f Pa\n", gdot,
                    c.shearModulus*elasticPerStep/m.s_uo, s.meanTau);
        EXPECT_LT(s.meanTau, previous);
        EXPECT_NEAR(s.meanRate, gdot, 0.01*gdot);
        previous = s.meanTau;
    }
    EXPECT_LT(previous - m.s_uo, 0.01*(m.strength(gdot, 0.0) - m.s_uo));
}
