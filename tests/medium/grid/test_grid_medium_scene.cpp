// glint.medium{ type = "grid" | "cloud" } from a scene script: built into a heterogeneous
// medium, and a bad parameter or grid file an error with the script's file and line.
#include <glint/core/error.h>
#include <glint/medium/heterogeneous_medium.h>
#ifdef GLINT_HAVE_NANOVDB
#include <glint/medium/grid/nanovdb_file.h>
#endif
#include <glint/scene/scene.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace glint {
namespace {

using ::testing::HasSubstr;

const HeterogeneousMedium& only_medium(const test::BuiltScene& built) {
    EXPECT_EQ(built.scene->media().size(), 1u);
    const auto* medium = dynamic_cast<const HeterogeneousMedium*>(built.scene->media()[0].get());
    if (medium == nullptr) throw Error("not a heterogeneous medium");
    return *medium;
}

TEST(GridMediumScene, CloudIsBuiltWithItsParameters) {
    const test::BuiltScene built = test::build_lua(R"(
        glint.medium{ type = "cloud", min = {0, 0, 0}, max = {2, 1, 1}, resolution = 20,
                      density = 4, albedo = 0.5, g = 0.3, majorant_resolution = 4 }
    )");
    const HeterogeneousMedium& medium = only_medium(built);
    EXPECT_EQ(medium.grid().dims(), (GridIndex{20, 20, 20}));
    EXPECT_EQ(medium.majorant_grid().resolution(), (GridIndex{4, 4, 4}));
    EXPECT_FLOAT_EQ(medium.phase_asymmetry(), 0.3f);
    // Coefficients at density 1 split by the albedo, scaled by the density at the point.
    const Vec3 centre(1.0f, 0.5f, 0.5f);
    const float density = medium.grid().density(Vec3(0.5f));
    const MediumPoint p = medium.at(centre);
    EXPECT_GT(density, 0.0f);
    EXPECT_NEAR(p.sigma_s.value(0), 2.0f * density, 1e-5f);
    EXPECT_NEAR(p.sigma_a.value(1), 2.0f * density, 1e-5f);
    EXPECT_TRUE(medium.at(Vec3(2.5f, 0.5f, 0.5f)).sigma_s.is_black());
}

#ifdef GLINT_HAVE_NANOVDB
TEST(GridMediumScene, GridFileIsPlacedByItsTransform) {
    test::TempDir dir("glint-grid-scene");
    const std::string path = dir.file("block.nvdb");
    write_nanovdb_grid(path, "density", {{{0, 0, 0}, 2.0f}, {{1, 0, 0}, 2.0f}}, 0.5);
    const test::BuiltScene built = test::build_lua(fmt::format(R"(
        glint.medium{{ type = "grid", file = "{}", grid = "density", sigma_s = 1,
                      transform = glint.translate(10, 0, 0) }}
    )",
                                                               path));
    const HeterogeneousMedium& medium = only_medium(built);
    // Index box [-0.5, 1.5] x [-0.5, 0.5]^2 at 0.5 units per voxel, moved by 10 along x.
    EXPECT_FLOAT_EQ(medium.at(Vec3(10.2f, 0.0f, 0.0f)).sigma_s.value(0), 2.0f);
    EXPECT_TRUE(medium.at(Vec3(0.2f, 0.0f, 0.0f)).sigma_s.is_black());
}
#endif

TEST(GridMediumScene, BadParametersNameTheScriptLine) {
    const auto error = [](const std::string& code) {
        return test::error_of([&] { test::build_lua(code, "smoke.lua"); });
    };
    EXPECT_THAT(error("\n glint.medium{ type = \"grid\", file = \"/no/such/smoke.nvdb\" }"),
                AllOf(HasSubstr("smoke.lua:2"), HasSubstr("/no/such/smoke.nvdb")));
    EXPECT_THAT(error("glint.medium{ type = \"fog\" }"),
                AllOf(HasSubstr("smoke.lua:1"), HasSubstr("homogeneous, grid or cloud")));
    EXPECT_THAT(error("glint.medium{ type = \"cloud\", file = \"x.nvdb\" }"),
                AllOf(HasSubstr("smoke.lua:1"), HasSubstr("file")));
    EXPECT_THAT(error("glint.medium{ type = \"cloud\", resolution = 100000 }"),
                HasSubstr("'resolution' must lie in [1, 512]"));
    EXPECT_THAT(error("glint.medium{ type = \"cloud\", min = {0, 0, 0}, max = {1, 0, 1} }"),
                HasSubstr("'max' must exceed 'min'"));
    EXPECT_THAT(error("glint.medium{ type = \"grid\" }"), HasSubstr("file"));
}

}  // namespace
}  // namespace glint
