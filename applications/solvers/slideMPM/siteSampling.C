#include "siteSampling.H"

#include <cmath>
#include <stdexcept>
#include <string>

namespace slide
{
namespace mpm
{

namespace
{

// Per site: area, mass, x and y momentum of the particles under the tent.
constexpr int sumsPerSite = 4;

struct SiteSums
{
    using value_type = double[];
    using size_type = int;
    unsigned value_count;
    int n;
    double d;
    double x[SiteSampler::maxSites];
    ParticleVector position, velocity;
    ParticleScalar mass, volume;

    KOKKOS_INLINE_FUNCTION void operator()(const int p, value_type sums) const
    {
        const double xp = position(p, 0);
        for (int k = 0; k < n; ++k)
        {
            const double r = (xp - x[k] >= 0.0 ? xp - x[k] : x[k] - xp)/d;
            if (r >= 1.0) continue;
            const double w = 1.0 - r;
            const double m = w*mass(p);
            sums[sumsPerSite*k] += w*volume(p);
            sums[sumsPerSite*k + 1] += m;
            sums[sumsPerSite*k + 2] += m*velocity(p, 0);
            sums[sumsPerSite*k + 3] += m*velocity(p, 1);
        }
    }
    KOKKOS_INLINE_FUNCTION void init(value_type sums) const
    {
        for (unsigned i = 0; i < value_count; ++i) sums[i] = 0.0;
    }
    KOKKOS_INLINE_FUNCTION void join(volatile value_type dst, const volatile value_type src) const
    {
        for (unsigned i = 0; i < value_count; ++i) dst[i] += src[i];
    }
};

} // namespace


double SiteSampler::frameX(const BaseLevelSet& level, const double arcLength)
{
    int k = 0;
    while (k < level.n - 2 && arcLength > level.s[k + 1]) ++k;
    return level.x[k] + (arcLength - level.s[k])*(level.x[k + 1] - level.x[k])/(level.s[k + 1] - level.s[k]);
}

SiteSampler::SiteSampler(const std::vector<scene::Site>& sites, const BaseFrame& frame, const double cellSize)
:
    n_(static_cast<int>(sites.size())),
    d_(cellSize)
{
    if (n_ > maxSites)
    {
        throw std::invalid_argument("slideMPM samples at most " + std::to_string(maxSites) + " sites");
    }
    for (int k = 0; k < n_; ++k)
    {
        x_[k] = frameX(frame.level, sites[k].position);
        slope_[k] = frame.level.slope(x_[k]);
    }
}

std::vector<output::SiteFlow> SiteSampler::sample(const MaterialPoints& mp, const StepStatistics& stats) const
{
    std::vector<output::SiteFlow> flow(n_);
    if (n_ == 0) return flow;
    SiteSums f;
    f.value_count = static_cast<unsigned>(sumsPerSite*n_);
    f.n = n_;
    f.d = d_;
    for (int k = 0; k < n_; ++k) f.x[k] = x_[k];
    f.position = mp.position;
    f.velocity = mp.velocity;
    f.mass = mp.mass;
    f.volume = mp.volume;
    std::vector<double> sums(f.value_count, 0.0);
    Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(sums.data(), sums.size());
    Kokkos::parallel_reduce("siteSums", Policy(0, mp.count), f, result);
    for (int k = 0; k < n_; ++k)
    {
        const double* s = &sums[sumsPerSite*k];
        output::SiteFlow& o = flow[k];
        o.covered = x_[k] >= stats.xmin && x_[k] <= stats.xmax && s[1] > 0.0;
        if (!o.covered) continue;
        // The tent integrates to d; the area over it is the height along the frame's
        // y, which the base's slope there turns into the thickness normal to it.
        const double norm = std::sqrt(1.0 + slope_[k]*slope_[k]);
        o.thickness = s[0]/d_/norm;
        o.velocity = (s[2] + slope_[k]*s[3])/(s[1]*norm);
    }
    return flow;
}

} // namespace mpm
} // namespace slide
