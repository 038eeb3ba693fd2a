#pragma once
// Spectral mode for methods that prepare what their camera paths read (a photon map, a
// radiosity solution) before the first camera ray. A photon's power, or a patch's radiosity,
// is known at the wavelengths it was traced or solved at, and a camera path can only read it
// at those same wavelengths. So such a method works with a few fixed sets of wavelengths
// (sppm's passes do the same, one set per pass): it prepares each set's part, and each camera
// sample takes one set, the same set for all of its path, and reads that set's part only.
// The sets' heroes stratify the visible range (pass_wavelengths), and a pixel's samples cycle
// through the sets from an offset of its own, so that a pixel with as many samples as there
// are sets sees each set once.
#include <glint/core/spectrum.h>
#include <glint/math/vector.h>

#include <cstdint>
#include <vector>

namespace glint {

class WavelengthSets {
public:
    /// One set and no wavelengths: RGB mode (every photon and sample in set 0).
    WavelengthSets() = default;
    /// `count` sets (>= 1), their heroes drawn from `seed`.
    WavelengthSets(int count, uint64_t seed);

    /// Whether there are wavelengths at all (spectral mode).
    bool spectral() const { return !m_sets.empty(); }
    /// Sets there are (1 in RGB mode).
    int count() const { return spectral() ? static_cast<int>(m_sets.size()) : 1; }
    /// The wavelengths of set `set` (spectral mode only).
    const WavelengthContext& operator[](int set) const { return m_sets[static_cast<size_t>(set)]; }
    /// The set of sample `index` of `pixel` (0 in RGB mode).
    int set_of_sample(uint64_t seed, Vec2i pixel, int index) const;
    /// The set of particle `index` (a photon): the sets take turns.
    int set_of_particle(uint64_t index) const {
        return static_cast<int>(index % static_cast<uint64_t>(count()));
    }
    /// The set the calling thread's current path carries: the one whose wavelengths are
    /// active (a WavelengthScope over one of this object's sets); 0 in RGB mode.
    int active_set() const;

private:
    std::vector<WavelengthContext> m_sets;
};

/// How many sets spectral mode uses by default (render setting `wavelength_sets`).
inline constexpr int kDefaultWavelengthSets = 16;

}  // namespace glint
