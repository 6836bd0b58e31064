// What slideBaseVelocity takes out of OpenFOAM's explicit transpose viscous flux
// on a base whose faces slip only under a moving block (a frictional base:
// the faces under still cells stay stuck), on the case's mesh and scene. The
// block (x within [blockStart, blockEnd] along the base, at 1 m/s along it) is
// given a velocity across the base that varies along it, so that the flux
// mu (S_f & dev2(T(grad U))) has a shear part that varies from face to face.
// Prints, over the slipping faces, the flux's shear force and what is taken out
// of it (per face and summed over the cells the solver adds it to), and the
// largest face-to-face difference between them; and the total of the momentum
// source the solver adds against the faces' (normal parts included). slideFoamTest.py
// `transposeShear` checks that the two totals agree (the base then exerts no net
// transpose force) while the faces' values do not (only the fluctuation stays).
//
//   baseTransposeShearTest -case <dir> blockStart blockEnd
#include "fvCFD.H"
#include "slideBaseVelocityFvPatchVectorField.H"

int main(int argc, char *argv[])
{
    argList::addArgument("blockStart");
    argList::addArgument("blockEnd");
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const scalar blockStart = args.get<scalar>(1);
    const scalar blockEnd = args.get<scalar>(2);

    // The base's slip reads the mixture's nu and rho on the wall: a plug's viscosity.
    volScalarField rho
    (
        IOobject("rho", runTime.timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh, dimensionedScalar("rho", dimDensity, 1000.0)
    );
    volScalarField nu
    (
        IOobject("nu", runTime.timeName(), mesh, IOobject::NO_READ, IOobject::NO_WRITE),
        mesh, dimensionedScalar("nu", dimViscosity, 100.0)
    );
    // The base's strength on each face is the slide's share of it (the wall
    // cell's alpha) and its ambient's share holds the ambient's no-slip traction.
    volScalarField alpha
    (
        IOobject("alpha.slide", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE),
        mesh
    );
    IOdictionary transportProperties
    (
        IOobject("transportProperties", runTime.constant(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh, IOobject::MUST_READ, IOobject::NO_WRITE),
        mesh
    );

    label basei = -1;
    forAll(U.boundaryField(), patchi)
    {
        if (isA<slideBaseVelocityFvPatchVectorField>(U.boundaryField()[patchi])) basei = patchi;
    }
    if (basei < 0)
    {
        FatalErrorInFunction << "0/U has no slideBaseVelocity patch" << exit(FatalError);
    }
    const vector along = -mesh.boundary()[basei].nf()()[0] ^ vector(0, 0, 1);   // downslope along the base
    const vector across = -mesh.boundary()[basei].nf()()[0];
    const scalar length = blockEnd - blockStart;
    forAll(U, celli)
    {
        const scalar s = mesh.C()[celli] & along;
        const scalar h = mesh.C()[celli] & across;
        if (s < blockStart || s > blockEnd) { U[celli] = Zero; continue; }
        // Across the base: rising from the base and varying along the block.
        U[celli] = along + 0.01*h*Foam::sin(2*constant::mathematical::pi*(s - blockStart)/(0.37*length))*across;
    }
    // Only the base: the other patches' conditions need the solver's fluxes.
    U.boundaryFieldRef()[basei].evaluate();

    const volScalarField muEff("muEff", rho*nu);
    const volTensorField gradU(fvc::grad(U));
    const auto& base = refCast<const slideBaseVelocityFvPatchVectorField>(U.boundaryField()[basei]);
    const vectorField takenOut(base.transposeShearFlux(gradU.boundaryField()[basei], muEff.boundaryField()[basei]));
    const tmp<volVectorField::Internal> tsource(slideBaseVelocityFvPatchVectorField::slipTransposeShear(U, muEff));

    const vectorField& Sf = mesh.boundary()[basei].Sf();
    const vectorField n(mesh.boundary()[basei].nf());
    const scalarField& muw = muEff.boundaryField()[basei];
    label slipping = 0;
    scalar explicitShear = 0, takenOutShear = 0, takenOutWhole = 0, largestShear = 0, largestFaceDifference = 0, normalDifference = 0;
    forAll(Sf, facei)
    {
        const vector f = muw[facei]*(Sf[facei] & dev2(Foam::T(gradU.boundaryField()[basei][facei])));
        if (mag(takenOut[facei]) == 0) continue;
        ++slipping;
        const vector shear = f - n[facei]*(n[facei] & f);
        const vector outShear = takenOut[facei] - n[facei]*(n[facei] & takenOut[facei]);
        explicitShear += shear & along;
        takenOutShear += outShear & along;
        takenOutWhole += takenOut[facei] & along;
        largestShear = max(largestShear, mag(shear));
        largestFaceDifference = max(largestFaceDifference, mag(shear - outShear));
        normalDifference = max(normalDifference, mag((n[facei] & f) - (n[facei] & takenOut[facei])));
    }
    // What the solver adds: the source per unit volume times the cells' volumes.
    const scalar addedAlong = gSum((tsource() & along)*mesh.V().field());

    Sout.precision(15);
    Info<< "slippingFaces " << slipping << nl
        << "baseFaces " << Sf.size() << nl
        << "explicitShear " << explicitShear << nl
        << "takenOutShear " << takenOutShear << nl
        << "takenOutWhole " << takenOutWhole << nl
        << "source " << addedAlong << nl
        << "largestShear " << largestShear << nl
        << "largestFaceDifference " << largestFaceDifference << nl
        << "normalDifference " << normalDifference << endl;
    return 0;
}
