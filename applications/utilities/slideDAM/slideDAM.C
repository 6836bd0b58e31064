// slideDAM: the enhanced depth-averaged method of Dong, Wang & Cui (2020),
// Eqs. (2)-(5), on the BING model (Imran, Harff & Parker 2001) for a
// Herschel-Bulkley material of general n with rate effect and remoulding
// (Eq. 1), along a planar or polyline base.
//
//   slideDAM [-case dir] [-setting reference|fast]
//
// Reads constant/sceneProperties, system/controlDict and system/damDict;
// writes postProcessing/slideDAM/{runout.dat, summary.json, profile.pvd} and, with
// sites in the scene, sites.dat.
#include "application.H"
#include "damControls.H"
#include "damIntegrator.H"
#include "damOutput.H"
#include "damApplicability.H"
#include "damRestart.H"
#include "restartState.H"
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
        const scene::Scene sc = scene::Scene::read(caseDir);
        const dam::DamControls controls =
            dam::DamControls::read(scene::readMethodDict(caseDir, "damDict"), args.get("setting"));
        {
            // Memory: nine doubles per node and a few per column.
            const unsigned long long bytes = 16ull*8ull*(controls.columns + 1ull);
            output::checkMemory(bytes, std::to_string(controls.columns) + " columns", caseDir + "/system/damDict",
                                controls.resolutionLine, controls.resolutionKey);
        }

        std::cout << sc.describe();
        std::cout << "\nNumerics: " << controls.describe() << "\n" << std::endl;
        if (!controls.courantWarning.empty()) std::cout << "Warning: " << controls.courantWarning << "\n" << std::endl;
        const dam::Applicability applicability = dam::checkApplicability(sc, dam::defaultApplicabilityMap());
        if (applicability.verdict == "outside")
        {
            std::cout << "Warning: " << applicability.message << ": the depth-averaged shear layer may misrepresent "
                      << "this slide; compare with slideMPM.\n" << std::endl;
        }

        dam::SlideColumns slide = dam::SlideColumns::fromScene(sc, controls.columns);
        dam::DamIntegrator integrator(sc, controls);
        const double rho = sc.slide.density;
        const double initialMass = rho*slide.totalArea();

        const scene::RunControl& rc = sc.control;
        double t = rc.startTime;
        long long step = 0;
        output::WriteSchedule schedule(rc);
        output::MechanismHistory mechanisms;
        dam::FrontSurges surges;
        const double restartAt = output::restartTime(caseDir, rc, "slideDAM");
        if (restartAt > 0.0)
        {
            const dam::RestartPoint at = dam::readState(output::statePath(caseDir, restartAt, "slideDAM"), slide, surges);
            t = at.time;
            step = at.step;
            schedule = at.schedule(rc);
            mechanisms = at.mechanisms;
            std::cout << "Restarting from " << output::statePath(caseDir, restartAt, "slideDAM") << " (t = " << t
                      << " s, step " << step << ")\n" << std::endl;
        }

        // Only now, with the input read and checked, is an earlier run's summary removed:
        // a refused scene loses nothing, and no old summary outlives a new run.
        output::prepareOutput(caseDir, "slideDAM");
        // A restart keeps what was written up to its start and replaces the rest.
        output::RunoutLog log(caseDir, "slideDAM", restartAt > 0.0, restartAt);
        output::SiteMonitor sites(sc.sites, sc.slide.frontPosition(), caseDir, "slideDAM", restartAt > 0.0, t);
        if (!sites.empty()) sites.observe(t, dam::siteFlow(slide, sc.sites));
        std::unique_ptr<output::PvdSeries> series;
        if (controls.writeFields)
        {
            series.reset(new output::PvdSeries(output::methodOutputDir(caseDir, "slideDAM"), "profile"));
            series->truncateAfter(restartAt > 0.0 ? restartAt : -1.0);
        }
        output::StatePurge purge(caseDir, "slideDAM", rc.purgeWrite);
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
            sites.write(t);
            if (series) series->add(t, dam::profile(slide, sc));
            if (controls.writeState)
            {
                dam::writeState(caseDir, {t, step, schedule.origin(), schedule.index(), schedule.interval(), mechanisms}, slide, surges);
                purge.written(t);
            }
        };

        output::Progress progress(t, rc.endTime, controls.progressInterval);
        if (restartAt <= 0.0) write(t);
        progress.report(t, step, true, "front = " + std::to_string(slide.front()) + " m");

        bool atRest = false;
        // The fastest node after the last step and before it (one pass over the nodes per step).
        double speed = dam::DamIntegrator::maxSpeed(slide);
        double speedBeforeStep = speed;
        bool warnedFixedStep = false;
        bool warnedPastBase = false;
        while (schedule.running(t))
        {
            if (controls.deltaT > 0.0 && !warnedFixedStep && controls.deltaT > integrator.stableTimeStep(slide))
            {
                std::cout << "Warning: the fixed deltaT " << controls.deltaT << " s (system/damDict) exceeds the stable "
                          << "time step " << integrator.stableTimeStep(slide) << " s at t = " << t << " s\n";
                warnedFixedStep = true;
            }
            const double dtStable = integrator.timeStep(slide);
            if (!(dtStable > 1e-9*rc.writeInterval))
            {
                std::ostringstream os;
                os << "the stable time step collapsed to " << dtStable << " s";
                throw output::BlowUp(t, "the slide", "time step", os.str());
            }
            const output::WriteSchedule::Step s = schedule.clip(t, dtStable);
            speedBeforeStep = speed;
            integrator.advance(slide, s.dt, t);
            speed = dam::DamIntegrator::maxSpeed(slide);
            surges.update(slide.U.back(), rc.restVelocity);
            ++step;
            t = s.time;
            if (!sites.empty()) sites.observe(t, dam::siteFlow(slide, sc.sites));
            if (!warnedPastBase)
            {
                const std::string warning = sc.base.pastEndWarning(slide.x.front(), slide.x.back(), t);
                if (!warning.empty()) std::cout << warning << "\n";
                warnedPastBase = !warning.empty();
            }

            if (rc.stopAtRest && dam::DamIntegrator::atRest(speed, speedBeforeStep, rc.restVelocity))
            {
                atRest = true;
                write(t);
                progress.report(t, step, true, "all columns at rest");
                break;
            }
            if (schedule.writeDue(s))
            {
                schedule.next();   // first, so that the state written holds the next write
                mechanisms.emplace_back(t, dam::detectMechanism(slide, sc.g));
                write(t);
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
        if (!atRest) atRest = dam::DamIntegrator::atRest(speed, speedBeforeStep, rc.restVelocity);

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
        summary.addNumber("rigid_slab_factor_of_safety", sc.rigidSlabFactorOfSafety());
        summary.addString("setting", controls.setting);
        summary.addNumber("steps", static_cast<double>(step));
        summary.addNumber("node_updates_per_second", step*static_cast<double>(slide.nNodes())/summary.wallTime);
        summary.addNumber("final_length_m", slide.x.back() - slide.x.front());
        summary.addNumber("front_of_99_percent_mass_m", slide.massFront(0.99));
        summary.addNumber("mass_relative_change", (mass - initialMass)/initialMass);
        const std::string finalMechanism = dam::detectMechanism(slide, sc.g);
        summary.addString("mechanism", output::runMechanism(mechanisms, finalMechanism, atRest));
        summary.addString("final_state_mechanism", finalMechanism);
        summary.addString("dam_applicability", applicability.verdict);
        summary.addNumber("front_surges", surges.count);
        summary.extra.emplace_back("mechanism_history", output::mechanismHistoryJson(mechanisms));
        sites.addTo(summary);
        summary.write(caseDir);

        if (surges.count >= dam::FrontSurges::warnFrom)
        {
            std::cout << "\nWarning: the front stalled and was carried on by the body overrunning it " << surges.count
                      << " times. The runout of a sheet that surges so scatters by several per cent with the column "
                      << "count (Table 1 Cases 4 and 5: validation/dam/timeSchemes.md); compare runs with a few "
                      << "columns more and fewer (system/damDict columns).\n";
        }
        std::cout << "\nRunout " << std::setprecision(6) << slide.front() << " m at t = " << t << " s ("
                  << (atRest ? "at rest" : "still moving") << "), " << step << " steps, wall time "
                  << std::setprecision(3) << summary.wallTime << " s\nEnd\n" << std::endl;
        return 0;
    });
}
