#include "mpmRestart.H"

#include "mpmOutput.H"
#include "restartState.H"

#include <Kokkos_Core.hpp>

namespace slide
{
namespace mpm
{

namespace
{

// A host field's values, particle by particle.
template<class View>
std::vector<double> flatten(const View& h)
{
    std::vector<double> out;
    out.reserve(h.size());
    if constexpr (View::rank == 1)
    {
        out.assign(h.data(), h.data() + h.size());
    }
    else
    {
        for (std::size_t p = 0; p < h.extent(0); ++p)
        {
            for (std::size_t c = 0; c < h.extent(1); ++c) out.push_back(h(p, c));
        }
    }
    return out;
}

// The values of `key`, which must number n (one per particle and component).
const std::vector<double>& sized(const output::StateFile& f, const std::string& path, const std::string& key,
                                 const std::size_t n)
{
    const std::vector<double>& data = f.vector(key);
    if (data.size() != n)
    {
        throw scene::InputError(path, 0, key, "expected " + std::to_string(n) + " values, found "
                                + std::to_string(data.size()));
    }
    return data;
}

template<class View>
void fill(const output::StateFile& f, const std::string& path, const std::string& key, const View& v)
{
    const std::vector<double>& data = sized(f, path, key, v.size());
    auto h = Kokkos::create_mirror(v);
    std::size_t k = 0;
    for (std::size_t p = 0; p < h.extent(0); ++p)
    {
        for (std::size_t c = 0; c < h.extent(1); ++c) h(p, c) = data[k++];
    }
    Kokkos::deep_copy(v, h);
}

void fill(const output::StateFile& f, const std::string& path, const std::string& key, const ParticleScalar& v)
{
    const std::vector<double>& data = sized(f, path, key, v.size());
    auto h = Kokkos::create_mirror(v);
    for (std::size_t p = 0; p < h.size(); ++p) h(p) = data[p];
    Kokkos::deep_copy(v, h);
}

} // namespace

void writeState(const std::string& caseDir, const RestartPoint& at, const HostPoints& mp)
{
    output::StateFile f;
    at.addTo(f);
    f.add("initialFront", at.initialFront);
    f.add("initialMass", at.initialMass);
    f.add("highest", at.highest);
    f.add("stats", {at.stats.xmin, at.stats.xmax, at.stats.ymin, at.stats.ymax, at.stats.maxSpeed,
                    at.stats.kineticEnergy, at.stats.finite ? 1.0 : 0.0});
    f.add("energy", {at.energyStart.potential, at.energyStart.kinetic, at.energyStart.elastic,
                     at.energyStart.plastic, at.boundaryWork});
    f.add("frontResolution", at.front.values());
    f.add("count", static_cast<double>(mp.count));
    f.add("spacing", mp.spacing);
    mp.forEachView([&](const char* name, const auto& v) { f.add(name, flatten(v)); });
    f.write(output::statePath(caseDir, at.time, "slideMPM"));
}

RestartPoint readState(const std::string& path, MaterialPoints& mp)
{
    const output::StateFile f = output::StateFile::read(path);
    const double count = f.scalar("count");
    if (!(count >= 1.0 && count < 2e9)) throw scene::InputError(path, 0, "count", "not a particle count");
    mp.allocate(static_cast<int>(count));
    mp.spacing = f.scalar("spacing");
    mp.forEachView([&](const char* name, const auto& v) { fill(f, path, name, v); });

    RestartPoint at;
    static_cast<output::RestartClock&>(at) = output::RestartClock::readFrom(f);
    at.initialFront = f.scalar("initialFront");
    at.initialMass = f.scalar("initialMass");
    at.highest = f.scalar("highest");
    const std::vector<double>& st = f.vector("stats");
    if (st.size() != 7) throw scene::InputError(path, 0, "stats", "expected 7 values");
    at.stats.xmin = st[0];
    at.stats.xmax = st[1];
    at.stats.ymin = st[2];
    at.stats.ymax = st[3];
    at.stats.maxSpeed = st[4];
    at.stats.kineticEnergy = st[5];
    at.stats.finite = st[6] != 0.0;
    const std::vector<double>& en = f.vector("energy");
    if (en.size() != 5) throw scene::InputError(path, 0, "energy", "expected 5 values");
    at.energyStart.potential = en[0];
    at.energyStart.kinetic = en[1];
    at.energyStart.elastic = en[2];
    at.energyStart.plastic = en[3];
    at.boundaryWork = en[4];
    if (f.has("frontResolution"))
    {
        at.front = FrontRecord::fromValues(f.vector("frontResolution"), path, "frontResolution");
    }
    return at;
}

} // namespace mpm
} // namespace slide
