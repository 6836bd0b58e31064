#include "materialPoints.H"
#include "backgroundGrid.H"
#include "quadraticBSpline.H"

#include <Kokkos_Sort.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace slide
{
namespace mpm
{

void MaterialPoints::allocate(const int n)
{
    count = n;
    forEachView([n](const char* name, auto& v) { v = std::decay_t<decltype(v)>(std::string(name), static_cast<std::size_t>(n)); });
}

void MaterialPoints::resize(const int n)
{
    count = n;
    forEachView([n](const char*, auto& v) { Kokkos::resize(v, n); });
}

namespace
{

ParticleScalar& spareFor(MaterialPoints& mp, const ParticleScalar&) { return mp.spareScalar; }
ParticleVector& spareFor(MaterialPoints& mp, const ParticleVector&) { return mp.spareVector; }
ParticleTensor& spareFor(MaterialPoints& mp, const ParticleTensor&) { return mp.spareTensor; }

// to's particle p becomes from's particle q.
KOKKOS_INLINE_FUNCTION void copyParticle(const ParticleScalar& to, const int p, const ParticleScalar& from, const int q)
{
    to(p) = from(q);
}

template<class View>
KOKKOS_INLINE_FUNCTION void copyParticle(const View& to, const int p, const View& from, const int q)
{
    for (int k = 0; k < static_cast<int>(View::static_extent(1)); ++k) to(p, k) = from(q, k);
}

// v in the order `order` gives (sorted p is old order(p), as BinSort::sort
// puts it), through `spare`, which v's old storage then becomes.
template<class View, class Order>
void permuteField(View& v, const Order& order, View& spare)
{
    const int n = static_cast<int>(v.extent(0));
    if (spare.extent(0) != v.extent(0))
    {
        spare = View();   // the old storage goes before the new is taken
        spare = View(Kokkos::view_alloc(Kokkos::WithoutInitializing, "sortSpare"), v.extent(0));
    }
    const View from = v, to = spare;
    Kokkos::parallel_for("sortPermute", Kokkos::RangePolicy<ExecutionSpace>(0, n), KOKKOS_LAMBDA(const int p)
    {
        copyParticle(to, p, from, order(p));
    });
    std::swap(v, spare);
}

} // namespace

void MaterialPoints::sortByCell(BackgroundGrid& grid)
{
    grid.pressureSumsCurrent = false;   // summed in the old order
    using KeyView = Kokkos::View<int*, MemorySpace>;
    KeyView keys("cellKeys", count);
    const auto x = position;
    const double invD = 1.0/grid.d, xOrigin = grid.xOrigin;
    const int i0 = grid.i0, j0 = grid.j0, nj = grid.nj;
    const RowShear rows = grid.rows;
    Kokkos::parallel_for("cellKeys", Kokkos::RangePolicy<ExecutionSpace>(0, count), KOKKOS_LAMBDA(const int p)
    {
        int i, j;
        Stencil::cell(x(p, 0), x(p, 1) - rows.height(x(p, 0)), xOrigin, invD, i0, j0, i, j);
        keys(p) = i*nj + j;
    });
    const int nBins = grid.ni*grid.nj;
    using Op = Kokkos::BinOp1D<KeyView>;
    Kokkos::BinSort<KeyView, Op> sorter(keys, Op(nBins, 0, nBins - 1), false);
    sorter.create_permute_vector();
    const auto order = sorter.get_permute_vector();
    forEachView([&](const char*, auto& v) { permuteField(v, order, spareFor(*this, v)); });
}

long long MaterialPoints::estimateCount(const scene::Scene& sc, const double d, const int ppc)
{
    const double a = d/ppc;
    return static_cast<long long>(std::ceil(sc.slide.area()/(a*a)*1.05)) + 16;
}

MaterialPoints MaterialPoints::seed(const scene::Scene& sc, const BaseFrame& frame, const UndrainedClay& clay,
                                   const double nu, const double d, const int ppc, const bool geostatic,
                                   const RowShear& rows)
{
    const double a = d/ppc;
    const double s0 = sc.slide.rearPosition, s1 = sc.slide.frontPosition();

    // Frame bounding box of the slide.
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    const int nSample = 200;
    for (int k = 0; k <= nSample; ++k)
    {
        const double s = s0 + (s1 - s0)*k/nSample;
        const double H = std::max(sc.slide.thickness(s), sc.slide.height);
        const scene::Point2 p = sc.base.point(s), n = sc.base.normal(s);
        for (double h : {0.0, H})
        {
            double xf, yf;
            frame.toFrame(p.x + h*n.x, p.z + h*n.z, xf, yf);
            yf -= rows.height(xf);
            xmin = std::min(xmin, xf); xmax = std::max(xmax, xf);
            ymin = std::min(ymin, yf); ymax = std::max(ymax, yf);
        }
    }
    // Sub-cells aligned with the grid (rear at a node line, base at y = 0 when
    // planar; along the grid's rows where they follow a polyline base).
    const long long i0 = static_cast<long long>(std::floor((xmin - frame.rearX)/a)) - 1;
    const long long i1 = static_cast<long long>(std::ceil((xmax - frame.rearX)/a)) + 1;
    const long long j0 = static_cast<long long>(std::floor(ymin/a)) - 1;
    const long long j1 = static_cast<long long>(std::ceil(ymax/a)) + 1;

    const double rho = sc.slide.density;
    const double K0 = nu/(1.0 - nu);
    std::vector<double> hx, hy, hs;
    for (long long i = i0; i <= i1; ++i)
    {
        for (long long j = j0; j <= j1; ++j)
        {
            const double xf = frame.rearX + (i + 0.5)*a, yf = rows.height(xf) + (j + 0.5)*a;
            double X, Z, s = 0.0, h = 0.0;
            frame.toGlobal(xf, yf, X, Z);
            sc.base.coordinates(X, Z, s, h);
            if (s < s0 || s > s1 || h <= 0.0) continue;
            const double H = sc.slide.thickness(s);
            if (h >= H) continue;
            // Geostatic stress of the column above (normal to the local base).
            const double sv = geostatic ? -rho*sc.g*std::cos(sc.base.angle(s))*(H - h) : 0.0;
            hx.push_back(xf);
            hy.push_back(yf);
            hs.push_back(sv);
        }
    }
    MaterialPoints mp;
    mp.spacing = a;
    mp.allocate(static_cast<int>(hx.size()));
    auto x = Kokkos::create_mirror_view(mp.position);
    auto m = Kokkos::create_mirror_view(mp.mass);
    auto V = Kokkos::create_mirror_view(mp.volume);
    auto sig = Kokkos::create_mirror_view(mp.stress);
    auto su = Kokkos::create_mirror_view(mp.strength);
    auto len = Kokkos::create_mirror_view(mp.size);
    for (int p = 0; p < mp.count; ++p)
    {
        x(p, 0) = hx[p];
        x(p, 1) = hy[p];
        V(p) = a*a;
        m(p) = rho*a*a;
        double s[4] = {K0*hs[p], hs[p], K0*hs[p], 0.0};
        const double tau = UndrainedClay::shearStress(s);
        const double suo = clay.strength.strength(0.0, 0.0);
        if (tau > suo) UndrainedClay::returnToYieldSurface(s, tau, suo);
        for (int c = 0; c < 4; ++c) sig(p, c) = s[c];
        su(p) = suo;
        len(p, 0) = a;
        len(p, 1) = a;
    }
    Kokkos::deep_copy(mp.position, x);
    Kokkos::deep_copy(mp.mass, m);
    Kokkos::deep_copy(mp.volume, V);
    Kokkos::deep_copy(mp.stress, sig);
    Kokkos::deep_copy(mp.strength, su);
    Kokkos::deep_copy(mp.size, len);
    return mp;
}

MaterialPoints::Located MaterialPoints::fastest() const
{
    using Reducer = Kokkos::MaxLoc<double, int>;
    typename Reducer::value_type best;
    const ParticleVector v = velocity;
    Kokkos::parallel_reduce("fastestParticle", Kokkos::RangePolicy<ExecutionSpace>(0, count),
        KOKKOS_LAMBDA(const int p, typename Reducer::value_type& b)
        {
            const double s2 = v(p, 0)*v(p, 0) + v(p, 1)*v(p, 1);
            const double key = s2 == s2 ? s2 : 1e308;   // NaN ranks first
            if (key > b.val) { b.val = key; b.loc = p; }
        }, Reducer(best));
    Located r;
    if (best.loc < 0 || best.loc >= count) return r;
    // Gathered on the device first: a particle's row of a LayoutLeft view (CUDA's
    // default) is strided, and Kokkos copies no strided view between spaces.
    Kokkos::View<double[4], MemorySpace> state("fastestState");
    const ParticleVector x = position;
    const int q = best.loc;
    Kokkos::parallel_for("fastestState", Kokkos::RangePolicy<ExecutionSpace>(0, 1), KOKKOS_LAMBDA(const int)
    {
        state(0) = x(q, 0);
        state(1) = x(q, 1);
        state(2) = v(q, 0);
        state(3) = v(q, 1);
    });
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), state);
    r.index = q;
    r.x = h(0);
    r.y = h(1);
    r.speed = std::sqrt(h(2)*h(2) + h(3)*h(3));
    return r;
}

} // namespace mpm
} // namespace slide
