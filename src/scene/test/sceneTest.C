// Reading a whole scene (constant/sceneProperties + system/controlDict) and
// the checks that reject a physically meaningless one.
#include "blockScene.H"
#include "scene.H"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using slide::scene::InputError;
using slide::scene::Scene;
using slide::scene::Interface;
using slide::scene::blockScene;

namespace
{

const char* flumeScene = R"(FoamFile { version 2.0; format ascii; class dictionary; object sceneProperties; }
title "Krone-Wright Run 15";
g 9.81;
slide
{
    shape        rectangle;
    length       1.8;
    height       0.3;
    rearPosition 0;
    rearWall     yes;
    density      1073;
}
rheology
{
    model    HerschelBulkleyRemoulding;
    s_uo     42.5;
    eta      0.0052;
    n        1;
    gdotRef  0.06;
    deltaRem 1;
}
base
{
    profile   planar;
    angle     3.43;
    interface noSlip;
}
ambient
{
    phase light;
}
)";

const char* control = "startTime 0;\nendTime 4.1;\nwriteInterval 0.1;\nstopAtRest yes;\n";

class SceneFixture : public ::testing::Test
{
protected:
    fs::path dir;

    void SetUp() override
    {
        dir = fs::temp_directory_path()/("slideSceneTest_" + std::to_string(::getpid()) + "_"
              + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir/"constant");
        fs::create_directories(dir/"system");
    }
    void TearDown() override { fs::remove_all(dir); }

    void write(const std::string& scene, const std::string& ctrl = control)
    {
        std::ofstream(dir/"constant/sceneProperties") << scene;
        std::ofstream(dir/"system/controlDict") << ctrl;
    }

    // Replace the first occurrence of `from` in the flume scene.
    static std::string edit(const std::string& from, const std::string& to)
    {
        std::string s = flumeScene;
        const std::size_t k = s.find(from);
        EXPECT_NE(k, std::string::npos) << from;
        return s.replace(k, from.size(), to);
    }

    // A profile-shaped slide takes no length, height or rearPosition.
    static std::string withoutRectangleKeys(std::string sc)
    {
        for (const char* k : {"    length       1.8;\n", "    height       0.3;\n", "    rearPosition 0;\n"})
        {
            sc = sc.replace(sc.find(k), std::string(k).size(), "");
        }
        return sc;
    }

    InputError readError()
    {
        try
        {
            Scene::read(dir.string());
        }
        catch (const InputError& e)
        {
            return e;
        }
        ADD_FAILURE() << "scene was accepted";
        return InputError("", 0, "", "");
    }
};

} // namespace

TEST_F(SceneFixture, ReadsTheFlume)
{
    write(flumeScene);
    const Scene s = Scene::read(dir.string());
    EXPECT_EQ(s.title, "Krone-Wright Run 15");
    EXPECT_DOUBLE_EQ(s.slide.length, 1.8);
    EXPECT_DOUBLE_EQ(s.slide.height, 0.3);
    EXPECT_TRUE(s.slide.rearWall);
    EXPECT_DOUBLE_EQ(s.slide.density, 1073.0);
    EXPECT_DOUBLE_EQ(s.rheology.s_uo, 42.5);
    EXPECT_DOUBLE_EQ(s.rheology.eta, 0.0052);
    EXPECT_DOUBLE_EQ(s.rheology.gdotRef, 0.06);
    EXPECT_DOUBLE_EQ(s.rheology.deltaRem, 1.0);
    EXPECT_TRUE(s.base.isPlanar());
    EXPECT_NEAR(s.base.angle(0.0), 3.43*M_PI/180.0, 1e-12);
    EXPECT_EQ(s.interface.type, slide::scene::Interface::Type::noSlip);
    EXPECT_EQ(s.ambient.phase, slide::scene::Ambient::Phase::light);
    EXPECT_DOUBLE_EQ(s.control.endTime, 4.1);
    EXPECT_DOUBLE_EQ(s.control.writeInterval, 0.1);
    EXPECT_TRUE(s.control.stopAtRest);
    EXPECT_NEAR(s.slide.area(), 0.54, 1e-12);
}

