// slideDAM: the depth-averaged method of Dong, Wang & Cui (2020), Eqs. (2)-(5),
// on the BING model (Imran, Harff & Parker 2001).
//
// Foundation stage: reads and validates the scene and system/damDict, and
// writes the output contract for the initial state (a zero-length run). The
// solver itself is the slideDAM issue.
#include "application.H"
#include "outputContract.H"
#include "scene.H"

#include <iostream>

using namespace slide;

int main(int argc, char** argv)
{
    output::ArgList args(argc, argv, "slideDAM",
        "Depth-averaged runout of a submarine slide (enhanced BING, Dong et al. 2020)", {});
    return output::runGuarded("slideDAM", [&]()
    {
        args.printBanner();
        output::prepareOutput(args.caseDir(), "slideDAM");
        const scene::Scene sc = scene::Scene::read(args.caseDir());
        const scene::Dictionary damDict = scene::readMethodDict(args.caseDir(), "damDict");
        damDict.checkKnownKeys({"FoamFile"});

        std::cout << "Scene: " << sc.title << "\n    slide " << sc.slide.length << " x " << sc.slide.height
                  << " m, rho' " << sc.slide.density << " kg/m3, s_uo " << sc.rheology.s_uo << " Pa\n"
                  << "    base " << (sc.base.isPlanar() ? "planar" : "polyline") << ", interface "
                  << sc.interface.typeName() << "\n" << std::endl;

        output::Progress progress(sc.control.startTime, sc.control.startTime);
        output::RunoutLog log(args.caseDir(), "slideDAM");
        output::RunoutSample s0;
        s0.time = sc.control.startTime;
        s0.rear = -sc.slide.length;
        s0.maxThickness = sc.slide.height;
        s0.mass = sc.slide.density*sc.slide.area();
        log.write(s0);
        progress.report(s0.time, 0, true);

        output::Summary summary;
        summary.method = "slideDAM";
        summary.caseName = sc.caseName;
        summary.runout = 0.0;
        summary.endTime = sc.control.startTime;
        summary.atRest = false;
        summary.wallTime = progress.elapsed();
        summary.problemSize = 0;
        summary.problemSizeUnit = "columns";
        summary.backend = "serial";
        summary.addString("status", "zero-length run: the DAM solver is not built yet");
        summary.write(args.caseDir());
        std::cout << "End\n" << std::endl;
        return 0;
    });
}
