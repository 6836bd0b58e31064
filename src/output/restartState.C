#include "restartState.H"

#include "dictionary.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace slide
{
namespace output
{

namespace
{

// The first line of a state file. A state holds every particle (10 million
// numbers a write for a 420 000-particle run): as raw doubles it is written
// less than half the size and about five times faster than as the hexadecimal
// floats of the states before session 59, which read() still takes.
const char* const binaryHeader =
    "// SlideFoam restart state: lines 'key count', each followed by count 8-byte IEEE doubles, little-endian";

bool hostIsLittleEndian()
{
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
}

void swapBytes(double& x)
{
    unsigned char b[sizeof(double)];
    std::memcpy(b, &x, sizeof b);
    std::reverse(b, b + sizeof b);
    std::memcpy(&x, b, sizeof b);
}

} // namespace

void StateFile::add(const std::string& key, const std::vector<double>& values)
{
    if (!data_.count(key)) order_.push_back(key);
    data_[key] = values;
}

void StateFile::write(const std::string& path) const
{
    fs::create_directories(fs::path(path).parent_path());
    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary);
        if (!os) throw std::runtime_error("cannot write " + tmp);
        os << binaryHeader << '\n';
        std::vector<double> swapped;   // only on a big-endian host: the file is little-endian
        for (const std::string& key : order_)
        {
            const std::vector<double>* v = &data_.at(key);
            os << key << ' ' << v->size() << '\n';
            if (!hostIsLittleEndian())
            {
                swapped = *v;
                for (double& x : swapped) swapBytes(x);
                v = &swapped;
            }
            os.write(reinterpret_cast<const char*>(v->data()), static_cast<std::streamsize>(v->size()*sizeof(double)));
            os << '\n';
        }
        if (!os) throw std::runtime_error("cannot write " + tmp);
    }
    fs::rename(tmp, path);
}

StateFile StateFile::read(const std::string& path)
{
    std::ifstream is(path, std::ios::binary);
    if (!is) throw scene::InputError(path, 0, "", "no restart state: the file cannot be read");
    StateFile f;
    f.path_ = path;
    std::string line;
    std::getline(is, line);
    if (line == binaryHeader)
    {
        // key count, newline, count raw doubles, newline; line numbers count the key lines.
        int lineNo = 1;
        std::string key;
        std::size_t n = 0;
        while (is >> key >> n)
        {
            ++lineNo;
            if (is.get() != '\n' || n > (std::size_t(1) << 34))
            {
                throw scene::InputError(path, lineNo, key, "unreadable restart state: not 'key count' on this line");
            }
            std::vector<double> v(n);
            is.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n*sizeof(double)));
            if (!is || is.get() != '\n') throw scene::InputError(path, lineNo, key, "truncated restart state");
            if (!hostIsLittleEndian()) for (double& x : v) swapBytes(x);
            f.add(key, v);
        }
        if (!is.eof()) throw scene::InputError(path, lineNo, key, "unreadable restart state after this entry");
        return f;
    }
    // States written before session 59: one hexadecimal float per line.
    int lineNo = 1;
    std::string key;
    std::size_t n = 0;
    while (is >> key >> n)
    {
        ++lineNo;
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            std::string word;
            if (!(is >> word)) throw scene::InputError(path, lineNo, key, "truncated restart state");
            ++lineNo;
            char* end = nullptr;
            v[i] = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0')
            {
                throw scene::InputError(path, lineNo, key, "not a number: '" + word + "'");
            }
        }
        f.add(key, v);
    }
    if (!is.eof()) throw scene::InputError(path, lineNo, key, "unreadable restart state after this entry");
    return f;
}

const std::vector<double>& StateFile::vector(const std::string& key) const
{
    const auto it = data_.find(key);
    if (it == data_.end()) throw scene::InputError(path_, 0, key, "missing from the restart state");
    return it->second;
}

bool StateFile::has(const std::string& key) const
{
    return data_.count(key) > 0;
}

