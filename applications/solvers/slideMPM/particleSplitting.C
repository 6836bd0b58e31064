#include "particleSplitting.H"
#include "quadraticBSpline.H"

#include <algorithm>

namespace slide
{
namespace mpm
{

namespace splitting
{

using Offsets = Kokkos::View<int*, MemorySpace>;

// What to do with each particle: -1 keep, 0 split along x, 1 split along y.
using Axes = Kokkos::View<int*, MemorySpace>;

// The child of split particle p (at n + offset(p)) starts as its copy.
template<class V>
void copyToChildren(const V& v, const Axes& axis, const Offsets& offset, const int n)
{
    Kokkos::parallel_for("splitCopy", Policy(0, n), KOKKOS_LAMBDA(const int p)
    {
        if (axis(p) < 0) return;
        const int c = n + offset(p);
        for (int k = 0; k < static_cast<int>(v.extent(1)); ++k) v(c, k) = v(p, k);
    });
}

void copyToChildren(const ParticleScalar& v, const Axes& axis, const Offsets& offset, const int n)
{
    Kokkos::parallel_for("splitCopy", Policy(0, n), KOKKOS_LAMBDA(const int p)
    {
        if (axis(p) >= 0) v(n + offset(p)) = v(p);
    });
}

} // namespace splitting

using namespace splitting;

long long ParticleSplitting::split(MaterialPoints& mp, BackgroundGrid& grid, const BaseLevelSet& level,
                                   const long long maxCount) const
{
    if (!enabled || mp.count == 0) return 0;
    const int n = mp.count;
    const double longest = maxLength*grid.d;
    const double fullCell = (grid.d/mp.spacing)*(grid.d/mp.spacing);   // particles the seeding puts in a cell

    // Particles per cell.
    const auto x = mp.position;
    const double d = grid.d, invD = 1.0/d, xOrigin = grid.xOrigin;
    const int i0 = grid.i0, j0 = grid.j0;
    const RowShear rows = grid.rows;
    grid.pressureSumsCurrent = false;   // the particles change
    sumOverCells(grid, x, n, KOKKOS_LAMBDA(const int, double& a, double&) { a = 1.0; });

    const auto len = mp.size;
    const auto vol = mp.volume;
    const double minVolume = minVolumeFraction*mp.spacing*mp.spacing;
    const auto count = grid.averaging;
    Axes axis("splitAxis", n);
    Offsets offset("splitOffsets", n);
    int added = 0;
    Kokkos::parallel_scan("splitPlan", Policy(0, n), KOKKOS_LAMBDA(const int p, int& running, const bool final)
    {
        const double lx = len(p, 0), ly = len(p, 1);
        int a = -1;
        if ((lx > longest || ly > longest) && 0.5*vol(p) >= minVolume)
        {
            int i, j;
            Stencil::cell(x(p, 0), x(p, 1) - rows.height(x(p, 0)), xOrigin, invD, i0, j0, i, j);
            if (count(i, j, 0) < fullCell) a = lx >= ly ? 0 : 1;
        }
        if (final)
        {
            axis(p) = a;
            offset(p) = running;
        }
        if (a >= 0) ++running;
    }, added);
    if (added == 0) return 0;
    if (n + static_cast<long long>(added) > maxCount) return -static_cast<long long>(added);

    // Children go after the n parents.
    mp.resize(n + added);
    mp.forEachView([&](const char*, const auto& v) { copyToChildren(v, axis, offset, n); });

    const auto xs = mp.position;
    const auto vel = mp.velocity;
    const auto C = mp.affine;
    const auto m = mp.mass;
    const auto V = mp.volume;
    const auto W = mp.plasticWork;
    const auto ls = mp.size;
    Kokkos::parallel_for("splitParticles", Policy(0, n), KOKKOS_LAMBDA(const int p)
    {
        const int a = axis(p);
        if (a < 0) return;
        const int c = n + offset(p);
        // The halves' centres lie a quarter of the domain either side, and within
        // half a cell: the grid's window around the parents holds them.
        const double h = std::fmin(0.25*ls(p, a), 0.5*d);   // fmin: std::min is host-only under nvcc
        const double hx = a == 0 ? h : 0.0, hy = a == 1 ? h : 0.0;
        // C is the velocity's gradient on the grid's lattice: the offset in its
        // coordinates has the height above the sheared rows' base.
        const double hr = hy - rows.slope(xs(p, 0))*hx;
        const double dvx = C(p, 0)*hx + C(p, 1)*hr, dvy = C(p, 2)*hx + C(p, 3)*hr;
        const double x0 = xs(p, 0), y0 = xs(p, 1), vx0 = vel(p, 0), vy0 = vel(p, 1);
        const double half[4] = {0.5*m(p), 0.5*V(p), 0.5*ls(p, a), 0.5*W(p)};
        const int member[2] = {p, c};
        for (int k = 0; k < 2; ++k)
        {
            const int q = member[k];
            const double sign = k == 0 ? 1.0 : -1.0;
            const double xq = x0 + sign*hx;
            double yq = y0 + sign*hy;
            const double yb = level.height(xq);
            if (yq < yb) yq = yb;
            xs(q, 0) = xq;
            xs(q, 1) = yq;
            vel(q, 0) = vx0 + sign*dvx;
            vel(q, 1) = vy0 + sign*dvy;
            m(q) = half[0];
            V(q) = half[1];
            ls(q, a) = half[2];
            W(q) = half[3];
        }
    });
    return added;
}

} // namespace mpm
} // namespace slide
