#include "fvMesh.H"
#include "alongSlopeGravity.H"
#include "fvMatrices.H"
#include "incompressibleTwoPhaseMixture.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(alongSlopeGravity, 0);
    addToRunTimeSelectionTable(option, alongSlopeGravity, dictionary);
}
}


Foam::fv::alongSlopeGravity::alongSlopeGravity
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    acceleration_(Zero)
{
    fieldNames_ = wordList(1, coeffs_.lookupOrDefault<word>("U", "U"));
    applied_.setSize(1, false);
    read(dict);
}


void Foam::fv::alongSlopeGravity::addSup(fvMatrix<vector>&, const label)
{
    FatalErrorInFunction
        << "fvOptions " << name_ << ": alongSlopeGravity weighs the slide's density excess over the ambient"
        << " and needs a solver with a density (slideFoam, interFoam)" << exit(FatalError);
}


void Foam::fv::alongSlopeGravity::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label
)
{
    const auto& mixture =
        mesh_.lookupObject<incompressibleTwoPhaseMixture>("transportProperties");
    eqn += (rho() - mixture.rho2())*dimensionedVector("acceleration", dimAcceleration, acceleration_);
}


bool Foam::fv::alongSlopeGravity::read(const dictionary& dict)
{
    if (!option::read(dict))
    {
        return false;
    }
    acceleration_ = coeffs_.get<vector>("acceleration");
    return true;
}
