#include "fvMesh.H"
#include "mixtureMomentumOption.H"
#include "incompressibleTwoPhaseMixture.H"

Foam::fv::mixtureMomentumOption::mixtureMomentumOption
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh)
{
    fieldNames_ = wordList(1, coeffs_.lookupOrDefault<word>("U", "U"));
    applied_.setSize(1, false);
}


const Foam::incompressibleTwoPhaseMixture& Foam::fv::mixtureMomentumOption::mixture() const
{
    return mesh_.lookupObject<incompressibleTwoPhaseMixture>("transportProperties");
}


void Foam::fv::mixtureMomentumOption::addSup(fvMatrix<vector>&, const label)
{
    FatalErrorInFunction
        << "fvOptions " << name_ << ": " << type() << " weighs the slide and the ambient apart and needs a solver"
        << " with the mixture's density (slideFoam, interFoam)" << exit(FatalError);
}
