#include "meshLayout.H"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace slide
{
namespace cfd
{

namespace
{
std::string num(double v)
{
    std::ostringstream os;
    os << std::setprecision(12) << v;
    return os.str();
}
}

MeshLayout MeshLayout::build(const scene::Scene& sc, const CfdControls& c, const double behind, const double reach)
{
    MeshLayout m;
    const double H0 = sc.slide.height;
    const double dx = H0/c.cellsPerHeight;
    const double sRear = sc.slide.frontPosition() - sc.slide.length;
    m.depth_ = dx;
    // Whole cells from the rear, so that a rectangle's edges fall on cell faces.
    const int nBehind = int(std::ceil(behind/dx - 1e-9));
    const int nSlide = int(std::ceil(sc.slide.length/dx - 1e-9));
    const int nAhead = int(std::ceil(reach/dx - 1e-9));
    const double s0 = sRear - nBehind*dx, s1 = sRear + (nSlide + nAhead)*dx;
    m.nx_ = nBehind + nSlide + nAhead;

    m.levels_ = {0.0};
    if (c.baseRefinement > 1)
    {
        // n graded cells from dx/r to dx at a ratio q = r^(1/(n-1)) <= baseGrowth.
        const double r = c.baseRefinement;
        m.nGraded_ = int(std::ceil(std::log(r)/std::log(c.baseGrowth) - 1e-9)) + 1;
        const double q = std::pow(r, 1.0/(m.nGraded_ - 1));
        m.gradedHeight_ = dx/r*(std::pow(q, m.nGraded_) - 1.0)/(q - 1.0);
        m.refinement_ = r;
        m.levels_.push_back(m.gradedHeight_);
        m.rows_.push_back(m.nGraded_);
    }
    auto uniformRows = [&](double height) { return std::max(1, int(std::ceil((height - m.gradedHeight_)/dx - 1e-9))); };
    const int nUniform = uniformRows(c.heightRatio*H0);
    const int nLower = uniformRows(c.aheadHeightRatio*H0);
    // The lower top starts aheadHeightFrom (default H0) ahead of the initial front, on a cell face.
    const int nStepAhead = std::min(nAhead, c.aheadHeightFrom < 0.0 ? c.cellsPerHeight
                                                                    : int(std::ceil(c.aheadHeightFrom/dx - 1e-9)));
    const bool lowerTop = nLower < nUniform && nStepAhead < nAhead;
    const double sStep = sRear + (nSlide + nStepAhead)*dx;
    if (lowerTop)
    {
        m.levels_.push_back(m.gradedHeight_ + nLower*dx);
        m.rows_.push_back(nLower);
    }
    m.levels_.push_back(m.gradedHeight_ + nUniform*dx);
    m.rows_.push_back(lowerTop ? nUniform - nLower : nUniform);
    const int nLayers = static_cast<int>(m.rows_.size());

    // Vertex columns along the base: its ends, the polyline's kinks and the lower top's start.
    std::vector<double> s = {s0};
    if (!sc.base.isPlanar())
    {
        for (int k = 1; k < sc.base.nSegments(); ++k)
        {
            const double kink = sc.base.segmentStart(k);
            if (kink > s0 + 0.5*dx && kink < s1 - 0.5*dx) s.push_back(kink);
        }
    }
    if (lowerTop)
    {
        // A kink within half a cell of the step takes its place.
        bool near = false;
        for (double v : s) near = near || std::fabs(v - sStep) < 0.5*dx;
        if (!near) s.push_back(sStep);
        std::sort(s.begin(), s.end());
    }
    s.push_back(s1);

    m.polyline_ = !sc.base.isPlanar();
    double steepest = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k)
    {
        if (m.polyline_)
        {
            const scene::Point2 p = sc.base.point(s[k]);
            m.x_.push_back(p.x);
            m.yBase_.push_back(p.z);
        }
        else
        {
            // Planar: x along the base from arc length 0, y normal to it.
            m.x_.push_back(s[k]);
            m.yBase_.push_back(0.0);
        }
        if (k + 1 < s.size())
        {
            const int n = m.polyline_ ? std::max(1, int(std::lround((s[k + 1] - s[k])/dx)))
                                      : int(std::lround((s[k + 1] - s[k])/dx));
            m.nSegment_.push_back(n);
            m.nLayersOver_.push_back(lowerTop && s[k] >= sStep - 0.5*dx ? nLayers - 1 : nLayers);
            if (m.polyline_) steepest = std::max(steepest, std::fabs(sc.base.angle(0.5*(s[k] + s[k + 1]))));
        }
    }
    if (m.polyline_)
    {
        m.nx_ = 0;
        for (int n : m.nSegment_) m.nx_ += n;
        m.verticalScale_ = 1.0/std::cos(steepest);
    }
    return m;
}

long long MeshLayout::nCells() const
{
    long long n = 0;
    for (std::size_t k = 0; k < nSegment_.size(); ++k)
    {
        for (int l = 0; l < nLayersOver_[k]; ++l) n += static_cast<long long>(nSegment_[k])*rows_[l];
    }
    return n;
}

std::string MeshLayout::describe() const
{
    std::ostringstream os;
    int ny = 0;
    for (int r : rows_) ny += r;
    os << nCells() << " cells of " << depth_ << " m, " << nx_ << " along the base, up to " << ny << " across";
    if (nGraded_ > 0)
    {
        os << " (" << nGraded_ << " graded rows from " << depth_/refinement_ << " m on the base up to "
           << gradedHeight_ << " m)";
    }
    const double height = levels_.back();
    if (polyline_)
    {
        os << ", vertical columns over " << nSegment_.size() << " stretches of the polyline, x in [" << x_.front()
           << ", " << x_.back() << "] m, " << height*verticalScale_ << " m high (vertically)";
    }
    else
    {
        os << ", x in [" << x_.front() << ", " << x_.back() << "] m along the base, height " << height << " m";
    }
    for (std::size_t k = 0; k < nSegment_.size(); ++k)
    {
        if (nLayersOver_[k] < static_cast<int>(rows_.size()))
        {
            os << ", " << levels_[nLayersOver_[k]] << " m high from x = " << x_[k] << " m on";
            break;
        }
    }
    return os.str();
}

std::vector<double> MeshLayout::rowFaceHeights() const
{
    std::vector<double> y = {0.0};
    for (int j = 0; j < nGraded_; ++j)
    {
        const double q = nGraded_ > 1 ? std::pow(refinement_, 1.0/(nGraded_ - 1)) : 1.0;
        y.push_back(y.back() + depth_/refinement_*std::pow(q, j));
    }
    for (std::size_t l = nGraded_ > 0 ? 1 : 0; l < rows_.size(); ++l)
    {
        const double h = (levels_[l + 1] - levels_[l])/rows_[l];
        for (int j = 1; j <= rows_[l]; ++j) y.push_back(levels_[l] + j*h);
    }
    return y;
}

std::vector<double> MeshLayout::slideFraction(const scene::Scene& sc, double* area) const
{
    double total = 0.0;
    // blockMesh's cell order: block by block (layer, then stretch of the base), in each x fastest, then y.
    std::vector<double> alpha;
    alpha.reserve(static_cast<std::size_t>(nCells()));
    const std::vector<double> faces = rowFaceHeights();
    // Slide coordinates (arc length s, height h normal to the base) of a point of
    // stretch k at fraction f along it and height y above the base.
    auto slideCoordinates = [&](std::size_t k, double f, double y, double& s, double& h)
    {
        const double X = x_[k] + f*(x_[k + 1] - x_[k]);
        s = X;
        h = y;   // planar: x is the arc length, y the height
        if (polyline_)
        {
            const double Y = yBase_[k] + f*(yBase_[k + 1] - yBase_[k]) + y*verticalScale_;
            sc.base.coordinates(X, Y, s, h);
        }
    };
    auto inside = [&](std::size_t k, double f, double y)
    {
        double s, h;
        slideCoordinates(k, f, y, s, h);
        return h > 0.0 && h < sc.slide.thickness(s);
    };
    // Samples along and across a cut cell: on a planar base the share of each of
    // nAlong verticals inside is exact; over a polyline's sheared columns nAcross
    // points per vertical resolve it to a 64th of the cell.
    constexpr int nAlong = 8, nAcross = 64;
    const int nLayers = static_cast<int>(rows_.size());
    for (int l = 0, j0 = 0; l < nLayers; j0 += rows_[l], ++l)
    {
        for (std::size_t k = 0; k < nSegment_.size(); ++k)
        {
            if (l >= nLayersOver_[k]) continue;
            const int n = nSegment_[k];
            for (int j = j0; j < j0 + rows_[l]; ++j)
            {
                const double y0 = faces[j], y1 = faces[j + 1];
                for (int i = 0; i < n; ++i)
                {
                    const double f0 = double(i)/n, f1 = double(i + 1)/n;
                    const bool corner = inside(k, f0, y0);
                    // A sheared column's cell has the area of its unsheared rectangle.
                    const double cellArea = (x_[k + 1] - x_[k])/n*(y1 - y0)*(polyline_ ? verticalScale_ : 1.0);
                    if (corner == inside(k, f1, y0) && corner == inside(k, f0, y1) && corner == inside(k, f1, y1)
                        && corner == inside(k, 0.5*(f0 + f1), 0.5*(y0 + y1)))
                    {
                        alpha.push_back(corner ? 1.0 : 0.0);
                        total += corner ? cellArea : 0.0;
                        continue;
                    }
                    double share = 0.0;
                    for (int a = 0; a < nAlong; ++a)
                    {
                        const double f = f0 + (a + 0.5)/nAlong*(f1 - f0);
                        if (!polyline_)
                        {
                            double s, h;
                            slideCoordinates(k, f, 0.0, s, h);
                            const double top = sc.slide.thickness(s);
                            share += std::clamp((top - y0)/(y1 - y0), 0.0, 1.0);
                            continue;
                        }
                        int in = 0;
                        for (int b = 0; b < nAcross; ++b) in += inside(k, f, y0 + (b + 0.5)/nAcross*(y1 - y0));
                        share += double(in)/nAcross;
                    }
                    // A surface on a row face, which the rows' summed heights miss by round-off, cuts nothing.
                    double a = share/nAlong;
                    a = a < 1e-9 ? 0.0 : (a > 1.0 - 1e-9 ? 1.0 : a);
                    alpha.push_back(a);
                    total += a*cellArea;
                }
            }
        }
    }
    if (area) *area = total;
    return alpha;
}

std::string MeshLayout::blockMeshDict(const std::string& rearType, const std::string& topType) const
{
    const int nCol = static_cast<int>(x_.size());
    const int nStretch = nCol - 1;
    const int nLayers = static_cast<int>(rows_.size());
    // Vertex (level, column, side): side 0 at z = 0, 1 at z = depth. Every level
    // has every column; blockMesh ignores the ones no block uses (above a lower top).
    auto v = [&](int l, int k, int side) { return std::to_string(2*(l*nCol + k) + side); };
    std::ostringstream os;
    os << "scale 1;\n\nvertices\n(\n";
    for (double h : levels_)
    {
        for (int k = 0; k < nCol; ++k)
        {
            const double y = yBase_[k] + h*verticalScale_;
            os << "    (" << num(x_[k]) << " " << num(y) << " 0) (" << num(x_[k]) << " " << num(y) << " "
               << num(depth_) << ")\n";
        }
    }
    os << ");\n\nblocks\n(\n";
    for (int l = 0; l < nLayers; ++l)
    {
        const bool graded = nGraded_ > 0 && l == 0;
        for (int k = 0; k < nStretch; ++k)
        {
            if (l >= nLayersOver_[k]) continue;
            os << "    hex (" << v(l, k, 0) << " " << v(l, k + 1, 0) << " " << v(l + 1, k + 1, 0) << " "
               << v(l + 1, k, 0) << " " << v(l, k, 1) << " " << v(l, k + 1, 1) << " " << v(l + 1, k + 1, 1) << " "
               << v(l + 1, k, 1) << ") (" << nSegment_[k] << " " << rows_[l]
               << " 1) simpleGrading (1 " << num(graded ? refinement_ : 1.0) << " 1)\n";
        }
    }
    // A side face between levels la and lb at column ka/kb, outward by argument order.
    auto face = [&](int la, int ka, int lb, int kb)
    {
        return " (" + v(la, ka, 0) + " " + v(la, ka, 1) + " " + v(lb, kb, 1) + " " + v(lb, kb, 0) + ")";
    };
    std::string base, top, up, down, sides;
    for (int k = 0; k < nStretch; ++k)
    {
        base += face(0, k, 0, k + 1);
        top += face(nLayersOver_[k], k + 1, nLayersOver_[k], k);
        for (int l = 0; l < nLayersOver_[k]; ++l)
        {
            sides += " (" + v(l, k, 0) + " " + v(l + 1, k, 0) + " " + v(l + 1, k + 1, 0) + " " + v(l, k + 1, 0)
                     + ") (" + v(l, k, 1) + " " + v(l, k + 1, 1) + " " + v(l + 1, k + 1, 1) + " " + v(l + 1, k, 1)
                     + ")";
        }
        // The step down to a lower top is part of the top (open or a lid).
        if (k + 1 < nStretch)
        {
            for (int l = nLayersOver_[k + 1]; l < nLayersOver_[k]; ++l) top += face(l, k + 1, l + 1, k + 1);
        }
    }
    for (int l = 0; l < nLayersOver_.front(); ++l) up += face(l + 1, 0, l, 0);
    for (int l = 0; l < nLayersOver_.back(); ++l) down += face(l, nCol - 1, l + 1, nCol - 1);
    os << ");\n\nedges\n(\n);\n\nboundary\n(\n"
       << "    base\n    {\n        type wall;\n        faces (" << base << " );\n    }\n"
       << "    top\n    {\n        type " << topType << ";\n        faces (" << top << " );\n    }\n"
       << "    upslope\n    {\n        type " << rearType << ";\n        faces (" << up << " );\n    }\n"
       << "    downslope\n    {\n        type patch;\n        faces (" << down << " );\n    }\n"
       << "    frontAndBack\n    {\n        type empty;\n        faces (" << sides << " );\n    }\n"
       << ");\n";
    return os.str();
}

} // namespace cfd
} // namespace slide
