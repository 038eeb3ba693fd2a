#pragma once
// Spectral mode's dispersive events. A glass whose index varies with wavelength sends each
// wavelength its own way; the path goes on with its hero wavelength alone, and from then on
// the film must read the path's value at the hero only (the other wavelengths' values no
// longer estimate anything). Whether that happened is per path: a thread's current path
// (PathWavelengths in integrator/transport/spectral_model.h opens and closes it).
namespace glint {

/// The current path went through a dispersive event: the film reads it at its hero alone.
void terminate_secondary_wavelengths();
/// Whether it did.
bool secondary_wavelengths_terminated();

/// A fresh path's state for its lifetime (not terminated), restoring the previous state
/// after it (a thread that runs another task while waiting).
class SecondaryWavelengthsScope {
public:
    SecondaryWavelengthsScope();
    ~SecondaryWavelengthsScope();
    SecondaryWavelengthsScope(const SecondaryWavelengthsScope&) = delete;
    SecondaryWavelengthsScope& operator=(const SecondaryWavelengthsScope&) = delete;

private:
    bool m_previous;
};

}  // namespace glint
