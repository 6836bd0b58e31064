#include "slideRunout.H"
#include "slideSceneObject.H"
#include "addToRunTimeSelectionTable.H"
#include "Pstream.H"
#include "cyclicPolyPatch.H"

#include <algorithm>
#include <numeric>

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(slideRunout, 0);
    addToRunTimeSelectionTable(functionObject, slideRunout, dictionary);
}
}


Foam::scalar Foam::functionObjects::slideRunout::arcLength(const scalar x) const
{
    // slideFoam's case generator puts a planar base along x from s = 0; a
    // polyline base is meshed in the global (x, z) frame with vertical columns.
    return scene_.base.isPlanar() ? x : scene_.base.arcLengthAtX(x);
}


void Foam::functionObjects::slideRunout::buildColumns()
{
    const label patchi = mesh_.boundaryMesh().findPatchID(patchName_);
    if (patchi < 0)
    {
        FatalErrorInFunction
            << "function object " << name() << ": no patch '" << patchName_
            << "' (the base) in the mesh" << exit(FatalError);
    }
    const fvPatch& base = mesh_.boundary()[patchi];

    // Every rank gets every base face (x, area), so that all agree on the columns.
    List<scalarField> allX(Pstream::nProcs()), allA(Pstream::nProcs()), allY(Pstream::nProcs());
    allX[Pstream::myProcNo()] = base.Cf().component(vector::X);
    allA[Pstream::myProcNo()] = base.magSf();
    allY[Pstream::myProcNo()] = base.Cf().component(vector::Y);
    Pstream::gatherList(allX);
    Pstream::scatterList(allX);
    Pstream::gatherList(allA);
    Pstream::scatterList(allA);
    Pstream::gatherList(allY);
    Pstream::scatterList(allY);

    DynamicList<scalar> x, a, y;
    DynamicList<label> owner, local;
    forAll(allX, proci)
    {
        forAll(allX[proci], i)
        {
            x.append(allX[proci][i]);
            a.append(allA[proci][i]);
            y.append(allY[proci][i]);
            owner.append(proci);
            local.append(i);
        }
    }
    labelList order(x.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](label i, label j) { return x[i] < x[j]; });

    const label nCol = x.size();
    scalarList colX(nCol);
    columnS_.setSize(nCol);
    columnArea_.setSize(nCol);
    columnBaseY_.setSize(nCol);
    faceColumn_.setSize(base.size());
    forAll(order, c)
    {
        const label k = order[c];
        colX[c] = x[k];
        columnS_[c] = arcLength(x[k]);
        columnArea_[c] = a[k];
        columnBaseY_[c] = y[k];
        if (owner[k] == Pstream::myProcNo()) faceColumn_[local[k]] = c;
    }

    // A cell belongs to the column whose base face lies below it: columns are
    // split half-way between neighbouring base-face centres.
    scalarList edges(max(nCol - 1, 0));
    forAll(edges, c) edges[c] = 0.5*(colX[c] + colX[c + 1]);
    const vectorField& C = mesh_.C();
    cellColumn_.setSize(mesh_.nCells());
    forAll(C, celli)
    {
        cellColumn_[celli] = label(std::upper_bound(edges.begin(), edges.end(), C[celli].x()) - edges.begin());
    }

    depth_ = mesh_.bounds().span().z();
    if (depth_ <= 0) depth_ = 1;

    // What the mechanism classifier needs of the mesh: each cell's width along x,
    // columns of the widest base face or H0/5, and the basal layer: the row of
    // cells on the base. Two rows, as slideMPM takes two particle spacings, were
    // most of a thin layer on a mesh not refined to the base (the flume at H0/10,
    // a layer three to six cells thick: a basal slip ratio of 0.8-0.9 where the
    // particles give 0.35), and read a sheared flow as block sliding.
    cellWidth_.setSize(mesh_.nCells());
    const pointField& pts = mesh_.points();
    forAll(cellWidth_, celli)
    {
        scalar lo = GREAT, hi = -GREAT;
        for (const label pointi : mesh_.cellPoints()[celli])
        {
            lo = min(lo, pts[pointi].x());
            hi = max(hi, pts[pointi].x());
        }
        cellWidth_[celli] = max(hi - lo, SMALL);
    }
    scalar baseCellHeight = 0;
    forAll(base.faceCells(), facei)
    {
        const label celli = base.faceCells()[facei];
        baseCellHeight = max(baseCellHeight, mesh_.V()[celli]/depth_/cellWidth_[celli]);
    }
    reduce(baseCellHeight, maxOp<scalar>());
    scalar widest = 0;
    forAll(columnArea_, c) widest = max(widest, columnArea_[c]/depth_);
    mechanismView_.H0 = scene_.slide.height;
    mechanismView_.g = scene_.g;
    mechanismView_.columnWidth = max(widest, 0.2*scene_.slide.height);
    mechanismView_.basalLayer = baseCellHeight;
}


