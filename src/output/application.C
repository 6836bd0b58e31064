#include "application.H"

#include "dictionary.H"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace slide
{
namespace output
{

namespace
{

void usage(const std::string& app, const std::string& description, const std::vector<ArgList::Option>& options)
{
    std::cout << "\nUsage: " << app << " [OPTIONS]\n"
              << "options:\n"
              << "  -case <dir>       Specify case directory to use (instead of the cwd)\n";
    for (const ArgList::Option& o : options)
    {
        std::string left = "-" + o.name + (o.argName.empty() ? "" : " <" + o.argName + ">");
        std::cout << "  " << std::left << std::setw(18) << left << o.help << '\n';
    }
    std::cout << "  -help             Print the usage\n\n" << description << "\n\n";
}

} // namespace

ArgList::ArgList(int argc, char** argv, const std::string& app, const std::string& description,
                 const std::vector<Option>& options)
:
    app_(app)
{
    for (int i = 0; i < argc; ++i) commandLine_ += (i ? " " : "") + std::string(argv[i]);
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        if (a == "-help" || a == "--help" || a == "-h")
        {
            usage(app, description, options);
            std::exit(0);
        }
        if (a == "-case")
        {
            if (i + 1 >= argc)
            {
                std::cerr << "\n--> " << app << " FATAL ERROR: option -case needs a directory\n";
                usage(app, description, options);
                std::exit(1);
            }
            caseDir_ = argv[++i];
            continue;
        }
        bool known = false;
        for (const Option& o : options)
        {
            if (a != "-" + o.name) continue;
            known = true;
            if (o.argName.empty())
            {
                values_[o.name] = "";
            }
            else
            {
                if (i + 1 >= argc)
                {
                    std::cerr << "\n--> " << app << " FATAL ERROR: option " << a << " needs <" << o.argName << ">\n";
                    usage(app, description, options);
                    std::exit(1);
                }
                values_[o.name] = argv[++i];
            }
        }
        if (!known)
        {
            std::cerr << "\n--> " << app << " FATAL ERROR: unknown option or argument '" << a << "'\n";
            usage(app, description, options);
            std::exit(1);
        }
    }
}

std::string ArgList::get(const std::string& opt, const std::string& deflt) const
{
    const auto it = values_.find(opt);
    return it == values_.end() ? deflt : it->second;
}

void ArgList::printBanner() const
{
    char host[256] = "unknown";
    gethostname(host, sizeof host - 1);
    char cwd[4096] = ".";
    if (!getcwd(cwd, sizeof cwd)) cwd[0] = '\0';
    std::cout
        << "/*---------------------------------------------------------------------------*\\\n"
        << "  SlideFoam: runout of submarine landslides (Dong, Wang & Cui 2020)\n"
        << "  Application: " << app_ << "\n"
        << "\\*---------------------------------------------------------------------------*/\n"
        << "Exec   : " << commandLine_ << '\n'
        << "Host   : " << host << '\n'
        << "PID    : " << getpid() << '\n'
        << "Case   : " << caseDir_ << '\n'
        << "cwd    : " << cwd << '\n'
        << "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n"
        << std::endl;
}

BlowUp::BlowUp(double time, const std::string& place, const std::string& quantity, const std::string& detail)
:
    std::runtime_error([&]
    {
        std::ostringstream os;
        os << "numerical blow-up at time " << std::setprecision(10) << time << " s, " << place << ": " << quantity
           << (detail.empty() ? "" : " (" + detail + ")")
           << ".\nThe output written before this time is kept; reduce the time step (system/*Dict) or check the scene.";
        return os.str();
    }()),
    time_(time)
{}

int runGuarded(const std::string& app, const std::function<int()>& body)
{
    try
    {
        return body();
    }
    catch (const scene::InputError& e)
    {
        std::cout.flush();
        std::cerr << "\n\n--> " << app << " FATAL IO ERROR:\n";
        if (!e.key().empty()) std::cerr << "key '" << e.key() << "': ";
        std::cerr << e.message() << "\n\nfile: " << e.file();
        if (e.line() > 0) std::cerr << " at line " << e.line();
        std::cerr << ".\n\n" << e.what() << "\n\nFOAM exiting\n" << std::endl;
        return 1;
    }
    catch (const std::exception& e)
    {
        std::cout.flush();
        std::cerr << "\n\n--> " << app << " FATAL ERROR:\n" << e.what() << "\n\nFOAM exiting\n" << std::endl;
        return 1;
    }
}

Progress::Progress(double startTime, double endTime, double intervalSeconds)
:
    t0_(startTime),
    t1_(endTime),
    interval_(intervalSeconds),
    wallStart_(std::chrono::steady_clock::now())
{}

double Progress::elapsed() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
}

void Progress::report(double time, long long step, bool force, const std::string& extra)
{
    const double wall = elapsed();
    if (!force && wall - lastPrint_ < interval_) return;
    lastPrint_ = wall;
    const double frac = t1_ > t0_ ? (time - t0_)/(t1_ - t0_) : 1.0;
    std::ostringstream os;
    os << "Time = " << std::setprecision(6) << time << "  step " << step << "  (" << std::fixed << std::setprecision(1)
       << 100.0*frac << " %)";
    os << "  ExecutionTime = " << std::setprecision(2) << wall << " s";
    if (frac > 1e-6 && frac < 1.0)
    {
        os << "  ETA = " << std::setprecision(1) << wall*(1.0 - frac)/frac << " s";
    }
    if (!extra.empty()) os << "  " << extra;
    std::cout << os.str() << std::endl;
}

unsigned long long availableMemoryBytes()
{
    std::ifstream is("/proc/meminfo");
    std::string key;
    unsigned long long kb = 0;
    std::string unit;
    while (is >> key >> kb >> unit)
    {
        if (key == "MemAvailable:") return kb*1024ull;
    }
    return 0;
}

void checkMemory(unsigned long long bytes, const std::string& what, const std::string& file, int line,
                 const std::string& key, const unsigned long long available)
{
    const unsigned long long avail = available > 0 ? available : availableMemoryBytes();
    if (avail > 0 && bytes > avail*8/10)
    {
        std::ostringstream os;
        os << what << " would need " << std::fixed << std::setprecision(1) << bytes/1073741824.0
           << " GiB of memory but only " << avail/1073741824.0 << " GiB are available; coarsen the resolution";
        throw scene::InputError(file, line, key, os.str());
    }
}

} // namespace output
} // namespace slide