TEST_F(SceneFixture, FrictionalAndHydroplaningInterfaces)
{
    write(edit("interface noSlip;", "interface frictional;\n    s_b 450;"));
    Scene s = Scene::read(dir.string());
    EXPECT_EQ(s.interface.type, slide::scene::Interface::Type::frictional);
    EXPECT_DOUBLE_EQ(s.interface.basalStrength(10.0), 450.0);

    write(edit("interface noSlip;", "interface hydroplaning;\n    C_F 0.003;"));
    s = Scene::read(dir.string());
    EXPECT_EQ(s.interface.type, slide::scene::Interface::Type::hydroplaning);
    EXPECT_NEAR(s.interface.basalStrength(7.2), 77.76, 1e-9);
}

TEST_F(SceneFixture, PolylineBaseAndThicknessProfile)
{
    std::string sc = edit("profile   planar;\n    angle     3.43;", "profile polyline;\n    points ((0 0) (100 -10) (300 -12));");
    sc = sc.replace(sc.find("shape        rectangle;"), 23, "shape profile;\n    thickness ((10 0) (20 4) (40 4) (50 0));");
    sc = withoutRectangleKeys(sc);
    write(sc);
    const Scene s = Scene::read(dir.string());
    EXPECT_FALSE(s.base.isPlanar());
    EXPECT_DOUBLE_EQ(s.slide.rearPosition, 10.0);
    EXPECT_DOUBLE_EQ(s.slide.length, 40.0);
    EXPECT_DOUBLE_EQ(s.slide.height, 4.0);
    EXPECT_DOUBLE_EQ(s.slide.area(), 0.5*4*10 + 4*20 + 0.5*4*10);
    EXPECT_DOUBLE_EQ(s.slide.thickness(15.0), 2.0);
    EXPECT_DOUBLE_EQ(s.slide.thickness(60.0), 0.0);
}

TEST_F(SceneFixture, BadValuesNameFileLineAndKey)
{
    struct Bad { std::string from, to, key; int line; };
    const std::vector<Bad> bad = {
        {"s_uo     42.5;", "s_uo     -42.5;", "rheology.s_uo", 16},
        {"s_uo     42.5;", "s_uo     0;", "rheology.s_uo", 16},
        {"deltaRem 1;", "deltaRem 1.5;", "rheology.deltaRem", 20},
        {"deltaRem 1;", "deltaRem 0;", "rheology.deltaRem", 20},
        {"n        1;", "n        0;", "rheology.n", 18},
        {"n        1;", "n        -0.2;", "rheology.n", 18},
        {"deltaRem 1;", "deltaRem 0.5;", "rheology.xi95", 13},   // xi95 needed with softening
        {"length       1.8;", "length       -1;", "slide.length", 7},
        {"density      1073;", "density      abc;", "slide.density", 11},
        {"angle     3.43;", "angle     95;", "base.angle", 25},
        {"interface noSlip;", "interface sticky;", "base.interface", 26},
        {"interface noSlip;", "interface frictional;", "base.s_b", 22},
        {"interface noSlip;", "interface noSlip; s_b 4;", "base.s_b", 26},
        {"model    HerschelBulkleyRemoulding;", "model    Bingham;", "rheology.model", 15},
        {"eta      0.0052;", "etta      0.0052;", "rheology.etta", 17},
    };
    for (const Bad& b : bad)
    {
        write(edit(b.from, b.to));
        const InputError e = readError();
        EXPECT_EQ(e.key(), b.key) << b.to << " -> " << e.what();
        EXPECT_EQ(e.line(), b.line) << b.to << " -> " << e.what();
        EXPECT_EQ(fs::path(e.file()).filename(), "sceneProperties") << e.what();
    }
}

TEST_F(SceneFixture, PolylineMustBeMonotonicAndHoldTheSlide)
{
    write(edit("profile   planar;\n    angle     3.43;", "profile polyline;\n    points ((0 0) (10 -1) (5 -2));"));
    InputError e = readError();
    EXPECT_EQ(e.key(), "base.points");
    EXPECT_NE(e.message().find("increase strictly"), std::string::npos) << e.what();

    write(edit("profile   planar;\n    angle     3.43;", "profile polyline;\n    points ((0 0) (1 -0.1));"));
    e = readError();
    EXPECT_EQ(e.key(), "slide.rearPosition");
    EXPECT_NE(e.message().find("does not lie on the base"), std::string::npos) << e.what();
}

