#pragma once
// Spectral mode as the integrators see it: the colour model that reads Rgb inputs at a
// wavelength and weighs a wavelength on the film, and the wavelengths each path carries.
// An integrator in spectral mode opens a WavelengthScope over each path (camera sample,
// light particle, photon, subpath pair) with `path_wavelengths(key)`, where the key is what
// already names that path's random numbers, so the image is the same for any thread count.
#include <glint/core/secondary_wavelengths.h>
#include <glint/core/spectrum.h>

#include <cstdint>
#include <optional>

namespace glint {

/// The model spectral mode uses: Rgb inputs uplifted to smooth spectra, the CIE 1931
/// observer turned into linear Rec.709 and normalised so that a white emitter's
/// spectrum integrates to (1, 1, 1).
const SpectralModel& spectral_model();

/// The wavelengths of the path whose random numbers are keyed by `key` (a pixel sample's
/// key, or a particle's): the hero drawn from a hash of the key, so that the sampler's
/// dimensions, and so RGB mode's images, are untouched.
WavelengthContext path_wavelengths(uint64_t key);

/// The wavelengths whose hero is drawn from `u` in [0, 1): for a method that keeps the
/// wavelength among the dimensions it samples (mlt's primary sample space).
WavelengthContext wavelengths_at(float u);

/// The wavelengths of pass `index` of a progressive method whose passes each share one set
/// (vcm's iterations, sppm's passes): a random offset from `key`, plus the radical inverse
/// of the index, so that the passes' hero draws fill the visible range evenly. With the few
/// passes such a method takes, independent draws would leave the whole image's colour noisy.
/// The heroes alone must cover the whole range: after dispersive glass a path is read at its
/// hero only (with the radical inverse spread over a quarter of the interval, as the rotated
/// lanes would allow, such paths saw a quarter of the spectrum, and their colour was wrong).
WavelengthContext pass_wavelengths(uint64_t key, uint32_t index);

}  // namespace glint

namespace glint {

/// Spectral mode's wavelengths for one path while it lives, when `spectral`; nothing in
/// RGB mode. Construct it in place where a path starts, with the key of its random numbers.
class PathWavelengths {
public:
    PathWavelengths(bool spectral, uint64_t key) {
        if (!spectral) return;
        m_context = path_wavelengths(key);
        m_scope.emplace(m_context);
        m_terminated.emplace();
    }
    /// A path that carries wavelengths shared with others (a set of WavelengthSets), kept
    /// where they are, so that the set can be told by its address; nothing when null.
    explicit PathWavelengths(const WavelengthContext* shared) {
        if (shared == nullptr) return;
        m_scope.emplace(*shared);
        m_terminated.emplace();
    }
    PathWavelengths(const PathWavelengths&) = delete;
    PathWavelengths& operator=(const PathWavelengths&) = delete;

private:
    WavelengthContext m_context;
    std::optional<WavelengthScope> m_scope;
    std::optional<SecondaryWavelengthsScope> m_terminated;
};

}  // namespace glint
