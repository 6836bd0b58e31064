#include "slideRheology.H"
#include "slideSceneObject.H"
#include "wallLayer.H"
#include "addToRunTimeSelectionTable.H"
#include "fvc.H"

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

    baseWallFunction_ = coeffs_.getOrDefault<bool>("baseWallFunction", false);
    if (baseWallFunction_ && (regularisation_.type != slide::rheology::Regularisation::cap || material_.eta <= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "key 'baseWallFunction': the wall function follows Eq. (1)'s rate profile under the viscosity cap;"
            << " it needs regularisation cap and a rate effect (eta > 0)" << exit(FatalIOError);
    }

    faceViscosity_ = coeffs_.getOrDefault<bool>("faceViscosity", false);

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


void Foam::viscosityModels::slideRheology::baseWallViscosity(const label patchi, scalarField& nup) const
{
    // The wall stress tau_w at which Eq. (1)'s profile under the stress tau_w - k z
    // (k: the slide's weight along the base per unit volume, the stress gradient of
    // a steady layer) reaches the wall cell's tangential speed at its centre; the
    // face's viscosity then carries tau_w through the one-sided gradient u_P/z_P.
    const fvPatch& patch = U_.mesh().boundary()[patchi];
    const slide::scene::Scene& scene = slideSceneObject::New(U_.db());
    const scalar theta = scene.base.isPlanar() ? scene.base.angle(0.0) : 0.0;
    // Planar meshes lie in the slope's frame (x downslope, y normal), polylines in the global one.
    const vector g = scene.g*vector(std::sin(theta), -std::cos(theta), 0);
    const vectorField nf(patch.nf());
    const scalarField& deltaCoeffs = patch.deltaCoeffs();
    const labelUList& cells = patch.faceCells();
    const volScalarField* xiPtr = U_.db().cfindObject<volScalarField>("xi");
    const scalar rho = rho_.value(), muMax = regularisation_.muMax;
    // The stress below which the capped material creeps depends on xi only through remoulding.
    const bool remoulds = material_.deltaRem < 1 && xiPtr;
    const scalar intactCap = remoulds ? 0 : slide::rheology::capStress(material_, 0.0, muMax);
    forAll(nup, facei)
    {
        const vector& n = nf[facei];
        const vector Up = U_[cells[facei]];
        const scalar u = mag(Up - (Up & n)*n);
        const scalar z = 1/deltaCoeffs[facei];
        const scalar k = rho*mag(g - (g & n)*n);
        const scalar xi = xiPtr ? (*xiPtr)[cells[facei]] : 0.0;
        const scalar tauCap = remoulds ? slide::rheology::capStress(material_, xi, muMax) : intactCap;
        const scalar tauWall = slide::rheology::wallLayerStress(material_, xi, muMax, tauCap, u, k, z);
        nup[facei] = (u > VSMALL ? min(tauWall*z/u, muMax) : muMax)/rho;
    }
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
        if (baseWallFunction_ && nup.patch().name() == "base" && U_.boundaryField()[patchi].type() == "noSlip")
        {
            baseWallViscosity(patchi, nup);
        }
    }
    return tnu;
}


Foam::tmp<Foam::surfaceScalarField>
Foam::viscosityModels::slideRheology::faceNu(const volTensorField& gradU) const
{
    const fvMesh& mesh = U_.mesh();
    surfaceTensorField gradUf(fvc::interpolate(gradU));
    const surfaceVectorField nf(mesh.Sf()/mesh.magSf());
    // In a layer sheared across its faces this is (u_N - u_P)/d, each face's own rate.
    gradUf += nf*(fvc::snGrad(U_) - (nf & gradUf));
    const surfaceScalarField sr(sqrt(2.0)*mag(symm(gradUf)));
    const volScalarField* xiPtr = U_.db().cfindObject<volScalarField>("xi");
    tmp<surfaceScalarField> txif;
    if (xiPtr) txif = fvc::interpolate(*xiPtr);

    tmp<surfaceScalarField> tnuf
    (
        new surfaceScalarField
        (
            IOobject(nu_.name() + "Face", U_.time().timeName(), U_.db()),
            mesh,
            dimensionedScalar(dimViscosity, Zero)
        )
    );
    surfaceScalarField& nuf = tnuf.ref();
    const scalar rho = rho_.value();
    forAll(nuf, facei)
    {
        const scalar xi = xiPtr ? txif()[facei] : 0.0;
        nuf[facei] = slide::rheology::apparentViscosity(material_, sr[facei], xi, regularisation_)/rho;
    }
    forAll(nuf.boundaryField(), patchi)
    {
        fvsPatchScalarField& nup = nuf.boundaryFieldRef()[patchi];
        if (nup.coupled())
        {
            const scalarField& srp = sr.boundaryField()[patchi];
            forAll(nup, facei)
            {
                const scalar xi = xiPtr ? txif().boundaryField()[patchi][facei] : 0.0;
                nup[facei] = slide::rheology::apparentViscosity(material_, srp[facei], xi, regularisation_)/rho;
            }
        }
        else
        {
            nup = nu_.boundaryField()[patchi];
        }
    }
    return tnuf;
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
