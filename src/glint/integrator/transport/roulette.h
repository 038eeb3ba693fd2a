#pragma once
// Russian roulette, the two rules glint's walks end paths by. Each walk decides which rule
// it follows; the rules themselves are written once here.
//
//   throughput roulette   camera walks (path, volpath) and the subpaths of bdpt, vcm and
//                         mlt: from the third hit on, a walk whose throughput fell below 1
//                         survives with a probability that falls with it, so that dim
//                         walks end and bright ones are never cut. The subpaths survive in
//                         proportion to the throughput; path and volpath with its square
//                         root (as Cycles does), which keeps more of the dim paths that
//                         still carry light. On the Cornell box (256 x 256, 2 threads) the
//                         square root took 10 % more time for 24 % lower relative MSE at
//                         64 spp (efficiency +16 to +24 % at 16 to 256 spp); for bdpt and
//                         vcm, whose vertices each pay for connections, it lost 6 and 9 %
//   power roulette        particles (photons, light-tracing paths): a particle survives
//                         with the fraction of power its scattering kept, so the power it
//                         carries stays roughly constant (Jensen 2001)
//
// The random number is drawn only where roulette applies, so that walks that never meet it
// draw nothing: `draw` is called at most once.
#include <algorithm>
#include <cmath>

namespace glint {

/// The depth (0 at the first hit) from which throughput roulette applies.
constexpr int kRouletteMinDepth = 2;

/// Throughput roulette at `depth` for a path whose throughput (the radiance scaling of
/// refraction taken out, so light about to leave glass survives) is `throughput`: false
/// when the path ends; otherwise `survival` is the probability it survived with (1 where
/// roulette does not apply), the factor its throughput is divided by.
template <typename Draw>
[[gnu::always_inline]] inline bool survives_throughput_roulette(int depth, float throughput,
                                                                Draw&& draw, float& survival) {
    survival = 1.0f;
    if (depth < kRouletteMinDepth || !(throughput < 1.0f)) return true;
    const float q = std::max(0.0f, 1.0f - throughput);
    if (draw() < q) return false;
    survival = 1.0f - q;
    return true;
}

/// The unidirectional tracers' throughput roulette: as above, surviving with the square root
/// of the throughput.
template <typename Draw>
[[gnu::always_inline]] inline bool survives_path_roulette(int depth, float throughput, Draw&& draw,
                                                          float& survival) {
    survival = 1.0f;
    if (depth < kRouletteMinDepth || !(throughput < 1.0f)) return true;
    const float q = std::max(0.0f, 1.0f - std::sqrt(std::max(0.0f, throughput)));
    if (draw() < q) return false;
    survival = 1.0f - q;
    return true;
}

/// Power roulette for a particle whose scattering kept `kept` of its power (max channel):
/// false when it ends; otherwise `survival` (at most 1) is the probability it survived with.
template <typename Draw>
[[gnu::always_inline]] inline bool survives_power_roulette(float kept, Draw&& draw,
                                                           float& survival) {
    survival = std::min(1.0f, kept);
    return survival > 0.0f && draw() < survival;
}

}  // namespace glint
