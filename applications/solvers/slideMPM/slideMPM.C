// slideMPM: an explicit material point method for submarine slides on Kokkos
// (OpenMP, CUDA and Serial backends from one source).
//
// Foundation stage: initialises Kokkos, reads and validates the scene and
// system/mpmDict, and writes the output contract for the initial state (a
// zero-length run). The solver itself is the slideMPM issue.
#include <Kokkos_Core.hpp>

#include "HerschelBulkleyRemoulding.H"
#include "application.H"
#include "outputContract.H"
#include "scene.H"

#include <iostream>

using namespace slide;

int main(int argc, char** argv)
{
    output::ArgList args(argc, argv, "slideMPM",
        "Material point method runout of a submarine slide on Kokkos", {});
    Kokkos::ScopeGuard kokkos(argc, argv);
    return output::runGuarded("slideMPM", [&]()
    {
        args.printBanner();
        output::prepareOutput(args.caseDir(), "slideMPM");
        const scene::Scene sc = scene::Scene::read(args.caseDir());
        const scene::Dictionary mpmDict = scene::readMethodDict(args.caseDir(), "mpmDict");
        mpmDict.checkKnownKeys({"FoamFile"});

        const std::string backend = Kokkos::DefaultExecutionSpace::name();
        std::cout << "Backend: " << backend << " (concurrency " << Kokkos::DefaultExecutionSpace().concurrency()
                  << ")\n" << std::endl;

        // One device evaluation of Eq. (1) checks that the shared rheology runs in kernels.
        const rheology::HerschelBulkleyRemoulding material = sc.rheology;
        double su = 0.0;
        Kokkos::parallel_reduce("strengthAtReferenceRate", 1,
            KOKKOS_LAMBDA(const int, double& s) { s += material.strength(material.gdotRef, 0.0); }, su);
        std::cout << "s_u(gdotRef, xi = 0) = " << su << " Pa\n" << std::endl;

        output::Progress progress(sc.control.startTime, sc.control.startTime);
        output::RunoutLog log(args.caseDir(), "slideMPM");
        output::RunoutSample s0;
        s0.time = sc.control.startTime;
        s0.rear = -sc.slide.length;
        s0.maxThickness = sc.slide.height;
        s0.mass = sc.slide.density*sc.slide.area();
        log.write(s0);
        progress.report(s0.time, 0, true);

        output::Summary summary;
        summary.method = "slideMPM";
        summary.caseName = sc.caseName;
        summary.endTime = sc.control.startTime;
        summary.wallTime = progress.elapsed();
        summary.problemSizeUnit = "particles";
        summary.backend = backend;
        summary.addString("status", "zero-length run: the MPM solver is not built yet");
        summary.write(args.caseDir());
        std::cout << "End\n" << std::endl;
        return 0;
    });
}
