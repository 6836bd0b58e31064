#include "slideColumns.H"

#include <stdexcept>

namespace slide
{
namespace dam
{

double SlideColumns::nodeThickness(int j) const
{
    return nodeArea(j)/nodeBaseLength(j);
}

double SlideColumns::totalArea() const
{
    double a = 0.0;
    for (double v : area) a += v;
    return a;
}

double SlideColumns::massFront(const double share) const
{
    const double behind = share*totalArea();
    double a = 0.0;
    for (int i = 0; i < nColumns(); ++i)
    {
        if (a + area[i] >= behind && area[i] > 0.0)
        {
            return x[i] + (behind - a)/area[i]*(x[i + 1] - x[i]) - initialFront;
        }
        a += area[i];
    }
    return front();
}

SlideColumns SlideColumns::fromScene(const scene::Scene& sc, int columns)
{
    const scene::SlideGeometry& g = sc.slide;
    SlideColumns s;
    const int N = columns;
    const double b = g.length/N;
    s.x.resize(N + 1);
    for (int j = 0; j <= N; ++j) s.x[j] = g.rearPosition + j*b;
    s.area.resize(N);
    for (int i = 0; i < N; ++i)
    {
        // Column mean of the thickness profile (exact for a rectangle; Simpson for a table).
        const double a = s.x[i], c = s.x[i + 1];
        const double h = (g.thickness(a) + 4.0*g.thickness(0.5*(a + c)) + g.thickness(c))/6.0;
        s.area[i] = h*b;
        if (!(s.area[i] > 0.0))
        {
            throw std::runtime_error("column " + std::to_string(i) + " of the initial slide holds no material; "
                                     "trim the zero-thickness ends of the thickness table");
        }
    }
    s.x0 = s.x;
    s.U.assign(N + 1, 0.0);
    s.Up.assign(N + 1, 0.0);
    s.xi.assign(N + 1, 0.0);
    s.shearLayer.assign(N + 1, 0.0);
    s.basalRate.assign(N + 1, 0.0);
    s.regime.assign(N + 1, 0);
    s.rearWall = g.rearWall;
    s.initialFront = s.x.back();
    s.initialLength = g.length;
    s.initialHeight = g.height;
    return s;
}

} // namespace dam
} // namespace slide
