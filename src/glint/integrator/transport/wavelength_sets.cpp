#include <glint/core/error.h>
#include <glint/core/rng.h>
#include <glint/integrator/transport/spectral_model.h>
#include <glint/integrator/transport/wavelength_sets.h>

#include <algorithm>
#include <functional>

namespace glint {

// Each set's four lanes are its hero rotated by a quarter of the range (in the visible
// density's u). The sets are placed on a grid of 4 x count points in u so that no lane of
// one set falls on a lane of another (all 4 x count wavelengths differ, as evenly spaced as
// a stratified draw), while the heroes alone still cover the whole range in order: set k's
// hero is the first grid point from k / count on whose rotations are all still free. (The
// heroes alone must cover it: after dispersive glass a path is read at its hero only.)
WavelengthSets::WavelengthSets(int count, uint64_t seed) {
    if (count < 1) throw Error("a spectral method needs at least one set of wavelengths");
    const int points = 4 * count;  // lanes of set k: grid points m, m + count, m + 2 count, ...
    std::vector<bool> residue_taken(static_cast<size_t>(count), false);
    const double offset = (mix_bits(seed ^ 0x3c6ef372u) >> 11) * 0x1p-53;
    m_sets.reserve(static_cast<size_t>(count));
    for (int set = 0; set < count; ++set) {
        int m = 4 * set;
        while (residue_taken[static_cast<size_t>(m % count)]) m = (m + 1) % points;
        residue_taken[static_cast<size_t>(m % count)] = true;
        double u = offset + static_cast<double>(m) / points;
        if (u >= 1.0) u -= 1.0;
        const float hero_u = std::min(static_cast<float>(u), 0x1.fffffep-1f);
        m_sets.push_back({SampledWavelengths::sample_visible(hero_u), &spectral_model()});
    }
}

int WavelengthSets::set_of_sample(uint64_t seed, Vec2i pixel, int index) const {
    if (!spectral()) return 0;
    const uint64_t offset =
        hash_combine(mix_bits(seed ^ 0xa54ff53au),
                     (static_cast<uint64_t>(static_cast<uint32_t>(pixel.y)) << 32) |
                         static_cast<uint32_t>(pixel.x));
    return static_cast<int>((offset + static_cast<uint64_t>(index)) % m_sets.size());
}

int WavelengthSets::active_set() const {
    if (!spectral()) return 0;
    // The active context is one of m_sets' elements: its index is its offset (read once
    // per photon estimate or radiosity lookup, so no search).
    const WavelengthContext* active = detail::t_active_wavelengths;
    const std::less<const WavelengthContext*> before;
    const WavelengthContext* first = m_sets.data();
    if (active != nullptr && !before(active, first) && before(active, first + m_sets.size()))
        return static_cast<int>(active - first);
    throw Error(
        "internal: a camera path reads a prepared spectral estimate outside its sets' "
        "wavelengths");
}

}  // namespace glint
