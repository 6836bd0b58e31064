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
    m.ny_ = int(std::ceil(c.heightRatio*c.cellsPerHeight - 1e-9));
    m.height_ = m.ny_*dx;
    return m;
}

long long MeshLayout::nCells() const
{
    return static_cast<long long>(nx_)*ny_;
}

std::string MeshLayout::describe() const
{
    std::ostringstream os;
    os << nx_ << " x " << ny_ << " = " << nCells() << " cells of " << depth_ << " m, x in [" << x_[0] << ", "
       << x_[1] << "] m along the base, height " << height_ << " m";
    return os.str();
}

std::string MeshLayout::blockMeshDict(const std::string& rearType) const
{
    std::ostringstream os;
    os << "scale 1;\n\nvertices\n(\n";
    for (double z : {0.0, depth_})
    {
        os << "    (" << num(x_[0]) << " 0 " << num(z) << ")\n    (" << num(x_[1]) << " 0 " << num(z) << ")\n"
           << "    (" << num(x_[1]) << " " << num(height_) << " " << num(z) << ")\n    (" << num(x_[0]) << " "
           << num(height_) << " " << num(z) << ")\n";
    }
    os << ");\n\nblocks\n(\n    hex (0 1 2 3 4 5 6 7) (" << nx_ << " " << ny_ << " 1) simpleGrading (1 1 1)\n);\n\n"
       << "edges\n(\n);\n\nboundary\n(\n"
       << "    base\n    {\n        type wall;\n        faces ((0 1 5 4));\n    }\n"
       << "    top\n    {\n        type patch;\n        faces ((3 7 6 2));\n    }\n"
       << "    upslope\n    {\n        type " << rearType << ";\n        faces ((0 4 7 3));\n    }\n"
       << "    downslope\n    {\n        type patch;\n        faces ((1 2 6 5));\n    }\n"
       << "    frontAndBack\n    {\n        type empty;\n        faces ((0 3 2 1) (4 5 6 7));\n    }\n"
       << ");\n";
    return os.str();
}

std::vector<double> MeshLayout::slideFraction(const scene::Scene& sc) const
{
    // blockMesh's cell order: x fastest, then y.
    std::vector<double> alpha;
    alpha.reserve(static_cast<std::size_t>(nCells()));
    const double dx = (x_[1] - x_[0])/nx_;
    for (int j = 0; j < ny_; ++j)
    {
        const double normal = (j + 0.5)*height_/ny_;
        for (int i = 0; i < nx_; ++i)
        {
            alpha.push_back(normal < sc.slide.thickness(x_[0] + (i + 0.5)*dx) ? 1.0 : 0.0);
        }
    }
    return alpha;
}

} // namespace cfd
} // namespace slide