Foam::vector Foam::functionObjects::slideRunout::tangent(const label column) const
{
    if (scene_.base.isPlanar()) return vector(1, 0, 0);
    const slide::scene::Point2 tp = scene_.base.tangent(columnS_[column]);
    return vector(tp.x, tp.z, 0);
}


slide::output::Mechanism Foam::functionObjects::slideRunout::detectMechanism() const
{
    const volScalarField& alpha = lookupObject<volScalarField>(alphaName_);
    const volVectorField& U = lookupObject<volVectorField>("U");
    const volScalarField* xi = findObject<volScalarField>("xi");
    const scalarField& V = mesh_.V();
    const vectorField& C = mesh_.C();
    // Each rank's cells holding slide, eight values a cell, gathered on the master.
    // A cell is the layer of slide it holds, alpha times its height, on its floor:
    // a deposit thinner than half the base cell (Table 1 Case 4's at 285 s, alpha
    // 0.42-0.49 over stretches of 2-3 m) is material on the base, where counting
    // only cells of alpha >= 0.5 read it as empty columns parting 14 bodies.
    const label nPack = 8;
    DynamicList<scalar> local;
    forAll(alpha, celli)
    {
        if (alpha[celli] < mechanismAlpha) continue;
        const label c = cellColumn_[celli];
        const scalar area = V[celli]/depth_;
        const scalar height = area/cellWidth_[celli];
        const scalar a = min(alpha[celli], scalar(1));
        local.append(arcLength(C[celli].x()));
        local.append(0.5*cellWidth_[celli]);
        local.append(C[celli].y() - columnBaseY_[c] - 0.5*(1 - a)*height);
        local.append(0.5*a*height);
        local.append(scene_.slide.density*a*area);
        local.append(U[celli] & tangent(c));
        local.append(xi ? (*xi)[celli] : scalar(0));
        local.append(a*area);   // a cell votes by its slide volume: the mesh is graded to the base
    }
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = local;
    Pstream::gatherList(all);
    slide::output::Mechanism m;
    if (!Pstream::master()) return m;
    std::vector<slide::output::MaterialSample> samples;
    forAll(all, proci)
    {
        const scalarList& l = all[proci];
        for (label k = 0; k + nPack <= l.size(); k += nPack)
        {
            slide::output::MaterialSample q;
            q.s = l[k];
            q.halfLength = l[k + 1];
            q.h = l[k + 2];
            q.halfHeight = l[k + 3];
            q.mass = l[k + 4];
            q.velocity = l[k + 5];
            q.xi = l[k + 6];
            q.vote = l[k + 7];
            samples.push_back(q);
        }
    }
    return slide::output::detectMechanism(samples, mechanismView_, scene_.rheology);
}


void Foam::functionObjects::slideRunout::recordMechanism()
{
    const slide::output::Mechanism m = detectMechanism();
    if (!Pstream::master() || m.name == "none") return;
    // A time already recorded: a restart's start row kept in mechanism.dat (as in
    // runout.dat), or a stop's state written at a write time.
    const scalar t = time_.value();
    if (!mechanisms_.empty() && (mechanisms_.back().first >= t || Time::timeName(mechanisms_.back().first) == time_.timeName()))
    {
        return;
    }
    mechanismLog_->write(time_.value(), m);
    mechanisms_.emplace_back(time_.value(), m.name);
}


