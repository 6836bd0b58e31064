#include "HerschelBulkleyRemoulding.H"
#include "bingShapeFactors.H"
#include "basalResistance.H"
// Device-code check: nvcc must accept the rheology headers in a kernel.
__global__ void k(slide::rheology::HerschelBulkleyRemoulding m, double* out)
{
    slide::rheology::ViscosityRegularisation reg;
    out[0] = m.strength(0.1, 1.0) + apparentViscosity(m, 0.1, 1.0, reg)
           + slide::rheology::shearLayerThickness(1.0, 0.8, 1.0, 0.5)
           + slide::rheology::frictionalBasalResistance(1.0, 2.0, 3.0, 0.1).tau_b;
}
int main() { return 0; }
