#include "scene.H"

#include "basalResistance.H"
#include "checkParameters.H"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace slide
{
namespace scene
{

namespace
{

std::string joinPath(const std::string& dir, const std::string& rel)
{
    if (dir.empty() || dir == ".") return rel;
    return dir.back() == '/' ? dir + rel : dir + "/" + rel;
}

std::string baseName(const std::string& dir)
{
    std::error_code ec;
    std::filesystem::path p = std::filesystem::absolute(dir, ec).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    return p.filename().string();
}

SlideGeometry readSlide(const Dictionary& d, const BaseProfile& base)
{
    d.checkKnownKeys({"shape", "length", "height", "rearPosition", "rearWall", "density", "thickness"});
    SlideGeometry s;
    const std::string shape = d.getWordOneOf("shape", {"rectangle", "profile"});
    s.density = d.getScalarInRange("density", 0.0, 1e5, false, true, "submerged density [kg/m3]");
    s.rearWall = d.getBool("rearWall", false);
    if (shape == "rectangle")
    {
        s.shape = SlideGeometry::Shape::rectangle;
        s.length = d.getScalarInRange("length", 0.0, 1e7, false, true, "slide length L0 [m]");
        s.height = d.getScalarInRange("height", 0.0, 1e5, false, true, "slide height H0 [m]");
        s.rearPosition = d.getScalar("rearPosition", 0.0);
    }
    else
    {
        s.shape = SlideGeometry::Shape::profile;
        const auto rows = d.getTupleList("thickness", 2);
        if (rows.size() < 2) d.fail("thickness", "a thickness profile needs at least two (s h) points");
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            if (i > 0 && rows[i][0] <= rows[i - 1][0])
            {
                d.fail("thickness", "arc lengths s must increase strictly along the profile (point "
                       + std::to_string(i + 1) + ")");
            }
            if (rows[i][1] < 0.0)
            {
                d.fail("thickness", "negative thickness at point " + std::to_string(i + 1)
                       + ": the slide would start below the base");
            }
            s.profileS.push_back(rows[i][0]);
            s.profileH.push_back(rows[i][1]);
        }
        s.rearPosition = s.profileS.front();
        s.length = s.profileS.back() - s.profileS.front();
        s.height = 0.0;
        for (double h : s.profileH) s.height = std::max(s.height, h);
        if (s.height <= 0.0) d.fail("thickness", "the thickness profile holds no material");
        if (d.found("length") || d.found("height") || d.found("rearPosition"))
        {
            d.fail(d.found("length") ? "length" : d.found("height") ? "height" : "rearPosition",
                   "not used with shape profile (the thickness table gives the geometry)");
        }
    }
    if (!base.isPlanar())
    {
        const double L = base.length();
        if (s.rearPosition < 0.0 || s.frontPosition() > L)
        {
            d.fail(d.found("rearPosition") ? "rearPosition" : "length",
                   "the slide [" + std::to_string(s.rearPosition) + ", " + std::to_string(s.frontPosition())
                   + "] m does not lie on the base polyline [0, " + std::to_string(L) + "] m");
        }
    }
    return s;
}

BaseProfile readBase(const Dictionary& d, Interface& iface)
{
    d.checkKnownKeys({"profile", "angle", "points", "interface", "s_b", "rhoWater", "C_F"});
    BaseProfile base;
    const std::string profile = d.getWordOneOf("profile", {"planar", "polyline"});
    if (profile == "planar")
    {
        const double a = d.getScalarInRange("angle", 0.0, 60.0, true, true, "slope angle [deg]");
        if (d.found("points")) d.fail("points", "not used with profile planar");
        base = BaseProfile::planar(a);
    }
    else
    {
        if (d.found("angle")) d.fail("angle", "not used with profile polyline (the points give the slopes)");
        const auto rows = d.getTupleList("points", 2);
        if (rows.size() < 2) d.fail("points", "a polyline needs at least two (x z) points");
        std::vector<Point2> pts;
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            if (i > 0 && rows[i][0] <= rows[i - 1][0])
            {
                d.fail("points", "x must increase strictly along the base polyline (point " + std::to_string(i + 1)
                       + ": x = " + std::to_string(rows[i][0]) + " after " + std::to_string(rows[i - 1][0]) + ")");
            }
            if (i > 0)
            {
                const double slope = std::atan2(rows[i - 1][1] - rows[i][1], rows[i][0] - rows[i - 1][0])*180/M_PI;
                if (slope > 60.0 || slope < -30.0)
                {
                    d.fail("points", "segment " + std::to_string(i) + " has an inclination of "
                           + std::to_string(slope) + " deg; a base segment must lie in [-30, 60] deg");
                }
            }
            pts.push_back({rows[i][0], rows[i][1]});
        }
        base = BaseProfile::polyline(pts);
    }

    const std::string type = d.getWordOneOf("interface", {"noSlip", "frictional", "hydroplaning"});
    if (type == "noSlip")
    {
        iface.type = Interface::Type::noSlip;
        for (const char* k : {"s_b", "C_F", "rhoWater"})
            if (d.found(k)) d.fail(k, "not used with interface noSlip");
    }
    else if (type == "frictional")
    {
        iface.type = Interface::Type::frictional;
        iface.s_b = d.getScalarInRange("s_b", 0.0, 1e8, true, true, "basal shear strength s_b [Pa]");
        for (const char* k : {"C_F", "rhoWater"})
            if (d.found(k)) d.fail(k, "not used with interface frictional");
    }
    else
    {
        iface.type = Interface::Type::hydroplaning;
        iface.C_F = d.getScalarInRange("C_F", 0.0, 1.0, false, true, "drag coefficient C_F");
        iface.rhoWater = d.found("rhoWater")
            ? d.getScalarInRange("rhoWater", 0.0, 1e5, false, true, "water density [kg/m3]")
            : 1000.0;
        if (d.found("s_b")) d.fail("s_b", "not used with interface hydroplaning (s_b = 0.5 rhoWater C_F V^2)");
    }
    return base;
}

rheology::HerschelBulkleyRemoulding readRheology(const Dictionary& d)
{
    d.checkKnownKeys({"model", "s_uo", "eta", "n", "gdotRef", "deltaRem", "xi95"});
    d.getWordOneOf("model", {"HerschelBulkleyRemoulding"});
    rheology::HerschelBulkleyRemoulding m;
    m.s_uo = d.getScalar("s_uo");
    m.eta = d.getScalar("eta");
    // n and gdotRef matter only with a rate effect; remoulding parameters only with softening.
    m.n = (m.eta != 0.0 || d.found("n")) ? d.getScalar("n") : 1.0;
    m.gdotRef = (m.eta != 0.0 || d.found("gdotRef")) ? d.getScalar("gdotRef") : 1.0;
    m.deltaRem = d.getScalar("deltaRem");
    const bool softening = m.deltaRem > 0.0 && m.deltaRem < 1.0;
    m.xi95 = (softening || d.found("xi95")) ? d.getScalar("xi95") : 1.0;
    const rheology::ParameterProblem p = rheology::checkParameters(m);
    if (!p.empty()) d.fail(p.key, p.message);
    return m;
}

Ambient readAmbient(const Dictionary& d)
{
    d.checkKnownKeys({"phase", "density", "viscosity"});
    Ambient a;
    const std::string phase = d.getWordOneOf("phase", {"light", "water"});
    a.phase = phase == "water" ? Ambient::Phase::water : Ambient::Phase::light;
    a.density = d.found("density")
        ? d.getScalarInRange("density", 0.0, 1e5, false, true, "ambient density [kg/m3]")
        : (a.phase == Ambient::Phase::water ? 1000.0 : 1.0);
    a.viscosity = d.found("viscosity")
        ? d.getScalarInRange("viscosity", 0.0, 1e6, false, true, "ambient dynamic viscosity [Pa s]")
        : (a.phase == Ambient::Phase::water ? 1e-3 : 1.8e-5);
    return a;
}

std::vector<Site> readSites(const Dictionary& d, const BaseProfile& base)
{
    // One particle reduction a step per site in slideMPM: a few dozen are plenty for a crossing survey.
    constexpr std::size_t maxSites = 32;
    std::vector<Site> sites;
    for (const Dictionary::Entry& e : d.entries())
    {
        if (!e.dict)
        {
            d.fail(e.key, "a site is a sub-dictionary: " + e.key + " { position <arc length along the base [m]>; }");
        }
        const Dictionary& sd = *e.dict;
        sd.checkKnownKeys({"position"});
        Site site;
        site.name = e.key;
        site.position = sd.getScalarInRange("position", -1e7, 1e7, true, true,
                                            "arc length along the base [m]");
        if (!base.isPlanar() && (site.position < 0.0 || site.position > base.length()))
        {
            sd.fail("position", "the site at " + std::to_string(site.position)
                    + " m does not lie on the base polyline [0, " + std::to_string(base.length()) + "] m");
        }
        sites.push_back(site);
    }
    if (sites.size() > maxSites)
    {
        d.fail(sites[maxSites].name, "more than " + std::to_string(maxSites) + " sites");
    }
    return sites;
}

RunControl readControl(const Dictionary& d)
{
    RunControl c;
    if (d.found("startFrom"))
    {
        c.startFromLatest = d.getWordOneOf("startFrom", {"startTime", "latestTime"}) == "latestTime";
    }
    c.startTime = d.getScalar("startTime", 0.0);
    if (c.startTime < 0.0) d.fail("startTime", "must be >= 0");
    c.endTime = d.getScalar("endTime");
    if (c.endTime <= c.startTime)
    {
        d.fail("endTime", "end time " + std::to_string(c.endTime) + " s is not after the start time "
               + std::to_string(c.startTime) + " s");
    }
    if (d.found("writeControl"))
    {
        d.getWordOneOf("writeControl", {"runTime", "adjustableRunTime", "adjustable", "clockTime", "cpuTime",
                                        "timeStep"});
    }
    c.writeInterval = d.getScalar("writeInterval");
    if (c.writeInterval <= 0.0) d.fail("writeInterval", "must be > 0 s");
    c.purgeWrite = d.getLabel("purgeWrite", 0);
    if (c.purgeWrite < 0) d.fail("purgeWrite", "must be >= 0 (0 keeps every write)");
    c.stopAtRest = d.getBool("stopAtRest", true);
    c.restVelocity = d.getScalar("restVelocity", 1e-3);
    if (c.restVelocity <= 0.0) d.fail("restVelocity", "must be > 0 m/s");
    return c;
}

} // namespace


