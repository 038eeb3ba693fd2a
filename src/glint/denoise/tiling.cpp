#include <glint/core/error.h>
#include <glint/denoise/tiling.h>

#include <fmt/format.h>

#include <algorithm>

namespace glint {

namespace {

struct Span {
    int start, keep0, keep1;
};

// One axis. An image no longer than a tile gets one tile at 0 (padded). Otherwise the
// interior [overlap, size - overlap) is split evenly into n spans of at most tile - 2 overlap
// pixels; the first span also keeps the pixels before it and the last those after it (the
// image's border), and each tile starts `overlap` before its span, moved inwards where that
// would leave the image.
std::vector<Span> plan_axis(int size, int tile) {
    if (size <= tile) return {{0, 0, size}};
    const int ov = denoise_tile_overlap;
    const long interior = size - 2 * ov;
    const long kept = tile - 2 * ov;
    const long n = (interior + kept - 1) / kept;
    auto boundary = [&](long i) {
        if (i == 0) return 0;
        if (i == n) return size;
        return static_cast<int>(ov + i * interior / n);
    };
    std::vector<Span> spans;
    for (long i = 0; i < n; ++i) {
        const int keep0 = boundary(i);
        spans.push_back({std::clamp(keep0 - ov, 0, size - tile), keep0, boundary(i + 1)});
    }
    return spans;
}

int round_up(int value, int step) {
    return (value + step - 1) / step * step;
}

}  // namespace

TilePlan plan_denoise_tiles(int width, int height, int max_tile) {
    if (width <= 0 || height <= 0)
        throw Error(fmt::format("cannot denoise a {} x {} image", width, height));
    if (max_tile % denoise_tile_alignment != 0 || max_tile <= 2 * denoise_tile_overlap)
        throw Error(fmt::format("denoiser tiles of {} pixels: expected a multiple of {} above {}",
                                max_tile, denoise_tile_alignment, 2 * denoise_tile_overlap));
    TilePlan plan;
    plan.width = std::min(max_tile, round_up(width, denoise_tile_alignment));
    plan.height = std::min(max_tile, round_up(height, denoise_tile_alignment));
    for (const Span& row : plan_axis(height, max_tile)) {
        for (const Span& column : plan_axis(width, max_tile)) {
            plan.tiles.push_back(
                {column.start, row.start, column.keep0, row.keep0, column.keep1, row.keep1});
        }
    }
    return plan;
}

}  // namespace glint
