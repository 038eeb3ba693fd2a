#include <glint/core/error.h>
#include <glint/core/params.h>

#include <gtest/gtest.h>

using namespace glint;

TEST(Params, ReadsValuesAndDefaults) {
    Params p("diffuse", "scene.lua:3");
    p.set("reflectance", std::vector<double>{0.1, 0.2, 0.3});
    p.set("ior", 1.5);
    EXPECT_EQ(p.get_rgb("reflectance"), Rgb(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(p.get_float("ior", 1.0f), 1.5f);
    EXPECT_FLOAT_EQ(p.get_float("roughness", 0.25f), 0.25f);
    EXPECT_NO_THROW(p.check_all_used());
}

TEST(Params, UnknownNameIsReportedWithLocation) {
    Params p("dielectric", "scene.lua:12");
    p.set("iorr", 1.5);
    p.get_float("ior", 1.5f);
    try {
        p.check_all_used();
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("scene.lua:12"), std::string::npos) << message;
        EXPECT_NE(message.find("iorr"), std::string::npos) << message;
        EXPECT_NE(message.find("ior"), std::string::npos) << message;
    }
}

TEST(Params, WrongTypeIsReported) {
    Params p("sphere", "scene.lua:4");
    p.set("radius", std::string("big"));
    try {
        p.get_float("radius", 1.0f);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("scene.lua:4"), std::string::npos) << message;
        EXPECT_NE(message.find("must be a number"), std::string::npos) << message;
    }
}