double SlideGeometry::thickness(double s) const
{
    if (shape == Shape::rectangle)
    {
        return (s >= rearPosition && s <= frontPosition()) ? height : 0.0;
    }
    if (s < profileS.front() || s > profileS.back()) return 0.0;
    std::size_t i = 1;
    while (i + 1 < profileS.size() && s > profileS[i]) ++i;
    const double w = (s - profileS[i - 1])/(profileS[i] - profileS[i - 1]);
    return profileH[i - 1] + w*(profileH[i] - profileH[i - 1]);
}

double SlideGeometry::area() const
{
    if (shape == Shape::rectangle) return length*height;
    double a = 0.0;
    for (std::size_t i = 1; i < profileS.size(); ++i)
    {
        a += 0.5*(profileH[i] + profileH[i - 1])*(profileS[i] - profileS[i - 1]);
    }
    return a;
}

double Interface::basalStrength(double V) const
{
    switch (type)
    {
        case Type::frictional: return s_b;
        case Type::hydroplaning: return rheology::hydroplaningResistance(rhoWater, C_F, V);
        default: return HUGE_VAL;
    }
}

std::string Interface::typeName() const
{
    switch (type)
    {
        case Type::frictional: return "frictional";
        case Type::hydroplaning: return "hydroplaning";
        default: return "noSlip";
    }
}

