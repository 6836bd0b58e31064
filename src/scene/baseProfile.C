#include "baseProfile.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace slide
{
namespace scene
{

BaseProfile BaseProfile::planar(double angleDeg)
{
    BaseProfile b;
    b.planar_ = true;
    b.angle_ = angleDeg*M_PI/180.0;
    const Point2 o{0.0, 0.0};
    b.vertices_ = {o};
    b.s_ = {0.0};
    return b;
}

BaseProfile BaseProfile::polyline(const std::vector<Point2>& vertices)
{
    BaseProfile b;
    b.planar_ = false;
    b.vertices_ = vertices;
    b.s_.resize(vertices.size(), 0.0);
    for (std::size_t i = 1; i < vertices.size(); ++i)
    {
        b.s_[i] = b.s_[i - 1] + std::hypot(vertices[i].x - vertices[i - 1].x, vertices[i].z - vertices[i - 1].z);
    }
    return b;
}

int BaseProfile::segmentAtS(double s) const
{
    if (planar_) return 0;
    const int last = static_cast<int>(s_.size()) - 2;
    // The segment [s_i, s_{i+1}) that holds s; the end segments extend to infinity.
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    const int i = static_cast<int>(it - s_.begin()) - 1;
    return std::max(0, std::min(i, last));
}

int BaseProfile::segmentAtX(double x) const
{
    if (planar_) return 0;
    const int last = static_cast<int>(vertices_.size()) - 2;
    int i = 0;
    while (i < last && x >= vertices_[i + 1].x) ++i;
    return i;
}

Point2 BaseProfile::tangent(double s) const
{
    if (planar_) return {std::cos(angle_), -std::sin(angle_)};
    const int i = segmentAtS(s);
    const double l = s_[i + 1] - s_[i];
    return {(vertices_[i + 1].x - vertices_[i].x)/l, (vertices_[i + 1].z - vertices_[i].z)/l};
}

Point2 BaseProfile::normal(double s) const
{
    const Point2 t = tangent(s);
    return {-t.z, t.x};
}

double BaseProfile::angle(double s) const
{
    const Point2 t = tangent(s);
    return std::atan2(-t.z, t.x);
}

Point2 BaseProfile::point(double s) const
{
    if (planar_) return {s*std::cos(angle_), -s*std::sin(angle_)};
    const int i = segmentAtS(s);
    const Point2 t = tangent(s);
    const double ds = s - s_[i];
    return {vertices_[i].x + ds*t.x, vertices_[i].z + ds*t.z};
}

double BaseProfile::elevation(double x) const
{
    if (planar_) return -x*std::tan(angle_);
    const int i = segmentAtX(x);
    const Point2& a = vertices_[i];
    const Point2& b = vertices_[i + 1];
    return a.z + (b.z - a.z)*(x - a.x)/(b.x - a.x);
}

std::string BaseProfile::pastEndWarning(const double sRear, const double sFront, const double t) const
{
    if (planar_ || (sFront <= length() && sRear >= 0.0)) return "";
    std::ostringstream os;
    os << "Warning: at t = " << t << " s the slide passed the " << (sFront > length() ? "last" : "first")
       << " vertex of the base polyline (constant/sceneProperties, base.points); its end segment is extended in a "
       << "straight line: lengthen the polyline if that is not the terrain";
    return os.str();
}

double BaseProfile::arcLengthAtX(double x) const
{
    if (planar_) return x/std::cos(angle_);
    const int i = segmentAtX(x);
    const Point2& a = vertices_[i];
    const Point2& b = vertices_[i + 1];
    return s_[i] + (x - a.x)/(b.x - a.x)*(s_[i + 1] - s_[i]);
}

void BaseProfile::coordinates(const double X, const double Z, double& s, double& h) const
{
    if (isPlanar())
    {
        const Point2 o = point(0.0), t = tangent(0.0), n = normal(0.0);
        s = (X - o.x)*t.x + (Z - o.z)*t.z;
        h = (X - o.x)*n.x + (Z - o.z)*n.z;
        return;
    }
    double best = std::numeric_limits<double>::max();
    for (int k = 0; k < nSegments(); ++k)
    {
        const double s0 = segmentStart(k);
        const double s1 = k + 1 < nSegments() ? segmentStart(k + 1) : length();
        const Point2 o = point(s0), t = tangent(0.5*(s0 + s1)), n = normal(0.5*(s0 + s1));
        double u = (X - o.x)*t.x + (Z - o.z)*t.z;
        const double lo = k == 0 ? -1e300 : 0.0, hi = k + 1 == nSegments() ? 1e300 : s1 - s0;
        u = std::min(std::max(u, lo), hi);
        const double px = o.x + u*t.x, pz = o.z + u*t.z;
        const double dd = std::hypot(X - px, Z - pz);
        if (dd < best)
        {
            best = dd;
            s = s0 + u;
            h = (X - o.x)*n.x + (Z - o.z)*n.z;
        }
    }
}

} // namespace scene
} // namespace slide
