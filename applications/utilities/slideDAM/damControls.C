#include "damControls.H"

#include "scene.H"

#include <algorithm>
#include <sstream>

namespace slide
{
namespace dam
{

DamControls DamControls::read(const scene::Dictionary& d, const std::string& overrideSetting)
{
    d.checkKnownKeys({"FoamFile", "setting", "columns", "timeStep", "timeScheme", "courant", "deltaT", "frictionalBase", "faceStability",
                      "minShearLayerFraction", "viscosityQuadratic", "viscosityLinear", "writeFields", "writeState",
                      "progressInterval"});
    DamControls c;
    c.setting = scene::readSetting(d, overrideSetting, {"reference", "fast"}, "reference");
    if (c.setting == "fast")
    {
        // Measured against the reference in validation/dam: see README there.
        c.columns = 200;
        c.timeStep = TimeStep::adaptive;
        c.courant = 0.5;
    }
    c.resolutionKey = d.found("columns") ? "columns" : "setting";
    c.resolutionLine = d.lineOf(c.resolutionKey);
    if (d.found("columns"))
    {
        c.columns = d.getLabel("columns");
        if (c.columns < 4 || c.columns > 50000000)
        {
            d.fail("columns", "number of columns must lie in [4, 5e7], got " + std::to_string(c.columns));
        }
    }
    if (d.found("timeStep"))
    {
        c.timeStep = d.getWordOneOf("timeStep", {"paper", "adaptive"}) == "paper" ? TimeStep::paper
                                                                                 : TimeStep::adaptive;
    }
    if (d.found("timeScheme"))
    {
        c.timeScheme = d.getWordOneOf("timeScheme", {"euler", "rk3"}) == "rk3" ? TimeScheme::rk3 : TimeScheme::euler;
    }
    if (d.found("courant")) c.courant = d.getScalarInRange("courant", 0.0, 1.0, false, true, "Courant number");
    if (d.found("deltaT")) c.deltaT = d.getScalarInRange("deltaT", 0.0, 1e6, false, true, "fixed time step [s]");
    // The explicit step of Eq. (3)'s momentum-flux bracket (a central difference) amplifies the shortest
    // waves of a thin, fast sheet a little every step, and a finer column takes more steps at a given
    // Courant number: the product is what must stay bounded.
    // Shu-Osher's third-order step is stable on central differences up to a Courant number of sqrt(3).
    const double safeCourant = c.timeScheme == TimeScheme::rk3 ? 1.0 : courantColumns/c.columns;
    if (!d.found("courant"))
    {
        c.courant = std::min(c.courant, safeCourant);
    }
    else if (c.timeStep == TimeStep::adaptive && c.deltaT <= 0.0 && c.courant > safeCourant)
    {
        std::ostringstream os;
        os << "courant " << c.courant << " with " << c.columns << " columns (" << d.file() << " line "
           << d.lineOf("courant") << ") exceeds " << courantColumns << "/columns = " << safeCourant
           << ": thin, fast sheets may run short (validation/dam/sheetStability.md); leave courant out for "
           << safeCourant;
        c.courantWarning = os.str();
    }
    if (d.found("frictionalBase"))
    {
        c.frictionalBase = d.getWordOneOf("frictionalBase", {"enhanced", "original"}) == "enhanced"
            ? FrictionalBase::enhanced : FrictionalBase::original;
    }
    if (d.found("faceStability"))
    {
        const std::string f = d.getWordOneOf("faceStability", {"rankine", "gate", "none"});
        c.faceStability = f == "rankine" ? FaceStability::rankine : f == "gate" ? FaceStability::gate
                                                                               : FaceStability::none;
    }
    if (d.found("minShearLayerFraction"))
    {
        c.minShearLayerFraction =
            d.getScalarInRange("minShearLayerFraction", 0.0, 0.5, false, true, "minimum shear-layer fraction");
    }
    if (d.found("viscosityQuadratic"))
    {
        c.viscosityQuadratic = d.getScalarInRange("viscosityQuadratic", 0.0, 10.0, true, true, "artificial viscosity");
    }
    if (d.found("viscosityLinear"))
    {
        c.viscosityLinear = d.getScalarInRange("viscosityLinear", 0.0, 10.0, true, true, "artificial viscosity");
    }
    c.writeFields = d.getBool("writeFields", true);
    c.writeState = d.getBool("writeState", true);
    if (d.found("progressInterval"))
    {
        c.progressInterval = d.getScalarInRange("progressInterval", 0.0, 1e6, true, true, "progress interval [s]");
    }
    return c;
}

std::string DamControls::describe() const
{
    std::ostringstream os;
    os << "setting " << setting << ": " << columns << " columns, time step "
       << (timeStep == TimeStep::paper ? "paper (0.001 sqrt(b/g))" : "adaptive (Courant ")
       << (timeStep == TimeStep::paper ? "" : std::to_string(courant).substr(0, 4) + ")")
       << (timeScheme == TimeScheme::rk3 ? ", third-order Runge-Kutta (SSP)" : ", forward Euler")
       << (deltaT > 0.0 ? ", overridden by a fixed deltaT " + std::to_string(deltaT) + " s" : std::string())
       << ", frictional base " << (frictionalBase == FrictionalBase::enhanced ? "enhanced (Eq. 5)" : "original (Eq. 4)")
       << ", face " << (faceStability == FaceStability::rankine ? "Rankine"
                              : faceStability == FaceStability::gate ? "hydrostatic above H_stability" : "hydrostatic") << ", min shear layer " << minShearLayerFraction << " D, artificial viscosity (" << viscosityQuadratic
       << ", " << viscosityLinear << ")";
    return os.str();
}

} // namespace dam
} // namespace slide
