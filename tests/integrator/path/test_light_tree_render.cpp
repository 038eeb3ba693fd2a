// The light tree in renders of examples/many-lights.lua (1,024 lamps): at equal samples its
// image is at least five times closer to the reference than power sampling's, and it gives
// the same bits for one and two threads. The same for examples/lamps-as-one-mesh.lua, the
// same lamps as four emissive meshes: the tree chooses among their triangles one by one.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <support/render_helpers.h>
#include <support/test_util.h>

#include <string>

using namespace glint;
using namespace glint::test;

namespace {

std::string many_lights(const std::string& light_sampler, int spp, int seed,
                        const std::string& example = "many-lights.lua") {
    return example_with_settings(
        example, fmt::format("width = 48, height = 36, spp = {}, seed = {}, max_depth = 2, "
                             "light_sampler = '{}'",
                             spp, seed, light_sampler));
}

// Relative MSE of `image` against `reference`, per pixel and channel, with a floor on the
// denominator of 1 % of the reference's mean so that near-black pixels do not dominate.
double relative_mse(const Image& image, const Image& reference) {
    double mean = 0.0;
    for (float v : reference.pixels) mean += v;
    mean /= static_cast<double>(reference.pixels.size());
    const double floor = 1e-2 * mean * mean;
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const double d = image.pixels[i] - reference.pixels[i];
        sum += d * d / (static_cast<double>(reference.pixels[i]) * reference.pixels[i] + floor);
    }
    return sum / static_cast<double>(image.pixels.size());
}

}  // namespace

TEST(ManyLights, TreeRelativeErrorAtLeastFiveTimesLowerThanPower) {
    // The reference: the tree at 64 times the samples (its own error is then about 1/64 of
    // the tree's at 4 spp, and far below power sampling's).
    const Image reference = render_lua(many_lights("tree", 256, 99));
    const Image tree = render_lua(many_lights("tree", 4, 1));
    const Image power = render_lua(many_lights("power", 4, 1));
    const double tree_error = relative_mse(tree, reference);
    const double power_error = relative_mse(power, reference);
    EXPECT_GE(power_error, 5.0 * tree_error)
        << "relMSE tree " << tree_error << ", power " << power_error;
}

TEST(ManyLights, TreeGivesTheSameBitsForOneAndTwoThreads) {
    const std::string scene = many_lights("tree", 2, 5);
    const Image one = render_lua(scene, 1);
    const Image two = render_lua(scene, 2);
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_TRUE(one.pixels == two.pixels);
}

// Power sampling chooses one of the four meshes by power, then a triangle on it by area:
// no better than choosing among all lamps by power. The tree, with a leaf per triangle,
// must do as well as it does with 1,024 separate lamps.
TEST(ManyLights, TreeChoosesAmongTheTrianglesOfEmissiveMeshes) {
    if (test::kSanitizerBuild) GTEST_SKIP() << "three 256-spp references: the normal tree runs it";
    const std::string meshes = "lamps-as-one-mesh.lua";
    const Image reference = render_lua(many_lights("tree", 256, 99, meshes));
    const Image tree = render_lua(many_lights("tree", 4, 1, meshes));
    const Image power = render_lua(many_lights("power", 4, 1, meshes));
    const double tree_error = relative_mse(tree, reference);
    const double power_error = relative_mse(power, reference);
    EXPECT_GE(power_error, 5.0 * tree_error)
        << "relMSE tree " << tree_error << ", power " << power_error;
    // The same scene as many-lights.lua: the two references agree within their noise. Each
    // has about 4/256 of the 4-spp image's error; their difference, twice that.
    const Image lamps = render_lua(many_lights("tree", 256, 98));
    const double noise = 2.0 * tree_error * 4.0 / 256.0;
    EXPECT_LT(relative_mse(reference, lamps), 3.0 * noise) << "noise " << noise;
}
