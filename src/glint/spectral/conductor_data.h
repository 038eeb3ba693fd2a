#pragma once
// The measured tables behind conductors.h (conductor_data.cpp).
#include <glint/spectral/conductors.h>

#include <vector>

namespace glint::spectral::data {

extern const std::vector<ConductorData::Sample> kGoldJohnsonChristy;
extern const std::vector<ConductorData::Sample> kSilverJohnsonChristy;
extern const std::vector<ConductorData::Sample> kCopperJohnsonChristy;
extern const std::vector<ConductorData::Sample> kAluminiumRakic;

}  // namespace glint::spectral::data
