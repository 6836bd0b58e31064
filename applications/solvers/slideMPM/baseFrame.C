#include "baseFrame.H"

#include <cmath>
#include <string>

namespace slide
{
namespace mpm
{

BasalContact basalContact(const scene::Interface& in)
{
    BasalContact c;
    c.type = in.type == scene::Interface::Type::noSlip ? BasalContact::Type::noSlip
           : in.type == scene::Interface::Type::frictional ? BasalContact::Type::frictional
           : BasalContact::Type::hydroplaning;
    c.s_b = in.s_b;
    c.rhoWater = in.rhoWater;
    c.C_F = in.C_F;
    return c;
}

BaseFrame BaseFrame::fromScene(const scene::Scene& sc)
{
    BaseFrame f;
    const scene::BaseProfile& base = sc.base;
    if (base.isPlanar())
    {
        f.angle = base.angle(0.0);
        const scene::Point2 o = base.point(0.0);
        f.originX = o.x;
        f.originZ = o.z;
        f.level = BaseLevelSet();
        f.level.s[0] = -1.0;   // the frame x is the arc length
        f.level.s[1] = 1.0;
    }
    else
    {
        const std::vector<scene::Point2>& v = base.vertices();
        if (static_cast<int>(v.size()) > BaseLevelSet::maxVertices)
        {
            throw scene::InputError(scene::Scene::sceneFile(), 0, "base.points",
                "slideMPM takes at most " + std::to_string(BaseLevelSet::maxVertices) + " base vertices, got "
                + std::to_string(v.size()));
        }
        f.originX = v.front().x;
        f.originZ = v.front().z;
        f.angle = std::atan2(v.front().z - v.back().z, v.back().x - v.front().x);
        f.level.n = static_cast<int>(v.size());
        for (int k = 0; k < f.level.n; ++k)
        {
            f.toFrame(v[k].x, v[k].z, f.level.x[k], f.level.y[k]);
            f.level.s[k] = k < base.nSegments() ? base.segmentStart(k) : base.length();
            if (k > 0 && !(f.level.x[k] > f.level.x[k - 1]))
            {
                throw scene::InputError(scene::Scene::sceneFile(), 0, "base.points",
                    "the base turns back on itself in the frame of its chord (vertex " + std::to_string(k)
                    + "): slideMPM needs a base that is a function of the downslope distance");
            }
        }
    }
    f.gravityX = sc.g*std::sin(f.angle);
    f.gravityY = -sc.g*std::cos(f.angle);
    f.rearWall = sc.slide.rearWall;
    const scene::Point2 rear = base.point(sc.slide.rearPosition);
    double yr;
    f.toFrame(rear.x, rear.z, f.rearX, yr);
    return f;
}

void BaseFrame::toGlobal(double xf, double yf, double& X, double& Z) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    X = originX + xf*c + yf*s;
    Z = originZ - xf*s + yf*c;
}

void BaseFrame::toFrame(double X, double Z, double& xf, double& yf) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    const double dx = X - originX, dz = Z - originZ;
    xf = dx*c - dz*s;
    yf = dx*s + dz*c;
}

void BaseFrame::vectorToGlobal(double vx, double vy, double& VX, double& VZ) const
{
    const double c = std::cos(angle), s = std::sin(angle);
    VX = vx*c + vy*s;
    VZ = -vx*s + vy*c;
}

} // namespace mpm
} // namespace slide
