#include "slideSceneObject.H"
#include "Time.H"
#include "error.H"

namespace Foam
{
    defineTypeNameAndDebug(slideSceneObject, 0);
}

Foam::slideSceneObject::slideSceneObject(const objectRegistry& db)
:
    regIOobject
    (
        IOobject
        (
            "slideSceneObject",
            db.time().constant(),
            db.time(),
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    )
{
    // In a decomposed run every rank reads the undecomposed case's scene.
    const fileName caseDir = db.time().globalPath();
    try
    {
        scene_ = slide::scene::Scene::read(caseDir);
    }
    catch (const slide::scene::InputError& e)
    {
        FatalErrorInFunction
            << "bad scene input: " << e.what() << nl << exit(FatalError);
    }
}


const slide::scene::Scene& Foam::slideSceneObject::New(const objectRegistry& db)
{
    const Time& runTime = db.time();
    const slideSceneObject* ptr = runTime.cfindObject<slideSceneObject>("slideSceneObject");
    if (!ptr)
    {
        slideSceneObject* created = new slideSceneObject(db);
        created->store();
        ptr = created;
    }
    return ptr->scene();
}