double StateFile::scalar(const std::string& key) const
{
    const std::vector<double>& v = vector(key);
    if (v.size() != 1) throw scene::InputError(path_, 0, key, "expected one value in the restart state");
    return v[0];
}

std::string timeName(double t)
{
    // As OpenFOAM names time directories (general format, here 10 digits): the
    // exact time is inside the state file.
    std::ostringstream os;
    os.precision(10);
    os << t;
    return os.str();
}

std::string statePath(const std::string& caseDir, double t, const std::string& method)
{
    return (fs::path(caseDir)/timeName(t)/(method + ".state")).string();
}

void StatePurge::written(double t)
{
    // A time written again (a final write at the last write time) is one state, not two.
    if (keep_ <= 0 || (!times_.empty() && times_.back() == t)) return;
    times_.push_back(t);
    while (times_.size() > static_cast<std::size_t>(keep_))
    {
        const fs::path state = statePath(caseDir_, times_.front(), method_);
        times_.erase(times_.begin());
        std::error_code ec;
        fs::remove(state, ec);
        if (fs::is_empty(state.parent_path(), ec) && !ec) fs::remove(state.parent_path(), ec);
    }
}

double restartTime(const std::string& caseDir, const scene::RunControl& rc, const std::string& method)
{
    if (rc.startFromLatest)
    {
        double latest = -1.0;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(caseDir, ec))
        {
            if (!e.is_directory()) continue;
            const std::string name = e.path().filename().string();
            char* end = nullptr;
            const double t = std::strtod(name.c_str(), &end);
            if (end == name.c_str() || *end != '\0' || !std::isfinite(t)) continue;
            if (t > latest && t < rc.endTime && fs::exists(e.path()/(method + ".state"))) latest = t;
        }
        return latest > 0.0 ? latest : -1.0;
    }
    if (rc.startTime <= 0.0) return -1.0;
    const std::string path = statePath(caseDir, rc.startTime, method);
    if (!fs::exists(path))
    {
        scene::Dictionary::readFile((fs::path(caseDir)/scene::Scene::controlFile()).string())
            .fail("startTime", "no " + method + " state to start from at " + timeName(rc.startTime) + " s ("
                  + path + " is missing); use startFrom latestTime or a written time");
    }
    return rc.startTime;
}

void RestartClock::addTo(StateFile& f) const
{
    f.add("time", time);
    f.add("step", static_cast<double>(step));
    f.add("scheduleOrigin", scheduleOrigin);
    f.add("scheduleIndex", static_cast<double>(scheduleIndex));
    f.add("scheduleInterval", scheduleInterval);
    std::vector<double> times, codes;
    for (const auto& m : mechanisms)
    {
        const auto& names = mechanismNames();
        times.push_back(m.first);
        codes.push_back(static_cast<double>(std::find(names.begin(), names.end(), m.second) - names.begin()));
    }
    f.add("mechanismTimes", times);
    f.add("mechanismCodes", codes);
}

RestartClock RestartClock::readFrom(const StateFile& f)
{
    RestartClock c;
    c.time = f.scalar("time");
    c.step = static_cast<long long>(f.scalar("step"));
    c.scheduleOrigin = f.scalar("scheduleOrigin");
    c.scheduleIndex = static_cast<long long>(f.scalar("scheduleIndex"));
    if (f.has("scheduleInterval")) c.scheduleInterval = f.scalar("scheduleInterval");
    const std::vector<double>& times = f.vector("mechanismTimes");
    const std::vector<double>& codes = f.vector("mechanismCodes");
    const auto& names = mechanismNames();
    for (std::size_t k = 0; k < times.size() && k < codes.size(); ++k)
    {
        const std::size_t code = static_cast<std::size_t>(codes[k]);
        c.mechanisms.emplace_back(times[k], code < names.size() ? names[code] : "unknown");
    }
    return c;
}

} // namespace output
} // namespace slide
