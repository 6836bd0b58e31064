// slideMPM: an explicit material point method for submarine slides on Kokkos
// (OpenMP, CUDA and Serial backends from one source), the non-averaged method
// of Dong, Wang & Cui (2020): undrained clay with s_u from Eq. (1), E = 100 s_uo,
// nu = 0.49, cell H0/60 with 4 x 4 particles, Courant 0.3 (Eq. 6), a rigid base
// with no-slip, frictional or hydroplaning contact.
//
//   slideMPM [-case dir] [-setting reference|fast]
//
// Reads constant/sceneProperties, system/controlDict and system/mpmDict;
// writes postProcessing/slideMPM/{runout.dat, summary.json, particles.pvd} and, with
// sites in the scene, sites.dat (sampled every step: siteSampling.H).
#include "application.H"
#include "backgroundGrid.H"
#include "baseFrame.H"
#include "frontResolution.H"
#include "materialPoints.H"
#include "mpmControls.H"
#include "mpmOutput.H"
#include "mpmRestart.H"
#include "restartState.H"
#include "outputContract.H"
#include "writeSchedule.H"
#include "scene.H"
#include "siteSampling.H"
#include "timeIntegrator.H"

#include <cmath>
#include <future>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

using namespace slide;

namespace
{

std::string backendName()
{
    std::ostringstream os;
    os << mpm::ExecutionSpace::name();
    if (std::string(mpm::ExecutionSpace::name()) == "OpenMP")
    {
        os << " (" << mpm::ExecutionSpace().concurrency() << " threads)";
    }
    return os.str();
}

} // namespace

