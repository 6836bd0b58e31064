#include "slideBaseVelocityFvPatchVectorField.H"
#include "slideSceneObject.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "fvcGrad.H"
#include "ListListOps.H"
#include <algorithm>

// C++11: getOrDefault binds it to a reference, which needs its definition.
constexpr Foam::scalar Foam::slideBaseVelocityFvPatchVectorField::defaultSlideTrace;

void Foam::slideBaseVelocityFvPatchVectorField::setStuck()
{
    refValue() = Zero;
    refGrad() = Zero;
    valueFraction() = symmTensor::I;
}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const fvPatch& p, const DimensionedField<vector, volMesh>& iF
)
:
    directionMixedFvPatchVectorField(p, iF),
    transposeShearMean_(false),
    slideShare_(true),
    slideTrace_(defaultSlideTrace),
    alphaName_("alpha.slide")
{
    setStuck();
}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const fvPatch& p, const DimensionedField<vector, volMesh>& iF, const dictionary& dict
)
:
    directionMixedFvPatchVectorField(p, iF),
    transposeShearMean_(false),
    slideShare_(true),
    slideTrace_(dict.getOrDefault<scalar>("slideTrace", defaultSlideTrace)),
    alphaName_(dict.getOrDefault<word>("alpha", "alpha.slide"))
{
    setStuck();
    const word strength = dict.getOrDefault<word>("baseStrength", "slideShare");
    if (strength != "slideShare" && strength != "wholeFace")
    {
        FatalIOErrorInFunction(dict)
            << "key 'baseStrength': expected slideShare or wholeFace, got " << strength << exit(FatalIOError);
    }
    slideShare_ = (strength == "slideShare");
    if (!(slideTrace_ >= 0 && slideTrace_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "key 'slideTrace': the alpha below which a base face is the ambient's must be in [0, 1), got "
            << slideTrace_ << exit(FatalIOError);
    }
    const word shear = dict.getOrDefault<word>("transposeShear", "nearKinks");
    if (shear != "nearKinks" && shear != "runningMean")
    {
        FatalIOErrorInFunction(dict)
            << "key 'transposeShear': expected nearKinks or runningMean, got " << shear << exit(FatalIOError);
    }
    transposeShearMean_ = (shear == "runningMean");
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
    directionMixedFvPatchVectorField(ptf, p, iF, mapper),
    transposeShearMean_(ptf.transposeShearMean_),
    slideShare_(ptf.slideShare_),
    slideTrace_(ptf.slideTrace_),
    alphaName_(ptf.alphaName_)
{}


Foam::slideBaseVelocityFvPatchVectorField::slideBaseVelocityFvPatchVectorField
(
    const slideBaseVelocityFvPatchVectorField& ptf, const DimensionedField<vector, volMesh>& iF
)
:
    directionMixedFvPatchVectorField(ptf, iF),
    transposeShearMean_(ptf.transposeShearMean_),
    slideShare_(ptf.slideShare_),
    slideTrace_(ptf.slideTrace_),
    alphaName_(ptf.alphaName_)
{}


Foam::scalar Foam::slideBaseVelocityFvPatchVectorField::slipSpeed
(
    const slide::scene::Interface& iface, const scalar cellSpeed, const scalar k, const scalar share,
    const scalar held
)
{
    using Type = slide::scene::Interface::Type;
    if (iface.type == Type::noSlip || cellSpeed <= 0) return 0;
    // The traction the face gives beyond what the ambient's share holds.
    const scalar c = max(scalar(0), k*cellSpeed - held);
    if (iface.type == Type::frictional)
    {
        return max(scalar(0), (c - share*iface.s_b)/k);
    }
    // Hydroplaning: c - k V = a V^2 with a = share 0.5 rho_w C_F; the positive
    // root written without cancellation.
    const scalar a = share*0.5*iface.rhoWater*iface.C_F;
    if (a <= 0) return c/k;
    return 2*c/(k + Foam::sqrt(k*k + 4*a*c));
}


Foam::scalar Foam::slideBaseVelocityFvPatchVectorField::ambientViscosity() const
{
    // The mixture's own dictionary (incompressibleTwoPhaseMixture registers it):
    // phases (slide ambient), the ambient Newtonian.
    const IOdictionary& transport = db().lookupObject<IOdictionary>("transportProperties");
    const wordList phases(transport.get<wordList>("phases"));
    const dictionary& ambient = transport.subDict(phases[1]);
    return dimensionedScalar("rho", dimDensity, ambient).value()
          *dimensionedScalar("nu", dimViscosity, ambient).value();
}


void Foam::slideBaseVelocityFvPatchVectorField::updateCoeffs()
{
    if (updated()) return;

    const slide::scene::Interface& iface = slideSceneObject::New(db()).interface;
    setStuck();

    if (iface.type != slide::scene::Interface::Type::noSlip)
    {
        const label patchi = patch().index();
        const scalarField& nuw = db().lookupObject<volScalarField>("nu").boundaryField()[patchi];
        const scalarField& rhow = db().lookupObject<volScalarField>("rho").boundaryField()[patchi];
        const vectorField Uc(patchInternalField());
        const vectorField n(patch().nf());
        const scalarField& deltaCoeffs = patch().deltaCoeffs();
        const scalarField alpha
        (
            min(max(db().lookupObject<volScalarField>(alphaName_).boundaryField()[patchi].patchInternalField(),
                scalar(0)), scalar(1))
        );
        const scalarField share(slideShare_ ? alpha : scalarField(size(), scalar(1)));
        const scalar muAmbient = slideShare_ ? ambientViscosity() : 0;

        forAll(Uc, facei)
        {
            const vector Ut = Uc[facei] - n[facei]*(n[facei] & Uc[facei]);
            const scalar speed = mag(Ut);
            const scalar mu = rhow[facei]*nuw[facei];
            const scalar k = mu*deltaCoeffs[facei];
            // A trace of plug gives an ambient cell the plug's viscosity times alpha:
            // with slideTrace such a face is the ambient's, stuck.
            if (alpha[facei] < slideTrace_) continue;
            // The mixture's viscosity is the phases' shares of theirs: the
            // ambient's share of the face stays stuck with its own no-slip traction.
            const scalar held = (1 - share[facei])*muAmbient*deltaCoeffs[facei]*speed;
            const scalar V = slipSpeed(iface, speed, k, share[facei], held);
            if (V <= 0) continue;   // stuck: the no-slip traction stays within s_b
            // Slipping: the base resists with s_b(V) against the motion (Eq. 5),
            // as the fraction s_b/(k |U_t|) of the no-slip traction on the cell's
            // new velocity. Applied whole against the last step's direction, a
            // frictional s_b reversed a creeping plug within one step (s_b dt/(rho h)
            // is 0.1 m/s for Table 1 Case 7) and flipped it back the next: the
            // base chattered about zero mean traction and let the plug creep.
            const scalar f = (share[facei]*iface.basalStrength(V) + held)/(k*speed);
            valueFraction()[facei] = sqr(n[facei]) + f*(symmTensor::I - sqr(n[facei]));
        }
    }

    directionMixedFvPatchVectorField::updateCoeffs();
}


namespace
{
// valueFraction is n n + f (I - n n): f = 1 on a stuck face, and on a slipping
// one the fraction of the no-slip traction that the base exerts. I - n n has
// trace 2 (the empty direction's component included).
inline Foam::scalar tractionFraction(const Foam::symmTensor& valueFraction)
{
    return 0.5*(Foam::tr(valueFraction) - 1);
}

inline bool slipping(const Foam::symmTensor& valueFraction)
{
    return tractionFraction(valueFraction) < 1 - Foam::SMALL;
}
}


Foam::tmp<Foam::Field<Foam::vector>>
Foam::slideBaseVelocityFvPatchVectorField::gradientInternalCoeffs() const
{
    tmp<Field<vector>> tc(directionMixedFvPatchVectorField::gradientInternalCoeffs());
    Field<vector>& c = tc.ref();
    const scalarField& deltaCoeffs = patch().deltaCoeffs();
    forAll(c, facei)
    {
        // The base's traction on the cell's new velocity, alike in every component.
        const symmTensor& vf = valueFraction()[facei];
        if (slipping(vf)) c[facei] = -tractionFraction(vf)*deltaCoeffs[facei]*vector::one;
    }
    return tc;
}


Foam::tmp<Foam::Field<Foam::vector>>
Foam::slideBaseVelocityFvPatchVectorField::gradientBoundaryCoeffs() const
{
    tmp<Field<vector>> tc(directionMixedFvPatchVectorField::gradientBoundaryCoeffs());
    Field<vector>& c = tc.ref();
    const scalarField& deltaCoeffs = patch().deltaCoeffs();
    const vectorField n(patch().nf());
    const vectorField Uc(patchInternalField());
    forAll(c, facei)
    {
        // Less its normal part: the face's zero flux holds the normal velocity.
        const symmTensor& vf = valueFraction()[facei];
        if (slipping(vf)) c[facei] = tractionFraction(vf)*deltaCoeffs[facei]*n[facei]*(n[facei] & Uc[facei]);
    }
    return tc;
}


const Foam::boolList& Foam::slideBaseVelocityFvPatchVectorField::bendZone() const
{
    if (!bendZone_.valid())
    {
        const slide::scene::Scene& sc = slideSceneObject::New(db());
        bendZone_.reset(new boolList(size(), false));
        boolList& zone = bendZone_.ref();
        const vectorField& centres = patch().Cf();
        for (int k = 1; k < sc.base.nSegments(); ++k)
        {
            const slide::scene::Point2 kink = sc.base.point(sc.base.segmentStart(k));
            forAll(zone, facei)
            {
                const scalar dx = centres[facei].x() - kink.x, dz = centres[facei].y() - kink.z;
                if (sqr(dx) + sqr(dz) < sqr(sc.slide.height)) zone[facei] = true;
            }
        }
    }
    return *bendZone_;
}


Foam::tmp<Foam::vectorField> Foam::slideBaseVelocityFvPatchVectorField::transposeShearFlux
(
    const tensorField& gradUf, const scalarField& muf
) const
{
    const vectorField& Sf = patch().Sf();
    const scalarField& magSf = patch().magSf();
    const vectorField n(patch().nf());
    const vectorField& centres = patch().Cf();
    const boolList& bent = bendZone();

    tmp<vectorField> tflux(new vectorField(size(), Zero));
    vectorField& flux = tflux.ref();

    // On each slipping face: the transpose flux's shear traction taken out whole
    // near a kink; with runningMean its normal traction taken out, and its shear
    // traction gathered for its running mean elsewhere.
    DynamicList<scalar> x(size());
    DynamicList<vector> traction(size());
    DynamicList<scalar> area(size());
    forAll(Sf, facei)
    {
        if (!slipping(valueFraction()[facei])) continue;
        const vector f = muf[facei]*(Sf[facei] & dev2(Foam::T(gradUf[facei])));
        const vector normal = n[facei]*(n[facei] & f);
        const vector shear = f - normal;
        if (transposeShearMean_) flux[facei] = normal;
        if (bent[facei])
        {
            flux[facei] += shear;
            continue;
        }
        if (!transposeShearMean_) continue;
        x.append(centres[facei].x());
        traction.append(shear/magSf[facei]);
        area.append(magSf[facei]);
    }
    if (!transposeShearMean_) return tflux;   // the same on every rank: the patch's own entry

    // Its running mean over the base within H0 either side, gathered over all
    // ranks so that serial and parallel runs take out the same flux. The base
    // is a function of x in both the slope frame and a polyline's frame.
    List<scalarList> allX(Pstream::nProcs());
    List<List<vector>> allTraction(Pstream::nProcs());
    List<scalarList> allArea(Pstream::nProcs());
    allX[Pstream::myProcNo()] = x;
    allTraction[Pstream::myProcNo()] = traction;
    allArea[Pstream::myProcNo()] = area;
    Pstream::gatherList(allX);
    Pstream::gatherList(allTraction);
    Pstream::gatherList(allArea);
    Pstream::scatterList(allX);
    Pstream::scatterList(allTraction);
    Pstream::scatterList(allArea);
    const scalarField gx(ListListOps::combine<scalarList>(allX, accessOp<scalarList>()));
    const vectorField gt(ListListOps::combine<List<vector>>(allTraction, accessOp<List<vector>>()));
    const scalarField ga(ListListOps::combine<scalarList>(allArea, accessOp<scalarList>()));
    const labelList order(sortedOrder(gx));
    scalarList sortedX(order.size());
    scalarList areaSum(order.size() + 1, Zero);
    forAll(order, k)
    {
        sortedX[k] = gx[order[k]];
        areaSum[k + 1] = areaSum[k] + ga[order[k]];
    }
    const scalar halfWidth = slideSceneObject::New(db()).slide.height;
    auto window = [&](const scalar xc, label& lo, label& hi)
    {
        lo = std::lower_bound(sortedX.begin(), sortedX.end(), xc - halfWidth) - sortedX.begin();
        hi = std::upper_bound(sortedX.begin(), sortedX.end(), xc + halfWidth) - sortedX.begin();
    };

    // Each face's shear force spread over the faces within H0 of it, in
    // proportion to their areas (the transpose of a running mean): what is taken
    // out sums to the flux itself over the base, so the base's shear traction
    // is s_b alone on the whole and only the flux's face-to-face fluctuation is
    // kept. The mean gathered at each face (until session 88) does not sum to it
    // where a window runs past the contact's ends: on the Finneidfjord block on
    // a constant s_b it took out 131 Pa a step where the flux braked by 107 Pa,
    // a net push of 24 Pa (validation/cfd/README.md).
    List<vector> spreadSum(order.size() + 1, Zero);
    forAll(order, k)
    {
        label lo, hi;
        window(sortedX[k], lo, hi);
        spreadSum[k + 1] = spreadSum[k]
          + gt[order[k]]*ga[order[k]]/max(areaSum[hi] - areaSum[lo], VSMALL);
    }

    forAll(flux, facei)
    {
        if (bent[facei] || !slipping(valueFraction()[facei])) continue;
        label lo, hi;
        window(centres[facei].x(), lo, hi);
        const vector spread = (spreadSum[hi] - spreadSum[lo])*magSf[facei];
        flux[facei] += spread - n[facei]*(n[facei] & spread);
    }
    return tflux;
}


Foam::tmp<Foam::volVectorField::Internal> Foam::slideBaseVelocityFvPatchVectorField::slipTransposeShear
(
    const volVectorField& U, const volScalarField& muEff
)
{
    const fvMesh& mesh = U.mesh();
    tmp<volVectorField::Internal> tshear
    (
        new volVectorField::Internal
        (
            IOobject("slipTransposeShear", mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(dimDensity*dimVelocity/dimTime, Zero)
        )
    );
    bool anySlip = false;
    forAll(U.boundaryField(), patchi)
    {
        const auto* base = isA<slideBaseVelocityFvPatchVectorField>(U.boundaryField()[patchi]);
        if (!base) continue;
        const boolList& bent = base->bendZone();
        forAll(bent, facei)
        {
            // Default (nearKinks): only the faces near a kink take anything out.
            if ((bent[facei] || base->transposeShearMean_) && slipping(base->valueFraction()[facei]))
            {
                anySlip = true;
                break;
            }
        }
    }
    // grad(U) communicates across processor patches: every rank evaluates it or none.
    if (!returnReduce(anySlip, orOp<bool>())) return tshear;

    const volTensorField gradU(fvc::grad(U));
    volVectorField::Internal& shear = tshear.ref();
    forAll(U.boundaryField(), patchi)
    {
        const auto* base = isA<slideBaseVelocityFvPatchVectorField>(U.boundaryField()[patchi]);
        if (!base) continue;
        const vectorField flux
        (
            base->transposeShearFlux(gradU.boundaryField()[patchi], muEff.boundaryField()[patchi])
        );
        const labelUList& cells = mesh.boundary()[patchi].faceCells();
        forAll(cells, facei)
        {
            shear[cells[facei]] += flux[facei]/mesh.V()[cells[facei]];
        }
    }
    return tshear;
}


void Foam::slideBaseVelocityFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    if (transposeShearMean_) os.writeEntry("transposeShear", word("runningMean"));
    if (!slideShare_) os.writeEntry("baseStrength", word("wholeFace"));
    os.writeEntry("slideTrace", slideTrace_);
    if (alphaName_ != "alpha.slide") os.writeEntry("alpha", alphaName_);
    writeEntry("value", os);
}


namespace Foam
{
    makePatchTypeField(fvPatchVectorField, slideBaseVelocityFvPatchVectorField);
}
