// The particles' stress update: the undrained clay's elastic step and return
// onto Eq. (1)'s strength (UndrainedClay), with the B-bar's cell dilatation.
#include "timeIntegrator.H"
#include "cellPressure.H"
#include "quadraticBSpline.H"

#include <algorithm>
#include <cmath>

namespace slide
{
namespace mpm
{

void TimeIntegrator::updateStress(MaterialPoints& mp, BackgroundGrid& grid, const double dt, const bool record) const
{
    const UndrainedClay clay = clay_;
    const auto L = mp.velocityGradient;
    const auto sig = mp.stress;
    const auto V = mp.volume;
    const auto xi = mp.plasticShearStrain;
    const auto su = mp.strength;
    const auto rate = mp.shearStrainRate;
    const auto plasticRate = mp.plasticShearStrainRate;
    const auto work = mp.plasticWork;
    const auto x = mp.position;
    const auto v = mp.velocity;
    const auto len = mp.size;
    const bool average = controls_.volumetricLocking == MpmControls::VolumetricLocking::cellAveraging;
    const bool lagged = clay.plasticRate && clay.previousStepRate;   // the next step reads this step's rate
    const bool warmStart = clay.returnIterates();   // the next step's return starts from this step's s_u
    const auto avg = grid.averaging;
    const auto m = mp.mass;
    const double invDensity = 1.0/density_;
    const double invD = 1.0/grid.d, xOrigin = grid.xOrigin;
    const int i0 = grid.i0, j0 = grid.j0, ni = grid.ni, nj = grid.nj;
    const RowShear rows = grid.rows;
    // The next step's B-bar pressure, summed here where the stress and the new place are at hand.
    if (average)
    {
        zeroInStream(grid.pressureSums);
        grid.pressureSumsScatter.reset_except(grid.pressureSums);
    }
    auto pressureScatter = grid.pressureSumsScatter;
    // Beyond twice the splitting length a domain's stretch no longer says where
    // the gaps are (a flow that folds its material fills them): capped there.
    const double maxLength = 2.0*splitting_.maxLength*grid.d;
    const BaseLevelSet level = frame_.level;
    const bool shifting = this->shifting();   // by shiftField's node shifts
    const auto nodeShift = grid.shift;
    Kokkos::parallel_for("updateStress", Policy(0, mp.count), KOKKOS_LAMBDA(const int p)
    {
        const double Lp[4] = {L(p, 0), L(p, 1), L(p, 2), L(p, 3)};
        double s[4] = {sig(p, 0), sig(p, 1), sig(p, 2), sig(p, 3)};
        double dil = Lp[0] + Lp[3];
        if (average)
        {
            int i, j;
            Stencil::cell(x(p, 0), x(p, 1) - rows.height(x(p, 0)), xOrigin, invD, i0, j0, i, j);   // where G2P summed it
            dil = avg(i, j, 0);   // the cell's mean
        }
        double xip = xi(p), sup, gdot;
        const double Vn = V(p), Vn1 = Vn*UndrainedClay::stretchFactor(dil*dt);
        // V0 from the mass: a particle is seeded at the slide's density, and splitting halves m and V together.
        const double invVn1 = 1.0/Vn1;
        const double dXi = clay.update(Lp, dil, dt, s, xip, sup, gdot, record, lagged ? plasticRate(p) : 0.0,
                                       Vn*invVn1, m(p)*invDensity*invVn1, warmStart ? su(p) : 0.0);
        for (int c = 0; c < 4; ++c) sig(p, c) = s[c];
        xi(p) = xip;
        if (dXi > 0.0) work(p) += sup*dXi*Vn;   // the return's dissipation, s:dEps_p = s_u dXi
        // Stored only by steps whose end is written (7 % of the memory traffic),
        // but s_u every step where the next step's return starts from it.
        if (record || warmStart) su(p) = sup;
        if (record) rate(p) = gdot;
        if (record || lagged) plasticRate(p) = dXi/dt;
        V(p) = Vn1;
        len(p, 0) = std::fmin(maxLength, len(p, 0)*UndrainedClay::stretchFactor(Lp[0]*dt));   // fmin: std::min is host-only under nvcc
        len(p, 1) = std::fmin(maxLength, len(p, 1)*UndrainedClay::stretchFactor(Lp[3]*dt));
        double xn = x(p, 0) + dt*v(p, 0);
        double yn = x(p, 1) + dt*v(p, 1);
        if (shifting)
        {
            // The nodes' shift where the particle took their velocity.
            const Stencil st(x(p, 0), x(p, 1) - rows.height(x(p, 0)), xOrigin, invD, i0, j0, true);
            for (int a = 0; a < 3; ++a)
            {
                for (int b = 0; b < 3; ++b)
                {
                    const double w = st.wx[a]*st.wy[b];
                    xn += w*nodeShift(st.bx + a, st.by + b, 0);
                    yn += w*nodeShift(st.bx + a, st.by + b, 1);
                }
            }
        }
        // The grid's contact keeps nodes out of the base, but a particle near it
        // also takes velocity from nodes above that may still be descending:
        // its centre is put back on the base and its approach removed.
        const double yb = level.height(xn);
        if (yn < yb)
        {
            const double s = level.slope(xn), n = std::sqrt(1.0 + s*s);
            const double nx = -s/n, ny = 1.0/n;
            const double vn = v(p, 0)*nx + v(p, 1)*ny;
            if (vn < 0.0)
            {
                v(p, 0) -= vn*nx;
                v(p, 1) -= vn*ny;
            }
            yn = yb;
        }
        x(p, 0) = xn;
        x(p, 1) = yn;
        if (average)
        {
            int i, j;
            Stencil::cell(xn, yn - rows.height(xn), xOrigin, invD, i0, j0, i, j);
            // A particle that left the storage (a blow-up, or a grid that must grow
            // and so will sum afresh) has no cell to add to.
            if (i >= 0 && i < ni && j >= 0 && j < nj)
            {
                double a, b;
                cellPressureTerms(sig, V, p, a, b);
                auto acc = pressureScatter.access();
                acc(i, j, 0) += a;
                acc(i, j, 1) += b;
            }
        }
    });
    if (average)
    {
        Kokkos::Experimental::contribute(grid.pressureSums, grid.pressureSumsScatter);
        cellMeans(grid.pressureSums);
        grid.pressureSumsCurrent = true;
    }
}

} // namespace mpm
} // namespace slide