Scene Scene::read(const std::string& caseDir)
{
    const FloatingPointTrapsOff noTraps;
    const std::string dir = caseDir.empty() ? "." : caseDir;
    const Dictionary d = Dictionary::readFile(joinPath(dir, sceneFile()));
    const Dictionary c = Dictionary::readFile(joinPath(dir, controlFile()));
    return fromDictionaries(d, c, dir);
}

Scene Scene::fromDictionaries(const Dictionary& d, const Dictionary& c, const std::string& caseDir)
{
    const FloatingPointTrapsOff noTraps;
    Scene sc;
    sc.caseDir = caseDir.empty() ? "." : caseDir;
    sc.caseName = baseName(sc.caseDir);

    d.checkKnownKeys({"FoamFile", "title", "slide", "rheology", "base", "ambient", "g", "sites"});
    sc.title = d.getWord("title", sc.caseName);
    sc.g = d.getScalarInRange("g", 0.0, 100.0, false, true, "gravitational acceleration [m/s2]");
    sc.base = readBase(d.subDict("base"), sc.interface);
    sc.slide = readSlide(d.subDict("slide"), sc.base);
    sc.rheology = readRheology(d.subDict("rheology"));
    if (d.found("ambient")) sc.ambient = readAmbient(d.subDict("ambient"));
    if (sc.ambient.density >= sc.slide.density)
    {
        d.subDict("ambient").fail("density", "the ambient phase must be lighter than the slide ("
                                  + std::to_string(sc.slide.density) + " kg/m3)");
    }

    if (d.found("sites")) sc.sites = readSites(d.subDict("sites"), sc.base);

    sc.control = readControl(c);
    return sc;
}

