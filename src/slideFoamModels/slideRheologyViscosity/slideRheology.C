#include "slideRheology.H"
#include "slideSceneObject.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace viscosityModels
{
    defineTypeNameAndDebug(slideRheology, 0);
    addToRunTimeSelectionTable(viscosityModel, slideRheology, dictionary);
}
}


void Foam::viscosityModels::slideRheology::readCoeffs()
{
    material_ = slideSceneObject::New(U_.db()).rheology;

    const word type = coeffs_.getOrDefault<word>("regularisation", "cap");
    if (type == "cap")
    {
        regularisation_.type = slide::rheology::Regularisation::cap;
        regularisation_.muMax = coeffs_.get<scalar>("muMax");
        if (regularisation_.muMax <= 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "key 'muMax': the viscosity cap must be > 0 Pa s, got "
                << regularisation_.muMax << exit(FatalIOError);
        }
    }
    else if (type == "papanastasiou")
    {
        regularisation_.type = slide::rheology::Regularisation::papanastasiou;
        regularisation_.m = coeffs_.get<scalar>("m");
        if (regularisation_.m <= 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "key 'm': the Papanastasiou growth rate must be > 0 s, got "
                << regularisation_.m << exit(FatalIOError);
        }
    }
    else
    {
        FatalIOErrorInFunction(coeffs_)
            << "key 'regularisation': expected cap or papanastasiou, got " << type
            << exit(FatalIOError);
    }

    shearBandThickness_ = coeffs_.getOrDefault<scalar>("shearBandThickness", 0);
    if (shearBandThickness_ < 0 || !std::isfinite(shearBandThickness_))
    {
        FatalIOErrorInFunction(coeffs_)
            << "key 'shearBandThickness': the shear band thickness must be >= 0 m (0: xi per cell), got "
            << shearBandThickness_ << exit(FatalIOError);
    }
}


Foam::tmp<Foam::scalarField>
Foam::viscosityModels::slideRheology::bandCellSize() const
{
    const fvMesh& mesh = U_.mesh();
    const vectorField& faceAreas = mesh.faceAreas();
    const Vector<label>& solutionD = mesh.solutionD();
    tmp<scalarField> tsize(new scalarField(mesh.nCells(), Zero));
    scalarField& size = tsize.ref();
    forAll(size, celli)
    {
        scalar largest = 0;
        for (const label facei : mesh.cells()[celli])
        {
            const vector& Sf = faceAreas[facei];
            const scalar A = mag(Sf);
            // A face of a 2D mesh's empty front or back bounds no band.
            scalar offPlane = 0;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (solutionD[d] < 0) offPlane += mag(Sf[d]);
            }
            if (offPlane < 0.5*A) largest = max(largest, A);
        }
        size[celli] = largest > 0 ? mesh.V()[celli]/largest : 0;
    }
    return tsize;
}


Foam::tmp<Foam::scalarField>
Foam::viscosityModels::slideRheology::shearBandStrainFactor() const
{
    tmp<scalarField> tfactor(new scalarField(U_.mesh().nCells(), scalar(1)));
    if (shearBandThickness_ > 0)
    {
        const scalarField h(bandCellSize());
        scalarField& factor = tfactor.ref();
        forAll(factor, celli)
        {
            factor[celli] = slide::rheology::shearBandStrainFactor(shearBandThickness_, h[celli]);
        }
    }
    return tfactor;
}


Foam::tmp<Foam::volScalarField>
Foam::viscosityModels::slideRheology::calcNu() const
{
    const tmp<volScalarField> tsr(strainRate());
    const volScalarField& sr = tsr();
    const volScalarField* xiPtr = U_.db().cfindObject<volScalarField>("xi");

    tmp<volScalarField> tnu
    (
        new volScalarField
        (
            IOobject(nu_.name() + "Apparent", U_.time().timeName(), U_.db()),
            U_.mesh(),
            dimensionedScalar(dimViscosity, Zero),
            sr.boundaryField().types()
        )
    );
    volScalarField& nu = tnu.ref();
    const scalar rho = rho_.value();

    forAll(nu, celli)
    {
        const scalar xi = xiPtr ? (*xiPtr)[celli] : 0.0;
        nu[celli] = slide::rheology::apparentViscosity(material_, sr[celli], xi, regularisation_)/rho;
    }
    forAll(nu.boundaryField(), patchi)
    {
        fvPatchScalarField& nup = nu.boundaryFieldRef()[patchi];
        const fvPatchScalarField& srp = sr.boundaryField()[patchi];
        forAll(nup, facei)
        {
            const scalar xi = xiPtr ? xiPtr->boundaryField()[patchi][facei] : 0.0;
            nup[facei] = slide::rheology::apparentViscosity(material_, srp[facei], xi, regularisation_)/rho;
        }
    }
    return tnu;
}


Foam::tmp<Foam::volScalarField>
Foam::viscosityModels::slideRheology::plasticShearRate() const
{
    const tmp<volScalarField> tsr(strainRate());
    const volScalarField& sr = tsr();
    const volScalarField* xiPtr = U_.db().cfindObject<volScalarField>("xi");

    tmp<volScalarField> trate
    (
        new volScalarField
        (
            IOobject("plasticShearRate", U_.time().timeName(), U_.db()),
            U_.mesh(),
            dimensionedScalar(dimless/dimTime, Zero)
        )
    );
    volScalarField& rate = trate.ref();
    // Recomputed each call: cheaper than the strain rate, and follows a moving mesh.
    const scalarField bandFactor(shearBandStrainFactor());
    forAll(rate, celli)
    {
        const scalar xi = xiPtr ? (*xiPtr)[celli] : 0.0;
        rate[celli] = bandFactor[celli]*slide::rheology::plasticShearRate(material_, sr[celli], xi, regularisation_);
    }
    return trate;
}


Foam::viscosityModels::slideRheology::slideRheology
(
    const word& name,
    const dictionary& viscosityProperties,
    const volVectorField& U,
    const surfaceScalarField& phi
)
:
    viscosityModel(name, viscosityProperties, U, phi),
    coeffs_(viscosityProperties.optionalSubDict(typeName + "Coeffs")),
    rho_("rho", dimDensity, viscosityProperties),
    nu_
    (
        IOobject(name, U_.time().timeName(), U_.db(), IOobject::NO_READ, IOobject::AUTO_WRITE),
        U_.mesh(),
        dimensionedScalar(dimViscosity, Zero)
    )
{
    readCoeffs();
    nu_ = calcNu();
}


bool Foam::viscosityModels::slideRheology::read(const dictionary& viscosityProperties)
{
    viscosityModel::read(viscosityProperties);
    coeffs_ = viscosityProperties.optionalSubDict(typeName + "Coeffs");
    readCoeffs();
    return true;
}
