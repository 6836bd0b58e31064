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
    m.x_ = {sRear - nBehind*dx, sRear + (nSlide + nAhead)*dx};
    m.nx_ = nBehind + nSlide + nAhead;
    const double wanted = c.heightRatio*H0;
    if (c.baseRefinement > 1)
    {
        // n graded cells from dx/r to dx at a ratio q = r^(1/(n-1)) <= baseGrowth.
        const double r = c.baseRefinement;
        m.nGraded_ = int(std::ceil(std::log(r)/std::log(c.baseGrowth) - 1e-9)) + 1;
        const double q = std::pow(r, 1.0/(m.nGraded_ - 1));
        m.gradedHeight_ = dx/r*(std::pow(q, m.nGraded_) - 1.0)/(q - 1.0);
        m.refinement_ = r;
    }
    const int nUniform = std::max(1, int(std::ceil((wanted - m.gradedHeight_)/dx - 1e-9)));
    m.ny_ = m.nGraded_ + nUniform;
    m.height_ = m.gradedHeight_ + nUniform*dx;
    if (!sc.base.isPlanar())
    {
        // Vertex columns at the mesh's ends and at the kinks between them; each
        // stretch gets whole cells of about dx along the base.
        m.polyline_ = true;
        const double s0 = m.x_[0], s1 = m.x_[1];
        std::vector<double> s = {s0};
        for (int k = 1; k < sc.base.nSegments(); ++k)
        {
            const double kink = sc.base.segmentStart(k);
            if (kink > s0 + 0.5*dx && kink < s1 - 0.5*dx) s.push_back(kink);
        }
        s.push_back(s1);
        m.x_.clear();
        m.nx_ = 0;
        double steepest = 0.0;
        for (std::size_t k = 0; k < s.size(); ++k)
        {
            const scene::Point2 p = sc.base.point(s[k]);
            m.x_.push_back(p.x);
            m.yBase_.push_back(p.z);
            if (k + 1 < s.size())
            {
                const int n = std::max(1, int(std::lround((s[k + 1] - s[k])/dx)));
                m.nSegment_.push_back(n);
                m.nx_ += n;
                steepest = std::max(steepest, std::fabs(sc.base.angle(0.5*(s[k] + s[k + 1]))));
            }
        }
        m.verticalScale_ = 1.0/std::cos(steepest);
    }
    return m;
}

long long MeshLayout::nCells() const
{
    return static_cast<long long>(nx_)*ny_;
}

std::string MeshLayout::describe() const
{
    std::ostringstream os;
    os << nx_ << " x " << ny_ << " = " << nCells() << " cells of " << depth_ << " m";
    if (nGraded_ > 0)
    {
        os << " (" << nGraded_ << " graded rows from " << depth_/refinement_ << " m on the base up to "
           << gradedHeight_ << " m)";
    }
    if (polyline_)
    {
        os << ", vertical columns over " << nSegment_.size() << " stretches of the polyline, x in [" << x_.front()
           << ", " << x_.back() << "] m, " << height_*verticalScale_ << " m high (vertically)";
    }
    else
    {
        os << ", x in [" << x_[0] << ", " << x_[1] << "] m along the base, height " << height_ << " m";
    }
    return os.str();
}

std::vector<double> MeshLayout::layerLevels() const
{
    std::vector<double> levels = {0.0};
    if (nGraded_ > 0) levels.push_back(gradedHeight_);
    levels.push_back(height_);
    return levels;
}

int MeshLayout::layerRows(const int layer) const
{
    return nGraded_ > 0 && layer == 0 ? nGraded_ : ny_ - nGraded_;
}

