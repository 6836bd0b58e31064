#include "mpmControls.H"

#include "scene.H"

#include <sstream>

namespace slide
{
namespace mpm
{

MpmControls MpmControls::read(const scene::Dictionary& d, const std::string& overrideSetting)
{
    d.checkKnownKeys({"FoamFile", "setting", "cellsPerHeight", "particlesPerCell", "courant", "deltaT", "youngsModulusRatio",
                      "poissonRatio", "volumetricLocking", "stressQuadrature", "transfer", "baseBoundary", "baseContact", "baseRowMassScaling", "strainRate", "stressRate", "initialStress", "shearBandThickness", "shearBandRate", "particleSplitting", "maxParticleLength", "particleShifting", "writeFields", "writeState",
                      "purgeState", "progressInterval", "phaseTimes", "writeInBackground", "nodeSums", "blockParticles"});
    MpmControls c;
    c.setting = scene::readSetting(d, overrideSetting, {"reference", "fast"}, "reference");
    if (c.setting == "fast")
    {
        // Measured against finer runs in validation/mpm (README there).
        c.cellsPerHeight = 20;
        c.particlesPerCell = 2;
    }
    c.resolutionKey = d.found("cellsPerHeight") ? "cellsPerHeight" : "setting";
    c.resolutionLine = d.lineOf(c.resolutionKey);
    if (d.found("cellsPerHeight"))
    {
        c.cellsPerHeight = d.getLabel("cellsPerHeight");
        if (c.cellsPerHeight < 2 || c.cellsPerHeight > 100000)
        {
            d.fail("cellsPerHeight", "cells per slide height must lie in [2, 1e5], got "
                   + std::to_string(c.cellsPerHeight));
        }
    }
    if (d.found("particlesPerCell"))
    {
        c.particlesPerCell = d.getLabel("particlesPerCell");
        if (c.particlesPerCell < 1 || c.particlesPerCell > 32)
        {
            d.fail("particlesPerCell", "particles per cell and direction must lie in [1, 32], got "
                   + std::to_string(c.particlesPerCell));
        }
    }
    if (d.found("courant")) c.courant = d.getScalarInRange("courant", 0.0, 1.0, false, true, "Courant number");
    if (d.found("deltaT")) c.deltaT = d.getScalarInRange("deltaT", 0.0, 1e6, false, true, "fixed time step [s]");
    if (d.found("youngsModulusRatio"))
    {
        c.youngsModulusRatio =
            d.getScalarInRange("youngsModulusRatio", 1.0, 1e6, true, true, "Young's modulus / s_uo");
    }
    if (d.found("poissonRatio"))
    {
        c.poissonRatio = d.getScalarInRange("poissonRatio", 0.0, 0.5, true, false, "Poisson's ratio");
    }
    if (d.found("volumetricLocking"))
    {
        c.volumetricLocking = d.getWordOneOf("volumetricLocking", {"cellAveraging", "none"}) == "none"
            ? VolumetricLocking::none : VolumetricLocking::cellAveraging;
    }
    if (d.found("transfer"))
    {
        const std::string t = d.getWordOneOf("transfer", {"apic", "quadratic", "pic"});
        c.transfer = t == "pic" ? Transfer::pic : t == "apic" ? Transfer::apic : Transfer::quadratic;
    }
    if (d.found("baseBoundary"))
    {
        c.baseBoundary = d.getWordOneOf("baseBoundary", {"fitted", "levelSet"}) == "fitted"
            ? BaseBoundary::fitted : BaseBoundary::levelSet;
    }
    if (d.found("baseContact"))
    {
        c.baseContact = d.getWordOneOf("baseContact", {"touching", "withinCell"}) == "touching"
                      ? BaseContact::touching : BaseContact::withinCell;
    }
    c.baseRowMassScaling = d.getBool("baseRowMassScaling", true);
    if (d.found("stressQuadrature"))
    {
        c.stressQuadrature = d.getWordOneOf("stressQuadrature", {"particleVolume", "cellCapped"}) == "cellCapped"
                           ? StressQuadrature::cellCapped : StressQuadrature::particleVolume;
        if (c.stressQuadrature == StressQuadrature::cellCapped
            && c.volumetricLocking != VolumetricLocking::cellAveraging)
        {
            d.fail("stressQuadrature", "cellCapped needs the cells' particle volumes of volumetricLocking cellAveraging");
        }
    }
    if (d.found("strainRate"))
    {
        const std::string r = d.getWordOneOf("strainRate", {"plastic", "total", "previousPlastic"});
        c.plasticStrainRate = r != "total";
        c.previousStepRate = r == "previousPlastic";
    }
    if (d.found("stressRate"))
    {
        c.kirchhoffStressRate = d.getWordOneOf("stressRate", {"kirchhoff", "cauchy"}) == "kirchhoff";
    }
    if (d.found("initialStress"))
    {
        c.geostaticStart = d.getWordOneOf("initialStress", {"geostatic", "none"}) == "geostatic";
    }
    if (d.found("shearBandThickness"))
    {
        c.shearBandThickness = d.getScalarInRange("shearBandThickness", 0.0, 1e6, true, true,
                                                  "shear band thickness of the remoulding [m]");
    }
    c.shearBandRate = d.getBool("shearBandRate", false);
    if (c.shearBandRate && !(c.shearBandThickness > 0.0))
    {
        d.fail("shearBandRate", "needs a shearBandThickness > 0 (the band whose rate Eq. (1) is to see)");
    }
    c.particleSplitting = d.getBool("particleSplitting", true);
    if (d.found("maxParticleLength"))
    {
        c.maxParticleLength = d.getScalarInRange("maxParticleLength", 0.25, 100.0, true, true,
                                                 "particle domain length [cells] beyond which a particle is split");
    }
    if (d.found("particleShifting"))
    {
        // Up to 0.25: the excess diffuses by about this many cells^2 a step, and
        // the explicit step holds up to about 0.6 on the base's row (share 1/3).
        c.particleShifting = d.getScalarInRange("particleShifting", 0.0, 0.25, true, true,
                                                "particle shift per step and unit of excess fill gradient [cells]");
        if (c.particleShifting > 0.0 && c.baseBoundary != BaseBoundary::fitted)
        {
            d.fail("particleShifting", "needs baseBoundary fitted (the fill of a node the base cuts is not known)");
        }
    }
    c.writeFields = d.getBool("writeFields", true);
    c.writeState = d.getBool("writeState", true);
    if (d.found("purgeState"))
    {
        c.purgeState = d.getLabel("purgeState");
        if (c.purgeState < 0) d.fail("purgeState", "must be >= 0 (0 keeps every write's state)");
    }
    if (d.found("progressInterval"))
    {
        c.progressInterval = d.getScalarInRange("progressInterval", 0.0, 1e6, true, true, "progress interval [s]");
    }
    c.phaseTimes = d.getBool("phaseTimes", false);
    if (d.found("writeInBackground")) c.writeInBackground = d.getBool("writeInBackground", false) ? 1 : 0;
    if (d.found("nodeSums"))
    {
        c.nodeSums = d.getWordOneOf("nodeSums", {"perBlock", "perParticle"}) == "perBlock"
                   ? NodeSums::perBlock : NodeSums::perParticle;
    }
    if (d.found("blockParticles"))
    {
        c.blockParticles = d.getLabel("blockParticles");
        if (c.blockParticles < 1 || c.blockParticles > 1024)
        {
            d.fail("blockParticles", "particles per block must lie in [1, 1024], got " + std::to_string(c.blockParticles));
        }
    }
    return c;
}

UndrainedClay MpmControls::clay(const rheology::HerschelBulkleyRemoulding& strength, const double cellSize) const
{
    UndrainedClay c = UndrainedClay::fromYoungs(strength, youngsModulusRatio*strength.s_uo, poissonRatio,
                                                plasticStrainRate);
    c.previousStepRate = previousStepRate;
    c.kirchhoffRate = kirchhoffStressRate;
    c.bandStrainFactor = rheology::shearBandStrainFactor(shearBandThickness, cellSize);
    c.bandRateFactor = shearBandRate ? c.bandStrainFactor : 1.0;
    return c;
}

std::string MpmControls::describe(const double cellSize) const
{
    std::ostringstream os;
    os << "setting " << setting << ": cell H0/" << cellsPerHeight << ", " << particlesPerCell << "x"
       << particlesPerCell << " particles per cell, quadratic B-splines"
       << (baseBoundary == BaseBoundary::fitted
           ? (baseContact == BaseContact::touching ? " fitted to the base (contact where the material touches it)"
                                                   : " fitted to the base (contact within its nodes' cell)")
           : " cut by the base")
       << (baseBoundary == BaseBoundary::fitted && !baseRowMassScaling ? " (no mass scaling of the row above it)" : "")
       << ", " << (transfer == Transfer::quadratic ? "APIC + quadratic mode across the base (PolyPIC)"
           : transfer == Transfer::apic ? "APIC" : "PIC") << " transfer, volumetric locking "
       << (volumetricLocking == VolumetricLocking::cellAveraging ? "cell averaging (B-bar)" : "not treated")
       << (stressQuadrature == StressQuadrature::cellCapped ? ", stress quadrature capped at each cell's area" : "")
       << ", Eq. (1) at the " << (!plasticStrainRate ? "total" : previousStepRate ? "previous step's plastic"
                                                                                  : "plastic") << " shear strain rate"
       << ", elasticity in the Jaumann rate of the " << (kirchhoffStressRate ? "Kirchhoff" : "Cauchy") << " stress"
       << (geostaticStart ? "" : ", released stress free")
       << ", Courant " << courant << " (Eq. 6)"
       << (deltaT > 0.0 ? ", overridden by a fixed deltaT " + std::to_string(deltaT) + " s" : std::string())
       << ", E = " << youngsModulusRatio << " s_uo, nu = " << poissonRatio;
    if (shearBandThickness > 0.0)
    {
        os << ", xi counts shear bands " << shearBandThickness << " m thick (band strain = "
           << rheology::shearBandStrainFactor(shearBandThickness, cellSize) << " x cell strain"
           << (shearBandRate ? ", and Eq. (1) their rate: the same factor x cell rate" : "") << ")";
    }
    if (particleSplitting) os << ", particles split when longer than " << maxParticleLength << " cell(s)";
    else os << ", no particle splitting";
    if (particleShifting > 0.0) os << ", particles shifted out of overfull nodes (" << particleShifting << " cell per step and unit of excess)";
    return os.str();
}

} // namespace mpm
} // namespace slide
