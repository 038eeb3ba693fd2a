#include <glint/core/error.h>
#include <glint/material/texture/noise.h>
#include <glint/medium/grid/fbm_cloud.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// Density at normalised position u: a sphere of radius `coverage` (in half box widths)
// whose edge the noise pushes in and out, rising smoothly from 0 at the perturbed edge.
float cloud_density(const Vec3& u, const FbmCloudSettings& s) {
    const float r = 2.0f * glm::length(u - Vec3(0.5f));
    const float noise = fbm(u * s.frequency + Vec3(s.offset), s.octaves);
    const float edge = s.coverage * (1.0f + 0.8f * noise);
    const float inside = (edge - r) / std::max(edge, 1e-3f);
    return std::clamp(2.0f * inside + 0.8f * noise, 0.0f, 1.0f) * (inside > 0.0f ? 1.0f : 0.0f);
}

}  // namespace

VoxelGrid make_fbm_cloud(const FbmCloudSettings& settings, const Bounds3& bounds) {
    if (settings.resolution < 1 || settings.resolution > 512) {
        throw Error("cloud: resolution must be in [1, 512]");
    }
    if (settings.octaves < 1 || settings.octaves > 16) {
        throw Error("cloud: octaves must be in [1, 16]");
    }
    if (!(settings.coverage > 0.0f && settings.coverage <= 1.0f)) {
        throw Error("cloud: coverage must be in (0, 1]");
    }
    const int n = settings.resolution;
    const GridIndex dims{n, n, n};
    std::vector<float> values(voxel_count(dims));
    size_t i = 0;
    for (int z = 0; z < n; ++z) {
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                values[i++] =
                    cloud_density((Vec3(x, y, z) + 0.5f) / static_cast<float>(n), settings);
            }
        }
    }
    return VoxelGrid(dims, std::move(values), bounds);
}

}  // namespace glint