std::string MeshLayout::blockMeshDict(const std::string& rearType) const
{
    if (polyline_) return polylineBlockMeshDict(rearType);
    // Vertices by level (bottom up), four per level: (x0, y, 0) (x1, y, 0) (x1, y, d) (x0, y, d).
    const std::vector<double> levels = layerLevels();
    std::ostringstream os;
    os << "scale 1;\n\nvertices\n(\n";
    for (double y : levels)
    {
        os << "    (" << num(x_[0]) << " " << num(y) << " 0) (" << num(x_[1]) << " " << num(y) << " 0) ("
           << num(x_[1]) << " " << num(y) << " " << num(depth_) << ") (" << num(x_[0]) << " " << num(y) << " "
           << num(depth_) << ")\n";
    }
    // Block k spans levels k and k+1; hex order: bottom face (0 1 top-1 top-0), then its far copy.
    auto v = [](int level, int k) { return 4*level + k; };
    auto hex = [&](int l)
    {
        std::ostringstream h;
        h << "hex (" << v(l, 0) << " " << v(l, 1) << " " << v(l + 1, 1) << " " << v(l + 1, 0) << " " << v(l, 3)
          << " " << v(l, 2) << " " << v(l + 1, 2) << " " << v(l + 1, 3) << ")";
        return h.str();
    };
    auto face = [&](int l, int a, int b) // a side face of block l between vertex columns a and b
    {
        std::ostringstream f;
        f << "(" << v(l, a) << " " << v(l, b) << " " << v(l + 1, b) << " " << v(l + 1, a) << ")";
        return f.str();
    };
    const int nBlocks = int(levels.size()) - 1;
    os << ");\n\nblocks\n(\n";
    for (int l = 0; l < nBlocks; ++l)
    {
        const bool graded = nGraded_ > 0 && l == 0;
        os << "    " << hex(l) << " (" << nx_ << " " << layerRows(l) << " 1) simpleGrading (1 "
           << num(graded ? refinement_ : 1.0) << " 1)\n";
    }
    std::string up, down, sides;
    for (int l = 0; l < nBlocks; ++l)
    {
        up += " " + face(l, 0, 3);
        down += " " + face(l, 1, 2);
        sides += " (" + std::to_string(v(l, 0)) + " " + std::to_string(v(l + 1, 0)) + " " + std::to_string(v(l + 1, 1))
                 + " " + std::to_string(v(l, 1)) + ") (" + std::to_string(v(l, 3)) + " " + std::to_string(v(l, 2))
                 + " " + std::to_string(v(l + 1, 2)) + " " + std::to_string(v(l + 1, 3)) + ")";
    }
    const int t = nBlocks;
    os << ");\n\nedges\n(\n);\n\nboundary\n(\n"
       << "    base\n    {\n        type wall;\n        faces ((0 1 2 3));\n    }\n"
       << "    top\n    {\n        type patch;\n        faces ((" << v(t, 0) << " " << v(t, 3) << " " << v(t, 2) << " "
       << v(t, 1) << "));\n    }\n"
       << "    upslope\n    {\n        type " << rearType << ";\n        faces (" << up << " );\n    }\n"
       << "    downslope\n    {\n        type patch;\n        faces (" << down << " );\n    }\n"
       << "    frontAndBack\n    {\n        type empty;\n        faces (" << sides << " );\n    }\n"
       << ");\n";
    return os.str();
}

std::vector<double> MeshLayout::cellCentreHeights() const
{
    std::vector<double> y;
    double bottom = 0.0;
    for (int j = 0; j < nGraded_; ++j)
    {
        const double q = nGraded_ > 1 ? std::pow(refinement_, 1.0/(nGraded_ - 1)) : 1.0;
        const double h = depth_/refinement_*std::pow(q, j);
        y.push_back(bottom + 0.5*h);
        bottom += h;
    }
    const double h = (height_ - gradedHeight_)/(ny_ - nGraded_);
    for (int j = nGraded_; j < ny_; ++j)
    {
        y.push_back(gradedHeight_ + (j - nGraded_ + 0.5)*h);
    }
    return y;
}