TEST_F(SceneFixture, SitesAreReadInOrderAndBadOnesNamed)
{
    std::string sc = flumeScene;
    write(sc + "sites\n{\n    pipeline { position 4.5; }\n    cable    { position -1; }\n}\n");
    const Scene s = Scene::read(dir.string());
    ASSERT_EQ(s.sites.size(), 2u);
    EXPECT_EQ(s.sites[0].name, "pipeline");
    EXPECT_DOUBLE_EQ(s.sites[0].position, 4.5);
    EXPECT_EQ(s.sites[1].name, "cable");
    EXPECT_DOUBLE_EQ(s.sites[1].position, -1.0);
    EXPECT_NE(s.describe().find("pipeline at 4.5 m"), std::string::npos) << s.describe();

    struct Bad { std::string sites, key; int line; std::string message; };
    const std::vector<Bad> bad = {
        {"sites\n{\n    pipeline 4.5;\n}\n", "sites.pipeline", 34, "a site is a sub-dictionary"},
        {"sites\n{\n    pipeline { position 4.5; depth 2; }\n}\n", "sites.pipeline.depth", 34, "unknown key"},
        {"sites\n{\n    pipeline { }\n}\n", "sites.pipeline.position", 34, "missing"},
        {"sites\n{\n    pipeline { position abc; }\n}\n", "sites.pipeline.position", 34, ""},
        {"sites\n{\n    pipeline { position 1e9; }\n}\n", "sites.pipeline.position", 34, "must lie in"},
    };
    for (const Bad& b : bad)
    {
        write(sc + b.sites);
        const InputError e = readError();
        EXPECT_EQ(e.key(), b.key) << b.sites << " -> " << e.what();
        EXPECT_EQ(e.line(), b.line) << b.sites << " -> " << e.what();
        EXPECT_NE(e.message().find(b.message), std::string::npos) << e.what();
    }

    // On a polyline the site must lie on it.
    write(edit("profile   planar;\n    angle     3.43;", "profile polyline;\n    points ((0 0) (10 -1));")
          + "sites\n{\n    pipeline { position 12; }\n}\n");
    InputError e = readError();
    EXPECT_EQ(e.key(), "sites.pipeline.position");
    EXPECT_NE(e.message().find("does not lie on the base polyline"), std::string::npos) << e.what();

    // At most 32: slideMPM reduces over its particles for every site every step.
    std::string many = "sites\n{\n";
    for (int k = 0; k < 33; ++k) many += "    s" + std::to_string(k) + " { position " + std::to_string(k) + "; }\n";
    write(sc + many + "}\n");
    e = readError();
    EXPECT_EQ(e.key(), "sites.s32");
    EXPECT_NE(e.message().find("more than 32 sites"), std::string::npos) << e.what();
}

TEST_F(SceneFixture, RigidSlabFactorOfSafetyIsTheLimitEquilibrium)
{
    // A block L x H on a planar base: s_u at rest over rho' g H sin(theta), the interface's
    // strength where lower than the clay's, none for a hydroplaning base at rest.
    const double H = 5.0, rho = 600.0, theta = 5.0*M_PI/180.0;
    const double weightAlong = rho*9.81*H*std::sin(theta);
    Scene s = blockScene(5.0, 40.0, H, rho, 5000.0, Interface());
    EXPECT_NEAR(s.rigidSlabFactorOfSafety(), 5000.0/weightAlong, 1e-12);   // Table 1 Case 6: 1.95
    EXPECT_NEAR(s.rigidSlabDriving(), 40.0*weightAlong, 1e-9);
    Interface frictional;
    frictional.type = Interface::Type::frictional;
    frictional.s_b = 1800.0;
    s.interface = frictional;
    EXPECT_NEAR(s.rigidSlabFactorOfSafety(), 1800.0/weightAlong, 1e-12);  // Case 8: 0.70
    frictional.s_b = 9000.0;
    s.interface = frictional;
    EXPECT_NEAR(s.rigidSlabFactorOfSafety(), 5000.0/weightAlong, 1e-12);  // the clay fails first
    Interface hydroplaning;
    hydroplaning.type = Interface::Type::hydroplaning;
    hydroplaning.C_F = 0.003;
    s.interface = hydroplaning;
    EXPECT_EQ(s.rigidSlabFactorOfSafety(), 0.0);
    s = blockScene(0.0, 40.0, H, rho, 5000.0, Interface());
    EXPECT_TRUE(std::isinf(s.rigidSlabFactorOfSafety()));
    EXPECT_NE(s.describe().find("factor of safety infinite"), std::string::npos) << s.describe();

    // A thickness profile across a polyline's kink: each part's weight along its own segment.
    std::string sc = edit("profile   planar;\n    angle     3.43;", "profile polyline;\n    points ((0 0) (30 -3) (300 -5));");
    sc = sc.replace(sc.find("shape        rectangle;"), 23, "shape profile;\n    thickness ((10 0) (20 4) (40 4) (50 0));");
    write(withoutRectangleKeys(sc));
    const Scene p = Scene::read(dir.string());
    const double L1 = std::hypot(30.0, 3.0);
    const double A1 = 0.5*4.0*10.0 + 4.0*(L1 - 20.0), A2 = 4.0*(40.0 - L1) + 0.5*4.0*10.0;
    const double driving = p.slide.density*p.g*(A1*3.0/L1 + A2*2.0/std::hypot(270.0, 2.0));
    EXPECT_NEAR(p.rigidSlabDriving()/driving, 1.0, 1e-4);
    EXPECT_NEAR(p.rigidSlabResistance(), p.rheology.s_uo*40.0, 1e-9*p.rheology.s_uo);
    EXPECT_NE(p.describe().find("as a rigid slab"), std::string::npos) << p.describe();
}

