#include "fvMesh.H"
#include "ambientDamping.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "incompressibleTwoPhaseMixture.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(ambientDamping, 0);
    addToRunTimeSelectionTable(option, ambientDamping, dictionary);
}
}


Foam::fv::ambientDamping::ambientDamping
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    mixtureMomentumOption(name, modelType, dict, mesh),
    relaxationTime_(0)
{
    read(dict);
}


void Foam::fv::ambientDamping::addSup
(
    const volScalarField&,
    fvMatrix<vector>& eqn,
    const label
)
{
    const incompressibleTwoPhaseMixture& mixture = this->mixture();

    // The ambient is phase 2 (phases (slide ambient)); its fraction is clipped
    // to [0, 1] so that MULES' round-off beyond the bounds adds no source.
    const volScalarField ambientShare(min(max(mixture.alpha2(), scalar(0)), scalar(1)));

    eqn -= fvm::Sp(ambientShare*mixture.rho2()/dimensionedScalar("relaxationTime", dimTime, relaxationTime_), eqn.psi());
}


bool Foam::fv::ambientDamping::read(const dictionary& dict)
{
    if (!option::read(dict))
    {
        return false;
    }
    relaxationTime_ = coeffs_.get<scalar>("relaxationTime");
    if (!(relaxationTime_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "fvOptions " << name_ << ": relaxationTime must be > 0 [s], got " << relaxationTime_
            << exit(FatalIOError);
    }
    return true;
}