std::vector<double> MeshLayout::slideFraction(const scene::Scene& sc) const
{
    // blockMesh's cell order: block by block (layer, then stretch of the base), in each x fastest, then y.
    std::vector<double> alpha;
    alpha.reserve(static_cast<std::size_t>(nCells()));
    const std::vector<double> heights = cellCentreHeights();
    const int nStretches = polyline_ ? static_cast<int>(nSegment_.size()) : 1;
    const int nLayers = static_cast<int>(layerLevels().size()) - 1;
    for (int l = 0, j0 = 0; l < nLayers; j0 += layerRows(l), ++l)
    {
        for (int k = 0; k < nStretches; ++k)
        {
            const int n = polyline_ ? nSegment_[k] : nx_;
            for (int j = j0; j < j0 + layerRows(l); ++j)
            {
                for (int i = 0; i < n; ++i)
                {
                    const double f = (i + 0.5)/n;
                    const double X = x_[k] + f*(x_[k + 1] - x_[k]);
                    double s = X, h = heights[j];   // planar: x is the arc length, y the height
                    if (polyline_)
                    {
                        const double Y = yBase_[k] + f*(yBase_[k + 1] - yBase_[k]) + heights[j]*verticalScale_;
                        sc.base.coordinates(X, Y, s, h);
                    }
                    alpha.push_back(h > 0.0 && h < sc.slide.thickness(s) ? 1.0 : 0.0);
                }
            }
        }
    }
    return alpha;
}

std::string MeshLayout::polylineBlockMeshDict(const std::string& rearType) const
{
    const std::vector<double> levels = layerLevels();
    const int nCol = static_cast<int>(x_.size());
    // Vertex (level, column, side): side 0 at z = 0, 1 at z = depth.
    auto v = [&](int l, int k, int side) { return std::to_string(2*(l*nCol + k) + side); };
    std::ostringstream os;
    os << "scale 1;\n\nvertices\n(\n";
    for (double h : levels)
    {
        for (int k = 0; k < nCol; ++k)
        {
            const double y = yBase_[k] + h*verticalScale_;
            os << "    (" << num(x_[k]) << " " << num(y) << " 0) (" << num(x_[k]) << " " << num(y) << " "
               << num(depth_) << ")\n";
        }
    }
    const int nLayers = int(levels.size()) - 1;
    os << ");\n\nblocks\n(\n";
    for (int l = 0; l < nLayers; ++l)
    {
        const bool graded = nGraded_ > 0 && l == 0;
        for (int k = 0; k + 1 < nCol; ++k)
        {
            os << "    hex (" << v(l, k, 0) << " " << v(l, k + 1, 0) << " " << v(l + 1, k + 1, 0) << " "
               << v(l + 1, k, 0) << " " << v(l, k, 1) << " " << v(l, k + 1, 1) << " " << v(l + 1, k + 1, 1) << " "
               << v(l + 1, k, 1) << ") (" << nSegment_[k] << " " << layerRows(l)
               << " 1) simpleGrading (1 " << num(graded ? refinement_ : 1.0) << " 1)\n";
        }
    }
    auto face = [&](int la, int ka, int lb, int kb)
    {
        return " (" + v(la, ka, 0) + " " + v(la, ka, 1) + " " + v(lb, kb, 1) + " " + v(lb, kb, 0) + ")";
    };
    std::string base, top, up, down, sides;
    for (int k = 0; k + 1 < nCol; ++k)
    {
        base += face(0, k, 0, k + 1);
        top += face(nLayers, k + 1, nLayers, k);
        for (int l = 0; l < nLayers; ++l)
        {
            sides += " (" + v(l, k, 0) + " " + v(l + 1, k, 0) + " " + v(l + 1, k + 1, 0) + " " + v(l, k + 1, 0)
                     + ") (" + v(l, k, 1) + " " + v(l, k + 1, 1) + " " + v(l + 1, k + 1, 1) + " " + v(l + 1, k, 1)
                     + ")";
        }
    }
    for (int l = 0; l < nLayers; ++l)
    {
        up += face(l + 1, 0, l, 0);
        down += face(l, nCol - 1, l + 1, nCol - 1);
    }
    os << ");\n\nedges\n(\n);\n\nboundary\n(\n"
       << "    base\n    {\n        type wall;\n        faces (" << base << " );\n    }\n"
       << "    top\n    {\n        type patch;\n        faces (" << top << " );\n    }\n"
       << "    upslope\n    {\n        type " << rearType << ";\n        faces (" << up << " );\n    }\n"
       << "    downslope\n    {\n        type patch;\n        faces (" << down << " );\n    }\n"
       << "    frontAndBack\n    {\n        type empty;\n        faces (" << sides << " );\n    }\n"
       << ");\n";
    return os.str();
}

} // namespace cfd
} // namespace slide
