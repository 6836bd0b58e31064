#include "outputContract.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace slide
{
namespace output
{

static const char* runoutHeader =
    "# time [s]  front [m]  rear [m]  frontVelocity [m/s]  maxVelocity [m/s]  maxThickness [m]"
    "  mass [kg/m]  kineticEnergy [J/m]\n";

std::string methodOutputDir(const std::string& caseDir, const std::string& method)
{
    const fs::path dir = fs::path(caseDir.empty() ? "." : caseDir)/"postProcessing"/method;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create output directory " + dir.string() + ": " + ec.message());
    return dir.string();
}

void prepareOutput(const std::string& caseDir, const std::string& method)
{
    // Nothing is created here: the case may not exist, and a failed run must not leave folders behind.
    const fs::path summary = fs::path(caseDir.empty() ? "." : caseDir)/"postProcessing"/method/"summary.json";
    std::error_code ec;
    fs::remove(summary, ec);
}

std::ofstream openHistory(const std::string& path, const std::string& header, const bool append,
                          const double startTime)
{
    std::vector<std::string> kept;
    if (append)
    {
        std::ifstream is(path);
        std::string line;
        while (std::getline(is, line))
        {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream ls(line);
            double t;
            if (ls >> t && t <= startTime*(1.0 + 1e-12) + 1e-300) kept.push_back(line);
        }
    }
    std::ofstream os(path, std::ios::trunc);
    if (!os) throw std::runtime_error("cannot write " + path);
    os << header;
    for (const std::string& line : kept) os << line << '\n';
    os.flush();
    return os;
}

RunoutLog::RunoutLog(const std::string& caseDir, const std::string& method, bool append, double startTime)
:
    path_((fs::path(methodOutputDir(caseDir, method))/"runout.dat").string()),
    os_(openHistory(path_, runoutHeader, append, startTime)),
    kept_(append ? readRunoutLog(path_) : std::vector<RunoutSample>())
{}

void RunoutLog::write(const RunoutSample& s)
{
    os_ << std::setprecision(10) << s.time << ' ' << s.front << ' ' << s.rear << ' ' << s.frontVelocity << ' '
        << s.maxVelocity << ' ' << s.maxThickness << ' ' << s.mass << ' ' << s.kineticEnergy << '\n';
    os_.flush();
}

std::vector<RunoutSample> readRunoutLog(const std::string& path)
{
    std::vector<RunoutSample> rows;
    std::ifstream is(path);
    std::string line;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        RunoutSample s;
        if (ls >> s.time >> s.front >> s.rear >> s.frontVelocity >> s.maxVelocity >> s.maxThickness >> s.mass
               >> s.kineticEnergy)
        {
            rows.push_back(s);
        }
    }
    return rows;
}

std::string jsonEscape(const std::string& s)
{
    std::string o = "\"";
    for (char c : s)
    {
        switch (c)
        {
            case '"': o += "\\\""; break;
            case '\\': o += "\\\\"; break;
            case '\n': o += "\\n"; break;
            case '\t': o += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20)
                {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    o += buf;
                }
                else
                {
                    o += c;
                }
        }
    }
    return o + "\"";
}

std::string jsonNumber(double v)
{
    if (!std::isfinite(v)) return "null";
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
}

void Summary::addNumber(const std::string& key, double v) { extra.emplace_back(key, jsonNumber(v)); }
void Summary::addString(const std::string& key, const std::string& v) { extra.emplace_back(key, jsonEscape(v)); }
void Summary::addBool(const std::string& key, bool v) { extra.emplace_back(key, v ? "true" : "false"); }

void Summary::write(const std::string& caseDir) const
{
    const fs::path dir = methodOutputDir(caseDir, method);
    const fs::path tmp = dir/"summary.json.tmp";
    {
        std::ofstream os(tmp);
        if (!os) throw std::runtime_error("cannot write " + tmp.string());
        os << "{\n"
           << "  \"method\": " << jsonEscape(method) << ",\n"
           << "  \"case\": " << jsonEscape(caseName) << ",\n"
           << "  \"runout_m\": " << jsonNumber(runout) << ",\n"
           << "  \"end_time_s\": " << jsonNumber(endTime) << ",\n"
           << "  \"at_rest\": " << (atRest ? "true" : "false") << ",\n"
           << "  \"wall_time_s\": " << jsonNumber(wallTime) << ",\n"
           << "  \"problem_size\": " << problemSize << ",\n"
           << "  \"problem_size_unit\": " << jsonEscape(problemSizeUnit) << ",\n"
           << "  \"backend\": " << jsonEscape(backend);
        for (const auto& kv : extra) os << ",\n  " << jsonEscape(kv.first) << ": " << kv.second;
        os << "\n}\n";
        if (!os) throw std::runtime_error("error writing " + tmp.string());
    }
    fs::rename(tmp, dir/"summary.json");
}

const std::vector<std::string>& mechanismNames()
{
    static const std::vector<std::string> names
    {
        "viscous elongation", "block sliding", "spreading (horsts and grabens)", "breakaway"
    };
    return names;
}

std::string runMechanism(const MechanismHistory& history, const std::string& finalName,
                         const bool atRest)
{
    const bool structural = finalName.rfind("spreading", 0) == 0 || finalName == "breakaway";
    if (!atRest || structural || history.empty()) return finalName;
    std::vector<std::pair<std::string, int>> counts;
    for (const auto& h : history)
    {
        auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == h.second; });
        if (it == counts.end()) counts.emplace_back(h.second, 1);
        else ++it->second;
    }
    auto best = counts.begin();
    for (auto it = counts.begin(); it != counts.end(); ++it) if (it->second > best->second) best = it;
    return best->first;
}

std::string mechanismHistoryJson(const MechanismHistory& history)
{
    std::ostringstream os;
    os << "[";
    for (std::size_t k = 0; k < history.size(); ++k)
    {
        os << (k ? ", " : "") << "[" << jsonNumber(history[k].first) << ", " << jsonEscape(history[k].second) << "]";
    }
    os << "]";
    return os.str();
}

} // namespace output
} // namespace slide
