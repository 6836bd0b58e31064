#include "damApplicability.H"

#include "dictionary.H"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace slide
{
namespace dam
{

std::string defaultApplicabilityMap()
{
    const char* top = std::getenv("SLIDEFOAM_DIR");
    return top ? std::string(top) + "/etc/damApplicability" : std::string();
}

Applicability checkApplicability(const scene::Scene& sc, const std::string& mapPath)
{
    if (mapPath.empty() || !std::filesystem::exists(mapPath)) return {"unknown", "no applicability map"};
    const scene::Dictionary d = scene::Dictionary::readFile(mapPath);
    const std::vector<double> suo = d.getScalarList("s_uo");
    const std::vector<double> st = d.getScalarList("sensitivity");
    const auto agrees = d.getTupleList("agrees", st.size());
    if (suo.empty() || st.empty() || agrees.size() != suo.size())
    {
        d.fail("agrees", "expected one row of " + std::to_string(st.size()) + " flags per s_uo value");
    }
    const double tolerance = d.getScalar("tolerance");
    const double s_uo = sc.rheology.s_uo;
    const double S_t = 1.0/sc.rheology.deltaRem;

    std::ostringstream why;
    why << "s_uo " << s_uo << " Pa, S_t " << S_t;
    // The grid is logarithmic in both: nearest point in log space.
    auto nearest = [](const std::vector<double>& v, double x)
    {
        std::size_t k = 0;
        for (std::size_t i = 1; i < v.size(); ++i)
        {
            if (std::fabs(std::log(v[i]/x)) < std::fabs(std::log(v[k]/x))) k = i;
        }
        return k;
    };
    Applicability a{"inside", ""};
    const double suoMin = *std::min_element(suo.begin(), suo.end());
    const double stMax = *std::max_element(st.begin(), st.end());
    if (s_uo < suoMin || S_t > stMax)
    {
        why << " lies outside the map (s_uo >= " << suoMin << " Pa, S_t <= " << stMax << ")";
        a = {"outside", why.str()};
    }
    else if (agrees[nearest(suo, s_uo)][nearest(st, S_t)] == 0.0)
    {
        why << " lies where slideDAM's runout differed from slideMPM's by more than " << 100*tolerance << " %";
        a = {"outside", why.str()};
    }
    if (a.verdict == "outside")
    {
        const double eta = d.getScalar("eta"), n = d.getScalar("n");
        a.message += " (" + mapPath + ", validation/applicability/map.md)";
        if (std::fabs(sc.rheology.eta - eta) > 0.2*eta || std::fabs(sc.rheology.n - n) > 0.2*n)
        {
            std::ostringstream os;
            os << "; the map was built for eta " << eta << ", n " << n << ", this scene has eta " << sc.rheology.eta
               << ", n " << sc.rheology.n;
            a.message += os.str();
        }
    }
    return a;
}

} // namespace dam
} // namespace slide
