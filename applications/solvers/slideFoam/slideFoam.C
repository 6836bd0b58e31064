/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           | www.openfoam.com
     \\/     M anipulation  |
-------------------------------------------------------------------------------
    Copyright (C) 2011-2017 OpenFOAM Foundation
-------------------------------------------------------------------------------
License
    This file is part of OpenFOAM.

    OpenFOAM is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    OpenFOAM is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.

Application
    slideFoam

Group
    SlideFoam solvers

Description
    Two-phase VOF solver (interFoam's PIMPLE/MULES algorithm) for the runout
    of submarine landslides and viscoplastic debris flows. The slide phase
    follows the Herschel-Bulkley strength with rate effect and remoulding of
    Dong, Wang & Cui (2020), Eq. (1), from the shared SlideFoam rheology
    library (src/rheology); the scene is read from constant/sceneProperties.

    Derived from OpenFOAM's interFoam (v1912); the algorithm files keep
    interFoam's names so that a reader can compare them one to one.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "dynamicFvMesh.H"
#include "CMULES.H"
#include "EulerDdtScheme.H"
#include "localEulerDdtScheme.H"
#include "CrankNicolsonDdtScheme.H"
#include "subCycle.H"
#include "immiscibleIncompressibleTwoPhaseMixture.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "CorrectPhi.H"
#include "fvcSmooth.H"

#include "upwind.H"
#include <iomanip>

#include "slideSceneObject.H"
#include "slideRheology.H"
#include "slideRunout.H"
#include "slideBaseVelocityFvPatchVectorField.H"
#include "outputContract.H"
#include "fluxReconstruction.H"
#include "alongSlopeFaceForce.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Solver for two incompressible, isothermal immiscible fluids"
        " using VOF phase-fraction based interface capturing.\n"
        "With optional mesh motion and mesh topology changes including"
        " adaptive re-meshing."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "checkScene.H"
    #include "createTime.H"
    #include "readSlideRheology.H"

    #include "createDynamicFvMesh.H"
    #include "initContinuityErrs.H"
    #include "createDyMControls.H"
    #include "createFields.H"
    #include "createSlideControls.H"
    #include "createAlphaFluxes.H"
    #include "initCorrectPhi.H"
    #include "createUfIfPresent.H"

    turbulence->validate();

    if (!LTS)
    {
        #include "CourantNo.H"
        #include "setInitialDeltaT.H"
    }

    // Nothing from an earlier run may claim a runout this run has not produced;
    // removed only now that the case has been read, so a refused case loses nothing.
    if (Pstream::master())
    {
        slide::output::prepareOutput(runTime.globalPath(), "slideFoam");
    }

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readDyMControls.H"

        if (LTS)
        {
            #include "setRDeltaT.H"
        }
        else
        {
            #include "CourantNo.H"
            #include "alphaCourantNo.H"
            #include "setDeltaT.H"
        }

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            if (pimple.firstIter() || moveMeshOuterCorrectors)
            {
                mesh.update();

                if (mesh.changing())
                {
                    // Do not apply previous time-step mesh compression flux
                    // if the mesh topology changed
                    if (mesh.topoChanging())
                    {
                        talphaPhi1Corr0.clear();
                    }

                    gh = ((g - gAlongSlope) & mesh.C()) - ghRef;
                    ghf = ((g - gAlongSlope) & mesh.Cf()) - ghRef;

                    MRF.update();

                    if (correctPhi)
                    {
                        // Calculate absolute flux
                        // from the mapped surface velocity
                        phi = mesh.Sf() & Uf();

                        #include "correctPhi.H"

                        // Make the flux relative to the mesh motion
                        fvc::makeRelative(phi, U);

                        mixture.correct();
                    }

                    if (checkMeshCourantNo)
                    {
                        #include "meshCourantNo.H"
                    }
                }
            }

            #include "alphaControls.H"
            #include "alphaEqnSubCycle.H"

            mixture.correct();

            if (pimple.frozenFlow())
            {
                continue;
            }

            #include "UEqn.H"

            // --- Pressure corrector loop
            #include "pressureCorrectors.H"

            if (pimple.turbCorr())
            {
                turbulence->correct();
            }
        }

        #include "xiEqn.H"
        #include "checkBlowUp.H"

        runTime.write();
        runout.execute();

        runTime.printExecutionTime(Info);

        // A slide leaving the mesh stops the run (its runout would be cut short), but the
        // state it reached is written first, for ParaView and for extendSlideMesh to carry
        // on from; no summary.json, which would read as a result.
        const bool leaving = runout.state().atDomainEnd || runout.state().atUpslopeEnd || runout.state().atTop;
        if (leaving)
        {
            if (!runTime.writeTime())
            {
                runTime.writeNow();
                runout.record();
            }
            // Marks the time for extendSlideMesh, which carries a run on from the write
            // before it: by now some of the slide may have left through the open end.
            IOdictionary stopped
            (
                IOobject("slideFoamStopped", runTime.timeName(), "uniform", runTime,
                         IOobject::NO_READ, IOobject::NO_WRITE, false)
            );
            stopped.add
            (
                "reason",
                word(runout.state().atDomainEnd ? "downslopeEnd" : runout.state().atUpslopeEnd ? "upslopeEnd" : "top")
            );
            stopped.regIOobject::write();
        }
        const std::string stateWritten = leaving
            ? " The fields at that time are in " + std::string(Pstream::parRun() ? "processor*/" : "")
              + runTime.timeName() + "/ and runout.dat ends there."
            : "";
        if (runout.state().atDomainEnd)
        {
            FatalErrorInFunction
                << "the slide's front reached the downslope end of the mesh at time "
                << runTime.timeName() << " s: its runout would be cut short. Give a longer"
                << " reach in system/cfdDict and regenerate the case (slideFoamCase), or carry the run on to a"
                << " longer mesh (extendSlideMesh)." << stateWritten.c_str() << exit(FatalError);
        }
        if (runout.state().atUpslopeEnd)
        {
            FatalErrorInFunction
                << "the slide's rear reached the upslope end of the mesh at time "
                << runTime.timeName() << " s (rear " << runout.state().sample.rear << " m): slide"
                << " would leave through it. Give a longer behind in system/cfdDict and regenerate the case"
                << " (slideFoamCase), or carry the run on to a longer mesh (extendSlideMesh)." << stateWritten.c_str()
                << exit(FatalError);
        }
        if (runout.state().atTop)
        {
            FatalErrorInFunction
                << "slide material reached the top of the mesh at time " << runTime.timeName()
                << " s: alpha up to " << runout.state().topAlpha << " there (at " << runout.state().topPoint
                << "), " << runout.state().topOutflow << " m2 of slide out through it ("
                << 100*runout.state().topOutflow/max(runout.initialVolume(), SMALL) << " % of the slide). Give a larger"
                << " heightRatio (or aheadHeightRatio, ahead of the slide) in system/cfdDict, or top slip where"
                << " only spray reaches it, and regenerate the case (slideFoamCase)." << stateWritten.c_str()
                << exit(FatalError);
        }
        if (scene.control.stopAtRest && runout.turned())
        {
            Info<< "The slide's downslope motion stopped at time " << runTime.timeName()
                << " s on a slope it climbs (its base would let it slide back)" << nl << endl;
            if (!runTime.writeTime())
            {
                runTime.writeNow();
                runout.record();
            }
            atRest = true;
            break;
        }
        if (scene.control.stopAtRest && runout.atRest())
        {
            Info<< "The slide is at rest (every slide cell slower than "
                << scene.control.restVelocity << " m/s at two successive writes)" << nl << endl;
            atRest = true;
            break;
        }
    }

    // An end time off the write interval is written too (a run carried on from the time it
    // left a shorter mesh counts its writes from there), so that summary.json's runout is
    // runout.dat's last row and a field on disk.
    if (!atRest && runTime.timeIndex() > runTime.startTimeIndex() && !runTime.writeTime())
    {
        runTime.writeNow();
        runout.record();
    }

    runout.writeSummary(runTime.elapsedClockTime(), atRest);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
