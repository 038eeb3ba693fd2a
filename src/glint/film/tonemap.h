#pragma once
// Display tone mapping: the curve that takes scene-linear radiance, scaled by the
// exposure, to display-linear values in [0, 1] before the sRGB transfer of an 8-bit image.
// EXR output never passes through it. A plain function on a value, a pixel or an Image, so
// that every display path (PNG output, the viewer) shows the same picture.
#include <glint/film/image.h>

#include <string>
#include <string_view>

namespace glint {

/// The tone curves, applied to each of R, G, B independently.
enum class Tonemap {
    clip,      ///< identity, then clamped to [0, 1]: what glint always wrote
    reinhard,  ///< x / (1 + x) (Reinhard et al. 2002, "Photographic tone reproduction", eq. 3)
    filmic,    ///< Narkowicz's 2015 fit of the ACES reference rendering transform:
               ///< x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), clamped to [0, 1]
};

/// How an image becomes a display image: the curve after a scale of 2^exposure.
struct ToneMapping {
    Tonemap curve = Tonemap::clip;
    float exposure = 0.0f;  ///< stops
};

/// The curve called `name` ("clip", "reinhard", "filmic"); throws glint::Error naming the
/// known curves otherwise.
Tonemap parse_tonemap(std::string_view name);
/// The name parse_tonemap() reads.
std::string tonemap_name(Tonemap curve);

/// The curve at `x` (linear, exposure already applied): a display-linear value in [0, 1].
/// Monotone non-decreasing, 0 at 0; non-positive and NaN inputs give 0.
double tone_curve(Tonemap curve, double x);

/// tone_curve(curve, 2^exposure * linear), computed as the PNG writer does.
double tone_map_value(const ToneMapping& mapping, double linear);

/// The R, G, B channels of `image` (found by name; or its only channel) replaced by their
/// tone-mapped, display-linear values in [0, 1]; other channels are left as they are.
/// Throws glint::Error when the image has neither R, G, B nor a single channel.
void tone_map(Image& image, const ToneMapping& mapping);

}  // namespace glint
