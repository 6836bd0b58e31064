#include "damRestart.H"

#include "restartState.H"

namespace slide
{
namespace dam
{

namespace
{
std::vector<double> toDoubles(const std::vector<int>& v)
{
    return std::vector<double>(v.begin(), v.end());
}
}

void writeState(const std::string& caseDir, const RestartPoint& at, const SlideColumns& s, const FrontSurges& surges)
{
    output::StateFile f;
    at.addTo(f);
    f.add("x", s.x);
    f.add("U", s.U);
    f.add("plugVelocity", s.Up);
    f.add("xi", s.xi);
    f.add("area", s.area);
    f.add("x0", s.x0);
    f.add("shearLayerThickness", s.shearLayer);
    f.add("basalRate", s.basalRate);
    f.add("basalRegime", toDoubles(s.regime));
    f.add("rigidVelocity", s.rigidVelocity);
    f.add("initialFront", s.initialFront);
    f.add("initialLength", s.initialLength);
    f.add("initialHeight", s.initialHeight);
    f.add("frontSurges", static_cast<double>(surges.count));
    f.add("frontRunning", surges.running ? 1.0 : 0.0);
    f.add("frontStalled", surges.stalled ? 1.0 : 0.0);
    f.write(output::statePath(caseDir, at.time, "slideDAM"));
}

RestartPoint readState(const std::string& path, SlideColumns& s, FrontSurges& surges)
{
    const output::StateFile f = output::StateFile::read(path);
    const std::vector<double>& area = f.vector("area");
    if (area.size() != s.area.size())
    {
        throw scene::InputError(path, 0, "area", "the state holds " + std::to_string(area.size())
                                + " columns, system/damDict gives " + std::to_string(s.area.size()));
    }
    auto nodes = [&](const std::string& key)
    {
        const std::vector<double>& v = f.vector(key);
        if (v.size() != s.x.size())
        {
            throw scene::InputError(path, 0, key, "expected " + std::to_string(s.x.size()) + " node values, found "
                                    + std::to_string(v.size()));
        }
        return v;
    };
    s.x = nodes("x");
    s.U = nodes("U");
    s.Up = nodes("plugVelocity");
    s.xi = nodes("xi");
    s.x0 = nodes("x0");
    s.shearLayer = nodes("shearLayerThickness");
    s.basalRate = nodes("basalRate");
    const std::vector<double> regime = nodes("basalRegime");
    s.regime.assign(regime.begin(), regime.end());
    s.area = area;
    s.rigidVelocity = f.scalar("rigidVelocity");
    s.initialFront = f.scalar("initialFront");
    s.initialLength = f.scalar("initialLength");
    s.initialHeight = f.scalar("initialHeight");
    if (f.has("frontSurges"))
    {
        surges.count = static_cast<int>(f.scalar("frontSurges"));
        surges.running = f.scalar("frontRunning") != 0.0;
        surges.stalled = f.scalar("frontStalled") != 0.0;
    }

    return output::RestartClock::readFrom(f);
}

} // namespace dam
} // namespace slide
