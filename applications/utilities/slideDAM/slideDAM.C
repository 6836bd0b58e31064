// slideDAM: the enhanced depth-averaged method of Dong, Wang & Cui (2020),
// Eqs. (2)-(5), on the BING model (Imran, Harff & Parker 2001) for a
// Herschel-Bulkley material of general n with rate effect and remoulding
// (Eq. 1), along a planar or polyline base.
//
//   slideDAM [-case dir] [-setting reference|fast]
//
// Reads constant/sceneProperties, system/controlDict and system/damDict;
// writes postProcessing/slideDAM/{runout.dat, summary.json, profile.pvd}.
#include "application.H"
#include "damControls.H"
#include "damIntegrator.H"
#include "damOutput.H"
#include "outputContract.H"
#include "writeSchedule.H"
#include "scene.H"
#include "slideColumns.H"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

using namespace slide;

int main(int argc, char** argv)
{
    output::ArgList args(argc, argv, "slideDAM",
        "Depth-averaged runout of a submarine slide (enhanced BING, Dong et al. 2020)",
        {{"setting", "name", "reference | fast (overrides system/damDict)"}});
    return output::runGuarded("slideDAM", [&]()
    {
        args.printBanner();
        const std::string caseDir = args.caseDir();
        output::prepareOutput(caseDir, "slideDAM");

        const scene::Scene sc = scene::Scene::read(caseDir);
        const dam::DamControls controls =
            dam::DamControls::read(scene::readMethodDict(caseDir, "damDict"), args.get("setting"));
        {
            // Memory: nine doubles per node and a few per column.
            const unsigned long long bytes = 16ull*8ull*(controls.columns + 1ull);
            output::checkMemory(bytes, std::to_string(controls.columns) + " columns", caseDir + "/system/damDict", 0,
                                "columns");
        }

        std::cout << sc.describe();
        std::cout << "\nNumerics: " << controls.describe() << "\n" << std::endl;

        dam::SlideColumns slide = dam::SlideColumns::fromScene(sc, controls.columns);
        dam::DamIntegrator integrator(sc, controls);
        const double rho = sc.slide.density;
        const double initialMass = rho*slide.totalArea();

        output::RunoutLog log(caseDir, "slideDAM");
        std::unique_ptr<output::PvdSeries> series;
        if (controls.writeFields)
        {
            series.reset(new output::PvdSeries(output::methodOutputDir(caseDir, "slideDAM"), "profile"));
            series->truncateAfter(-1.0);   // a fresh run replaces an earlier series
        }
        auto write = [&](double t)
        {
            const output::RunoutSample sample = dam::runoutSample(slide, t, rho);
            // Energy bound: depth-averaged kinetic energy beyond the work of gravity
            // (plus the initial potential energy of the column heights) is a blow-up.
            const double bound = dam::gravityWork(slide, sc) + rho*sc.g*slide.totalArea()*sc.slide.height;
            if (!(sample.kineticEnergy <= bound))
            {
                throw output::BlowUp(t, "the whole slide (front at s = " + std::to_string(slide.x.back()) + " m)",
                                     "kinetic energy", std::to_string(sample.kineticEnergy) + " J/m exceeds the "
                                     + std::to_string(bound) + " J/m that gravity can have supplied");
            }
            log.write(sample);
            if (series) series->add(t, dam::profile(slide, sc));
        };

        const scene::RunControl& rc = sc.control;
        double t = rc.startTime;
        long long step = 0;
        output::WriteSchedule schedule(rc);
        output::Progress progress(rc.startTime, rc.endTime, controls.progressInterval);
        write(t);
        progress.report(t, step, true, "front = 0 m");

        bool atRest = false;
        while (schedule.running(t))
        {
            const double dtStable = integrator.timeStep(slide);
            if (!(dtStable > 1e-9*rc.writeInterval))
            {
                std::ostringstream os;
                os << "the stable time step collapsed to " << dtStable << " s";
                throw output::BlowUp(t, "the slide", "time step", os.str());
            }
            const output::WriteSchedule::Step s = schedule.clip(t, dtStable);
            integrator.step(slide, s.dt, t);
            ++step;
            t = s.time;

            if (rc.stopAtRest && dam::DamIntegrator::atRest(slide, rc.restVelocity))
            {
                atRest = true;
                write(t);
                progress.report(t, step, true, "all columns at rest");
                break;
            }
            if (schedule.writeDue(s))
            {
                write(t);
                schedule.next();
                std::ostringstream extra;
                extra << std::setprecision(5) << "front = " << slide.front() << " m  U_front = " << slide.U.back()
                      << " m/s";
                progress.report(t, step, true, extra.str());
            }
            else if (s.landing)
            {
                write(t);   // the end time
            }
            else
            {
                progress.report(t, step);
            }
        }
        if (!atRest) atRest = dam::DamIntegrator::atRest(slide, rc.restVelocity);

        const double mass = rho*slide.totalArea();
        output::Summary summary;
        summary.method = "slideDAM";
        summary.caseName = sc.caseName;
        summary.runout = slide.front();
        summary.endTime = t;
        summary.atRest = atRest;
        summary.wallTime = progress.elapsed();
        summary.problemSize = slide.nColumns();
        summary.problemSizeUnit = "columns";
        summary.backend = "serial";
        summary.addString("setting", controls.setting);
        summary.addNumber("steps", static_cast<double>(step));
        summary.addNumber("node_updates_per_second", step*static_cast<double>(slide.nNodes())/summary.wallTime);
        summary.addNumber("final_length_m", slide.x.back() - slide.x.front());
        summary.addNumber("mass_relative_change", (mass - initialMass)/initialMass);
        summary.addString("mechanism", dam::detectMechanism(slide, sc.g));
        summary.write(caseDir);

        std::cout << "\nRunout " << std::setprecision(6) << slide.front() << " m at t = " << t << " s ("
                  << (atRest ? "at rest" : "still moving") << "), " << step << " steps, wall time "
                  << std::setprecision(3) << summary.wallTime << " s\nEnd\n" << std::endl;
        return 0;
    });
}
