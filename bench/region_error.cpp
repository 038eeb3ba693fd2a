// Relative MSE of a test image against a reference over a rectangle of pixels, as
// `glint compare` computes it over the whole image: for time-to-error measurements of one
// region (a caustic) that the rest of the image would drown.
//   glint_bench_region_error TEST.exr REF.exr X0 Y0 X1 Y1     (pixels [X0, X1) x [Y0, Y1))
// REF.exr may be the whole image or just the region (a render with --crop X0,Y0,X1,Y1).
#include <glint/core/error.h>
#include <glint/film/image_io.h>

#include <fmt/format.h>

#include <cstdio>
#include <string>

namespace {

glint::Image crop(const glint::Image& image, int x0, int y0, int x1, int y1) {
    glint::Image region = glint::make_image(x1 - x0, y1 - y0, {"R", "G", "B"});
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const int channel = image.channel_index(names[c]);
        if (channel < 0) throw glint::Error(fmt::format("channel {} missing", names[c]));
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) region.at(x - x0, y - y0, c) = image.at(x, y, channel);
    }
    return region;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr, "usage: %s TEST.exr REF.exr X0 Y0 X1 Y1\n", argv[0]);
        return 2;
    }
    try {
        const glint::Image test = glint::read_image(argv[1]);
        const glint::Image reference = glint::read_image(argv[2]);
        const int x0 = std::stoi(argv[3]), y0 = std::stoi(argv[4]);
        const int x1 = std::stoi(argv[5]), y1 = std::stoi(argv[6]);
        if (!(0 <= x0 && x0 < x1 && x1 <= test.width && 0 <= y0 && y0 < y1 && y1 <= test.height))
            throw glint::Error("the region must lie inside the image and not be empty");
        // A reference of exactly the region's size is a crop render (--crop) of the region.
        const bool reference_is_region =
            reference.width == x1 - x0 && reference.height == y1 - y0 &&
            (reference.width != test.width || reference.height != test.height);
        const glint::Image reference_region = reference_is_region
                                                  ? crop(reference, 0, 0, x1 - x0, y1 - y0)
                                                  : crop(reference, x0, y0, x1, y1);
        const glint::CompareResult r =
            glint::compare_images(crop(test, x0, y0, x1, y1), reference_region);
        fmt::print("{:.6g}\n", r.rel_mse);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
