#include "vtkWriter.H"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace slide
{
namespace output
{

void PolyData::addScalar(const std::string& name, std::vector<double> values)
{
    if (values.size() != nPoints()) throw std::logic_error("PolyData: array " + name + " has the wrong size");
    arrays_.push_back({name, 1, std::move(values)});
}

const std::vector<double>& PolyData::array(const std::string& name) const
{
    for (const Array& a : arrays_)
    {
        if (a.name == name) return a.data;
    }
    throw std::out_of_range("PolyData: no array " + name);
}

void PolyData::addVector(const std::string& name, std::vector<double> values)
{
    if (values.size() != 3*nPoints()) throw std::logic_error("PolyData: array " + name + " has the wrong size");
    arrays_.push_back({name, 3, std::move(values)});
}

namespace
{

// One block of appended raw data: a UInt64 byte count, then the bytes.
template<class T>
void appendBlock(std::string& buf, const std::vector<T>& v)
{
    const std::uint64_t n = v.size()*sizeof(T);
    buf.append(reinterpret_cast<const char*>(&n), sizeof n);
    if (n) buf.append(reinterpret_cast<const char*>(v.data()), n);
}

} // namespace

void PolyData::write(const std::string& path) const
{
    const std::size_t np = nPoints();
    std::ostringstream xml;
    std::string appended;
    std::uint64_t offset = 0;
    auto dataArray = [&](const std::string& type, const std::string& name, int nc)
    {
        xml << "        <DataArray type=\"" << type << "\"";
        if (!name.empty()) xml << " Name=\"" << name << "\"";
        if (nc > 1) xml << " NumberOfComponents=\"" << nc << "\"";
        xml << " format=\"appended\" offset=\"" << offset << "\"/>\n";
    };

    std::size_t nVerts = 0, nLines = 0;
    std::vector<std::int64_t> conn, offs;
    if (cells == Cells::vertices)
    {
        nVerts = np;
        conn.resize(np);
        offs.resize(np);
        for (std::size_t i = 0; i < np; ++i) { conn[i] = static_cast<std::int64_t>(i); offs[i] = static_cast<std::int64_t>(i + 1); }
    }
    else if (np > 1)
    {
        nLines = 1;
        conn.resize(np);
        for (std::size_t i = 0; i < np; ++i) conn[i] = static_cast<std::int64_t>(i);
        offs = {static_cast<std::int64_t>(np)};
    }

    xml << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "  <PolyData>\n"
        << "    <Piece NumberOfPoints=\"" << np << "\" NumberOfVerts=\"" << nVerts << "\" NumberOfLines=\""
        << nLines << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";

    xml << "      <PointData>\n";
    for (const Array& a : arrays_)
    {
        dataArray("Float64", a.name, a.nComponents);
        appendBlock(appended, a.data);
        offset = appended.size();
    }
    xml << "      </PointData>\n      <Points>\n";
    dataArray("Float64", "Points", 3);
    appendBlock(appended, points);
    offset = appended.size();
    xml << "      </Points>\n";

    const char* cellTag = cells == Cells::vertices ? "Verts" : "Lines";
    xml << "      <" << cellTag << ">\n";
    dataArray("Int64", "connectivity", 1);
    appendBlock(appended, conn);
    offset = appended.size();
    dataArray("Int64", "offsets", 1);
    appendBlock(appended, offs);
    offset = appended.size();
    xml << "      </" << cellTag << ">\n";
    xml << "    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
        if (!os) throw std::runtime_error("cannot write " + tmp);
        const std::string head = xml.str();
        os.write(head.data(), static_cast<std::streamsize>(head.size()));
        os.write(appended.data(), static_cast<std::streamsize>(appended.size()));
        os << "\n  </AppendedData>\n</VTKFile>\n";
        if (!os) throw std::runtime_error("error writing " + tmp);
    }
    fs::rename(tmp, path);
}


PvdSeries::PvdSeries(const std::string& dir, const std::string& stem)
:
    dir_(dir),
    stem_(stem),
    pvdPath_((fs::path(dir)/(stem + ".pvd")).string())
{
    fs::create_directories(fs::path(dir_)/stem_);
    // Pick up an existing series (restart); a fresh run truncates it first.
    std::ifstream is(pvdPath_);
    std::string line;
    const std::regex entry("timestep=\"([^\"]+)\".*file=\"([^\"]+)\"");
    while (std::getline(is, line))
    {
        std::smatch m;
        if (std::regex_search(line, m, entry)) steps_.emplace_back(std::stod(m[1]), m[2]);
    }
}

void PvdSeries::truncateAfter(double t)
{
    std::vector<std::pair<double, std::string>> kept;
    for (const auto& s : steps_)
    {
        if (s.first <= t*(1.0 + 1e-12) + 1e-300) kept.push_back(s);
        else
        {
            std::error_code ec;
            fs::remove(fs::path(dir_)/s.second, ec);
        }
    }
    steps_ = kept;
    writePvd();
}

std::string PvdSeries::add(double time, const PolyData& data)
{
    std::ostringstream name;
    name << stem_ << '/' << stem_ << '_' << std::setw(6) << std::setfill('0') << steps_.size() << ".vtp";
    const fs::path file = fs::path(dir_)/name.str();
    data.write(file.string());
    steps_.emplace_back(time, name.str());
    writePvd();
    return file.string();
}

void PvdSeries::writePvd() const
{
    const std::string tmp = pvdPath_ + ".tmp";
    {
        std::ofstream os(tmp, std::ios::trunc);
        if (!os) throw std::runtime_error("cannot write " + tmp);
        os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
           << "  <Collection>\n";
        for (const auto& s : steps_)
        {
            os << "    <DataSet timestep=\"" << std::setprecision(12) << s.first << "\" part=\"0\" file=\""
               << s.second << "\"/>\n";
        }
        os << "  </Collection>\n</VTKFile>\n";
    }
    fs::rename(tmp, pvdPath_);
}

} // namespace output
} // namespace slide