Dictionary readMethodDict(const std::string& caseDir, const std::string& name)
{
    const std::string path = joinPath(caseDir.empty() ? "." : caseDir, "system/" + name);
    std::ifstream probe(path);
    if (!probe) return Dictionary::parse("", path);
    return Dictionary::readFile(path);
}

namespace
{

// Integrates f(s, h) ds over the slide's extent on the base: a midpoint rule fine enough that a
// profile's or a polyline's kinks cost under 1e-6 of the result.
template<class F>
double overSlide(const Scene& sc, F f)
{
    const SlideGeometry& sl = sc.slide;
    const bool rect = sl.shape == SlideGeometry::Shape::rectangle;
    const double s0 = rect ? sl.rearPosition : sl.profileS.front();
    const double s1 = rect ? sl.frontPosition() : sl.profileS.back();
    const int n = rect && sc.base.isPlanar() ? 1 : 20000;
    const double ds = (s1 - s0)/n;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
    {
        const double s = s0 + (i + 0.5)*ds;
        const double h = sl.thickness(s);
        if (h > 0.0) sum += f(s, h)*ds;
    }
    return sum;
}

} // namespace

double Scene::rigidSlabResistance() const
{
    const double atRest = std::min(rheology.strength(0.0, 0.0), interface.basalStrength(0.0));
    return atRest*overSlide(*this, [](double, double) { return 1.0; });
}

double Scene::rigidSlabDriving() const
{
    const double rhoG = slide.density*g;
    return overSlide(*this, [&](double s, double h) { return rhoG*h*std::sin(base.angle(s)); });
}

double Scene::rigidSlabFactorOfSafety() const
{
    const double driving = rigidSlabDriving();
    return driving > 0.0 ? rigidSlabResistance()/driving : HUGE_VAL;
}

double Scene::strengthOverWeightStress() const
{
    return rheology.s_uo/(slide.density*g*slide.height);
}

bool Scene::slidesFreelyStrongerThan(const double ratio) const
{
    return interface.type != Interface::Type::noSlip && rigidSlabFactorOfSafety() < 1.0
        && strengthOverWeightStress() > ratio;
}

std::string Scene::describe() const
{
    std::ostringstream os;
    os << "Scene: " << title << '\n'
       << "    slide  " << slide.length << " m x " << slide.height << " m, rho' " << slide.density << " kg/m3"
       << (slide.rearWall ? ", held by a rear wall" : "") << '\n'
       << "    Eq. (1): s_uo " << rheology.s_uo << " Pa, eta " << rheology.eta << ", n " << rheology.n
       << ", gdotRef " << rheology.gdotRef << " 1/s, deltaRem " << rheology.deltaRem;
    if (rheology.deltaRem < 1.0) os << ", xi95 " << rheology.xi95;
    os << "\n    base   " << (base.isPlanar() ? "planar" : "polyline") << ", interface " << interface.typeName();
    if (interface.type == Interface::Type::frictional) os << ", s_b " << interface.s_b << " Pa";
    if (interface.type == Interface::Type::hydroplaning) os << ", C_F " << interface.C_F;
    {
        const double fs = rigidSlabFactorOfSafety();
        const std::streamsize precision = os.precision(3);
        os << "\n    as a rigid slab: strength at rest along its base " << rigidSlabResistance()/1e3
           << " kN/m, weight along the base " << rigidSlabDriving()/1e3 << " kN/m, factor of safety ";
        if (std::isfinite(fs)) os << fs; else os << "infinite";
        os.precision(precision);
        os << (fs > 1.0 ? " (it would not slide as one body: only its faces' collapse or a progressive failure"
                          " can move it)" : "");
    }
    if (!sites.empty())
    {
        os << "\n    sites ";
        for (const Site& st : sites) os << ' ' << st.name << " at " << st.position << " m";
    }
    return os.str();
}

std::string readSetting(const Dictionary& dict, const std::string& overrideSetting,
                        const std::vector<std::string>& allowed, const std::string& deflt)
{
    if (overrideSetting.empty()) return dict.getWordOneOf("setting", allowed, deflt);
    for (const std::string& a : allowed) if (a == overrideSetting) return a;
    std::string list;
    for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
    throw InputError("-setting", 0, "setting", "'" + overrideSetting + "' is not one of: " + list);
}

} // namespace scene
} // namespace slide
