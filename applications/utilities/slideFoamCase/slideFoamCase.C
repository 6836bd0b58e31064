// slideFoamCase: builds slideFoam's CFD case from the scene every method reads
// (constant/sceneProperties, system/controlDict) and system/cfdDict, in the
// same case directory, the OpenFOAM way:
//   system/blockMeshDict    a 2D mesh along the base, sized to the slide's reach:
//                           planar, in the slope's frame (x along the slope, y
//                           normal to it, gravity tilted); polyline, vertical
//                           columns over the segments in the global frame
//   system/fvSchemes, fvSolution, decomposeParDict
//   constant/g              gravity in the mesh's frame
//   constant/transportProperties, turbulenceProperties
//   0.orig/                 alpha.slide (the slide's initial extent), U, p_rgh,
//                           xi with the base condition
//   <case>.foam             for ParaView's OpenFOAM reader
// then: blockMesh; cp -r 0.orig 0; slideFoam (runSlideFoam in the tutorials' Allrun).
//
//   slideFoamCase [-case dir] [-setting reference|fast]
#include "application.H"
#include "cfdControls.H"
#include "meshLayout.H"
#include "outputContract.H"
#include "scene.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>
#include <sys/stat.h>

using namespace slide;

namespace
{

const double pi = 3.14159265358979323846;

std::string header(const std::string& cls, const std::string& object, const std::string& location = "")
{
    std::ostringstream os;
    os << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
       << "  Written by slideFoamCase from constant/sceneProperties and system/cfdDict:\n"
       << "  edit those and run slideFoamCase again rather than editing this file.\n"
       << "\\*---------------------------------------------------------------------------*/\n"
       << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       " << cls << ";\n";
    if (!location.empty()) os << "    location    \"" << location << "\";\n";
    os << "    object      " << object << ";\n}\n\n";
    return os.str();
}

void writeFile(const std::string& path, const std::string& text)
{
    std::ofstream os(path);
    if (!os) throw std::runtime_error("cannot write " + path);
    os << text;
}

// slideDAM's runout from an earlier run in the same case, or -1.
double damRunout(const std::string& caseDir)
{
    std::ifstream is(caseDir + "/postProcessing/slideDAM/summary.json");
    if (!is) return -1.0;
    std::stringstream ss;
    ss << is.rdbuf();
    const std::string text = ss.str();
    const std::string key = "\"runout_m\":";
    const auto pos = text.find(key);
    if (pos == std::string::npos) return -1.0;
    return std::atof(text.c_str() + pos + key.size());
}

// The farthest upslope slideDAM's rear got (arc length from the initial front), or 1 if none.
double damRearMin(const std::string& caseDir)
{
    std::ifstream is(caseDir + "/postProcessing/slideDAM/runout.dat");
    if (!is) return 1.0;
    std::string line;
    double rearMin = 1.0;
    while (std::getline(is, line))
    {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        double t, front, rear;
        if (ls >> t >> front >> rear) rearMin = std::min(rearMin, rear);
    }
    return rearMin;
}

// The patches closed to flow (base, a rear wall, a lid) and those open to the
// ambient, as a boundaryField key ("base" or "\"(base|upslope)\"").
struct PatchGroups
{
    std::string walls, open;
};

PatchGroups patchGroups(const scene::Scene& sc, const cfd::CfdControls& c)
{
    std::vector<std::string> walls{"base"}, open{"downslope"};
    (sc.slide.rearWall ? walls : open).push_back("upslope");
    (c.top == "slip" ? walls : open).push_back("top");
    auto key = [](const std::vector<std::string>& names)
    {
        if (names.size() == 1) return names.front();
        std::string k = "\"(";
        for (std::size_t i = 0; i < names.size(); ++i) k += (i ? "|" : "") + names[i];
        return k + ")\"";
    };
    return {key(walls), key(open)};
}

// boundaryField entries of alpha.slide and xi: zero gradient on walls, nothing
// carried in where ambient fluid enters.
std::string scalarBoundaries(const PatchGroups& g)
{
    return "    " + g.walls + "\n    {\n        type            zeroGradient;\n    }\n"
           "    " + g.open + "\n    {\n        type            inletOutlet;\n        inletValue      uniform 0;\n"
           "        value           uniform 0;\n    }\n"
           "    frontAndBack\n    {\n        type            empty;\n    }\n";
}

std::string num(double v)
{
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
}

} // namespace