TEST(Scene, StrongBlockSlidingFreely)
{
    // s_uo over rho' g H0, and the regime where slideFoam's plug was measured to fail: a slide that must slide on a
    // frictional or hydroplaning base, stronger than the ratio asked.
    const double H = 5.0, rho = 600.0;
    Interface frictionless;
    frictionless.type = Interface::Type::frictional;
    frictionless.s_b = 0.0;
    Scene s = blockScene(5.0, 40.0, H, rho, 200000.0, frictionless);
    EXPECT_NEAR(s.strengthOverWeightStress(), 200000.0/(rho*9.81*H), 1e-12);   // 6.80
    EXPECT_TRUE(s.slidesFreelyStrongerThan(4.0));
    EXPECT_FALSE(s.slidesFreelyStrongerThan(8.0));
    s.rheology.s_uo = 50000.0;                                                 // 1.70
    EXPECT_FALSE(s.slidesFreelyStrongerThan(Scene::cfdStrongBlockRatio));
    s = blockScene(5.0, 40.0, H, rho, 200000.0, Interface());                  // no-slip: held
    EXPECT_FALSE(s.slidesFreelyStrongerThan(4.0));
    Interface held;
    held.type = Interface::Type::frictional;
    held.s_b = 5000.0;                                                         // above rho' g H sin(5 deg), 2565 Pa
    s = blockScene(5.0, 40.0, H, rho, 200000.0, held);
    EXPECT_FALSE(s.slidesFreelyStrongerThan(4.0));
    Interface hydroplaning;
    hydroplaning.type = Interface::Type::hydroplaning;
    hydroplaning.C_F = 0.003;
    s = blockScene(5.0, 40.0, H, rho, 200000.0, hydroplaning);
    EXPECT_TRUE(s.slidesFreelyStrongerThan(4.0));
}

TEST_F(SceneFixture, SlideBelowTheBaseIsRejected)
{
    std::string sc = edit("shape        rectangle;", "shape profile;\n    thickness ((0 0) (1 -0.2) (2 0));");
    sc = withoutRectangleKeys(sc);
    write(sc);
    const InputError e = readError();
    EXPECT_EQ(e.key(), "slide.thickness");
    EXPECT_NE(e.message().find("below the base"), std::string::npos) << e.what();
}

TEST_F(SceneFixture, EndTimeBeforeStartTime)
{
    write(flumeScene, "startTime 5;\nendTime 4.1;\nwriteInterval 0.1;\n");
    const InputError e = readError();
    EXPECT_EQ(e.key(), "endTime");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(fs::path(e.file()).filename(), "controlDict");
}

TEST_F(SceneFixture, PurgeWriteReadAndNegativeRejected)
{
    write(flumeScene, "endTime 4.1;\nwriteInterval 0.1;\npurgeWrite 2;\n");
    EXPECT_EQ(Scene::read(dir.string()).control.purgeWrite, 2);
    write(flumeScene, "endTime 4.1;\nwriteInterval 0.1;\npurgeWrite -1;\n");
    const InputError e = readError();
    EXPECT_EQ(e.key(), "purgeWrite");
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(fs::path(e.file()).filename(), "controlDict");
}

TEST_F(SceneFixture, MissingSceneFile)
{
    const InputError e = readError();
    EXPECT_NE(e.file().find("constant/sceneProperties"), std::string::npos);
}
