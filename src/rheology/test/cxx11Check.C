// Compiled as C++11 with -pedantic -Werror: the rheology headers must stay
// within the language level of OpenFOAM v1912's wmake rules.
#include "HerschelBulkleyRemoulding.H"
#include "basalResistance.H"
#include "bingShapeFactors.H"
#include "checkParameters.H"

double cxx11Check()
{
    slide::rheology::HerschelBulkleyRemoulding m;
    slide::rheology::ViscosityRegularisation reg;
    const slide::rheology::BasalResistance r =
        slide::rheology::frictionalBasalResistance(1.0, 2.0, 3.0, 0.1);
    return m.strength(1.0, 0.0) + apparentViscosity(m, 1.0, 0.0, reg) + r.tau_b
        + slide::rheology::shapeFactorA1(0.5) + (checkParameters(m).empty() ? 1.0 : 0.0);
}
