#include "slideBaseVelocityFvPatchVectorField.H"
#include "slideSceneObject.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"

Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const fvPatch& p, const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(p, iF),
    relaxation_(1)
{}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const fvPatch& p, const DimensionedField<vector, volMesh>& iF, const dictionary& dict
)
:
    fixedValueFvPatchVectorField(p, iF, dict, false),
    relaxation_(dict.getOrDefault<scalar>("relaxation", 1))
{
    if (relaxation_ <= 0 || relaxation_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "key 'relaxation': must lie in (0, 1], got " << relaxation_ << exit(FatalIOError);
    }
    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(vector::zero);
    }
}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const slideBaseVelocityFvPatchVectorField& ptf, const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF, const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchVectorField(ptf, p, iF, mapper),
    relaxation_(ptf.relaxation_)
{}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const slideBaseVelocityFvPatchVectorField& ptf
)
:
    fixedValueFvPatchVectorField(ptf),
    relaxation_(ptf.relaxation_)
{}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const slideBaseVelocityFvPatchVectorField& ptf, const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(ptf, iF),
    relaxation_(ptf.relaxation_)
{}


Foam::scalar Foam::slideBaseVelocityFvPatchVectorField::slipSpeed
(
    const slide::scene::Interface& iface, const scalar cellSpeed, const scalar k
)
{
    using Type = slide::scene::Interface::Type;
    if (iface.type == Type::noSlip || cellSpeed <= 0) return 0;
    if (iface.type == Type::frictional)
    {
        // Stuck while the traction k |U_t| stays within s_b (Eq. 5's frictional base).
        return max(scalar(0), cellSpeed - iface.s_b/k);
    }
    // Hydroplaning: k (|U_t| - U_w) = a U_w^2 with a = 0.5 rho_w C_F; the
    // positive root written without cancellation.
    const scalar a = 0.5*iface.rhoWater*iface.C_F;
    if (a <= 0) return cellSpeed;
    return 2*k*cellSpeed/(k + Foam::sqrt(k*k + 4*a*k*cellSpeed));
}


void Foam::slideBaseVelocityFvPatchVectorField::updateCoeffs()
{
    if (updated()) return;

    const slide::scene::Interface& iface = slideSceneObject::New(db()).interface;
    vectorField Uw(patch().size(), Zero);

    if (iface.type != slide::scene::Interface::Type::noSlip)
    {
        const label patchi = patch().index();
        const scalarField& nuw = db().lookupObject<volScalarField>("nu").boundaryField()[patchi];
        const scalarField& rhow = db().lookupObject<volScalarField>("rho").boundaryField()[patchi];
        const vectorField Uc(patchInternalField());
        const vectorField n(patch().nf());
        const scalarField& deltaCoeffs = patch().deltaCoeffs();

        forAll(Uw, facei)
        {
            const vector Ut = Uc[facei] - n[facei]*(n[facei] & Uc[facei]);
            const scalar speed = mag(Ut);
            if (speed < VSMALL) continue;
            const scalar k = rhow[facei]*nuw[facei]*deltaCoeffs[facei];
            Uw[facei] = Ut*(slipSpeed(iface, speed, k)/speed);
        }
    }

    const vectorField& old = *this;
    fvPatchVectorField::operator==((1 - relaxation_)*old + relaxation_*Uw);
    fixedValueFvPatchVectorField::updateCoeffs();
}


void Foam::slideBaseVelocityFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeEntryIfDifferent<scalar>("relaxation", 1, relaxation_);
    writeEntry("value", os);
}


namespace Foam
{
    makePatchTypeField(fvPatchVectorField, slideBaseVelocityFvPatchVectorField);
}
