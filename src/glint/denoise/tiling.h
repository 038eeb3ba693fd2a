#pragma once
// Cutting an image into the tiles the network runs on, so that memory stays bounded for any
// image size. Tiles overlap: the network's receptive field is 174 pixels wide, so a pixel's
// result depends on its neighbours up to 87 pixels away, and each tile's outer 96 pixels
// (87 rounded up to the 16-pixel alignment) are computed but not kept, except at the image's
// border. All tiles have the same size (one set of primitives serves them all); an image
// narrower than a tile is padded with zeros to a multiple of 16 on the right or bottom.

#include <vector>

namespace glint {

struct DenoiseTile {
    int x = 0, y = 0;  ///< the tile's top-left pixel in the image
    int keep_x0 = 0,
        keep_y0 = 0;  ///< the pixels it writes: [keep_x0, keep_x1) x [keep_y0, keep_y1)
    int keep_x1 = 0, keep_y1 = 0;
};

struct TilePlan {
    int width = 0, height = 0;  ///< of each tile, multiples of `alignment`
    std::vector<DenoiseTile> tiles;
};

constexpr int denoise_tile_overlap = 96;
constexpr int denoise_tile_alignment = 16;

/// Tiles of at most `max_tile` x `max_tile` pixels (a multiple of the alignment larger than
/// twice the overlap) whose kept regions cover every pixel of the image exactly once.
TilePlan plan_denoise_tiles(int width, int height, int max_tile);

}  // namespace glint