int main(int argc, char** argv)
{
    output::ArgList args(argc, argv, "slideMPM",
        "Material point method runout of a submarine slide on Kokkos (Dong et al. 2020)",
        {{"setting", "name", "reference | fast (overrides system/mpmDict)"}});
    Kokkos::ScopeGuard kokkos(argc, argv);
    return output::runGuarded("slideMPM", [&]()
    {
        args.printBanner();
        const std::string caseDir = args.caseDir();
        const scene::Scene sc = scene::Scene::read(caseDir);
        const mpm::MpmControls controls =
            mpm::MpmControls::read(scene::readMethodDict(caseDir, "mpmDict"), args.get("setting"));

        const double H0 = sc.slide.height;
        const double d = H0/controls.cellsPerHeight;
        const int ppc = controls.particlesPerCell;
        {
            const long long n = mpm::MaterialPoints::estimateCount(sc, d, ppc);
            output::checkMemory(n*mpm::MaterialPoints::bytesPerParticle
                                + mpm::BackgroundGrid::bytesFor(4ll*n/(ppc*ppc) + 1000),
                                std::to_string(n) + " particles", caseDir + "/system/mpmDict",
                                controls.resolutionLine, controls.resolutionKey, mpm::availableMemoryBytes());
        }
        const mpm::BaseFrame frame = mpm::BaseFrame::fromScene(sc);
        const mpm::UndrainedClay clay = controls.clay(sc.rheology, d);
        const mpm::RowShear rows = mpm::gridRows(frame, controls);
        mpm::MaterialPoints points = mpm::MaterialPoints::seed(sc, frame, clay, controls.poissonRatio, d, ppc,
                                                               controls.geostaticStart, rows);
        mpm::BackgroundGrid grid(d, frame.rearX, rows);
        const mpm::TimeIntegrator integrator(frame, clay, mpm::basalContact(sc.interface), controls, sc.slide.density);

        const std::string backend = backendName();
        std::cout << sc.describe();
        std::cout << "\nNumerics: " << controls.describe(d) << "\n"
                  << "    " << points.count << " particles, cell " << d << " m, elastic wave speed "
                  << integrator.waveSpeed() << " m/s, dt " << integrator.stableTimeStep(d, 0.0) << " s\n"
                  << "Backend: " << backend << "\n" << std::endl;
        if (controls.deltaT > integrator.stableTimeStep(d, 0.0))
        {
            std::cout << "Warning: the fixed deltaT " << controls.deltaT << " s (system/mpmDict) exceeds the stable "
                      << "time step " << integrator.stableTimeStep(d, 0.0) << " s (Eq. 6)\n" << std::endl;
        }

        mpm::HostPoints initial(points);
        double initialFront = frame.level.arcLength(initial.frontX());
        double initialMass = initial.totalMass();
        double highest = -1e300;   // elevation of the highest particle at the start
        for (int p = 0; p < initial.count; ++p)
        {
            double X, Z;
            frame.toGlobal(initial.position(p, 0), initial.position(p, 1), X, Z);
            highest = std::max(highest, Z);
        }

        const scene::RunControl& rc = sc.control;
        double t = rc.startTime;
        long long step = 0;
        output::WriteSchedule schedule(rc);
        output::MechanismHistory mechanisms;
        const double restartAt = output::restartTime(caseDir, rc, "slideMPM");
        std::unique_ptr<mpm::StepStatistics> restartStats;
        mpm::EnergyState energyStart = mpm::energyState(initial, frame, clay, sc.slide.density, d);
        double boundaryWork = 0.0;
        mpm::FrontRecord frontRecord;
        if (restartAt > 0.0)
        {
            const std::string path = output::statePath(caseDir, restartAt, "slideMPM");
            const mpm::RestartPoint at = mpm::readState(path, points);
            t = at.time;
            step = at.step;
            schedule = at.schedule(rc);
            initialFront = at.initialFront;
            initialMass = at.initialMass;
            highest = at.highest;
            mechanisms = at.mechanisms;
            restartStats.reset(new mpm::StepStatistics(at.stats));
            energyStart = at.energyStart;
            boundaryWork = at.boundaryWork;
            frontRecord = at.front;
            std::cout << "Restarting from " << path << " (t = " << t << " s, step " << step << ")\n" << std::endl;
        }

        // Only now, with the input read and checked, is an earlier run's summary removed:
        // a refused scene loses nothing, and no old summary outlives a new run.
        output::prepareOutput(caseDir, "slideMPM");
        // A restart keeps what was written up to its start and replaces the rest.
        output::RunoutLog log(caseDir, "slideMPM", restartAt > 0.0, restartAt);
        mpm::EnergyLog energyLog(caseDir, restartAt > 0.0, restartAt);
        std::unique_ptr<output::PvdSeries> series;
        if (controls.writeFields)
        {
            series.reset(new output::PvdSeries(output::methodOutputDir(caseDir, "slideMPM"), "particles"));
            series->truncateAfter(restartAt > 0.0 ? restartAt : -1.0);
        }
        mpm::StepStatistics stats = restartStats ? *restartStats : mpm::TimeIntegrator::statistics(points, rows);
        // Sampled every step: a passing front is faster than the writes.
        const mpm::SiteSampler siteSampler(sc.sites, frame, d);
        output::SiteMonitor sites(sc.sites, sc.slide.frontPosition(), caseDir, "slideMPM", restartAt > 0.0, t);
        if (!siteSampler.empty()) sites.observe(t, siteSampler.sample(points, stats));
        output::RunoutSample last;
        output::StatePurge purge(caseDir, "slideMPM", controls.statesKept(rc.purgeWrite));
        // The front zone is the slide's foremost H0: a length of the slide, not of the cell.
        mpm::FrontResolution frontResolution(d, H0, rc.restVelocity, frontRecord);
        std::unique_ptr<mpm::PhaseTimes> times(controls.phaseTimes ? new mpm::PhaseTimes : nullptr);
        // A write copies the particles to the host and takes the runout sample
        // (`last`, which the progress lines and error messages read); the rest
        // (the mechanism where asked, the runout and energy logs, the front's
        // resolution, the particle series, the restart state) is a job on that
        // copy alone. With writeInBackground it runs beside the next steps, one
        // job at a time and in order; its warnings are printed when it is done.
        const bool background = controls.writeInBackground < 0 ? mpm::devicePaths : controls.writeInBackground == 1;
        std::future<std::string> pending;
        auto finishWrites = [&]()
        {
            if (!pending.valid()) return;
            const std::string warning = pending.get();   // rethrows what the job threw
            if (!warning.empty()) std::cout << warning << "\n" << std::endl;
        };
        auto write = [&](double t, bool logRow = true, bool mechanism = false)
        {
            if (times) times->lap(mpm::PhaseTimes::hostWork);
            struct Lap { mpm::PhaseTimes* t; ~Lap() { if (t) t->lap(mpm::PhaseTimes::output); } } lap{times.get()};
            finishWrites();
            const auto hp = std::make_shared<const mpm::HostPoints>(points);
            last = mpm::runoutSample(*hp, frame, t, initialFront, d);
            if (!logRow) return;
            sites.write(t);   // here, not in the job: the record goes on with the next step
            // What the state records, as it is now.
            const output::RunoutSample sample = last;
            const long long stepNow = step;
            const double origin = schedule.origin(), interval = schedule.interval();
            const auto index = schedule.index();
            const mpm::StepStatistics statsNow = stats;
            const double boundaryWorkNow = boundaryWork;
            auto job = [&, hp, t, sample, stepNow, origin, index, interval, statsNow, boundaryWorkNow, mechanism]()
            {
                // The mechanism first, so that the state written holds it.
                if (mechanism) mechanisms.emplace_back(t, mpm::detectMechanism(*hp, frame, H0, sc.g, d, sc.rheology).name);
                log.write(sample);
                const std::string warning = frontResolution.observe(t, sample.front, mpm::frontZone(*hp, frame, H0));
                energyLog.write(t, mpm::energyState(*hp, frame, clay, sc.slide.density, d), energyStart, boundaryWorkNow);
                if (series) series->add(t, mpm::particleData(*hp, frame, sc.rheology));
                if (controls.writeState)
                {
                    mpm::writeState(caseDir, {{t, stepNow, origin, index, interval, mechanisms}, initialFront,
                                              initialMass, highest, statsNow, energyStart, boundaryWorkNow,
                                              frontResolution.record()}, *hp);
                    purge.written(t);
                }
                return warning;
            };
            if (background) pending = std::async(std::launch::async, job);
            else
            {
                std::promise<std::string> done;
                done.set_value(job());
                pending = done.get_future();
                finishWrites();
            }
        };

        const long long firstStep = step;
        output::Progress progress(t, rc.endTime, controls.progressInterval);
        write(t, restartAt <= 0.0);   // a restart only needs `last`: its row is in runout.dat
        progress.report(t, step, true, "front = " + std::to_string(last.front) + " m");
        const unsigned long long freeMemory = mpm::availableMemoryBytes();
        const unsigned long long gridBudget = freeMemory > 0 ? freeMemory/2 : 8ull << 30;

        bool atRest = false;
        bool slowingDown = true;
        double particleUpdates = 0.0;
        const mpm::ParticleSplitting& splitting = integrator.splitting();
        // Splitting may grow the cloud up to the memory free at the start (read once, not every check).
        const long long maxParticles = freeMemory > 0
            ? freeMemory*8/10/mpm::MaterialPoints::bytesPerParticle : 1ll << 40;
        // s_u and the strain rates are output only: recorded by the steps whose end is written.
        bool restPending = false;
        // Hydroplaning needs motion: the water film that carries the slide has no
        // strength at rest, so a block that climbs an adverse slope would slide back
        // and forth for ever. So would a block on a frictional base whose s_b is
        // below the pull of the adverse slope it climbs. Its runout is where its bulk
        // motion stops (the downslope momentum reaches zero), as slideDAM arrests a
        // column whose velocity would reverse; an elastic block rings too much for
        // every particle to fall below restVelocity together. On a frictional base
        // only where the base under the slide rises towards its front: on a downslope
        // a stopping slide's ringing turns its momentum long before it is at rest.
        const bool hydroplaning = sc.interface.type == scene::Interface::Type::hydroplaning;
        const bool frictional = sc.interface.type == scene::Interface::Type::frictional;
        bool turned = false;
        bool moved = false;   // a turn needs motion first: the slide's mean downslope speed above restVelocity
        bool warnedPastBase = false;
        while (schedule.running(t))
        {
            if (times) times->lap(mpm::PhaseTimes::hostWork);
            if (!grid.fit(stats.xmin, stats.xmax, stats.ymin, stats.ymax, gridBudget))
            {
                std::ostringstream os;
                os << "material spans x in [" << stats.xmin << ", " << stats.xmax << "] m, y in [" << stats.ymin
                   << ", " << stats.ymax << "] m of the base frame" << (rows.on ? " (height above the base)" : "") << ": the background grid would need more memory "
                   << "than is free";
                throw output::BlowUp(t, "the particle cloud", "grid extent", os.str());
            }
            if (times) times->lap(mpm::PhaseTimes::gridFit);
            if (step > 0 && step % mpm::sortInterval == 0)
            {
                const long long added = splitting.split(points, grid, frame.level, maxParticles);
                if (added < 0)
                {
                    std::ostringstream os;
                    os << "splitting " << -added << " stretched particles would take the run to "
                       << points.count - added << " particles, more memory than is free; set particleSplitting no "
                       << "in system/mpmDict; the last good state is the one written at t = " << last.time << " s";
                    throw output::BlowUp(t, "the particle cloud", "particle count", os.str());
                }
                if (times) times->lap(mpm::PhaseTimes::splitting);
                points.sortByCell(grid);
                if (times) times->lap(mpm::PhaseTimes::sorting);
            }
            const output::WriteSchedule::Step s = schedule.clip(t, integrator.timeStep(d, stats.maxSpeed));
            const bool confirming = restPending;   // the step after rest was seen unrecorded
            const bool recorded = s.landing || confirming;
            const mpm::StepStatistics next = integrator.step(points, grid, s.dt, recorded, times.get());
            ++step;
            t = s.time;
            boundaryWork += next.boundaryWork;
            particleUpdates += points.count;

            // Runaway: faster than a fall from the highest start point to the lowest
            // point reached could make it, with a factor 2 of margin.
            double Xl, Zl;
            frame.toGlobal(next.xmax, next.ymin + rows.height(next.xmax), Xl, Zl);
            const double drop = std::max(highest - Zl, H0);
            const double bound = 2.0*std::sqrt(2.0*sc.g*drop) + integrator.waveSpeed();
            if (!next.finite || next.maxSpeed > bound)
            {
                std::ostringstream place, detail;
                const mpm::MaterialPoints::Located p = points.fastest();
                double Xp, Zp;
                frame.toGlobal(p.x, p.y, Xp, Zp);
                place << "particle " << p.index << " at s = " << p.x << " m along the base, " << p.y
                      << " m above it (x = " << Xp << ", z = " << Zp << " m)";
                detail << (next.finite ? "particle speed " + std::to_string(next.maxSpeed)
                                             + " m/s exceeds the " + std::to_string(bound)
                                             + " m/s that gravity and the elastic waves can give"
                                       : std::string("non-finite position or velocity"))
                       << "; the last good state is the one written at t = " << last.time << " s";
                throw output::BlowUp(t, place.str(), next.finite ? "velocity" : "NaN", detail.str());
            }
            // Slow is not rest while accelerating: a slide released under a small net force starts slowly.
            slowingDown = next.maxSpeed <= stats.maxSpeed;
            moved = moved || next.momentumX > rc.restVelocity*initialMass;
            if (!turned && moved && stats.momentumX > 0.0 && next.momentumX <= 0.0)
            {
                const bool climbing = frictional
                    && sc.base.point(frame.level.arcLength(next.xmax)).z
                       > sc.base.point(frame.level.arcLength(next.xmin)).z;
                turned = hydroplaning || climbing;
            }
            stats = next;
            if (!siteSampler.empty()) sites.observe(t, siteSampler.sample(points, stats));
            if (!warnedPastBase)
            {
                const std::string warning = sc.base.pastEndWarning(frame.level.arcLength(stats.xmin),
                                                                   frame.level.arcLength(stats.xmax), t);
                if (!warning.empty()) std::cout << warning << "\n" << std::endl;
                warnedPastBase = !warning.empty();
            }

            // At rest after a step that did not record: one more step, which records
            // what the state written at rest holds.
            const bool slow = stats.maxSpeed < rc.restVelocity;
            restPending = rc.stopAtRest && ((slow && slowingDown) || turned) && !recorded;
            if (restPending) continue;
            if (rc.stopAtRest && ((slow && (slowingDown || confirming)) || turned))
            {
                atRest = true;
                write(t);
                progress.report(t, step, true, slow ? "all particles at rest"
                                                    : hydroplaning
                                                    ? "the slide's downslope motion stopped (hydroplaning holds nothing at rest)"
                                                    : "the slide's downslope motion stopped (where s_b cannot hold it, it would slide back)");
                break;
            }
            if (schedule.writeDue(s))
            {
                // The schedule first, so that the state written holds it.
                schedule.next();
                write(t, true, true);
                std::ostringstream extra;
                extra << std::setprecision(5) << "front = " << last.front << " m  U_front = " << last.frontVelocity
                      << " m/s  |U|max = " << last.maxVelocity << " m/s";
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
        if (!atRest) atRest = stats.maxSpeed < rc.restVelocity && slowingDown;
        finishWrites();

        const mpm::HostPoints hp(points);
        const output::Mechanism mech = mpm::detectMechanism(hp, frame, H0, sc.g, d, sc.rheology);
        const double mass = hp.totalMass();
        output::Summary summary;
        summary.method = "slideMPM";
        summary.caseName = sc.caseName;
        summary.runout = last.front;
        summary.endTime = t;
        summary.atRest = atRest;
        summary.wallTime = progress.elapsed();
        summary.problemSize = points.count;
        summary.problemSizeUnit = "particles";
        summary.backend = backend;
        summary.addNumber("rigid_slab_factor_of_safety", sc.rigidSlabFactorOfSafety());
        summary.addString("setting", controls.setting);
        summary.addNumber("cells_per_height", controls.cellsPerHeight);
        summary.addNumber("particles_per_cell", controls.particlesPerCell);
        summary.addString("base_contact", controls.baseContactWord());
        // The choices a rerun must repeat to reproduce the runout (mpmDict's keys).
        summary.addBool("base_row_mass_scaling",
                        controls.baseBoundary == mpm::MpmControls::BaseBoundary::fitted && controls.baseRowMassScaling);
        summary.addNumber("particle_shifting", controls.particleShifting);
        summary.addString("stress_quadrature", controls.stressQuadratureWord());
        summary.addNumber("courant", controls.courant);
        summary.addString("strain_rate", controls.strainRateWord());
        summary.addString("stress_rate", controls.stressRateWord());
        summary.addNumber("shear_band_thickness_m", controls.shearBandThickness);
        summary.addBool("shear_band_rate", controls.shearBandRate);
        summary.addString("initial_stress", controls.geostaticStart ? "geostatic" : "none");
        summary.addNumber("steps", static_cast<double>(step));
        summary.addNumber("particle_updates_per_second", particleUpdates/summary.wallTime);
        summary.addNumber("final_length_m", last.front - last.rear);
        summary.addNumber("max_thickness_m", last.maxThickness);
        // The front of the slide's body, from the initial front as runout_m: particles thrown
        // ahead of a fast, thin sheet set runout_m (the foremost one) and not this.
        const double massFront = frame.level.arcLength(hp.massFrontX(0.99)) - initialFront;
        summary.addNumber("front_of_99_percent_mass_m", massFront);
        summary.addNumber("mass_relative_change", (mass - initialMass)/initialMass);
        {
            // The energy budget at the end (energy.dat has its history): where gravity's work went.
            const mpm::EnergyBudget b = mpm::energyBudget(mpm::energyState(hp, frame, clay, sc.slide.density, d),
                                                          energyStart, boundaryWork);
            const double share = b.gravity > 0.0 ? 1.0/b.gravity : 0.0;
            summary.addNumber("gravity_work_J_per_m", b.gravity);
            summary.addNumber("plastic_dissipation_fraction", b.plastic*share);
            summary.addNumber("boundary_dissipation_fraction", b.boundary*share);
            summary.addNumber("numerical_dissipation_fraction", b.numerical*share);
        }
        frontResolution.addTo(summary, last.front);
        output::addMechanism(summary, mechanisms, mech, atRest, H0);
        sites.addTo(summary);
        summary.write(caseDir);
        if (times)
        {
            times->lap(mpm::PhaseTimes::hostWork);
            std::cout << "\n";
            times->print(std::cout, step - firstStep);
        }

        std::cout << "\nRunout " << std::setprecision(6) << last.front << " m at t = " << t << " s ("
                  << (atRest ? "at rest" : "still moving") << "), mechanism: "
                  << output::runMechanism(mechanisms, mech.name, atRest) << "\n"
                  << "Front of 99 % of the mass " << std::setprecision(6) << massFront << " m\n"
                  << frontResolution.report(last.front)
                  << step << " steps, " << points.count << " particles, wall time " << std::setprecision(3)
                  << summary.wallTime << " s, " << particleUpdates/summary.wallTime
                  << " particle-updates/s on " << backend << "\nEnd\n" << std::endl;
        return 0;
    });
}