Foam::functionObjects::slideRunout::slideRunout
(
    const word& name, const Time& runTime, const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    alphaName_("alpha.slide"),
    patchName_("base"),
    scene_(slideSceneObject::New(mesh_))
{
    read(dict);
    buildColumns();
    const fileName setUp = runTime.globalPath()/"system"/"cfdSetUp";
    if (Foam::isFile(setUp))
    {
        try
        {
            const slide::scene::Dictionary d = slide::scene::Dictionary::readFile(setUp);
            setting_ = d.getWord("setting");
            cellsPerHeight_ = d.getLabel("cellsPerHeight");
            baseRefinement_ = d.getLabel("baseRefinement");
            top_ = d.getWord("top", "open");
        }
        catch (const slide::scene::InputError& e)
        {
            FatalErrorInFunction << "bad set-up record: " << e.what() << nl << exit(FatalError);
        }
    }
    const scalar t0 = runTime.startTime().value();
    if (Pstream::master())
    {
        log_.reset(new slide::output::RunoutLog(runTime.globalPath(), "slideFoam", t0 > 0, t0));
        const std::vector<slide::output::RunoutSample>& kept = log_->kept();
        // A restart measures the volume change from the run's start, not its own.
        if (!kept.empty() && kept.front().mass > 0) initialVolume_ = kept.front().mass/scene_.slide.density;
        // The start time is read off its directory's name (timePrecision digits): a row
        // of the same name is its own, whether or not it was on the write interval.
        startRowKept_ = !kept.empty() && Time::timeName(kept.back().time) == runTime.timeName();
        mechanismLog_.reset(new slide::output::MechanismLog(runTime.globalPath(), "slideFoam", t0 > 0, t0));
        sites_.reset(new slide::output::SiteMonitor(scene_.sites, scene_.slide.frontPosition(), runTime.globalPath(),
                                                    "slideFoam", t0 > 0, t0));
        mechanisms_ = mechanismLog_->kept();
    }
    Pstream::scatter(initialVolume_);
}


bool Foam::functionObjects::slideRunout::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    alphaName_ = dict.getOrDefault<word>("alpha", "alpha.slide");
    patchName_ = dict.getOrDefault<word>("patch", "base");
    return true;
}


