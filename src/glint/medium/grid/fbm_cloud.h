#pragma once
// A procedural cloud: fractal noise (fbm of Perlin noise) shaped by a soft sphere inside a
// box, baked into a VoxelGrid. It needs no file, so examples and tests use it; its empty
// corners and thin wisps are what a majorant grid makes cheap.
#include <glint/medium/grid/voxel_grid.h>

namespace glint {

struct FbmCloudSettings {
    int resolution = 64;     ///< voxels along each axis
    float frequency = 3.0f;  ///< noise cycles across the box at the first octave
    int octaves = 5;         ///< fbm octaves
    float coverage = 0.45f;  ///< in (0, 1]: the share of the sphere's radius the cloud fills
    float offset = 0.0f;     ///< shifts the noise, a different cloud for each value
};

/// Bakes the cloud over `bounds`; densities lie in [0, 1]. Throws glint::Error for a
/// resolution outside [1, 512], octaves outside [1, 16] or coverage outside (0, 1].
VoxelGrid make_fbm_cloud(const FbmCloudSettings& settings, const Bounds3& bounds);

}  // namespace glint
