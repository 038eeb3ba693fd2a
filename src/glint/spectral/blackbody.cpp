#include <glint/spectral/blackbody.h>

#include <cmath>

namespace glint::spectral {
namespace {

constexpr double kPlanck = 6.62607015e-34;            // J·s
constexpr double kLightSpeed = 299792458.0;           // m/s
constexpr double kBoltzmann = 1.380649e-23;           // J/K
constexpr double kWienDisplacement = 2.897771955e-3;  // m·K

}  // namespace

double blackbody(double nm, double kelvin) {
    if (kelvin <= 0.0 || nm <= 0.0) return 0.0;
    const double lambda = nm * 1e-9;
    const double lambda5 = lambda * lambda * lambda * lambda * lambda;
    const double per_metre =
        2.0 * kPlanck * kLightSpeed * kLightSpeed /
        (lambda5 * std::expm1(kPlanck * kLightSpeed / (lambda * kBoltzmann * kelvin)));
    return per_metre * 1e-9;
}

double blackbody_normalized(double nm, double kelvin) {
    if (kelvin <= 0.0) return 0.0;
    const double peak_nm = kWienDisplacement / kelvin * 1e9;
    return blackbody(nm, kelvin) / blackbody(peak_nm, kelvin);
}

}  // namespace glint::spectral