bool Foam::functionObjects::slideRunout::execute()
{
    const volScalarField& alpha = lookupObject<volScalarField>(alphaName_);
    const volVectorField& U = lookupObject<volVectorField>("U");
    const volScalarField* xi = findObject<volScalarField>("xi");
    const scalarField& V = mesh_.V();
    const scalar rho = scene_.slide.density;
    const label nCol = columnS_.size();

    scalarList baseAlpha(nCol, scalar(-1)), colAV(nCol, Zero), colAVU(nCol, Zero);
    const label patchi = mesh_.boundaryMesh().findPatchID(patchName_);
    const labelUList& faceCells = mesh_.boundary()[patchi].faceCells();
    forAll(faceCells, facei)
    {
        baseAlpha[faceColumn_[facei]] = alpha[faceCells[facei]];
    }

    State s;
    scalar ke = 0, uMax = 0, xiMax = 0;
    scalar aMin = GREAT, aMax = -GREAT;
    forAll(alpha, celli)
    {
        const scalar a = alpha[celli];
        const scalar av = a*V[celli];
        const label c = cellColumn_[celli];
        const vector t = tangent(c);
        colAV[c] += av;
        colAVU[c] += av*(U[celli] & t);
        s.volume += av;
        ke += 0.5*av*magSqr(U[celli]);
        aMin = min(aMin, a);
        aMax = max(aMax, a);
        if (a >= 0.5)
        {
            uMax = max(uMax, mag(U[celli]));
            if (xi) xiMax = max(xiMax, (*xi)[celli]);
        }
    }
    Pstream::listCombineGather(baseAlpha, maxEqOp<scalar>());
    Pstream::listCombineScatter(baseAlpha);
    Pstream::listCombineGather(colAV, plusEqOp<scalar>());
    Pstream::listCombineScatter(colAV);
    Pstream::listCombineGather(colAVU, plusEqOp<scalar>());
    Pstream::listCombineScatter(colAVU);
    reduce(s.volume, sumOp<scalar>());
    reduce(ke, sumOp<scalar>());
    reduce(uMax, maxOp<scalar>());
    reduce(xiMax, maxOp<scalar>());
    reduce(aMin, minOp<scalar>());
    reduce(aMax, maxOp<scalar>());

    // The alpha = 0.5 contour along the base, between base-row cell centres.
    label front = -1, rear = -1;
    for (label c = nCol - 1; c >= 0; --c) if (baseAlpha[c] >= 0.5) { front = c; break; }
    for (label c = 0; c < nCol; ++c) if (baseAlpha[c] >= 0.5) { rear = c; break; }

    const scalar s0 = scene_.slide.frontPosition();
    s.sample = state_.sample;
    s.sample.time = time_.value();
    if (front >= 0)
    {
        scalar sf = columnS_[front];
        if (front + 1 < nCol)
        {
            const scalar a0 = baseAlpha[front], a1 = max(baseAlpha[front + 1], scalar(0));
            sf += (a0 - 0.5)/max(a0 - a1, SMALL)*(columnS_[front + 1] - columnS_[front]);
        }
        // A slide against the mesh's end (a flume's end wall) reaches its face.
        if (front == nCol - 1 && nCol > 1) sf = columnS_[front] + 0.5*(columnS_[front] - columnS_[front - 1]);
        scalar sr = columnS_[rear];
        if (rear == 0 && nCol > 1)
        {
            sr -= 0.5*(columnS_[1] - columnS_[0]);
        }
        else if (rear > 0)
        {
            const scalar a0 = baseAlpha[rear], a1 = max(baseAlpha[rear - 1], scalar(0));
            sr -= (a0 - 0.5)/max(a0 - a1, SMALL)*(columnS_[rear] - columnS_[rear - 1]);
        }
        s.sample.front = sf - s0;
        s.sample.rear = sr - s0;
        s.sample.frontVelocity = colAV[front] > 0 ? colAVU[front]/colAV[front] : 0;
    }
    // The point with 99 % of the slide's volume behind it, each column's spread over
    // its width: the front of the body where a thin smear or a thrown-off piece sets
    // the alpha = 0.5 front, defined as slideMPM's and slideDAM's (summary.json).
    {
        scalar total = 0;
        forAll(colAV, c) total += colAV[c];
        const scalar behind = 0.99*total;
        scalar upTo = 0;
        for (label c = 0; c < nCol && total > 0; ++c)
        {
            if (upTo + colAV[c] >= behind && colAV[c] > 0)
            {
                const scalar half = nCol > 1
                    ? 0.5*(c + 1 < nCol ? columnS_[c + 1] - columnS_[c] : columnS_[c] - columnS_[c - 1]) : 0;
                const scalar lo = c > 0 ? 0.5*(columnS_[c - 1] + columnS_[c]) : columnS_[c] - half;
                const scalar hi = c + 1 < nCol ? 0.5*(columnS_[c] + columnS_[c + 1]) : columnS_[c] + half;
                s.massFront = lo + (behind - upTo)/colAV[c]*(hi - lo) - s0;
                break;
            }
            upTo += colAV[c];
        }
    }
    if (sites_ && !sites_->empty())
    {
        // The column over each site (the base face nearest it): its slide volume over
        // its base face is the thickness normal to the base, its alpha-weighted mean
        // velocity along the base the velocity; covered between the alpha = 0.5 rear and front.
        std::vector<slide::output::SiteFlow> flow(scene_.sites.size());
        for (std::size_t k = 0; k < flow.size(); ++k)
        {
            const scalar at = scene_.sites[k].position;
            if (front < 0 || nCol == 0 || at < s.sample.rear + s0 || at > s.sample.front + s0) continue;
            label c = label(std::lower_bound(columnS_.begin(), columnS_.end(), at) - columnS_.begin());
            if (c == nCol || (c > 0 && at - columnS_[c - 1] < columnS_[c] - at)) --c;
            flow[k].covered = true;
            flow[k].thickness = colAV[c]/columnArea_[c];
            flow[k].velocity = colAV[c] > 0 ? colAVU[c]/colAV[c] : 0;
        }
        sites_->observe(time_.value(), flow);
    }
    // Slide on the base in the last column is leaving through the open downslope
    // end, whether or not the (thin) front there still reaches alpha = 0.5.
    // Ends made cyclic (an infinite layer, validation/cfd/rateLayer.py) lose nothing.
    const label downi = mesh_.boundaryMesh().findPatchID("downslope");
    const bool periodic = downi >= 0 && isA<cyclicPolyPatch>(mesh_.boundaryMesh()[downi]);
    s.atDomainEnd = !periodic && nCol > 0 && baseAlpha[nCol - 1] >= 0.1;
    // The same at the open upslope end: a weak slide's rear spreads upslope too
    // (Table 1 Case 4's by 50 m in 5 s), beyond slideDAM's spreading that sized the mesh.
    s.atUpslopeEnd = !periodic && !scene_.slide.rearWall && nCol > 0 && baseAlpha[0] >= 0.1;
    // Slide at the open top (a mesh too low over it) would leave there or be pressed down.
    const label topi = mesh_.boundaryMesh().findPatchID("top");
    if (topi >= 0)
    {
        const labelUList& topCells = mesh_.boundary()[topi].faceCells();
        // A cell in the corner of a lower top's step has two faces on the top: counted once.
        boolList counted(mesh_.nCells(), false);
        forAll(topCells, facei)
        {
            const label celli = topCells[facei];
            if (!counted[celli]) s.topVolume += alpha[celli]*mesh_.V()[celli];
            counted[celli] = true;
            if (alpha[topCells[facei]] > s.topAlpha)
            {
                s.topAlpha = alpha[topCells[facei]];
                s.topPoint = mesh_.C()[topCells[facei]];
            }
        }
    }
    const scalar localTopAlpha = s.topAlpha;
    reduce(s.topAlpha, maxOp<scalar>());
    s.topVolume = returnReduce(s.topVolume, sumOp<scalar>())/depth_;
    // The step's slide flux (MULES's, which slideFoam registers as alphaPhi0.<phase>) through the top.
    const surfaceScalarField* alphaPhi =
        findObject<surfaceScalarField>(IOobject::groupName("alphaPhi0", alpha.group()));
    if (topi >= 0 && alphaPhi && time_.timeIndex() > time_.startTimeIndex())
    {
        topOutflow_ += gSum(static_cast<const scalarField&>(alphaPhi->boundaryField()[topi]))*time_.deltaTValue();
    }
    s.topOutflow = topOutflow_/depth_;
    // Alpha 0.1 in a top cell was the test until Table 1 Case 4 at H0/10 threw
    // spray (alpha 0.1, 1e-4 of the slide) 3.8 m up from a front 0.5 m thick at
    // 25 m/s in the light ambient: a surface at the top, or volume lost there,
    // is what says the mesh is too low.
    s.atTop =
        s.topAlpha >= 0.5 || (initialVolume_ > 0 && s.topOutflow > topOutflowLimit*initialVolume_);
    if (s.atTop)
    {
        // Only on the way to stopping: the place, from the rank that holds it.
        point p = localTopAlpha == s.topAlpha ? s.topPoint : point::max;
        reduce(p, minOp<point>());
        s.topPoint = p;
    }
    scalar hMax = 0;
    forAll(colAV, c) hMax = max(hMax, colAV[c]/columnArea_[c]);
    s.sample.maxVelocity = uMax;
    s.sample.maxThickness = hMax;
    s.sample.mass = rho*s.volume/depth_;
    s.sample.kineticEnergy = rho*ke/depth_;
    s.volume /= depth_;
    s.alphaMin = aMin;
    s.alphaMax = aMax;
    s.xiMax = xiMax;
    if (initialVolume_ < 0) initialVolume_ = s.volume;
    topShareMax_ = max(topShareMax_, s.topVolume/max(initialVolume_, VSMALL));
    state_ = s;

    // As slideMPM and slideDAM end a run where the downslope motion stops and the
    // base could not hold the slide: always on a hydroplaning base, and on a
    // frictional one where the base under the slide rises towards its front (an s_b
    // below the adverse slope's pull lets it slide back; on a downslope a stopping
    // slide's momentum may turn before it is at rest).
    scalar momentum = 0;
    forAll(colAVU, c) momentum += rho*colAVU[c]/depth_;
    // A turn needs motion first: released at rest, the first steps' momentum is of
    // round-off size and may change sign (it did at 6 ms on the Finneidfjord block).
    moved_ = moved_ || momentum > scene_.control.restVelocity*s.sample.mass;
    if
    (
        !turned_ && moved_ && time_.timeIndex() > time_.startTimeIndex()
     && downslopeMomentum_ > 0 && momentum <= 0
    )
    {
        using Type = slide::scene::Interface::Type;
        const bool climbing = scene_.interface.type == Type::frictional && front >= 0
            && scene_.base.point(s.sample.front + s0).z > scene_.base.point(s.sample.rear + s0).z;
        turned_ = scene_.interface.type == Type::hydroplaning || climbing;
    }
    downslopeMomentum_ = momentum;

    if (time_.writeTime() || time_.timeIndex() == time_.startTimeIndex())
    {
        // A restart's start row is already in runout.dat, as slideMPM and slideDAM leave it.
        if (log_ && !(startRowKept_ && time_.timeIndex() == time_.startTimeIndex()))
        {
            log_->write(state_.sample);
            sites_->write(time_.value());
        }
        recordMechanism();

        // Rest: every slide cell slower than restVelocity at two successive writes.
        // A layer smeared thinner than its cells may hold no cell of alpha >= 0.5
        // (Table 1 Case 4 at H0/5 did, at 11 m/s): its RMS speed must be slow too.
        if (time_.timeIndex() > time_.startTimeIndex())
        {
            const scalar rmsSpeed = state_.volume > 0 ? Foam::sqrt(2*ke/(state_.volume*depth_)) : 0;
            slowSamples_ = max(uMax, rmsSpeed) < scene_.control.restVelocity ? slowSamples_ + 1 : 0;
            atRest_ = slowSamples_ >= 2;
        }

        const scalar t0 = time_.startTime().value(), t1 = time_.endTime().value();
        const scalar frac = t1 > t0 ? (time_.value() - t0)/(t1 - t0) : 1;
        const scalar wall = time_.elapsedClockTime();
        Info<< "slideRunout: time " << time_.value() << " s  front " << state_.sample.front
            << " m  rear " << state_.sample.rear << " m  max |U| " << uMax
            << " m/s  volume change " << (state_.volume/initialVolume_ - 1)
            << "  xi max " << xiMax;
        if (frac > 0 && frac < 1) Info<< "  estimated time left " << wall*(1 - frac)/frac << " s";
        Info<< endl;
    }
    return true;
}


