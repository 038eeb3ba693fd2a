#pragma once
// The standard tables behind cie.h and illuminants.h (cie_data.cpp), at 5 nm steps.
#include <array>

namespace glint::spectral::data {

inline constexpr int kStepNm = 5;
inline constexpr int kCieFirstNm = 360;
inline constexpr int kCieSamples = 95;  // 360–830 nm
inline constexpr int kFluorescentFirstNm = 380;
inline constexpr int kFluorescentSamples = 81;  // 380–780 nm

extern const std::array<std::array<double, 3>, kCieSamples> kCie1931;
extern const std::array<double, kCieSamples> kD65;
extern const std::array<std::array<double, kFluorescentSamples>, 12> kFluorescent;

}  // namespace glint::spectral::data