int main(int argc, char** argv)
{
    output::ArgList args(argc, argv, "slideFoamCase",
        "Builds slideFoam's CFD case (mesh, fields, numerics) from the scene",
        {{"setting", "name", "reference | fast (overrides system/cfdDict)"}});
    return output::runGuarded("slideFoamCase", [&]()
    {
        args.printBanner();
        const std::string caseDir = args.caseDir();
        const scene::Scene sc = scene::Scene::read(caseDir);
        const scene::Dictionary cfdDict = scene::readMethodDict(caseDir, "cfdDict");
        const cfd::CfdControls c = cfd::CfdControls::read(cfdDict, args.get("setting"));
        const std::string cfdFile = caseDir + "/system/cfdDict";

        if (c.endTime > 0.0 && !(c.endTime > sc.control.startTime && c.endTime <= sc.control.endTime))
        {
            cfdDict.fail("endTime", "slideFoam's end time " + num(c.endTime) + " s must lie after the start time "
                         + num(sc.control.startTime) + " s and not after the scene's end time " + num(sc.control.endTime)
                         + " s (system/controlDict)");
        }
        if (c.ambientRelaxationTime > 0.0 && sc.ambient.phase == scene::Ambient::Phase::water)
        {
            cfdDict.fail("ambientRelaxationTime", "damps a light ambient only; this scene's ambient is water, "
                         "whose drag and added mass act on the slide (constant/sceneProperties ambient)");
        }
        // The wall function is Eq. (1)'s rate profile through a no-slip wall cell: refused where it could not act,
        // since the solver would otherwise run the case as if it had never been asked for.
        if (c.rateWallFunction && !(sc.rheology.eta > 0.0))
        {
            cfdDict.fail("rateWallFunction", "follows Eq. (1)'s rate term through the base's cell; this scene's slide "
                         "has none (eta 0, constant/sceneProperties rheology)");
        }
        if (c.rateWallFunction && sc.interface.type != scene::Interface::Type::noSlip)
        {
            cfdDict.fail("rateWallFunction", "acts on a no-slip base; this scene's base is "
                         + sc.interface.typeName() + " (constant/sceneProperties base interface)");
        }
        if (c.alongSlopeGravity == "faceForce" && !sc.base.isPlanar())
        {
            cfdDict.fail("alongSlopeGravity", "faceForce splits gravity in the slope's frame, which a planar base has;"
                         " this scene's base is a polyline, meshed with gravity down (constant/sceneProperties base)");
        }
        const double H0 = sc.slide.height;
        const PatchGroups patches = patchGroups(sc, c);
        const bool lid = c.top == "slip";
        double reach = c.reach;
        std::string reachFrom = "system/cfdDict reach";
        if (reach <= 0.0)
        {
            const double dam = damRunout(caseDir);
            if (dam < 0.0)
            {
                throw scene::InputError(cfdFile, 0, "reach",
                                        "no reach given and no slideDAM result (postProcessing/slideDAM/summary.json) "
                                        "to size the mesh from: give reach [m] or run slideDAM first");
            }
            reach = c.reachFactor*dam + 2.0*H0;
            reachFrom = num(c.reachFactor) + " x slideDAM's runout " + num(dam) + " m + 2 H0";
        }
        double behind = c.behind;
        std::string behindFrom = "system/cfdDict behind";
        if (behind < 0.0)
        {
            const double rearMin = damRearMin(caseDir);
            if (sc.slide.rearWall)
            {
                behind = 0.0;
                behindFrom = "the rear wall";
            }
            else if (rearMin < 1.0)
            {
                // The rear spreads upslope as the slide collapses: size from the DAM's farthest rear.
                behind = c.reachFactor*std::max(0.0, -rearMin - sc.slide.length) + 2.0*H0;
                behindFrom = num(c.reachFactor) + " x slideDAM's upslope spreading "
                             + num(std::max(0.0, -rearMin - sc.slide.length)) + " m + 2 H0";
            }
            else
            {
                behind = 2.0*H0;
                behindFrom = "2 H0 (no slideDAM result)";
            }
        }

        const cfd::MeshLayout mesh = cfd::MeshLayout::build(sc, c, behind, reach);
        output::checkMemory(static_cast<unsigned long long>(double(mesh.nCells())*2000.0),
                            std::to_string(mesh.nCells()) + " cells", cfdFile,
                            c.resolutionLine, c.resolutionKey);

        const bool water = sc.ambient.phase == scene::Ambient::Phase::water;
        // In water the slide carries its full density and buoyancy comes from the
        // water's pressure; in a light ambient the submerged density does both.
        const double rhoSlide = sc.slide.density + (water ? sc.ambient.density : 0.0);
        const double theta = sc.base.angle(0.0);
        const double creep = c.plugCreepRate > 0.0 ? c.plugCreepRate : 1e-3*std::sqrt(sc.g/H0);
        const double muMax = sc.rheology.strength(creep, 0.0)/creep;

        std::cout << sc.describe() << "\nCFD set-up: " << c.describe() << "\n"
                  << "  mesh " << mesh.describe() << "\n"
                  << "  reach ahead of the front " << reach << " m (" << reachFrom << ")\n"
                  << "  mesh behind the rear " << behind << " m (" << behindFrom << ")\n"
                  << "  slide density " << rhoSlide << " kg/m3 in a " << (water ? "water" : "light") << " ambient of "
                  << sc.ambient.density << " kg/m3\n"
                  << "  plug creep rate " << creep << " 1/s: " << (c.regularisation == "cap"
                      ? "muMax = " + num(muMax) + " Pa s" : "m = " + num(1.0/creep) + " s") << "\n" << std::endl;
        if (c.baseRefinement > 4)
        {
            // Measured, not a limit of the mesh: a nose overrides base cells this flat and
            // rides on the light ambient left in them (validation/cfd/README.md).
            std::cout << "Warning: " << cfdFile << ":" << c.baseRefinementLine << ": key 'baseRefinement': base cells "
                      << c.baseRefinement << " times thinner than the columns are wide; above 4 a head's nose has "
                      << "ridden over light ambient left in the wall cells and broken away (validation/cfd/README.md, "
                      << "\"Ambient under the nose\"): refine the columns (cellsPerHeight) with the base\n" << std::endl;
        }

        if (sc.slidesFreelyStrongerThan(scene::Scene::cfdStrongBlockRatio))
        {
            std::ostringstream ratio;
            ratio << std::setprecision(3) << sc.strengthOverWeightStress();
            std::cout << "Warning: " << scene::Scene::sceneFile() << ": rheology s_uo " << num(sc.rheology.s_uo)
                      << " Pa is " << ratio.str() << " times the slide's weight stress rho' g H0 ("
                      << num(std::round(sc.slide.density*sc.g*sc.slide.height)) << " Pa), and it slides on its "
                      << sc.interface.typeName() << " base: slideFoam's capped plug has slid blocks this strong "
                      << "wrongly (the flume's slurry: blow-ups in two of three runs at 3.2 times; at 8 and 16 times 8.5 and "
                      << "53 % short of the rigid block's law; validation/cfd/strongBlock.md). Check the result against the "
                      << "rigid block's law, slideDAM or slideMPM\n" << std::endl;
        }

        if (!sc.base.isPlanar() && c.transposeShear == "nearKinks" && sc.slidesFreelyStrongerThan(scene::Scene::facesStandRatio))
        {
            // A block whose faces stand slides as a plug, and a polyline's cells lie a few mm/s
            // off its base: with a plug's viscosity the transpose flux that nearKinks keeps
            // pushed a 15 kPa block on a straight 5 deg polyline 80 Pa beyond s_b
            // (validation/cfd/README.md, session 91).
            std::cout << "Warning: " << cfdFile << ": key 'transposeShear': nearKinks on a polyline " << sc.interface.typeName()
                      << " base under a block whose faces stand (s_uo " << num(sc.rheology.s_uo) << " Pa against rho' g H0 "
                      << num(std::round(sc.slide.density*sc.g*sc.slide.height)) << " Pa): the base's explicit transpose "
                      << "flux pushed such a block 80 Pa beyond s_b on a straight polyline. For a block that slides far, set "
                      << "transposeShear runningMean (or conservePlugMomentum yes); it shakes a block its base holds "
                      << "(validation/cfd/README.md)\n" << std::endl;
        }

        mkdir((caseDir + "/0.orig").c_str(), 0755);
        const std::string rearPatchType = sc.slide.rearWall ? "wall" : "patch";

        // --- mesh and the slide's initial extent
        writeFile(caseDir + "/system/blockMeshDict", header("dictionary", "blockMeshDict", "system")
                  + mesh.blockMeshDict(sc.slide.rearWall ? "wall" : "patch",
                                                       lid ? "wall" : "patch"));
        {
            double area = 0.0;
            const std::vector<double> alpha = mesh.slideFraction(sc, &area);
            std::cout << "  slide area on the mesh " << num(area) << " m2 (the scene's " << num(sc.slide.area())
                      << " m2)\n" << std::endl;
            std::ostringstream os;
            os << header("volScalarField", "alpha.slide", "0") << "dimensions      [0 0 0 0 0 0 0];\n\n"
               << "// The share of each cell inside the slide (constant/sceneProperties)\n"
               << "internalField   nonuniform List<scalar>\n" << alpha.size() << "\n(\n";
            os.precision(12);   // the cut cells' shares sum to the scene's area to 1e-9
            for (double a : alpha) os << a << "\n";
            os << ")\n;\n\nboundaryField\n{\n" << scalarBoundaries(patches) << "}\n";
            writeFile(caseDir + "/0.orig/alpha.slide", os.str());
        }
        // --- physics
        {
            std::ostringstream os;
            os << header("uniformDimensionedVectorField", "g", "constant");
            if (sc.base.isPlanar())
            {
                os << "// planar base at " << num(theta*180.0/pi) << " deg: x along the slope, y normal to it\n"
                   << "dimensions      [0 1 -2 0 0 0 0];\nvalue           (" << num(sc.g*std::sin(theta)) << " "
                   << num(-sc.g*std::cos(theta)) << " 0);\n";
            }
            else
            {
                os << "// polyline base: x horizontal, y up\n"
                   << "dimensions      [0 1 -2 0 0 0 0];\nvalue           (0 " << num(-sc.g) << " 0);\n";
            }
            writeFile(caseDir + "/constant/g", os.str());
        }
        {
            std::ostringstream os;
            os << header("dictionary", "transportProperties", "constant") << "phases (slide ambient);\n\n"
               << "slide\n{\n    // Eq. (1) with the scene's rheology, read from constant/sceneProperties\n"
               << "    transportModel  slideRheology;\n    slideRheologyCoeffs\n    {\n"
               << "        regularisation  " << c.regularisation << ";\n"
               << "        muMax           " << num(muMax) << ";   // s_u(rate)/rate at the plug creep rate "
               << num(creep) << " 1/s\n"
               << "        m               " << num(1.0/creep) << ";\n"
               << (c.shearBandThickness > 0.0
                   ? "        shearBandThickness " + num(c.shearBandThickness) + ";   // cfdDict: xi per band this thick\n"
                   : "")
               << (c.rateWallFunction ? "        baseWallFunction yes;   // cfdDict rateWallFunction\n" : "")
               << (c.faceViscosity ? "        faceViscosity   yes;   // cfdDict faceViscosity\n" : "")
               << "    }\n"
               << "    rho             " << num(rhoSlide) << ";\n}\n\n"
               << "ambient\n{\n    transportModel  Newtonian;\n    nu              "
               << num(sc.ambient.viscosity/sc.ambient.density) << ";\n    rho             " << num(sc.ambient.density)
               << ";\n}\n\nsigma           0;\n";
            writeFile(caseDir + "/constant/transportProperties", os.str());
            writeFile(caseDir + "/constant/turbulenceProperties",
                      header("dictionary", "turbulenceProperties", "constant") + "simulationType  laminar;\n");
            // cfdDict ambientRelaxationTime: the light ambient relaxes to rest (ambientDamping).
            const std::string fvOptionsFile = caseDir + "/constant/fvOptions";
            if (c.ambientRelaxationTime > 0.0)
            {
                writeFile(fvOptionsFile, header("dictionary", "fvOptions", "constant")
                          + "// cfdDict ambientRelaxationTime: the source -(1 - alpha) rho_ambient U / relaxationTime\n"
                            "ambientDamping\n{\n    type            ambientDamping;\n    relaxationTime  "
                          + num(c.ambientRelaxationTime) + ";\n}\n");
            }
            else if (std::ifstream in{fvOptionsFile})
            {
                // One this program wrote for an earlier cfdDict would damp a run that no longer asks for it.
                std::string firstLines(400, '\0');
                in.read(&firstLines[0], firstLines.size());
                if (firstLines.find("Written by slideFoamCase") != std::string::npos) std::remove(fvOptionsFile.c_str());
            }
        }
        // --- fields
        const std::string baseU = sc.interface.type == scene::Interface::Type::noSlip
            ? "        type            noSlip;\n"
            : "        type            slideBaseVelocity;   // " + sc.interface.typeName()
              + " base from constant/sceneProperties\n"
              + "        transposeShear  " + c.transposeShear + ";   // cfdDict transposeShear\n"
              + (c.baseStrength == "wholeFace" ? "        baseStrength    wholeFace;   // cfdDict baseStrength\n" : "")
              + "        slideTrace      " + num(c.baseSlideTrace) + ";   // cfdDict baseSlideTrace\n"
              + "        value           uniform (0 0 0);\n";
        const std::string rearU = sc.slide.rearWall ? "        type            noSlip;\n"
            : "        type            pressureInletOutletVelocity;\n        value           uniform (0 0 0);\n";
        {
            std::ostringstream os;
            os << header("volVectorField", "U", "0") << "dimensions      [0 1 -1 0 0 0 0];\n\n"
               << "internalField   uniform (0 0 0);\n\nboundaryField\n{\n"
               << "    base\n    {\n" << baseU << "    }\n"
               << "    upslope\n    {\n" << rearU << "    }\n"
               << "    " << (lid ? "downslope" : "\"(top|downslope)\"")
               << "\n    {\n        type            pressureInletOutletVelocity;\n"
               << "        value           uniform (0 0 0);\n    }\n"
               << (lid ? "    top\n    {\n        type            slip;   // cfdDict top slip: a lid\n    }\n"
                                   : "")
               << "    frontAndBack\n    {\n        type            empty;\n    }\n}\n";
            writeFile(caseDir + "/0.orig/U", os.str());
        }
        {
            std::ostringstream os;
            os << header("volScalarField", "p_rgh", "0") << "dimensions      [1 -1 -2 0 0 0 0];\n\n"
               << "internalField   uniform 0;\n\nboundaryField\n{\n"
               << "    " << patches.walls << "\n    {\n        type            fixedFluxPressure;\n"
               << "        value           uniform 0;\n    }\n"
               << "    " << patches.open << "\n    {\n        type            totalPressure;\n"
               << "        p0              uniform 0;\n    }\n"
               << "    frontAndBack\n    {\n        type            empty;\n    }\n}\n";
            writeFile(caseDir + "/0.orig/p_rgh", os.str());
        }
        writeFile(caseDir + "/0.orig/xi", header("volScalarField", "xi", "0")
                  + "dimensions      [0 0 0 0 0 0 0];\n\ninternalField   uniform 0;\n\nboundaryField\n{\n"
                  + scalarBoundaries(patches) + "}\n");
        // --- numerics
        writeFile(caseDir + "/system/fvSchemes", header("dictionary", "fvSchemes", "system") +
R"(ddtSchemes
{
    default         Euler;
}

gradSchemes
{
    default         Gauss linear;
}

divSchemes
{
    div(rhoPhi,U)   Gauss linearUpwind grad(U);
    div(phi,alpha)  Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}

// The weight on the faces (ghf snGrad(rho)) and the pressure that holds it
// (snGrad(p_rgh) and the p_rgh equation's laplacian) take the same face
// gradient, so that a slide at rest is in discrete hydrostatic balance. Their
// non-orthogonal corrections, from interpolated cell gradients across an
// interface where rho jumps 500-1600-fold, do not balance: on a polyline base's
// sheared columns they drove a light ambient beside a slide at rest to 50 m/s
// in 10 s (validation/cfd/README.md). On an orthogonal mesh both forms agree.
laplacianSchemes
{
    default         Gauss linear corrected;
    laplacian(rAtUf,p_rgh) Gauss linear uncorrected;
}

interpolationSchemes
{
    default         linear;
}

snGradSchemes
{
    default         corrected;
    snGrad(rho)     uncorrected;
    snGrad(p_rgh)   uncorrected;
}
)");
        writeFile(caseDir + "/system/fvSolution", header("dictionary", "fvSolution", "system") +
R"(solvers
{
    "alpha.slide.*"
    {
        nAlphaCorr      1;
        // One sub-cycle: the xi transport uses the step's alpha flux.
        nAlphaSubCycles 1;
        cAlpha          1;
        MULESCorr       yes;
        nLimiterIter    5;
        solver          smoothSolver;
        smoother        symGaussSeidel;
        tolerance       1e-8;
        relTol          0;
    }

    "pcorr.*"
    {
        solver          PCG;
        preconditioner  DIC;
        tolerance       1e-5;
        relTol          0;
    }

    p_rgh
    {
        solver          GAMG;
        smoother        DIC;
        tolerance       1e-7;
        relTol          0.01;
    }

    p_rghFinal
    {
        $p_rgh;
        relTol          0;
    }

    "U.*"
    {
        // The plug's capped viscosity makes the momentum matrix stiff.
        solver          PBiCGStab;
        preconditioner  DILU;
        tolerance       )" + num(c.momentumTolerance) + R"(;
        relTol          0;
    }
}

PIMPLE
{
    momentumPredictor   yes;
    nOuterCorrectors    )" + std::to_string(c.outerCorrectors) + R"(;
    nCorrectors         3;
)" + std::string(c.alongSlopeGravity == "faceForce" ?
"    // cfdDict alongSlopeGravity faceForce: p_rgh takes gravity's normal part only.\n    alongSlopeFaceForce yes;\n" : "")
   + std::string(c.conservePlugMomentum ?
"    // cfdDict conservePlugMomentum: correctors 2 and 3 give back the momentum they take.\n    restoreCorrectorMomentum yes;\n" : "") + R"(    nNonOrthogonalCorrectors 0;
)" + std::string(c.pressureCoupling == "simplec" ?
"    // SIMPLEC: the pressure moves a plug whole (cfdDict pressureCoupling).\n    consistent          yes;\n" :
"    consistent          no;\n") + R"(}

// No relaxationFactors: even a factor of 1 makes fvMatrix::relax() add the
// largest component of a wall's coefficient to the diagonal of every component,
// which on a slipping base (directionMixed) ties the tangential velocity of the
// base cells to its old value, a drag of order mu/d that held a frictionless
// block still (validation/cfd/README.md).
)");
        {
            std::ostringstream os;
            os << header("dictionary", "decomposeParDict", "system") << "numberOfSubdomains " << c.processors
               << ";\n\nmethod          simple;\n\ncoeffs\n{\n    n           (" << c.processors << " 1 1);\n}\n";
            writeFile(caseDir + "/system/decomposeParDict", os.str());
        }
        // What this case was built with, for slideFoam's summary.json (the setting may come from -setting).
        writeFile(caseDir + "/system/cfdSetUp", header("dictionary", "cfdSetUp", "system")
                  + "setting         " + c.setting + ";\ncellsPerHeight  " + std::to_string(c.cellsPerHeight)
                  + ";\nbaseRefinement  " + std::to_string(c.baseRefinement) + ";\ntop             " + c.top + ";\n");
        writeFile(caseDir + "/" + (sc.caseName.empty() ? std::string("case") : sc.caseName) + ".foam", "");
        std::cout << "Wrote system/{blockMeshDict,fvSchemes,fvSolution,decomposeParDict,cfdSetUp}, "
                  << "constant/{g,transportProperties,turbulenceProperties" << (c.ambientRelaxationTime > 0.0 ? ",fvOptions" : "")
                  << "}, 0.orig/{U,p_rgh,alpha.slide,xi}\n"
                  << "End" << std::endl;
        return 0;
    });
}
