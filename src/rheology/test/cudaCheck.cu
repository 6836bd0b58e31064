#include "HerschelBulkleyRemoulding.H"
#include "bingShapeFactors.H"
#include "basalResistance.H"
// Device-code check: nvcc must accept the rheology headers in a kernel, with no
// call to a host-only constexpr function (warning 20013, an error here: nvcc
// compiles such a call as unreachable, which hung slideMPM on an H100).
__global__ void k(slide::rheology::HerschelBulkleyRemoulding m, double* out)
{
    slide::rheology::ViscosityRegularisation reg;
    out[0] = m.strength(0.1, 1.0) + apparentViscosity(m, 0.1, 1.0, reg)
           + slide::rheology::shearLayerThickness(1.0, 0.8, 1.0, 0.5)
           + slide::rheology::frictionalBasalResistance(1.0, 2.0, 3.0, 0.1).tau_b;
    double plasticStrain;
    out[1] = m.returnStrength(2.0, 100.0, 0.01, 0.5, plasticStrain) + plasticStrain;
}
int main() { return 0; }
