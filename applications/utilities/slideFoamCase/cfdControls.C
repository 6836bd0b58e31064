#include "cfdControls.H"

#include <sstream>

namespace slide
{
namespace cfd
{

CfdControls CfdControls::read(const scene::Dictionary& d, const std::string& overrideSetting)
{
    d.checkKnownKeys({"FoamFile", "setting", "cellsPerHeight", "reach", "reachFactor", "behind", "heightRatio",
                      "aheadHeightRatio", "aheadHeightFrom", "top", "ambientRelaxationTime", "baseRefinement", "baseGrowth", "regularisation",
                      "pressureCoupling", "outerCorrectors", "alongSlopeGravity", "conservePlugMomentum", "transposeShear", "baseStrength", "baseSlideTrace", "shearBandThickness", "rateWallFunction", "faceViscosity",
                      "plugCreepRate", "momentumTolerance", "processors", "endTime"});
    CfdControls c;
    c.setting = scene::readSetting(d, overrideSetting, {"reference", "fast"}, "fast");
    c.cellsPerHeight = c.setting == "reference" ? 60 : 20;
    c.resolutionKey = d.found("cellsPerHeight") ? "cellsPerHeight" : "setting";
    c.resolutionLine = d.lineOf(c.resolutionKey);
    if (d.found("cellsPerHeight"))
    {
        c.cellsPerHeight = d.getLabel("cellsPerHeight");
        if (c.cellsPerHeight < 2 || c.cellsPerHeight > 2000)
        {
            d.fail("cellsPerHeight", "must lie in [2, 2000], got " + std::to_string(c.cellsPerHeight));
        }
    }
    if (d.found("reach")) c.reach = d.getScalarInRange("reach", 0.0, 1e6, false, true, "reach ahead of the front [m]");
    if (d.found("reachFactor"))
    {
        c.reachFactor = d.getScalarInRange("reachFactor", 1.0, 10.0, true, true, "reach factor");
    }
    if (d.found("behind")) c.behind = d.getScalarInRange("behind", 0.0, 1e6, true, true, "mesh behind the rear [m]");
    if (d.found("heightRatio"))
    {
        c.heightRatio = d.getScalarInRange("heightRatio", 1.05, 100.0, true, true, "mesh height / H0");
    }
    c.aheadHeightRatio = c.heightRatio;
    if (d.found("aheadHeightRatio"))
    {
        c.aheadHeightRatio = d.getScalarInRange("aheadHeightRatio", 0.2, c.heightRatio, true, true,
                                                "mesh height / H0 ahead of the slide (at most heightRatio)");
    }
    if (d.found("aheadHeightFrom"))
    {
        c.aheadHeightFrom = d.getScalarInRange("aheadHeightFrom", 0.0, 1e6, true, true,
                                               "where the lower top starts, ahead of the initial front [m]");
    }
    if (d.found("top")) c.top = d.getWordOneOf("top", {"open", "slip"});
    if (d.found("ambientRelaxationTime"))
    {
        c.ambientRelaxationTime = d.getScalarInRange("ambientRelaxationTime", 0.0, 1e9, false, true,
                                                     "the light ambient's relaxation time [s]");
    }
    if (d.found("baseRefinement"))
    {
        c.baseRefinement = d.getLabel("baseRefinement");
        c.baseRefinementLine = d.lineOf("baseRefinement");
        if (c.baseRefinement < 1 || c.baseRefinement > 64)
        {
            d.fail("baseRefinement", "must lie in [1, 64], got " + std::to_string(c.baseRefinement));
        }
    }
    if (d.found("baseGrowth"))
    {
        c.baseGrowth = d.getScalarInRange("baseGrowth", 1.0, 2.0, false, true, "cell growth ratio away from the base");
    }
    if (d.found("regularisation")) c.regularisation = d.getWordOneOf("regularisation", {"cap", "papanastasiou"});
    if (d.found("pressureCoupling"))
    {
        c.pressureCoupling = d.getWordOneOf("pressureCoupling", {"simplec", "piso"});
    }
    if (d.found("outerCorrectors"))
    {
        c.outerCorrectors = d.getLabel("outerCorrectors");
        if (c.outerCorrectors < 1 || c.outerCorrectors > 50)
        {
            d.fail("outerCorrectors", "must lie in [1, 50], got " + std::to_string(c.outerCorrectors));
        }
    }
    if (d.found("alongSlopeGravity"))
    {
        c.alongSlopeGravity = d.getWordOneOf("alongSlopeGravity", {"pressure", "faceForce"});
        if (c.alongSlopeGravity == "faceForce" && c.outerCorrectors < 3)
        {
            d.fail("alongSlopeGravity", "faceForce needs outerCorrectors 3 or more: one SIMPLEC step takes the face "
                   "force with a momentum error (the flume's front +11 %), got outerCorrectors "
                   + std::to_string(c.outerCorrectors));
        }
    }
    c.conservePlugMomentum = d.getBool("conservePlugMomentum", false);
    c.transposeShear = d.found("transposeShear") ? d.getWordOneOf("transposeShear", {"nearKinks", "runningMean"})
                     : c.conservePlugMomentum ? "runningMean" : "nearKinks";
    if (d.found("baseStrength")) c.baseStrength = d.getWordOneOf("baseStrength", {"slideShare", "wholeFace"});
    if (d.found("baseSlideTrace"))
    {
        c.baseSlideTrace = d.getScalarInRange("baseSlideTrace", 0.0, 1.0, true, false,
                                              "slide trace (the alpha below which a base face is the ambient's)");
    }
    c.rateWallFunction = d.getBool("rateWallFunction", false);
    if (c.rateWallFunction && c.regularisation != "cap")
    {
        d.fail("rateWallFunction", "the wall function follows Eq. (1)'s profile under the viscosity cap: it needs"
               " regularisation cap, got " + c.regularisation);
    }
    c.faceViscosity = d.getBool("faceViscosity", false);
    if (d.found("plugCreepRate"))
    {
        c.plugCreepRate = d.getScalarInRange("plugCreepRate", 0.0, 1e3, false, true, "plug creep rate [1/s]");
    }
    if (d.found("momentumTolerance"))
    {
        c.momentumTolerance = d.getScalarInRange("momentumTolerance", 1e-14, 1e-3, true, true,
                                                 "momentum predictor's absolute tolerance");
    }
    if (d.found("shearBandThickness"))
    {
        c.shearBandThickness = d.getScalarInRange("shearBandThickness", 0.0, 1e6, true, true,
                                                  "shear band thickness xi counts [m] (0: per cell)");
    }
    if (d.found("processors"))
    {
        c.processors = d.getLabel("processors");
        if (c.processors < 1 || c.processors > 4096)
        {
            d.fail("processors", "must lie in [1, 4096], got " + std::to_string(c.processors));
        }
    }
    if (d.found("endTime")) c.endTime = d.getScalarInRange("endTime", 0.0, 1e9, false, true, "slideFoam's end time [s]");
    return c;
}

std::string CfdControls::describe() const
{
    std::ostringstream os;
    os << "setting " << setting << ", H0/" << cellsPerHeight;
    if (baseRefinement > 1) os << " (H0/" << cellsPerHeight*baseRefinement << " on the base)";
    os << ", height " << heightRatio << " H0";
    if (aheadHeightRatio < heightRatio)
    {
        os << " (" << aheadHeightRatio << " H0 from ";
        if (aheadHeightFrom < 0.0) os << "H0";
        else os << aheadHeightFrom << " m";
        os << " ahead of the slide on)";
    }
    if (top != "open") os << ", " << top << " top";
    if (ambientRelaxationTime > 0.0) os << ", ambient relaxed to rest in " << ambientRelaxationTime << " s";
    os << ", regularisation " << regularisation << ", pressure coupling " << pressureCoupling;
    if (outerCorrectors > 1) os << " with " << outerCorrectors << " outer correctors";
    if (alongSlopeGravity != "pressure") os << ", gravity's along-slope part as a face force";
    os
       << (conservePlugMomentum ? ", plug momentum conserved" : "")
       << (transposeShear == "runningMean" && !conservePlugMomentum ? ", the base's transpose flux's running mean taken out" : "")
       << (transposeShear == "nearKinks" && conservePlugMomentum ? ", the base's transpose flux kept away from kinks" : "")
       << (baseStrength == "wholeFace" ? ", s_b on every base face the slide touches" : "")
       << (rateWallFunction ? ", Eq. (1)'s wall function on the base" : "")
       << (faceViscosity ? ", the slide's viscosity at each face's rate" : "")
       << ", momentum tolerance " << momentumTolerance << ", processors " << processors;
    if (baseSlideTrace > 0.0) os << ", base faces under less than " << baseSlideTrace << " of slide the ambient's";
    else os << ", no slide-trace floor on the base";
    if (shearBandThickness > 0.0) os << ", xi counts shear bands " << shearBandThickness << " m thick";
    if (endTime > 0.0) os << ", slideFoam ends at " << endTime << " s";
    return os.str();
}

} // namespace cfd
} // namespace slide
