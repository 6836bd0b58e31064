// Reconstructs the face fluxes of a uniform velocity on the case's mesh with
// slideFoam's FluxReconstruction and with fvc::reconstruct, and prints the
// largest error of each relative to |U| and how far the mesh's faces are from
// the axes (the largest |off-diagonal| of sum Sf^ Sf over its diagonal).
// slideFoamTest.py `reconstruction` runs it on a rotated mesh.
#include "fvCFD.H"
#include "fluxReconstruction.H"

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const dimensionedVector U0("U", dimVelocity, vector(0.3, -0.7, 0));
    const surfaceScalarField phi("phi", mesh.Sf() & U0);

    const FluxReconstruction reconstructFlux(mesh);
    const volVectorField ours(reconstructFlux(phi));
    const volVectorField theirs(fvc::reconstruct(phi));

    const surfaceVectorField unitNormals(mesh.Sf()/mesh.magSf());
    const volTensorField normalSum(fvc::surfaceSum(unitNormals*mesh.Sf()));
    scalar offDiagonal = 0;
    forAll(normalSum, celli)
    {
        const tensor& T = normalSum[celli];
        offDiagonal = max(offDiagonal, mag(T.xy())/min(mag(T.xx()), mag(T.yy())));
    }

    const scalar u = mag(U0.value());
    Info<< "offDiagonal " << gMax(scalarField(1, offDiagonal)) << nl
        << "ourError " << gMax(mag(ours.primitiveField() - U0.value()))/u << nl
        << "fvcReconstructError " << gMax(mag(theirs.primitiveField() - U0.value()))/u << endl;
    return 0;
}
