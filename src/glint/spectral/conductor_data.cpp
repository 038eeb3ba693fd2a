// Measured optical constants (η, k) of metals over the visible range, wavelengths in nm.
// Values from the publications cited in docs/materials.md, written out here:
// - Au, Ag, Cu: P. B. Johnson and R. W. Christy, "Optical constants of the noble metals",
//   Phys. Rev. B 6, 4370–4379 (1972), room temperature;
// - Al: A. D. Rakić, "Algorithm for the determination of intrinsic optical constants of metal
//   films: application to aluminum", Appl. Opt. 34, 4755–4767 (1995).
#include <glint/spectral/conductor_data.h>

namespace glint::spectral::data {

// {nm, η, k}
const std::vector<ConductorData::Sample> kGoldJohnsonChristy = {
    {284.4f, 1.47f, 1.869f}, {292.4f, 1.49f, 1.878f}, {300.9f, 1.53f, 1.889f},
    {310.7f, 1.53f, 1.893f}, {320.4f, 1.54f, 1.898f}, {331.5f, 1.48f, 1.883f},
    {342.5f, 1.48f, 1.871f}, {354.2f, 1.5f, 1.866f},  {367.9f, 1.48f, 1.895f},
    {381.5f, 1.46f, 1.933f}, {397.4f, 1.47f, 1.952f}, {413.3f, 1.46f, 1.958f},
    {430.5f, 1.45f, 1.948f}, {450.9f, 1.38f, 1.914f}, {471.4f, 1.31f, 1.849f},
    {495.9f, 1.04f, 1.833f}, {520.9f, 0.62f, 2.081f}, {548.6f, 0.43f, 2.455f},
    {582.1f, 0.29f, 2.863f}, {616.8f, 0.21f, 3.272f}, {659.5f, 0.14f, 3.697f},
    {704.5f, 0.13f, 4.103f}, {756.0f, 0.14f, 4.542f}, {821.1f, 0.16f, 5.083f},
    {892.0f, 0.17f, 5.663f},
};

// {nm, η, k}
const std::vector<ConductorData::Sample> kSilverJohnsonChristy = {
    {284.4f, 1.41f, 1.264f}, {292.4f, 1.39f, 1.161f}, {300.9f, 1.34f, 0.964f},
    {310.7f, 1.13f, 0.616f}, {320.4f, 0.81f, 0.392f}, {331.5f, 0.17f, 0.829f},
    {342.5f, 0.14f, 1.142f}, {354.2f, 0.1f, 1.419f},  {367.9f, 0.07f, 1.657f},
    {381.5f, 0.05f, 1.864f}, {397.4f, 0.05f, 2.07f},  {413.3f, 0.05f, 2.275f},
    {430.5f, 0.04f, 2.462f}, {450.9f, 0.04f, 2.657f}, {471.4f, 0.05f, 2.869f},
    {495.9f, 0.05f, 3.093f}, {520.9f, 0.05f, 3.324f}, {548.6f, 0.06f, 3.586f},
    {582.1f, 0.05f, 3.858f}, {616.8f, 0.06f, 4.152f}, {659.5f, 0.05f, 4.483f},
    {704.5f, 0.04f, 4.838f}, {756.0f, 0.03f, 5.242f}, {821.1f, 0.04f, 5.727f},
    {892.0f, 0.04f, 6.312f},
};

// {nm, η, k}
const std::vector<ConductorData::Sample> kCopperJohnsonChristy = {
    {284.4f, 1.45f, 1.633f}, {292.4f, 1.42f, 1.633f}, {300.9f, 1.4f, 1.679f},
    {310.7f, 1.38f, 1.729f}, {320.4f, 1.38f, 1.783f}, {331.5f, 1.34f, 1.821f},
    {342.5f, 1.36f, 1.864f}, {354.2f, 1.37f, 1.916f}, {367.9f, 1.36f, 1.975f},
    {381.5f, 1.33f, 2.045f}, {397.4f, 1.32f, 2.116f}, {413.3f, 1.28f, 2.207f},
    {430.5f, 1.25f, 2.305f}, {450.9f, 1.24f, 2.397f}, {471.4f, 1.25f, 2.483f},
    {495.9f, 1.22f, 2.564f}, {520.9f, 1.18f, 2.608f}, {548.6f, 1.02f, 2.577f},
    {582.1f, 0.7f, 2.704f},  {616.8f, 0.3f, 3.205f},  {659.5f, 0.22f, 3.747f},
    {704.5f, 0.21f, 4.205f}, {756.0f, 0.24f, 4.665f}, {821.1f, 0.26f, 5.18f},
    {892.0f, 0.3f, 5.768f},
};

// {nm, η, k}
const std::vector<ConductorData::Sample> kAluminiumRakic = {
    {310.0f, 0.28003f, 3.7081f}, {326.3f, 0.31474f, 3.9165f}, {364.7f, 0.39877f, 4.3957f},
    {413.3f, 0.52135f, 5.0008f}, {442.8f, 0.6079f, 5.3676f},  {476.9f, 0.7278f, 5.7781f},
    {516.6f, 0.8734f, 6.2418f},  {563.6f, 1.0728f, 6.7839f},  {619.9f, 1.366f, 7.4052f},
    {652.2f, 1.5724f, 7.7354f},  {688.8f, 1.8301f, 8.0601f},  {729.3f, 2.1606f, 8.3565f},
    {774.9f, 2.6154f, 8.4914f},  {794.8f, 2.7675f, 8.3866f},  {815.7f, 2.7668f, 8.2573f},
    {837.7f, 2.6945f, 8.1878f},  {885.6f, 2.2802f, 8.1134f},
};

}  // namespace glint::spectral::data
