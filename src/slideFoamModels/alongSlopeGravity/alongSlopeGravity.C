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
    mixtureMomentumOption(name, modelType, dict, mesh),
    acceleration_(Zero)
{
    read(dict);
}


void Foam::fv::alongSlopeGravity::addSup
(
    const volScalarField& rho,
    fvMatrix<vector>& eqn,
    const label
)
{
    const incompressibleTwoPhaseMixture& mixture = this->mixture();
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