void Foam::functionObjects::slideRunout::record()
{
    if (log_)
    {
        log_->write(state_.sample);
        sites_->write(time_.value());
    }
    recordMechanism();
}


void Foam::functionObjects::slideRunout::writeSummary(const scalar wallTime, const bool atRest) const
{
    const label nCells = returnReduce(mesh_.nCells(), sumOp<label>());
    // How much of the slide is in cells that are mostly slide: a layer thinner than
    // its cells (Table 1 Case 4 at H0/10 kept a quarter of it by 193 s, 0.1-0.2 m
    // thick in cells 0.25 m high) or mixed into the ambient is not resolved, and its
    // alpha = 0.5 front on the base is not the slide's.
    const volScalarField& alpha = lookupObject<volScalarField>(alphaName_);
    scalar coherent = 0, total = 0;
    forAll(alpha, celli)
    {
        const scalar v = alpha[celli]*mesh_.V()[celli];
        total += v;
        if (alpha[celli] > 0.5) coherent += v;
    }
    reduce(coherent, sumOp<scalar>());
    reduce(total, sumOp<scalar>());
    const slide::output::Mechanism mech = detectMechanism();
    if (!Pstream::master()) return;

    slide::output::Summary sum;
    sum.method = "slideFoam";
    sum.caseName = scene_.caseName;
    sum.runout = state_.sample.front;
    sum.endTime = time_.value();
    sum.atRest = atRest;
    sum.wallTime = wallTime;
    sum.problemSize = nCells;
    sum.problemSizeUnit = "cells";
    sum.backend = Pstream::parRun()
        ? "OpenFOAM v1912, MPI (" + std::to_string(Pstream::nProcs()) + " ranks)"
        : std::string("OpenFOAM v1912, serial");
    sum.addNumber("rigid_slab_factor_of_safety", scene_.rigidSlabFactorOfSafety());
    sum.addNumber("final_length_m", state_.sample.front - state_.sample.rear);
    sum.addNumber("front_of_99_percent_mass_m", state_.massFront);
    sum.addNumber("max_thickness_m", state_.sample.maxThickness);
    sum.addNumber("volume_relative_change", state_.volume/initialVolume_ - 1);
    sum.addNumber("alpha_min", state_.alphaMin);
    sum.addNumber("alpha_max", state_.alphaMax);
    sum.addNumber("xi_max", state_.xiMax);
    sum.addBool("reached_domain_end", state_.atDomainEnd);
    sum.addNumber("top_cells_slide_share_max", topShareMax_);
    sum.addNumber("slide_share_above_half", total > 0 ? coherent/total : 0);
    // As slideMPM reads it off its particles (src/output/runoutMechanism.H).
    slide::output::addMechanism(sum, mechanisms_, mech, atRest, scene_.slide.height);
    sites_->addTo(sum);
    if (!setting_.empty())
    {
        sum.addString("setting", setting_);
        sum.addNumber("cells_per_height", cellsPerHeight_);
        sum.addNumber("base_refinement", baseRefinement_);
        sum.addString("top", top_);
    }
    sum.write(time_.globalPath());
}
